#pragma once
// pbrt-v4's scene collection ships includes as .pbrt.gz and meshes as .ply.gz: files are read
// through zlib, which passes uncompressed files through unchanged.
#include <optional>
#include <string>

namespace lenslab {

// The whole file, decompressed when it is gzip; nullopt when it cannot be opened or is corrupt.
std::optional<std::string> readPossiblyGzipped(const std::string& path);

bool isGzipName(const std::string& path);  // ends in .gz

}  // namespace lenslab
