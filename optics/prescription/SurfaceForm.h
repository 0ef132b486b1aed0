#pragma once
// The sag of a surface beyond the conic and the even-asphere terms: Zemax's odd asphere and
// Forbes's Q-type aspheres (Qbfs, Qcon) as Zemax and Code V state them (docs/prescriptions.md).
#include <array>
#include <cstdint>

namespace lenslab {

enum class SurfaceKind : std::uint8_t {
    EvenAsphere,  // conic + a_1 r^2 + ... + a_8 r^16 (LensTableRow::aspheric); a sphere without terms
    OddAsphere,   // conic + b_1 r + b_2 r^2 + ... + b_16 r^16 (Zemax ODDASPH)
    Qbfs,         // best-fit sphere + u^2 (1 - u^2) / sqrt(1 - c^2 r^2) sum a_m Qbfs_m(u^2), u = r / r_norm
    Qcon,         // conic + u^4 sum a_m Qcon_m(u^2) (Forbes 2007)
    // Zemax TOROIDAL: the y-z profile conic(y) + a_1 y^2 + a_2 y^4 + ... turned about an axis parallel
    // to y at the radius of rotation R from the vertex (R 0: a cylinder, the profile swept along x)
    Toroidal,
};

constexpr int kFormTerms = 16;

struct SurfaceForm {
    SurfaceKind kind = SurfaceKind::EvenAsphere;
    // OddAsphere: terms[i] multiplies r^(i+1) (mm^-i). Qbfs, Qcon: terms[m] is a_m (mm). Toroidal:
    // terms[0] is R (mm), terms[i] multiplies y^(2i) (mm^(1-2i)).
    std::array<double, kFormTerms> terms{};
    int termCount = 0;                // terms used (trailing zeros dropped)
    double normalisationRadius = 0;   // Q-types: r_norm, mm
    bool isEvenAsphere() const { return kind == SurfaceKind::EvenAsphere; }
};

const char* surfaceKindName(SurfaceKind kind);  // "even asphere", "odd asphere", "Qbfs", "Qcon"

}  // namespace lenslab
