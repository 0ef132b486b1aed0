#include "guards/ResponseEncoding.h"

#include <cstdlib>

#include "core/CommaList.h"
#include "core/LowerCase.h"

namespace lenslab {

namespace {

// A coding's quality ("gzip;q=0.5" -> 0.5); 1 without one.
double quality(const std::string& coding) {
    const std::string lower = lowerCase(coding);
    const std::size_t q = lower.find("q=", lower.find(';'));
    return lower.find(';') == std::string::npos || q == std::string::npos ? 1.0 : std::atof(lower.c_str() + q + 2);
}

// "gzip;q=0, deflate, br;q=0.9" -> "deflate": the codings the client accepts (quality above 0)
// but Brotli. cpp-httplib looks for "gzip" anywhere in the header, "gzip;q=0" included.
std::string acceptedWithoutBrotli(const std::string& accepted) {
    std::string kept;
    for (const std::string& coding : commaListEntries(accepted)) {
        const std::string name = lowerCase(trimmedText(coding.substr(0, coding.find(';'))));
        if (name == "br" || !(quality(coding) > 0)) continue;
        kept += (kept.empty() ? "" : ", ") + coding;
    }
    return kept;
}

}  // namespace

void declineBrotli(const httplib::Request& req) {
    auto& headers = const_cast<httplib::Request&>(req).headers;
    const auto [begin, end] = headers.equal_range("Accept-Encoding");
    for (auto it = begin; it != end; ++it) it->second = acceptedWithoutBrotli(it->second);
}

}  // namespace lenslab
