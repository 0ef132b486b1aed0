#include "core/CompressedFile.h"

#include <zlib.h>

namespace lenslab {

std::optional<std::string> readPossiblyGzipped(const std::string& path) {
    gzFile f = gzopen(path.c_str(), "rb");
    if (!f) return std::nullopt;
    std::string text;
    char buffer[1 << 16];
    int n = 0;
    while ((n = gzread(f, buffer, sizeof buffer)) > 0) text.append(buffer, std::size_t(n));
    const bool failed = n < 0;
    gzclose(f);
    if (failed) return std::nullopt;
    return text;
}

bool isGzipName(const std::string& path) { return path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0; }

}  // namespace lenslab
