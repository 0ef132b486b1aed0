// `lenslab diagram`: options reach the picture, and bad arguments are usage errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>

#include "ArgParser.h"
#include "Commands.h"
#include "DiagramTestSupport.h"

namespace lenslab::test {
namespace {

std::string lensPath(const std::string& stem) { return std::string(LENSLAB_SOURCE_DIR) + "/lenses/" + stem + ".dat"; }

TEST(DiagramCommand, WritesThePngAtTheRequestedSize) {
    const std::string out = ::testing::TempDir() + "lenslab_diagram_command.png";
    ASSERT_EQ(runDiagramCommand({lensPath("telephoto.250mm"), "-o", out, "--mode", "thick", "--fstop", "8", "--focus",
                                 "5000", "--field", "10", "--rays", "5", "--size", "640x320", "--backend", "osmesa"}),
              0);
    std::ifstream file(out, std::ios::binary);
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    const RgbaImage image = decodePng(bytes);
    EXPECT_EQ(image.width, 640);
    EXPECT_EQ(image.height, 320);
    std::remove(out.c_str());
}

TEST(DiagramCommand, BadArgumentsAreUsageErrors) {
    const std::string lens = lensPath("dgauss.50mm");
    EXPECT_THROW(runDiagramCommand({lens}), UsageError);                                    // no -o
    EXPECT_THROW(runDiagramCommand({lens, "-o", "x.png", "--size", "big"}), UsageError);    // not WxH
    EXPECT_THROW(runDiagramCommand({lens, "-o", "x.png", "--rays", "0"}), UsageError);
    EXPECT_THROW(runDiagramCommand({lens, "-o", "x.png", "--fstop", "fast"}), UsageError);
    EXPECT_THROW(runDiagramCommand({lens, "-o", "x.png", "--mode", "sketch"}), DiagramError);
}

}  // namespace
}  // namespace lenslab::test
