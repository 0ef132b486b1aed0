#pragma once
// A float grid read from a NanoVDB file (.nvdb, the format of OpenVDB's NanoVDB, major version 32),
// as pbrt-v4's "nanovdb" medium uses it. The file's tree keeps its shape here, its links turned
// from byte offsets into indices: root tiles of 4096^3 voxels, each a constant or an upper node of
// 32^3 entries (128^3 voxels each), each entry a constant or a lower node of 16^3 entries (8^3
// voxels each), each a constant or a leaf of 8^3 voxel values. Every offset and size in the file
// is checked before use: a truncated or corrupted file is a NanoVdbError, never a crash.
//
// Layout (from NanoVDB.h and io/IO.h of OpenVDB, read for the format only): a file is segments, each
// a 16-byte header (magic "NanoVDB0" or "NanoVDB2", version, grid count, codec), one 176-byte record
// and name per grid, then the grids' buffers in order. A buffer is GridData (672 bytes: name,
// index-to-world map, type, class), TreeData (64 bytes: offsets to the node arrays), the root (64
// bytes and 32 per tile), then upper, lower and leaf nodes. All little-endian.
#include <array>
#include <cstdint>
#include <istream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace lenslab {

// "FILE: problem".
class NanoVdbError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct NanoVdbGrid {
    std::string name;
    // Index space (voxel centres at integer coordinates) to the grid's world space: x_world =
    // m * x_index + t, rows of [m | t].
    std::array<std::array<double, 4>, 3> indexToWorld{};
    // The active voxels' bounding box in index space, both ends inclusive (NanoVDB's root bbox).
    std::array<int, 3> activeMin{}, activeMax{};
    float background = 0;  // the value of every voxel no node or tile holds
    float smallest = 0, largest = 0;  // over every stored value and the background

    struct RootTile {
        uint64_t key = 0;  // NanoVDB's root key: each coordinate's top 20 bits, x highest
        int32_t upper = -1;  // index of its upper node, or -1: a constant tile
        float value = 0;
    };
    std::vector<RootTile> root;  // sorted by key
    // Per node, one entry per child slot: the child's index or -1, and the constant of a slot
    // without a child. Upper nodes 32^3 slots, lower nodes 16^3.
    std::vector<int32_t> upperChild, lowerChild;
    std::vector<float> upperValue, lowerValue;
    std::vector<float> leafValues;  // 8^3 per leaf, z fastest

    // The stored value of voxel (i, j, k): inactive voxels keep theirs, as in NanoVDB.
    float voxel(int i, int j, int k) const;
    // The aligned 8^3 block of voxels around (i, j, k): its leaf's 512 values (x slowest, z
    // fastest), or null when a tile or the background gives the whole block `constant`.
    const float* block(int i, int j, int k, float& constant) const;
    // Trilinear between voxel centres at index-space point (x, y, z).
    float interpolate(double x, double y, double z) const;
};

constexpr int kNanoVdbUpperSlots = 32 * 32 * 32, kNanoVdbLowerSlots = 16 * 16 * 16, kNanoVdbLeafVoxels = 8 * 8 * 8;

// The float grid named gridName in the file, or nullopt when the file has no grid of that name.
// Throws NanoVdbError naming `label` (the file) for anything this reader does not accept: not a
// NanoVDB file, another major version, a compressed (ZIP, Blosc) segment, a grid that is not float
// or not a fog volume, truncation, offsets outside the buffer, values that are not finite.
std::optional<NanoVdbGrid> readNanoVdbGrid(std::istream& in, const std::string& gridName, const std::string& label);
std::optional<NanoVdbGrid> readNanoVdbFile(const std::string& path, const std::string& gridName);

}  // namespace lenslab
