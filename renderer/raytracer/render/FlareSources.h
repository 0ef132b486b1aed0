#pragma once
// The scene's emitters as lens flare sees them (cameras/LensFlare.h): point, spot, goniometric,
// projection and distant lights as they light the lens's front vertex, and area lights and
// environment maps sampled from there in patches kFlarePatchRadians across, joined into sources
// kFlareCompactRadians across (a small area light or a map's sun is one source). Each is kept when it is in or near the frame (its image, by the chief
// ray, within the frame widened by half on every side) and not hidden behind the scene. Its light
// is given per flare wavelength through the spectral film's response (film/SpectralSensor.h).
#include <vector>

#include "cameras/LensFlare.h"
#include "film/SpectralSensor.h"
#include "geometry/SceneGeometry.h"

namespace lenslab {

// How bright an emitter must be for its ghosts to matter: the radiance of its direct image, its
// irradiance at the lens spread over its own solid angle or one pixel's, whichever is larger, in
// the scene's units (a white surface lit at 1 has radiance near 1/pi): auto models ghosts only of
// emitters at least this bright, and the area lights and environment maps give only such patches.
constexpr double kFlareBrightRadiance = 100;
constexpr double kFlarePatchRadians = 1.0 / 120;  // about half a degree
constexpr double kFlareCompactRadians = 0.035;     // 2 degrees
constexpr int kMostFlareSources = 8;               // the brightest, when more qualify

// brightOnly: the delta lights too must pass kFlareBrightRadiance (auto). `time` is the moment the
// scene's lights are looked at (the shutter's opening).
std::vector<FlareSource> findFlareSources(const SceneGeometry& geometry, const RealisticCamera& camera, int width,
                                          int height, const SpectralSensor& sensor, bool brightOnly, float time);

}  // namespace lenslab
