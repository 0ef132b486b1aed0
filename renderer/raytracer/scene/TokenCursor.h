#pragma once
// Reading position in one scene file's tokens, with the typed reads every directive needs. Errors
// name the file, line and directive.
#include <string>
#include <vector>

#include "core/ParamSet.h"
#include "scene/SceneTokenizer.h"

namespace lenslab {

class TokenCursor {
public:
    TokenCursor(std::string file, std::vector<Token> tokens) : file_(std::move(file)), tokens_(std::move(tokens)) {}

    const std::string& file() const { return file_; }
    bool atEnd() const { return pos_ >= tokens_.size(); }
    const Token& peek() const { return tokens_[pos_]; }
    bool peekBracket() const { return !atEnd() && !peek().quoted && peek().text == "["; }
    const Token& take(const SourceLocation& where, const char* what);
    void skipToEnd() { pos_ = tokens_.size(); }
    // Fraction of the file read, for progress lines.
    double fraction() const { return tokens_.empty() ? 1.0 : double(pos_) / double(tokens_.size()); }

    double number(const SourceLocation& where);
    std::string quoted(const SourceLocation& where, const char* what);
    // Exactly `count` numbers, bracketed or not (Transform, ConcatTransform).
    std::vector<double> numberArray(const SourceLocation& where, std::size_t count);
    // The bracketed list or single value after a parameter declaration.
    std::vector<Token> valueList(const SourceLocation& where, const std::string& declaration);

private:
    std::string file_;
    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
};

// A finite number; otherwise SceneError at the token's line.
double tokenNumber(const Token& t, const SourceLocation& where);

}  // namespace lenslab
