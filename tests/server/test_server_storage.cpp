// A full or broken data folder (issue 14): uploads that cannot be written are answered 507 with a
// message the user can act on, never a path of the server's file system, and renders whose image
// cannot be written fail with such a message too; a data-folder quota is enforced the same way.
// The fixture's server is started with a file-size limit (RLIMIT_FSIZE, inherited across fork and
// exec), under which writing past the limit fails as on a full disk.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>

#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

constexpr std::size_t kFileSizeLimit = 256 << 10;

class ServerStorage : public ::testing::Test {
protected:
    // Starts the fake-render server with files limited to kFileSizeLimit bytes.
    void SetUp() override {
        writeFakeRendererScene(scenes_.path());
        server_ = startWithFileSizeLimit(LENSLAB_FAKE_SERVER, data_.path() + "/data", {"--scenes", scenes_.path()},
                                         kFileSizeLimit);
    }
    void expectNoServerPath(const std::string& message) {
        EXPECT_EQ(message.find(data_.path()), std::string::npos) << message;
        EXPECT_EQ(message.find("/tmp"), std::string::npos) << message;
    }

    TempDir data_, scenes_;
    std::unique_ptr<ServerProcess> server_;
};

// A valid table of about `bytes` bytes (comment lines between its rows pad it).
std::string largeTable(std::size_t bytes) {
    std::string table = "50.0 5.0 1.5 20.0\n";
    while (table.size() < bytes) table += "# padding to make the file larger than the file-size limit\n";
    return table + "-50.0 45.0 1.0 20.0\n0.0 0.0 0.0 15.0\n";
}

}  // namespace

TEST_F(ServerStorage, AnUploadThatDoesNotFitIs507WithoutPaths) {
    auto c = server_->client();
    const Reply r = postRaw(c, "/api/lenses?name=big.dat", largeTable(600 << 10));
    EXPECT_EQ(r.status, 507) << r.raw;
    const std::string message = r.body["error"];
    EXPECT_NE(message.find("full"), std::string::npos) << message;
    expectNoServerPath(message);
    EXPECT_EQ(postRaw(c, "/api/lenses?name=small.dat", largeTable(1000)).status, 201);  // small ones still fit
}

TEST_F(ServerStorage, ARenderThatCannotBeWrittenFailsWithAMessageWithoutPaths) {
    // The renders folder replaced by a file: the image cannot be written there.
    std::filesystem::remove_all(data_.path() + "/data/renders");
    std::ofstream(data_.path() + "/data/renders") << "not a folder\n";
    auto c = server_->client();
    const Reply submitted =
        postJson(c, "/api/renders", {{"scene", "any"}, {"lens", "dgauss.50mm"}, {"spp", 1}, {"width", 64}, {"height", 64}});
    ASSERT_EQ(submitted.status, 202) << submitted.raw;
    const json job = waitForRenderState(c, submitted.body["id"], {"done", "failed"}, 30);
    ASSERT_EQ(job["state"], "failed") << job.dump();
    const std::string error = job["error"];
    EXPECT_NE(error.find("could not write to its data folder"), std::string::npos) << error;
    expectNoServerPath(error);
}

TEST_F(ServerStorage, ALensWhoseFileCannotBeRemovedStaysAndTheClientHearsWhy) {
    auto c = server_->client();
    const Reply uploaded = postRaw(c, "/api/lenses?name=stuck.dat", largeTable(100));
    ASSERT_EQ(uploaded.status, 201) << uploaded.raw;
    const std::string id = uploaded.body["id"];
    // Its file replaced by a folder with something in it: removing it fails.
    const std::string file = data_.path() + "/data/lenses/" + id + ".dat";
    std::filesystem::remove(file);
    std::filesystem::create_directories(file + "/inside");
    const Reply refused = remove(c, "/api/lenses/" + id);
    EXPECT_EQ(refused.status, 503) << refused.raw;
    expectNoServerPath(refused.raw);
    EXPECT_EQ(get(c, "/api/lenses/" + id).status, 200);  // still listed, as it still is on disk
}

// --max-data-gb: once the data folder reaches its quota, uploads and render submissions are
// answered 507 with the sizes and what to do (no server path), reads go on, and writes are taken
// again once space is freed.
TEST(ServerQuota, WritesAre507AtTheDataFolderQuotaAndReadsGoOn) {
    TempDir data, scenes;
    writeFakeRendererScene(scenes.path());
    const double quotaGiB = 4.0 / 1024;  // 4 MiB: the fresh folder (database, log) holds far less
    ServerProcess server(LENSLAB_FAKE_SERVER, data.path() + "/data",
                         {"--scenes", scenes.path(), "--max-data-gb", std::to_string(quotaGiB)});
    auto c = server.client();
    const Reply first = postRaw(c, "/api/lenses?name=first.dat", kSmallLensTable);
    ASSERT_EQ(first.status, 201) << first.raw;

    const std::string filler = data.path() + "/data/filler.bin";
    std::ofstream(filler) << std::string(6 << 20, 'x');  // the folder filled past the quota
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));  // the last measurement expires
    const Reply upload = postRaw(c, "/api/lenses?name=second.dat", kSmallLensTable);
    EXPECT_EQ(upload.status, 507) << upload.raw;
    const std::string message = upload.body.value("error", "");
    EXPECT_NE(message.find("quota"), std::string::npos) << message;
    EXPECT_NE(message.find("DELETE /api/renders/{id}"), std::string::npos) << message;
    EXPECT_NE(message.find("of 4.19 MB"), std::string::npos) << message;
    EXPECT_EQ(message.find(data.path()), std::string::npos) << message;
    const Reply render = postJson(c, "/api/renders", {{"scene", "any"}, {"lens", "dgauss.50mm"}, {"width", 64}, {"height", 64}});
    EXPECT_EQ(render.status, 507) << render.raw;

    const Reply lenses = get(c, "/api/lenses");
    ASSERT_EQ(lenses.status, 200);
    EXPECT_NE(lenses.raw.find(first.body["id"].get<std::string>()), std::string::npos);
    EXPECT_EQ(lenses.raw.find("second.dat"), std::string::npos);
    EXPECT_EQ(get(c, "/api/lenses/" + first.body["id"].get<std::string>()).status, 200);

    std::filesystem::remove(filler);
    std::this_thread::sleep_for(std::chrono::milliseconds(1100));
    EXPECT_EQ(postRaw(c, "/api/lenses?name=second.dat", kSmallLensTable).status, 201);
}
