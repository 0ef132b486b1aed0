#pragma once
// A strict well-formedness check of generated HTML: every element closed in order (void elements
// and self-closed SVG elements excepted), attributes quoted or bare, entities well formed, ids
// unique. Stricter than HTML itself, which is what a generator should meet.
#include <map>
#include <string>
#include <vector>

namespace lenslab::test {

struct HtmlElement {
    std::string name;  // lower case
    std::map<std::string, std::string> attributes;
};

struct HtmlCheck {
    std::vector<std::string> errors;    // empty: well formed
    std::vector<HtmlElement> elements;  // every start tag, in document order
};

HtmlCheck checkHtml(const std::string& html);

}  // namespace lenslab::test
