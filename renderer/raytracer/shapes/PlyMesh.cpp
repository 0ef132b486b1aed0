#include "shapes/PlyMesh.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include "core/CompressedFile.h"

namespace lenslab {

MeshData readPlyMesh(const std::string& path, const SourceLocation& where, std::vector<std::string>& warnings) {
    Assimp::Importer importer;
    // No post-processing: every step that helps games (joining vertices, generating normals) would
    // change the mesh pbrt-v3 renders.
    const aiScene* scene = nullptr;
    if (isGzipName(path)) {  // pbrt-v4's .ply.gz
        const std::optional<std::string> bytes = readPossiblyGzipped(path);
        if (!bytes) sceneFail(where, "cannot decompress '" + path + "'");
        scene = importer.ReadFileFromMemory(bytes->data(), bytes->size(), 0, "ply");
    } else {
        scene = importer.ReadFile(path, 0);
    }
    if (!scene) sceneFail(where, "cannot read PLY file '" + path + "': " + importer.GetErrorString());
    MeshData m;
    std::size_t skipped = 0;
    for (unsigned k = 0; k < scene->mNumMeshes; ++k) {
        const aiMesh& a = *scene->mMeshes[k];
        const auto base = std::uint32_t(m.p.size());
        const bool normals = a.HasNormals(), uvs = a.HasTextureCoords(0);
        if (k > 0 && (normals != !m.n.empty() || uvs != !m.uv.empty()))
            sceneFail(where, "PLY file '" + path + "': its parts disagree on normals or texture coordinates");
        for (unsigned i = 0; i < a.mNumVertices; ++i) {
            m.p.push_back({a.mVertices[i].x, a.mVertices[i].y, a.mVertices[i].z});
            if (normals) m.n.push_back({a.mNormals[i].x, a.mNormals[i].y, a.mNormals[i].z});
            if (uvs) {
                m.uv.push_back(a.mTextureCoords[0][i].x);
                m.uv.push_back(a.mTextureCoords[0][i].y);
            }
        }
        for (unsigned f = 0; f < a.mNumFaces; ++f) {
            const aiFace& face = a.mFaces[f];
            const unsigned* i = face.mIndices;
            if (face.mNumIndices != 3 && face.mNumIndices != 4) {
                ++skipped;
                continue;
            }
            for (unsigned c = 0; c < face.mNumIndices; ++c)
                if (i[c] >= a.mNumVertices)
                    sceneFail(where, "PLY file '" + path + "': face " + std::to_string(f) + " names vertex " +
                                         std::to_string(i[c]) + " of " + std::to_string(a.mNumVertices));
            m.indices.insert(m.indices.end(), {base + i[0], base + i[1], base + i[2]});
            if (face.mNumIndices == 4) m.indices.insert(m.indices.end(), {base + i[3], base + i[0], base + i[2]});
        }
    }
    if (skipped)
        warnings.push_back(describe(where) + ": skipped " + std::to_string(skipped) + " faces of '" + path +
                           "' that are neither triangles nor quads (as pbrt-v3)");
    if (m.indices.empty()) sceneFail(where, "PLY file '" + path + "' holds no triangles or quads");
    return m;
}

}  // namespace lenslab
