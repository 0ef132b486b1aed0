#pragma once
// The CIE 1931 2-degree colour matching functions as sums of piecewise Gaussians: Wyman, Sloan &
// Shirley, "Simple Analytic Approximations to the CIE XYZ Color Matching Functions", JCGT 2(2),
// 2013 (the multi-lobe fit, within about 1% of the tabulated functions). Wavelengths in nm.
#include "prescription/Wavelength.h"  // kVisibleFirstNm, kVisibleLastNm

namespace lenslab {

double cieX(double nm);
double cieY(double nm);
double cieZ(double nm);
// The sum of cieY at every whole nm from 360 to 830: the luminance of a constant 1.
double cieYIntegral();

}  // namespace lenslab
