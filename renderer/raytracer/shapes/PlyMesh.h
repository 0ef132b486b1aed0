#pragma once
// pbrt-v3's "plymesh": a binary or ASCII PLY file read with assimp, its vertices (positions,
// normals, texture coordinates) and faces exactly as in the file; quads split as pbrt-v3 splits them.
#include <string>
#include <vector>

#include "shapes/TriangleMeshShape.h"

namespace lenslab {

// Throws SceneError at `where` naming the file and assimp's reason when the file does not parse or
// holds no triangles. Faces of other than 3 or 4 corners are skipped with a warning (as pbrt-v3).
MeshData readPlyMesh(const std::string& path, const SourceLocation& where, std::vector<std::string>& warnings);

}  // namespace lenslab
