#pragma once
// Single-precision vectors and RGB colours for the ray tracer (world units: metres).
#include <algorithm>
#include <cmath>

namespace lenslab {

struct Vec3f {
    float x = 0, y = 0, z = 0;
    float operator[](int i) const { return i == 0 ? x : i == 1 ? y : z; }
};

inline Vec3f operator+(Vec3f a, Vec3f b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3f operator-(Vec3f a, Vec3f b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3f operator-(Vec3f a) { return {-a.x, -a.y, -a.z}; }
inline Vec3f operator*(float s, Vec3f a) { return {s * a.x, s * a.y, s * a.z}; }
inline Vec3f operator*(Vec3f a, float s) { return s * a; }
inline Vec3f operator*(Vec3f a, Vec3f b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline Vec3f operator/(Vec3f a, float s) { return (1.0f / s) * a; }
inline Vec3f& operator+=(Vec3f& a, Vec3f b) { return a = a + b; }
inline Vec3f& operator*=(Vec3f& a, Vec3f b) { return a = a * b; }
inline float dot(Vec3f a, Vec3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3f cross(Vec3f a, Vec3f b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(Vec3f a) { return std::sqrt(dot(a, a)); }
inline Vec3f normalize(Vec3f a) { return a / length(a); }
inline float maxComponent(Vec3f a) { return std::max(a.x, std::max(a.y, a.z)); }
inline bool isBlack(Vec3f a) { return a.x == 0 && a.y == 0 && a.z == 0; }
inline bool allFinite(Vec3f a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }
inline Vec3f grey(float v) { return {v, v, v}; }
inline Vec3f atLeastZero(Vec3f c) { return {std::max(0.0f, c.x), std::max(0.0f, c.y), std::max(0.0f, c.z)}; }
inline float luminance(Vec3f c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// An orthonormal basis around a unit normal (Duff et al. 2017), for local shading coordinates.
struct Frame {
    Vec3f s, t, n;
    explicit Frame(Vec3f normal) : n(normal) {
        const float sign = std::copysign(1.0f, n.z);
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        s = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
        t = {b, sign + n.y * n.y * a, -n.y};
    }
    Vec3f toLocal(Vec3f v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    Vec3f toWorld(Vec3f v) const { return v.x * s + v.y * t + v.z * n; }
};

}  // namespace lenslab
