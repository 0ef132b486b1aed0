#include "cameras/CameraFactory.h"

#include "firstorder/ExitPupilBounds.h"

#include "prescription/LensTable.h"
#include "prescription/NumberText.h"
#include "prescription/OpticsError.h"
#include "cameras/EnvironmentCamera.h"
#include "cameras/MovingCamera.h"
#include "cameras/OrthographicCamera.h"
#include "cameras/PerspectiveCamera.h"
#include "cameras/RealisticCamera.h"
#include "cameras/Shutter.h"

namespace lenslab {

namespace {

// Parameters that say the same thing in different generations: naming two of them is a contradiction.
void refuseSynonyms(const ParamSet& p, std::initializer_list<const char*> names, const std::string& what) {
    const char* first = nullptr;
    for (const char* name : names) {
        if (!p.has(name)) continue;
        if (first) p.fail(std::string("\"") + first + "\" and \"" + name + "\" both give " + what + ": give one of them");
        first = name;
    }
}

// The shutter interval. The course's scenes open and close it at 0: unit exposure, with a warning.
double exposureTime(const ParamSet& p, std::vector<std::string>& warnings) {
    const Shutter s = readShutter(p);
    if (s.close > s.open) return s.close - s.open;
    warnings.push_back(describe(p.where()) + ": shutteropen = shutterclose = " + formatNumber(s.open) +
                       ": no exposure interval, rendering with unit exposure");
    return 1;
}

// The later course's clipping planes. Camera rays start at the front lens element and run uncut, so
// only values that could clip something (other than pbrt-v2's defaults) are worth a warning.
void checkClipping(const ParamSet& p, std::vector<std::string>& warnings) {
    const double hither = p.getFloat("hither", 1e-3), yon = p.getFloat("yon", 1e30);
    if (hither > 1e-3 || yon < 1e30)
        warnings.push_back(describe(p.where()) + ": hither " + formatNumber(hither) + " / yon " + formatNumber(yon) +
                           " not applied: camera rays run uncut from the front lens element");
}

// Runs `build`, reporting the optics' own errors at the Camera directive; errors about a setting
// already name where it came from (a scene line, or a command-line flag that overrode it).
template <class Build>
auto atCamera(const ParamSet& p, Build build) -> decltype(build()) {
    try {
        return build();
    } catch (const SetupCancelled&) {
        throw RenderCancelled();
    } catch (const SettingError& e) {
        throw SceneError(e.what());
    } catch (const OpticsError& e) {
        p.fail(e.what());
    } catch (const LensTableError& e) {
        p.fail(e.what());
    }
}

ApertureShape apertureShape(const SceneDescription& scene, const ParamSet& p) {
    const std::string name = p.getString("aperture", "circular");
    if (ApertureShape::isNamed(name)) return ApertureShape::named(name);
    const std::string image = resolveScenePath(scene, name, p.where());
    try {
        return ApertureShape::fromImage(image);
    } catch (const std::runtime_error& e) {
        p.fail(std::string(e.what()) + " (aperture: circular, gaussian, square, pentagon, star or an image file)");
    }
}

// Everything the realistic camera's Camera directive and the overrides say, the lens read; nothing
// measured yet (the exit pupil's setup is the camera's own).
// The lens flare asked for: the settings' ghosts and ghost model, else the camera's parameters.
GhostSelection ghostSelection(const ParamSet& p, const CameraOverrides& o) {
    const std::string ghosts = o.ghosts.value_or(p.getString("ghosts", "off"));
    std::optional<GhostSelection> s = parseGhostSelection(ghosts);
    if (!s) {
        if (o.ghosts) throw SceneError(badGhostsMessage(ghosts));
        p.fail(badGhostsMessage(ghosts));
    }
    const std::string model = o.ghostModel.value_or(p.getString("ghostmodel", "exact"));
    const std::optional<GhostModel> m = parseGhostModel(model);
    if (!m) {
        if (o.ghostModel) throw SceneError(badGhostModelMessage(model));
        p.fail(badGhostModelMessage(model));
    }
    s->model = *m;
    return *s;
}

// The lens's tilt, swing and shift (LensMount.h): the scene's "lenstilt", "lensswing" (degrees)
// and "lensshift" (x y, lens millimetres), each replaced by its override.
LensMount lensMount(const ParamSet& p, const CameraOverrides& o) {
    LensMount m;
    m.tiltDegrees = o.tiltDegrees.value_or(p.getFloat("lenstilt", 0));
    m.swingDegrees = o.swingDegrees.value_or(p.getFloat("lensswing", 0));
    if (o.shiftMm) {
        m.shiftMm = *o.shiftMm;
    } else if (p.has("lensshift")) {
        const std::vector<double> shift = p.getFloats("lensshift");
        if (shift.size() != 2) p.fail("lensshift needs two numbers, x and y in millimetres");
        m.shiftMm = {shift[0], shift[1]};
    }
    atCamera(p, [&] { return bodyFromLens(m, 0); });  // the ranges, named by the camera's line
    return m;
}

RealisticParams readRealisticParams(SceneDescription& scene, const CameraOverrides& o) {
    const ParamSet& p = scene.camera.params;
    refuseSynonyms(p, {"specfile", "lensfile"}, "the lens table");
    refuseSynonyms(p, {"fstop", "aperture_diameter", "aperturediameter"}, "the aperture");
    refuseSynonyms(p, {"focaldistance", "filmdistance", "focusdistance"}, "the focus");
    refuseSynonyms(p, {"filmdiagonal", "filmdiag"}, "the film diagonal");
    // Three generations of names (docs/camera-conventions.md). The course's (specfile: fstop,
    // focaldistance, filmdiagonal; later filmdistance, aperture_diameter, filmdiag) have camera space
    // in millimetres; pbrt-v3/v4's lensfile puts it in metres (lens mm x 0.001), with focusdistance
    // in those units measured from the film, a 1 mm opening and simple weighting by default; and its
    // camera space starts at the film, where the course's starts at the front lens vertex.
    const bool pbrtStyle = p.has("lensfile");
    RealisticParams r;
    r.cameraUnitMm = pbrtStyle ? 1000 : 1;
    r.originAtFilm = pbrtStyle;
    const std::string lensName = pbrtStyle ? p.getString("lensfile", "") : p.getString("specfile", "");
    if (lensName.empty() && !o.lensFile) p.fail("needs \"string specfile\" (or pbrt-v3's \"lensfile\")");
    // The scene's own lens: the one rendered, or (under an override) the one its filmdistance was set for.
    const auto sceneLens = [&] { return resolveScenePath(scene, lensName, p.where()); };
    r.lensPath = o.lensFile ? *o.lensFile : sceneLens();
    r.lens = atCamera(p, [&] { return loadLensSystem(r.lensPath, o.lensFile ? o.lensLayout : std::nullopt); });

    // The scene's settings, each named by its parameter; the caller's overrides replace them.
    const auto sceneSetting = [&](const char* name, double scale = 1) -> std::optional<Setting> {
        if (!p.has(name)) return std::nullopt;
        return Setting{scale * p.getFloat(name, 0), describe(p.where()) + ": " + name};
    };
    LensSettings& s = r.settings;
    s.fstop = sceneSetting("fstop");
    s.stopDiameter = p.has("aperture_diameter") ? sceneSetting("aperture_diameter") : sceneSetting("aperturediameter");
    if (pbrtStyle && !s.fstop && !s.stopDiameter)
        s.stopDiameter = Setting{1.0, describe(p.where()) + ": aperturediameter (pbrt-v3's default, 1 mm)"};
    if (o.fstop) {
        s.fstop = o.fstop;
        s.stopDiameter.reset();
    }
    s.filmDistance = sceneSetting("filmdistance");
    s.focusFromFilm = p.has("focusdistance") || (pbrtStyle && !p.has("focaldistance"));
    if (s.filmDistance) {
        s.focusFromFilm = false;
    } else if (s.focusFromFilm) {
        s.focusDistance = p.has("focusdistance") ? sceneSetting("focusdistance", r.cameraUnitMm)
                                                 : Setting{r.cameraUnitMm * 10, describe(p.where()) + ": focusdistance (pbrt-v3's default, 10 units)"};
    } else {
        s.focusDistance = p.has("focaldistance") ? sceneSetting("focaldistance")
                                                 : Setting{10000, describe(p.where()) + ": focaldistance (default, 10 m)"};
    }
    if (o.focusDistance) {
        s.focusDistance = o.focusDistance;
        s.focusFromFilm = false;
        s.filmDistance.reset();
    } else if (o.lensFile && s.filmDistance) {
        // A film distance belongs to the scene's lens: another lens focuses where that one did.
        const std::string ownPath = sceneLens();
        const double distance = atCamera(p, [&] {
            const LensSystem own = loadLensSystem(ownPath);
            return thickLensFocusForFilm(own, computeFirstOrder(own), own.rearZ() - s.filmDistance->value);
        });
        s.focusDistance = Setting{distance, s.filmDistance->source + " (where the scene's own lens focuses)"};
        s.filmDistance.reset();
    }
    s.wavelength = o.wavelength;
    if (o.spectral.value_or(false) && o.wavelength)
        throw SceneError(o.wavelength->source + " traces the lens at one wavelength; a spectral render traces them all");
    const double sceneDiagonal = p.has("filmdiag") ? p.getFloat("filmdiag", 35) : p.getFloat("filmdiagonal", scene.film.diagonalMm);
    r.filmDiagonalMm = o.filmDiagonal.value_or(sceneDiagonal);
    const std::string mode = o.mode.value_or(p.getString("mode", "exact"));
    const std::optional<LensMode> lensMode = parseLensMode(mode);
    if (!lensMode) p.fail("mode must be exact|thick|auto, got \"" + mode + "\"");
    r.mode = *lensMode;
    r.mount = lensMount(p, o);
    if (r.mount.isMoved() && o.spectral.value_or(false))
        throw SceneError("a tilted or shifted lens renders in RGB at one wavelength: spectral on cannot be had with it");
    // The thick lens has no dispersion: its film stays RGB unless asked; a moved lens too.
    r.spectral = o.spectral.value_or(!o.wavelength && r.mode != LensMode::Thick && !r.mount.isMoved()) && r.lens.isDispersive();
    r.autoThresholdPixels = p.getFloat("autothreshold", r.autoThresholdPixels);
    r.crop = scene.film.crop;  // the effective window: the render settings' crop overrides the scene's
    checkClipping(p, scene.warnings);
    if (scene.dialect == SceneDialect::PbrtV4) {
        // pbrt-v4 always weights by the exit pupil (cos^4 A / d^2: lenslab's radiometric weight);
        // the shutter's exposure time scales the film instead (scene/SceneParser.cpp).
        r.exposureTime = 1;
        r.simpleWeighting = false;
    } else {
        r.exposureTime = exposureTime(p, scene.warnings);
        r.simpleWeighting = p.getBool("simpleweighting", pbrtStyle);
        r.pbrtExposure = pbrtStyle;
    }
    r.aperture = apertureShape(scene, p);
    r.ghosts = ghostSelection(p, o);
    if (r.mount.isMoved() && r.ghosts.on()) {
        // Auto asks for what the scene requires, and flare through a moved lens is not modelled.
        if (r.ghosts.mode != GhostSelection::Mode::Auto)
            throw SceneError("lens flare is not modelled for a tilted or shifted lens: ghosts must be off or auto");
        r.ghosts.mode = GhostSelection::Mode::Off;
    }
    p.checkAllUsed(scene.warnings, {"frameaspectratio", "screenwindow"});
    return r;
}

std::unique_ptr<Camera> makeRealistic(SceneDescription& scene, const CameraOverrides& o, const Transform& cameraToWorld,
                                      int width, int height, double margin, const std::atomic<bool>* cancel) {
    const RealisticParams r = readRealisticParams(scene, o);
    return atCamera(scene.camera.params, [&]() -> std::unique_ptr<Camera> {
        return std::make_unique<RealisticCamera>(r, cameraToWorld, width, height, margin, cancel);
    });
}

std::unique_ptr<Camera> makeOrthographic(const SceneDescription& scene, const Transform& cameraToWorld, int width, int height) {
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
    return std::make_unique<OrthographicCamera>(o, cameraToWorld, width, height);
}

// The camera of the scene's type, placed in the world by cameraToWorld.
std::unique_ptr<Camera> makePlacedCamera(SceneDescription& scene, const CameraOverrides& o, const Transform& cameraToWorld,
                                         int width, int height, double filmMarginPixels, const std::atomic<bool>* cancel) {
    const ParamSet& p = scene.camera.params;
    if (scene.camera.type == "realistic") return makeRealistic(scene, o, cameraToWorld, width, height, filmMarginPixels, cancel);
    if (o.lensFile || o.fstop || o.focusDistance || o.wavelength || o.filmDiagonal || o.mode)
        throw SceneError(scene.file + ": the lens overrides need a Camera \"realistic\"; this scene has a " +
                         scene.camera.type + " camera");
    // Lens flare comes from a lens: asked of another camera it is refused, unless only "if needed".
    if (o.ghosts || o.ghostModel) {
        const GhostSelection ghosts = ghostSelection(ParamSet{}, o);
        if (ghosts.on() && ghosts.mode != GhostSelection::Mode::Auto)
            throw SceneError(scene.file + ": ghosts need a Camera \"realistic\" (lens flare comes from a lens's surfaces); this "
                             "scene has a " + scene.camera.type + " camera");
    }
    if (scene.camera.type == "environment") {
        p.checkAllUsed(scene.warnings, {"shutteropen", "shutterclose", "frameaspectratio", "screenwindow"});
        return std::make_unique<EnvironmentCamera>(cameraToWorld, width, height);
    }
    if (scene.camera.type == "orthographic") {
        auto camera = makeOrthographic(scene, cameraToWorld, width, height);
        p.checkAllUsed(scene.warnings, {"shutteropen", "shutterclose", "frameaspectratio"});
        return camera;
    }
    PerspectiveParams pp;
    // pbrt-v3 also reads "halffov" (pbrt-v1's name), which wins when positive.
    const double halfFov = p.getFloat("halffov", -1);
    const double fov = halfFov > 0 ? 2 * halfFov : p.getFloat("fov", 90);
    if (!(fov > 0 && fov < 180)) p.fail("fov must lie in (0, 180) degrees");
    pp.fovDegrees = fov;
    pp.lensRadius = p.getFloat("lensradius", 0);
    pp.focalDistance = p.getFloat("focaldistance", 1e6);
    if (pp.lensRadius < 0 || !(pp.focalDistance > 0)) p.fail("lensradius must be >= 0 and focaldistance > 0 (metres)");
    p.checkAllUsed(scene.warnings, {"shutteropen", "shutterclose"});
    return std::make_unique<PerspectiveCamera>(pp, cameraToWorld, width, height);
}

}  // namespace

void checkCameraSettings(SceneDescription& scene, const CameraOverrides& overrides) {
    if (scene.camera.type != "realistic") {
        makePlacedCamera(scene, overrides, Transform{}, 1, 1, 0, nullptr);
        return;
    }
    const RealisticParams r = readRealisticParams(scene, overrides);
    atCamera(scene.camera.params, [&] { return analyzeLens(r.lens, r.settings); });
}

std::unique_ptr<Camera> makeCamera(SceneDescription& scene, const CameraOverrides& o, int width, int height,
                                   double filmMarginPixels, const std::atomic<bool>* cancel) {
    const AnimatedTransform& cameraToWorld = scene.camera.cameraToWorld;
    if (!cameraToWorld.moves())
        return makePlacedCamera(scene, o, cameraToWorld.start(), width, height, filmMarginPixels, cancel);
    return std::make_unique<MovingCamera>(makePlacedCamera(scene, o, Transform{}, width, height, filmMarginPixels, cancel),
                                          cameraToWorld);
}

}  // namespace lenslab
