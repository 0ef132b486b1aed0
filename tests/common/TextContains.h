#pragma once
// Whether a message or a written file holds a phrase: what tests check of text they do not parse.
#include <string>

namespace lenslab::test {

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace lenslab::test
