// Access control (issue 14): beyond loopback a token guards every request that writes or spends
// CPU; reads stay open unless made private; other sites' pages cannot drive the API.
// LENSLAB_SERVER_BINARY overrides the binary under test (to see these fail on an older build).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

class ServerAccess : public ::testing::Test {
protected:
    std::string tokenFile() const { return data_.path() + "/token"; }
    void start(std::vector<std::string> args) {
        server_ = std::make_unique<ServerProcess>(binaryUnderTest(), data_.path() + "/data", args);
    }
    std::string token() const {
        std::ifstream in(tokenFile());
        std::string t;
        std::getline(in, t);
        return t;
    }

    TempDir data_;
    std::unique_ptr<ServerProcess> server_;
};

}  // namespace

TEST_F(ServerAccess, WritesNeedTheTokenThatTheFirstStartMadeAndPrinted) {
    start({"--token-file", tokenFile()});
    ASSERT_EQ(token().size(), 48u);
    EXPECT_NE(server_->output().find(token()), std::string::npos);  // printed once, at creation

    auto c = server_->client();
    const auto refused = c.Post("/api/lenses?name=t.dat", kSmallLensTable, "text/plain");
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->status, 401);
    EXPECT_EQ(refused->get_header_value("WWW-Authenticate"), "Bearer");
    EXPECT_EQ(remove(c, "/api/lenses/dgauss.50mm").status, 401);
    EXPECT_EQ(postJson(c, "/api/renders", {{"lens", "dgauss.50mm"}}).status, 401);
    EXPECT_EQ(postJson(c, "/api/report", json::object()).status, 401);
    EXPECT_EQ(get(c, "/api/lenses").status, 200);  // reads stay open

    c.set_bearer_token_auth(std::string(47, 'x') + "y");
    EXPECT_EQ(c.Post("/api/lenses?name=t.dat", kSmallLensTable, "text/plain")->status, 401);
    c.set_bearer_token_auth(token());
    EXPECT_EQ(c.Post("/api/lenses?name=t.dat", kSmallLensTable, "text/plain")->status, 201);

    const std::string first = token();
    server_.reset();
    start({"--token-file", tokenFile()});
    EXPECT_EQ(token(), first);  // kept across restarts, and not printed again
    EXPECT_EQ(server_->output().find(first), std::string::npos);
}

TEST_F(ServerAccess, PrivateReadsNeedTheTokenToo) {
    start({"--token-file", tokenFile(), "--private-reads"});
    auto c = server_->client();
    EXPECT_EQ(get(c, "/api/lenses").status, 401);
    c.set_bearer_token_auth(token());
    EXPECT_EQ(get(c, "/api/lenses").status, 200);
}

TEST_F(ServerAccess, ListeningBeyondLoopbackWithoutATokenIsRefused) {
    try {
        ServerProcess open(binaryUnderTest(), data_.path() + "/data", {"--host", "0.0.0.0"});
        ADD_FAILURE() << "the server listened on 0.0.0.0 with no token";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("--token-file"), std::string::npos) << e.what();
    }
}

TEST_F(ServerAccess, NoAuthMustBeAskedForExplicitly) {
    start({"--host", "0.0.0.0", "--no-auth"});
    httplib::Client c("127.0.0.1", server_->port());
    EXPECT_EQ(c.Post("/api/lenses?name=t.dat", kSmallLensTable, "text/plain")->status, 201);
}

TEST_F(ServerAccess, CrossOriginRequestsAreRefusedUnlessAllowed) {
    start({"--allow-origin", "http://trusted.example"});
    auto c = server_->client();
    const std::string self = "http://127.0.0.1:" + std::to_string(server_->port());
    const auto foreign = c.Post("/api/lenses?name=a.dat", {{"Origin", "http://evil.example"}}, kSmallLensTable, "text/plain");
    ASSERT_TRUE(foreign);
    EXPECT_EQ(foreign->status, 403);
    EXPECT_EQ(c.Get("/api/lenses", {{"Origin", "http://evil.example"}})->status, 403);
    EXPECT_EQ(c.Post("/api/lenses?name=b.dat", {{"Origin", self}}, kSmallLensTable, "text/plain")->status, 201);
    EXPECT_EQ(c.Post("/api/lenses?name=c.dat", {{"Origin", "http://trusted.example"}}, kSmallLensTable, "text/plain")->status, 201);
}

// Issue 23, finding 12: a token file saved with a trailing space and CR (as some editors do) still
// works, since header values arrive trimmed; a token with a space inside is refused at start.
TEST_F(ServerAccess, ATokenFileWithTrailingWhitespaceIsTrimmed) {
    const std::string token = "0123456789abcdef0123456789abcdef";
    std::ofstream(tokenFile()) << token << " \r\n";
    start({"--token-file", tokenFile()});
    auto c = server_->client();
    c.set_default_headers({{"Authorization", "Bearer " + token}});
    EXPECT_EQ(postRaw(c, "/api/lenses?name=t.dat", kSmallLensTable).status, 201);

    std::ofstream(tokenFile()) << "0123456789abcdef 0123456789abcdef\n";
    EXPECT_THROW(ServerProcess(binaryUnderTest(), data_.path() + "/data2", {"--token-file", tokenFile()}), std::runtime_error);
}

// Issue 23, finding 4: DNS rebinding. A page on attacker.example whose name resolves to 127.0.0.1
// sends Host and Origin with the attacker's name; it must not upload or delete. Addresses,
// localhost and names given with --allow-host are answered.
TEST_F(ServerAccess, RequestsNamingAnotherHostAreRefused) {
    start({"--allow-host", "lab.example"});
    auto c = server_->client();
    const std::string port = std::to_string(server_->port());
    const httplib::Headers rebound = {{"Host", "attacker.example:" + port}, {"Origin", "http://attacker.example:" + port}};
    const auto deleted = c.Delete("/api/lenses/dgauss.50mm", rebound);
    ASSERT_TRUE(deleted);
    EXPECT_EQ(deleted->status, 421) << deleted->body;
    const auto uploaded = c.Post("/api/lenses?name=x.dat", rebound, kSmallLensTable, "text/plain");
    ASSERT_TRUE(uploaded);
    EXPECT_EQ(uploaded->status, 421);
    EXPECT_TRUE(json::parse(uploaded->body, nullptr, false).contains("error")) << uploaded->body;
    const auto read = c.Get("/api/lenses", {{"Host", "attacker.example"}});
    ASSERT_TRUE(read);
    EXPECT_EQ(read->status, 421);

    for (const std::string& host : {"127.0.0.1:" + port, "localhost:" + port, "[::1]:" + port, std::string("lab.example")}) {
        const auto ok = c.Get("/api/health", {{"Host", host}});
        ASSERT_TRUE(ok);
        EXPECT_EQ(ok->status, 200) << host;
    }
}

// Issue 23, finding 8: a page on an origin listed in --allow-origin can call the API with its token:
// the browser's preflight is answered without the token, and the answers name the origin.
TEST_F(ServerAccess, AListedOriginMayCallTheApiWithItsToken) {
    const std::string page = "http://page.example:8000";
    start({"--token-file", tokenFile(), "--allow-origin", page});
    auto c = server_->client();
    const auto preflight = c.Options("/api/lenses", {{"Origin", page},
                                                     {"Access-Control-Request-Method", "POST"},
                                                     {"Access-Control-Request-Headers", "authorization,content-type"}});
    ASSERT_TRUE(preflight);
    EXPECT_EQ(preflight->status, 204);
    EXPECT_EQ(preflight->get_header_value("Access-Control-Allow-Origin"), page);
    EXPECT_NE(preflight->get_header_value("Access-Control-Allow-Headers").find("Authorization"), std::string::npos);
    EXPECT_NE(preflight->get_header_value("Access-Control-Allow-Methods").find("POST"), std::string::npos);

    const auto upload = c.Post("/api/lenses?name=t.dat", {{"Origin", page}, {"Authorization", "Bearer " + token()}},
                               kSmallLensTable, "text/plain");
    ASSERT_TRUE(upload);
    EXPECT_EQ(upload->status, 201);
    EXPECT_EQ(upload->get_header_value("Access-Control-Allow-Origin"), page);

    const auto other = c.Get("/api/lenses", {{"Origin", "http://other.example"}});
    ASSERT_TRUE(other);
    EXPECT_EQ(other->status, 403);
    EXPECT_FALSE(other->has_header("Access-Control-Allow-Origin"));
}
