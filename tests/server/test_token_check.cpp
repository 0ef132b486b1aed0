// The bearer-token comparison in-process: only the whole token passes. A prefix of it, the token
// with more after it or an empty "Bearer " must be refused, which a wrong token of the right
// length (the only case the HTTP tests send) cannot tell from a check that skips the lengths.
#include <gtest/gtest.h>

#include "AccessControl.h"

using namespace lenslab;

namespace {

const std::string kToken = "0123456789abcdef0123456789abcdef";

// The status refuseAccess answers a POST carrying `authorization`, 0 when it lets it through.
int statusFor(const std::string& authorization) {
    httplib::Request req;
    req.method = "POST";
    req.headers.emplace("Authorization", authorization);
    AccessPolicy policy;
    policy.token = kToken;
    const auto refusal = refuseAccess(req, policy);
    return refusal ? refusal->status() : 0;
}

}  // namespace

TEST(TokenCheck, OnlyTheWholeTokenPasses) {
    EXPECT_EQ(statusFor("Bearer " + kToken), 0);
    EXPECT_EQ(statusFor("Bearer "), 401);
    EXPECT_EQ(statusFor("Bearer " + kToken.substr(0, 1)), 401);
    EXPECT_EQ(statusFor("Bearer " + kToken.substr(0, kToken.size() - 1)), 401);
    EXPECT_EQ(statusFor("Bearer " + kToken + "0"), 401);
    EXPECT_EQ(statusFor(kToken), 401);  // no scheme
}
