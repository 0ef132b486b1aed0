#pragma once
// Spectral values in scene files, turned into the renderer's linear sRGB the way pbrt-v3's RGB
// build does it: the spectrum (linearly interpolated between its samples, held constant beyond
// them) is integrated against the CIE 1931 colour matching functions from 360 to 830 nm,
// normalised so that a constant 1 has luminance Y = 1, then mapped XYZ -> linear sRGB.
#include <vector>

#include "core/Vec3f.h"

namespace lenslab {

// Wavelengths in nm, ascending; values as given. Both the same non-zero length.
Vec3f sampledSpectrumToRgb(const std::vector<double>& lambdaNm, const std::vector<double>& values);

// Planck's law: a black body's spectral radiance at temperature T (kelvin), W / (m^2 sr m).
double planckRadiance(double kelvin, double nm);

// pbrt-v3's "blackbody" [T scale]: Planck's law at temperature T (kelvin), divided by its own peak
// (Wien's displacement law), converted like a sampled spectrum, times scale.
Vec3f blackbodyToRgb(double kelvin, double scale);

Vec3f xyzToRgb(double x, double y, double z);

}  // namespace lenslab
