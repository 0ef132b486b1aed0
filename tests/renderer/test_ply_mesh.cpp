// plymesh: ASCII and binary PLY files (written here) give the same mesh as the equivalent
// trianglemesh, quads split as pbrt-v3 splits them; a file that does not parse is an error naming
// it and assimp's reason.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "ShapeTestScenes.h"

namespace lenslab {
namespace {

// A quad and a triangle, with per-vertex normals (one tilted) and (u, v).
struct Vertex {
    float p[3], n[3], uv[2];
};
const Vertex kVertices[] = {{{0, 0, 2}, {0, 0, -1}, {0, 0}},     {{1, 0, 2}, {0, 0, -1}, {1, 0}},
                            {{1, 1, 2}, {0, 0, -1}, {1, 1}},     {{0, 1, 2}, {0, 0, -1}, {0, 1}},
                            {{0.5f, 1.5f, 2}, {0, 0.6f, -0.8f}, {0.5f, 1}}};
const std::vector<std::vector<int>> kFaces = {{0, 1, 2, 3}, {3, 2, 4}};

std::string header(const std::string& format) {
    return "ply\nformat " + format + " 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
           "property float nx\nproperty float ny\nproperty float nz\nproperty float u\nproperty float v\n"
           "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string asciiPly() {
    std::ostringstream s;
    s << header("ascii");
    for (const Vertex& v : kVertices)
        s << v.p[0] << " " << v.p[1] << " " << v.p[2] << " " << v.n[0] << " " << v.n[1] << " " << v.n[2] << " " << v.uv[0]
          << " " << v.uv[1] << "\n";
    for (const auto& f : kFaces) {
        s << f.size();
        for (int i : f) s << " " << i;
        s << "\n";
    }
    return s.str();
}

std::string binaryPly() {
    std::string s = header("binary_little_endian");
    const auto put = [&](const void* data, std::size_t n) { s.append(static_cast<const char*>(data), n); };
    for (const Vertex& v : kVertices) put(&v, sizeof v);  // 8 floats, in the header's order
    for (const auto& f : kFaces) {
        const auto count = std::uint8_t(f.size());
        put(&count, 1);
        for (std::int32_t i : f) put(&i, 4);
    }
    return s;
}

// The same mesh as pbrt-v3 reads it: the quad 0 1 2 3 becomes (0 1 2) and (3 0 2).
const char* kTriangleMesh =
    "Shape \"trianglemesh\" \"integer indices\" [0 1 2  3 0 2  3 2 4]\n"
    "  \"point P\" [0 0 2  1 0 2  1 1 2  0 1 2  0.5 1.5 2]\n"
    "  \"normal N\" [0 0 -1  0 0 -1  0 0 -1  0 0 -1  0 0.6 -0.8]\n"
    "  \"float uv\" [0 0  1 0  1 1  0 1  0.5 1]";

void expectSameSurface(const Shape& a, const Shape& b) {
    ASSERT_EQ(a.primitiveCount(), b.primitiveCount());
    for (unsigned prim = 0; prim < a.primitiveCount(); ++prim) {
        EXPECT_FLOAT_EQ(a.primitiveArea(prim), b.primitiveArea(prim));
        for (const auto& bary : {std::pair{0.2f, 0.3f}, std::pair{0.7f, 0.1f}, std::pair{0.0f, 1.0f}}) {
            SurfaceHit ha, hb;
            a.surface({}, {}, 0, prim, bary.first, bary.second, ha);
            b.surface({}, {}, 0, prim, bary.first, bary.second, hb);
            EXPECT_FLOAT_EQ(ha.p.x, hb.p.x);
            EXPECT_FLOAT_EQ(ha.p.y, hb.p.y);
            EXPECT_FLOAT_EQ(ha.ng.z, hb.ng.z);
            EXPECT_FLOAT_EQ(ha.ns.y, hb.ns.y);
            EXPECT_FLOAT_EQ(ha.ns.z, hb.ns.z);
            EXPECT_FLOAT_EQ(ha.u, hb.u);
            EXPECT_FLOAT_EQ(ha.v, hb.v);
        }
    }
}

TEST(PlyMesh, AsciiAndBinaryEqualTheTriangleMesh) {
    test::TempDir dir;
    dir.write("ascii.ply", asciiPly());
    dir.write("binary.ply", binaryPly());
    const SceneDescription s = test::parseWorld(dir, std::string(kTriangleMesh) +
                                                         "\nShape \"plymesh\" \"string filename\" \"ascii.ply\""
                                                         "\nShape \"plymesh\" \"string filename\" \"binary.ply\"");
    ASSERT_EQ(s.shapes.size(), 3u);
    ASSERT_EQ(s.shapes[0].shape->primitiveCount(), 3u);
    expectSameSurface(*s.shapes[0].shape, *s.shapes[1].shape);
    expectSameSurface(*s.shapes[0].shape, *s.shapes[2].shape);
    // The tilted normal reaches the shading normal: halfway along the edge from vertex 2 to 4.
    SurfaceHit h;
    s.shapes[2].shape->surface({}, {}, 0, 2, 0.5f, 0.5f, h);
    EXPECT_NEAR(h.ns.y, normalize(Vec3f{0, 0.6f, -1.8f}).y, 1e-6);
    EXPECT_NEAR(h.u, 0.75, 1e-6);
    EXPECT_NEAR(h.v, 1, 1e-6);
}

TEST(PlyMesh, RendersUnderTheCurrentTransform) {
    test::TempDir dir;
    dir.write("m.ply", binaryPly());
    const auto g = test::geometryOf(dir, "Translate 0 0 3\nShape \"plymesh\" \"string filename\" \"m.ply\"");
    Intersection it;
    ASSERT_TRUE(test::trace(*g, {0.25f, 0.5f, 0}, {0, 0, 1}, it));
    EXPECT_NEAR(it.t, 5, 1e-5);
    EXPECT_NEAR(it.hit.u, 0.25, 1e-6);
    EXPECT_NEAR(it.hit.v, 0.5, 1e-6);
}

TEST(PlyMesh, UnreadableFilesNameTheFileAndTheReason) {
    test::TempDir dir;
    dir.write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1\n");
    dir.write("junk.ply", "this is not a mesh\n");
    for (const std::string file : {"bad.ply", "junk.ply"}) {
        try {
            test::parseWorld(dir, "Shape \"plymesh\" \"string filename\" \"" + file + "\"");
            ADD_FAILURE() << file << ": no error";
        } catch (const SceneError& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("s.pbrt:5: Shape \"plymesh\": "), std::string::npos) << m;
            EXPECT_NE(m.find(file), std::string::npos) << m;
            if (file == "junk.ply") {  // assimp's reason follows
                EXPECT_NE(m.find("cannot read PLY file"), std::string::npos) << m;
            }
        }
    }
}

}  // namespace
}  // namespace lenslab
