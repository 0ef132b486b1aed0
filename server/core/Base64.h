#pragma once
// Standard base64 (RFC 4648, with padding): binary in JSON bodies (the editor's diagram PNG).
#include <cstdint>
#include <string>
#include <vector>

namespace lenslab {

std::string base64Encode(const std::vector<std::uint8_t>& bytes);

}  // namespace lenslab
