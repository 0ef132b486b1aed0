// Finished renders can be deleted, and the retention policy (issue 14) collects the oldest ones
// by age and by total size, so the data folder does not grow with every render.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

const std::string kFakeServer = LENSLAB_FAKE_SERVER;

class ServerRetention : public ::testing::Test {
protected:
    void SetUp() override { writeFakeRendererScene(scenes_.path()); }
    std::unique_ptr<ServerProcess> start(std::vector<std::string> args = {}) {
        args.insert(args.end(), {"--scenes", scenes_.path()});
        return std::make_unique<ServerProcess>(kFakeServer, data(), args);
    }
    std::string data() const { return data_.path() + "/data"; }
    // Submits a quick render and waits until it is done; returns its id.
    std::string renderToDone(httplib::Client& c) {
        const Reply submitted = postJson(c, "/api/renders", {{"scene", "any"}, {"lens", "dgauss.50mm"}, {"spp", 1},
                                                            {"width", 64}, {"height", 64}});
        EXPECT_EQ(submitted.status, 202) << submitted.raw;
        const std::string id = submitted.body["id"];
        EXPECT_EQ(waitForRenderState(c, id, {"done"}, 20)["state"], "done");
        return id;
    }
    std::uintmax_t filesOf(const std::string& id) const {
        std::uintmax_t bytes = 0;
        for (const char* ext : {".png", ".exr"}) {
            std::error_code error;
            const auto size = fs::file_size(data() + "/renders/" + id + ext, error);
            if (!error) bytes += size;
        }
        return bytes;
    }

    TempDir data_, scenes_;
};

}  // namespace

TEST_F(ServerRetention, DeletingAFinishedRenderRemovesItsFilesAndRow) {
    auto server = start();
    auto c = server->client();
    const std::string id = renderToDone(c);
    ASSERT_GT(filesOf(id), 0u);
    const Reply deleted = remove(c, "/api/renders/" + id);
    EXPECT_EQ(deleted.status, 200) << deleted.raw;
    EXPECT_EQ(deleted.body["deleted"], true);
    EXPECT_EQ(filesOf(id), 0u);
    EXPECT_EQ(get(c, "/api/renders/" + id).status, 404);
    EXPECT_EQ(remove(c, "/api/renders/" + id).status, 404);
}

TEST_F(ServerRetention, TheOldestGoFirstWhenTheSizeLimitIsPassed) {
    std::vector<std::string> ids;
    {
        auto server = start();
        auto c = server->client();
        for (int i = 0; i < 4; ++i) ids.push_back(renderToDone(c));
    }
    const double keepBytes = 2.5 * filesOf(ids[0]);
    auto server = start({"--keep-gb", std::to_string(keepBytes / (1 << 30))});
    auto c = server->client();
    EXPECT_EQ(get(c, "/api/renders/" + ids[0]).status, 404);
    EXPECT_EQ(get(c, "/api/renders/" + ids[1]).status, 404);
    EXPECT_EQ(filesOf(ids[1]), 0u);
    EXPECT_EQ(get(c, "/api/renders/" + ids[2]).status, 200);
    EXPECT_EQ(get(c, "/api/renders/" + ids[3]).status, 200);
    // A new render pushes out the oldest kept one.
    const std::string newest = renderToDone(c);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    EXPECT_EQ(get(c, "/api/renders/" + ids[2]).status, 404);
    EXPECT_EQ(get(c, "/api/renders/" + newest).status, 200);
}

TEST_F(ServerRetention, RendersOlderThanTheAgeLimitAreCollected) {
    std::string id;
    {
        auto server = start();
        auto c = server->client();
        id = renderToDone(c);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1200));
    auto server = start({"--keep-days", "0.00001"});  // 0.86 s
    auto c = server->client();
    EXPECT_EQ(get(c, "/api/renders/" + id).status, 404);
    EXPECT_EQ(filesOf(id), 0u);
}
