#include "guards/ResponseEncoding.h"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace lenslab {

namespace {

std::string trimmed(const std::string& s) {
    const auto begin = s.find_first_not_of(" \t");
    if (begin == std::string::npos) return "";
    return s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
}

// "gzip, deflate, br;q=0.9" -> "gzip, deflate": every coding but Brotli, parameters kept.
std::string withoutBrotli(const std::string& accepted) {
    std::istringstream codings(accepted);
    std::string kept;
    for (std::string coding; std::getline(codings, coding, ',');) {
        coding = trimmed(coding);
        std::string name = trimmed(coding.substr(0, coding.find(';')));
        std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
        if (name == "br" || coding.empty()) continue;
        kept += (kept.empty() ? "" : ", ") + coding;
    }
    return kept;
}

}  // namespace

void declineBrotli(const httplib::Request& req) {
    auto& headers = const_cast<httplib::Request&>(req).headers;
    const auto [begin, end] = headers.equal_range("Accept-Encoding");
    for (auto it = begin; it != end; ++it) it->second = withoutBrotli(it->second);
}

}  // namespace lenslab
