#include "guards/GuardedStream.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

namespace lenslab {

namespace {

using Clock = std::chrono::steady_clock;

// poll() for `events` up to `wait`; true when ready (or the peer hung up: the read then says so).
bool waitFor(int socket, short events, std::chrono::milliseconds wait) {
    pollfd entry{socket, events, 0};
    const int ms = static_cast<int>(std::max<std::chrono::milliseconds::rep>(0, wait.count()));
    int ready;
    do ready = ::poll(&entry, 1, ms);
    while (ready < 0 && errno == EINTR);
    return ready > 0;
}

void addressOf(const sockaddr_storage& address, std::string& ip, int& port) {
    char text[INET6_ADDRSTRLEN] = "";
    if (address.ss_family == AF_INET) {
        const auto& v4 = reinterpret_cast<const sockaddr_in&>(address);
        inet_ntop(AF_INET, &v4.sin_addr, text, sizeof text);
        port = ntohs(v4.sin_port);
    } else if (address.ss_family == AF_INET6) {
        const auto& v6 = reinterpret_cast<const sockaddr_in6&>(address);
        inet_ntop(AF_INET6, &v6.sin6_addr, text, sizeof text);
        port = ntohs(v6.sin6_port);
    }
    ip = text;
}

constexpr std::size_t kFramingPrefix = 18;  // strlen("transfer-encoding:")

bool isFramingHeader(const std::string& lowerCaseStart) {
    return lowerCaseStart.rfind("content-length:", 0) == 0 || lowerCaseStart.rfind("transfer-encoding:", 0) == 0;
}

}  // namespace

GuardedStream::GuardedStream(int socket, const StreamLimits& limits, std::string pending,
                             std::chrono::steady_clock::time_point headDeadline,
                             std::chrono::steady_clock::time_point bodyDeadline)
    : socket_(socket), limits_(limits), buffer_(std::move(pending)), headDeadline_(headDeadline), bodyDeadline_(bodyDeadline) {}

bool GuardedStream::is_readable() const { return begin_ < buffer_.size() || waitFor(socket_, POLLIN, limits_.readTimeout); }

bool GuardedStream::is_writable() const {
    if (answerDeadlineLifted_) return waitFor(socket_, POLLOUT, limits_.writeTimeout);
    if (answerDeadline_ == Clock::time_point()) answerDeadline_ = Clock::now() + limits_.answerTimeout;
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(answerDeadline_ - Clock::now());
    return left.count() > 0 && waitFor(socket_, POLLOUT, std::min(limits_.writeTimeout, left));
}

bool GuardedStream::fail(StreamViolation violation) {
    violation_ = violation;
    return false;
}

bool GuardedStream::fill() {
    if (violation_ != StreamViolation::None) return false;
    const auto deadline = inHead_ ? headDeadline_ : bodyDeadline_;
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
    if (!waitFor(socket_, POLLIN, wait)) return inHead_ ? fail(StreamViolation::HeaderTimeout) : false;
    char chunk[16384];
    ssize_t got;
    do got = ::recv(socket_, chunk, sizeof chunk, 0);
    while (got < 0 && errno == EINTR);
    if (got <= 0) return false;
    buffer_.assign(chunk, static_cast<std::size_t>(got));
    begin_ = 0;
    return true;
}

bool GuardedStream::account(const char* bytes, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        if (!inHead_) {
            bodyBytes_ += count - i;
            const bool withinPayload = !chunked_ || chunkedPayload_.take(bytes + i, count - i, limits_.maxBodyBytes);
            return (withinPayload && bodyBytes_ <= limits_.maxBodyWireBytes) || fail(StreamViolation::BodyTooLarge);
        }
        ++headBytes_;
        ++lineBytes_;
        // The request line may run past the header-line limit so that cpp-httplib answers 414 itself.
        const std::size_t lineLimit = firstLine_ ? limits_.maxHeaderLine + CPPHTTPLIB_REQUEST_URI_MAX_LENGTH : limits_.maxHeaderLine;
        if (headBytes_ > limits_.maxHeaderBytes || lineBytes_ > lineLimit) return fail(StreamViolation::HeaderTooLarge);
        if (bytes[i] == '\n') {
            inHead_ = !atLineStart_;  // an empty line ends the head
            if (!inHead_ && bodyDeadline_ == Clock::time_point()) bodyDeadline_ = Clock::now() + limits_.readTimeout;
            bodyFramed_ = bodyFramed_ || isFramingHeader(lineStart_);
            // The head's checks refuse every Transfer-Encoding but chunked before the body is read.
            chunked_ = chunked_ || lineStart_.rfind("transfer-encoding:", 0) == 0;
            atLineStart_ = true;
            firstLine_ = false;
            lineBytes_ = 0;
            lineStart_.clear();
        } else if (bytes[i] != '\r') {
            atLineStart_ = false;
            if (lineStart_.size() < kFramingPrefix) lineStart_ += static_cast<char>(std::tolower(static_cast<unsigned char>(bytes[i])));
        }
    }
    return true;
}

ssize_t GuardedStream::read(char* ptr, size_t size) {
    if (!inHead_ && !bodyFramed_) return 0;
    if (begin_ == buffer_.size() && !fill()) return -1;
    const std::size_t count = std::min(size, buffer_.size() - begin_);
    if (!account(buffer_.data() + begin_, count)) return -1;
    std::memcpy(ptr, buffer_.data() + begin_, count);
    begin_ += count;
    return static_cast<ssize_t>(count);
}

ssize_t GuardedStream::write(const char* ptr, size_t size) {
    if (!is_writable()) return -1;
    ssize_t sent;
    do sent = ::send(socket_, ptr, size, MSG_NOSIGNAL);
    while (sent < 0 && errno == EINTR);
    return sent;
}

void GuardedStream::get_remote_ip_and_port(std::string& ip, int& port) const {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (::getpeername(socket_, reinterpret_cast<sockaddr*>(&address), &length) == 0) addressOf(address, ip, port);
}

void GuardedStream::get_local_ip_and_port(std::string& ip, int& port) const {
    sockaddr_storage address{};
    socklen_t length = sizeof address;
    if (::getsockname(socket_, reinterpret_cast<sockaddr*>(&address), &length) == 0) addressOf(address, ip, port);
}

}  // namespace lenslab
