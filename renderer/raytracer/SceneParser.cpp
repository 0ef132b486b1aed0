// pbrt-v3 scene syntax, the subset lenslab renders. Every directive or parameter it cannot honour
// is an error naming the file, line and directive, or a warning when ignoring it cannot change the
// image.
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "Render.h"
#include "SceneDescription.h"
#include "SceneTokenizer.h"

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

struct GraphicsState {
    Transform ctm;
    std::shared_ptr<const Material> material;
    std::optional<AreaEmission> area;
    bool reverseOrientation = false;
};

struct StackEntry {
    bool attribute;  // AttributeBegin (whole state) or TransformBegin (transform only)
    GraphicsState state;
    SourceLocation where;
};

class Parser {
public:
    explicit Parser(SceneDescription& scene) : scene_(scene) { g_.material = makeDefaultMaterial(); }

    void parseFile(const std::string& path, int depth) {
        if (depth > kMaxIncludeDepth) throw SceneError(path + ": Include nested deeper than 32 (a cycle?)");
        std::ifstream in(path, std::ios::binary);
        if (!in) throw SceneError("cannot open scene file '" + path + "'");
        std::stringstream text;
        text << in.rdbuf();
        file_.push_back(path);
        tokens_.push_back(tokenizeScene(text.str(), path));
        pos_.push_back(0);
        while (pos_.back() < tokens_.back().size()) directive(depth);
        file_.pop_back();
        tokens_.pop_back();
        pos_.pop_back();
    }

    void finish() {
        if (object_) sceneFail(objectWhere_, "not closed by ObjectEnd");
        if (!stack_.empty())
            sceneFail(stack_.back().where, "not closed by " + std::string(stack_.back().attribute ? "AttributeEnd" : "TransformEnd"));
        if (!worldBegun_) throw SceneError(scene_.file + ": no WorldBegin: the scene describes no world");
    }

private:
    // --- tokens -----------------------------------------------------------------------------
    bool atEnd() const { return pos_.back() >= tokens_.back().size(); }
    const Token& peek() const { return tokens_.back()[pos_.back()]; }
    const Token& take(const SourceLocation& where, const char* what) {
        if (atEnd()) sceneFail(where, std::string("expected ") + what + " but the file ended");
        return tokens_.back()[pos_.back()++];
    }
    SourceLocation here(const std::string& directive, int line) const { return {file_.back(), line, directive}; }

    static double toNumber(const Token& t, const SourceLocation& where) {
        if (t.quoted || t.text == "[" || t.text == "]") sceneFail(where, "expected a number, got '" + t.text + "'");
        errno = 0;
        char* end = nullptr;
        const double v = std::strtod(t.text.c_str(), &end);
        if (end != t.text.c_str() + t.text.size() || errno == ERANGE || !std::isfinite(v))
            sceneFail({where.file, t.line, where.directive}, "bad number '" + t.text + "'");
        return v;
    }
    double number(const SourceLocation& where) { return toNumber(take(where, "a number"), where); }
    std::string quoted(const SourceLocation& where, const char* what) {
        const Token& t = take(where, what);
        if (!t.quoted) sceneFail(where, std::string("expected ") + what + " in quotes, got '" + t.text + "'");
        return t.text;
    }
    // Bracketed numbers, exactly `count` of them (Transform, ConcatTransform).
    std::vector<double> numberArray(const SourceLocation& where, std::size_t count) {
        std::vector<double> v;
        const bool bracket = !atEnd() && peek().text == "[" && !peek().quoted;
        if (bracket) take(where, "[");
        while (v.size() < count) v.push_back(number(where));
        if (bracket && take(where, "]").text != "]") sceneFail(where, "expected " + std::to_string(count) + " numbers in [ ]");
        return v;
    }

    static std::optional<ParamType> typeFromName(const std::string& t) {
        static const std::map<std::string, ParamType> kTypes = {
            {"float", ParamType::Float},    {"integer", ParamType::Integer}, {"string", ParamType::String},
            {"bool", ParamType::Bool},      {"point", ParamType::Point3},    {"point3", ParamType::Point3},
            {"vector", ParamType::Vector3}, {"vector3", ParamType::Vector3}, {"normal", ParamType::Normal},
            {"normal3", ParamType::Normal}, {"rgb", ParamType::Rgb},         {"color", ParamType::Rgb},
            {"point2", ParamType::Point2},  {"texture", ParamType::Texture}};
        auto it = kTypes.find(t);
        if (it == kTypes.end()) return std::nullopt;
        return it->second;
    }

    ParamSet params(const SourceLocation& where) {
        std::vector<Param> list;
        while (!atEnd() && peek().quoted && peek().text.find(' ') != std::string::npos) {
            const Token decl = take(where, "a parameter");
            std::istringstream words(decl.text);
            std::string typeName, name, extra;
            words >> typeName >> name >> extra;
            const SourceLocation at{where.file, decl.line, where.directive};
            if (name.empty() || !extra.empty()) sceneFail(at, "bad parameter declaration \"" + decl.text + "\"");
            const auto type = typeFromName(typeName);
            if (!type) {
                if (typeName == "spectrum" || typeName == "blackbody" || typeName == "xyz")
                    sceneFail(at, "parameter \"" + decl.text + "\": " + typeName + " values are not supported; use rgb");
                sceneFail(at, "unknown parameter type '" + typeName + "' in \"" + decl.text + "\"");
            }
            for (const Param& p : list)
                if (p.name == name) sceneFail(at, "parameter \"" + name + "\" given twice");
            Param p;
            p.type = *type;
            p.name = name;
            std::vector<Token> values;
            if (atEnd()) sceneFail(at, "parameter \"" + decl.text + "\" has no value");
            if (peek().text == "[" && !peek().quoted) {
                take(at, "[");
                while (true) {
                    const Token& t = take(at, "]");
                    if (t.text == "]" && !t.quoted) break;
                    values.push_back(t);
                }
            } else {
                values.push_back(take(at, "a value"));
            }
            for (const Token& t : values) {
                const SourceLocation vat{where.file, t.line, where.directive};
                if (p.type == ParamType::String || p.type == ParamType::Texture) {
                    if (!t.quoted) sceneFail(vat, "parameter \"" + name + "\" needs quoted strings, got '" + t.text + "'");
                    p.strings.push_back(t.text);
                } else if (p.type == ParamType::Bool) {
                    if (t.text != "true" && t.text != "false")
                        sceneFail(vat, "parameter \"" + name + "\" needs true or false, got '" + t.text + "'");
                    p.strings.push_back(t.text);
                } else {
                    p.numbers.push_back(toNumber(t, vat));
                }
            }
            if (values.empty()) sceneFail(at, "parameter \"" + name + "\" has an empty value list");
            list.push_back(std::move(p));
        }
        return ParamSet(where, std::move(list));
    }

    // --- directives -------------------------------------------------------------------------
    void requireWorld(const SourceLocation& where, bool inside) {
        if (inside && !worldBegun_) sceneFail(where, "only allowed after WorldBegin");
        if (!inside && worldBegun_) sceneFail(where, "only allowed before WorldBegin");
    }

    void applyTransform(const Transform& t) { g_.ctm = g_.ctm * t; }

    void directive(int depth) {
        const Token tok = tokens_.back()[pos_.back()++];
        const std::string& name = tok.text;
        SourceLocation where = here(name, tok.line);
        if (tok.quoted || name == "[" || name == "]") sceneFail(where, "expected a directive, got '" + name + "'");
        if (worldEnded_) {
            scene_.warnings.push_back(describe(where) + ": ignoring everything after WorldEnd");
            pos_.back() = tokens_.back().size();
            return;
        }
        try {
            dispatch(name, where, depth);
        } catch (const std::domain_error& e) {  // singular or degenerate transforms
            sceneFail(where, e.what());
        }
    }

    void dispatch(const std::string& name, SourceLocation& where, int depth) {
        if (name == "Translate") {
            const double x = number(where), y = number(where), z = number(where);
            applyTransform(translate(x, y, z));
        } else if (name == "Scale") {
            const double x = number(where), y = number(where), z = number(where);
            if (x == 0 || y == 0 || z == 0) sceneFail(where, "zero scale factor");
            applyTransform(scale(x, y, z));
        } else if (name == "Rotate") {
            const double a = number(where), x = number(where), y = number(where), z = number(where);
            applyTransform(rotate(a, x, y, z));
        } else if (name == "LookAt") {
            double v[9];
            for (double& x : v) x = number(where);
            applyTransform(lookAt(v, v + 3, v + 6));
        } else if (name == "Transform" || name == "ConcatTransform") {
            const std::vector<double> v = numberArray(where, 16);
            Matrix44 m;
            for (int i = 0; i < 16; ++i) m.m[i % 4][i / 4] = v[i];  // pbrt lists the matrix column by column
            const Transform t = makeTransform(m);
            if (name == "Transform") g_.ctm = t;
            else applyTransform(t);
        } else if (name == "Identity") {
            g_.ctm = Transform{};
        } else if (name == "CoordinateSystem") {
            namedCoordinates_[quoted(where, "a name")] = g_.ctm;
        } else if (name == "CoordSysTransform") {
            const std::string n = quoted(where, "a name");
            auto it = namedCoordinates_.find(n);
            if (it == namedCoordinates_.end()) sceneFail(where, "unknown coordinate system \"" + n + "\"");
            g_.ctm = it->second;
        } else if (name == "AttributeBegin" || name == "TransformBegin") {
            stack_.push_back({name == "AttributeBegin", g_, where});
        } else if (name == "AttributeEnd" || name == "TransformEnd") {
            const bool attribute = name == "AttributeEnd";
            if (stack_.empty()) sceneFail(where, "without a matching " + std::string(attribute ? "AttributeBegin" : "TransformBegin"));
            if (stack_.back().attribute != attribute)
                sceneFail(where, "closes " + describe(stack_.back().where) + " (mismatched nesting)");
            if (attribute) g_ = stack_.back().state;
            else g_.ctm = stack_.back().state.ctm;
            stack_.pop_back();
        } else if (name == "ReverseOrientation") {
            g_.reverseOrientation = !g_.reverseOrientation;
        } else if (name == "Include" || name == "Import") {
            const std::string file = quoted(where, "a file name");
            parseFile(resolveScenePath(scene_, file, where), depth + 1);
        } else if (name == "Camera") {
            requireWorld(where, false);
            const std::string type = quoted(where, "a camera type");
            where.directive += " \"" + type + "\"";
            if (type != "perspective" && type != "realistic")
                sceneFail(where, "camera \"" + type + "\" is not supported (perspective, realistic)");
            scene_.camera.type = type;
            scene_.camera.params = params(where);
            scene_.camera.cameraToWorld = inverse(g_.ctm);
            namedCoordinates_["camera"] = scene_.camera.cameraToWorld;
        } else if (name == "Film") {
            requireWorld(where, false);
            film(where);
        } else if (name == "Sampler") {
            requireWorld(where, false);
            sampler(where);
        } else if (name == "Integrator") {
            requireWorld(where, false);
            integrator(where);
        } else if (name == "PixelFilter") {
            requireWorld(where, false);
            filter(where);
        } else if (name == "Accelerator") {
            requireWorld(where, false);
            quoted(where, "an accelerator type");
            params(where);
            scene_.warnings.push_back(describe(where) + ": ignored (lenslab always uses Embree's BVH)");
        } else if (name == "WorldBegin") {
            requireWorld(where, false);
            worldBegun_ = true;
            g_.ctm = Transform{};
            namedCoordinates_["world"] = g_.ctm;
        } else if (name == "WorldEnd") {
            requireWorld(where, true);
            worldEnded_ = true;
        } else if (name == "Shape") {
            requireWorld(where, true);
            shape(where);
        } else if (name == "ObjectBegin") {
            requireWorld(where, true);
            objectBegin(where);
        } else if (name == "ObjectEnd") {
            requireWorld(where, true);
            objectEnd(where);
        } else if (name == "ObjectInstance") {
            requireWorld(where, true);
            objectInstance(where);
        } else if (name == "Material") {
            requireWorld(where, true);
            const std::string type = quoted(where, "a material type");
            where.directive += " \"" + type + "\"";
            g_.material = makeMaterial(type, params(where), textures_, scene_.warnings);
        } else if (name == "MakeNamedMaterial") {
            requireWorld(where, true);
            const std::string n = quoted(where, "a material name");
            where.directive += " \"" + n + "\"";
            const ParamSet p = params(where);
            namedMaterials_[n] = makeMaterial(p.getString("type", ""), p, textures_, scene_.warnings);
        } else if (name == "NamedMaterial") {
            requireWorld(where, true);
            const std::string n = quoted(where, "a material name");
            auto it = namedMaterials_.find(n);
            if (it == namedMaterials_.end()) sceneFail(where, "unknown material \"" + n + "\"");
            g_.material = it->second;
        } else if (name == "Texture") {
            requireWorld(where, true);
            texture(where);
        } else if (name == "LightSource") {
            requireWorld(where, true);
            const std::string type = quoted(where, "a light type");
            where.directive += " \"" + type + "\"";
            scene_.lights.push_back(makeLight(type, params(where), g_.ctm, scene_.warnings));
        } else if (name == "AreaLightSource") {
            requireWorld(where, true);
            const std::string type = quoted(where, "an area light type");
            where.directive += " \"" + type + "\"";
            if (type != "diffuse") sceneFail(where, "area light \"" + type + "\" is not supported (diffuse)");
            const ParamSet p = params(where);
            g_.area = AreaEmission{p.getRgb("scale", {1, 1, 1}) * p.getRgb("L", {1, 1, 1}), p.getBool("twosided", false)};
            p.checkAllUsed(scene_.warnings, {"nsamples", "samples"});
        } else {
            sceneFail(where, "unsupported directive '" + name + "'");
        }
    }

    void film(SourceLocation& where) {
        const std::string type = quoted(where, "a film type");
        where.directive += " \"" + type + "\"";
        if (type != "image") sceneFail(where, "film \"" + type + "\" is not supported (image)");
        const ParamSet p = params(where);
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
        p.checkAllUsed(scene_.warnings);
    }

    void sampler(SourceLocation& where) {
        const std::string type = quoted(where, "a sampler type");
        where.directive += " \"" + type + "\"";
        const ParamSet p = params(where);
        static const char* kKnown[] = {"halton", "sobol", "random", "stratified", "02sequence", "lowdiscrepancy", "maxmindist", "zerotwosequence"};
        bool known = false;
        for (const char* k : kKnown) known = known || type == k;
        if (!known) p.fail("unknown sampler \"" + type + "\"");
        if (type == "stratified") scene_.pixelSamples = p.getInt("xsamples", 4) * p.getInt("ysamples", 4);
        else scene_.pixelSamples = p.getInt("pixelsamples", 16);
        p.checkAllUsed(scene_.warnings, {"jitter", "dimensions", "seed"});
        if (type != "sobol" && type != "zerotwosequence" && type != "02sequence" && type != "lowdiscrepancy")
            scene_.warnings.push_back(describe(where) + ": lenslab uses its own scrambled Sobol' sampler (noise differs, not the image)");
    }

    void integrator(SourceLocation& where) {
        const std::string type = quoted(where, "an integrator type");
        where.directive += " \"" + type + "\"";
        if (type != "path" && type != "directlighting")
            sceneFail(where, "integrator \"" + type + "\" is not supported (path, directlighting)");
        const ParamSet p = params(where);
        scene_.integrator.type = type == "directlighting" ? IntegratorType::DirectLighting : IntegratorType::Path;
        scene_.integrator.maxDepth = p.getInt("maxdepth", 5);
        if (scene_.integrator.maxDepth < 0 || scene_.integrator.maxDepth > 1000) p.fail("maxdepth must lie in [0, 1000]");
        p.checkAllUsed(scene_.warnings, {"rrthreshold", "lightsamplestrategy", "strategy"});
    }

    void filter(SourceLocation& where) {
        const std::string type = quoted(where, "a filter type");
        where.directive += " \"" + type + "\"";
        const ParamSet p = params(where);
        FilterSpec& f = scene_.filter;
        if (type == "box") {
            f = FilterSpec{};
            f.xwidth = p.getFloat("xwidth", 0.5);
            f.ywidth = p.getFloat("ywidth", 0.5);
        } else if (type == "gaussian") {
            f = FilterSpec{};
            f.type = FilterType::Gaussian;
            f.xwidth = p.getFloat("xwidth", 2);
            f.ywidth = p.getFloat("ywidth", 2);
            f.alpha = p.getFloat("alpha", 2);
            if (!(f.alpha > 0)) p.fail("alpha must be positive");
        } else {
            p.fail("pixel filter \"" + type + "\" is not supported (box, gaussian)");
        }
        if (!(f.xwidth > 0 && f.xwidth <= 16 && f.ywidth > 0 && f.ywidth <= 16)) p.fail("filter widths must lie in (0, 16] pixels");
        p.checkAllUsed(scene_.warnings);
    }

    void texture(SourceLocation& where) {
        const std::string n = quoted(where, "a texture name");
        const std::string kind = quoted(where, "a texture type");
        const std::string cls = quoted(where, "a texture class");
        where.directive += " \"" + n + "\" \"" + kind + "\" \"" + cls + "\"";
        if (kind != "spectrum" && kind != "float" && kind != "color" && kind != "rgb")
            sceneFail(where, "texture type \"" + kind + "\" must be spectrum or float");
        const ParamSet p = params(where);
        textures_[n] = makeTexture(cls, p, textures_,
                                   [&](const std::string& file, const SourceLocation& at) {
                                       return resolveScenePath(scene_, file, at);
                                   },
                                   scene_.warnings);
    }

    void shape(SourceLocation& where) {
        const std::string type = quoted(where, "a shape type");
        where.directive += " \"" + type + "\"";
        const ParamSet p = params(where);
        std::optional<AreaEmission> emission = g_.area;
        if (emission && object_) {
            scene_.warnings.push_back(describe(where) + ": area lights inside ObjectBegin are not supported (as in pbrt-v3); "
                                      "this shape does not emit");
            emission.reset();
        }
        const PathResolver resolve = [&](const std::string& file, const SourceLocation& at) {
            return resolveScenePath(scene_, file, at);
        };
        std::vector<ShapeEntry>& group = object_ ? scene_.objects[*object_].shapes : scene_.shapes;
        for (auto& s : makeShapes(type, p, g_.ctm, g_.reverseOrientation, resolve, scene_.warnings))
            group.push_back({std::move(s), g_.material, emission});
    }

    // pbrt-v3: ObjectBegin opens an attribute block that ObjectEnd closes; shapes inside keep the
    // current transform as the object's own space.
    void objectBegin(SourceLocation& where) {
        const std::string n = quoted(where, "an object name");
        where.directive += " \"" + n + "\"";
        if (object_) sceneFail(where, "inside the definition of object \"" + scene_.objects[*object_].name + "\" (objects do not nest)");
        stack_.push_back({true, g_, where});
        objectDepth_ = stack_.size();
        objectWhere_ = where;
        if (objectIndex_.count(n))
            scene_.warnings.push_back(describe(where) + ": redefines object \"" + n + "\" for the instances that follow");
        objectIndex_[n] = scene_.objects.size();
        object_ = scene_.objects.size();
        scene_.objects.push_back({n, {}});
    }

    void objectEnd(const SourceLocation& where) {
        if (!object_) sceneFail(where, "without a matching ObjectBegin");
        if (stack_.size() != objectDepth_)
            sceneFail(where, "AttributeBegin/AttributeEnd inside object \"" + scene_.objects[*object_].name + "\" do not pair up");
        g_ = stack_.back().state;
        stack_.pop_back();
        object_.reset();
    }

    void objectInstance(SourceLocation& where) {
        const std::string n = quoted(where, "an object name");
        where.directive += " \"" + n + "\"";
        if (object_) sceneFail(where, "inside the definition of object \"" + scene_.objects[*object_].name + "\"");
        const auto it = objectIndex_.find(n);
        if (it == objectIndex_.end()) sceneFail(where, "unknown object \"" + n + "\" (no ObjectBegin defines it before here)");
        scene_.instances.push_back({it->second, g_.ctm});
    }

    SceneDescription& scene_;
    GraphicsState g_;
    std::vector<StackEntry> stack_;
    std::map<std::string, Transform> namedCoordinates_;
    std::map<std::string, std::shared_ptr<const Material>> namedMaterials_;
    TextureMap textures_;
    std::map<std::string, std::size_t> objectIndex_;  // the latest definition of each object name
    std::optional<std::size_t> object_;                // the object being defined
    std::size_t objectDepth_ = 0;                      // stack_ size inside its ObjectBegin block
    SourceLocation objectWhere_;                       // its ObjectBegin
    bool worldBegun_ = false, worldEnded_ = false;
    std::vector<std::string> file_;
    std::vector<std::vector<Token>> tokens_;
    std::vector<std::size_t> pos_;
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
    Parser parser(scene);
    parser.parseFile(scene.file, 0);
    parser.finish();
    return scene;
}

}  // namespace lenslab
