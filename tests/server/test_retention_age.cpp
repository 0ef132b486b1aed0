// The retention policy's age limit is in days of 86,400 s: with --keep-days 1, a render finished
// two hours ago stays and one finished two days ago goes. (The HTTP test can only wait seconds, so
// its limit of 0.00001 days cannot tell days from hours.)
#include <gtest/gtest.h>

#include "storage/Database.h"
#include "FakeRenderer.h"
#include "core/Identifiers.h"
#include "jobs/RenderRetention.h"
#include "TempDir.h"

using namespace lenslab;

TEST(RetentionAge, KeepDaysCountsDaysOf86400Seconds) {
    test::TempDir dir;
    Database db(dir.path() + "/jobs.db");
    JobStore store(db);
    FakeRenderer renderer;
    JobQueue queue(store, renderer, RenderLimits{}, dir.path() + "/renders");
    constexpr double kNow = 2e9, kHour = 3600, kDay = 86400;
    const auto finishedAt = [&](double t) {
        JobRecord r;
        r.id = newRandomIdentifier("render-");
        r.state = JobState::Done;
        r.created = r.started.emplace(t - 10);
        r.finished = t;
        store.insert(r);
        store.save(r);  // the times
        return r.id;
    };
    const std::string recent = finishedAt(kNow - 2 * kHour), old = finishedAt(kNow - 2 * kDay);
    RetentionPolicy policy;
    policy.keepDays = 1;
    policy.keepBytes = 0;
    EXPECT_EQ(collectRenders(queue, store, policy, kNow), 1);
    EXPECT_FALSE(store.find(old));
    EXPECT_TRUE(store.find(recent));
}
