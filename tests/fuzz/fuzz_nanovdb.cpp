// libFuzzer target: the NanoVDB reader (renderer/raytracer/media/NanoVdbFile.cpp) on the input as a
// file, and on a valid file (written by the tests' writer: a root tile, an upper node, two lower
// nodes, leaves and tiles) damaged as the input says: its first byte picks a truncation (odd: cut
// at the next four bytes' length), then each five bytes XOR one byte (four bytes position, one
// value). Refusals must be NanoVdbError naming the file; an accepted grid must look up finite values.
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "FuzzCheck.h"
#include "NanoVdbTestFile.h"
#include "media/NanoVdbFile.h"

using namespace lenslab;
using lenslab::fuzz::check;

namespace {

const std::string& baseFile() {
    static const std::string file = [] {
        test::NanoVdbTestGrid g;
        g.voxels = {{{0, 0, 0}, 1}, {{7, 1, 2}, 5}, {{8, 1, 2}, 7}, {{130, 5, 5}, 0.25f}};
        g.tiles = {{{16, 16, 16}, 1, 0.5f}, {{256, 0, 0}, 2, 0.125f}};
        g.matrix[0][0] = 0.5;
        return test::nanoVdbFile({g});
    }();
    return file;
}

void readAndLookUp(const std::string& bytes) {
    std::istringstream in(bytes);
    try {
        const auto grid = readNanoVdbGrid(in, "density", "fuzz.nvdb");
        if (!grid) return;
        check(std::isfinite(grid->smallest) && std::isfinite(grid->largest), "finite extremes");
        for (int i = -2; i < 140; i += 3)
            for (int j = -2; j < 10; j += 3) check(std::isfinite(grid->interpolate(i + 0.3, j + 0.6, 2.5)), "finite lookups");
    } catch (const NanoVdbError& e) {
        check(std::string(e.what()).rfind("fuzz.nvdb: ", 0) == 0, "a refusal names the file");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    readAndLookUp(std::string(reinterpret_cast<const char*>(data), size));
    if (size == 0) return 0;
    std::string damaged = baseFile();
    std::size_t at = 1;
    if ((data[0] & 1) && size >= 5) {
        std::uint32_t length;
        std::memcpy(&length, data + 1, 4);
        damaged.resize(length % (damaged.size() + 1));
        at = 5;
    }
    for (; at + 5 <= size && !damaged.empty(); at += 5) {
        std::uint32_t position;
        std::memcpy(&position, data + at, 4);
        damaged[position % damaged.size()] ^= char(data[at + 4]);
    }
    readAndLookUp(damaged);
    return 0;
}
