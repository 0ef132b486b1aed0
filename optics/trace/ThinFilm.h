#pragma once
// How much light a surface reflects and transmits: Fresnel's equations for bare glass, and the
// thin-film characteristic matrix for coated glass (Macleod, Thin-Film Optical Filters, ch. 2:
// each layer a 2x2 matrix in its phase thickness and tilted admittance), for unpolarised light
// (the mean of s and p), at any angle of incidence and wavelength. Lossless layers: R + T = 1.
#include "prescription/Coating.h"
#include "prescription/LensSystem.h"

namespace lenslab {

struct InterfaceResponse {
    double reflectance = 0;    // power, unpolarised
    double transmittance = 1;  // power carried into the second medium, unpolarised
};

// Light in a medium of index n1 meets the medium n2 through `layers` (in the order it meets them;
// none: bare Fresnel) with cosine of incidence cos1 in [0, 1]. Beyond the critical angle R = 1.
InterfaceResponse thinFilmResponse(double n1, double n2, const std::vector<CoatingLayer>& layers, bool layersReversed,
                                   double cos1, double wavelengthNm);

// Surface i of the lens met from its scene side (fromScene) or its film side, at the media's
// indices at wavelengthNm (the glasses' dispersion) with its coating, whose layers run from the
// air side (or, between two glasses or two airs, the scene side). A mirror reflects everything.
InterfaceResponse surfaceResponse(const LensSystem& lens, int i, bool fromScene, double cos1, double wavelengthNm);

}  // namespace lenslab
