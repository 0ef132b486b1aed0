#include "guards/RequestChecks.h"

#include <algorithm>
#include <string>

namespace lenslab {

namespace {

bool sendsBody(const httplib::Request& req) {
    return req.has_header("Content-Length") || req.has_header("Transfer-Encoding");
}

}  // namespace

std::optional<HttpError> refuseRequestHead(const httplib::Request& req, const HttpLimits& limits) {
    if (req.get_header_value_count("Content-Length") > 1 || req.get_header_value_count("Transfer-Encoding") > 1 ||
        (req.has_header("Content-Length") && req.has_header("Transfer-Encoding")))
        return HttpError(400, "the request gives its body length more than once (Content-Length / Transfer-Encoding)");
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
