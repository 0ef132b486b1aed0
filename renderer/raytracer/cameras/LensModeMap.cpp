#include "cameras/LensModeMap.h"

#include <algorithm>
#include <cmath>

#include "prescription/NumberText.h"

namespace lenslab {

const char* lensModeName(LensMode mode) {
    switch (mode) {
        case LensMode::Exact: return "exact";
        case LensMode::Thick: return "thick";
        case LensMode::Auto: return "auto";
    }
    return "?";
}

std::optional<LensMode> parseLensMode(const std::string& name) {
    for (LensMode m : {LensMode::Exact, LensMode::Thick, LensMode::Auto})
        if (name == lensModeName(m)) return m;
    if (name == "accurate") return LensMode::Exact;
    if (name == "approximate") return LensMode::Thick;
    return std::nullopt;
}

LensModeMap LensModeMap::exactEverywhere(double minFilmRadius, double maxFilmRadius) {
    LensModeMap m;
    m.minRadius_ = minFilmRadius;
    m.maxRadius_ = maxFilmRadius;
    m.thick_ = {false};
    return m;
}

LensModeMap LensModeMap::thickEverywhere(double minFilmRadius, double maxFilmRadius) {
    LensModeMap m = exactEverywhere(minFilmRadius, maxFilmRadius);
    m.thick_ = {true};
    return m;
}

bool LensModeMap::thickAllowed(const ThickLensFilmError& e, double thresholdMm) {
    return e.maxErrorMm < thresholdMm && std::fabs(e.illuminationRatio - 1) < kAutoBrightnessTolerance;
}

LensModeMap LensModeMap::fromErrors(const std::vector<ThickLensFilmError>& errors, double thresholdMm) {
    LensModeMap m;
    m.minRadius_ = errors.front().filmRadius;
    m.maxRadius_ = errors.back().filmRadius;
    const auto under = [&](const ThickLensFilmError& e) { return thickAllowed(e, thresholdMm); };
    if (errors.size() < 2 || !(m.maxRadius_ > m.minRadius_)) {
        m.thick_ = {std::all_of(errors.begin(), errors.end(), under)};
        return m;
    }
    for (std::size_t i = 0; i + 1 < errors.size(); ++i) m.thick_.push_back(under(errors[i]) && under(errors[i + 1]));
    return m;
}

int LensModeMap::bandOf(double filmRadius) const {
    const int n = int(thick_.size());
    if (n == 1 || !(maxRadius_ > minRadius_)) return 0;
    return std::clamp(int((filmRadius - minRadius_) / bandWidth()), 0, n - 1);
}

bool LensModeMap::thickAt(double filmRadius) const { return thick_[bandOf(filmRadius)]; }

bool LensModeMap::usesThick() const { return std::find(thick_.begin(), thick_.end(), true) != thick_.end(); }

bool LensModeMap::usesExact() const { return std::find(thick_.begin(), thick_.end(), false) != thick_.end(); }

double LensModeMap::exactMinRadius() const {
    const auto first = std::find(thick_.begin(), thick_.end(), false) - thick_.begin();
    return minRadius_ + first * bandWidth();
}

double LensModeMap::exactMaxRadius() const {
    const auto last = thick_.rend() - std::find(thick_.rbegin(), thick_.rend(), false);
    return minRadius_ + last * bandWidth();
}

std::string LensModeMap::describe() const {
    if (!usesThick()) return "exact for " + formatNumber(minRadius_, 3) + " <= r <= " + formatNumber(maxRadius_, 3) + " mm";
    if (!usesExact()) return "thick for " + formatNumber(minRadius_, 3) + " <= r <= " + formatNumber(maxRadius_, 3) + " mm";
    // Runs of equal bands, e.g. "thick for r < 8.3 mm, exact beyond".
    std::string s;
    std::size_t i = 0;
    while (i < thick_.size()) {
        std::size_t j = i;
        while (j < thick_.size() && thick_[j] == thick_[i]) ++j;
        const std::string model = thick_[i] ? "thick" : "exact";
        const double lo = minRadius_ + i * bandWidth(), hi = minRadius_ + j * bandWidth();
        if (!s.empty()) s += ", ";
        if (j == thick_.size() && i > 0) s += model + " beyond";
        else if (i == 0 && lo == 0) s += model + " for r < " + formatNumber(hi, 3) + " mm";
        else s += model + " for " + formatNumber(lo, 3) + " <= r < " + formatNumber(hi, 3) + " mm";
        i = j;
    }
    return s;
}

}  // namespace lenslab
