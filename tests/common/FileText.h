#pragma once
// A file's whole contents as bytes ("" when it cannot be read): what tests compare and send.
#include <fstream>
#include <sstream>
#include <string>

namespace lenslab::test {

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace lenslab::test
