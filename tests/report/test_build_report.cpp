// buildReport called directly, as the server's report job does: progress, cancellation, an
// uploaded lens added to the bundled ones, named and cited as what it was.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

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

std::string fileText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
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

TEST(BuildReport, AnUploadIsNamedAndCitedAsWhatItWasAndTheAnalysisIsThePages) {
    ReportOptions o = lensOnlyOptions("names");
    // An upload is stored under its id as .dat whatever it was: here a Zemax file.
    const fs::path uploads = o.outputDir.string() + "-uploads", upload = uploads / "upload-0123456789abcdef.dat";
    fs::create_directories(uploads);
    std::ofstream(upload) << fileText(LENSLAB_SOURCE_DIR "/lenses/us2015-0092100-ex1-55mm.zmx");
    o.lenses.push_back(upload.string());
    o.lensNames[upload.string()] = "sony-ex1.zmx";
    const ReportSummary s = buildReport(o);
    EXPECT_TRUE(s.problems.empty());
    const std::string html = fileText(s.indexPath);
    EXPECT_NE(html.find("<h3>sony-ex1.zmx</h3>"), std::string::npos);
    const std::size_t byId = html.find(">upload-0123456789abcdef<");
    EXPECT_EQ(byId, std::string::npos) << html.substr(byId == std::string::npos ? 0 : byId - 300, 400);
    EXPECT_NE(html.find("<code>lenslab lens sony-ex1.zmx --json</code> with the settings above; a Zemax .zmx prescription)"),
              std::string::npos);
    EXPECT_NE(html.find("<code>lenslab lens dgauss.50mm.dat --json</code> with the settings above; a lens table (.dat))"),
              std::string::npos);
    // The designer's analysis at the page's first settings, named: dgauss.50mm at its widest focused
    // at infinity, 13.56 um RMS on the axis (the tables' 2 m focus gave 12.62).
    EXPECT_NE(html.find("The lens designer's analysis at f/2.02, focused at infinity</h4>"), std::string::npos);
    const nlohmann::json analysis = nlohmann::json::parse(fileText(o.outputDir / "assets/lenses/dgauss.50mm-analysis/analysis.json"));
    EXPECT_TRUE(analysis.at("focus_distance").is_null());
    EXPECT_NEAR(1000 * analysis.at("fields").at(0).at("polychromatic").at("rms_radius_mm").get<double>(), 13.56, 0.005);
    fs::remove_all(o.outputDir);
    fs::remove_all(uploads);
}
