#include "HtmlCheck.h"

#include <cctype>
#include <regex>
#include <set>

namespace lenslab::test {

namespace {

const std::set<std::string> kVoid = {"area", "base", "br", "col", "embed", "hr", "img", "input",
                                     "link", "meta", "source", "track", "wbr"};

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Line number of an offset, for messages.
int lineOf(const std::string& html, std::size_t offset) {
    int line = 1;
    for (std::size_t i = 0; i < offset && i < html.size(); ++i) line += html[i] == '\n';
    return line;
}

void checkEntities(const std::string& text, std::size_t offset, const std::string& html, std::vector<std::string>& errors) {
    static const std::regex entity("^&([A-Za-z][A-Za-z0-9]*|#[0-9]+|#x[0-9A-Fa-f]+);");
    for (std::size_t i = text.find('&'); i != std::string::npos; i = text.find('&', i + 1))
        if (!std::regex_search(text.begin() + i, text.end(), entity))
            errors.push_back("line " + std::to_string(lineOf(html, offset + i)) + ": a bare '&' (write &amp;)");
}

}  // namespace

HtmlCheck checkHtml(const std::string& html) {
    HtmlCheck result;
    auto& errors = result.errors;
    std::vector<std::pair<std::string, std::size_t>> open;  // name, offset
    std::set<std::string> ids;
    std::size_t i = 0;
    while (i < html.size()) {
        const std::size_t lt = html.find('<', i);
        checkEntities(html.substr(i, lt == std::string::npos ? std::string::npos : lt - i), i, html, errors);
        if (lt == std::string::npos) break;
        const std::string where = "line " + std::to_string(lineOf(html, lt)) + ": ";
        if (html.compare(lt, 4, "<!--") == 0) {
            const std::size_t end = html.find("-->", lt + 4);
            if (end == std::string::npos) {
                errors.push_back(where + "unterminated comment");
                break;
            }
            i = end + 3;
            continue;
        }
        if (html.compare(lt, 2, "<!") == 0) {  // doctype
            const std::size_t end = html.find('>', lt);
            if (lower(html.substr(lt, 15)) != "<!doctype html>") errors.push_back(where + "unexpected declaration");
            i = end == std::string::npos ? html.size() : end + 1;
            continue;
        }
        std::size_t p = lt + 1;
        const bool closing = p < html.size() && html[p] == '/';
        if (closing) ++p;
        std::size_t nameEnd = p;
        while (nameEnd < html.size() && (std::isalnum(static_cast<unsigned char>(html[nameEnd])) || html[nameEnd] == '-'))
            ++nameEnd;
        if (nameEnd == p) {
            errors.push_back(where + "a bare '<' (write &lt;)");
            i = lt + 1;
            continue;
        }
        const std::string name = lower(html.substr(p, nameEnd - p));
        HtmlElement element{name, {}};
        bool selfClosed = false;
        p = nameEnd;
        for (;;) {
            while (p < html.size() && std::isspace(static_cast<unsigned char>(html[p]))) ++p;
            if (p >= html.size()) {
                errors.push_back(where + "unterminated tag <" + name);
                return result;
            }
            if (html[p] == '>') {
                ++p;
                break;
            }
            if (html.compare(p, 2, "/>") == 0) {
                selfClosed = true;
                p += 2;
                break;
            }
            std::size_t a = p;
            while (a < html.size() && !std::isspace(static_cast<unsigned char>(html[a])) && html[a] != '=' && html[a] != '>' &&
                   html[a] != '/' && html[a] != '"' && html[a] != '\'' && html[a] != '<')
                ++a;
            if (a == p) {
                errors.push_back(where + "malformed attribute in <" + name + ">");
                ++p;
                continue;
            }
            const std::string attribute = lower(html.substr(p, a - p));
            std::string value;
            p = a;
            if (p < html.size() && html[p] == '=') {
                ++p;
                if (p < html.size() && (html[p] == '"' || html[p] == '\'')) {
                    const std::size_t close = html.find(html[p], p + 1);
                    if (close == std::string::npos) {
                        errors.push_back(where + "unterminated attribute value in <" + name + ">");
                        return result;
                    }
                    value = html.substr(p + 1, close - p - 1);
                    checkEntities(value, p + 1, html, errors);
                    p = close + 1;
                } else {
                    const std::size_t start = p;
                    while (p < html.size() && !std::isspace(static_cast<unsigned char>(html[p])) && html[p] != '>') ++p;
                    value = html.substr(start, p - start);
                }
            }
            if (element.attributes.count(attribute)) errors.push_back(where + "duplicate attribute " + attribute);
            element.attributes[attribute] = value;
        }
        i = p;
        if (closing) {
            if (open.empty()) errors.push_back(where + "</" + name + "> closes nothing");
            else if (open.back().first != name)
                errors.push_back(where + "</" + name + "> closes <" + open.back().first + "> of line " +
                                 std::to_string(lineOf(html, open.back().second)));
            else open.pop_back();
            continue;
        }
        if (element.attributes.count("id") && !ids.insert(element.attributes["id"]).second)
            errors.push_back(where + "duplicate id " + element.attributes["id"]);
        result.elements.push_back(element);
        if (selfClosed || kVoid.count(name)) continue;
        open.push_back({name, lt});
        if (name == "style" || name == "script") {  // raw text up to the end tag
            const std::size_t end = html.find("</" + name, i);
            i = end == std::string::npos ? html.size() : end;
        }
    }
    for (const auto& [name, offset] : open)
        errors.push_back("line " + std::to_string(lineOf(html, offset)) + ": <" + name + "> is never closed");
    return result;
}

}  // namespace lenslab::test
