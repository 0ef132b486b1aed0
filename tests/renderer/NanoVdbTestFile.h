#pragma once
// Writes small NanoVDB files (.nvdb, version 32.3.3, codec NONE) for the reader's tests: float
// grids from a list of voxels and constant tiles, laid out as NanoVDB lays them out (grid, tree,
// root and its tiles, upper, lower and leaf nodes in that order, offsets relative to each node),
// with the fields the reader does not use filled in as NanoVDB would. Written from the format's
// description (NanoVDB.h, io/IO.h), independently of the reader.
#include <array>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace lenslab::test {

using Coord = std::array<int, 3>;

struct NanoVdbTestGrid {
    std::string name = "density";
    std::map<Coord, float> voxels;  // active voxels, in leaves
    // Constant tiles: level 1 an 8^3 tile in a lower node, 2 a 128^3 tile in an upper node, 3 a
    // 4096^3 root tile; origin is any voxel inside it.
    struct Tile {
        Coord origin;
        int level;
        float value;
    };
    std::vector<Tile> tiles;
    float background = 0;
    double matrix[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // index to world, row-major
    double translation[3] = {0, 0, 0};
    uint32_t type = 1;       // float
    uint32_t gridClass = 2;  // fog volume
};

constexpr uint32_t kNanoVdbTestVersion = (32u << 21) | (3u << 10) | 3u;

namespace nanovdb_writer {

template <class T>
void put(std::string& b, std::size_t at, T v) {
    if (b.size() < at + sizeof(T)) b.resize(at + sizeof(T), '\0');
    std::memcpy(&b[at], &v, sizeof(T));
}

inline void setBit(std::string& b, std::size_t maskAt, int n) { b[maskAt + n / 8] = char(uint8_t(b[maskAt + n / 8]) | (1u << (n % 8))); }

// Node slots: x slowest, z fastest, as NanoVDB numbers them.
inline int slot(const Coord& c, int childShift, int log2Dim) {
    const int mask = (1 << log2Dim) - 1;
    return (((c[0] >> childShift) & mask) << (2 * log2Dim)) | (((c[1] >> childShift) & mask) << log2Dim) | ((c[2] >> childShift) & mask);
}
inline uint64_t rootKey(const Coord& c) {
    return (uint64_t(uint32_t(c[0]) >> 12) << 42) | (uint64_t(uint32_t(c[1]) >> 12) << 21) | uint64_t(uint32_t(c[2]) >> 12);
}

struct Leaf {
    std::array<float, 512> values{};
    bool filled = false;  // with the background
};
struct Lower {
    std::map<int, Leaf> leaves;
    std::map<int, float> tiles;
};
struct Upper {
    std::map<int, Lower> lowers;
    std::map<int, float> tiles;
};

// The grid buffer alone (GridData onwards).
inline std::string gridBuffer(const NanoVdbTestGrid& g) {
    std::map<uint64_t, Upper> uppers;
    std::map<uint64_t, float> rootTiles;
    Coord lo{1 << 30, 1 << 30, 1 << 30}, hi{-(1 << 30), -(1 << 30), -(1 << 30)};
    auto grow = [&](const Coord& a, int size) {
        for (int i = 0; i < 3; ++i) {
            lo[i] = std::min(lo[i], a[i]);
            hi[i] = std::max(hi[i], a[i] + size - 1);
        }
    };
    auto aligned = [](const Coord& c, int size) { return Coord{c[0] & ~(size - 1), c[1] & ~(size - 1), c[2] & ~(size - 1)}; };
    for (const auto& [c, v] : g.voxels) {
        Leaf& leaf = uppers[rootKey(c)].lowers[slot(c, 7, 5)].leaves[slot(c, 3, 4)];
        if (!leaf.filled) leaf.values.fill(g.background);
        leaf.filled = true;
        leaf.values[slot(c, 0, 3)] = v;
        grow(c, 1);
    }
    for (const auto& t : g.tiles) {
        const int size = t.level == 1 ? 8 : t.level == 2 ? 128 : 4096;
        if (t.level == 3) rootTiles[rootKey(t.origin)] = t.value;
        if (t.level == 2) uppers[rootKey(t.origin)].tiles[slot(t.origin, 7, 5)] = t.value;
        if (t.level == 1) uppers[rootKey(t.origin)].lowers[slot(t.origin, 7, 5)].tiles[slot(t.origin, 3, 4)] = t.value;
        grow(aligned(t.origin, size), size);
    }
    const std::size_t upperSize = 8256 + 8 * 32768, lowerSize = 1088 + 8 * 4096, leafSize = 96 + 4 * 512;
    std::size_t lowerCount = 0, leafCount = 0;
    for (const auto& [k, u] : uppers) {
        lowerCount += u.lowers.size();
        for (const auto& [s, l] : u.lowers) leafCount += l.leaves.size();
    }
    const std::size_t tree = 672, root = tree + 64, tileCount = uppers.size() + rootTiles.size();
    const std::size_t firstUpper = root + 64 + 32 * tileCount, firstLower = firstUpper + upperSize * uppers.size(),
                      firstLeaf = firstLower + lowerSize * lowerCount, total = firstLeaf + leafSize * leafCount;
    std::string b(total, '\0');

    // GridData
    put<uint64_t>(b, 0, 0x304244566f6e614eULL);
    put<uint64_t>(b, 8, ~uint64_t(0));  // checksum disabled
    put<uint32_t>(b, 16, kNanoVdbTestVersion);
    put<uint32_t>(b, 28, 1);  // grid count
    put<uint64_t>(b, 32, total);
    std::memcpy(&b[40], g.name.c_str(), std::min<std::size_t>(g.name.size(), 255));
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            put<float>(b, 296 + 4 * (3 * r + c), float(g.matrix[r][c]));
            put<double>(b, 296 + 88 + 8 * (3 * r + c), g.matrix[r][c]);
        }
        put<float>(b, 296 + 72 + 4 * r, float(g.translation[r]));
        put<double>(b, 296 + 232 + 8 * r, g.translation[r]);
    }
    put<uint32_t>(b, 632, g.gridClass);
    put<uint32_t>(b, 636, g.type);
    put<int64_t>(b, 640, int64_t(total));  // no blind data

    // TreeData: offsets of the first leaf, lower, upper node and the root, from the tree.
    put<int64_t>(b, tree, int64_t(firstLeaf - tree));
    put<int64_t>(b, tree + 8, int64_t(firstLower - tree));
    put<int64_t>(b, tree + 16, int64_t(firstUpper - tree));
    put<int64_t>(b, tree + 24, int64_t(root - tree));
    put<uint32_t>(b, tree + 32, uint32_t(leafCount));
    put<uint32_t>(b, tree + 36, uint32_t(lowerCount));
    put<uint32_t>(b, tree + 40, uint32_t(uppers.size()));
    put<uint64_t>(b, tree + 56, g.voxels.size());

    // Root, its tiles in key order (children and constants interleaved).
    for (int i = 0; i < 3; ++i) {
        put<int32_t>(b, root + 4 * i, lo[i]);
        put<int32_t>(b, root + 12 + 4 * i, hi[i]);
    }
    put<uint32_t>(b, root + 24, uint32_t(tileCount));
    put<float>(b, root + 28, g.background);
    std::map<uint64_t, const Upper*> keyed;
    for (const auto& [k, u] : uppers) keyed[k] = &u;
    for (const auto& [k, v] : rootTiles) keyed.emplace(k, nullptr);
    std::size_t tileAt = root + 64, upperAt = firstUpper, lowerAt = firstLower, leafAt = firstLeaf;
    for (const auto& [key, u] : keyed) {
        put<uint64_t>(b, tileAt, key);
        if (u) {
            put<int64_t>(b, tileAt + 8, int64_t(upperAt - root));
            for (int n = 0; n < 32768; ++n) put<float>(b, upperAt + 8256 + 8 * n, g.background);
            for (const auto& [s, v] : u->tiles) {
                put<float>(b, upperAt + 8256 + 8 * s, v);
                setBit(b, upperAt + 32, s);  // active
            }
            for (const auto& [s, lower] : u->lowers) {
                setBit(b, upperAt + 32 + 4096, s);
                put<int64_t>(b, upperAt + 8256 + 8 * s, int64_t(lowerAt - upperAt));
                for (int n = 0; n < 4096; ++n) put<float>(b, lowerAt + 1088 + 8 * n, g.background);
                for (const auto& [t, v] : lower.tiles) {
                    put<float>(b, lowerAt + 1088 + 8 * t, v);
                    setBit(b, lowerAt + 32, t);
                }
                for (const auto& [t, leaf] : lower.leaves) {
                    setBit(b, lowerAt + 32 + 512, t);
                    put<int64_t>(b, lowerAt + 1088 + 8 * t, int64_t(leafAt - lowerAt));
                    for (int n = 0; n < 512; ++n) put<float>(b, leafAt + 96 + 4 * n, leaf.values[n]);
                    leafAt += leafSize;
                }
                lowerAt += lowerSize;
            }
            upperAt += upperSize;
        } else {
            put<uint32_t>(b, tileAt + 16, 1);  // active
            put<float>(b, tileAt + 20, rootTiles.at(key));
        }
        tileAt += 32;
    }
    return b;
}

}  // namespace nanovdb_writer

// A file of one segment holding the grids. codec is written into the header and the records only
// (the buffers stay uncompressed: enough to test that the reader refuses a codec).
inline std::string nanoVdbFile(const std::vector<NanoVdbTestGrid>& grids, uint16_t codec = 0,
                               uint32_t version = kNanoVdbTestVersion) {
    using nanovdb_writer::put;
    std::string f;
    put<uint64_t>(f, 0, 0x304244566f6e614eULL);
    put<uint32_t>(f, 8, version);
    put<uint16_t>(f, 12, uint16_t(grids.size()));
    put<uint16_t>(f, 14, codec);
    std::vector<std::string> buffers;
    for (const auto& g : grids) {
        buffers.push_back(nanovdb_writer::gridBuffer(g));
        const std::size_t at = f.size();
        put<uint64_t>(f, at, buffers.back().size());      // in memory
        put<uint64_t>(f, at + 8, buffers.back().size());  // on disk
        put<uint64_t>(f, at + 24, g.voxels.size());
        put<uint32_t>(f, at + 32, g.type);
        put<uint32_t>(f, at + 36, g.gridClass);
        put<uint32_t>(f, at + 136, uint32_t(g.name.size() + 1));
        put<uint16_t>(f, at + 168, codec);
        put<uint32_t>(f, at + 172, version);
        f += g.name;
        f += '\0';
    }
    for (const auto& b : buffers) f += b;
    return f;
}

}  // namespace lenslab::test
