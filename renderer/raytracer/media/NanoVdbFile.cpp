#include "media/NanoVdbFile.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <unordered_map>

namespace lenslab {

namespace {

// "NanoVDB0" (files and grids before 32.6), "NanoVDB1" (grids), "NanoVDB2" (files), read as
// little-endian 64-bit words.
constexpr uint64_t kMagicOld = 0x304244566f6e614eULL, kMagicGrid = 0x314244566f6e614eULL,
                   kMagicFile = 0x324244566f6e614eULL;
constexpr uint32_t kMajorVersion = 32;
constexpr uint16_t kCodecNone = 0;
constexpr uint32_t kGridTypeFloat = 1;
constexpr uint32_t kClassUnknown = 0, kClassFogVolume = 2;

// Byte sizes and field offsets of NanoVDB 32's structures (float grids).
constexpr uint64_t kFileHeaderSize = 16, kGridRecordSize = 176;
constexpr uint64_t kGridDataSize = 672, kMapOffset = 296, kGridClassOffset = 632, kGridTypeOffset = 636;
constexpr uint64_t kRootHeaderSize = 64, kRootTileSize = 32;
constexpr uint64_t kUpperChildMask = 4128, kUpperTable = 8256, kUpperSize = kUpperTable + 8 * kNanoVdbUpperSlots;
constexpr uint64_t kLowerChildMask = 544, kLowerTable = 1088, kLowerSize = kLowerTable + 8 * kNanoVdbLowerSlots;
constexpr uint64_t kLeafValues = 96, kLeafSize = kLeafValues + 4 * kNanoVdbLeafVoxels;
// Grid names longer than this are not NanoVDB's (its long names live in blind data).
constexpr uint32_t kMaxNameSize = 1 << 16;

[[noreturn]] void fail(const std::string& label, const std::string& problem) {
    throw NanoVdbError(label + ": " + problem);
}

std::string versionText(uint32_t v) {
    return std::to_string(v >> 21) + "." + std::to_string((v >> 10) & 2047) + "." + std::to_string(v & 1023);
}

// Little-endian reads from a byte buffer; any read past its end fails naming what was read.
class Bytes {
public:
    Bytes(const std::string& bytes, std::string label) : bytes_(bytes), label_(std::move(label)) {}
    uint64_t size() const { return bytes_.size(); }
    const std::string& label() const { return label_; }
    void need(uint64_t offset, uint64_t count, const char* what) const {
        if (offset > size() || count > size() - offset)
            fail(label_, std::string("truncated or corrupt: ") + what + " at byte " + std::to_string(offset) + " needs " +
                             std::to_string(count) + " bytes, the buffer has " + std::to_string(size()));
    }
    template <class T>
    T at(uint64_t offset, const char* what) const {
        need(offset, sizeof(T), what);
        T v;
        std::memcpy(&v, bytes_.data() + offset, sizeof(T));
        return v;
    }
    bool bit(uint64_t maskOffset, uint32_t n) const {
        return (uint8_t(bytes_[maskOffset + (n >> 3)]) >> (n & 7)) & 1;  // callers checked the mask's bytes
    }

private:
    const std::string& bytes_;
    std::string label_;
};

// Where a child lies: its node's offset plus a signed link, 32-byte aligned as NanoVDB lays nodes
// out, inside the buffer with its whole size.
uint64_t childOffset(const Bytes& b, uint64_t node, int64_t link, uint64_t childSize, const char* what) {
    const bool beforeStart = link < 0 && uint64_t(-(link + 1)) >= node;  // -link > node, without overflow
    const uint64_t offset = beforeStart ? 0 : link < 0 ? node - uint64_t(-(link + 1)) - 1 : node + uint64_t(link);
    if (beforeStart || offset % 32 != 0)
        fail(b.label(), std::string("corrupt: ") + what + " linked from byte " + std::to_string(node) + " at " +
                            std::to_string(link) + " bytes lies outside the buffer or off NanoVDB's 32-byte alignment");
    b.need(offset, childSize, what);
    return offset;
}

// The tree of one grid buffer into NanoVdbGrid. A node linked from several places is read once.
class TreeReader {
public:
    TreeReader(const Bytes& b, NanoVdbGrid& g) : b_(b), g_(g) {}

    float value(uint64_t offset, const char* what) {
        const float v = b_.at<float>(offset, what);
        if (!std::isfinite(v)) fail(b_.label(), std::string("non-finite value in ") + what + " at byte " + std::to_string(offset));
        g_.smallest = std::min(g_.smallest, v);
        g_.largest = std::max(g_.largest, v);
        return v;
    }

    int32_t upper(uint64_t offset) {
        return node(upperIndex_, offset, kUpperSize, "upper node", [&](uint64_t at) {
            readTable(at, kUpperChildMask, kUpperTable, kNanoVdbUpperSlots, g_.upperChild, g_.upperValue,
                      [&](uint64_t child) { return lower(child); });
        });
    }

private:
    int32_t lower(uint64_t offset) {
        return node(lowerIndex_, offset, kLowerSize, "lower node", [&](uint64_t at) {
            readTable(at, kLowerChildMask, kLowerTable, kNanoVdbLowerSlots, g_.lowerChild, g_.lowerValue,
                      [&](uint64_t child) { return leaf(child); });
        });
    }
    int32_t leaf(uint64_t offset) {
        return node(leafIndex_, offset, kLeafSize, "leaf", [&](uint64_t at) {
            for (int i = 0; i < kNanoVdbLeafVoxels; ++i) g_.leafValues.push_back(value(at + kLeafValues + 4 * i, "a leaf"));
        });
    }

    // The index of the node at offset among those of its level, reading it if new.
    template <class Read>
    int32_t node(std::unordered_map<uint64_t, int32_t>& index, uint64_t offset, uint64_t size, const char* what, Read read) {
        const auto it = index.find(offset);
        if (it != index.end()) return it->second;
        b_.need(offset, size, what);
        // Aligned nodes that do not overlap: what a corrupt file's links could claim beyond that
        // would be memory out of all proportion to the file.
        if (index.size() >= b_.size() / size) fail(b_.label(), std::string("corrupt: more ") + what + "s than the buffer holds");
        const int32_t n = int32_t(index.size());
        index.emplace(offset, n);
        read(offset);
        return n;
    }

    // An internal node's table: per slot a child (its link, 8 bytes) or a value (4 bytes).
    template <class Child>
    void readTable(uint64_t at, uint64_t maskAt, uint64_t tableAt, int slots, std::vector<int32_t>& children,
                   std::vector<float>& values, Child child) {
        const std::size_t first = children.size();
        children.resize(first + slots, -1);
        values.resize(first + slots, 0);
        for (int n = 0; n < slots; ++n) {
            const uint64_t entry = at + tableAt + 8 * uint64_t(n);
            if (b_.bit(at + maskAt, n)) {
                const int64_t link = b_.at<int64_t>(entry, "a child link");
                const int32_t c = child(childOffset(b_, at, link, 1, "a child node"));
                children[first + n] = c;  // not a reference: child() grows other vectors only
            } else {
                values[first + n] = value(entry, "a tile value");
            }
        }
    }

    const Bytes& b_;
    NanoVdbGrid& g_;
    std::unordered_map<uint64_t, int32_t> upperIndex_, lowerIndex_, leafIndex_;
};

void readMap(const Bytes& b, NanoVdbGrid& g) {
    // Map: 9 floats, 9 inverse floats, 3 + 1 floats, then 9 doubles (the matrix, row-major), 9 for
    // its inverse, 3 for the translation.
    const uint64_t matrix = kMapOffset + 88, translation = matrix + 144;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) g.indexToWorld[r][c] = b.at<double>(matrix + 8 * (3 * r + c), "the grid's map");
        g.indexToWorld[r][3] = b.at<double>(translation + 8 * r, "the grid's map");
    }
    const auto& m = g.indexToWorld;
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    for (const auto& row : m)
        for (double v : row)
            if (!std::isfinite(v)) fail(b.label(), "the grid's index-to-world map is not finite");
    if (!(std::abs(det) > 1e-300) || !std::isfinite(det)) fail(b.label(), "the grid's index-to-world map is singular");
}

NanoVdbGrid readGridBuffer(const Bytes& b, const std::string& name) {
    NanoVdbGrid g;
    g.name = name;
    const uint64_t magic = b.at<uint64_t>(0, "the grid's magic number");
    if (magic != kMagicOld && magic != kMagicGrid) fail(b.label(), "grid \"" + name + "\" does not start with NanoVDB's magic number");
    const uint32_t version = b.at<uint32_t>(16, "the grid's version");
    if (version >> 21 != kMajorVersion)
        fail(b.label(), "grid \"" + name + "\" is NanoVDB " + versionText(version) + " (this reader reads version 32)");
    const uint32_t type = b.at<uint32_t>(kGridTypeOffset, "the grid's type");
    if (type != kGridTypeFloat)
        fail(b.label(), "grid \"" + name + "\" holds values of NanoVDB type " + std::to_string(type) + ", not float (1)");
    const uint32_t gridClass = b.at<uint32_t>(kGridClassOffset, "the grid's class");
    if (gridClass != kClassFogVolume && gridClass != kClassUnknown)
        fail(b.label(), "grid \"" + name + "\" is of NanoVDB class " + std::to_string(gridClass) +
                            ", not a fog volume (2): a level set is no density");
    readMap(b, g);

    const int64_t rootLink = b.at<int64_t>(kGridDataSize + 24, "the tree's root offset");
    const uint64_t root = childOffset(b, kGridDataSize, rootLink, kRootHeaderSize, "the root node");
    for (int a = 0; a < 3; ++a) {
        g.activeMin[a] = b.at<int32_t>(root + 4 * a, "the root's bounding box");
        g.activeMax[a] = b.at<int32_t>(root + 12 + 4 * a, "the root's bounding box");
    }
    const uint32_t tiles = b.at<uint32_t>(root + 24, "the root's tile count");
    b.need(root + kRootHeaderSize, uint64_t(tiles) * kRootTileSize, "the root's tiles");
    TreeReader tree(b, g);
    g.smallest = INFINITY;
    g.largest = -INFINITY;
    g.background = tree.value(root + 28, "the background");
    for (uint32_t i = 0; i < tiles; ++i) {
        const uint64_t tile = root + kRootHeaderSize + uint64_t(i) * kRootTileSize;
        NanoVdbGrid::RootTile t;
        t.key = b.at<uint64_t>(tile, "a root tile");
        const int64_t link = b.at<int64_t>(tile + 8, "a root tile");
        if (link != 0)
            t.upper = tree.upper(childOffset(b, root, link, 1, "an upper node"));
        else
            t.value = tree.value(tile + 20, "a root tile");
        g.root.push_back(t);
    }
    std::stable_sort(g.root.begin(), g.root.end(), [](const auto& x, const auto& y) { return x.key < y.key; });
    g.root.erase(std::unique(g.root.begin(), g.root.end(), [](const auto& x, const auto& y) { return x.key == y.key; }),
                 g.root.end());
    return g;
}

// `count` bytes at `offset` of the stream, whose size is `size`.
std::string readAt(std::istream& in, uint64_t offset, uint64_t count, uint64_t size, const std::string& label,
                   const char* what) {
    if (offset > size || count > size - offset)
        fail(label, std::string("truncated: ") + what + " at byte " + std::to_string(offset) + " needs " +
                        std::to_string(count) + " bytes, the file has " + std::to_string(size));
    std::string bytes(count, '\0');
    in.clear();
    in.seekg(std::streamoff(offset));
    if (!in.read(bytes.data(), std::streamsize(count))) fail(label, std::string("cannot read ") + what);
    return bytes;
}

template <class T>
T field(const std::string& bytes, uint64_t offset) {
    T v;
    std::memcpy(&v, bytes.data() + offset, sizeof(T));
    return v;
}

const char* codecName(uint16_t codec) { return codec == 1 ? "ZIP" : codec == 2 ? "Blosc" : "unknown"; }

}  // namespace

std::optional<NanoVdbGrid> readNanoVdbGrid(std::istream& in, const std::string& gridName, const std::string& label) {
    in.clear();
    in.seekg(0, std::ios::end);
    const std::streamoff end = in.tellg();
    if (end < 0) fail(label, "cannot read the file");
    const uint64_t size = uint64_t(end);
    if (size == 0) fail(label, "empty file, not NanoVDB");
    uint64_t segment = 0;
    while (segment < size) {
        const std::string header = readAt(in, segment, kFileHeaderSize, size, label, "a segment header");
        const uint64_t magic = field<uint64_t>(header, 0);
        if (magic == kMagicGrid) fail(label, "a raw NanoVDB grid buffer, not a .nvdb file with grid records (unsupported)");
        if (magic != kMagicOld && magic != kMagicFile) fail(label, "not a NanoVDB file (no \"NanoVDB\" magic number at byte " + std::to_string(segment) + ")");
        const uint32_t version = field<uint32_t>(header, 8);
        if (version >> 21 != kMajorVersion)
            fail(label, "NanoVDB file version " + versionText(version) + " is not supported (this reader reads version 32)");
        const uint16_t gridCount = field<uint16_t>(header, 12), codec = field<uint16_t>(header, 14);
        if (gridCount == 0) fail(label, "a segment with no grids at byte " + std::to_string(segment));
        struct Record {
            std::string name;
            uint64_t gridSize, fileSize;
        };
        std::vector<Record> records;
        uint64_t at = segment + kFileHeaderSize;
        for (int i = 0; i < gridCount; ++i) {
            const std::string r = readAt(in, at, kGridRecordSize, size, label, "a grid record");
            const uint32_t nameSize = field<uint32_t>(r, 136);
            if (nameSize > kMaxNameSize) fail(label, "a grid name of " + std::to_string(nameSize) + " bytes");
            const std::string name = readAt(in, at + kGridRecordSize, nameSize, size, label, "a grid name");
            records.push_back({name.substr(0, name.find('\0')), field<uint64_t>(r, 0), field<uint64_t>(r, 8)});
            at += kGridRecordSize + nameSize;
        }
        for (const Record& r : records) {
            if (r.name == gridName) {
                if (codec != kCodecNone)
                    fail(label, "grid \"" + gridName + "\" is compressed with " + codecName(codec) +
                                    " (unsupported: write the file with codec NONE, e.g. nanovdb_convert without -z/-b)");
                if (r.fileSize != r.gridSize) fail(label, "grid \"" + gridName + "\" has different sizes in memory and on disk");
                if (r.gridSize < kGridDataSize + 64) fail(label, "grid \"" + gridName + "\" is too small to hold a tree");
                const std::string buffer = readAt(in, at, r.gridSize, size, label, "a grid");
                return readGridBuffer(Bytes(buffer, label), gridName);
            }
            if (at > size || r.fileSize > size - at)
                fail(label, "truncated: grid \"" + r.name + "\" at byte " + std::to_string(at) + " needs " +
                                std::to_string(r.fileSize) + " bytes, the file has " + std::to_string(size));
            at += r.fileSize;
        }
        segment = at;
    }
    return std::nullopt;
}

std::optional<NanoVdbGrid> readNanoVdbFile(const std::string& path, const std::string& gridName) {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail(path, "cannot open");
    return readNanoVdbGrid(in, gridName, path);
}

const float* NanoVdbGrid::block(int i, int j, int k, float& constant) const {
    const uint64_t key = (uint64_t(uint32_t(i) >> 12) << 42) | (uint64_t(uint32_t(j) >> 12) << 21) | uint64_t(uint32_t(k) >> 12);
    const auto tile = std::lower_bound(root.begin(), root.end(), key, [](const RootTile& t, uint64_t k) { return t.key < k; });
    constant = background;
    if (tile == root.end() || tile->key != key) return nullptr;
    constant = tile->value;
    if (tile->upper < 0) return nullptr;
    const std::size_t u = std::size_t(tile->upper) * kNanoVdbUpperSlots + (((i & 4095) >> 7) << 10 | ((j & 4095) >> 7) << 5 | ((k & 4095) >> 7));
    constant = upperValue[u];
    if (upperChild[u] < 0) return nullptr;
    const std::size_t l = std::size_t(upperChild[u]) * kNanoVdbLowerSlots + (((i & 127) >> 3) << 8 | ((j & 127) >> 3) << 4 | ((k & 127) >> 3));
    constant = lowerValue[l];
    if (lowerChild[l] < 0) return nullptr;
    return &leafValues[std::size_t(lowerChild[l]) * kNanoVdbLeafVoxels];
}

float NanoVdbGrid::voxel(int i, int j, int k) const {
    float constant;
    const float* leaf = block(i, j, k, constant);
    return leaf ? leaf[(i & 7) << 6 | (j & 7) << 3 | (k & 7)] : constant;
}

float NanoVdbGrid::interpolate(double x, double y, double z) const {
    constexpr double kFar = 1 << 30;  // beyond any NanoVDB coordinate; keeps the int conversions defined
    if (!(std::abs(x) < kFar && std::abs(y) < kFar && std::abs(z) < kFar)) return background;
    const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
    const int i = int(fx), j = int(fy), k = int(fz);
    const float tx = float(x - fx), ty = float(y - fy), tz = float(z - fz);
    const auto weight = [&](int dx, int dy, int dz) { return (dx ? tx : 1 - tx) * (dy ? ty : 1 - ty) * (dz ? tz : 1 - tz); };
    float sum = 0;
    if ((i & 7) != 7 && (j & 7) != 7 && (k & 7) != 7) {
        // The eight corners share one aligned 8^3 block (7 in 8 lookups per axis): one descent.
        float constant;
        const float* leaf = block(i, j, k, constant);
        const int first = (i & 7) << 6 | (j & 7) << 3 | (k & 7);
        for (int corner = 0; corner < 8; ++corner) {
            const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
            sum += weight(dx, dy, dz) * (leaf ? leaf[first + (dx << 6 | dy << 3 | dz)] : constant);
        }
        return sum;
    }
    for (int corner = 0; corner < 8; ++corner) {
        const int dx = corner & 1, dy = (corner >> 1) & 1, dz = corner >> 2;
        const float w = weight(dx, dy, dz);
        if (w > 0) sum += w * voxel(i + dx, j + dy, k + dz);
    }
    return sum;
}

}  // namespace lenslab
