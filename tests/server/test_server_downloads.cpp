// Downloads of finished renders (issue 23, findings 5 and 11): large images and their pixels are
// sent a piece at a time instead of being read or decoded whole per request, and an image that
// cannot be read is answered without the server's paths.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "RawConnection.h"
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
// each cost the whole image in memory: they are sent a band of rows at a time. (16 downloads to one
// client need that share, and 64 workers, of which a quarter may send downloads.)
TEST(ServerDownloads, LargeDownloadsAreStreamed) {
    FakeRenderService service({"--http-threads", "64", "--downloads-per-client", "16"});
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

// Issue 40, finding 2: slow readers of large downloads. The write timeout is per write, and a reader
// taking 74 KB/s keeps every write going: a whole answer must be taken within the answer timeout,
// and one client address is sent at most --downloads-per-client render images at once (429 past
// it), so that the other workers answer health meanwhile.
TEST(ServerDownloads, SlowReadersAreCutOffAndHoldFewWorkers) {
    FakeRenderService service({"--answer-timeout", "2", "--downloads-per-client", "2"});
    ServerProcess& server = service.server;
    auto c = server.client();
    const Reply job = postJson(c, "/api/renders", {{"scene", "any"}, {"spp", 1}, {"width", 768}, {"height", 768}});
    ASSERT_EQ(job.status, 202) << job.raw;
    const std::string id = job.body["id"];
    ASSERT_EQ(waitForRenderState(c, id, {"done"}, 20)["state"], "done");
    const std::size_t pixelBytes = 768u * 768 * 12;
    const std::string pixels = "/api/renders/" + id + "/pixels";

    std::vector<std::string> read(2);
    std::vector<std::thread> readers;
    for (int i = 0; i < 2; ++i)
        readers.emplace_back([&, i] {
            RawConnection reader(server.port(), 4096);
            reader.send("GET " + pixels + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
            read[i] = reader.readSlowly(256 << 10, 3.2);  // the whole would take half a minute
        });
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // both are being sent
    const Reply third = get(c, pixels);
    EXPECT_EQ(third.status, 429) << third.raw.substr(0, 200);
    EXPECT_TRUE(third.body.is_object() && third.body.contains("error")) << third.raw.substr(0, 200);
    EXPECT_EQ(get(c, "/api/health").status, 200);
    // Past the answer timeout both are cut off (what the kernel holds still trickles to them), and
    // their workers and slots are free again.
    std::this_thread::sleep_for(std::chrono::milliseconds(2500));
    const auto whole = c.Get(pixels);
    ASSERT_TRUE(whole);
    EXPECT_EQ(whole->status, 200);
    EXPECT_EQ(whole->body.size(), pixelBytes);
    for (std::thread& t : readers) t.join();
    for (const std::string& r : read) EXPECT_EQ(statusOf(r), 200);
}
