#include "core/ParamSet.h"

#include <cmath>

#include "Render.h"

namespace lenslab {

std::string describe(const SourceLocation& where) {
    return where.file + ":" + std::to_string(where.line) + ": " + where.directive;
}

void sceneFail(const SourceLocation& where, const std::string& message) {
    throw SceneError(describe(where) + ": " + message);
}

const char* paramTypeName(ParamType type) {
    switch (type) {
        case ParamType::Float: return "float";
        case ParamType::Integer: return "integer";
        case ParamType::String: return "string";
        case ParamType::Bool: return "bool";
        case ParamType::Point3: return "point3";
        case ParamType::Vector3: return "vector3";
        case ParamType::Normal: return "normal";
        case ParamType::Rgb: return "rgb";
        case ParamType::Point2: return "point2";
        case ParamType::Texture: return "texture";
    }
    return "?";
}

const Param* ParamSet::find(const std::string& name) const {
    for (const Param& p : params_)
        if (p.name == name) return &p;
    return nullptr;
}

// As pbrt-v3 looks parameters up by type and name, one given with another type is not found: it
// stays unused and checkAllUsed warns about it. A wrong count is an error.
const Param* ParamSet::lookup(const std::string& name, std::initializer_list<ParamType> types, std::size_t count) const {
    const Param* p = find(name);
    if (!p) return nullptr;
    bool typeOk = false;
    for (ParamType t : types) typeOk = typeOk || p->type == t;
    if (!typeOk) return nullptr;
    const std::size_t have = p->type == ParamType::String || p->type == ParamType::Texture || p->type == ParamType::Bool
                                 ? p->strings.size()
                                 : p->numbers.size();
    if (count != 0 && have != count)
        fail("parameter \"" + name + "\" needs " + std::to_string(count) + " value(s), got " + std::to_string(have));
    p->used = true;
    return p;
}

double ParamSet::getFloat(const std::string& name, double fallback) const {
    const Param* p = lookup(name, {ParamType::Float, ParamType::Integer}, 1);
    return p ? p->numbers[0] : fallback;
}

int ParamSet::getInt(const std::string& name, int fallback) const {
    const Param* p = lookup(name, {ParamType::Integer}, 1);
    if (!p) return fallback;
    const double v = p->numbers[0];
    if (v != std::floor(v) || std::fabs(v) > 2e9) fail("parameter \"" + name + "\" must be an integer");
    return static_cast<int>(v);
}

bool ParamSet::getBool(const std::string& name, bool fallback) const {
    const Param* p = lookup(name, {ParamType::Bool}, 1);
    return p ? p->strings[0] == "true" : fallback;
}

std::string ParamSet::getString(const std::string& name, const std::string& fallback) const {
    const Param* p = lookup(name, {ParamType::String}, 1);
    return p ? p->strings[0] : fallback;
}

Vec3f ParamSet::getPoint(const std::string& name, Vec3f fallback) const {
    const Param* p = lookup(name, {ParamType::Point3, ParamType::Vector3, ParamType::Normal}, 3);
    if (!p) return fallback;
    const auto& v = p->numbers;
    return {float(v[0]), float(v[1]), float(v[2])};
}

Vec3f ParamSet::getRgb(const std::string& name, Vec3f fallback) const {
    if (const Param* g = lookup(name, {ParamType::Float}, 1)) {
        const float x = float(g->numbers[0]);
        return {x, x, x};
    }
    const Param* p = lookup(name, {ParamType::Rgb}, 3);
    if (!p) return fallback;
    const auto& v = p->numbers;
    return {float(v[0]), float(v[1]), float(v[2])};
}

ColorOrTexture ParamSet::getColorOrTexture(const std::string& name, Vec3f fallback) const {
    ColorOrTexture c{fallback, std::nullopt};
    if (const Param* t = lookup(name, {ParamType::Texture}, 1)) c.texture = t->strings[0];
    else c.color = getRgb(name, fallback);
    return c;
}

std::vector<double> ParamSet::getFloats(const std::string& name) const {
    const Param* p = lookup(name, {ParamType::Float, ParamType::Integer, ParamType::Point2}, 0);
    return p ? p->numbers : std::vector<double>{};
}

std::vector<std::string> ParamSet::getStrings(const std::string& name) const {
    const Param* p = lookup(name, {ParamType::String}, 0);
    return p ? p->strings : std::vector<std::string>{};
}

std::vector<int> ParamSet::getInts(const std::string& name) const {
    std::vector<int> out;
    const Param* p = lookup(name, {ParamType::Integer}, 0);
    if (!p) return out;
    for (double v : p->numbers) {
        if (v != std::floor(v) || v < 0 || v > 2e9) fail("parameter \"" + name + "\" needs non-negative integers");
        out.push_back(static_cast<int>(v));
    }
    return out;
}

std::vector<Vec3f> ParamSet::getPoints(const std::string& name) const {
    std::vector<Vec3f> out;
    const Param* p = lookup(name, {ParamType::Point3, ParamType::Vector3, ParamType::Normal}, 0);
    if (!p) return out;
    const auto& v = p->numbers;
    if (v.size() % 3 != 0) fail("parameter \"" + name + "\" needs a multiple of 3 values");
    for (std::size_t i = 0; i < v.size(); i += 3) out.push_back({float(v[i]), float(v[i + 1]), float(v[i + 2])});
    return out;
}

bool ParamSet::isSpectral(const std::string& name) const {
    const Param* p = find(name);
    return p && p->spectral;
}

ParamSet ParamSet::withDefaults(const ParamSet& defaults) const {
    ParamSet merged = *this;
    for (const Param& d : defaults.params_) {
        if (has(d.name)) continue;
        Param inherited = d;
        inherited.used = false;
        inherited.inherited = true;
        merged.params_.push_back(std::move(inherited));
    }
    return merged;
}

void ParamSet::checkAllUsed(std::vector<std::string>& warnings, const std::vector<std::string>& harmless) const {
    for (const Param& p : params_) {
        if (p.used || p.inherited) continue;
        bool isHarmless = false;
        for (const auto& h : harmless) isHarmless = isHarmless || h == p.name;
        const std::string what = "\"" + std::string(paramTypeName(p.type)) + " " + p.name + "\"";
        warnings.push_back(describe(SourceLocation{where_.file, p.line, where_.directive}) + ": ignoring parameter " + what +
                           (isHarmless ? " (does not change the image)" : " (unknown here or of another type; the picture may differ from pbrt-v3's)"));
    }
}

}  // namespace lenslab
