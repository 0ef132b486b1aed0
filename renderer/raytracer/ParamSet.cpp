#include "ParamSet.h"

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

const Param& ParamSet::expect(const std::string& name, std::initializer_list<ParamType> types, std::size_t count) const {
    const Param* p = find(name);
    bool typeOk = false;
    for (ParamType t : types) typeOk = typeOk || p->type == t;
    if (!typeOk)
        fail("parameter \"" + name + "\" has type " + paramTypeName(p->type) + ", expected " + paramTypeName(*types.begin()));
    const std::size_t have = p->type == ParamType::String || p->type == ParamType::Texture || p->type == ParamType::Bool
                                 ? p->strings.size()
                                 : p->numbers.size();
    if (count != 0 && have != count)
        fail("parameter \"" + name + "\" needs " + std::to_string(count) + " value(s), got " + std::to_string(have));
    p->used = true;
    return *p;
}

double ParamSet::getFloat(const std::string& name, double fallback) const {
    if (!has(name)) return fallback;
    return expect(name, {ParamType::Float, ParamType::Integer}, 1).numbers[0];
}

int ParamSet::getInt(const std::string& name, int fallback) const {
    if (!has(name)) return fallback;
    const double v = expect(name, {ParamType::Integer}, 1).numbers[0];
    if (v != std::floor(v) || std::fabs(v) > 2e9) fail("parameter \"" + name + "\" must be an integer");
    return static_cast<int>(v);
}

bool ParamSet::getBool(const std::string& name, bool fallback) const {
    if (!has(name)) return fallback;
    return expect(name, {ParamType::Bool}, 1).strings[0] == "true";
}

std::string ParamSet::getString(const std::string& name, const std::string& fallback) const {
    if (!has(name)) return fallback;
    return expect(name, {ParamType::String}, 1).strings[0];
}

Vec3f ParamSet::getPoint(const std::string& name, Vec3f fallback) const {
    if (!has(name)) return fallback;
    const auto& v = expect(name, {ParamType::Point3, ParamType::Vector3, ParamType::Normal}, 3).numbers;
    return {float(v[0]), float(v[1]), float(v[2])};
}

Vec3f ParamSet::getRgb(const std::string& name, Vec3f fallback) const {
    if (!has(name)) return fallback;
    const Param& p = *find(name);
    if (p.type == ParamType::Float) {
        const float g = float(expect(name, {ParamType::Float}, 1).numbers[0]);
        return {g, g, g};
    }
    const auto& v = expect(name, {ParamType::Rgb}, 3).numbers;
    return {float(v[0]), float(v[1]), float(v[2])};
}

ColorOrTexture ParamSet::getColorOrTexture(const std::string& name, Vec3f fallback) const {
    ColorOrTexture c{fallback, std::nullopt};
    if (!has(name)) return c;
    if (find(name)->type == ParamType::Texture) c.texture = expect(name, {ParamType::Texture}, 1).strings[0];
    else c.color = getRgb(name, fallback);
    return c;
}

std::vector<double> ParamSet::getFloats(const std::string& name) const {
    if (!has(name)) return {};
    return expect(name, {ParamType::Float, ParamType::Integer, ParamType::Point2}, 0).numbers;
}

std::vector<int> ParamSet::getInts(const std::string& name) const {
    std::vector<int> out;
    if (!has(name)) return out;
    for (double v : expect(name, {ParamType::Integer}, 0).numbers) {
        if (v != std::floor(v) || v < 0 || v > 2e9) fail("parameter \"" + name + "\" needs non-negative integers");
        out.push_back(static_cast<int>(v));
    }
    return out;
}

std::vector<Vec3f> ParamSet::getPoints(const std::string& name) const {
    std::vector<Vec3f> out;
    if (!has(name)) return out;
    const auto& v = expect(name, {ParamType::Point3, ParamType::Vector3, ParamType::Normal}, 0).numbers;
    if (v.size() % 3 != 0) fail("parameter \"" + name + "\" needs a multiple of 3 values");
    for (std::size_t i = 0; i < v.size(); i += 3) out.push_back({float(v[i]), float(v[i + 1]), float(v[i + 2])});
    return out;
}

void ParamSet::checkAllUsed(std::vector<std::string>& warnings, const std::vector<std::string>& harmless) const {
    for (const Param& p : params_) {
        if (p.used) continue;
        bool isHarmless = false;
        for (const auto& h : harmless) isHarmless = isHarmless || h == p.name;
        if (!isHarmless) fail("unsupported parameter \"" + std::string(paramTypeName(p.type)) + " " + p.name + "\"");
        warnings.push_back(describe(where_) + ": ignoring parameter \"" + p.name + "\" (does not change the image)");
    }
}

}  // namespace lenslab
