#pragma once
// Scene-file parameters built in code, as the parser would give them ("float fov" 40, ...): what
// tests pass to lights, textures and materials made without a scene file.
#include <string>

#include "core/ParamSet.h"
#include "core/Vec3f.h"

namespace lenslab::test {

inline Param floatParam(const std::string& name, double x) { return {ParamType::Float, name, {x}, {}}; }
inline Param intParam(const std::string& name, int x) { return {ParamType::Integer, name, {double(x)}, {}}; }
inline Param rgbParam(const std::string& name, Vec3f c) { return {ParamType::Rgb, name, {c.x, c.y, c.z}, {}}; }
inline Param vectorParam(const std::string& name, Vec3f c) { return {ParamType::Vector3, name, {c.x, c.y, c.z}, {}}; }
inline Param stringParam(const std::string& name, const std::string& s) { return {ParamType::String, name, {}, {s}}; }
inline Param textureRef(const std::string& name, const std::string& s) { return {ParamType::Texture, name, {}, {s}}; }
inline Param boolParam(const std::string& name, bool b) { return {ParamType::Bool, name, {}, {b ? "true" : "false"}}; }

}  // namespace lenslab::test
