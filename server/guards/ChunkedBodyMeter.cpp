#include "guards/ChunkedBodyMeter.h"

#include <algorithm>

namespace lenslab {

namespace {

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

bool ChunkedBodyMeter::take(const char* bytes, std::size_t count, std::size_t limit) {
    for (std::size_t i = 0; i < count; ++i) {
        const char c = bytes[i];
        switch (state_) {
            case State::Size:
            case State::Extension:
                if (c == '\n') {
                    if (sizeTooLarge_ || size_ > limit - payload_) return false;
                    state_ = size_ == 0 ? State::Trailer : State::Data;
                    remaining_ = size_;
                    size_ = 0;
                } else if (state_ == State::Size && hexDigit(c) >= 0) {
                    // A size past the limit is refused when its line ends; digits beyond it need no sum.
                    sizeTooLarge_ = sizeTooLarge_ || size_ > limit;
                    if (!sizeTooLarge_) size_ = size_ * 16 + std::size_t(hexDigit(c));
                } else if (c != '\r') {
                    state_ = State::Extension;  // ";name=value" after the size, or a framing error httplib reports
                }
                break;
            case State::Data: {
                const std::size_t n = std::min(remaining_, count - i);
                payload_ += n;
                remaining_ -= n;
                i += n - 1;
                if (remaining_ == 0) state_ = State::DataEnd;
                break;
            }
            case State::DataEnd:
                if (c == '\n') state_ = State::Size;
                break;
            case State::Trailer: return true;
        }
    }
    return true;
}

}  // namespace lenslab
