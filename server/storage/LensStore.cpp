#include "storage/LensStore.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <limits>
#include <mutex>

#include "storage/AtomicFile.h"
#include "core/ContentDigest.h"
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
    lens->fstopMax = a.aperture.fstopMaxOffered;
    if (!table.comments.empty()) {
        std::string d = table.comments.front();
        d.erase(0, d.find_first_not_of(' '));
        lens->description = printableText(d);
    }
    return lens;
}

// What the lens is made of: its text and the layout it is read with.
std::string tableDigest(const std::string& text, std::optional<TableLayout> layout) {
    return contentDigest(std::string(layout ? layoutName(*layout) : "detected") + "\n" + text);
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

std::string uploadDisplayName(const std::string& clientName, const std::string& fallback) {
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
    return name.empty() ? fallback : name;
}

// An entry registered at start (or added); its lens is described once, lazily.
struct LensStore::Entry {
    std::string id, name, path;
    bool bundled = false;
    double created = 0;
    std::optional<TableLayout> layout;  // as recorded for an upload; detected when absent
    std::once_flag once;
    // Under the store's mutex: set once described; `failed` when it could not be.
    std::shared_ptr<const StoredLens> lens;
    bool failed = false;
};

LensStore::LensStore(const std::string& bundledDir, const std::string& uploadDir, Database& database, int maxUploads)
    : uploadDir_(uploadDir), database_(database), maxUploads_(maxUploads) {
    fs::create_directories(uploadDir_);
    database_.run(
        "CREATE TABLE IF NOT EXISTS lenses (id TEXT PRIMARY KEY, name TEXT NOT NULL, created REAL NOT NULL, "
        "layout TEXT)");
    registerBundled(bundledDir);
    for (const auto& entry : entries_) described(*entry);  // a few small tables, read now
    registerUploads();
}

LensStore::~LensStore() {
    stopping_ = true;
    if (describer_.joinable()) describer_.join();
}

void LensStore::registerBundled(const std::string& folder) {
    std::error_code ec;
    std::vector<fs::path> files;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        if (isLensFileName(it->path().string()) && isSafeIdentifier(it->path().stem().string()))
            files.push_back(it->path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
        auto entry = std::make_shared<Entry>();
        entry->id = file.stem().string();
        entry->name = file.filename().string();
        entry->path = file.string();
        entry->bundled = true;
        entries_.push_back(std::move(entry));
    }
}

void LensStore::registerUploads() {
    std::vector<std::string> known;
    database_.run("SELECT id, name, created, layout FROM lenses ORDER BY created", {}, [&](const SqlRow& row) {
        const std::string id = row.text(0);
        known.push_back(id + ".dat");
        if (!isSafeIdentifier(id)) return;
        auto entry = std::make_shared<Entry>();
        entry->id = id;
        entry->name = row.text(1);
        entry->created = row.real(2);
        entry->path = (fs::path(uploadDir_) / (id + ".dat")).string();
        if (const auto layout = row.optionalText(3)) entry->layout = parseLayoutName(*layout);
        entries_.push_back(std::move(entry));
    });
    std::error_code ec;
    for (fs::directory_iterator it(uploadDir_, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string file = it->path().filename().string();
        if (std::find(known.begin(), known.end(), file) == known.end()) fs::remove(it->path(), ec);
    }
}

void LensStore::describeInBackground() {
    if (describer_.joinable()) return;
    describer_ = std::thread([this] {
        std::vector<std::shared_ptr<Entry>> entries;
        {
            std::shared_lock<std::shared_mutex> lock(mutex_);
            entries = entries_;
        }
        for (const auto& entry : entries) {
            if (stopping_) return;
            described(*entry);
        }
    });
}

std::shared_ptr<const StoredLens> LensStore::described(Entry& entry) const {
    std::call_once(entry.once, [&] {
        std::shared_ptr<StoredLens> lens;
        try {
            const std::string text = readWholeFile(entry.path);
            lens = describeLens(parseLensTable(text, entry.name, entry.layout));
            lens->id = entry.id;
            lens->name = entry.name;
            lens->bundled = entry.bundled;
            lens->created = entry.created;
            lens->path = entry.path;
            lens->digest = tableDigest(text, entry.layout);
        } catch (const std::exception& e) {
            std::cerr << "lenslab serve: skipping " << (entry.bundled ? "bundled" : "uploaded") << " lens " << entry.id
                      << ": " << e.what() << "\n";
        }
        std::unique_lock<std::shared_mutex> lock(mutex_);
        entry.lens = lens;
        entry.failed = !lens;
    });
    std::shared_lock<std::shared_mutex> lock(mutex_);
    return entry.lens;
}

std::vector<std::shared_ptr<const StoredLens>> LensStore::list() const {
    std::shared_lock<std::shared_mutex> lock(mutex_);
    std::vector<std::shared_ptr<const StoredLens>> lenses;
    for (const auto& entry : entries_)
        if (entry->lens) lenses.push_back(entry->lens);
    return lenses;
}

LensStore::Counts LensStore::counts() const {
    std::shared_lock<std::shared_mutex> lock(mutex_);
    Counts c;
    for (const auto& entry : entries_) {
        c.lenses += !entry->failed;
        c.waiting += !entry->lens && !entry->failed;
    }
    return c;
}

std::shared_ptr<LensStore::Entry> LensStore::entryOf(const std::string& id) const {
    std::shared_lock<std::shared_mutex> lock(mutex_);
    for (const auto& entry : entries_)
        if (entry->id == id && !entry->failed) return entry;
    return nullptr;
}

std::shared_ptr<const StoredLens> LensStore::find(const std::string& id) const {
    const auto entry = entryOf(id);
    return entry ? described(*entry) : nullptr;
}

std::vector<std::string> LensStore::lensesWhere(const std::function<bool(const StoredLens&)>& test) const {
    std::vector<std::shared_ptr<Entry>> entries;
    {
        std::shared_lock<std::shared_mutex> lock(mutex_);
        entries = entries_;
    }
    std::vector<std::string> ids;
    for (const auto& entry : entries)
        if (const auto lens = described(*entry); lens && test(*lens)) ids.push_back(lens->id);
    return ids;
}

std::shared_ptr<const StoredLens> LensStore::add(const std::string& uploadName, const std::string& text,
                                                 std::optional<TableLayout> layout) {
    auto entry = std::make_shared<Entry>();
    entry->name = uploadDisplayName(uploadName);
    auto lens = describeLens(parseLensTable(text, entry->name, layout));
    entry->id = lens->id = newRandomIdentifier("upload-");
    lens->name = entry->name;
    entry->created = lens->created = secondsSinceEpoch();
    entry->path = lens->path = (fs::path(uploadDir_) / (lens->id + ".dat")).string();
    entry->layout = layout;
    lens->digest = tableDigest(text, layout);
    std::call_once(entry->once, [&] { entry->lens = lens; });

    std::unique_lock<std::shared_mutex> lock(mutex_);
    const auto uploads =
        std::count_if(entries_.begin(), entries_.end(), [](const auto& e) { return !e->bundled && !e->failed; });
    if (uploads >= maxUploads_)
        throw LensStoreFull("the service holds " + std::to_string(uploads) + " uploaded lenses, its limit; delete some first");
    writeFileAtomically(lens->path, text);
    database_.run("INSERT INTO lenses (id, name, created, layout) VALUES (?, ?, ?, ?)",
                  {lens->id, lens->name, lens->created,
                   layout ? SqlValue(std::string(layoutName(*layout))) : SqlValue(nullptr)});
    entries_.push_back(std::move(entry));
    return lens;
}

LensStore::Removal LensStore::remove(const std::string& id, const std::function<void()>& checkUnused) {
    std::unique_lock<std::shared_mutex> noLensTaken(deleting_);
    if (checkUnused) checkUnused();
    std::unique_lock<std::shared_mutex> lock(mutex_);
    auto it = std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e->id == id && !e->failed; });
    if (it == entries_.end()) return Removal::NotFound;
    if ((*it)->bundled) return Removal::ReadOnly;
    // The file first: when it cannot go (read-only folder) the lens stays listed and the client
    // hears why, instead of a 200 with the file left behind.
    std::error_code error;
    fs::remove((*it)->path, error);
    if (error && error != std::errc::no_such_file_or_directory)
        throw StorageError(storageErrorKind(error.value()), "cannot remove " + (*it)->path + ": " + error.message());
    database_.run("DELETE FROM lenses WHERE id = ?", {id});
    entries_.erase(it);
    return Removal::Removed;
}

std::shared_lock<std::shared_mutex> LensStore::holdLenses() const {
    return std::shared_lock<std::shared_mutex>(deleting_);
}

}  // namespace lenslab
