#pragma once
// Which lens model traces a camera ray, by the film radius it starts from: the exact trace or the
// thick lens. Mode "auto" uses the thick lens on the bands of film radius where its predicted
// error (ThickLensFilmError) stays under a threshold at both ends, the exact trace elsewhere.
#include <optional>
#include <string>
#include <vector>

#include "ThickLensFilmError.h"

namespace lenslab {

enum class LensMode { Exact, Thick, Auto };

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
    // errors: samples at evenly spaced radii, in order; thresholdMm: the largest film error allowed.
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
    double minRadius_ = 0, maxRadius_ = 0;
    std::vector<bool> thick_;  // per band, evenly spaced from minRadius_ to maxRadius_
    double bandWidth() const { return (maxRadius_ - minRadius_) / thick_.size(); }
    int bandOf(double filmRadius) const;
};

}  // namespace lenslab
