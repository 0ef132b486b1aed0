// Lens uploads as people make them (issue 14): Unicode file names kept for display (ids stay
// plain ASCII), tables saved with a UTF-8 byte order mark, and descriptions kept to a bound size.
// LENSLAB_SERVER_BINARY overrides the binary under test (to see these fail on an older build).
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

class ServerUploads : public ::testing::Test {
protected:
    void SetUp() override { server_ = std::make_unique<ServerProcess>(binaryUnderTest(), data_.path() + "/data"); }
    TempDir data_;
    std::unique_ptr<ServerProcess> server_;
};

}  // namespace

TEST_F(ServerUploads, UnicodeFileNamesAreKeptForDisplay) {
    auto c = server_->client();
    const std::string name = "\xc3\xbcn\xc3\xaf" "c\xc3\xb8" "d\xc3\xa9-\xf0\x9f\x94\xad-\xe9\x95\x9c\xe5\xa4\xb4.dat";  // ünïcødé-🔭-镜头.dat
    const auto r = c.Post("/api/lenses", httplib::MultipartFormDataItems{{"file", kSmallLensTable, name, "text/plain"}});
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    const json lens = json::parse(r->body);
    EXPECT_EQ(lens["name"], name);
    const std::string id = lens["id"];
    EXPECT_EQ(id.rfind("upload-", 0), 0u);
    for (char ch : id) EXPECT_LT(static_cast<unsigned char>(ch), 0x80) << id;
    const Reply listed = get(c, "/api/lenses/" + id);
    EXPECT_EQ(listed.body["name"], name);
}

TEST_F(ServerUploads, MalformedUtf8AndControlsAreDroppedFromNames) {
    auto c = server_->client();
    const std::string name = "a\xff\xfe" "b\xe2\x80\xae" "c.dat";  // invalid bytes and a right-to-left override
    const auto r = c.Post("/api/lenses", httplib::MultipartFormDataItems{{"file", kSmallLensTable, name, "text/plain"}});
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
    EXPECT_EQ(json::parse(r->body)["name"], "abc.dat");
}

TEST_F(ServerUploads, AByteOrderMarkIsAccepted) {
    auto c = server_->client();
    const auto r = c.Post("/api/lenses?name=bom.dat", "\xef\xbb\xbf" + kSmallLensTable, "text/plain");
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 201) << r->body;
    const auto commented = c.Post("/api/lenses?name=bom2.dat", "\xef\xbb\xbf# a lens\n" + kSmallLensTable, "text/plain");
    ASSERT_TRUE(commented);
    ASSERT_EQ(commented->status, 201) << commented->body;
    EXPECT_EQ(json::parse(commented->body)["description"], "a lens");
}

TEST_F(ServerUploads, OverlongDescriptionsAreRefused) {
    auto c = server_->client();
    const Reply r = postRaw(c, "/api/lenses?name=long.dat", "# " + std::string(5000, 'x') + "\n" + kSmallLensTable);
    EXPECT_EQ(r.status, 400) << r.raw.substr(0, 200);
    EXPECT_NE(r.raw.find("4096"), std::string::npos);
    EXPECT_EQ(get(c, "/api/lenses").raw.find(std::string(100, 'x')), std::string::npos);
}
