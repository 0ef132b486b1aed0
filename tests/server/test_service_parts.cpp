// The service's parts in-process: request checking, identifiers, the diagram cache's sharing and
// eviction, and the job queue's limits, cancellation and persistence with a fake renderer.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <future>
#include <thread>

#include "storage/Database.h"
#include "storage/DiagramCache.h"
#include "FakeRenderer.h"
#include "core/HttpError.h"
#include "core/Identifiers.h"
#include "jobs/JobQueue.h"
#include "jobs/JobStore.h"
#include "storage/LensStore.h"
#include "jobs/RenderRequest.h"
#include "ServerProcess.h"

using namespace lenslab;
using nlohmann::json;

TEST(RenderRequestTest, FillsDefaultsAndChecksRanges) {
    const RenderLimits limits;
    const RenderRequest r = parseRenderRequest(json::object(), limits, "cornell");
    EXPECT_EQ(r.scene, "cornell");
    EXPECT_EQ(r.lens, "dgauss.50mm");
    EXPECT_EQ(r.mode, "exact");
    EXPECT_FALSE(r.fstop.has_value());
    EXPECT_EQ(r.spp, 16);
    EXPECT_FALSE(r.spectral.has_value());  // spectral when the lens disperses
    EXPECT_FALSE(parseRenderRequest(json{{"spectral", nullptr}}, limits, "s").spectral.has_value());
    const json full = {{"scene", "s"}, {"lens", "l"}, {"fstop", 2.8}, {"focaldistance", 1500}, {"filmdiagonal", 43.3},
                       {"mode", "thick"}, {"spectral", true}, {"spp", 4}, {"width", 64}, {"height", 48},
                       {"ghosts", "12"}, {"ghost_model", "paraxial"}};
    EXPECT_EQ(renderRequestJson(parseRenderRequest(full, limits, "")), full);
    EXPECT_FALSE(r.ghosts.has_value());  // the scene's own
    EXPECT_EQ(parseRenderRequest(json{{"ghosts", 7}}, limits, "s").ghosts, "7");
    EXPECT_EQ(parseRenderRequest(json{{"ghosts", "auto"}}, limits, "s").ghosts, "auto");
    for (const json& bad : {json{{"spp", 0}}, json{{"spp", limits.maxSpp + 1}}, json{{"width", 7}},
                            json{{"height", limits.maxHeight + 1}}, json{{"fstop", "wide"}}, json{{"focaldistance", "near"}},
                            json{{"filmdiagonal", "big"}}, json{{"mode", "fast"}}, json{{"scene", "../x"}},
                            json{{"lens", ""}}, json{{"colour", 1}}, json{{"spp", 1.5}}, json{{"spectral", "on"}},
                            json{{"ghosts", "some"}}, json{{"ghosts", 0}}, json{{"ghosts", 1001}}, json{{"ghosts", true}},
                            json{{"ghost_model", "fast"}}}) {
        try {
            parseRenderRequest(bad, limits, "s");
            ADD_FAILURE() << "accepted " << bad.dump();
        } catch (const HttpError& e) {
            EXPECT_EQ(e.status(), 400) << bad.dump();
        }
    }
    EXPECT_THROW(parseRenderRequest(json::object(), limits, ""), HttpError);
}

TEST(IdentifiersTest, AcceptOnlyPlainNames) {
    EXPECT_TRUE(isSafeIdentifier("dgauss.50mm"));
    EXPECT_TRUE(isSafeIdentifier("upload-0123456789abcdef"));
    for (const char* bad : {"", ".hidden", "../x", "a/b", "a\\b", "x y", "-x"}) EXPECT_FALSE(isSafeIdentifier(bad)) << bad;
    EXPECT_FALSE(isSafeIdentifier(std::string(81, 'a')));
    EXPECT_NE(newRandomIdentifier("r-"), newRandomIdentifier("r-"));
    EXPECT_EQ(uploadDisplayName("C:\\Users\\me\\..\\lens.dat"), "lens.dat");
    EXPECT_EQ(uploadDisplayName("../../"), "upload.dat");
}

TEST(DiagramCacheTest, SharesOneDrawingBetweenConcurrentRequests) {
    DiagramCache cache(1 << 20);
    std::atomic<int> draws{0};
    const auto slowDraw = [&] {
        ++draws;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        return Bytes(100, 7);
    };
    std::vector<std::future<std::shared_ptr<const Bytes>>> results;
    for (int i = 0; i < 8; ++i) results.push_back(std::async(std::launch::async, [&] { return cache.getOrDraw("k", slowDraw); }));
    for (auto& r : results) EXPECT_EQ(r.get()->size(), 100u);
    EXPECT_EQ(draws, 1);
    EXPECT_EQ(cache.stats().hits + cache.stats().misses, 8u);
}

TEST(DiagramCacheTest, EvictsTheLeastRecentlyUsedAndDoesNotCacheErrors) {
    DiagramCache cache(250);
    int draws = 0;
    const auto draw = [&] {
        ++draws;
        return Bytes(100, 1);
    };
    cache.getOrDraw("a", draw);
    cache.getOrDraw("b", draw);
    cache.getOrDraw("a", draw);  // a is now the most recent
    cache.getOrDraw("c", draw);  // evicts b
    EXPECT_EQ(draws, 3);
    cache.getOrDraw("a", draw);
    EXPECT_EQ(draws, 3);
    cache.getOrDraw("b", draw);
    EXPECT_EQ(draws, 4);
    EXPECT_LE(cache.stats().bytes, 250u);
    EXPECT_THROW(cache.getOrDraw("bad", []() -> Bytes { throw std::runtime_error("no"); }), std::runtime_error);
    EXPECT_EQ(cache.getOrDraw("bad", draw)->size(), 100u);
    cache.forget("b");
    EXPECT_EQ(cache.getOrDraw("b", draw)->size(), 100u);
    EXPECT_EQ(draws, 6);
}

namespace {

RenderJobInput fakeJob(int millisecondsPerTile) {
    RenderJobInput job;
    job.jobId = newRandomIdentifier("render-");
    job.request.scene = "s";
    job.request.spp = millisecondsPerTile;
    job.request.width = 32;
    job.request.height = 32;
    return job;
}

JobState waitForState(JobQueue& queue, const std::string& id, JobState wanted) {
    for (int i = 0; i < 500; ++i) {
        const JobState s = queue.find(id)->record.state;
        if (s == wanted) return s;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return queue.find(id)->record.state;
}

}  // namespace

TEST(JobQueueTest, LimitsCancelsAndPersists) {
    test::TempDir dir;
    Database db(dir.path() + "/jobs.db");
    JobStore store(db);
    FakeRenderer renderer;
    RenderLimits limits;
    limits.maxQueued = 1;
    limits.concurrentRenders = 1;
    std::string slowId, waitingId;
    {
        JobQueue queue(store, renderer, limits, dir.path() + "/renders");
        slowId = queue.submit(fakeJob(200)).id;
        EXPECT_EQ(waitForState(queue, slowId, JobState::Running), JobState::Running);
        waitingId = queue.submit(fakeJob(1)).id;
        EXPECT_THROW(queue.submit(fakeJob(1)), QueueFull);
        EXPECT_EQ(queue.cancel(waitingId), JobQueue::Cancel::Cancelled);
        EXPECT_EQ(store.find(waitingId)->state, JobState::Cancelled);
        EXPECT_EQ(queue.cancel(waitingId), JobQueue::Cancel::AlreadyFinished);
        EXPECT_EQ(queue.cancel("render-unknown"), JobQueue::Cancel::NotFound);
        queue.shutdown();  // the running job returns to the queue
    }
    EXPECT_EQ(store.find(slowId)->state, JobState::Queued);
    EXPECT_EQ(store.queued().size(), 1u);
    JobQueue queue(store, renderer, limits, dir.path() + "/renders");
    const JobRecord record = *store.find(slowId);
    RenderJobInput again = fakeJob(1);
    again.jobId = slowId;
    queue.restore(record, again);
    EXPECT_EQ(waitForState(queue, slowId, JobState::Done), JobState::Done);
    EXPECT_TRUE(std::filesystem::exists(queue.imagePath(slowId, "png")));
    EXPECT_TRUE(std::filesystem::exists(queue.imagePath(slowId, "exr")));
    EXPECT_EQ(renderer.mostAtOnce(), 1);
}

namespace {

// A renderer that fails the way a scene error does, naming the files by their server paths.
class FailingRenderer : public JobRenderer {
public:
    RenderedImages render(const RenderJobInput& job, const TileCallback&, const std::atomic<bool>&) override {
        throw SceneError(job.scenePath + ":5: Camera \"realistic\": cannot open 'x.dat' (looked for " +
                         job.lensPath + ")");
    }
    std::vector<std::uint8_t> encodePreview(const Image&) const override { return {}; }
};

}  // namespace

TEST(JobQueueTest, FailedJobsNameFilesWithoutServerPaths) {
    test::TempDir dir;
    Database db(dir.path() + "/jobs.db");
    JobStore store(db);
    FailingRenderer renderer;
    JobQueue queue(store, renderer, RenderLimits{}, dir.path() + "/renders");
    RenderJobInput job = fakeJob(1);
    job.scenePath = "/srv/lenslab/scenes/cornell.pbrt";
    job.lensPath = "/srv/lenslab/data/lenses/upload-1.dat";
    const std::string id = queue.submit(job).id;
    ASSERT_EQ(waitForState(queue, id, JobState::Failed), JobState::Failed);
    const std::string error = queue.find(id)->record.error;
    EXPECT_EQ(error, "cornell.pbrt:5: Camera \"realistic\": cannot open 'x.dat' (looked for upload-1.dat)");
    EXPECT_EQ(error.find("/srv"), std::string::npos);
    queue.shutdown();
}
