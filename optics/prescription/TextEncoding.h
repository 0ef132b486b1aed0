#pragma once
// Lens files as UTF-8 text: Windows programs (Zemax among them) save UTF-16 with a byte order mark.
#include <string>

namespace lenslab {

// True when the bytes start with a UTF-16 byte order mark (LE FF FE or BE FE FF).
bool startsWithUtf16ByteOrderMark(const std::string& bytes);

// The bytes as UTF-8 without a byte order mark: UTF-16 LE/BE (by its mark) is converted, UTF-8 is
// kept. Throws LensTableError naming `name` and the line for an odd byte count or a broken
// surrogate pair.
std::string toUtf8Text(const std::string& bytes, const std::string& name);

// ASCII letters in upper case: glass, catalog and command names compare without case.
std::string upperCase(std::string s);

}  // namespace lenslab
