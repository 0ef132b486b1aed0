#pragma once
// A plain TCP connection to the server on loopback, for requests httplib::Client will not send:
// malformed or oversized heads, bodies without a length, clients that send slowly.
#include <cstddef>
#include <string>

namespace lenslab::test {

class RawConnection {
public:
    // Connects to 127.0.0.1:port (std::runtime_error if it cannot); receiveBuffer > 0 sets SO_RCVBUF,
    // so that a client that reads slowly is not hidden by the kernel taking the answer for it.
    explicit RawConnection(int port, int receiveBuffer = 0);
    ~RawConnection();
    RawConnection(const RawConnection&) = delete;
    RawConnection& operator=(const RawConnection&) = delete;

    bool send(const std::string& bytes);  // false once the server has closed the connection
    // Everything that arrives until the server closes or `seconds` pass without a complete reply
    // (a reply is complete when its Content-Length bytes have come).
    std::string readReply(double seconds);
    // Whether the server has closed the connection (checked now, without waiting or reading data).
    bool closedByServer();
    // Reads like a slow client, at most `bytesPerSecond`, until the server closes or `seconds` pass;
    // what it read.
    std::string readSlowly(std::size_t bytesPerSecond, double seconds);

private:
    int fd_ = -1;
};

// The status code of a raw reply ("HTTP/1.1 431 ..."), 0 when there is none.
int statusOf(const std::string& reply);

// `body` in chunked transfer encoding, `chunk` bytes a chunk, with the closing empty chunk.
std::string chunked(const std::string& body, std::size_t chunk);

}  // namespace lenslab::test
