#include "prescription/Coating.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace lenslab {

namespace {

// Typical indices of evaporated films in the visible, near 550 nm (the values coating designers
// start from; a real film's index depends on how it was deposited).
struct NamedMaterial {
    const char* name;
    double index;
};
constexpr NamedMaterial kMaterials[] = {
    {"MgF2", 1.38}, {"SiO2", 1.46}, {"Al2O3", 1.63}, {"ZrO2", 2.05}, {"TiO2", 2.35},
};

constexpr int kMaxLayers = 64;
constexpr double kMinDesignNm = 300, kMaxDesignNm = 2500;

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    return b == std::string::npos ? "" : s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

// The whole text as a finite number, else nullopt-like NaN.
double numberOrNaN(const std::string& s) {
    if (s.empty()) return NAN;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size() && errno != ERANGE && std::isfinite(v) ? v : NAN;
}

double materialIndex(const std::string& text, const std::string& whole) {
    const double n = numberOrNaN(text);
    if (!std::isnan(n)) {
        if (!(n >= 1 && n <= 5)) throw CoatingError("coating '" + whole + "': layer index " + text + " must lie in [1, 5]");
        return n;
    }
    for (const NamedMaterial& m : kMaterials)
        if (lower(text) == lower(m.name)) return m.index;
    throw CoatingError("coating '" + whole + "': unknown material '" + text + "' (known: " + coatingMaterialNames() +
                       "; or give the layer's index as a number)");
}

// "2q": multiples of a quarter wave at the design wavelength; "80nm": physical thickness.
double layerThicknessNm(const std::string& text, double index, double designNm, const std::string& whole) {
    const auto fail = [&](const std::string& problem) {
        throw CoatingError("coating '" + whole + "': layer thickness '" + text + "' " + problem);
    };
    const std::string t = lower(text);
    const bool quarters = t.size() > 1 && t.back() == 'q';
    const bool nm = t.size() > 2 && t.compare(t.size() - 2, 2, "nm") == 0;
    if (!quarters && !nm) fail("needs a unit: q (quarter waves, e.g. 2q) or nm (e.g. 80nm)");
    const double v = numberOrNaN(t.substr(0, t.size() - (quarters ? 1 : 2)));
    if (!(v > 0) || v > (quarters ? 100 : 1e5)) fail(quarters ? "must lie in (0, 100] quarter waves" : "must lie in (0, 100000] nm");
    return quarters ? v * designNm / (4 * index) : v;
}

}  // namespace

std::string coatingMaterialNames() {
    std::string out;
    for (const NamedMaterial& m : kMaterials) {
        char n[16];
        std::snprintf(n, sizeof n, "%.2f", m.index);
        out += (out.empty() ? "" : ", ") + std::string(m.name) + " " + n;
    }
    return out;
}

Coating parseCoating(const std::string& written) {
    Coating c;
    c.text = trimmed(written);
    if (c.text.empty()) throw CoatingError("empty coating: write none, a material (MgF2, MgF2@550) or a stack");
    if (lower(c.text) == "none") return c;
    std::string stack = c.text;
    double designNm = kCoatingDesignNm;
    if (const auto at = stack.rfind('@'); at != std::string::npos) {
        designNm = numberOrNaN(trimmed(stack.substr(at + 1)));
        if (!(designNm >= kMinDesignNm && designNm <= kMaxDesignNm))
            throw CoatingError("coating '" + c.text + "': design wavelength '" + stack.substr(at + 1) +
                               "' must be a number of nm in [300, 2500]");
        stack.resize(at);
    }
    std::size_t start = 0;
    while (true) {
        const std::size_t plus = stack.find('+', start);
        const std::string layer = trimmed(stack.substr(start, plus == std::string::npos ? std::string::npos : plus - start));
        if (layer.empty()) throw CoatingError("coating '" + c.text + "': an empty layer between '+' signs");
        if (int(c.layers.size()) == kMaxLayers)
            throw CoatingError("coating '" + c.text + "': more than " + std::to_string(kMaxLayers) + " layers");
        const auto colon = layer.find(':');
        CoatingLayer l;
        l.index = materialIndex(trimmed(layer.substr(0, colon)), c.text);
        l.thicknessNm = layerThicknessNm(colon == std::string::npos ? "1q" : trimmed(layer.substr(colon + 1)), l.index, designNm, c.text);
        c.layers.push_back(l);
        if (plus == std::string::npos) break;
        start = plus + 1;
    }
    return c;
}

}  // namespace lenslab
