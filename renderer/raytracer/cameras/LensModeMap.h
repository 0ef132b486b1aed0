#pragma once
// Which lens model traces a camera ray, by the film radius it starts from: the exact trace or the
// thick lens. Mode "auto" uses the thick lens on the bands of film radius where its predicted
// errors (ThickLensFilmError) stay under the thresholds at both ends: the worst ray's film error
// under the position threshold and the brightness within kAutoBrightnessTolerance of the exact
// lens's (the thick lens has no vignetting); the exact trace elsewhere. A split pays only where the
// thick lens covers most of the picture (kAutoMinThickShare), so below that auto traces exactly
// everywhere.
#include <optional>
#include <string>
#include <vector>

#include "cameras/ThickLensFilmError.h"

namespace lenslab {

enum class LensMode { Exact, Thick, Auto };

// Auto's brightness bound: |thick / exact film irradiance - 1|. A bias b in a region adds about b
// to a 16-spp frame's relative RMSE of ~0.2 in quadrature: 3% keeps it within ~2% of the exact
// lens's.
constexpr double kAutoBrightnessTolerance = 0.03;
// Auto's smallest thick share of the rendered film area worth a split. A thick-lens camera ray
// costs about what an exact one does (bench/README.md): what the thick lens saves is the exact
// trace's setup (exit-pupil bounds) for its radii and rays the bounds waste, a few percent of a
// small frame even over the whole picture; over less than nine tenths of it the saving is below
// the noise of a frame time, while the seam between the models' pictures (up to the threshold
// apart) stays.
constexpr double kAutoMinThickShare = 0.9;

// The lens model: "exact" (every ray traced through every surface), "thick" (the thick-lens
// model), "auto" (per film radius) — the words diagrams use too. parseLensMode also takes round
// one's "accurate" and "approximate", so older scenes and API clients keep working; nullopt for
// any other name.
const char* lensModeName(LensMode mode);
std::optional<LensMode> parseLensMode(const std::string& name);

class LensModeMap {
public:
    static LensModeMap exactEverywhere(double minFilmRadius, double maxFilmRadius);
    static LensModeMap thickEverywhere(double minFilmRadius, double maxFilmRadius);
    // errors: samples at evenly spaced radii, in order; thresholdMm: the largest film error allowed;
    // brightness: kAutoBrightnessTolerance.
    static LensModeMap fromErrors(const std::vector<ThickLensFilmError>& errors, double thresholdMm);

    bool thickAt(double filmRadius) const;
    bool usesThick() const;
    bool usesExact() const;
    // The film radii the exact trace covers (meaningful when usesExact()).
    double exactMinRadius() const;
    double exactMaxRadius() const;
    // e.g. "thick for r < 8.3 mm, exact beyond" or "exact for 0 <= r <= 21.6 mm".
    std::string describe() const;

private:
    // Whether the thick lens may draw at a sampled radius.
    static bool thickAllowed(const ThickLensFilmError& error, double thresholdMm);

    double minRadius_ = 0, maxRadius_ = 0;
    std::vector<bool> thick_;  // per band, evenly spaced from minRadius_ to maxRadius_
    double bandWidth() const { return (maxRadius_ - minRadius_) / thick_.size(); }
    int bandOf(double filmRadius) const;
};

}  // namespace lenslab
