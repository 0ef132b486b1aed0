#include "analysis/GhostAnalysis.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "trace/RayTransfer.h"
#include "trace/ThinFilm.h"

namespace lenslab {

namespace {

// The paraxial rays every path is measured with, both starting at the entrance pupil's plane.
struct PupilRays {
    double z = 0;                    // the entrance pupil
    double marginalY = 0, marginalU = 0;  // from the axial object point through the pupil's rim
    double filmZ = 0;
};

// What of an on-axis beam filling the entrance pupil passes every clear aperture and obscuration of
// `lens`: concentric circles, each clipping the beam to a smaller circle or blocking its middle.
struct PassingBeam {
    double scale = 1, obscured = 0;  // its outer and inner radius, as fractions of the pupil's
    double share() const { return std::max(0.0, scale * scale - obscured * obscured); }
};

PassingBeam passingBeam(const LensSystem& lens, const PupilRays& rays) {
    double scale = 1, obscured = 0;
    for (int k = 0; k < int(lens.surfaces.size()); ++k) {
        const Surface& s = lens.surfaces[k];
        const double y = std::fabs(rayTransfer(lens, rays.z, k + 1, s.z).height(rays.marginalY, rays.marginalU));
        if (!(y > 0)) continue;
        scale = std::min(scale, s.apertureRadius / y);
        obscured = std::max(obscured, s.obscurationRadius / y);
    }
    return {scale, obscured};
}

// The light a sequence of steps passes: R where it reflects, T where it refracts.
double passedLight(const LensSystem& lens, const std::vector<GhostStep>& steps, double nm) {
    double p = 1;
    for (const GhostStep& s : steps) {
        const InterfaceResponse r = surfaceResponse(lens, s.surface, s.fromScene, 1, nm);
        p *= s.reflects ? r.reflectance : r.transmittance;
    }
    return p;
}

std::vector<GhostStep> directSteps(const LensSystem& lens) {
    std::vector<GhostStep> steps;
    for (int k = 0; k < int(lens.surfaces.size()); ++k) steps.push_back({k, true, lens.surfaces[k].mirror});
    return steps;
}

}  // namespace

GhostAnalysis analyzeGhosts(const LensAnalysis& a, const std::atomic<bool>* stop) {
    const LensSystem& lens = a.lens;
    GhostAnalysis out;
    out.reflectingSurfaces = int(reflectingSurfaces(lens).size());
    out.filmZ = a.focus.imageZExact;
    out.wavelength = lens.wavelength;
    PupilRays rays;
    rays.z = a.pupils.entrance.z;
    rays.filmZ = out.filmZ;
    rays.marginalY = 0.5 * a.pupils.entrance.diameter;
    rays.marginalU = a.focus.infinity ? 0.0 : rays.marginalY / (a.focus.objectZ - rays.z);
    const int n = int(lens.surfaces.size());
    const RayTransfer direct = rayTransfer(lens, rays.z, n, out.filmZ);
    const double directLight = passedLight(lens, directSteps(lens), lens.wavelength) * passingBeam(lens, rays).share();
    const double sourceRadius = 0.5 * kGhostSourceDiameterDegrees * M_PI / 180;
    const double directImageRadius = std::fabs(direct.b) * sourceRadius;  // chief ray: y 0, slope 1 at the pupil

    for (const GhostPath& path : ghostPaths(lens)) {
        if (stop && stop->load(std::memory_order_relaxed)) break;
        const UnfoldedGhost g = unfoldGhost(lens, path);
        const int m = int(g.lens.surfaces.size());
        GhostImage image;
        image.path = path;
        image.reflectanceFirst = surfaceResponse(lens, path.first, true, 1, lens.wavelength).reflectance;
        image.reflectanceSecond = surfaceResponse(lens, path.second, false, 1, lens.wavelength).reflectance;
        const RayTransfer last = rayTransfer(g.lens, rays.z, m, g.lens.surfaces.back().z);
        const double y = last.height(rays.marginalY, rays.marginalU), u = last.slope(rays.marginalY, rays.marginalU);
        image.focusZ = std::fabs(u) > 1e-12 * std::fabs(y) ? g.lens.surfaces.back().z + y / u
                                                          : std::numeric_limits<double>::quiet_NaN();
        image.focusFromFilm = image.focusZ - out.filmZ;
        const RayTransfer film = rayTransfer(g.lens, rays.z, m, out.filmZ);
        const PassingBeam beam = passingBeam(g.lens, rays);
        const double blurRadius = beam.scale * std::fabs(film.height(rays.marginalY, rays.marginalU));
        image.blurDiameter = 2 * blurRadius;
        image.fieldScale = film.b / direct.b;
        image.energy = directLight > 0 ? passedLight(lens, g.steps, lens.wavelength) * beam.share() / directLight : 0.0;
        const double larger = std::max(blurRadius, std::fabs(film.b) * sourceRadius);
        image.relativeIntensity = larger > 0 ? image.energy * directImageRadius * directImageRadius / (larger * larger) : 0.0;
        image.focused = image.blurDiameter < kFocusedGhostDiameterMm;
        out.ghosts.push_back(image);
    }
    std::stable_sort(out.ghosts.begin(), out.ghosts.end(),
                     [](const GhostImage& x, const GhostImage& y) { return x.relativeIntensity > y.relativeIntensity; });
    return out;
}

}  // namespace lenslab
