#include "core/Identifiers.h"

#include <cctype>
#include <mutex>
#include <random>

namespace lenslab {

bool isSafeIdentifier(const std::string& id) {
    if (id.empty() || id.size() > 80 || !std::isalnum(static_cast<unsigned char>(id[0]))) return false;
    for (char c : id)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_' && c != '-') return false;
    return true;
}

std::string newRandomIdentifier(const std::string& prefix) {
    static std::mutex mutex;
    static std::mt19937_64 generator{std::random_device{}()};
    std::uint64_t bits;
    {
        std::lock_guard<std::mutex> lock(mutex);
        bits = generator();
    }
    static const char* kHex = "0123456789abcdef";
    std::string id = prefix;
    for (int shift = 60; shift >= 0; shift -= 4) id += kHex[(bits >> shift) & 0xf];
    return id;
}

}  // namespace lenslab
