#include "shapes/CurveShape.h"

#include <algorithm>
#include <cmath>

#include "Render.h"

namespace lenslab {

namespace {

enum class CurveType { Flat, Cylinder, Ribbon };

struct Segment {
    Vec3f c[4];  // cubic Bezier control points, group space
};

// Cubic Bezier point and tangent at t.
Vec3f bezier(const Segment& s, float t, Vec3f* tangent) {
    const float u = 1 - t;
    if (tangent)
        *tangent = 3 * (u * u * (s.c[1] - s.c[0]) + 2 * u * t * (s.c[2] - s.c[1]) + t * t * (s.c[3] - s.c[2]));
    return u * u * u * s.c[0] + 3 * u * u * t * s.c[1] + 3 * u * t * t * s.c[2] + t * t * t * s.c[3];
}

// A uniform cubic B-spline span as the equivalent Bezier segment.
Segment bsplineToBezier(Vec3f p0, Vec3f p1, Vec3f p2, Vec3f p3) {
    return {{(p0 + 4 * p1 + p2) / 6, (2 * p1 + p2) / 3, (p1 + 2 * p2) / 3, (p1 + 4 * p2 + p3) / 6}};
}

// The part of a cubic Bezier segment between parameters a and b, as a segment of its own: its
// control points are the curve's blossom at (a, a, a), (a, a, b), (a, b, b) and (b, b, b).
Segment piece(const Segment& s, float a, float b) {
    const auto blossom = [&](float t1, float t2, float t3) {
        const auto lerp = [](Vec3f x, Vec3f y, float t) { return (1 - t) * x + t * y; };
        const Vec3f q0 = lerp(s.c[0], s.c[1], t1), q1 = lerp(s.c[1], s.c[2], t1), q2 = lerp(s.c[2], s.c[3], t1);
        return lerp(lerp(q0, q1, t2), lerp(q1, q2, t2), t3);
    };
    return {{blossom(a, a, a), blossom(a, a, b), blossom(a, b, b), blossom(b, b, b)}};
}

// Quadratic Bezier raised to cubic (same curve).
Segment elevate(Vec3f q0, Vec3f q1, Vec3f q2) { return {{q0, q0 + (2.0f / 3) * (q1 - q0), q2 + (2.0f / 3) * (q1 - q2), q2}}; }

class CurveShape : public Shape {
public:
    CurveShape(std::vector<Segment> segments, std::vector<Vec3f> normals, CurveType type, float radius0, float radius1)
        : segs_(std::move(segments)), normals_(std::move(normals)), type_(type), r0_(radius0), r1_(radius1) {}

    unsigned attach(RTCDevice device, RTCScene scene) const override {
        const RTCGeometryType kind = type_ == CurveType::Flat       ? RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE
                                     : type_ == CurveType::Cylinder ? RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE
                                                                    : RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BEZIER_CURVE;
        RTCGeometry g = rtcNewGeometry(device, kind);
        const std::size_t n = segs_.size();
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 4 * n));
        auto* ix = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), n));
        float* nv = type_ == CurveType::Ribbon ? static_cast<float*>(rtcSetNewGeometryBuffer(
                                                     g, RTC_BUFFER_TYPE_NORMAL, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 4 * n))
                                               : nullptr;
        if (!v || !ix || (type_ == CurveType::Ribbon && !nv)) {
            rtcReleaseGeometry(g);
            throw SceneError("Embree: out of memory for a curve of " + std::to_string(n) + " segments");
        }
        for (std::size_t s = 0; s < n; ++s) {
            ix[s] = unsigned(4 * s);
            for (int k = 0; k < 4; ++k) {
                float* out = v + 4 * (4 * s + k);
                const Vec3f c = segs_[s].c[k];
                out[0] = c.x;
                out[1] = c.y;
                out[2] = c.z;
                out[3] = radiusAt(s, k / 3.0f);
                if (nv) {
                    const Vec3f nk = normalAt(s, k / 3.0f);
                    float* o = nv + 3 * (4 * s + k);
                    o[0] = nk.x;
                    o[1] = nk.y;
                    o[2] = nk.z;
                }
            }
        }
        rtcCommitGeometry(g);
        const unsigned id = rtcAttachGeometry(scene, g);
        rtcReleaseGeometry(g);
        return id;
    }

    // u runs along the whole curve (pbrt-v3), v across it from 0 to 1.
    void surface(Vec3f o, Vec3f d, float t, unsigned prim, float hitU, float hitV, SurfaceHit& h) const override {
        h.p = o + t * d;
        Vec3f tangent;
        const Vec3f centre = bezier(segs_[prim], hitU, &tangent);
        const float tl = length(tangent);
        const Vec3f T = tl > 0 ? tangent / tl : Vec3f{0, 0, 1};
        Vec3f n = type_ == CurveType::Cylinder ? h.p - centre : type_ == CurveType::Ribbon ? normalAt(prim, hitU) : -d;
        n = n - dot(n, T) * T;
        const float nl = length(n);
        n = nl > 0 ? n / nl : -d;
        if (type_ != CurveType::Cylinder && dot(n, d) > 0) n = -n;  // a ribbon is seen from either side
        h.ng = h.ns = n;
        h.u = (float(prim) + hitU) / float(segs_.size());
        // v: where the ray crossed the curve's apparent width, from the hit's offset off the axis
        // along n x T for a curve facing the ray (for a tube, along the seen width -d x T), so that
        // pbrt-v4's hair reads its offset h = 2v - 1 the same way for every curve type.
        const Vec3f across = type_ == CurveType::Cylinder ? cross(-d, T) : cross(n, T);
        const float acrossLen = length(across), radius = radiusAt(prim, hitU);
        const float offset = acrossLen > 0 && radius > 0 ? dot(h.p - centre, across) / (acrossLen * radius) : hitV;
        h.v = std::clamp(0.5f * (offset + 1), 0.0f, 1.0f);
        // Along the curve, per unit of this u; across it, the width, turned so that dp/du x dp/dv
        // runs along the normal (as pbrt-v3's curves).
        h.dpdu = float(segs_.size()) * tangent;
        h.dpdv = (2 * radiusAt(prim, hitU)) * cross(n, T);
        h.dndu = h.dndv = {};  // pbrt-v3's curves give the normal no turning
    }

    // pbrt-v3 cannot sample curves either: they do not emit (the parser warns).
    std::size_t primitiveCount() const override { return 0; }
    float primitiveArea(std::size_t) const override { return 0; }
    ShapeSample samplePrimitive(std::size_t, float, float) const override { return {}; }
    float primitivePdf(std::size_t, const SurfaceHit&) const override { return 0; }

private:
    float radiusAt(std::size_t seg, float t) const {
        const float f = (float(seg) + t) / float(segs_.size());
        return (1 - f) * r0_ + f * r1_;
    }
    Vec3f normalAt(std::size_t seg, float t) const {
        if (normals_.empty()) return {};
        const float f = (float(seg) + t) / float(segs_.size()) * float(normals_.size() - 1);
        const std::size_t i = std::min(std::size_t(f), normals_.size() - 2);
        const float w = f - float(i);
        return normalize((1 - w) * normals_[i] + w * normals_[i + 1]);
    }

    std::vector<Segment> segs_;
    std::vector<Vec3f> normals_;  // ribbon: one per segment end, group space
    CurveType type_;
    float r0_, r1_;
};

}  // namespace

std::shared_ptr<const Shape> makeCurve(const ParamSet& p, const Transform& toGroup) {
    const std::string basis = p.getString("basis", "bezier");
    const int degree = p.getInt("degree", 3);
    if (basis != "bezier" && basis != "bspline") p.fail("basis must be bezier or bspline, got \"" + basis + "\"");
    if (degree != 2 && degree != 3) p.fail("degree must be 2 or 3");
    const std::string typeName = p.getString("type", "flat");
    if (typeName != "flat" && typeName != "cylinder" && typeName != "ribbon") p.fail("type must be flat, cylinder or ribbon");
    const CurveType type = typeName == "flat" ? CurveType::Flat : typeName == "cylinder" ? CurveType::Cylinder : CurveType::Ribbon;
    std::vector<Vec3f> P;
    for (const Vec3f& x : p.getPoints("P")) P.push_back(transformPoint(toGroup, x));
    // Bezier segments share end points; B-spline spans overlap by degree points.
    const std::size_t n = P.size();
    std::size_t segments = 0;
    if (basis == "bezier") {
        if (n < std::size_t(degree) + 1 || (n - 1) % degree != 0)
            p.fail("a degree-" + std::to_string(degree) + " Bezier curve needs " + std::to_string(degree) + "k+1 points \"P\", got " +
                   std::to_string(n));
        segments = (n - 1) / degree;
    } else {
        if (n < std::size_t(degree) + 1) p.fail("a B-spline curve needs at least " + std::to_string(degree + 1) + " points");
        segments = n - degree;
    }
    // Each segment is split into 2^splitdepth pieces, as pbrt splits it: the same curve, but each
    // piece's bounding box hugs it, where a long, thin, bent segment's box is mostly empty space
    // that every ray through it pays an intersection test for.
    const int splitDepth = p.getInt("splitdepth", 3);
    if (splitDepth < 0 || splitDepth > 10) p.fail("splitdepth must lie in [0, 10], got " + std::to_string(splitDepth));
    const int pieces = 1 << splitDepth;
    std::vector<Segment> segs;
    segs.reserve(segments * std::size_t(pieces));
    for (std::size_t s = 0; s < segments; ++s) {
        Segment whole;
        if (basis == "bezier") {
            const Vec3f* c = &P[s * degree];
            whole = degree == 3 ? Segment{{c[0], c[1], c[2], c[3]}} : elevate(c[0], c[1], c[2]);
        } else {
            const Vec3f* c = &P[s];
            whole = degree == 3 ? bsplineToBezier(c[0], c[1], c[2], c[3]) : elevate((c[0] + c[1]) / 2, c[1], (c[1] + c[2]) / 2);
        }
        for (int k = 0; k < pieces; ++k) segs.push_back(piece(whole, float(k) / float(pieces), float(k + 1) / float(pieces)));
    }
    // Widths are in object space: scale them by the transform's mean linear scale.
    const float scale = std::cbrt(length(transformVector(toGroup, {1, 0, 0})) * length(transformVector(toGroup, {0, 1, 0})) *
                                  length(transformVector(toGroup, {0, 0, 1})));
    const double width = p.getFloat("width", 1);
    const double w0 = p.getFloat("width0", width), w1 = p.getFloat("width1", width);
    if (!(w0 >= 0 && w1 >= 0 && w0 + w1 > 0)) p.fail("widths must not be negative, and not both zero");
    std::vector<Vec3f> normals;
    if (type == CurveType::Ribbon) {
        for (const Vec3f& x : p.getPoints("N")) normals.push_back(normalize(transformNormal(toGroup, x)));
        if (normals.size() != segments + 1) p.fail("a ribbon needs one normal \"N\" per segment end (" + std::to_string(segments + 1) + ")");
    }
    return std::make_shared<CurveShape>(std::move(segs), std::move(normals), type, float(w0 / 2) * scale, float(w1 / 2) * scale);
}

}  // namespace lenslab
