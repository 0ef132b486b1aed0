// The HTTP front under abuse (issue 14): every limit answers at once with its own status, slow
// clients are cut off without starving others, and a port or data folder is never shared.
// LENSLAB_SERVER_BINARY overrides the binary under test (to see these fail on an older build).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <thread>

#include "RawServerTest.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// A valid lens table of about `bytes` bytes (comment lines between its rows pad it).
std::string paddedTable(std::size_t bytes) {
    std::string table = "# radius thickness ior aperture\n50.0 5.0 1.5 20.0\n";
    while (table.size() < bytes) table += "# padding line to make the table larger than the form limit of 8 KiB\n";
    return table + "-50.0 45.0 1.0 20.0\n0.0 0.0 0.0 15.0\n";
}

class ServerLimits : public RawServerTest {};

}  // namespace

TEST_F(ServerLimits, ChunkedBodyPastTheLimitIs413AndNothingIsStored) {
    start({"--max-body", "65536"});
    const std::string body = paddedTable(300000);
    const std::string reply = exchange("POST /api/lenses?name=big.dat HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/plain\r\n"
                                       "Transfer-Encoding: chunked\r\n\r\n" + chunked(body, 4096));
    EXPECT_EQ(statusOf(reply), 413) << reply.substr(0, 300);
    EXPECT_NE(reply.find("65536"), std::string::npos);
    auto c = server_->client();
    EXPECT_EQ(get(c, "/api/lenses/big").status, 404);
}

TEST_F(ServerLimits, ChunkedBodyWithinTheLimitIsAccepted) {
    start({"--max-body", "65536"});
    const std::string reply = exchange("POST /api/lenses?name=small.dat HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/plain\r\n"
                                       "Transfer-Encoding: chunked\r\n\r\n" + chunked(paddedTable(20000), 1000));
    EXPECT_EQ(statusOf(reply), 201) << reply.substr(0, 300);
}

TEST_F(ServerLimits, MultipleRangesAreRefused) {
    start();
    std::string ranges = "bytes=0-";
    for (int i = 0; i < 199; ++i) ranges += ",0-";
    const std::string reply = exchange("GET /api/lenses/dgauss.50mm/table HTTP/1.1\r\nHost: 127.0.0.1\r\nRange: " + ranges + "\r\n\r\n");
    EXPECT_EQ(statusOf(reply), 416) << reply.substr(0, 300);
    EXPECT_LT(reply.size(), 2000u);
    const std::string single = exchange("GET /api/lenses/dgauss.50mm/table HTTP/1.1\r\nHost: 127.0.0.1\r\nRange: bytes=0-9\r\n\r\n");
    EXPECT_EQ(statusOf(single), 206) << single.substr(0, 300);
    EXPECT_NE(single.find("Content-Length: 10\r\n"), std::string::npos);
}

TEST_F(ServerLimits, SlowHeadersAreCutOffAndHealthStillAnswers) {
    start({"--http-threads", "4", "--header-timeout", "2"});
    // More slow clients than worker threads, each sending one header line every 300 ms for 6 s.
    std::vector<std::unique_ptr<RawConnection>> slow;
    for (int i = 0; i < 8; ++i) {
        slow.push_back(std::make_unique<RawConnection>(server_->port()));
        slow.back()->send("GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\n");
    }
    std::atomic<bool> stop{false};
    std::thread dribble([&] {
        for (int line = 0; line < 20 && !stop; ++line) {
            for (auto& connection : slow) connection->send("X-Slow: " + std::to_string(line) + "\r\n");
            std::this_thread::sleep_for(std::chrono::milliseconds(300));
        }
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const auto asked = Clock::now();
    auto c = server_->client();
    c.set_read_timeout(8);
    const Reply health = get(c, "/api/health");
    const double waited = secondsSince(asked);
    stop = true;
    dribble.join();
    EXPECT_EQ(health.status, 200);
    EXPECT_LT(waited, 1.0);  // slow heads wait outside the worker threads
    const std::string cutOff = slow.front()->readReply(1);
    EXPECT_TRUE(cutOff.empty() || statusOf(cutOff) == 408) << cutOff.substr(0, 200);
}

TEST_F(ServerLimits, HeadersPastTheirTotalSizeAre431) {
    start({"--max-header-bytes", "16384"});
    std::string headers;
    for (int i = 0; i < 40; ++i) headers += "X-Filler-" + std::to_string(i) + ": " + std::string(1000, 'a') + "\r\n";
    const std::string reply = exchange("GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\n" + headers + "\r\n");
    EXPECT_EQ(statusOf(reply), 431) << reply.substr(0, 300);
}

TEST_F(ServerLimits, OneOverLongHeaderLineIs431) {
    start();
    const std::string reply = exchange("GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Long: " + std::string(9000, 'a') + "\r\n\r\n");
    EXPECT_EQ(statusOf(reply), 431) << reply.substr(0, 300);
}

TEST_F(ServerLimits, TwoContentLengthsAreRefused) {
    start();
    const std::string reply = exchange("POST /api/lenses HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/plain\r\n"
                                       "Content-Length: 5\r\nContent-Length: 50\r\n\r\nhello");
    EXPECT_EQ(statusOf(reply), 400) << reply.substr(0, 300);
    EXPECT_NE(reply.find("more than once"), std::string::npos);
}

TEST_F(ServerLimits, PostWithoutABodyIsAnsweredAtOnce) {
    start();
    RawConnection connection(server_->port());
    const auto sent = Clock::now();
    connection.send("POST /api/renders/r-does-not-exist/resubmit HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
    const std::string reply = connection.readReply(8);
    EXPECT_LT(secondsSince(sent), 1.5);
    EXPECT_EQ(statusOf(reply), 404) << reply.substr(0, 300);
}

TEST_F(ServerLimits, FormEncodedUploadIsRefusedWithACommandThatWorks) {
    start();
    auto c = server_->client();
    const std::string table = paddedTable(20000);
    const auto form = c.Post("/api/lenses?name=form.dat", table, "application/x-www-form-urlencoded");
    ASSERT_TRUE(form);
    EXPECT_EQ(form->status, 415);
    EXPECT_NE(form->body.find("Content-Type: text/plain"), std::string::npos);
    const auto plain = c.Post("/api/lenses?name=plain.dat", table, "text/plain");
    ASSERT_TRUE(plain);
    EXPECT_EQ(plain->status, 201) << plain->body;
}

TEST_F(ServerLimits, ASecondServerOnTheSamePortFailsToStart) {
    start();
    try {
        ServerProcess second(binaryUnderTest(), data_.path() + "/other", {"--port", std::to_string(server_->port())});
        ADD_FAILURE() << "a second server started on port " << server_->port();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("in use"), std::string::npos) << e.what();
    }
}

TEST_F(ServerLimits, ASecondServerOnTheSameDataFolderFailsToStart) {
    start();
    try {
        ServerProcess second(binaryUnderTest(), data_.path() + "/data");
        ADD_FAILURE() << "a second server started on the same data folder";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("in use by another lenslab serve"), std::string::npos) << e.what();
    }
}

// The whole-answer deadline and the per-client download cap are set like the other limits, and
// refused out of their range with the range named.
TEST_F(ServerLimits, AnswerTimeoutAndDownloadsPerClientRefuseValuesOutOfRange) {
    const std::vector<std::pair<std::vector<std::string>, std::string>> refused = {
        {{"--answer-timeout", "0"}, "serve: --answer-timeout must lie between 1 and 86400"},
        {{"--downloads-per-client", "257"}, "serve: --downloads-per-client must lie between 1 and 256"}};
    for (const auto& [args, message] : refused) {
        try {
            ServerProcess server(binaryUnderTest(), data_.path() + "/data", args);
            ADD_FAILURE() << "the server started with " << args[0] << " " << args[1];
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
        }
    }
}

TEST_F(ServerLimits, PastTheConnectionLimitTheLongestWaitingAreDropped) {
    start({"--max-connections", "8", "--header-timeout", "30"});
    std::vector<std::unique_ptr<RawConnection>> slow;
    for (int i = 0; i < 12; ++i) {
        slow.push_back(std::make_unique<RawConnection>(server_->port()));
        slow.back()->send("GET /api/health HTTP/1.1\r\n");
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    auto c = server_->client();
    EXPECT_EQ(get(c, "/api/health").status, 200);
    // The first four were dropped: reading them ends at once, without a reply.
    const auto asked = Clock::now();
    EXPECT_EQ(slow.front()->readReply(3), "");
    EXPECT_LT(secondsSince(asked), 1.0);
    // The last ones still wait for the rest of their head.
    const auto stillOpen = Clock::now();
    EXPECT_EQ(slow.back()->readReply(0.5), "");
    EXPECT_GE(secondsSince(stillOpen), 0.45);
}

TEST_F(ServerLimits, ARequestRefusedBeforeItsBodyClosesTheConnection) {
    start();
    RawConnection connection(server_->port());
    // Were the connection kept, the unread body would be taken for the next request. (The whole
    // body is sent: a request goes to a worker once its declared body has come.)
    connection.send("POST /api/lenses HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/x-www-form-urlencoded\r\n"
                    "Content-Length: 30\r\n\r\nGET /api/health HTTP/1.1\r\n\r\n\r\n");
    EXPECT_EQ(statusOf(connection.readReply(3)), 415);
    const auto asked = Clock::now();
    EXPECT_EQ(connection.readReply(3), "");
    EXPECT_LT(secondsSince(asked), 1.0);
}
