#pragma once
// The typed parameter list of a scene directive ("float fov" [45] ...), with the source location
// for messages and use tracking so that no parameter is ever ignored silently.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/Vec3f.h"

namespace lenslab {

struct SourceLocation {
    std::string file;
    int line = 0;
    std::string directive;  // e.g. Shape "sphere"
};

// Maps a file name from the scene (an Include, a lens, a PLY mesh, an image) to a readable path, or
// fails naming the path tried.
using PathResolver = std::function<std::string(const std::string& name, const SourceLocation& where)>;

// Throws SceneError "file:line: directive: message".
[[noreturn]] void sceneFail(const SourceLocation& where, const std::string& message);
std::string describe(const SourceLocation& where);  // "file:line: directive"

enum class ParamType { Float, Integer, String, Bool, Point3, Vector3, Normal, Rgb, Point2, Texture };

struct Param {
    ParamType type = ParamType::Float;
    std::string name;
    std::vector<double> numbers;
    std::vector<std::string> strings;  // String, Texture; Bool as "true"/"false"
    int line = 0;                      // where it was declared
    mutable bool used = false;
    bool spectral = false;   // Rgb from a spectrum or blackbody (pbrt-v4 lights normalise those)
    bool inherited = false;  // from an Attribute default: never warned about when unused
};

// A spectrum-valued parameter: a colour, or the name of a texture.
struct ColorOrTexture {
    Vec3f color;
    std::optional<std::string> texture;
};

class ParamSet {
public:
    ParamSet() = default;
    ParamSet(SourceLocation where, std::vector<Param> params) : where_(std::move(where)), params_(std::move(params)) {}

    const SourceLocation& where() const { return where_; }
    bool has(const std::string& name) const { return find(name) != nullptr; }

    // Single values; a parameter given with the wrong type or count is an error naming it.
    double getFloat(const std::string& name, double fallback) const;
    int getInt(const std::string& name, int fallback) const;
    bool getBool(const std::string& name, bool fallback) const;
    std::string getString(const std::string& name, const std::string& fallback) const;
    Vec3f getPoint(const std::string& name, Vec3f fallback) const;
    Vec3f getRgb(const std::string& name, Vec3f fallback) const;  // rgb/color, or one float as grey
    ColorOrTexture getColorOrTexture(const std::string& name, Vec3f fallback) const;
    bool isSpectral(const std::string& name) const;  // given as a spectrum or blackbody, not rgb
    // pbrt-v4's Attribute: the defaults' parameters this list does not give itself join it.
    ParamSet withDefaults(const ParamSet& defaults) const;
    // Arrays (any count, possibly empty when absent).
    std::vector<double> getFloats(const std::string& name) const;
    std::vector<int> getInts(const std::string& name) const;
    std::vector<std::string> getStrings(const std::string& name) const;
    std::vector<Vec3f> getPoints(const std::string& name) const;  // point3/normal/vector

    // Every parameter not read (unknown, or given with another type) becomes a warning naming its
    // file and line, as in pbrt-v3; those in `harmless` are said not to change the image.
    void checkAllUsed(std::vector<std::string>& warnings, const std::vector<std::string>& harmless = {}) const;

    [[noreturn]] void fail(const std::string& message) const { sceneFail(where_, message); }

private:
    const Param* find(const std::string& name) const;
    // The parameter when given with one of `types` (marked used), else nullptr; count 0: any.
    const Param* lookup(const std::string& name, std::initializer_list<ParamType> types, std::size_t count) const;

    SourceLocation where_;
    std::vector<Param> params_;
};

const char* paramTypeName(ParamType type);

}  // namespace lenslab
