#include "core/ByteRange.h"

#include <cctype>
#include <optional>

#include "core/HttpReply.h"

namespace lenslab {

namespace {

struct Span {
    std::size_t first, last;  // inclusive
};

void replaceHeader(httplib::Response& res, const std::string& name, const std::string& value) {
    res.headers.erase(name);
    res.headers.emplace(name, value);
}

std::optional<std::size_t> digits(const std::string& text) {
    if (text.empty() || text.size() > 18) return std::nullopt;
    std::size_t value = 0;
    for (char c : text) {
        if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
        value = value * 10 + static_cast<std::size_t>(c - '0');
    }
    return value;
}

enum class Outcome { Whole, Part, Unsatisfiable };

// "bytes=A-B", "bytes=A-" or "bytes=-N" against `total` bytes.
Outcome parse(const std::string& header, std::size_t total, Span& span) {
    const std::string prefix = "bytes=";
    if (header.rfind(prefix, 0) != 0 || header.find(',') != std::string::npos) return Outcome::Whole;
    const std::string spec = header.substr(prefix.size());
    const std::size_t dash = spec.find('-');
    if (dash == std::string::npos) return Outcome::Whole;
    const std::string from = spec.substr(0, dash), to = spec.substr(dash + 1);
    if (from.empty()) {
        const auto suffix = digits(to);
        if (!suffix) return Outcome::Whole;
        if (*suffix == 0 || total == 0) return Outcome::Unsatisfiable;
        span = {total - std::min(*suffix, total), total - 1};
        return Outcome::Part;
    }
    const auto first = digits(from);
    const auto last = to.empty() ? std::optional<std::size_t>(total - 1) : digits(to);
    if (!first || !last) return Outcome::Whole;
    if (*first >= total) return Outcome::Unsatisfiable;
    if (*last < *first) return Outcome::Whole;
    span = {*first, std::min(*last, total - 1)};
    return Outcome::Part;
}

}  // namespace

void applyByteRange(const std::string& rangeHeader, httplib::Response& res) {
    if (rangeHeader.empty() || res.status != 200 || res.is_chunked_content_provider_) return;
    const bool provided = static_cast<bool>(res.content_provider_);
    const std::size_t total = provided ? res.content_length_ : res.body.size();
    Span span{};
    switch (parse(rangeHeader, total, span)) {
        case Outcome::Whole: return;
        case Outcome::Unsatisfiable:
            res.content_provider_ = nullptr;
            res.content_length_ = 0;
            replyError(res, 416, "the requested range lies outside the " + std::to_string(total) + " bytes of this resource");
            replaceHeader(res, "Content-Type", "application/json");
            replaceHeader(res, "Content-Range", "bytes */" + std::to_string(total));
            break;
        case Outcome::Part: {
            const std::size_t length = span.last - span.first + 1;
            if (provided) {
                res.content_provider_ = [whole = std::move(res.content_provider_), start = span.first](
                                            std::size_t offset, std::size_t size, httplib::DataSink& sink) {
                    return whole(start + offset, size, sink);
                };
                res.content_length_ = length;
            } else {
                res.body = res.body.substr(span.first, length);
            }
            res.status = 206;
            replaceHeader(res, "Content-Range", "bytes " + std::to_string(span.first) + "-" + std::to_string(span.last) +
                                                    "/" + std::to_string(total));
            break;
        }
    }
    replaceHeader(res, "Content-Length", std::to_string(res.content_provider_ ? res.content_length_ : res.body.size()));
}

}  // namespace lenslab
