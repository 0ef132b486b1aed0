#pragma once
// pbrt-v3's triangle mesh: vertices in the group's space, optional per-vertex normals and (u, v);
// one Embree triangle geometry. trianglemesh, plymesh and loopsubdiv all end up here.
#include <cstdint>
#include <memory>
#include <vector>

#include "shapes/Shape.h"

namespace lenslab {

struct MeshData {
    std::vector<Vec3f> p, n;             // n: empty or one per point
    std::vector<float> uv;               // empty or two per point
    std::vector<std::uint32_t> indices;  // three per triangle, each < p.size()
    std::shared_ptr<const Texture> alpha, shadowAlpha;  // cutouts: no surface where they are 0
};

// Moves the mesh from its object space into the group's space (points, and normals by the inverse
// transpose) and wraps it as a shape. flipNormals: ReverseOrientation xor a handedness swap.
std::shared_ptr<const Shape> makeTriangleMesh(MeshData mesh, const Transform& objectToGroup, bool reverseOrientation);

}  // namespace lenslab
