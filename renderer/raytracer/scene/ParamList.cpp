#include "scene/ParamList.h"

#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include "prescription/GlassCatalog.h"
#include "materials/MetalSpectra.h"
#include "core/Spectrum.h"

namespace lenslab {

namespace {

enum class Declared { Plain, Spectrum, Blackbody, Xyz };

std::optional<std::pair<ParamType, Declared>> typeFromName(const std::string& t) {
    static const std::map<std::string, std::pair<ParamType, Declared>> kTypes = {
        {"float", {ParamType::Float, Declared::Plain}},       {"integer", {ParamType::Integer, Declared::Plain}},
        {"string", {ParamType::String, Declared::Plain}},     {"bool", {ParamType::Bool, Declared::Plain}},
        {"point", {ParamType::Point3, Declared::Plain}},      {"point3", {ParamType::Point3, Declared::Plain}},
        {"vector", {ParamType::Vector3, Declared::Plain}},    {"vector3", {ParamType::Vector3, Declared::Plain}},
        {"normal", {ParamType::Normal, Declared::Plain}},     {"normal3", {ParamType::Normal, Declared::Plain}},
        {"rgb", {ParamType::Rgb, Declared::Plain}},           {"color", {ParamType::Rgb, Declared::Plain}},
        {"point2", {ParamType::Point2, Declared::Plain}},     {"vector2", {ParamType::Point2, Declared::Plain}},
        {"texture", {ParamType::Texture, Declared::Plain}},   {"spectrum", {ParamType::Rgb, Declared::Spectrum}},
        {"blackbody", {ParamType::Rgb, Declared::Blackbody}}, {"xyz", {ParamType::Rgb, Declared::Xyz}}};
    auto it = kTypes.find(t);
    if (it == kTypes.end()) return std::nullopt;
    return it->second;
}

Vec3f sampledPairs(const std::vector<double>& v, const SourceLocation& at, const std::string& name) {
    if (v.size() < 2 || v.size() % 2 != 0)
        sceneFail(at, "spectrum \"" + name + "\" needs (wavelength, value) pairs, got " + std::to_string(v.size()) + " numbers");
    std::vector<double> lambda, value;
    for (std::size_t i = 0; i < v.size(); i += 2) {
        if (!lambda.empty() && !(v[i] > lambda.back())) sceneFail(at, "spectrum \"" + name + "\": wavelengths must increase");
        lambda.push_back(v[i]);
        value.push_back(v[i + 1]);
    }
    return sampledSpectrumToRgb(lambda, value);
}

// A .spd file: whitespace-separated (wavelength, value) pairs, '#' comments.
Vec3f spectrumFile(const std::string& name, const SourceLocation& at, const PathResolver& resolve) {
    const std::string path = resolve(name, at);
    std::ifstream in(path);
    std::vector<double> v;
    std::string line;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
        std::istringstream words(line.substr(0, line.find('#')));
        std::string w;
        while (words >> w) v.push_back(tokenNumber({w, lineNo, false}, {path, lineNo, "spectrum file"}));
    }
    return sampledPairs(v, at, name);
}

// pbrt-v4's named glasses ("glass-BK7"): the catalog glass's index at the d line (587.6 nm); an
// RGB renderer has no dispersion (docs/pbrt-v4.md).
std::optional<float> namedGlassIndex(const std::string& name) {
    const std::string prefix = "glass-";
    if (name.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
    const GlassLookup found = findGlass(name.substr(prefix.size()), {"SCHOTT"});
    if (!found.glass) return std::nullopt;
    return float(found.glass->nd);
}

Vec3f spectralToRgb(Declared kind, const std::vector<Token>& values, const SourceLocation& at, const std::string& name,
                    const PathResolver& resolve) {
    if (kind == Declared::Spectrum && values.size() == 1 && values[0].quoted) {
        if (const auto named = namedSpectrumRgb(values[0].text)) return *named;  // "metal-Cu-eta"
        if (const auto glass = namedGlassIndex(values[0].text)) return {*glass, *glass, *glass};
        return spectrumFile(values[0].text, at, resolve);
    }
    std::vector<double> v;
    for (const Token& t : values) v.push_back(tokenNumber(t, at));
    if (kind == Declared::Xyz) {
        if (v.size() != 3) sceneFail(at, "parameter \"" + name + "\" needs 3 xyz values");
        return xyzToRgb(v[0], v[1], v[2]);
    }
    if (kind == Declared::Blackbody) {
        if (v.size() == 1) v.push_back(1);  // pbrt-v4 gives the temperature alone
        if (v.size() != 2) sceneFail(at, "parameter \"" + name + "\" needs blackbody [temperature scale]");
        if (!(v[0] > 0 && v[0] < 1e6)) sceneFail(at, "blackbody temperature must lie in (0, 1e6) K");
        return blackbodyToRgb(v[0], v[1]);
    }
    return sampledPairs(v, at, name);
}

}  // namespace

ParamSet readParamList(TokenCursor& in, const SourceLocation& where, const PathResolver& resolve) {
    std::vector<Param> list;
    while (!in.atEnd() && in.peek().quoted && in.peek().text.find(' ') != std::string::npos) {
        const Token decl = in.take(where, "a parameter");
        std::istringstream words(decl.text);
        std::string typeName, name, extra;
        words >> typeName >> name >> extra;
        const SourceLocation at = locate(decl, where);
        if (name.empty() || !extra.empty()) sceneFail(at, "bad parameter declaration \"" + decl.text + "\"");
        const auto type = typeFromName(typeName);
        if (!type) sceneFail(at, "unknown parameter type '" + typeName + "' in \"" + decl.text + "\"");
        for (const Param& p : list)
            if (p.name == name) sceneFail(at, "parameter \"" + name + "\" given twice");
        Param p;
        p.type = type->first;
        p.name = name;
        p.line = decl.line;
        const std::vector<Token> values = in.valueList(at, decl.text);
        if (type->second != Declared::Plain) {
            const Vec3f rgb = spectralToRgb(type->second, values, at, name, resolve);
            p.numbers = {rgb.x, rgb.y, rgb.z};
            p.spectral = type->second == Declared::Spectrum || type->second == Declared::Blackbody;
            list.push_back(std::move(p));
            continue;
        }
        for (const Token& t : values) {
            const SourceLocation vat = locate(t, where);
            if (p.type == ParamType::String || p.type == ParamType::Texture) {
                if (!t.quoted) sceneFail(vat, "parameter \"" + name + "\" needs quoted strings, got '" + t.text + "'");
                p.strings.push_back(t.text);
            } else if (p.type == ParamType::Bool) {
                if (t.text != "true" && t.text != "false")
                    sceneFail(vat, "parameter \"" + name + "\" needs true or false, got '" + t.text + "'");
                p.strings.push_back(t.text);
            } else {
                p.numbers.push_back(tokenNumber(t, vat));
            }
        }
        list.push_back(std::move(p));
    }
    return ParamSet(where, std::move(list));
}

}  // namespace lenslab
