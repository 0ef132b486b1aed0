#include "scene/SceneTokenizer.h"

#include <cctype>

#include "Render.h"

namespace lenslab {

std::vector<Token> tokenizeScene(const std::string& text, const std::string& fileName) {
    std::vector<Token> tokens;
    int line = 1;
    std::size_t i = 0;
    const std::size_t n = text.size();
    while (i < n) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            ++i;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (c == '#') {
            while (i < n && text[i] != '\n') ++i;
        } else if (c == '[' || c == ']') {
            tokens.push_back({std::string(1, c), line, false});
            ++i;
        } else if (c == '"') {
            const int start = line;
            std::size_t j = i + 1;
            while (j < n && text[j] != '"' && text[j] != '\n') ++j;
            if (j >= n || text[j] != '"')
                throw SceneError(fileName + ":" + std::to_string(start) + ": unterminated string");
            tokens.push_back({text.substr(i + 1, j - i - 1), line, true});
            i = j + 1;
        } else {
            std::size_t j = i;
            while (j < n && !std::isspace(static_cast<unsigned char>(text[j])) && text[j] != '"' && text[j] != '[' &&
                   text[j] != ']' && text[j] != '#')
                ++j;
            tokens.push_back({text.substr(i, j - i), line, false});
            i = j;
        }
    }
    return tokens;
}

}  // namespace lenslab
