// `mpirun -np 3 lenslab render --mpi` on loopback: the image equals the single-process render bit
// for bit (same seed); a worker that dies has its tile re-queued when mpirun allows the job to go
// on (--enable-recovery), and otherwise the run fails naming the rank and leaves no image.
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct CommandResult {
    int exitCode = -1;
    std::string output;  // stdout and stderr
};

// Through the shell for the redirection; every path here is the test's own. `timeout` bounds it.
CommandResult run(const std::string& command, const fs::path& log) {
    const std::string line = "timeout -k 5 90 " + command + " > '" + log.string() + "' 2>&1";
    const int status = std::system(line.c_str());
    CommandResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(log);
    std::ostringstream text;
    text << in.rdbuf();
    r.output = text.str();
    return r;
}

std::vector<float> readExrRgb(const fs::path& path) {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i dw = file.header().dataWindow();
    const int width = dw.max.x - dw.min.x + 1, height = dw.max.y - dw.min.y + 1;
    std::vector<float> rgb(std::size_t(width) * height * 3);
    Imf::FrameBuffer fb;
    const std::size_t xStride = 3 * sizeof(float), yStride = xStride * width;
    char* base = reinterpret_cast<char*>(rgb.data()) - (dw.min.x * xStride + dw.min.y * yStride);
    for (int c = 0; c < 3; ++c)
        fb.insert(c == 0 ? "R" : c == 1 ? "G" : "B", Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xStride, yStride));
    file.setFrameBuffer(fb);
    file.readPixels(dw.min.y, dw.max.y);
    return rgb;
}

class MpiRender : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("lenslab-mpi-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(dir_);
    }

    // The render arguments shared by the single-process and the MPI runs.
    static std::string renderArgs(const std::string& size) {
        return std::string(" render ") + LENSLAB_SOURCE_DIR + "/scenes/shared-dgauss.pbrt --tile 8 --seed 7 " + size;
    }
    CommandResult single(const std::string& size, const fs::path& out) {
        return run(std::string(LENSLAB_BINARY) + renderArgs(size) + " --quiet -o '" + out.string() + "'", dir_ / "single.log");
    }
    CommandResult mpirun(const std::string& mpiOptions, const std::string& size, const std::string& renderOptions) {
        return run(std::string(LENSLAB_MPIEXEC) + " --oversubscribe --allow-run-as-root --bind-to none " + mpiOptions +
                       " -np 3 " + LENSLAB_BINARY + renderArgs(size) + " --mpi " + renderOptions,
                   dir_ / "mpi.log");
    }

    fs::path dir_;
};

TEST_F(MpiRender, ThreeProcessesGiveTheSingleProcessImageBitForBit) {
    const std::string size = "--spp 2 --width 64 --height 48";
    const CommandResult one = single(size, dir_ / "single.exr");
    ASSERT_EQ(one.exitCode, 0) << one.output;
    const CommandResult mpi = mpirun("", size, "--progress-json -o '" + (dir_ / "mpi.exr").string() + "'");
    ASSERT_EQ(mpi.exitCode, 0) << mpi.output;
    EXPECT_EQ(readExrRgb(dir_ / "mpi.exr"), readExrRgb(dir_ / "single.exr"));
    EXPECT_NE(mpi.output.find("{\"tilesDone\":48,\"tilesTotal\":48,"), std::string::npos) << mpi.output;
}

// Through a dispersive lens the frame is spectral; with several wavelengths a sample, samples leave
// splats in other pixels, other tiles' included, which the workers send with their tiles.
TEST_F(MpiRender, ThreeProcessesGiveTheSingleProcessSpectralImageBitForBit) {
    const std::string size = std::string("--spp 2 --width 64 --height 48 --wavelengths-per-sample 3 --lens ") +
                             LENSLAB_SOURCE_DIR + "/lenses/dgauss-glass.dat";
    const CommandResult one = single(size, dir_ / "single.exr");
    ASSERT_EQ(one.exitCode, 0) << one.output;
    const CommandResult mpi = mpirun("", size, "-o '" + (dir_ / "mpi.exr").string() + "'");
    ASSERT_EQ(mpi.exitCode, 0) << mpi.output;
    EXPECT_EQ(readExrRgb(dir_ / "mpi.exr"), readExrRgb(dir_ / "single.exr"));
}

// Worker rank 2 kills itself (test hook) when handed its second tile; enough tiles that it gets one.
const std::string kKillHook = " -x LENSLAB_MPI_TEST_KILL_RANK=2 -x LENSLAB_MPI_TEST_KILL_AFTER_TILES=1";
const std::string kKillSize = "--spp 32 --width 96 --height 72";

TEST_F(MpiRender, DeadWorkersTileIsRequeuedWhenMpirunKeepsTheJob) {
    const CommandResult one = single(kKillSize, dir_ / "single.exr");
    ASSERT_EQ(one.exitCode, 0) << one.output;
    const CommandResult mpi = mpirun("--enable-recovery" + kKillHook, kKillSize, "--mpi-timeout 3 -o '" + (dir_ / "mpi.exr").string() + "'");
    ASSERT_EQ(mpi.exitCode, 0) << mpi.output;
    EXPECT_NE(mpi.output.find("MPI worker rank 2"), std::string::npos) << mpi.output;
    EXPECT_NE(mpi.output.find("goes back to the queue"), std::string::npos) << mpi.output;
    EXPECT_EQ(readExrRgb(dir_ / "mpi.exr"), readExrRgb(dir_ / "single.exr"));
}

TEST_F(MpiRender, DeadWorkerFailsTheRunWithoutAnImageByDefault) {
    const CommandResult mpi = mpirun(kKillHook, kKillSize, "-o '" + (dir_ / "mpi.exr").string() + "' -o '" + (dir_ / "mpi.png").string() + "'");
    EXPECT_NE(mpi.exitCode, 0) << mpi.output;
    EXPECT_NE(mpi.output.find("rank 2"), std::string::npos) << mpi.output;
    EXPECT_NE(mpi.output.find("no image was written"), std::string::npos) << mpi.output;
    for (const auto& entry : fs::directory_iterator(dir_))
        EXPECT_EQ(entry.path().extension(), ".log") << "left behind: " << entry.path();
}

}  // namespace
