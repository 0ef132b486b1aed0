#include "guards/HeadWaiter.h"

#include "guards/RequestCompleteness.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

namespace lenslab {

namespace {

using Clock = std::chrono::steady_clock;

void closeConnection(int socket) {
    ::shutdown(socket, SHUT_RDWR);
    ::close(socket);
}

}  // namespace

HeadWaiter::HeadWaiter(const Limits& limits, Ready ready) : limits_(limits), ready_(std::move(ready)) {
    int pipeEnds[2];
    if (::pipe2(pipeEnds, O_CLOEXEC | O_NONBLOCK) != 0) throw std::runtime_error("cannot create a pipe");
    wakeRead_ = pipeEnds[0];
    wakeWrite_ = pipeEnds[1];
    thread_ = std::thread([this] { run(); });
}

HeadWaiter::~HeadWaiter() {
    stop();
    ::close(wakeRead_);
    ::close(wakeWrite_);
}

void HeadWaiter::add(WaitingConnection connection) {
    const auto now = Clock::now();
    Entry entry{std::move(connection), now, now + limits_.idleTimeout, false, false};
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_) {
            closeConnection(entry.connection.socket);
            return;
        }
        incoming_.push_back(std::move(entry));
    }
    const char wake = 1;
    (void)::write(wakeWrite_, &wake, 1);
}

void HeadWaiter::stop() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_) return;
        stopping_ = true;
    }
    const char wake = 1;
    (void)::write(wakeWrite_, &wake, 1);
    if (thread_.joinable()) thread_.join();
}

bool HeadWaiter::receive(Entry& entry) {
    WaitingConnection& c = entry.connection;
    char chunk[4096];
    const ssize_t got = ::recv(c.socket, chunk, sizeof chunk, MSG_DONTWAIT);
    if (got < 0 && (errno == EAGAIN || errno == EINTR)) return false;
    if (got <= 0) {
        if (c.pending.empty()) {
            closeConnection(c.socket);  // the client left between requests
            return true;
        }
        ready_(std::move(c));  // a partial head: the worker answers it
        return true;
    }
    if (!entry.started) {
        entry.started = true;
        c.headDeadline = Clock::now() + limits_.headerTimeout;
    }
    c.pending.append(chunk, static_cast<std::size_t>(got));
    return handOnIfWhole(entry);
}

bool HeadWaiter::handOnIfWhole(Entry& entry) {
    WaitingConnection& c = entry.connection;
    const Received received = receivedOf(c.pending, limits_.maxBodyBytes);
    if (received == Received::Whole || (received == Received::Partial && c.pending.size() > limits_.maxHeaderBytes)) {
        ready_(std::move(c));
        return true;
    }
    if (received == Received::HeadOnly && !entry.headDone) {
        entry.headDone = true;
        c.bodyDeadline = Clock::now() + limits_.readTimeout;
    }
    return false;
}

void HeadWaiter::dropLongestWaiting(std::vector<Entry>& waiting) const {
    std::size_t buffered = 0;
    for (const Entry& entry : waiting) buffered += entry.connection.pending.size();
    if (waiting.size() <= limits_.maxWaiting && buffered <= limits_.maxBufferedBytes) return;
    std::sort(waiting.begin(), waiting.end(), [](const Entry& a, const Entry& b) { return a.since < b.since; });
    std::size_t dropped = 0;
    for (; dropped < waiting.size() && (waiting.size() - dropped > limits_.maxWaiting || buffered > limits_.maxBufferedBytes);
         ++dropped) {
        buffered -= waiting[dropped].connection.pending.size();
        closeConnection(waiting[dropped].connection.socket);
    }
    waiting.erase(waiting.begin(), waiting.begin() + static_cast<std::ptrdiff_t>(dropped));
}

void HeadWaiter::run() {
    std::vector<Entry> waiting;
    for (;;) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (stopping_) break;
            for (Entry& entry : incoming_) {
                // Bytes of a pipelined request came with the last one: it may be complete already.
                if (!entry.connection.pending.empty()) {
                    entry.started = true;
                    entry.connection.headDeadline = Clock::now() + limits_.headerTimeout;
                    if (handOnIfWhole(entry)) continue;
                }
                waiting.push_back(std::move(entry));
            }
            incoming_.clear();
        }
        dropLongestWaiting(waiting);
        const auto now = Clock::now();
        auto wait = std::chrono::milliseconds(1000);
        std::vector<pollfd> polled{{wakeRead_, POLLIN, 0}};
        for (Entry& entry : waiting) {
            polled.push_back({entry.connection.socket, POLLIN, 0});
            const auto deadline = entry.headDone  ? entry.connection.bodyDeadline
                                  : entry.started ? entry.connection.headDeadline
                                                  : entry.idleDeadline;
            wait = std::min(wait, std::max(std::chrono::milliseconds(0),
                                           std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now)));
        }
        int ready;
        do ready = ::poll(polled.data(), polled.size(), static_cast<int>(wait.count()) + 1);
        while (ready < 0 && errno == EINTR);
        if (polled[0].revents & POLLIN) {
            char drain[64];
            while (::read(wakeRead_, drain, sizeof drain) > 0) {
            }
        }
        const auto after = Clock::now();
        std::vector<Entry> still;
        for (std::size_t i = 0; i < waiting.size(); ++i) {
            Entry& entry = waiting[i];
            if (polled[i + 1].revents != 0 && receive(entry)) continue;
            if (!entry.started && after >= entry.idleDeadline) {
                closeConnection(entry.connection.socket);
            } else if (entry.headDone ? after >= entry.connection.bodyDeadline
                                      : entry.started && after >= entry.connection.headDeadline) {
                ready_(std::move(entry.connection));  // late: the worker answers 408 or ends it at once
            } else {
                still.push_back(std::move(entry));
            }
        }
        waiting.swap(still);
    }
    for (Entry& entry : waiting) closeConnection(entry.connection.socket);
    std::lock_guard<std::mutex> lock(mutex_);
    for (Entry& entry : incoming_) closeConnection(entry.connection.socket);
    incoming_.clear();
}

}  // namespace lenslab
