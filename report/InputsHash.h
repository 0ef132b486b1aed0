#pragma once
// A fingerprint of everything an output of the report depends on (file contents, parameters, the
// lenslab version), so that an unchanged item can be reused instead of rebuilt.
#include <cstdint>
#include <string>

namespace lenslab {

class InputsHash {
public:
    InputsHash& add(const std::string& text);       // length-prefixed: "ab"+"c" differs from "a"+"bc"
    InputsHash& add(double value);                  // exact bits
    InputsHash& addFile(const std::string& path);   // its content; a missing file hashes as such
    std::string hex() const;                        // 32 hex digits

private:
    // Two FNV-1a streams with different offsets: 128 bits keep accidental collisions out of reach.
    std::uint64_t a_ = 0xcbf29ce484222325ull, b_ = 0x84222325cbf29ce4ull;
    void bytes(const void* data, std::size_t size);
};

}  // namespace lenslab
