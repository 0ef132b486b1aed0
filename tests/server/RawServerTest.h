#pragma once
// A test that starts `lenslab serve` with chosen flags and talks raw HTTP to it: for the tests of
// the HTTP front itself, where a client library would tidy the bytes on the wire.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "RawConnection.h"
#include "ServerProcess.h"

namespace lenslab::test {

class RawServerTest : public ::testing::Test {
protected:
    void start(const std::vector<std::string>& args = {}) {
        server_ = std::make_unique<ServerProcess>(binaryUnderTest(), data_.path() + "/data", args);
    }
    // Sends `request` on a fresh connection and returns the raw reply.
    std::string exchange(const std::string& request, double seconds = 5) {
        RawConnection connection(server_->port());
        connection.send(request);
        return connection.readReply(seconds);
    }

    TempDir data_;
    std::unique_ptr<ServerProcess> server_;
};

}  // namespace lenslab::test
