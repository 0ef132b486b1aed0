// Downloads of finished renders (issue 23, findings 5 and 11): large images and their pixels are
// sent a piece at a time instead of being read or decoded whole per request, and an image that
// cannot be read is answered without the server's paths.
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <thread>

#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

// The server's peak resident memory so far, in MB (VmHWM).
double peakResidentMb(const ServerProcess& server) {
    std::ifstream status("/proc/" + std::to_string(server.pid()) + "/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024;
    return 0;
}

}  // namespace

// Finding 5: 16 concurrent downloads of a large render's pixels (12.6 MB each) and its EXR must not
// each cost the whole image in memory: they are sent a band of rows at a time.
TEST(ServerDownloads, LargeDownloadsAreStreamed) {
    FakeRenderService service;
    ServerProcess& server = service.server;
    auto c = server.client();
    const Reply job = postJson(c, "/api/renders", {{"scene", "any"}, {"spp", 1}, {"width", 1024}, {"height", 1024}});
    ASSERT_EQ(job.status, 202) << job.raw;
    const std::string id = job.body["id"];
    ASSERT_EQ(waitForRenderState(c, id, {"done"}, 60)["state"], "done");
    const double before = peakResidentMb(server);
    std::vector<std::thread> clients;
    std::atomic<int> complete{0};
    for (int i = 0; i < 16; ++i)
        clients.emplace_back([&, i] {
            auto client = server.client();
            const auto reply = client.Get("/api/renders/" + id + (i % 2 ? "/pixels" : "/image.exr"));
            if (reply && reply->status == 200 && (i % 2 == 0 || reply->body.size() == 1024u * 1024 * 12)) ++complete;
        });
    for (std::thread& t : clients) t.join();
    EXPECT_EQ(complete, 16);
    EXPECT_LT(peakResidentMb(server) - before, 60) << "MB more at the peak than before the downloads";
}

// Finding 11: a render whose EXR is missing or truncated.
TEST(ServerDownloads, AnUnreadableImageNamesNoServerPath) {
    FakeRenderService service;
    ServerProcess& server = service.server;
    auto c = server.client();
    const Reply job = postJson(c, "/api/renders", {{"scene", "any"}, {"spp", 1}, {"width", 64}, {"height", 64}});
    ASSERT_EQ(job.status, 202) << job.raw;
    const std::string id = job.body["id"];
    ASSERT_EQ(waitForRenderState(c, id, {"done"}, 20)["state"], "done");
    const std::string exr = service.data.path() + "/data/renders/" + id + ".exr";
    std::filesystem::resize_file(exr, 100);
    const Reply truncated = get(c, "/api/renders/" + id + "/pixels");
    EXPECT_EQ(truncated.status, 404);
    EXPECT_EQ(truncated.raw.find(service.data.path()), std::string::npos) << truncated.raw;
    std::filesystem::remove(exr);
    const Reply missing = get(c, "/api/renders/" + id + "/pixels");
    EXPECT_EQ(missing.status, 404);
    EXPECT_TRUE(missing.body.is_object() && missing.body.contains("error")) << missing.raw;
    EXPECT_EQ(missing.raw.find(service.data.path()), std::string::npos) << missing.raw;
}
