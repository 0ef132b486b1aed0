#include "SiteFiles.h"

#include <fstream>
#include <iterator>
#include <stdexcept>

namespace lenslab {

namespace fs = std::filesystem;

namespace {

void writeBytes(const fs::path& siteDir, const std::string& relativePath, const char* data, std::size_t size) {
    const fs::path target = siteDir / relativePath;
    fs::create_directories(target.parent_path());
    const fs::path temporary = target.string() + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out.write(data, static_cast<std::streamsize>(size));
        if (!out) throw std::runtime_error("cannot write " + temporary.string());
    }
    fs::rename(temporary, target);
}

}  // namespace

void writeSiteFile(const fs::path& siteDir, const std::string& relativePath, const std::string& content) {
    writeBytes(siteDir, relativePath, content.data(), content.size());
}

void writeSiteFile(const fs::path& siteDir, const std::string& relativePath, const std::vector<std::uint8_t>& content) {
    writeBytes(siteDir, relativePath, reinterpret_cast<const char*>(content.data()), content.size());
}

std::vector<std::uint8_t> readBinaryFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace lenslab
