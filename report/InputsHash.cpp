#include "InputsHash.h"

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

namespace lenslab {

void InputsHash::bytes(const void* data, std::size_t size) {
    constexpr std::uint64_t kPrime = 0x100000001b3ull;
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
        a_ = (a_ ^ p[i]) * kPrime;
        b_ = (b_ ^ p[i] ^ 0x5a) * kPrime;
    }
}

InputsHash& InputsHash::add(const std::string& text) {
    const std::uint64_t n = text.size();
    bytes(&n, sizeof n);
    bytes(text.data(), text.size());
    return *this;
}

InputsHash& InputsHash::add(double value) {
    std::uint64_t bits;
    std::memcpy(&bits, &value, sizeof bits);
    bytes(&bits, sizeof bits);
    return *this;
}

InputsHash& InputsHash::addFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return add("missing file " + path);
    return add(std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()));
}

std::string InputsHash::hex() const {
    char b[40];
    std::snprintf(b, sizeof b, "%016llx%016llx", static_cast<unsigned long long>(a_), static_cast<unsigned long long>(b_));
    return b;
}

}  // namespace lenslab
