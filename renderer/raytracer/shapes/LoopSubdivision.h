#pragma once
// pbrt-v3's "loopsubdiv" shape: Loop's subdivision rules applied `levels` times to a triangle
// control mesh (boundary edges and vertices by the boundary rules), then every vertex moved to
// its limit position and given the limit surface's normal, as pbrt-v3 does.
#include <cstdint>
#include <vector>

#include "shapes/TriangleMeshShape.h"

namespace lenslab {

// Throws std::invalid_argument for a control mesh Loop's rules cannot walk: an edge shared by more
// than two triangles or by two of the same winding, or a vertex whose triangles form several fans.
MeshData loopSubdivide(const std::vector<Vec3f>& points, const std::vector<std::uint32_t>& indices, int levels);

}  // namespace lenslab
