#include "SlowClients.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <vector>

namespace lenslab::bench {

namespace {

int connectTo(int port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (fd >= 0 && ::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0) {
        const std::string start = "GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\n";
        if (::send(fd, start.data(), start.size(), MSG_NOSIGNAL) > 0) return fd;
    }
    if (fd >= 0) ::close(fd);
    return -1;
}

}  // namespace

SlowClients::SlowClients(int port, int connections) {
    thread_ = std::thread([this, port, connections] {
        std::vector<int> fds(static_cast<std::size_t>(connections), -1);
        for (long line = 0; !stop_; ++line) {
            for (int& fd : fds) {
                const std::string header = "X-Slow-" + std::to_string(line) + ": 1\r\n";
                if (fd >= 0 && ::send(fd, header.data(), header.size(), MSG_NOSIGNAL) > 0) continue;
                if (fd >= 0) {
                    ::close(fd);
                    ++reconnects_;
                }
                fd = connectTo(port);
            }
            for (int tick = 0; tick < 10 && !stop_; ++tick) std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
        for (int fd : fds)
            if (fd >= 0) ::close(fd);
    });
}

SlowClients::~SlowClients() {
    stop_ = true;
    thread_.join();
}

}  // namespace lenslab::bench
