#pragma once
// Several wavelengths per camera sample (docs/spectral.md, "Several wavelengths per sample"). The
// sample's ray is made at its own (hero) wavelength and the scene path it starts is shared by the
// sample's other wavelengths: each is scored where the lens brings that same scene ray to the film
// at that wavelength. They are weighed by the balance heuristic over the wavelengths' densities of
// making that scene ray (Wilkie et al., "Hero Wavelength Spectral Sampling", EGSR 2014): each
// density is the camera's (per unit of ray measure, FilmLanding) times the density of film samples
// there, summed over every rendered pixel's filter.
//
// A wavelength landing at x_k counts for each pixel P with P's filter h_P(x_k). It is split in two
// parts: h_P(x_0) (its sample's own film point), carried in the sample's own pixel the way the hero
// is (so that a sample's wavelengths, stratified to sum to a smooth spectrum, stay together), and
// the difference h_P(x_k) - h_P(x_0), splatted into the pixels whose filters reach either point
// (small and smooth for smooth filters; for the box filter it moves the wavelength to the pixel it
// landed in). Both parts together are unbiased for every pixel; through a lens without dispersion
// the difference is zero and the estimate is the plain mean over the wavelengths.
#include "cameras/Camera.h"
#include "core/Vec3f.h"
#include "film/PixelFilter.h"
#include "film/SpectralSensor.h"
#include "render/SplatBuffer.h"
#include "render/TileScheduler.h"

namespace lenslab {

// The most wavelengths a sample carries (RenderSettings::wavelengthsPerSample).
constexpr int kMaxWavelengthsPerSample = 8;

// One sample's estimate. (px, py): its pixel, ownWeight: the filter weight its film point drew,
// area: the rendered pixels; radiance: what its ray brought back; wavelengths and landings: `count`
// of each (landings[0], its own film point). Returns the value FilteredPixel adds for the own pixel
// (with ownWeight); what belongs to other pixels is added, times `splatScale`, to `splats`.
Vec3f heroWavelengthEstimate(const SpectralSensor& sensor, const PixelFilter& filter, const PixelRect& area, int px,
                             int py, float ownWeight, const Vec3f& radiance, const WavelengthSample* wavelengths,
                             const FilmLanding* landings, int count, float splatScale, SplatBuffer& splats);

}  // namespace lenslab
