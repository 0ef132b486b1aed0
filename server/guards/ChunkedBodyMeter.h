#pragma once
// Counts the payload of a chunked request body as its wire bytes pass, so that the body limit holds
// exactly for chunked bodies too: cpp-httplib 0.11.4 checks its payload limit against
// Content-Length only, and a bound on wire bytes must leave slack for the chunk framing. The meter
// only counts; cpp-httplib still decodes and checks the framing itself.
#include <cstddef>

namespace lenslab {

class ChunkedBodyMeter {
public:
    // Takes the next `count` wire bytes; false once the payload passes `limit` bytes (a chunk size
    // line that declares more counts at once, before its data arrives).
    bool take(const char* bytes, std::size_t count, std::size_t limit);
    std::size_t payloadBytes() const { return payload_; }

private:
    enum class State { Size, Extension, Data, DataEnd, Trailer };
    State state_ = State::Size;
    std::size_t size_ = 0, remaining_ = 0, payload_ = 0;
    bool sizeTooLarge_ = false;
};

}  // namespace lenslab
