#include "guards/RequestCompleteness.h"

#include <cstdlib>

#include "core/LowerCase.h"

namespace lenslab {

namespace {

// The value of header `name` (lower case, with its colon) in `head`, or "" when absent.
std::string headerValue(const std::string& head, const std::string& name) {
    const std::size_t at = head.find("\n" + name);
    if (at == std::string::npos) return "";
    const std::size_t start = at + 1 + name.size(), end = head.find('\n', start);
    std::string value = head.substr(start, end - start);
    value.erase(0, value.find_first_not_of(" \t"));
    value.erase(value.find_last_not_of(" \t\r") + 1);
    return value;
}

}  // namespace

Received receivedOf(const std::string& bytes, std::size_t maxBodyBytes) {
    std::size_t headEnd = bytes.find("\r\n\r\n");
    std::size_t bodyStart = headEnd + 4;
    if (headEnd == std::string::npos) {
        headEnd = bytes.find("\n\n");
        if (headEnd == std::string::npos) return Received::Partial;
        bodyStart = headEnd + 2;
    }
    const std::string head = lowerCase(bytes.substr(0, headEnd));
    const std::size_t bodyBytes = bytes.size() - bodyStart;
    if (bodyBytes > maxBodyBytes || headerValue(head, "expect:") == "100-continue") return Received::Whole;
    const std::string coding = headerValue(head, "transfer-encoding:");
    if (!coding.empty() && coding != "chunked") return Received::Whole;  // the worker refuses it at once
    if (coding == "chunked") {
        const std::size_t lastChunk = bytes.find("0\r\n\r\n", bodyStart);
        const bool ended = lastChunk != std::string::npos && (lastChunk == bodyStart || bytes[lastChunk - 1] == '\n');
        return ended ? Received::Whole : Received::HeadOnly;
    }
    const std::string length = headerValue(head, "content-length:");
    if (length.empty()) return Received::Whole;
    char* end = nullptr;
    const unsigned long long declared = std::strtoull(length.c_str(), &end, 10);
    if (*end != '\0' || declared > maxBodyBytes) return Received::Whole;  // the worker refuses it
    return bodyBytes >= declared ? Received::Whole : Received::HeadOnly;
}

}  // namespace lenslab
