// The body-size limit at its edge: a body of exactly --max-body bytes is taken, one byte more is
// 413. Bodies far past the limit are also cut off by the connection's stream guard, whose slack
// would hide a server that forgot to give the limit to the HTTP parser.
#include <gtest/gtest.h>

#include "ServerProcess.h"

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
