// The service's parts in-process: request checking, a download's file name, a chunked body's payload count, identifiers, the result cache's sharing and
// eviction, the heavy-work pool's admission, event-stream slots, storage errors' statuses, the
// remembered render checks, and the job queue's limits, cancellation, persistence and retention by
// count with a fake renderer.
#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <future>
#include <list>
#include <thread>

#include "storage/Database.h"
#include "storage/ResultCache.h"
#include "FakeRenderer.h"
#include "core/HttpError.h"
#include "core/ContentDisposition.h"
#include "core/Identifiers.h"
#include "core/WallClock.h"
#include "guards/ChunkedBodyMeter.h"
#include "guards/EventStreamSlots.h"
#include "jobs/JobJson.h"
#include "jobs/JobQueue.h"
#include "jobs/JobStore.h"
#include "storage/LensStore.h"
#include "storage/StorageError.h"
#include "jobs/RenderRequest.h"
#include "jobs/RenderRetention.h"
#include "jobs/RenderSettingsChecks.h"
#include "jobs/WorkPool.h"
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
                       {"ghosts", "12"}, {"ghost_model", "paraxial"}, {"tilt", 6}, {"swing", -2.5},
                       {"shift", {3, -4}}, {"sensor", {{"iso", 800}, {"read", 1.5}, {"cfa", "rggb"}}}};
    EXPECT_EQ(renderRequestJson(parseRenderRequest(full, limits, "")), full);
    EXPECT_TRUE(renderRequestJson(r)["shift"].is_null());  // the scene's own
    EXPECT_TRUE(renderRequestJson(r)["sensor"].is_null());  // the noiseless film
    EXPECT_FALSE(r.ghosts.has_value());  // the scene's own
    EXPECT_EQ(parseRenderRequest(json{{"ghosts", 7}}, limits, "s").ghosts, "7");
    EXPECT_EQ(parseRenderRequest(json{{"ghosts", "auto"}}, limits, "s").ghosts, "auto");
    for (const json& bad : {json{{"spp", 0}}, json{{"spp", limits.maxSpp + 1}}, json{{"width", 7}},
                            json{{"height", limits.maxHeight + 1}}, json{{"fstop", "wide"}}, json{{"focaldistance", "near"}},
                            json{{"filmdiagonal", "big"}}, json{{"mode", "fast"}}, json{{"scene", "../x"}},
                            json{{"lens", ""}}, json{{"colour", 1}}, json{{"spp", 1.5}}, json{{"spectral", "on"}},
                            json{{"ghosts", "some"}}, json{{"ghosts", 0}}, json{{"ghosts", 1001}}, json{{"ghosts", true}},
                            json{{"ghost_model", "fast"}}, json{{"tilt", 46}}, json{{"swing", "left"}},
                            json{{"shift", {1}}}, json{{"shift", {1, 101}}}, json{{"shift", "up"}}, json{{"shift", {1, "a"}}},
                            json{{"sensor", {{"cfa", "rgbg"}}}}, json{{"sensor", {{"cfa", 1}}}}, json{{"sensor", {{"iso", true}}}},
                            json{{"sensor", {{"iso", "fast"}}}}}) {
        try {
            parseRenderRequest(bad, limits, "s");
            ADD_FAILURE() << "accepted " << bad.dump();
        } catch (const HttpError& e) {
            EXPECT_EQ(e.status(), 400) << bad.dump();
        }
    }
    EXPECT_THROW(parseRenderRequest(json::object(), limits, ""), HttpError);
}

// Chunks of 10, 0x1a and 5 bytes (41 in all; the last one's data looks like the closing chunk)
// with an extension, CRLFs and a trailer.
const std::string kChunkedWire = "a\r\n0123456789\r\n1A;name=value\r\nabcdefghijklmnopqrstuvwxyz\r\n5\r\n\r\n0\r\n\r\n"
                                 "0\r\nX-Trailer: 1\r\n\r\n";

TEST(ChunkedBodyMeterTest, CountsThePayloadNotTheFramingHoweverTheBytesArrive) {
    ChunkedBodyMeter whole;
    EXPECT_TRUE(whole.take(kChunkedWire.data(), kChunkedWire.size(), 41));
    EXPECT_EQ(whole.payloadBytes(), 41u);
    ChunkedBodyMeter byteByByte;
    for (char c : kChunkedWire) ASSERT_TRUE(byteByByte.take(&c, 1, 41));
    EXPECT_EQ(byteByByte.payloadBytes(), 41u);
}

TEST(ChunkedBodyMeterTest, RefusesTheChunkThatPassesTheLimitFromItsSizeLine) {
    ChunkedBodyMeter meter;
    const std::size_t thirdSizeLine = kChunkedWire.find("5\r\n");
    ASSERT_TRUE(meter.take(kChunkedWire.data(), thirdSizeLine, 40));
    EXPECT_EQ(meter.payloadBytes(), 36u);
    EXPECT_FALSE(meter.take(kChunkedWire.data() + thirdSizeLine, 3, 40));  // "5\r\n": 41 > 40 before any data
    const std::string huge = "fffffffffffffffffffffffff\r\n";  // past size_t: refused, not wrapped round
    EXPECT_FALSE(ChunkedBodyMeter().take(huge.data(), huge.size(), 1 << 20));
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

TEST(ResultCacheTest, SharesOneDrawingBetweenConcurrentRequests) {
    ResultCache cache(1 << 20);
    std::atomic<int> draws{0};
    const auto slowDraw = [&] {
        ++draws;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        return Bytes(100, 7);
    };
    std::vector<std::future<std::shared_ptr<const Bytes>>> results;
    for (int i = 0; i < 8; ++i) results.push_back(std::async(std::launch::async, [&] { return cache.getOrCompute("k", slowDraw); }));
    for (auto& r : results) EXPECT_EQ(r.get()->size(), 100u);
    EXPECT_EQ(draws, 1);
    EXPECT_EQ(cache.stats().hits + cache.stats().misses, 8u);
}

TEST(ResultCacheTest, EvictsTheLeastRecentlyUsedAndDoesNotCacheErrors) {
    ResultCache cache(250);
    int draws = 0;
    const auto draw = [&] {
        ++draws;
        return Bytes(100, 1);
    };
    cache.getOrCompute("a", draw);
    cache.getOrCompute("b", draw);
    cache.getOrCompute("a", draw);  // a is now the most recent
    cache.getOrCompute("c", draw);  // evicts b
    EXPECT_EQ(draws, 3);
    cache.getOrCompute("a", draw);
    EXPECT_EQ(draws, 3);
    cache.getOrCompute("b", draw);
    EXPECT_EQ(draws, 4);
    EXPECT_LE(cache.stats().bytes, 250u);
    EXPECT_THROW(cache.getOrCompute("bad", []() -> Bytes { throw std::runtime_error("no"); }), std::runtime_error);
    EXPECT_EQ(cache.getOrCompute("bad", draw)->size(), 100u);
    cache.forget("b");
    EXPECT_EQ(cache.getOrCompute("b", draw)->size(), 100u);
    EXPECT_EQ(draws, 6);
}

// The heavy-work pool: at most `admitted` requests wait on it, `perClient` of them from one client,
// others hear 429 at once with Retry-After; places come back when requests end; results and
// exceptions reach the waiting caller; work queued before the pool is destroyed still runs.
TEST(WorkPoolTest, AdmitsBoundedSharesAndRunsTheWork) {
    WorkPool pool({2, 5, 3});
    std::list<WorkPool::Admission> held;
    for (int i = 0; i < 3; ++i) held.push_back(pool.admit("10.0.0.1"));
    try {
        pool.admit("10.0.0.1");
        ADD_FAILURE() << "a fourth place for one client";
    } catch (const HttpError& e) {
        EXPECT_EQ(e.status(), 429);
        EXPECT_GT(e.retryAfterSeconds(), 0);
        EXPECT_NE(std::string(e.what()).find("share"), std::string::npos) << e.what();
    }
    held.push_back(pool.admit("10.0.0.2"));
    held.push_back(pool.admit("10.0.0.3"));
    try {
        pool.admit("10.0.0.4");
        ADD_FAILURE() << "a sixth place in a pool of five";
    } catch (const HttpError& e) {
        EXPECT_EQ(e.status(), 429);
        EXPECT_NE(std::string(e.what()).find("busy"), std::string::npos) << e.what();
    }
    EXPECT_EQ(pool.stats().admitted, 5);
    EXPECT_EQ(pool.stats().refused, 2u);
    held.pop_front();
    EXPECT_NO_THROW(pool.admit("10.0.0.4"));  // its place, given back at once
    EXPECT_NO_THROW(held.push_back(pool.admit("10.0.0.1")));
    held.clear();
    EXPECT_EQ(pool.stats().admitted, 0);

    EXPECT_EQ(pool.run([] { return 6 * 7; }), 42);
    EXPECT_THROW(pool.run([]() -> int { throw std::runtime_error("no"); }), std::runtime_error);
}

TEST(WorkPoolTest, RunsNoMoreThanItsThreadsAtOnce) {
    std::atomic<int> now{0}, most{0};
    {
        WorkPool pool({2, 16, 16});
        std::vector<std::future<void>> waiting;
        for (int i = 0; i < 8; ++i)
            waiting.push_back(std::async(std::launch::async, [&] {
                pool.run([&] {
                    most = std::max(most.load(), ++now);
                    std::this_thread::sleep_for(std::chrono::milliseconds(50));
                    --now;
                    return 0;
                });
            }));
        for (auto& w : waiting) w.get();
    }
    EXPECT_EQ(most, 2);
}

// A cached result is served without a place in the pool: a full pool still answers it.
TEST(WorkPoolTest, CachedResultsNeedNoPlace) {
    WorkPool pool({1, 1, 1});
    ResultCache cache(1 << 20);
    EXPECT_EQ(pool.cachedOrComputed(cache, "k", "a", [] { return Bytes(3, 1); })->size(), 3u);
    const WorkPool::Admission full = pool.admit("b");
    EXPECT_EQ(pool.cachedOrComputed(cache, "k", "a", [] { return Bytes(5, 1); })->size(), 3u);
    EXPECT_THROW(pool.cachedOrComputed(cache, "other", "a", [] { return Bytes(5, 1); }), HttpError);
}

// Records kept from before (or any error text) are served without server paths or long values.
TEST(JobJsonTest, AnErrorIsServedAsAPublicMessage) {
    JobRecord record;
    record.id = "render-0000000000000001";
    record.state = JobState::Failed;
    record.error = "could not be restarted: lens table '/srv/lenslab/data/lenses/upload-1.dat' not found; " + std::string(500, 'x');
    const json served = jobJson(JobView{record, false, {}}, 0, 0);
    const std::string error = served["error"];
    EXPECT_EQ(error.find("/srv"), std::string::npos) << error;
    EXPECT_NE(error.find("'upload-1.dat'"), std::string::npos) << error;
    EXPECT_LT(error.size(), 200u) << error;
}

// Event streams: a client's fourth stream is its last (docs/api.md: "at most 4 per client address"),
// and the total is the total; a slot given back is free again.
TEST(EventStreamSlotsTest, AClientGetsItsShareAndTheTotalHolds) {
    auto slots = std::make_shared<EventStreamSlots>(6, 4);
    std::vector<std::shared_ptr<void>> held;
    for (int i = 0; i < 4; ++i) {
        held.push_back(slots->take("10.0.0.1"));
        EXPECT_TRUE(held.back()) << "stream " << i + 1;
    }
    EXPECT_FALSE(slots->take("10.0.0.1")) << "a fifth stream for one client";
    held.push_back(slots->take("10.0.0.2"));
    held.push_back(slots->take("10.0.0.3"));
    EXPECT_TRUE(held[4] && held[5]);
    EXPECT_FALSE(slots->take("10.0.0.4")) << "a seventh stream of six";
    held.erase(held.begin());
    EXPECT_TRUE(slots->take("10.0.0.1"));
}

// A full disk is 507 (ENOSPC above all: the usual errno), a read-only one or any other failure 503.
TEST(StorageErrorTest, AFullDiskIs507AndOtherFailures503) {
    for (int full : {ENOSPC, EDQUOT, EFBIG}) EXPECT_EQ(StorageError(storageErrorKind(full), "x").httpStatus(), 507) << full;
    for (int other : {EROFS, EACCES, EPERM, EIO}) EXPECT_EQ(StorageError(storageErrorKind(other), "x").httpStatus(), 503) << other;
}

// A render's check is remembered per scene, lens and settings: a scene at f/2.1 is fine through
// dgauss.50mm (f/2.02) and refused through telephoto.250mm (f/5.59), asked in either order.
TEST(RenderSettingsChecksTest, TheRememberedOutcomeIsTheLenssOwn) {
    const std::string source = LENSLAB_SOURCE_DIR;
    const auto job = [&](const std::string& lens) {
        RenderJobInput input;
        input.request.scene = "depth-of-field";
        input.scenePath = source + "/scenes/depth-of-field.pbrt";
        input.lensPath = source + "/lenses/" + lens + ".dat";
        input.lensLayout = TableLayout::GapAfter;
        return input;
    };
    for (bool wideFirst : {true, false}) {
        RenderSettingsChecks checks;
        const auto expectRefused = [&] {
            try {
                checks.check(job("telephoto.250mm"));
                ADD_FAILURE() << "f/2.1 accepted through a lens that opens to f/5.59";
            } catch (const HttpError& e) {
                EXPECT_EQ(e.status(), 422);
            }
        };
        if (!wideFirst) expectRefused();
        EXPECT_NO_THROW(checks.check(job("dgauss.50mm")));
        expectRefused();
        EXPECT_NO_THROW(checks.check(job("dgauss.50mm")));
    }
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

// Issue 40, finding 8: submit + cancel kept every job record for 30 days (20,464 in 240 s), and a
// job cancelled while it waited never ran the retention. With a count limit of 5, 12 jobs cancelled
// while they wait leave the 5 newest.
TEST(JobQueueTest, FinishedJobsAreCappedByCountTheNewestKept) {
    test::TempDir dir;
    Database db(dir.path() + "/jobs.db");
    JobStore store(db);
    FakeRenderer renderer;
    RenderLimits limits;
    limits.concurrentRenders = 1;
    JobQueue queue(store, renderer, limits, dir.path() + "/renders");
    RetentionPolicy policy;
    policy.keepCount = 5;
    queue.setAfterJob([&] { collectRenders(queue, store, policy, secondsSinceEpoch()); });
    const std::string slowId = queue.submit(fakeJob(200)).id;  // keeps the others waiting
    ASSERT_EQ(waitForState(queue, slowId, JobState::Running), JobState::Running);
    std::vector<std::string> cancelled;
    for (int i = 0; i < 12; ++i) {
        cancelled.push_back(queue.submit(fakeJob(1)).id);
        EXPECT_EQ(queue.cancel(cancelled.back()), JobQueue::Cancel::Cancelled);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));  // finish times apart
    }
    EXPECT_EQ(store.finishedCount(), 5);
    for (int i = 0; i < 12; ++i) EXPECT_EQ(store.find(cancelled[i]).has_value(), i >= 7) << "job " << i;
    EXPECT_EQ(store.find(slowId)->state, JobState::Running);
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

// A download's name as a person gave it: quotes, slashes, backslashes, controls and non-ASCII never
// break out of the header or name a path.
TEST(ContentDispositionTest, AnyNameIsOneSafeFileName) {
    EXPECT_EQ(attachmentDisposition("dgauss.50mm.zmx"), "attachment; filename=\"dgauss.50mm.zmx\"; filename*=UTF-8''dgauss.50mm.zmx");
    EXPECT_EQ(attachmentDisposition("a \"quoted\" lens.zmx"),
              "attachment; filename=\"a _quoted_ lens.zmx\"; filename*=UTF-8''a%20%22quoted%22%20lens.zmx");
    EXPECT_EQ(attachmentDisposition("../../etc/passwd"), "attachment; filename=\".._.._etc_passwd\"; filename*=UTF-8''.._.._etc_passwd");
    EXPECT_EQ(attachmentDisposition("C:\\lens;x=1\r\nSet-Cookie: a.dat"),
              "attachment; filename=\"C__lens_x_1__Set-Cookie_ a.dat\"; filename*=UTF-8''C%3A_lens%3Bx%3D1__Set-Cookie%3A%20a.dat");
    EXPECT_EQ(attachmentDisposition("Zoom 24–70 ƒ2.8 日本.zmx"),
              "attachment; filename=\"Zoom 24_70 _2.8 __.zmx\"; "
              "filename*=UTF-8''Zoom%2024%E2%80%9370%20%C6%922.8%20%E6%97%A5%E6%9C%AC.zmx");
}
