// The HTTP front's details from issue 23 (findings 6 and 13): a request that cannot be parsed ends
// its connection, byte ranges apply to complete answers only, Keep-Alive states the real limits,
// a too-long request line gets its 414, a refusal comes before "100 Continue", and unknown API
// paths answer JSON. LENSLAB_SERVER_BINARY overrides the binary under test.
#include <gtest/gtest.h>

#include <memory>
#include <thread>

#include "RawServerTest.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

class ServerHttpDetails : public RawServerTest {
protected:
    static std::string bodyOf(const std::string& reply) {
        const std::size_t end = reply.find("\r\n\r\n");
        return end == std::string::npos ? "" : reply.substr(end + 4);
    }
    static bool isJsonError(const std::string& reply) {
        const json body = json::parse(bodyOf(reply), nullptr, false);
        return body.is_object() && body.contains("error");
    }
    static std::string get(const std::string& path, const std::string& headers = "") {
        return "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\n" + headers + "\r\n";
    }
};

}  // namespace

// Finding 6: after a request line that cannot be parsed, the next line must not be taken as a new
// request (request smuggling): 400 with Connection: close, and the connection ends.
TEST_F(ServerHttpDetails, AnUnparsableRequestEndsTheConnection) {
    start();
    auto c = server_->client();
    const Reply uploaded = postRaw(c, "/api/lenses?name=keep.dat", kSmallLensTable);
    ASSERT_EQ(uploaded.status, 201);
    const std::string id = uploaded.body["id"];
    RawConnection connection(server_->port());
    connection.send("GET /a b c HTTP/1.1\r\nDELETE /api/lenses/" + id + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
    const std::string reply = connection.readReply(3);
    EXPECT_EQ(statusOf(reply), 400) << reply;
    EXPECT_NE(reply.find("Connection: close"), std::string::npos) << reply;
    EXPECT_EQ(reply.find("HTTP/1.1 200"), std::string::npos) << reply;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    EXPECT_EQ(::lenslab::test::get(c, "/api/lenses/" + id).status, 200);
}

// Finding 13: ranges are not applied to error answers or event streams, and a range outside the
// resource is 416 with "bytes */LENGTH" and a JSON body.
TEST_F(ServerHttpDetails, RangesApplyToCompleteAnswersOnly) {
    start();
    const std::string notFound = exchange(get("/api/renders/render-0000000000000000", "Range: bytes=0-3\r\n"));
    EXPECT_EQ(statusOf(notFound), 404) << notFound;
    EXPECT_TRUE(isJsonError(notFound)) << notFound;

    auto c = server_->client();
    const std::size_t length = ::lenslab::test::get(c, "/api/lenses/dgauss.50mm/table").raw.size();
    for (const std::string range : {"bytes=-0", "bytes=100000000-"}) {
        const std::string reply = exchange(get("/api/lenses/dgauss.50mm/table", "Range: " + range + "\r\n"));
        EXPECT_EQ(statusOf(reply), 416) << range << "\n" << reply;
        EXPECT_NE(reply.find("Content-Range: bytes */" + std::to_string(length) + "\r\n"), std::string::npos) << reply;
        EXPECT_TRUE(isJsonError(reply)) << reply;
    }
    const std::string tail = exchange(get("/api/lenses/dgauss.50mm/table", "Range: bytes=-5\r\n"));
    EXPECT_EQ(statusOf(tail), 206) << tail;
    EXPECT_EQ(bodyOf(tail).size(), 5u);

    const std::string events = exchange(get("/api/report/events", "Range: bytes=0-3\r\n"), 3);
    EXPECT_EQ(statusOf(events), 200) << events;
}

// Browsers accept Brotli, which cpp-httplib runs at its slowest quality (220 ms for the editor's
// 225 KB preview): a browser's request is answered in gzip, a request for Brotli alone uncompressed.
TEST_F(ServerHttpDetails, BrowsersGetGzipNotBrotli) {
    start();
    const std::string browser = exchange(get("/api/lenses", "Accept-Encoding: gzip, deflate, br\r\n"));
    EXPECT_EQ(statusOf(browser), 200) << browser;
    EXPECT_NE(browser.find("Content-Encoding: gzip\r\n"), std::string::npos) << browser.substr(0, 400);
    const std::string brotliOnly = exchange(get("/api/lenses", "Accept-Encoding: br;q=1.0\r\n"));
    EXPECT_EQ(statusOf(brotliOnly), 200);
    EXPECT_EQ(brotliOnly.find("Content-Encoding"), std::string::npos) << brotliOnly.substr(0, 400);
    EXPECT_NE(bodyOf(brotliOnly).find("dgauss.50mm"), std::string::npos);
}

// Finding 13: Keep-Alive states the configured limits and is not sent beside Connection: close.
TEST_F(ServerHttpDetails, KeepAliveStatesTheRealLimits) {
    start({"--idle-timeout", "3", "--keep-alive-requests", "40"});
    const std::string kept = exchange(get("/api/health"));
    EXPECT_NE(kept.find("Keep-Alive: timeout=3, max=40\r\n"), std::string::npos) << kept;
    const std::string refused = exchange("POST /api/lenses HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 3\r\n"
                                         "Content-Encoding: gzip\r\n\r\nabc");
    EXPECT_EQ(statusOf(refused), 415) << refused;
    EXPECT_NE(refused.find("Connection: close"), std::string::npos) << refused;
    EXPECT_EQ(refused.find("Keep-Alive"), std::string::npos) << refused;
}

// Finding 13: a request line over the limit is answered 414 (it was closed without an answer).
TEST_F(ServerHttpDetails, ALongRequestLineIs414) {
    start();
    const std::string reply = exchange("GET /api/health?x=" + std::string(20000, 'a') + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
    EXPECT_EQ(statusOf(reply), 414) << reply.substr(0, 300);
    EXPECT_TRUE(isJsonError(reply)) << reply.substr(0, 300);
}

// Finding 13: with a token, a client asking for "100 Continue" hears 401 instead, before its body.
TEST_F(ServerHttpDetails, ARefusalComesBeforeContinue) {
    start({"--token-file", data_.path() + "/token"});
    RawConnection connection(server_->port());
    connection.send("POST /api/lenses?name=x.dat HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/plain\r\n"
                    "Content-Length: 60\r\nExpect: 100-continue\r\n\r\n");
    const std::string reply = connection.readReply(3);
    EXPECT_EQ(statusOf(reply), 401) << reply;
    EXPECT_TRUE(isJsonError(reply)) << reply;
}

// Finding 13: unknown paths under /api/ answer JSON, not the web page's HTML.
TEST_F(ServerHttpDetails, UnknownApiPathsAnswerJson) {
    start();
    auto c = server_->client();
    const Reply reply = ::lenslab::test::get(c, "/api/no-such-thing");
    EXPECT_EQ(reply.status, 404);
    EXPECT_TRUE(reply.body.is_object() && reply.body.contains("error")) << reply.raw;
}
