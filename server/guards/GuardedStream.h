#pragma once
// The connection cpp-httplib reads one request from, with the limits its own socket stream lacks
// (0.11.4): a deadline for the whole request head (GuardedServer hands a connection to a worker
// once its head is complete or late, so a late head is cut off here with 408), a cap on the
// head's total size (cpp-httplib only caps single lines), a cap on the body bytes that also holds
// for chunked bodies (it only checks Content-Length): their payload counted exactly, their wire
// bytes with slack for the framing, and a deadline for the whole body. A read past
// a limit fails, and violation() says which limit it was, so the answer can be 408, 413 or 431
// rather than a plain 400. A request with neither Content-Length nor Transfer-Encoding has an
// empty body (RFC 9112 6.3): reading it ends at once instead of waiting for the client to close
// (an empty POST used to wait the read timeout).
#include <httplib.h>

#include <chrono>
#include <cstddef>
#include <string>

#include "guards/ChunkedBodyMeter.h"

namespace lenslab {

struct StreamLimits {
    std::size_t maxHeaderBytes = 16 << 10;  // request line and headers together
    std::size_t maxHeaderLine = 8 << 10;    // one line of them
    std::size_t maxBodyBytes = 1 << 20;      // a chunked body's payload
    std::size_t maxBodyWireBytes = 1 << 20;  // body bytes as sent, chunk framing included
    std::chrono::milliseconds headerTimeout{10000};  // the whole head, from its first wait
    std::chrono::milliseconds readTimeout{10000};    // the body, in all
    std::chrono::milliseconds writeTimeout{10000};   // one write
    std::chrono::milliseconds answerTimeout{300000}; // the whole answer, from its first write
};

enum class StreamViolation { None, HeaderTimeout, HeaderTooLarge, BodyTooLarge };

class GuardedStream : public httplib::Stream {
public:
    // One request on `socket`, whose first bytes (`pending`) have been read already; its head must
    // be complete by `headDeadline`, and its body by `bodyDeadline` (unset: the read timeout after the head).
    GuardedStream(int socket, const StreamLimits& limits, std::string pending,
                  std::chrono::steady_clock::time_point headDeadline, std::chrono::steady_clock::time_point bodyDeadline);

    StreamViolation violation() const { return violation_; }
    // For an answer that lasts as long as it must (an event stream): no answerTimeout.
    void liftAnswerDeadline() { answerDeadlineLifted_ = true; }
    // Bytes received but not read (the start of a pipelined next request).
    std::string leftover() const { return buffer_.substr(begin_); }

    bool is_readable() const override;
    bool is_writable() const override;
    ssize_t read(char* ptr, size_t size) override;
    ssize_t write(const char* ptr, size_t size) override;
    void get_remote_ip_and_port(std::string& ip, int& port) const override;
    void get_local_ip_and_port(std::string& ip, int& port) const override;
    socket_t socket() const override { return socket_; }

private:
    bool fill();  // reads more bytes into the buffer, waiting as long as the current phase allows
    bool account(const char* bytes, std::size_t count);  // false (and violation_ set) past a limit
    bool fail(StreamViolation violation);

    int socket_;
    StreamLimits limits_;
    std::string buffer_;
    std::size_t begin_ = 0;
    bool inHead_ = true, atLineStart_ = true, firstLine_ = true, bodyFramed_ = false, chunked_ = false;
    ChunkedBodyMeter chunkedPayload_;
    std::string lineStart_;  // the current head line's first characters, to spot the framing headers
    std::size_t headBytes_ = 0, lineBytes_ = 0, bodyBytes_ = 0;
    std::chrono::steady_clock::time_point headDeadline_, bodyDeadline_;
    mutable std::chrono::steady_clock::time_point answerDeadline_;  // set by the answer's first write
    bool answerDeadlineLifted_ = false;
    StreamViolation violation_ = StreamViolation::None;
};

}  // namespace lenslab
