#include "scene/TokenCursor.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace lenslab {

SourceLocation locate(const Token& t, const SourceLocation& where) {
    return {t.file ? *t.file : where.file, t.line, where.directive};
}

double tokenNumber(const Token& t, const SourceLocation& where) {
    if (t.quoted || t.text == "[" || t.text == "]") sceneFail(locate(t, where), "expected a number, got '" + t.text + "'");
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(t.text.c_str(), &end);
    if (end != t.text.c_str() + t.text.size() || errno == ERANGE || !std::isfinite(v))
        sceneFail(locate(t, where), "bad number '" + t.text + "'");
    return v;
}

void TokenCursor::include(const std::string& file, std::vector<Token> tokens) {
    names_.push_back(file);
    for (Token& t : tokens) t.file = &names_.back();
    if (open_.empty()) mainSize_ = tokens.size();
    open_.push_back({std::move(tokens)});
}

bool TokenCursor::atEnd() const {
    for (const OpenFile& f : open_)
        if (!f.done()) return false;
    return true;
}

const Token& TokenCursor::peek() const {
    auto f = open_.rbegin();
    while (f->done()) ++f;
    return f->tokens[f->pos];
}

const Token& TokenCursor::take(const SourceLocation& where, const char* what) {
    if (atEnd()) sceneFail(where, std::string("expected ") + what + " but the file ended");
    // Files are closed only here, when the stream moves on past them (see depth()).
    while (open_.back().done()) open_.pop_back();
    OpenFile& f = open_.back();
    return f.tokens[f.pos++];
}

double TokenCursor::fraction() const {
    if (mainSize_ == 0) return 1.0;
    return open_.empty() ? 1.0 : double(open_.front().pos) / double(mainSize_);
}

double TokenCursor::number(const SourceLocation& where) { return tokenNumber(take(where, "a number"), where); }

std::string TokenCursor::quoted(const SourceLocation& where, const char* what) {
    const Token& t = take(where, what);
    if (!t.quoted) sceneFail(where, std::string("expected ") + what + " in quotes, got '" + t.text + "'");
    return t.text;
}

std::vector<double> TokenCursor::numberArray(const SourceLocation& where, std::size_t count) {
    std::vector<double> v;
    const bool bracket = peekBracket();
    if (bracket) take(where, "[");
    while (v.size() < count) v.push_back(number(where));
    if (bracket && take(where, "]").text != "]") sceneFail(where, "expected " + std::to_string(count) + " numbers in [ ]");
    return v;
}

std::vector<Token> TokenCursor::valueList(const SourceLocation& where, const std::string& declaration) {
    std::vector<Token> values;
    if (atEnd()) sceneFail(where, "parameter \"" + declaration + "\" has no value");
    if (peekBracket()) {
        take(where, "[");
        while (true) {
            const Token& t = take(where, "]");
            if (t.text == "]" && !t.quoted) break;
            values.push_back(t);
        }
    } else {
        values.push_back(take(where, "a value"));
    }
    if (values.empty()) sceneFail(where, "parameter \"" + declaration + "\" has an empty value list");
    return values;
}

}  // namespace lenslab
