#pragma once
// CIE daylight (the D illuminants, CIE 15:2004): the chromaticity of daylight at a correlated
// colour temperature and its spectral power distribution, S0 + M1 S1 + M2 S2 of the CIE's three
// characteristic vectors.
namespace lenslab {

// The chromaticity (x, y) of CIE daylight at a correlated colour temperature (4000 to 25000 K).
void daylightChromaticity(double kelvin, double& x, double& y);

// Its relative spectral power at a wavelength (nm; 100 at 560 nm as the CIE scales it), linearly
// interpolated in the CIE's 10 nm table from 300 to 830 nm, the end values held beyond.
double daylightSpectrum(double kelvin, double nm);

}  // namespace lenslab
