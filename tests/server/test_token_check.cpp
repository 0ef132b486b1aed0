// The access check in-process: only the whole bearer token passes (a prefix of it, the token with
// more after it or an empty "Bearer " is refused, which a wrong token of the right length, the only
// case the HTTP tests send, cannot tell from a check that skips the lengths), and only requests
// that write or spend CPU need it unless reads are private (GET, HEAD and OPTIONS are reads).
#include <gtest/gtest.h>

#include "guards/AccessControl.h"

using namespace lenslab;

namespace {

const std::string kToken = "0123456789abcdef0123456789abcdef";

// The status refuseAccess answers `method` carrying `authorization` (none when empty), 0 when it
// lets the request through.
int statusFor(const std::string& method, const std::string& authorization, bool privateReads = false) {
    httplib::Request req;
    req.method = method;
    if (!authorization.empty()) req.headers.emplace("Authorization", authorization);
    AccessPolicy policy;
    policy.token = kToken;
    policy.privateReads = privateReads;
    const auto refusal = refuseAccess(req, policy);
    return refusal ? refusal->status() : 0;
}

}  // namespace

TEST(TokenCheck, OnlyTheWholeTokenPasses) {
    EXPECT_EQ(statusFor("POST", "Bearer " + kToken), 0);
    EXPECT_EQ(statusFor("POST", "Bearer "), 401);
    EXPECT_EQ(statusFor("POST", "Bearer " + kToken.substr(0, 1)), 401);
    EXPECT_EQ(statusFor("POST", "Bearer " + kToken.substr(0, kToken.size() - 1)), 401);
    EXPECT_EQ(statusFor("POST", "Bearer " + kToken + "0"), 401);
    EXPECT_EQ(statusFor("POST", kToken), 401);  // no scheme
}

TEST(TokenCheck, ReadsNeedItOnlyWhenPrivate) {
    for (const char* read : {"GET", "HEAD", "OPTIONS"}) {
        EXPECT_EQ(statusFor(read, ""), 0) << read;
        EXPECT_EQ(statusFor(read, "", true), 401) << read;
    }
    for (const char* write : {"POST", "PUT", "DELETE"}) EXPECT_EQ(statusFor(write, ""), 401) << write;
}
