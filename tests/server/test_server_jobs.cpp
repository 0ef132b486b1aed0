// The service's render queue over HTTP, with the FakeRenderer standing in for the ray tracer
// (spp = milliseconds per tile): progress and partial images, cancellation, a full queue,
// restarts that keep jobs, and a kill -9 mid-render that recovers cleanly.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <future>
#include <thread>

#include "ServerProcess.h"

using namespace lenslab::test;
using nlohmann::json;

namespace {

json slowRender(int millisecondsPerTile) {
    return {{"scene", "any"}, {"lens", "dgauss.50mm"}, {"spp", millisecondsPerTile}, {"width", 64}, {"height", 64}};
}

class ServerJobs : public ::testing::Test {
protected:
    std::unique_ptr<ServerProcess> start(const std::vector<std::string>& args = {}) {
        return std::make_unique<ServerProcess>(fakeServerUnderTest(), data_.path() + "/data", args);
    }
    std::vector<std::string> sceneArgs() const { return {"--scenes", scenes_.path()}; }
    void SetUp() override { writeFakeRendererScene(scenes_.path()); }

    TempDir data_, scenes_;
};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

}  // namespace

TEST_F(ServerJobs, ReportsProgressAndPartialImages) {
    auto server = start(sceneArgs());
    auto c = server->client();
    const Reply submitted = postJson(c, "/api/renders", slowRender(60));  // 16 tiles, about 1 s
    ASSERT_EQ(submitted.status, 202) << submitted.raw;
    EXPECT_EQ(submitted.body["state"], "queued");
    EXPECT_EQ(submitted.header("Location"), "/api/renders/" + submitted.body["id"].get<std::string>());
    const std::string id = submitted.body["id"];
    json status;
    for (int i = 0; i < 200; ++i) {
        status = get(c, "/api/renders/" + id).body;
        if (status["progress"]["tiles_done"].get<int>() >= 2) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_EQ(status["state"], "running") << status.dump();
    EXPECT_EQ(status["progress"]["tiles_total"], 16);
    EXPECT_FALSE(status["progress"]["eta_s"].is_null());
    EXPECT_GE(status["tiles"].size(), 2u);
    const auto preview = c.Get("/api/renders/" + id + "/preview.png");
    ASSERT_EQ(preview->status, 200);
    EXPECT_TRUE(isPng(preview->body));
    EXPECT_EQ(c.Get("/api/renders/" + id + "/image.png")->status, 409);  // not done yet

    const json later = get(c, "/api/renders/" + id + "?tiles_since=" + std::to_string(status["tiles"].size())).body;
    EXPECT_EQ(later["tiles_since"], status["tiles"].size());

    const json done = waitForRenderState(c, id, {"done", "failed"}, 20);
    ASSERT_EQ(done["state"], "done") << done.dump();
    EXPECT_DOUBLE_EQ(done["progress"]["fraction"].get<double>(), 1.0);
    EXPECT_TRUE(isPng(c.Get("/api/renders/" + id + "/image.png")->body));
    EXPECT_TRUE(isExr(c.Get("/api/renders/" + id + "/image.exr")->body));
    EXPECT_EQ(remove(c, "/api/renders/" + id).status, 200);  // a finished render is deleted
    EXPECT_EQ(get(c, "/api/renders/" + id).status, 404);
}

// Issue 40, finding 4: readers polling the preview of a 1920^2 render at once share one encoding
// of the partial image (each used to copy its 44 MB and encode it again), byte for byte.
TEST_F(ServerJobs, ConcurrentPreviewReadersShareOneEncoding) {
    auto server = start(sceneArgs());
    auto c = server->client();
    const Reply submitted = postJson(c, "/api/renders", {{"scene", "any"}, {"spp", 1000}, {"width", 1920}, {"height", 1920}});
    ASSERT_EQ(submitted.status, 202) << submitted.raw;
    const std::string id = submitted.body["id"];
    for (int i = 0; i < 200 && get(c, "/api/renders/" + id).body["progress"]["tiles_done"] == 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    const ConcurrentReads reads = readAtOnce(*server, "/api/renders/" + id + "/preview.png", 8);
    EXPECT_EQ(reads.answered, 8);
    ASSERT_EQ(reads.bodies.size(), 1u);
    EXPECT_TRUE(isPng(*reads.bodies.begin()));
    EXPECT_EQ(get(c, "/api/health").body["renders"]["previews_encoded"], 1);
    EXPECT_EQ(remove(c, "/api/renders/" + id).status, 202);
}

TEST_F(ServerJobs, CancelsQueuedAndRunningRendersAndRefusesAFullQueue) {
    auto server = start(with(sceneArgs(), {"--max-queue", "2", "--renders", "1"}));
    auto c = server->client();
    const std::string running = postJson(c, "/api/renders", slowRender(500)).body["id"];
    ASSERT_EQ(waitForRenderState(c, running, {"running"}, 10)["state"], "running");
    const Reply second = postJson(c, "/api/renders", slowRender(5));
    const Reply third = postJson(c, "/api/renders", slowRender(5));
    ASSERT_EQ(second.status, 202);
    ASSERT_EQ(third.status, 202);
    const Reply full = postJson(c, "/api/renders", slowRender(5));
    EXPECT_EQ(full.status, 429);
    EXPECT_NE(full.body["error"].get<std::string>().find("queue is full"), std::string::npos) << full.raw;
    EXPECT_EQ(full.header("Retry-After"), "10");
    EXPECT_EQ(get(c, "/api/health").body["renders"]["queued"], 2);

    const Reply cancelQueued = remove(c, "/api/renders/" + second.body["id"].get<std::string>());
    EXPECT_EQ(cancelQueued.status, 200);
    EXPECT_EQ(get(c, "/api/renders/" + second.body["id"].get<std::string>()).body["state"], "cancelled");

    const Reply cancelRunning = remove(c, "/api/renders/" + running);
    EXPECT_EQ(cancelRunning.status, 202);
    EXPECT_EQ(waitForRenderState(c, running, {"cancelled"}, 5)["state"], "cancelled");
    EXPECT_EQ(c.Get("/api/renders/" + running + "/image.png")->status, 409);

    const json third_done = waitForRenderState(c, third.body["id"], {"done"}, 10);
    EXPECT_EQ(third_done["state"], "done");
    EXPECT_EQ(postJson(c, "/api/renders", slowRender(5)).status, 202);  // room again
}

TEST_F(ServerJobs, RunsNoMoreRendersAtOnceThanConfigured) {
    auto server = start(with(sceneArgs(), {"--renders", "2"}));
    auto c = server->client();
    std::vector<std::string> ids;
    for (int i = 0; i < 4; ++i) ids.push_back(postJson(c, "/api/renders", slowRender(40)).body["id"]);
    int mostRunning = 0;
    for (int i = 0; i < 100; ++i) {
        const json health = get(c, "/api/health").body;
        mostRunning = std::max(mostRunning, health["renders"]["running"].get<int>());
        if (health["renders"]["running"] == 0 && health["renders"]["queued"] == 0) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(30));
    }
    EXPECT_EQ(mostRunning, 2);
    for (const std::string& id : ids) EXPECT_EQ(waitForRenderState(c, id, {"done"}, 10)["state"], "done");
}

TEST_F(ServerJobs, KeepsJobsAndLensesAcrossARestart) {
    std::string doneId, queuedId, lensId;
    {
        auto server = start(with(sceneArgs(), {"--renders", "1"}));
        auto c = server->client();
        std::ifstream table(std::string(LENSLAB_SOURCE_DIR) + "/lenses/wide.dat");
        const std::string text((std::istreambuf_iterator<char>(table)), std::istreambuf_iterator<char>());
        lensId = postRaw(c, "/api/lenses?name=mine.dat", text).body["id"];
        ASSERT_FALSE(lensId.empty());
        doneId = postJson(c, "/api/renders", slowRender(1)).body["id"];
        ASSERT_EQ(waitForRenderState(c, doneId, {"done"}, 10)["state"], "done");
        postJson(c, "/api/renders", slowRender(300));  // occupies the worker
        queuedId = postJson(c, "/api/renders", slowRender(1)).body["id"];
        ASSERT_EQ(get(c, "/api/renders/" + queuedId).body["state"], "queued");
        server->stop();  // SIGTERM: the running job goes back to the queue
    }
    auto server = start(sceneArgs());
    auto c = server->client();
    EXPECT_EQ(get(c, "/api/lenses/" + lensId).status, 200);
    const json done = get(c, "/api/renders/" + doneId).body;
    EXPECT_EQ(done["state"], "done");
    EXPECT_TRUE(isPng(c.Get("/api/renders/" + doneId + "/image.png")->body));
    EXPECT_EQ(waitForRenderState(c, queuedId, {"done"}, 30)["state"], "done");
    bool listed = false;
    const Reply list = get(c, "/api/renders");
    for (const json& job : list.body["renders"]) listed = listed || job["id"] == doneId;
    EXPECT_TRUE(listed);
}

TEST_F(ServerJobs, RecoversFromKillDuringARender) {
    std::string id;
    {
        auto server = start(sceneArgs());
        auto c = server->client();
        id = postJson(c, "/api/renders", slowRender(400)).body["id"];
        json status;
        for (int i = 0; i < 200 && (status.is_null() || status["progress"]["tiles_done"].get<int>() < 1); ++i) {
            status = get(c, "/api/renders/" + id).body;
            std::this_thread::sleep_for(std::chrono::milliseconds(25));
        }
        ASSERT_EQ(status["state"], "running");
        server->kill9();
    }
    auto server = start(sceneArgs());
    auto c = server->client();
    const json after = get(c, "/api/renders/" + id).body;
    EXPECT_EQ(after["state"], "failed") << after.dump();
    EXPECT_TRUE(after["interrupted"].get<bool>());
    EXPECT_NE(after["error"].get<std::string>().find("resubmit"), std::string::npos);
    EXPECT_EQ(c.Get("/api/renders/" + id + "/image.png")->status, 409);
    EXPECT_FALSE(std::filesystem::exists(data_.path() + "/data/renders/" + id + ".png"));
    for (const auto& entry : std::filesystem::recursive_directory_iterator(data_.path() + "/data"))
        EXPECT_EQ(entry.path().filename().string().find(".partial-"), std::string::npos) << entry.path();

    const Reply resubmitted = postRaw(c, "/api/renders/" + id + "/resubmit", "");
    ASSERT_EQ(resubmitted.status, 202) << resubmitted.raw;
    EXPECT_NE(resubmitted.body["id"], id);
    EXPECT_EQ(resubmitted.body["request"]["spp"], 400);
    EXPECT_EQ(remove(c, "/api/renders/" + resubmitted.body["id"].get<std::string>()).status / 100, 2);
}

// Issue 32, finding 9: deleting a lens that a queued render uses was 200, and the render failed when
// it started. Now 409 naming the render until it has ended; then the lens goes.
TEST_F(ServerJobs, ALensARenderWaitsForCannotBeDeleted) {
    auto server = start(with(sceneArgs(), {"--renders", "1"}));
    auto c = server->client();
    const Reply lens = postRaw(c, "/api/lenses?name=mine.dat", kSmallLensTable);
    ASSERT_EQ(lens.status, 201);
    const std::string id = lens.body["id"];
    const std::string running = postJson(c, "/api/renders", slowRender(500)).body["id"];
    json queued = slowRender(5);
    queued["lens"] = id;
    const Reply waiting = postJson(c, "/api/renders", queued);
    ASSERT_EQ(waiting.status, 202) << waiting.raw;
    const Reply refused = remove(c, "/api/lenses/" + id);
    EXPECT_EQ(refused.status, 409) << refused.raw;
    EXPECT_NE(refused.body.value("error", std::string()).find(waiting.body["id"].get<std::string>()), std::string::npos) << refused.raw;
    EXPECT_EQ(remove(c, "/api/renders/" + running).status, 202);
    EXPECT_EQ(waitForRenderState(c, waiting.body["id"], {"done"}, 20)["state"], "done");
    EXPECT_EQ(remove(c, "/api/lenses/" + id).status, 200);
}

// Issue 40, finding 7: a render submitted while its lens was being deleted got 202 and the delete
// 200 (22 rounds of 30), and the job failed when it opened the lens. The lens's lookup and the job's
// queueing now hold the deletion off: each round either the delete sees the render (409) or the
// render never finds the lens (400). The delete goes out a little later each round, across the
// submission's check of the new lens (the window the race had).
TEST_F(ServerJobs, ARenderAndItsLenssDeletionNeverBothSucceed) {
    auto server = start(sceneArgs());
    auto c = server->client();
    for (int round = 0; round < 30; ++round) {
        const Reply lens = postRaw(c, "/api/lenses?name=mine.dat", kSmallLensTable);
        ASSERT_EQ(lens.status, 201) << lens.raw;
        const std::string id = lens.body["id"];
        json request = slowRender(1);
        request["lens"] = id;
        auto submitted = std::async(std::launch::async, [&] {
            auto own = server->client();
            return postJson(own, "/api/renders", request);
        });
        std::this_thread::sleep_for(std::chrono::microseconds(200 * (round % 15)));
        const Reply deleted = remove(c, "/api/lenses/" + id);
        const Reply render = submitted.get();
        ASSERT_TRUE((render.status == 202 && deleted.status == 409) || (render.status == 400 && deleted.status == 200))
            << "round " << round << ": render " << render.status << " " << render.raw << ", delete " << deleted.status << " "
            << deleted.raw;
        if (render.status == 400) continue;
        const json ended = waitForRenderState(c, render.body["id"], {"done", "failed", "cancelled"}, 20);
        EXPECT_EQ(ended["state"], "done") << ended.dump();
        EXPECT_EQ(remove(c, "/api/lenses/" + id).status, 200);
    }
}

