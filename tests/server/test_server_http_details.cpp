// The HTTP front's details from issue 23 (findings 6 and 13): a request that cannot be parsed ends
// its connection, byte ranges apply to complete answers only, Keep-Alive states the real limits,
// a too-long request line gets its 414, a refusal comes before "100 Continue", and unknown API
// paths answer JSON; and issue 32's nits (codings with quality 0, Vary, 413 before "100 Continue",
// Host lists and trailing dots, two Host headers, other transfer codings, the access log's bytes).
// LENSLAB_SERVER_BINARY overrides the binary under test.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <regex>
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

// ---- issue 32, finding 9 --------------------------------------------------------------------------

// gzip;q=0 refuses gzip (cpp-httplib looked for "gzip" anywhere in the header), and every answer
// says it depends on Accept-Encoding, so caches keep the two apart.
bool variesByEncoding(const std::string& reply) {
    return std::regex_search(reply.substr(0, reply.find("\r\n\r\n")), std::regex("\r\nVary: [^\r]*Accept-Encoding"));
}

TEST_F(ServerHttpDetails, ACodingWithQualityZeroIsNotUsedAndAnswersVaryByIt) {
    start();
    for (const std::string refusing : {"gzip;q=0", "gzip; q=0.0, br;q=0", "identity, gzip;Q=0"}) {
        const std::string reply = exchange(get("/api/lenses", "Accept-Encoding: " + refusing + "\r\n"));
        EXPECT_EQ(statusOf(reply), 200) << refusing;
        EXPECT_EQ(reply.find("Content-Encoding"), std::string::npos) << refusing << "\n" << reply.substr(0, 400);
        EXPECT_TRUE(variesByEncoding(reply)) << reply.substr(0, 400);
    }
    const std::string gzip = exchange(get("/api/lenses", "Accept-Encoding: gzip;q=0.5\r\n"));
    EXPECT_NE(gzip.find("Content-Encoding: gzip"), std::string::npos) << gzip.substr(0, 400);
    EXPECT_TRUE(variesByEncoding(gzip)) << gzip.substr(0, 400);
}

// A client asking for "100 Continue" with a body past the limit hears 413, not an invitation to send it.
TEST_F(ServerHttpDetails, AnOversizeBodyIsRefusedBeforeContinue) {
    start();
    RawConnection connection(server_->port());
    connection.send("POST /api/lenses?name=x.dat HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/plain\r\n"
                    "Content-Length: 2000000\r\nExpect: 100-continue\r\n\r\n");
    const std::string reply = connection.readReply(3);
    EXPECT_EQ(statusOf(reply), 413) << reply;
    EXPECT_EQ(reply.find("100 Continue"), std::string::npos) << reply;
    EXPECT_NE(bodyOf(reply).find("1048576"), std::string::npos) << reply;
}

// A route's own smaller limit is the one its 413 names (a preview body: 512 KiB, not the 1 MiB of --max-body).
TEST_F(ServerHttpDetails, APreviewBodyPastItsLimitNamesThatLimit) {
    start();
    auto c = server_->client();
    const Reply reply = postRaw(c, "/api/prescriptions/preview", "{\"rows\": [], \"comments\": [\"" + std::string(600000, 'x') + "\"]}");
    EXPECT_EQ(reply.status, 413) << reply.raw.substr(0, 300);
    EXPECT_NE(reply.body.value("error", std::string()).find("512 KiB"), std::string::npos) << reply.raw.substr(0, 300);
}

// Host names as operators and DNS write them: "a, b" lists b, and a trailing dot names the same host.
TEST_F(ServerHttpDetails, HostNamesAreReadAsWrittenInListsAndByDns) {
    start({"--allow-host", "lab.example, other.example"});
    for (const std::string host : {"lab.example", "other.example", "other.example.", "localhost.", "other.example.:8080"})
        EXPECT_EQ(statusOf(exchange("GET /api/health HTTP/1.1\r\nHost: " + host + "\r\n\r\n")), 200) << host;
    EXPECT_EQ(statusOf(exchange("GET /api/health HTTP/1.1\r\nHost: attacker.example.\r\n\r\n")), 421);
}

// Two Host headers could be read two ways (cpp-httplib took the first, a proxy might take the last).
TEST_F(ServerHttpDetails, TwoHostHeadersAreRefused) {
    start();
    const std::string reply = exchange("GET /api/health HTTP/1.1\r\nHost: 127.0.0.1\r\nHost: attacker.example\r\n\r\n");
    EXPECT_EQ(statusOf(reply), 400) << reply;
    EXPECT_TRUE(isJsonError(reply)) << reply;
}

// A Transfer-Encoding other than chunked leaves the body's end unknown: 400 at once, not after the
// read timeout (30 s here).
TEST_F(ServerHttpDetails, ATransferEncodingOtherThanChunkedIsRefusedAtOnce) {
    start({"--read-timeout", "30"});
    for (const std::string coding : {"gzip", "gzip, chunked", "chunked, gzip", "identity"}) {
        RawConnection connection(server_->port());
        connection.send("POST /api/lenses?name=x.dat HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/plain\r\n"
                        "Transfer-Encoding: " + coding + "\r\n\r\n5\r\nhello\r\n");
        const std::string reply = connection.readReply(5);
        EXPECT_EQ(statusOf(reply), 400) << coding << ": " << reply;
    }
}

// The access log counts the bytes of files sent in pieces too (the web page was logged as 0 bytes).
TEST_F(ServerHttpDetails, TheAccessLogCountsFilesSentInPieces) {
    const std::string log = data_.path() + "/access.log";
    start({"--access-log", log});
    auto c = server_->client();
    const Reply page = ::lenslab::test::get(c, "/");
    ASSERT_EQ(page.status, 200);
    std::ifstream in(std::string(LENSLAB_SOURCE_DIR) + "/web/index.html", std::ios::binary | std::ios::ate);
    const auto size = static_cast<std::size_t>(in.tellg());
    server_->stop();
    std::ifstream lines(log);
    bool found = false;
    for (std::string line; std::getline(lines, line);) {
        const json entry = json::parse(line, nullptr, false);
        if (entry.is_object() && entry["path"] == "/" && entry["status"] == 200) {
            EXPECT_EQ(entry["bytes"].get<std::size_t>(), size) << line;
            found = true;
        }
    }
    EXPECT_TRUE(found);
}

// Issue 40, item 9: every answer, the page, the API, a refusal and one written without cpp-httplib,
// carries a content security policy, refuses to be framed and sends no referrer.
TEST_F(ServerHttpDetails, EveryAnswerCarriesTheSecurityHeaders) {
    start();
    const std::string policy =
        "Content-Security-Policy: default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data: blob:; "
        "connect-src 'self'; object-src 'none'; base-uri 'none'; form-action 'self'; frame-ancestors 'none'\r\n";
    const std::vector<std::string> replies = {
        exchange(get("/")), exchange(get("/app.js")), exchange(get("/api/health")), exchange(get("/api/no-such-thing")),
        exchange("GET /api/health?x=" + std::string(20000, 'a') + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")};
    for (const std::string& reply : replies) {
        const std::string head = reply.substr(0, reply.find("\r\n\r\n") + 2);
        EXPECT_NE(head.find(policy), std::string::npos) << head;
        EXPECT_NE(head.find("X-Frame-Options: DENY\r\n"), std::string::npos) << head;
        EXPECT_NE(head.find("Referrer-Policy: no-referrer\r\n"), std::string::npos) << head;
        EXPECT_NE(head.find("X-Content-Type-Options: nosniff\r\n"), std::string::npos) << head;
    }
    EXPECT_EQ(statusOf(replies[4]), 414);
}
