// The body-size limit at its edge: a body of exactly --max-body bytes is taken, one byte more is
// 413, with a Content-Length and chunked. Bodies far past the limit are also cut off by the
// connection's stream guard, whose slack would hide a server that forgot to give the limit to the
// HTTP parser: a chunked body declares no length, so only the parser's limit refuses it at the edge.
#include <gtest/gtest.h>

#include "RawServerTest.h"

using namespace lenslab::test;

namespace {

constexpr std::size_t kLimit = 65536;

// kSmallLensTable with comment lines after its first row (comments before a table are limited)
// that bring it to exactly `bytes` bytes.
std::string tableOfExactly(std::size_t bytes) {
    const std::size_t firstRow = kSmallLensTable.find('\n') + 1;
    std::string padding;
    while (padding.size() + kSmallLensTable.size() < bytes) {
        const std::size_t room = bytes - kSmallLensTable.size() - padding.size();
        const std::size_t line = std::min<std::size_t>(room, 72);
        padding += line == 1 ? std::string("\n") : "#" + std::string(line - 2, '.') + "\n";
    }
    return kSmallLensTable.substr(0, firstRow) + padding + kSmallLensTable.substr(firstRow);
}

}  // namespace

TEST(BodyLimitEdge, ExactlyTheLimitIsTakenAndOneByteMoreIs413) {
    TempDir data;
    ServerProcess server(binaryUnderTest(), data.path() + "/data", {"--max-body", std::to_string(kLimit)});
    auto client = server.client();
    const std::string atLimit = tableOfExactly(kLimit), overLimit = tableOfExactly(kLimit + 1);
    ASSERT_EQ(atLimit.size(), kLimit);
    ASSERT_EQ(overLimit.size(), kLimit + 1);
    const Reply at = postRaw(client, "/api/lenses?name=at.dat", atLimit);
    EXPECT_EQ(at.status, 201) << at.raw;
    const Reply over = postRaw(client, "/api/lenses?name=over.dat", overLimit);
    EXPECT_EQ(over.status, 413);
    EXPECT_NE(over.raw.find(std::to_string(kLimit)), std::string::npos) << over.raw;
    EXPECT_EQ(get(client, "/api/lenses/over").status, 404);
}

class BodyLimitEdgeChunked : public RawServerTest {};

TEST_F(BodyLimitEdgeChunked, ExactlyTheLimitIsTakenAndOneByteMoreIs413) {
    start({"--max-body", std::to_string(kLimit)});
    auto post = [&](const std::string& name, const std::string& body) {
        return exchange("POST /api/lenses?name=" + name + " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: text/plain\r\n"
                        "Transfer-Encoding: chunked\r\n\r\n" + chunked(body, 4096));
    };
    const std::string at = post("at.dat", tableOfExactly(kLimit));
    EXPECT_EQ(statusOf(at), 201) << at.substr(0, 300);
    const std::string over = post("over.dat", tableOfExactly(kLimit + 1));
    EXPECT_EQ(statusOf(over), 413) << over.substr(0, 300);
    auto client = server_->client();
    EXPECT_EQ(get(client, "/api/lenses/over").status, 404);
}
