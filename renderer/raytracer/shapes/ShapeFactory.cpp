// Shape "TYPE": pbrt-v3's shapes by name, with their parameters.
#include <stdexcept>

#include "shapes/CurveShape.h"
#include "shapes/LoopSubdivision.h"
#include "shapes/NurbsSurface.h"
#include "shapes/PlyMesh.h"
#include "shapes/Quadric.h"
#include "shapes/Shape.h"
#include "shapes/TriangleMeshShape.h"

namespace lenslab {

namespace {

constexpr std::size_t kMaxTriangles = std::size_t(1) << 25;  // 33 M triangles: about 3 GB once refined and built

std::vector<std::uint32_t> triangleIndices(const ParamSet& p, std::size_t pointCount) {
    std::vector<int> idx = p.getInts("indices");
    if (idx.empty()) {
        if (pointCount != 3) p.fail("needs \"indices\" (only a single triangle may omit them)");
        idx = {0, 1, 2};
    }
    if (idx.size() % 3 != 0) p.fail("\"indices\" count " + std::to_string(idx.size()) + " is not a multiple of 3");
    std::vector<std::uint32_t> out;
    out.reserve(idx.size());
    for (int i : idx) {
        if (std::size_t(i) >= pointCount)
            p.fail("index " + std::to_string(i) + " out of range (" + std::to_string(pointCount) + " points)");
        out.push_back(std::uint32_t(i));
    }
    return out;
}

std::vector<Vec3f> controlPoints(const ParamSet& p) {
    std::vector<Vec3f> P = p.getPoints("P");
    if (P.size() < 3) p.fail("needs at least 3 points \"P\"");
    return P;
}

MeshData triangleMesh(const ParamSet& p) {
    MeshData m;
    m.p = controlPoints(p);
    m.indices = triangleIndices(p, m.p.size());
    m.n = p.getPoints("N");
    if (!m.n.empty() && m.n.size() != m.p.size()) p.fail("\"N\" needs one normal per point");
    const std::vector<double> uv = p.has("uv") ? p.getFloats("uv") : p.getFloats("st");
    if (!uv.empty() && uv.size() < 2 * m.p.size()) p.fail("\"uv\" needs two numbers per point");
    for (std::size_t i = 0; i < uv.size() && i < 2 * m.p.size(); ++i) m.uv.push_back(float(uv[i]));
    return m;
}

// pbrt-v4's bilinear patches, each four points p00 p10 p01 p11 ("indices", default 0 1 2 3), as
// two triangles: exact for flat patches (the common case: quads), a fold along the diagonal for
// twisted ones. Without "uv", each patch's corners take pbrt-v4's (0,0) (1,0) (0,1) (1,1).
MeshData bilinearMesh(const ParamSet& p) {
    MeshData m;
    const std::vector<Vec3f> P = p.getPoints("P");
    std::vector<int> corners = p.getInts("indices");
    if (corners.empty() && P.size() == 4) corners = {0, 1, 2, 3};
    if (corners.empty() || corners.size() % 4 != 0) p.fail("needs four \"indices\" per patch (or exactly four points \"P\")");
    for (int i : corners)
        if (std::size_t(i) >= P.size()) p.fail("index " + std::to_string(i) + " out of range (" + std::to_string(P.size()) + " points)");
    const std::vector<Vec3f> N = p.getPoints("N");
    const std::vector<double> uv = p.getFloats("uv");
    if (!N.empty() && N.size() != P.size()) p.fail("\"N\" needs one normal per point");
    if (!uv.empty() && uv.size() != 2 * P.size()) p.fail("\"uv\" needs two numbers per point");
    static const float kCornerUv[4][2] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
    // Vertices are unshared per patch so that default uvs can differ between patches.
    for (std::size_t q = 0; q < corners.size(); q += 4) {
        const auto base = std::uint32_t(m.p.size());
        for (int c = 0; c < 4; ++c) {
            const int i = corners[q + c];
            m.p.push_back(P[i]);
            if (!N.empty()) m.n.push_back(N[i]);
            m.uv.push_back(uv.empty() ? kCornerUv[c][0] : float(uv[2 * i]));
            m.uv.push_back(uv.empty() ? kCornerUv[c][1] : float(uv[2 * i + 1]));
        }
        m.indices.insert(m.indices.end(), {base, base + 1, base + 3, base, base + 3, base + 2});
    }
    return m;
}

// pbrt-v3's "discarddegenerateUVs": with shading normals, (u, v) that map a triangle's corners
// onto each other would give no usable texture frame, so all (u, v) go.
void discardDegenerateUvs(MeshData& m, const ParamSet& p, std::vector<std::string>& warnings) {
    if (!p.getBool("discarddegenerateUVs", false) || m.uv.empty() || m.n.empty()) return;
    auto same = [&](std::uint32_t a, std::uint32_t b) { return m.uv[2 * a] == m.uv[2 * b] && m.uv[2 * a + 1] == m.uv[2 * b + 1]; };
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const std::uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
        if (0.5f * length(cross(m.p[a] - m.p[b], m.p[c] - m.p[b])) < 1e-7f) continue;
        if (same(a, b) || same(b, c) || same(c, a)) {
            warnings.push_back(describe(p.where()) + ": degenerate (u, v) in the mesh: discarding all (u, v)");
            m.uv.clear();
            return;
        }
    }
}

// pbrt-v3's cutouts: where "alpha" (a number or a float texture) is 0 the mesh is not there for
// camera and scattered rays; "shadowalpha" does the same for shadow rays. Alpha 1 everywhere is
// no cutout at all.
void readCutouts(const ParamSet& p, const TextureMap& textures, MeshData& m) {
    const auto cutout = [&](const char* name) -> std::shared_ptr<const Texture> {
        if (!p.has(name)) return nullptr;
        if (!p.getColorOrTexture(name, {1, 1, 1}).texture && p.getFloat(name, 1) != 0) return nullptr;
        return floatTextureParam(p, name, 1, textures);
    };
    m.alpha = cutout("alpha");
    m.shadowAlpha = cutout("shadowalpha");
}

std::shared_ptr<const Shape> loopSubdivisionSurface(const ParamSet& p, const Transform& toGroup, bool ro) {
    const int levels = p.has("nlevels") ? p.getInt("nlevels", 3) : p.getInt("levels", 3);  // pbrt-v3 / pbrt-v4 names
    const std::vector<Vec3f> P = controlPoints(p);
    const std::vector<std::uint32_t> indices = triangleIndices(p, P.size());
    if (levels < 0) p.fail("nlevels must not be negative");
    std::size_t triangles = indices.size() / 3;
    for (int i = 0; i < levels; ++i)
        if ((triangles *= 4) > kMaxTriangles) p.fail("nlevels " + std::to_string(levels) + " would make too many triangles");
    try {
        return makeTriangleMesh(loopSubdivide(P, indices, levels), toGroup, ro);
    } catch (const std::invalid_argument& e) {
        p.fail(std::string("the control mesh is not a manifold: ") + e.what());
    }
}

}  // namespace

std::vector<std::shared_ptr<const Shape>> makeShapes(const std::string& type, const ParamSet& p,
                                                     const Transform& toGroup, bool ro, const TextureMap& textures,
                                                     const PathResolver& resolve, std::vector<std::string>& warnings) {
    std::shared_ptr<const Shape> shape;
    if (type == "sphere") {
        shape = makeSphere(p, toGroup, ro);
    } else if (type == "disk") {
        shape = makeDisk(p, toGroup, ro);
    } else if (type == "cylinder") {
        shape = makeCylinder(p, toGroup, ro);
    } else if (type == "cone") {
        shape = makeCone(p, toGroup, ro);
    } else if (type == "paraboloid") {
        shape = makeParaboloid(p, toGroup, ro);
    } else if (type == "hyperboloid") {
        shape = makeHyperboloid(p, toGroup, ro);
    } else if (type == "trianglemesh" || type == "plymesh") {
        MeshData m = type == "trianglemesh" ? triangleMesh(p)
                                            : readPlyMesh(resolve(p.getString("filename", ""), p.where()), p.where(), warnings);
        readCutouts(p, textures, m);
        discardDegenerateUvs(m, p, warnings);
        shape = makeTriangleMesh(std::move(m), toGroup, ro);
    } else if (type == "bilinearmesh") {
        shape = makeTriangleMesh(bilinearMesh(p), toGroup, ro);
    } else if (type == "loopsubdiv") {
        shape = loopSubdivisionSurface(p, toGroup, ro);
    } else if (type == "nurbs") {
        shape = makeTriangleMesh(diceNurbs(p), toGroup, ro);
    } else if (type == "curve") {
        shape = makeCurve(p, toGroup);
    } else {
        p.fail("shape \"" + type + "\" is not supported (sphere, disk, cylinder, cone, paraboloid, hyperboloid, "
               "trianglemesh, plymesh, bilinearmesh, loopsubdiv, nurbs, curve)");
    }
    // Tangents ("S") only turn an anisotropic shading frame; lenslab's materials are isotropic.
    p.checkAllUsed(warnings, {"S", "faceIndices", "scheme"});
    return {shape};
}

}  // namespace lenslab
