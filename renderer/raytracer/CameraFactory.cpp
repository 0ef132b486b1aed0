#include "CameraFactory.h"

#include <filesystem>

#include "LensTable.h"
#include "OpticsError.h"
#include "OrthographicCamera.h"
#include "PerspectiveCamera.h"
#include "RealisticCamera.h"

namespace fs = std::filesystem;

namespace lenslab {

std::string findLensFile(const SceneDescription& scene, const std::string& name, const SourceLocation& where) {
    try {
        return resolveScenePath(scene, name, where);
    } catch (const SceneError&) {
        const fs::path bundled = fs::path(LENSLAB_LENS_DIR) / fs::path(name).filename();
        if (fs::is_regular_file(bundled)) return bundled.string();
        sceneFail(where, "lens file '" + name + "' not found in the scene's folder tree nor among the bundled lenses (" +
                             std::string(LENSLAB_LENS_DIR) + ")");
    }
}

namespace {

std::unique_ptr<Camera> makeRealistic(SceneDescription& scene, const CameraOverrides& o, int width, int height,
                                      double margin) {
    const ParamSet& p = scene.camera.params;
    RealisticParams r;
    // pbrt-v3 names (lensfile, aperturediameter, focusdistance in metres from the film,
    // simpleweighting) and the course's (specfile, fstop, focaldistance in mm from the front vertex).
    const bool pbrtStyle = p.has("lensfile");
    const std::string lensName = pbrtStyle ? p.getString("lensfile", "") : p.getString("specfile", "");
    if (o.lensFile) r.lensPath = *o.lensFile;
    else if (lensName.empty()) p.fail("needs \"string specfile\" (or pbrt-v3's \"lensfile\")");
    else r.lensPath = findLensFile(scene, lensName, p.where());

    if (p.has("fstop")) r.fstop = p.getFloat("fstop", 0);
    if (p.has("aperturediameter")) r.stopDiameterMm = p.getFloat("aperturediameter", 1);
    else if (pbrtStyle && !r.fstop) r.stopDiameterMm = 1.0;  // pbrt-v3's default opening
    if (o.fstop) {
        r.fstop = *o.fstop;
        r.stopDiameterMm.reset();
    }
    if (p.has("focaldistance") && p.has("focusdistance"))
        p.fail("give either \"focaldistance\" (mm from the front vertex) or \"focusdistance\" (m from the film)");
    if (p.has("focusdistance")) {
        r.focusDistanceMm = 1000.0 * p.getFloat("focusdistance", 10);
        r.focusFromFilm = true;
    } else {
        r.focusDistanceMm = p.getFloat("focaldistance", 10000);
    }
    if (o.focalDistance) {
        r.focusDistanceMm = *o.focalDistance;
        r.focusFromFilm = false;
    }
    r.filmDiagonalMm = o.filmDiagonal.value_or(p.getFloat("filmdiagonal", scene.film.diagonalMm));
    const std::string mode = o.mode.value_or(p.getString("mode", "accurate"));
    const std::optional<LensMode> lensMode = parseLensMode(mode);
    if (!lensMode) p.fail("mode must be accurate|approximate|auto, got \"" + mode + "\"");
    r.mode = *lensMode;
    r.autoThresholdPixels = p.getFloat("autothreshold", r.autoThresholdPixels);
    r.crop = scene.film.crop;  // the effective window: the render settings' crop overrides the scene's
    r.exposureTime = p.getFloat("shutterclose", 1) - p.getFloat("shutteropen", 0);
    r.simpleWeighting = p.getBool("simpleweighting", pbrtStyle);
    p.checkAllUsed(scene.warnings, {"frameaspectratio", "screenwindow"});
    try {
        return std::make_unique<RealisticCamera>(r, scene.camera.cameraToWorld, width, height, margin);
    } catch (const OpticsError& e) {
        p.fail(e.what());
    } catch (const LensTableError& e) {
        p.fail(e.what());
    }
}

std::unique_ptr<Camera> makeOrthographic(const SceneDescription& scene, int width, int height) {
    const ParamSet& p = scene.camera.params;
    OrthographicParams o;
    o.screen = ScreenWindow::forImage(width, height);
    if (p.has("screenwindow")) {
        const std::vector<double> w = p.getFloats("screenwindow");
        if (w.size() != 4 || !(w[0] < w[1] && w[2] < w[3])) p.fail("screenwindow needs x0 < x1, y0 < y1");
        o.screen = {w[0], w[1], w[2], w[3]};
    }
    o.lensRadius = p.getFloat("lensradius", 0);
    o.focalDistance = p.getFloat("focaldistance", 1e6);
    if (o.lensRadius < 0 || !(o.focalDistance > 0)) p.fail("lensradius must be >= 0 and focaldistance > 0");
    return std::make_unique<OrthographicCamera>(o, scene.camera.cameraToWorld, width, height);
}

}  // namespace

std::unique_ptr<Camera> makeCamera(SceneDescription& scene, const CameraOverrides& o, int width, int height,
                                   double filmMarginPixels) {
    const ParamSet& p = scene.camera.params;
    if (scene.camera.type == "realistic") return makeRealistic(scene, o, width, height, filmMarginPixels);
    if (o.lensFile || o.fstop || o.focalDistance || o.filmDiagonal || o.mode)
        throw SceneError(scene.file + ": the lens overrides need a Camera \"realistic\"; this scene has a " +
                         scene.camera.type + " camera");
    if (scene.camera.type == "orthographic") {
        auto camera = makeOrthographic(scene, width, height);
        p.checkAllUsed(scene.warnings, {"shutteropen", "shutterclose", "frameaspectratio"});
        return camera;
    }
    PerspectiveParams pp;
    const double fov = p.getFloat("fov", 90);
    if (!(fov > 0 && fov < 180)) p.fail("fov must lie in (0, 180) degrees");
    pp.fovDegrees = fov;
    pp.lensRadius = p.getFloat("lensradius", 0);
    pp.focalDistance = p.getFloat("focaldistance", 1e6);
    if (pp.lensRadius < 0 || !(pp.focalDistance > 0)) p.fail("lensradius must be >= 0 and focaldistance > 0 (metres)");
    p.checkAllUsed(scene.warnings, {"shutteropen", "shutterclose"});
    return std::make_unique<PerspectiveCamera>(pp, scene.camera.cameraToWorld, width, height);
}

}  // namespace lenslab
