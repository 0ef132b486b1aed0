#pragma once
// What a field of a written prescription may hold. A .dat or .zmx field is text on one line of the
// file: a line break (or a character a reader may take for one) in a comment, name or glass would
// start a row or a keyword line of its own, and the file would read back as another lens.
#include <optional>
#include <string>

namespace lenslab {

// Why `text` cannot be written within one line (a control character other than tab, a Unicode
// line or paragraph separator, malformed UTF-8), or nullopt.
std::optional<std::string> lineTextProblem(const std::string& text);

// Why `text` cannot be written as one word of a line (a glass or catalog name): the above, or
// empty, or holding a space.
std::optional<std::string> wordTextProblem(const std::string& text);

}  // namespace lenslab
