#pragma once
// Reading and writing the files of the site folder. Writes go to a temporary file renamed into
// place, so a browser or the server never sees half a file while the report is rebuilt.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lenslab {

// Writes siteDir/relativePath, creating folders. Throws std::runtime_error naming the file.
void writeSiteFile(const std::filesystem::path& siteDir, const std::string& relativePath, const std::string& content);
void writeSiteFile(const std::filesystem::path& siteDir, const std::string& relativePath,
                   const std::vector<std::uint8_t>& content);

// The whole file; throws std::runtime_error naming it when it cannot be read.
std::vector<std::uint8_t> readBinaryFile(const std::filesystem::path& path);

}  // namespace lenslab
