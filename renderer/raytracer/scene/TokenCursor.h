#pragma once
// Reading position in a scene's token stream, with the typed reads every directive needs. As in
// pbrt, an Include splices the included file's tokens into the stream where it stands, so a
// directive at the end of an included file takes the parameters that follow the Include. Errors
// name the file and line of the token at fault, and the directive.
#include <deque>
#include <string>
#include <vector>

#include "core/ParamSet.h"
#include "scene/SceneTokenizer.h"

namespace lenslab {

class TokenCursor {
public:
    // Reads `tokens` (from `file`) before the rest of the stream.
    void include(const std::string& file, std::vector<Token> tokens);

    bool atEnd() const;
    const Token& peek() const;  // not at the end
    bool peekBracket() const { return !atEnd() && !peek().quoted && peek().text == "["; }
    // The reference lasts until the next take.
    const Token& take(const SourceLocation& where, const char* what);
    void skipToEnd() { open_.clear(); }
    // Files open at the read position: 1 in the main file. A file whose last token was read still
    // counts until the next take, so an Include at the end of a file that includes itself nests.
    std::size_t depth() const { return open_.size(); }
    // Fraction of the main file read, for progress lines.
    double fraction() const;

    double number(const SourceLocation& where);
    std::string quoted(const SourceLocation& where, const char* what);
    // Exactly `count` numbers, bracketed or not (Transform, ConcatTransform).
    std::vector<double> numberArray(const SourceLocation& where, std::size_t count);
    // The bracketed list or single value after a parameter declaration.
    std::vector<Token> valueList(const SourceLocation& where, const std::string& declaration);

private:
    struct OpenFile {
        std::vector<Token> tokens;
        std::size_t pos = 0;
        bool done() const { return pos >= tokens.size(); }
    };
    std::deque<std::string> names_;  // every file read; a deque keeps the tokens' pointers valid
    std::vector<OpenFile> open_;     // the main file, then the Includes open at the read position
    std::size_t mainSize_ = 0;       // for fraction() once the main file is closed
};

// `where` at the token's file and line.
SourceLocation locate(const Token& t, const SourceLocation& where);

// A finite number; otherwise SceneError at the token's file and line.
double tokenNumber(const Token& t, const SourceLocation& where);

}  // namespace lenslab
