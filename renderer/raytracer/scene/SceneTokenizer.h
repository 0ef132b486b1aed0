#pragma once
// Splits pbrt-v3 scene text into tokens: bare words and numbers, "quoted strings", [ and ], with
// '#' comments dropped. Every token keeps its line for messages.
#include <string>
#include <vector>

namespace lenslab {

struct Token {
    std::string text;     // without the quotes
    int line = 0;
    bool quoted = false;
    const std::string* file = nullptr;  // set by TokenCursor::include, which owns the name
};

// Throws SceneError for an unterminated string (naming file and line).
std::vector<Token> tokenizeScene(const std::string& text, const std::string& fileName);

}  // namespace lenslab
