// The report's cache is keyed by the code that makes each item: a change to the ray tracer rebuilds
// the renders and keeps the lens tables; a change to optics rebuilds everything.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

#include "ItemRunner.h"

namespace fs = std::filesystem;
using namespace lenslab;

namespace {

CodeDigests changed(CodeDigests c, CodePart part) {
    c.digests[int(part)] += "-changed";
    return c;
}

std::string key(const char* kind, const CodeDigests& code) { return itemInputs(kind, code).hex(); }

}  // namespace

TEST(ReportCacheKeys, EachKindFollowsTheCodeThatMakesIt) {
    const CodeDigests built = builtCode();
    for (const std::string& d : built.digests) EXPECT_TRUE(std::regex_match(d, std::regex("[0-9a-f]{64}"))) << d;
    EXPECT_EQ(key("render", built), itemInputs("render").hex());
    const CodeDigests tracer = changed(built, CodePart::Raytracer);
    for (const char* kind : {"render", "difference", "speed"}) EXPECT_NE(key(kind, tracer), key(kind, built)) << kind;
    for (const char* kind : {"lens", "diagram"}) EXPECT_EQ(key(kind, tracer), key(kind, built)) << kind;
    EXPECT_NE(key("diagram", changed(built, CodePart::Diagram)), key("diagram", built));
    EXPECT_NE(key("lens", changed(built, CodePart::Formats)), key("lens", built));
    for (CodePart everyone : {CodePart::Optics, CodePart::Report})
        for (const char* kind : {"lens", "diagram", "render", "difference", "speed"})
            EXPECT_NE(key(kind, changed(built, everyone)), key(kind, built)) << kind;
}

// The build step behind builtCode(): one file of renderer/raytracer edited (in one of its concept
// folders) changes that part's digest and no other.
TEST(ReportCacheKeys, TheDigestScriptFollowsFileContents) {
    const fs::path dir = fs::temp_directory_path() / ("lenslab-digests-" + std::to_string(getpid()));
    fs::remove_all(dir);
    for (const char* part : {"optics", "renderer/raytracer/cameras"}) fs::create_directories(dir / part);
    const auto write = [&](const std::string& file, const std::string& text) { std::ofstream(dir / file) << text; };
    write("optics/Lens.cpp", "int lens;\n");
    write("renderer/raytracer/cameras/Trace.cpp", "int trace;\n");
    const auto digests = [&] {
        const std::string out = (dir / "SourceDigests.h").string();
        const std::string command = "cmake -DSOURCE_DIR=" + dir.string() + " -DOUTPUT=" + out + " -P " +
                                    std::string(LENSLAB_SOURCE_DIR) + "/report/SourceDigests.cmake";
        EXPECT_EQ(std::system(command.c_str()), 0) << command;
        std::ifstream in(out);
        const std::string text{std::istreambuf_iterator<char>(in), {}};
        std::vector<std::string> found;
        const std::regex digest("\"([0-9a-f]{64})\"");
        for (auto it = std::sregex_iterator(text.begin(), text.end(), digest); it != std::sregex_iterator(); ++it)
            found.push_back((*it)[1]);
        return found;
    };
    const std::vector<std::string> before = digests();
    ASSERT_EQ(before.size(), std::size_t(kCodeParts));
    write("renderer/raytracer/cameras/Trace.cpp", "int trace = 1;\n");
    const std::vector<std::string> after = digests();
    ASSERT_EQ(after.size(), std::size_t(kCodeParts));
    for (int i = 0; i < kCodeParts; ++i) {
        if (i == int(CodePart::Raytracer)) EXPECT_NE(after[i], before[i]);
        else EXPECT_EQ(after[i], before[i]) << i;
    }
    fs::remove_all(dir);
}
