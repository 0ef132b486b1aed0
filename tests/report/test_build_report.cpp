// buildReport called directly, as the server's report job does: progress, cancellation and an
// uploaded lens added to the bundled ones.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "BuildReport.h"

namespace fs = std::filesystem;
using namespace lenslab;

namespace {

ReportOptions lensOnlyOptions(const std::string& name) {
    ReportOptions o;
    o.outputDir = fs::temp_directory_path() / ("lenslab-build-report-" + name + "-" + std::to_string(getpid()));
    fs::remove_all(o.outputDir);
    o.sceneDir = (o.outputDir / "no-scenes").string();
    o.lenses = {"dgauss.50mm"};
    o.quick = true;
    return o;
}

}  // namespace

TEST(BuildReport, ReportsProgressUpToTheTotalAndAddsAnUploadedLensUnderAFreeId) {
    ReportOptions o = lensOnlyOptions("progress");
    o.extraLenses = {std::string(LENSLAB_SOURCE_DIR) + "/lenses/dgauss.50mm.dat"};  // the same id as a bundled lens
    std::vector<ReportProgress> steps;
    const ReportSummary s = buildReport(o, [&](const ReportProgress& p) { steps.push_back(p); });
    ASSERT_FALSE(steps.empty());
    for (std::size_t k = 0; k < steps.size(); ++k) {
        EXPECT_EQ(steps[k].done, static_cast<int>(k) + 1);
        EXPECT_EQ(steps[k].total, steps.back().total);
    }
    EXPECT_EQ(s.lenses, 2);
    EXPECT_EQ(s.renders, 0);
    EXPECT_TRUE(s.problems.empty());
    std::ifstream in(s.indexPath);
    const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(html.find("id=\"lens-dgauss.50mm\""), std::string::npos);
    EXPECT_NE(html.find("id=\"lens-dgauss.50mm-2\""), std::string::npos);
    fs::remove_all(o.outputDir);
}

TEST(BuildReport, StopsWhenCancelledAndKeepsWhatItFinished) {
    const ReportOptions o = lensOnlyOptions("cancel");
    std::atomic<bool> cancel{false};
    int calls = 0;
    EXPECT_THROW(buildReport(o, [&](const ReportProgress&) { cancel = ++calls >= 2; }, &cancel), ReportCancelled);
    EXPECT_EQ(calls, 2);
    EXPECT_FALSE(fs::exists(o.outputDir / "index.html"));
    const ReportSummary resumed = buildReport(o);
    EXPECT_EQ(resumed.reused, 2);
    EXPECT_EQ(resumed.built, resumed.items - 2);
    fs::remove_all(o.outputDir);
}

TEST(BuildReport, RefusesAnUnknownLens) {
    ReportOptions o = lensOnlyOptions("unknown");
    o.lenses = {"no-such-lens"};
    EXPECT_THROW(buildReport(o), std::runtime_error);
    fs::remove_all(o.outputDir);
}

TEST(BuildReport, RebuildsOnlyWhatAChangedLensTableFeeds) {
    ReportOptions o = lensOnlyOptions("changed");
    const fs::path lenses = o.outputDir.string() + "-lenses";
    fs::create_directories(lenses);
    for (const char* id : {"dgauss.50mm", "wide.22mm"})
        fs::copy_file(std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + id + ".dat", lenses / (std::string(id) + ".dat"),
                      fs::copy_options::overwrite_existing);
    o.lensDir = lenses.string();
    o.lenses.clear();
    const ReportSummary first = buildReport(o);
    EXPECT_EQ(first.built, 10);  // per lens: the data, three diagrams and the designer's analysis
    std::ofstream(lenses / "wide.22mm.dat", std::ios::app) << "\n# an edit that changes no number\n";
    const ReportSummary second = buildReport(o);
    EXPECT_EQ(second.built, 5);
    EXPECT_EQ(second.reused, 5);
    fs::remove_all(o.outputDir);
    fs::remove_all(lenses);
}
