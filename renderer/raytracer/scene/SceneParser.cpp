// pbrt-v3 scene syntax. Like pbrt-v3, an unknown or unused parameter is a warning naming its file
// and line; a feature lenslab cannot render is an error naming it where the picture would be wrong
// in a way the user must know, and a warning where a faithful substitute renders instead.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "core/CameraSensorCurves.h"
#include "core/CompressedFile.h"
#include "scene/DialectDetection.h"
#include "images/LinearImage.h"
#include "lights/Pbrt4Emission.h"
#include "scene/ParamList.h"
#include "Render.h"
#include "scene/SceneDescription.h"
#include "scene/TokenCursor.h"

namespace fs = std::filesystem;

namespace lenslab {

std::string resolveScenePath(const SceneDescription& scene, const std::string& name, const SourceLocation& where) {
    if (name.empty()) sceneFail(where, "empty file name");
    const fs::path given(name);
    const fs::path p = fs::weakly_canonical(given.is_absolute() ? given : fs::path(scene.rootDir) / given);
    if (scene.confined) {
        const auto rel = p.lexically_relative(fs::weakly_canonical(fs::path(scene.rootDir)));
        if (rel.empty() || *rel.begin() == "..")
            sceneFail(where, "'" + name + "' lies outside the scene's folder " + scene.rootDir +
                                 " (scenes served over HTTP may only name files in their folder tree)");
    }
    if (!fs::is_regular_file(p)) sceneFail(where, "cannot open '" + name + "' (looked for " + p.string() + ")");
    return p.string();
}

namespace {

constexpr int kMaxIncludeDepth = 32;

// pbrt-v3 keeps two current transforms, for shutter open and close (motion blur).
struct TransformPair {
    Transform start, end;
};

struct GraphicsState {
    Transform ctm;      // at the start time (TransformTimes)
    Transform ctmEnd;   // at the end time
    // Which of the two the transform directives change (ActiveTransform). Scoped like the
    // transforms themselves, as in pbrt-v3 and pbrt-v4: AttributeEnd and TransformEnd restore it,
    // WorldBegin resets it to both.
    bool activeStart = true, activeEnd = true;
    std::shared_ptr<const Material> material;
    std::optional<AreaEmission> area;
    bool reverseOrientation = false;
    std::string insideMedium, outsideMedium;  // MediumInterface's names; empty is vacuum
    // Scoped by AttributeBegin/End as in pbrt-v3; shared with the saved states until a Texture
    // directive changes it (copy on write: entering a block copies no textures).
    std::shared_ptr<TextureMap> textures = std::make_shared<TextureMap>();
    // pbrt-v4's Attribute "shape" | "light" | "material" | "texture": parameters every later
    // directive of that kind takes unless it gives its own.
    std::map<std::string, ParamSet> defaults;
};

struct StackEntry {
    bool attribute;  // AttributeBegin (whole state) or TransformBegin (transform only)
    GraphicsState state;
    SourceLocation where;
};

enum class Phase { Options, World, Anywhere };

class Parser {
public:
    Parser(SceneDescription& scene, const SceneParseOptions& options) : scene_(scene), options_(options) {
        g_.material = makeDefaultMaterial();
        integratorWhere_.file = scene.file;
    }

    void parseFile(const std::string& path) {
        std::vector<Token> tokens = readTokens(path);
        scene_.dialect = detectDialect(tokens);
        in_.include(path, std::move(tokens));
        while (!in_.atEnd() && !(options_.optionsOnly && worldBegun_)) {
            directive();
            if (options_.progress) options_.progress(in_.fraction());
        }
    }

    void finish() {
        if (object_) sceneFail(objectWhere_, "not closed by ObjectEnd");
        if (!cameraMedium_.empty()) scene_.camera.medium = namedMedium(cameraMediumWhere_, cameraMedium_);
        chooseMediaIntegrator();
        if (!stack_.empty())
            sceneFail(stack_.back().where, "not closed by " + std::string(stack_.back().attribute ? "AttributeEnd" : "TransformEnd"));
        if (!worldBegun_) throw SceneError(scene_.file + ": no WorldBegin: the scene describes no world");
        if (scene_.dialect == SceneDialect::PbrtV4) applyPbrt4Exposure();
    }

private:
    using Handler = void (Parser::*)(SourceLocation&);
    struct DirectiveEntry {
        Handler handler;
        Phase phase;
    };

    static std::vector<Token> readTokens(const std::string& path) {
        const std::optional<std::string> text = readPossiblyGzipped(path);  // pbrt-v4's .pbrt.gz too
        if (!text) throw SceneError("cannot open scene file '" + path + "'");
        return tokenizeScene(*text, path);
    }
    double number(const SourceLocation& where) { return in_.number(where); }
    std::string quoted(const SourceLocation& where, const char* what) { return in_.quoted(where, what); }
    PathResolver resolver() const {
        return [this](const std::string& name, const SourceLocation& at) { return resolveScenePath(scene_, name, at); };
    }
    ParamSet params(const SourceLocation& where) { return readParamList(in_, where, resolver()); }
    void warn(const SourceLocation& where, const std::string& message) {
        scene_.warnings.push_back(describe(where) + ": " + message);
    }
    // The directive's quoted type name, added to `where` for messages: Shape "disk".
    std::string typeName(SourceLocation& where, const char* what) {
        const std::string type = quoted(where, what);
        where.directive += " \"" + type + "\"";
        return type;
    }

    void directive() {
        const Token tok = in_.take({scene_.file, 0, ""}, "a directive");
        SourceLocation where = locate(tok, {"", 0, tok.text});
        if (tok.quoted || tok.text == "[" || tok.text == "]") sceneFail(where, "expected a directive, got '" + tok.text + "'");
        if (worldEnded_) {
            warn(where, "ignoring everything after WorldEnd");
            in_.skipToEnd();
            return;
        }
        const auto& table = directives();
        const auto it = table.find(tok.text);
        if (it == table.end()) sceneFail(where, "unsupported directive '" + tok.text + "'");
        if (it->second.phase == Phase::World && !worldBegun_) sceneFail(where, "only allowed after WorldBegin");
        if (it->second.phase == Phase::Options && worldBegun_) sceneFail(where, "only allowed before WorldBegin");
        try {
            (this->*it->second.handler)(where);
        } catch (const std::domain_error& e) {  // singular or degenerate transforms
            sceneFail(where, e.what());
        }
    }

    static const std::map<std::string, DirectiveEntry>& directives() {
        static const std::map<std::string, DirectiveEntry> table = {
            {"Translate", {&Parser::translateDirective, Phase::Anywhere}},
            {"Scale", {&Parser::scaleDirective, Phase::Anywhere}},
            {"Rotate", {&Parser::rotateDirective, Phase::Anywhere}},
            {"LookAt", {&Parser::lookAtDirective, Phase::Anywhere}},
            {"Transform", {&Parser::matrixDirective, Phase::Anywhere}},
            {"ConcatTransform", {&Parser::matrixDirective, Phase::Anywhere}},
            {"Identity", {&Parser::identityDirective, Phase::Anywhere}},
            {"CoordinateSystem", {&Parser::coordinateSystem, Phase::Anywhere}},
            {"CoordSysTransform", {&Parser::coordSysTransform, Phase::Anywhere}},
            {"ActiveTransform", {&Parser::activeTransform, Phase::Anywhere}},
            {"TransformTimes", {&Parser::transformTimes, Phase::Options}},
            {"AttributeBegin", {&Parser::beginBlock, Phase::Anywhere}},
            {"TransformBegin", {&Parser::beginBlock, Phase::Anywhere}},
            {"AttributeEnd", {&Parser::endBlock, Phase::Anywhere}},
            {"TransformEnd", {&Parser::endBlock, Phase::Anywhere}},
            {"ReverseOrientation", {&Parser::reverseOrientation, Phase::Anywhere}},
            {"Include", {&Parser::include, Phase::Anywhere}},
            {"Import", {&Parser::include, Phase::Anywhere}},
            {"Option", {&Parser::option, Phase::Anywhere}},
            {"ColorSpace", {&Parser::ignoredName, Phase::Anywhere}},
            {"Camera", {&Parser::camera, Phase::Options}},
            {"Film", {&Parser::film, Phase::Options}},
            {"Sampler", {&Parser::sampler, Phase::Options}},
            {"Integrator", {&Parser::integrator, Phase::Options}},
            {"SurfaceIntegrator", {&Parser::integrator, Phase::Options}},  // pbrt-v2's name
            {"VolumeIntegrator", {&Parser::volumeIntegrator, Phase::Options}},
            {"Renderer", {&Parser::renderer, Phase::Options}},
            {"Volume", {&Parser::volume, Phase::World}},
            {"PixelFilter", {&Parser::filter, Phase::Options}},
            {"Accelerator", {&Parser::accelerator, Phase::Options}},
            {"MakeNamedMedium", {&Parser::medium, Phase::Anywhere}},
            {"MediumInterface", {&Parser::mediumInterface, Phase::Anywhere}},
            {"WorldBegin", {&Parser::worldBegin, Phase::Options}},
            {"WorldEnd", {&Parser::worldEnd, Phase::World}},
            {"Shape", {&Parser::shapeDirective, Phase::World}},
            {"ObjectBegin", {&Parser::objectBegin, Phase::World}},
            {"ObjectEnd", {&Parser::objectEnd, Phase::World}},
            {"ObjectInstance", {&Parser::objectInstance, Phase::World}},
            {"Material", {&Parser::material, Phase::World}},
            {"MakeNamedMaterial", {&Parser::makeNamedMaterial, Phase::World}},
            {"NamedMaterial", {&Parser::namedMaterial, Phase::World}},
            {"Texture", {&Parser::textureDirective, Phase::World}},
            {"LightSource", {&Parser::lightSource, Phase::World}},
            {"AreaLightSource", {&Parser::areaLightSource, Phase::World}},
            {"Attribute", {&Parser::attribute, Phase::Anywhere}},
        };
        return table;
    }

    // --- transforms -------------------------------------------------------------------------
    // Applies t to the transforms ActiveTransform selected (both unless told otherwise).
    void applyTransform(const Transform& t) {
        if (g_.activeStart) g_.ctm = g_.ctm * t;
        if (g_.activeEnd) g_.ctmEnd = g_.ctmEnd * t;
    }
    void setTransform(const Transform& t) {
        if (g_.activeStart) g_.ctm = t;
        if (g_.activeEnd) g_.ctmEnd = t;
    }
    void translateDirective(SourceLocation& where) {
        const double x = number(where), y = number(where), z = number(where);
        applyTransform(translate(x, y, z));
    }
    void scaleDirective(SourceLocation& where) {
        const double x = number(where), y = number(where), z = number(where);
        if (x == 0 || y == 0 || z == 0) sceneFail(where, "zero scale factor");
        applyTransform(scale(x, y, z));
    }
    void rotateDirective(SourceLocation& where) {
        const double a = number(where), x = number(where), y = number(where), z = number(where);
        applyTransform(rotate(a, x, y, z));
    }
    void lookAtDirective(SourceLocation& where) {
        double v[9];
        for (double& x : v) x = number(where);
        applyTransform(lookAt(v, v + 3, v + 6));
    }
    void matrixDirective(SourceLocation& where) {
        const std::vector<double> v = in_.numberArray(where, 16);
        Matrix44 m;
        for (int i = 0; i < 16; ++i) m.m[i % 4][i / 4] = v[i];  // pbrt lists the matrix column by column
        const Transform t = makeTransform(m);
        if (where.directive == "Transform") setTransform(t);
        else applyTransform(t);
    }
    void identityDirective(SourceLocation&) { setTransform(Transform{}); }
    void coordinateSystem(SourceLocation& where) { namedCoordinates_[quoted(where, "a name")] = {g_.ctm, g_.ctmEnd}; }
    // Both keyframes, whatever ActiveTransform says (as pbrt-v3 and pbrt-v4 do): a named system
    // is a whole motion.
    void coordSysTransform(SourceLocation& where) {
        const std::string n = quoted(where, "a name");
        auto it = namedCoordinates_.find(n);
        if (it == namedCoordinates_.end()) sceneFail(where, "unknown coordinate system \"" + n + "\"");
        g_.ctm = it->second.start;
        g_.ctmEnd = it->second.end;
    }
    void activeTransform(SourceLocation& where) {
        const Token& t = in_.take(where, "StartTime, EndTime or All");
        if (t.quoted || (t.text != "StartTime" && t.text != "EndTime" && t.text != "All"))
            sceneFail(where, "expected StartTime, EndTime or All, got '" + t.text + "'");
        g_.activeStart = t.text != "EndTime";
        g_.activeEnd = t.text != "StartTime";
    }
    void transformTimes(SourceLocation& where) {
        const double start = number(where), end = number(where);
        if (!(end >= start)) sceneFail(where, "the end time must not precede the start time");
        scene_.transformTimes = {start, end};
    }
    AnimatedTransform currentMotion() const { return {g_.ctm, g_.ctmEnd}; }
    // What cannot move in lenslab (as in pbrt-v3: lights, textures; and, unlike pbrt-v4, area lights
    // and shapes inside an object, which Embree would have to instance two levels deep) stands where
    // the start transform puts it.
    void warnIfMoving(const SourceLocation& where, const char* what) {
        if (currentMotion().moves()) warn(where, std::string(what) + " cannot move during the exposure: drawn at the start time");
    }

    // --- blocks and files -------------------------------------------------------------------
    void beginBlock(SourceLocation& where) { stack_.push_back({where.directive == "AttributeBegin", g_, where}); }
    void endBlock(SourceLocation& where) {
        const bool attribute = where.directive == "AttributeEnd";
        if (stack_.empty()) sceneFail(where, "without a matching " + std::string(attribute ? "AttributeBegin" : "TransformBegin"));
        if (stack_.back().attribute != attribute) sceneFail(where, "closes " + describe(stack_.back().where) + " (mismatched nesting)");
        if (attribute) {
            g_ = stack_.back().state;
        } else {
            g_.ctm = stack_.back().state.ctm;
            g_.ctmEnd = stack_.back().state.ctmEnd;
            g_.activeStart = stack_.back().state.activeStart;
            g_.activeEnd = stack_.back().state.activeEnd;
        }
        stack_.pop_back();
    }
    void reverseOrientation(SourceLocation&) { g_.reverseOrientation = !g_.reverseOrientation; }
    // pbrt splices the file's tokens into the stream: its last directive may take parameters that
    // follow the Include.
    void include(SourceLocation& where) {
        const std::string path = resolveScenePath(scene_, quoted(where, "a file name"), where);
        if (in_.depth() > kMaxIncludeDepth) sceneFail(where, "Include nested deeper than 32 (a cycle?)");
        in_.include(path, readTokens(path));
    }
    void ignoredName(SourceLocation& where) {
        warn({where.file, where.line, where.directive + " \"" + quoted(where, "a name") + "\""}, "ignored (lenslab renders in linear sRGB)");
    }
    // pbrt-v4's Option "TYPE NAME" value: renderer settings that do not change the picture's meaning.
    void option(SourceLocation& where) {
        params(where);
        warn(where, "ignored (a pbrt-v4 rendering option lenslab does not use)");
    }

    // pbrt-v4's Attribute: defaults for the parameters of later directives of one kind, scoped
    // like the rest of the graphics state.
    void attribute(SourceLocation& where) {
        const std::string target = typeName(where, "shape, light, material, medium or texture");
        const ParamSet p = params(where);
        if (target == "medium") {
            warn(where, "ignored (medium parameter defaults are not applied: give each MakeNamedMedium its parameters)");
            return;
        }
        if (target != "shape" && target != "light" && target != "material" && target != "texture")
            p.fail("Attribute needs \"shape\", \"light\", \"material\", \"medium\" or \"texture\", not \"" + target + "\"");
        g_.defaults[target] = p.withDefaults(g_.defaults[target]);
    }
    // A directive's parameters with the Attribute defaults of its kind.
    ParamSet paramsOf(const char* kind, const SourceLocation& where) {
        const ParamSet own = params(where);
        const auto it = g_.defaults.find(kind);
        return it == g_.defaults.end() ? own : own.withDefaults(it->second);
    }

    // --- rendering options ------------------------------------------------------------------
    void camera(SourceLocation& where) {
        const std::string type = typeName(where, "a camera type");
        if (type != "perspective" && type != "realistic" && type != "orthographic" && type != "environment" && type != "spherical")
            sceneFail(where, "camera \"" + type + "\" is not supported (perspective, orthographic, environment, spherical, realistic)");
        scene_.camera.params = params(where);
        scene_.camera.type = type;
        if (type == "spherical") {  // pbrt-v4's; its equirectangular mapping is pbrt-v3's environment camera
            const std::string mapping = scene_.camera.params.getString("mapping", "equalarea");
            if (mapping != "equirectangular")
                scene_.camera.params.fail("spherical camera mapping \"" + mapping + "\" is not supported (equirectangular)");
            scene_.camera.type = "environment";
        }
        scene_.camera.cameraToWorld = AnimatedTransform(inverse(g_.ctm), inverse(g_.ctmEnd));
        // pbrt's camera sits in the outside medium current here; media may be named later.
        cameraMedium_ = g_.outsideMedium;
        cameraMediumWhere_ = where;
        namedCoordinates_["camera"] = {inverse(g_.ctm), inverse(g_.ctmEnd)};
    }
    void accelerator(SourceLocation& where) {
        typeName(where, "an accelerator type");
        params(where);
        warn(where, "ignored (lenslab always uses Embree's BVH)");
    }
    // --- participating media -----------------------------------------------------------------
    void medium(SourceLocation& where) {
        const std::string name = typeName(where, "a medium name");
        const ParamSet p = params(where);
        if (!p.has("type")) p.fail("MakeNamedMedium needs \"string type\"");
        if (namedMedia_.count(name)) warn(where, "redefines medium \"" + name + "\" for what follows");
        namedMedia_[name] = makeMedium(p.getString("type", ""), p, g_.ctm, resolver(), scene_.warnings);
        warnIfMoving(where, "a medium");
    }
    // pbrt-v3 gives one name for both sides too.
    void mediumInterface(SourceLocation& where) {
        g_.insideMedium = quoted(where, "a medium name");
        g_.outsideMedium = !in_.atEnd() && in_.peek().quoted ? quoted(where, "a medium name") : g_.insideMedium;
    }
    std::shared_ptr<const ParticipatingMedium> namedMedium(const SourceLocation& where, const std::string& name) {
        if (name.empty()) return nullptr;
        const auto it = namedMedia_.find(name);
        if (it == namedMedia_.end()) sceneFail(where, "unknown medium \"" + name + "\" (no MakeNamedMedium defines it before here)");
        mediaUsed_ = true;
        return it->second;
    }
    // Media show only through an integrator that renders them: volpath, and bdpt, mlt and sppm,
    // which render media in pbrt too (here by volpath). path, directlighting and whitted ignore
    // them, as in pbrt. Without an Integrator, pbrt-v3 traces paths and pbrt-v4 runs volpath (the
    // path tracer's picture wherever there is neither medium nor subsurface material).
    void chooseMediaIntegrator() {
        IntegratorSpec& spec = scene_.integrator;
        const bool v4Default = !integratorGiven_ && scene_.dialect == SceneDialect::PbrtV4;
        if (subsurfaceWhere_ && spec.type != IntegratorType::VolPath) {
            spec.type = IntegratorType::VolPath;
            if (!v4Default)
                warn(integratorWhere_, "rendered by volpath (pbrt-v4's default integrator): the subsurface material at " +
                                           describe(*subsurfaceWhere_) + " scatters light in a volume, which only volpath follows");
            return;
        }
        if (!mediaUsed_) return;
        if (integratorRendersMedia_ || v4Default) {
            spec.type = IntegratorType::VolPath;
        } else {
            warn(integratorWhere_, "ignores the scene's participating media, as in pbrt (Integrator \"volpath\" renders them)");
        }
    }
    void worldBegin(SourceLocation&) {
        worldBegun_ = true;
        g_.ctm = g_.ctmEnd = Transform{};
        g_.activeStart = g_.activeEnd = true;
        namedCoordinates_["world"] = {Transform{}, Transform{}};
    }
    void worldEnd(SourceLocation&) { worldEnded_ = true; }

    void film(SourceLocation& where) {
        const std::string type = typeName(where, "a film type");
        const ParamSet p = params(where);
        const bool v4 = scene_.dialect == SceneDialect::PbrtV4;
        if (type != "image" && !(v4 && type == "rgb"))
            warn(where, "film \"" + type + "\" is rendered as an RGB film");
        FilmSpec& f = scene_.film;
        f.where = where;
        f.xresolution = p.getInt("xresolution", 1280);
        f.yresolution = p.getInt("yresolution", 720);
        f.filename = p.getString("filename", "");
        f.diagonalMm = p.getFloat("diagonal", 35);
        if (!(f.diagonalMm > 0 && f.diagonalMm < 1e4)) p.fail("diagonal must lie in (0, 10000) mm");
        if (p.has("cropwindow")) {
            const auto c = p.getFloats("cropwindow");
            if (c.size() != 4) p.fail("cropwindow needs 4 numbers: x0 x1 y0 y1");
            for (int i = 0; i < 4; ++i) f.crop[i] = c[i];
        }
        f.scale = p.getFloat("scale", 1);
        if (!(f.scale > 0)) p.fail("scale must be positive");
        f.maxSampleLuminance = p.getFloat("maxsampleluminance", 0);
        if (f.maxSampleLuminance < 0) p.fail("maxsampleluminance must not be negative");
        if (v4) readPbrt4Sensor(p, f);
        p.checkAllUsed(scene_.warnings, {"savefp16", "writefp16"});
    }

    // pbrt-v4's sensor: an ISO speed, a white balance and the CIE 1931 observer or a measured
    // camera (film/MeasuredCameraSensor.h); the exposure time comes from the camera's shutter
    // (applyPbrt4Exposure).
    void readPbrt4Sensor(const ParamSet& p, FilmSpec& f) {
        f.iso = p.getFloat("iso", 100);
        if (!(f.iso > 0)) p.fail("iso must be positive");
        const std::string sensor = p.getString("sensor", "cie1931");
        if (sensor != "cie1931" && !findCameraSensorCurves(sensor))
            p.fail("unknown sensor \"" + sensor + "\" (known: cie1931, " + cameraSensorNames() + ")");
        if (sensor != "cie1931") f.cameraSensor = sensor;
        f.whiteBalanceKelvin = p.getFloat("whitebalance", 0);
        if (f.whiteBalanceKelvin != 0 && !(f.whiteBalanceKelvin >= 1000 && f.whiteBalanceKelvin <= 25000))
            p.fail("whitebalance must lie in [1000, 25000] K (or 0: none)");
        // pbrt-v4 balances a camera for 6500 K unless told otherwise; the observer, not at all.
        if (!f.cameraSensor.empty() && f.whiteBalanceKelvin == 0) f.whiteBalanceKelvin = 6500;
        f.maxComponentValue = p.getFloat("maxcomponentvalue", 0);
        if (f.maxComponentValue < 0) p.fail("maxcomponentvalue must not be negative");
    }
    // pbrt-v4 scales the image by the exposure time (shutterclose - shutteropen) times ISO / 100.
    void applyPbrt4Exposure() {
        const ParamSet& c = scene_.camera.params;
        const double exposure = c.getFloat("shutterclose", 1) - c.getFloat("shutteropen", 0);
        if (!(exposure > 0)) c.fail("shutterclose must come after shutteropen");
        scene_.film.scale *= exposure * scene_.film.iso / 100;
    }

    void sampler(SourceLocation& where) {
        const std::string type = typeName(where, "a sampler type");
        const ParamSet p = params(where);
        if (type == "stratified") scene_.pixelSamples = p.getInt("xsamples", 4) * p.getInt("ysamples", 4);
        else scene_.pixelSamples = p.getInt("pixelsamples", 16);
        p.checkAllUsed(scene_.warnings, {"jitter", "dimensions", "seed"});
        if (type != "sobol" && type != "zsobol" && type != "zerotwosequence" && type != "02sequence" && type != "lowdiscrepancy")
            warn(where, "lenslab uses its own Owen-scrambled Sobol'/Faure sampler (noise differs, not the image)");
    }

    void integrator(SourceLocation& where) {
        const std::string type = typeName(where, "an integrator type");
        const ParamSet p = params(where);
        IntegratorSpec& spec = scene_.integrator;
        integratorWhere_ = where;
        integratorGiven_ = true;
        integratorRendersMedia_ =
            type == "volpath" || type == "simplevolpath" || type == "bdpt" || type == "mlt" || type == "sppm";
        // Global-illumination methods of pbrt-v3 and pbrt-v2 converge to the path tracer's picture
        // (media aside); the others compute something else and are refused.
        static const char* kGlobalIllumination[] = {"bdpt", "mlt", "sppm", "photonmap", "exphotonmap",
                                                    "irradiancecache", "igi", "dipolesubsurface",
                                                    // pbrt-v4's
                                                    "simplepath", "simplevolpath", "lightpath", "randomwalk"};
        if (type == "directlighting") {
            spec.type = IntegratorType::DirectLighting;
        } else if (type == "whitted") {
            spec.type = IntegratorType::Whitted;
        } else if (type == "path") {
            spec.type = IntegratorType::Path;
        } else if (type == "volpath") {
            spec.type = IntegratorType::VolPath;
        } else if (std::find(std::begin(kGlobalIllumination), std::end(kGlobalIllumination), type) != std::end(kGlobalIllumination)) {
            spec.type = IntegratorType::Path;
            warn(where, "integrator \"" + type + "\" rendered by the path tracer, volpath in media (same picture in the limit, other noise)");
        } else {
            p.fail("integrator \"" + type + "\" is not supported (path, volpath, directlighting, whitted; bdpt, mlt, sppm "
                   "and pbrt-v2's photonmap, irradiancecache, igi render as path, or as volpath in media)");
        }
        spec.maxDepth = p.getInt("maxdepth", 5);
        if (spec.maxDepth < 0 || spec.maxDepth > 1000) p.fail("maxdepth must lie in [0, 1000]");
        p.checkAllUsed(scene_.warnings, {"rrthreshold", "lightsamplestrategy", "strategy", "pixelbounds", "visualizestrategies",
                                         "visualizeweights", "bootstrapsamples", "chains", "mutationsperpixel",
                                         "largestepprobability", "sigma", "iterations", "photonsperiteration", "radius",
                                         "imagewritefrequency", "samples", "maxdistance", "cossample", "regularize"});
    }

    // pbrt-v2: its volumes are refused (Volume), so its volume integrator has nothing to do.
    void volumeIntegrator(SourceLocation& where) {
        typeName(where, "a volume integrator type");
        params(where);
        warn(where, "ignored (pbrt-v2 volumes are not read; pbrt-v3's media render with volpath)");
    }
    // pbrt-v2's Renderer: "sampler" is the ordinary one, "metropolis" converges to the same picture.
    void renderer(SourceLocation& where) {
        const std::string type = typeName(where, "a renderer type");
        const ParamSet p = params(where);
        if (type != "sampler" && type != "metropolis")
            p.fail("renderer \"" + type + "\" is not supported (sampler; metropolis renders as the path tracer)");
        if (type == "metropolis") warn(where, "rendered by the path tracer (same picture in the limit, other noise)");
    }
    void volume(SourceLocation& where) {
        sceneFail(where, "participating media (Volume \"" + quoted(where, "a volume type") + "\") are not supported: the picture would lack the medium");
    }

    void filter(SourceLocation& where) {
        const std::string type = typeName(where, "a filter type");
        const ParamSet p = params(where);
        // pbrt-v3's defaults: box 0.5, gaussian/mitchell/triangle 2, sinc 4 pixels.
        static const std::map<std::string, std::pair<FilterType, double>> kFilters = {
            {"box", {FilterType::Box, 0.5}},         {"gaussian", {FilterType::Gaussian, 2}},
            {"triangle", {FilterType::Triangle, 2}}, {"mitchell", {FilterType::Mitchell, 2}},
            {"sinc", {FilterType::Sinc, 4}}};
        const auto it = kFilters.find(type);
        if (it == kFilters.end()) p.fail("pixel filter \"" + type + "\" is not supported (box, gaussian, triangle, mitchell, sinc)");
        FilterSpec f;
        f.type = it->second.first;
        f.xwidth = p.getFloat("xwidth", it->second.second);
        f.ywidth = p.getFloat("ywidth", it->second.second);
        f.alpha = p.getFloat("alpha", 2);
        f.B = p.getFloat("B", 1.0 / 3);
        f.C = p.getFloat("C", 1.0 / 3);
        f.tau = p.getFloat("tau", 3);
        if (!(f.alpha > 0)) p.fail("alpha must be positive");
        if (!(f.tau > 0)) p.fail("tau must be positive");
        if (!(f.xwidth > 0 && f.xwidth <= 16 && f.ywidth > 0 && f.ywidth <= 16)) p.fail("filter widths must lie in (0, 16] pixels");
        scene_.filter = f;
        p.checkAllUsed(scene_.warnings);
    }

    // --- the world ----------------------------------------------------------------------------
    MaterialContext materialContext() { return {*g_.textures, namedMaterials_, resolver(), scene_.warnings}; }
    void material(SourceLocation& where) {
        const std::string type = typeName(where, "a material type");
        g_.material = makeMaterial(type, paramsOf("material", where), materialContext());
        noteSubsurface(*g_.material, where);
    }
    // A subsurface material's volume renders only in the volumetric path tracer (chooseMediaIntegrator).
    void noteSubsurface(const Material& m, const SourceLocation& where) {
        if (m.hasInterior() && !subsurfaceWhere_) subsurfaceWhere_ = where;
    }
    void makeNamedMaterial(SourceLocation& where) {
        const std::string n = typeName(where, "a material name");
        const ParamSet p = paramsOf("material", where);
        if (!p.has("type")) p.fail("MakeNamedMaterial needs \"string type\"");
        namedMaterials_[n] = makeMaterial(p.getString("type", ""), p, materialContext());
        noteSubsurface(*namedMaterials_[n], where);
    }
    void namedMaterial(SourceLocation& where) {
        const std::string n = quoted(where, "a material name");
        auto it = namedMaterials_.find(n);
        if (it == namedMaterials_.end()) sceneFail(where, "unknown material \"" + n + "\"");
        g_.material = it->second;
    }
    void textureDirective(SourceLocation& where) { texture(where); }
    void lightSource(SourceLocation& where) {
        const std::string type = typeName(where, "a light type");
        scene_.lights.push_back(makeLight(type, paramsOf("light", where), g_.ctm, scene_.dialect, resolver(), scene_.warnings));
        warnIfMoving(where, "a light");
    }
    // pbrt-v3 accepts "area" as another name for "diffuse".
    void areaLightSource(SourceLocation& where) {
        const std::string type = typeName(where, "an area light type");
        if (type != "diffuse" && type != "area") sceneFail(where, "area light \"" + type + "\" is not supported (diffuse)");
        const ParamSet p = paramsOf("light", where);
        g_.area = scene_.dialect == SceneDialect::PbrtV4 ? pbrt4AreaEmission(p)
                                                        : AreaEmission{p.getRgb("scale", {1, 1, 1}) * p.getRgb("L", {1, 1, 1}), p.getBool("twosided", false)};
        p.checkAllUsed(scene_.warnings, {"nsamples", "samples"});
    }
    // pbrt-v4's diffuse area light. An image ("filename") over the shape's uv renders as its mean
    // colour (lenslab's area lights emit one radiance per shape), and "power" is not applied
    // (pbrt-v4 normalises each triangle by its own area): both with a warning.
    AreaEmission pbrt4AreaEmission(const ParamSet& p) {
        Vec3f L = pbrt4Emission(p, "L");
        const std::string image = p.getString("filename", "");
        if (!image.empty()) {
            if (p.has("L")) p.fail("give \"L\" or \"filename\", not both (as pbrt-v4)");
            L = float(p.getFloat("scale", 1)) * readLinearImage(resolveScenePath(scene_, image, p.where()), image, p.where()).average();
            warn(p.where(), "the emission image '" + image + "' is rendered as its mean colour over the shape");
        }
        if (p.has("power")) warn(p.where(), "\"power\" of an area light is not applied");
        return AreaEmission{L, p.getBool("twosided", false)};
    }
    void shapeDirective(SourceLocation& where) { shape(where); }

    void texture(SourceLocation& where) {
        const std::string n = quoted(where, "a texture name");
        const std::string kind = quoted(where, "a texture type");
        const std::string cls = quoted(where, "a texture class");
        where.directive += " \"" + n + "\" \"" + kind + "\" \"" + cls + "\"";
        if (kind != "spectrum" && kind != "float" && kind != "color" && kind != "rgb")
            sceneFail(where, "texture type \"" + kind + "\" must be spectrum or float");
        const ParamSet p = paramsOf("texture", where);
        auto texture = makeTexture(cls, kind == "float" ? TextureKind::Float : TextureKind::Spectrum, p, g_.ctm,
                                   *g_.textures, resolver(), scene_.warnings);
        if (g_.textures.use_count() > 1) g_.textures = std::make_shared<TextureMap>(*g_.textures);
        auto& slot = (kind == "float" ? g_.textures->floats : g_.textures->spectra)[n];
        if (slot) warn(where, "redefines texture \"" + n + "\"");
        slot = std::move(texture);
        warnIfMoving(where, "a texture's space");
    }


    void shape(SourceLocation& where) {
        const std::string type = typeName(where, "a shape type");
        const ParamSet p = paramsOf("shape", where);
        std::optional<AreaEmission> emission = g_.area;
        if (emission && object_) {
            warn(where, "area lights inside ObjectBegin are not supported (as in pbrt-v3); this shape does not emit");
            emission.reset();
        }
        if (object_ || emission) warnIfMoving(where, object_ ? "a shape inside ObjectBegin" : "an area light");
        const AnimatedTransform motion = currentMotion();
        const MediumInterface media{namedMedium(where, g_.insideMedium), namedMedium(where, g_.outsideMedium)};
        if (motion.moves() && !object_ && !emission) return movingShape(type, p, motion, media);
        std::vector<ShapeEntry>& group = object_ ? scene_.objects[*object_].shapes : scene_.shapes;
        for (auto& s : makeShapes(type, p, g_.ctm, g_.reverseOrientation, *g_.textures, resolver(), scene_.warnings)) {
            if (emission && s->primitiveCount() == 0) warn(where, "this shape cannot emit (as in pbrt-v3): no area light");
            group.push_back({std::move(s), g_.material, emission, media});
        }
    }

    // A moving shape is made in its own space and placed by an instance that moves (pbrt-v3's
    // TransformedPrimitive), so Embree interpolates one transform, not every vertex. Its orientation
    // is flipped here for a mirroring transform, as the still shape would flip it.
    void movingShape(const std::string& type, const ParamSet& p, const AnimatedTransform& motion,
                     const MediumInterface& media) {
        const bool flip = g_.reverseOrientation != swapsHandedness(g_.ctm);
        ObjectDefinition own{"", {}};
        for (auto& s : makeShapes(type, p, Transform{}, flip, *g_.textures, resolver(), scene_.warnings))
            own.shapes.push_back({std::move(s), g_.material, std::nullopt, media});
        scene_.instances.push_back({scene_.objects.size(), motion});
        scene_.objects.push_back(std::move(own));
    }

    // pbrt-v3: ObjectBegin opens an attribute block that ObjectEnd closes; shapes inside keep the
    // current transform as the object's own space.
    void objectBegin(SourceLocation& where) {
        const std::string n = typeName(where, "an object name");
        if (object_) sceneFail(where, "inside the definition of object \"" + scene_.objects[*object_].name + "\" (objects do not nest)");
        stack_.push_back({true, g_, where});
        objectDepth_ = stack_.size();
        objectWhere_ = where;
        if (objectIndex_.count(n)) warn(where, "redefines object \"" + n + "\" for the instances that follow");
        objectIndex_[n] = scene_.objects.size();
        object_ = scene_.objects.size();
        scene_.objects.push_back({n, {}});
    }

    void objectEnd(SourceLocation& where) {
        if (!object_) sceneFail(where, "without a matching ObjectBegin");
        if (stack_.size() != objectDepth_)
            sceneFail(where, "AttributeBegin/AttributeEnd inside object \"" + scene_.objects[*object_].name + "\" do not pair up");
        g_ = stack_.back().state;
        stack_.pop_back();
        object_.reset();
    }

    void objectInstance(SourceLocation& where) {
        const std::string n = typeName(where, "an object name");
        if (object_) sceneFail(where, "inside the definition of object \"" + scene_.objects[*object_].name + "\"");
        const auto it = objectIndex_.find(n);
        if (it == objectIndex_.end()) sceneFail(where, "unknown object \"" + n + "\" (no ObjectBegin defines it before here)");
        scene_.instances.push_back({it->second, currentMotion()});
    }

    SceneDescription& scene_;
    SceneParseOptions options_;
    GraphicsState g_;
    std::vector<StackEntry> stack_;
    std::map<std::string, TransformPair> namedCoordinates_;
    NamedMaterials namedMaterials_;
    std::map<std::string, std::shared_ptr<const ParticipatingMedium>> namedMedia_;
    std::string cameraMedium_;           // the outside medium's name at Camera
    SourceLocation cameraMediumWhere_;
    bool mediaUsed_ = false;             // a shape or the camera lies in a medium
    bool integratorGiven_ = false;       // the file has an Integrator directive
    bool integratorRendersMedia_ = false;
    std::optional<SourceLocation> subsurfaceWhere_;  // the first subsurface material
    SourceLocation integratorWhere_{"", 0, "Integrator (default path)"};
    std::map<std::string, std::size_t> objectIndex_;  // the latest definition of each object name
    std::optional<std::size_t> object_;                // the object being defined
    std::size_t objectDepth_ = 0;                      // stack_ size inside its ObjectBegin block
    SourceLocation objectWhere_;                       // its ObjectBegin
    bool worldBegun_ = false, worldEnded_ = false;
    TokenCursor in_;
};

}  // namespace

SceneDescription parseSceneFile(const std::string& path, const SceneParseOptions& options) {
    SceneDescription scene;
    scene.confined = options.confined;
    if (!fs::is_regular_file(path)) throw SceneError("cannot open scene file '" + path + "'");
    scene.file = fs::weakly_canonical(path).string();
    scene.rootDir = fs::path(scene.file).parent_path().string();
    scene.film.where = {scene.file, 0, "Film (defaults)"};
    scene.camera.params = ParamSet({scene.file, 0, "Camera (default perspective)"}, {});
    Parser parser(scene, options);
    parser.parseFile(scene.file);
    parser.finish();
    return scene;
}

}  // namespace lenslab
