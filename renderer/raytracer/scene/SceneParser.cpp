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
    std::shared_ptr<const Material> material;
    std::optional<AreaEmission> area;
    bool reverseOrientation = false;
    // Scoped by AttributeBegin/End as in pbrt-v3; shared with the saved states until a Texture
    // directive changes it (copy on write: entering a block copies no textures).
    std::shared_ptr<TextureMap> textures = std::make_shared<TextureMap>();
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
    }

    void parseFile(const std::string& path, int depth) {
        if (depth > kMaxIncludeDepth) throw SceneError(path + ": Include nested deeper than 32 (a cycle?)");
        std::ifstream in(path, std::ios::binary);
        if (!in) throw SceneError("cannot open scene file '" + path + "'");
        std::stringstream text;
        text << in.rdbuf();
        files_.emplace_back(path, tokenizeScene(text.str(), path));
        while (!in_().atEnd()) {
            directive(depth);
            if (options_.progress && depth == 0) options_.progress(in_().fraction());
        }
        files_.pop_back();
    }

    void finish() {
        if (object_) sceneFail(objectWhere_, "not closed by ObjectEnd");
        if (!stack_.empty())
            sceneFail(stack_.back().where, "not closed by " + std::string(stack_.back().attribute ? "AttributeEnd" : "TransformEnd"));
        if (!worldBegun_) throw SceneError(scene_.file + ": no WorldBegin: the scene describes no world");
    }

private:
    using Handler = void (Parser::*)(SourceLocation&, int);
    struct DirectiveEntry {
        Handler handler;
        Phase phase;
    };

    TokenCursor& in_() { return files_.back(); }
    double number(const SourceLocation& where) { return in_().number(where); }
    std::string quoted(const SourceLocation& where, const char* what) { return in_().quoted(where, what); }
    PathResolver resolver() const {
        return [this](const std::string& name, const SourceLocation& at) { return resolveScenePath(scene_, name, at); };
    }
    ParamSet params(const SourceLocation& where) { return readParamList(in_(), where, resolver()); }
    void warn(const SourceLocation& where, const std::string& message) {
        scene_.warnings.push_back(describe(where) + ": " + message);
    }
    // The directive's quoted type name, added to `where` for messages: Shape "disk".
    std::string typeName(SourceLocation& where, const char* what) {
        const std::string type = quoted(where, what);
        where.directive += " \"" + type + "\"";
        return type;
    }

    void directive(int depth) {
        const Token tok = in_().take({in_().file(), 0, ""}, "a directive");
        SourceLocation where{in_().file(), tok.line, tok.text};
        if (tok.quoted || tok.text == "[" || tok.text == "]") sceneFail(where, "expected a directive, got '" + tok.text + "'");
        if (worldEnded_) {
            warn(where, "ignoring everything after WorldEnd");
            in_().skipToEnd();
            return;
        }
        const auto& table = directives();
        const auto it = table.find(tok.text);
        if (it == table.end()) sceneFail(where, "unsupported directive '" + tok.text + "'");
        if (it->second.phase == Phase::World && !worldBegun_) sceneFail(where, "only allowed after WorldBegin");
        if (it->second.phase == Phase::Options && worldBegun_) sceneFail(where, "only allowed before WorldBegin");
        try {
            (this->*it->second.handler)(where, depth);
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
            {"Option", {&Parser::ignoredWithParams, Phase::Options}},
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
            {"Attribute", {&Parser::ignoredWithParams, Phase::World}},
        };
        return table;
    }

    // --- transforms -------------------------------------------------------------------------
    // Applies t to the transforms ActiveTransform selected (both unless told otherwise).
    void applyTransform(const Transform& t) {
        if (activeStart_) g_.ctm = g_.ctm * t;
        if (activeEnd_) g_.ctmEnd = g_.ctmEnd * t;
    }
    void setTransform(const Transform& t) {
        if (activeStart_) g_.ctm = t;
        if (activeEnd_) g_.ctmEnd = t;
    }
    void translateDirective(SourceLocation& where, int) {
        const double x = number(where), y = number(where), z = number(where);
        applyTransform(translate(x, y, z));
    }
    void scaleDirective(SourceLocation& where, int) {
        const double x = number(where), y = number(where), z = number(where);
        if (x == 0 || y == 0 || z == 0) sceneFail(where, "zero scale factor");
        applyTransform(scale(x, y, z));
    }
    void rotateDirective(SourceLocation& where, int) {
        const double a = number(where), x = number(where), y = number(where), z = number(where);
        applyTransform(rotate(a, x, y, z));
    }
    void lookAtDirective(SourceLocation& where, int) {
        double v[9];
        for (double& x : v) x = number(where);
        applyTransform(lookAt(v, v + 3, v + 6));
    }
    void matrixDirective(SourceLocation& where, int) {
        const std::vector<double> v = in_().numberArray(where, 16);
        Matrix44 m;
        for (int i = 0; i < 16; ++i) m.m[i % 4][i / 4] = v[i];  // pbrt lists the matrix column by column
        const Transform t = makeTransform(m);
        if (where.directive == "Transform") setTransform(t);
        else applyTransform(t);
    }
    void identityDirective(SourceLocation&, int) { setTransform(Transform{}); }
    void coordinateSystem(SourceLocation& where, int) { namedCoordinates_[quoted(where, "a name")] = {g_.ctm, g_.ctmEnd}; }
    void coordSysTransform(SourceLocation& where, int) {
        const std::string n = quoted(where, "a name");
        auto it = namedCoordinates_.find(n);
        if (it == namedCoordinates_.end()) sceneFail(where, "unknown coordinate system \"" + n + "\"");
        setTransform(activeStart_ ? it->second.start : it->second.end);
        if (activeStart_ && activeEnd_) g_.ctmEnd = it->second.end;
    }
    void activeTransform(SourceLocation& where, int) {
        const Token& t = in_().take(where, "StartTime, EndTime or All");
        if (t.quoted || (t.text != "StartTime" && t.text != "EndTime" && t.text != "All"))
            sceneFail(where, "expected StartTime, EndTime or All, got '" + t.text + "'");
        activeStart_ = t.text != "EndTime";
        activeEnd_ = t.text != "StartTime";
    }
    void transformTimes(SourceLocation& where, int) {
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
    void beginBlock(SourceLocation& where, int) { stack_.push_back({where.directive == "AttributeBegin", g_, where}); }
    void endBlock(SourceLocation& where, int) {
        const bool attribute = where.directive == "AttributeEnd";
        if (stack_.empty()) sceneFail(where, "without a matching " + std::string(attribute ? "AttributeBegin" : "TransformBegin"));
        if (stack_.back().attribute != attribute) sceneFail(where, "closes " + describe(stack_.back().where) + " (mismatched nesting)");
        if (attribute) {
            g_ = stack_.back().state;
        } else {
            g_.ctm = stack_.back().state.ctm;
            g_.ctmEnd = stack_.back().state.ctmEnd;
        }
        stack_.pop_back();
    }
    void reverseOrientation(SourceLocation&, int) { g_.reverseOrientation = !g_.reverseOrientation; }
    void include(SourceLocation& where, int depth) {
        const std::string file = quoted(where, "a file name");
        parseFile(resolveScenePath(scene_, file, where), depth + 1);
    }
    void ignoredName(SourceLocation& where, int) {
        warn({where.file, where.line, where.directive + " \"" + quoted(where, "a name") + "\""}, "ignored (lenslab renders in linear sRGB)");
    }
    void ignoredWithParams(SourceLocation& where, int) {
        typeName(where, "a name");
        params(where);
        warn(where, "ignored (a pbrt-v4 directive lenslab does not use)");
    }

    // --- rendering options ------------------------------------------------------------------
    void camera(SourceLocation& where, int) {
        const std::string type = typeName(where, "a camera type");
        if (type != "perspective" && type != "realistic" && type != "orthographic" && type != "environment")
            sceneFail(where, "camera \"" + type + "\" is not supported (perspective, orthographic, environment, realistic)");
        scene_.camera.type = type;
        scene_.camera.params = params(where);
        scene_.camera.cameraToWorld = AnimatedTransform(inverse(g_.ctm), inverse(g_.ctmEnd));
        namedCoordinates_["camera"] = {inverse(g_.ctm), inverse(g_.ctmEnd)};
    }
    void accelerator(SourceLocation& where, int) {
        typeName(where, "an accelerator type");
        params(where);
        warn(where, "ignored (lenslab always uses Embree's BVH)");
    }
    // Participating media would change the picture everywhere: refuse rather than render without.
    void medium(SourceLocation& where, int) {
        sceneFail(where, "participating media (MakeNamedMedium \"" + quoted(where, "a medium name") +
                             "\") are not supported: the picture would lack the medium");
    }
    void mediumInterface(SourceLocation& where, int) {
        const std::string inside = quoted(where, "a medium name");
        const std::string outside = !in_().atEnd() && in_().peek().quoted ? quoted(where, "a medium name") : inside;
        if (!inside.empty() || !outside.empty())
            sceneFail(where, "participating media are not supported (MediumInterface \"" + inside + "\" \"" + outside + "\")");
    }
    void worldBegin(SourceLocation&, int) {
        worldBegun_ = true;
        g_.ctm = g_.ctmEnd = Transform{};
        namedCoordinates_["world"] = {Transform{}, Transform{}};
    }
    void worldEnd(SourceLocation&, int) { worldEnded_ = true; }

    void film(SourceLocation& where, int) {
        const std::string type = typeName(where, "a film type");
        const ParamSet p = params(where);
        if (type != "image") warn(where, "film \"" + type + "\" is rendered as pbrt-v3's \"image\" film (RGB)");
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
        p.checkAllUsed(scene_.warnings);
    }

    void sampler(SourceLocation& where, int) {
        const std::string type = typeName(where, "a sampler type");
        const ParamSet p = params(where);
        if (type == "stratified") scene_.pixelSamples = p.getInt("xsamples", 4) * p.getInt("ysamples", 4);
        else scene_.pixelSamples = p.getInt("pixelsamples", 16);
        p.checkAllUsed(scene_.warnings, {"jitter", "dimensions", "seed"});
        if (type != "sobol" && type != "zerotwosequence" && type != "02sequence" && type != "lowdiscrepancy")
            warn(where, "lenslab uses its own Owen-scrambled Sobol'/Faure sampler (noise differs, not the image)");
    }

    void integrator(SourceLocation& where, int) {
        const std::string type = typeName(where, "an integrator type");
        const ParamSet p = params(where);
        IntegratorSpec& spec = scene_.integrator;
        // Global-illumination methods of pbrt-v3 and pbrt-v2 converge to the path tracer's picture
        // (media aside); the others compute something else and are refused.
        static const char* kGlobalIllumination[] = {"bdpt", "mlt", "sppm", "volpath", "photonmap", "exphotonmap",
                                                    "irradiancecache", "igi", "dipolesubsurface"};
        if (type == "directlighting") {
            spec.type = IntegratorType::DirectLighting;
        } else if (type == "whitted") {
            spec.type = IntegratorType::Whitted;
        } else if (type == "path") {
            spec.type = IntegratorType::Path;
        } else if (std::find(std::begin(kGlobalIllumination), std::end(kGlobalIllumination), type) != std::end(kGlobalIllumination)) {
            spec.type = IntegratorType::Path;
            warn(where, "integrator \"" + type + "\" rendered by the path tracer (same picture in the limit, other noise)");
        } else {
            p.fail("integrator \"" + type + "\" is not supported (path, directlighting, whitted; bdpt, mlt, sppm, volpath "
                   "and pbrt-v2's photonmap, irradiancecache, igi render as path)");
        }
        spec.maxDepth = p.getInt("maxdepth", 5);
        if (spec.maxDepth < 0 || spec.maxDepth > 1000) p.fail("maxdepth must lie in [0, 1000]");
        p.checkAllUsed(scene_.warnings, {"rrthreshold", "lightsamplestrategy", "strategy", "pixelbounds", "visualizestrategies",
                                         "visualizeweights", "bootstrapsamples", "chains", "mutationsperpixel",
                                         "largestepprobability", "sigma", "iterations", "photonsperiteration", "radius",
                                         "imagewritefrequency", "samples", "maxdistance", "cossample", "regularize"});
    }

    // pbrt-v2: without media a volume integrator changes nothing.
    void volumeIntegrator(SourceLocation& where, int) {
        typeName(where, "a volume integrator type");
        params(where);
        warn(where, "ignored (no participating media in lenslab scenes)");
    }
    // pbrt-v2's Renderer: "sampler" is the ordinary one, "metropolis" converges to the same picture.
    void renderer(SourceLocation& where, int) {
        const std::string type = typeName(where, "a renderer type");
        const ParamSet p = params(where);
        if (type != "sampler" && type != "metropolis")
            p.fail("renderer \"" + type + "\" is not supported (sampler; metropolis renders as the path tracer)");
        if (type == "metropolis") warn(where, "rendered by the path tracer (same picture in the limit, other noise)");
    }
    void volume(SourceLocation& where, int) {
        sceneFail(where, "participating media (Volume \"" + quoted(where, "a volume type") + "\") are not supported: the picture would lack the medium");
    }

    void filter(SourceLocation& where, int) {
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
    void material(SourceLocation& where, int) {
        const std::string type = typeName(where, "a material type");
        g_.material = makeMaterial(type, params(where), materialContext());
    }
    void makeNamedMaterial(SourceLocation& where, int) {
        const std::string n = typeName(where, "a material name");
        const ParamSet p = params(where);
        if (!p.has("type")) p.fail("MakeNamedMaterial needs \"string type\"");
        namedMaterials_[n] = makeMaterial(p.getString("type", ""), p, materialContext());
    }
    void namedMaterial(SourceLocation& where, int) {
        const std::string n = quoted(where, "a material name");
        auto it = namedMaterials_.find(n);
        if (it == namedMaterials_.end()) sceneFail(where, "unknown material \"" + n + "\"");
        g_.material = it->second;
    }
    void textureDirective(SourceLocation& where, int) { texture(where); }
    void lightSource(SourceLocation& where, int) {
        const std::string type = typeName(where, "a light type");
        scene_.lights.push_back(makeLight(type, params(where), g_.ctm, resolver(), scene_.warnings));
        warnIfMoving(where, "a light");
    }
    // pbrt-v3 accepts "area" as another name for "diffuse".
    void areaLightSource(SourceLocation& where, int) {
        const std::string type = typeName(where, "an area light type");
        if (type != "diffuse" && type != "area") sceneFail(where, "area light \"" + type + "\" is not supported (diffuse)");
        const ParamSet p = params(where);
        g_.area = AreaEmission{p.getRgb("scale", {1, 1, 1}) * p.getRgb("L", {1, 1, 1}), p.getBool("twosided", false)};
        p.checkAllUsed(scene_.warnings, {"nsamples", "samples"});
    }
    void shapeDirective(SourceLocation& where, int) { shape(where); }

    void texture(SourceLocation& where) {
        const std::string n = quoted(where, "a texture name");
        const std::string kind = quoted(where, "a texture type");
        const std::string cls = quoted(where, "a texture class");
        where.directive += " \"" + n + "\" \"" + kind + "\" \"" + cls + "\"";
        if (kind != "spectrum" && kind != "float" && kind != "color" && kind != "rgb")
            sceneFail(where, "texture type \"" + kind + "\" must be spectrum or float");
        const ParamSet p = params(where);
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
        const ParamSet p = params(where);
        std::optional<AreaEmission> emission = g_.area;
        if (emission && object_) {
            warn(where, "area lights inside ObjectBegin are not supported (as in pbrt-v3); this shape does not emit");
            emission.reset();
        }
        if (object_ || emission) warnIfMoving(where, object_ ? "a shape inside ObjectBegin" : "an area light");
        const AnimatedTransform motion = currentMotion();
        if (motion.moves() && !object_ && !emission) return movingShape(type, p, motion);
        std::vector<ShapeEntry>& group = object_ ? scene_.objects[*object_].shapes : scene_.shapes;
        for (auto& s : makeShapes(type, p, g_.ctm, g_.reverseOrientation, *g_.textures, resolver(), scene_.warnings)) {
            if (emission && s->primitiveCount() == 0) warn(where, "this shape cannot emit (as in pbrt-v3): no area light");
            group.push_back({std::move(s), g_.material, emission});
        }
    }

    // A moving shape is made in its own space and placed by an instance that moves (pbrt-v3's
    // TransformedPrimitive), so Embree interpolates one transform, not every vertex. Its orientation
    // is flipped here for a mirroring transform, as the still shape would flip it.
    void movingShape(const std::string& type, const ParamSet& p, const AnimatedTransform& motion) {
        const bool flip = g_.reverseOrientation != swapsHandedness(g_.ctm);
        ObjectDefinition own{"", {}};
        for (auto& s : makeShapes(type, p, Transform{}, flip, *g_.textures, resolver(), scene_.warnings))
            own.shapes.push_back({std::move(s), g_.material, std::nullopt});
        scene_.instances.push_back({scene_.objects.size(), motion});
        scene_.objects.push_back(std::move(own));
    }

    // pbrt-v3: ObjectBegin opens an attribute block that ObjectEnd closes; shapes inside keep the
    // current transform as the object's own space.
    void objectBegin(SourceLocation& where, int) {
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

    void objectEnd(SourceLocation& where, int) {
        if (!object_) sceneFail(where, "without a matching ObjectBegin");
        if (stack_.size() != objectDepth_)
            sceneFail(where, "AttributeBegin/AttributeEnd inside object \"" + scene_.objects[*object_].name + "\" do not pair up");
        g_ = stack_.back().state;
        stack_.pop_back();
        object_.reset();
    }

    void objectInstance(SourceLocation& where, int) {
        const std::string n = typeName(where, "an object name");
        if (object_) sceneFail(where, "inside the definition of object \"" + scene_.objects[*object_].name + "\"");
        const auto it = objectIndex_.find(n);
        if (it == objectIndex_.end()) sceneFail(where, "unknown object \"" + n + "\" (no ObjectBegin defines it before here)");
        scene_.instances.push_back({it->second, currentMotion()});
    }

    SceneDescription& scene_;
    SceneParseOptions options_;
    GraphicsState g_;
    bool activeStart_ = true, activeEnd_ = true;
    std::vector<StackEntry> stack_;
    std::map<std::string, TransformPair> namedCoordinates_;
    NamedMaterials namedMaterials_;
    std::map<std::string, std::size_t> objectIndex_;  // the latest definition of each object name
    std::optional<std::size_t> object_;                // the object being defined
    std::size_t objectDepth_ = 0;                      // stack_ size inside its ObjectBegin block
    SourceLocation objectWhere_;                       // its ObjectBegin
    bool worldBegun_ = false, worldEnded_ = false;
    std::vector<TokenCursor> files_;  // the file being read and those that Include it
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
    parser.parseFile(scene.file, 0);
    parser.finish();
    return scene;
}

}  // namespace lenslab
