#include "guards/RequestChecks.h"

#include <algorithm>
#include <string>

#include "core/LowerCase.h"

namespace lenslab {

namespace {

bool sendsBody(const httplib::Request& req) {
    return req.has_header("Content-Length") || req.has_header("Transfer-Encoding");
}

// The declared body length when it is a plain number.
std::optional<unsigned long long> declaredLength(const httplib::Request& req) {
    const std::string text = req.get_header_value("Content-Length");
    if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 19) return std::nullopt;
    return std::stoull(text);
}

}  // namespace

std::optional<HttpError> refuseRequestHead(const httplib::Request& req, const HttpLimits& limits) {
    if (req.get_header_value_count("Content-Length") > 1 || req.get_header_value_count("Transfer-Encoding") > 1 ||
        (req.has_header("Content-Length") && req.has_header("Transfer-Encoding")))
        return HttpError(400, "the request gives its body length more than once (Content-Length / Transfer-Encoding)");
    // cpp-httplib takes the first of two Host headers, a proxy in front perhaps the last.
    if (req.get_header_value_count("Host") > 1) return HttpError(400, "the request names its host more than once (Host)");
    // Any other coding would leave the body's end unknown: cpp-httplib would read until the read timeout.
    if (req.has_header("Transfer-Encoding") && lowerCase(req.get_header_value("Transfer-Encoding")) != "chunked")
        return HttpError(400, "Transfer-Encoding must be chunked (or absent, with Content-Length)");
    // Before "100 Continue" too: a client must not be invited to send a body that will be refused.
    if (const auto length = declaredLength(req); length && *length > limits.maxBodyBytes)
        return HttpError(413, "request body too large (at most " + std::to_string(limits.maxBodyBytes) + " bytes)");
    if (sendsBody(req) && req.has_header("Content-Encoding") && req.get_header_value("Content-Encoding") != "identity")
        return HttpError(415, "compressed request bodies are not accepted; send the body uncompressed");
    if (sendsBody(req) && req.get_header_value("Content-Type").rfind("application/x-www-form-urlencoded", 0) == 0)
        return HttpError(415, "form-encoded bodies are not accepted; send the file with its own type, e.g. "
                              "curl --data-binary @lens.dat -H 'Content-Type: text/plain'");
    if (req.has_header("Range")) {
        const std::string range = req.get_header_value("Range");
        const long ranges = 1 + std::count(range.begin(), range.end(), ',');
        if (ranges > limits.maxRanges)
            return HttpError(416, "at most " + std::to_string(limits.maxRanges) + " byte range(s) per request");
    }
    return std::nullopt;
}

}  // namespace lenslab
