#include "storage/LensStore.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <mutex>

#include "storage/AtomicFile.h"
#include "core/Identifiers.h"
#include "prescription/OpticsError.h"
#include "storage/StorageError.h"
#include "core/WallClock.h"

namespace lenslab {

namespace fs = std::filesystem;

namespace {

std::string printableText(const std::string& text);

// Builds the geometry and the widest-aperture, infinity-focus data every listing shows.
std::shared_ptr<StoredLens> describeLens(const LensTable& table) {
    auto lens = std::make_shared<StoredLens>();
    lens->system = buildLensSystem(table);
    const LensAnalysis a = analyzeLens(lens->system, std::nullopt, std::numeric_limits<double>::infinity());
    lens->efl = a.firstOrder.efl;
    lens->fstopMin = a.aperture.fstopMin;
    lens->fstopMax = a.aperture.fstopMax;
    if (!table.comments.empty()) {
        std::string d = table.comments.front();
        d.erase(0, d.find_first_not_of(' '));
        lens->description = printableText(d);
    }
    return lens;
}

constexpr std::size_t kDisplayNameCharacters = 64;

// Bytes of the well-formed UTF-8 sequence starting at `at` (1 for ASCII), 0 when it is malformed
// (stray continuation byte, truncated, overlong, surrogate or beyond U+10FFFF).
std::size_t utf8SequenceLength(const std::string& text, std::size_t at) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(at);
    if (lead < 0x80) return lead >= 0x20 && lead != 0x7f ? 1 : 0;
    const std::size_t length = lead >= 0xf0 ? 4 : lead >= 0xe0 ? 3 : lead >= 0xc2 ? 2 : 0;
    if (length == 0 || lead > 0xf4 || at + length > text.size()) return 0;
    std::uint32_t code = lead & (0x7f >> length);
    for (std::size_t i = 1; i < length; ++i) {
        if ((byte(at + i) & 0xc0) != 0x80) return 0;
        code = (code << 6) | (byte(at + i) & 0x3f);
    }
    const std::uint32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < smallest[length] || (code >= 0xd800 && code <= 0xdfff) || code > 0x10ffff) return 0;
    return length;
}

// C1 controls and the bidirectional overrides that can make a name display as another.
bool isInvisibleControl(const std::string& character) {
    const auto b = [&](std::size_t i) { return static_cast<unsigned char>(character[i]); };
    if (character.size() == 2 && b(0) == 0xc2 && b(1) < 0xa0) return true;  // U+0080..U+009F
    if (character.size() == 3 && b(0) == 0xe2 && b(1) == 0x80 && (b(2) >= 0xaa && b(2) <= 0xae)) return true;
    if (character.size() == 3 && b(0) == 0xe2 && b(1) == 0x81 && (b(2) >= 0xa6 && b(2) <= 0xa9)) return true;
    return character == "\xef\xbb\xbf";  // byte order mark
}

// `text` without malformed UTF-8, control characters and bidirectional overrides.
std::string printableText(const std::string& text) {
    std::string kept;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t length = utf8SequenceLength(text, at);
        if (length > 1 && !isInvisibleControl(text.substr(at, length))) kept += text.substr(at, length);
        else if (length == 1) kept += text[at];
        at += std::max<std::size_t>(length, 1);
    }
    return kept;
}

}  // namespace

std::string uploadDisplayName(const std::string& clientName) {
    const std::size_t slash = clientName.find_last_of("/\\");
    const std::string base = slash == std::string::npos ? clientName : clientName.substr(slash + 1);
    std::string name;
    std::size_t characters = 0;
    for (std::size_t at = 0; at < base.size() && characters < kDisplayNameCharacters;) {
        const std::size_t length = utf8SequenceLength(base, at);
        if (length == 0) {
            ++at;  // not UTF-8: dropped, so the name stays valid in JSON
            continue;
        }
        const std::string character = base.substr(at, length);
        at += length;
        if (length == 1 && !std::isalnum(static_cast<unsigned char>(character[0])) &&
            std::string("._-+() ").find(character[0]) == std::string::npos)
            continue;
        if (length > 1 && isInvisibleControl(character)) continue;
        name += character;
        ++characters;
    }
    name.erase(0, name.find_first_not_of(". "));
    return name.empty() ? "upload.dat" : name;
}

LensStore::LensStore(const std::string& bundledDir, const std::string& uploadDir, Database& database, int maxUploads)
    : uploadDir_(uploadDir), database_(database), maxUploads_(maxUploads) {
    fs::create_directories(uploadDir_);
    database_.run(
        "CREATE TABLE IF NOT EXISTS lenses (id TEXT PRIMARY KEY, name TEXT NOT NULL, created REAL NOT NULL, "
        "layout TEXT)");
    loadBundled(bundledDir);
    loadUploads();
}

void LensStore::loadBundled(const std::string& folder) {
    std::error_code ec;
    std::vector<fs::path> files;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        if (isLensFileName(it->path().string()) && isSafeIdentifier(it->path().stem().string()))
            files.push_back(it->path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
        try {
            auto lens = describeLens(readLensTable(file.string()));
            lens->id = file.stem().string();
            lens->name = file.filename().string();
            lens->bundled = true;
            lens->path = file.string();
            lenses_.push_back(std::move(lens));
        } catch (const std::exception& e) {
            std::cerr << "lenslab serve: skipping bundled lens " << file << ": " << e.what() << "\n";
        }
    }
}

void LensStore::loadUploads() {
    std::vector<std::string> known;
    database_.run("SELECT id, name, created, layout FROM lenses ORDER BY created", {}, [&](const SqlRow& row) {
        const std::string id = row.text(0);
        known.push_back(id + ".dat");
        if (!isSafeIdentifier(id)) return;
        const std::string path = (fs::path(uploadDir_) / (id + ".dat")).string();
        try {
            const auto layoutName = row.optionalText(3);
            auto lens = describeLens(parseLensTable(readWholeFile(path), row.text(1),
                                                    layoutName ? parseLayoutName(*layoutName) : std::nullopt));
            lens->id = id;
            lens->name = row.text(1);
            lens->created = row.real(2);
            lens->path = path;
            lenses_.push_back(std::move(lens));
        } catch (const std::exception& e) {
            std::cerr << "lenslab serve: skipping uploaded lens " << id << ": " << e.what() << "\n";
        }
    });
    std::error_code ec;
    for (fs::directory_iterator it(uploadDir_, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string file = it->path().filename().string();
        if (std::find(known.begin(), known.end(), file) == known.end()) fs::remove(it->path(), ec);
    }
}

std::vector<std::shared_ptr<const StoredLens>> LensStore::list() const {
    std::shared_lock<std::shared_mutex> lock(mutex_);
    return lenses_;
}

std::shared_ptr<const StoredLens> LensStore::find(const std::string& id) const {
    std::shared_lock<std::shared_mutex> lock(mutex_);
    for (const auto& lens : lenses_)
        if (lens->id == id) return lens;
    return nullptr;
}

std::shared_ptr<const StoredLens> LensStore::add(const std::string& uploadName, const std::string& text,
                                                 std::optional<TableLayout> layout) {
    const std::string name = uploadDisplayName(uploadName);
    auto lens = describeLens(parseLensTable(text, name, layout));
    lens->id = newRandomIdentifier("upload-");
    lens->name = name;
    lens->created = secondsSinceEpoch();
    lens->path = (fs::path(uploadDir_) / (lens->id + ".dat")).string();

    std::unique_lock<std::shared_mutex> lock(mutex_);
    const auto uploads = std::count_if(lenses_.begin(), lenses_.end(), [](const auto& l) { return !l->bundled; });
    if (uploads >= maxUploads_)
        throw LensStoreFull("the service holds " + std::to_string(uploads) + " uploaded lenses, its limit; delete some first");
    writeFileAtomically(lens->path, text);
    database_.run("INSERT INTO lenses (id, name, created, layout) VALUES (?, ?, ?, ?)",
                  {lens->id, lens->name, lens->created,
                   layout ? SqlValue(std::string(layoutName(*layout))) : SqlValue(nullptr)});
    lenses_.push_back(lens);
    return lens;
}

LensStore::Removal LensStore::remove(const std::string& id) {
    std::unique_lock<std::shared_mutex> lock(mutex_);
    auto it = std::find_if(lenses_.begin(), lenses_.end(), [&](const auto& l) { return l->id == id; });
    if (it == lenses_.end()) return Removal::NotFound;
    if ((*it)->bundled) return Removal::ReadOnly;
    // The file first: when it cannot go (read-only folder) the lens stays listed and the client
    // hears why, instead of a 200 with the file left behind.
    std::error_code error;
    fs::remove((*it)->path, error);
    if (error && error != std::errc::no_such_file_or_directory)
        throw StorageError(storageErrorKind(error.value()), "cannot remove " + (*it)->path + ": " + error.message());
    database_.run("DELETE FROM lenses WHERE id = ?", {id});
    lenses_.erase(it);
    return Removal::Removed;
}

}  // namespace lenslab
