#include "prescription/LensTable.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "prescription/CodeVFile.h"
#include "prescription/SubstitutionFile.h"
#include "prescription/TextEncoding.h"
#include "prescription/ZemaxFile.h"

namespace lenslab {

double& gapAfter(LensTable& table, int row) {
    return table.layout == TableLayout::GapAfter ? table.rows[row].gap : table.rows[row + 1].gap;
}

double gapAfter(const LensTable& table, int row) { return gapAfter(const_cast<LensTable&>(table), row); }

const char* layoutName(TableLayout layout) {
    return layout == TableLayout::GapBefore ? "gap-before" : "gap-after";
}

std::optional<TableLayout> parseLayoutName(const std::string& name) {
    if (name == "gap-before") return TableLayout::GapBefore;
    if (name == "gap-after") return TableLayout::GapAfter;
    return std::nullopt;
}

static std::string formatLocation(const std::string& file, int line) {
    return line > 0 ? file + ":" + std::to_string(line) : file;
}

LensTableError::LensTableError(const std::string& file, int line, const std::string& problem)
    : std::runtime_error(formatLocation(file, line) + ": " + problem),
      file_(file), line_(line), problem_(problem) {}

namespace {

const std::string kUtf8ByteOrderMark = "\xef\xbb\xbf";

const char* const kColumnNames[5] = {"radius", "gap", "N", "diameter", "glass or Vd"};

std::vector<std::string> splitFields(const std::string& s) {
    std::vector<std::string> fields;
    std::istringstream in(s);
    std::string f;
    while (in >> f) fields.push_back(f);
    return fields;
}

// A field as an error message quotes it: a long one is cut, so a message stays a line long.
std::string quoted(const std::string& field) {
    constexpr std::size_t kShown = 40;
    return "'" + (field.size() > kShown ? field.substr(0, kShown) + "..." : field) + "'";
}

double parseNumber(const std::string& field, int column, const std::string& file, int line) {
    const char* begin = field.c_str();
    char* end = nullptr;
    errno = 0;
    double v = std::strtod(begin, &end);
    if (end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(v))
        throw LensTableError(file, line, std::string("column ") + std::to_string(column + 1) + " (" +
                                             kColumnNames[column] + ") is not a finite number: " +
                                             quoted(field));
    return v;
}

bool isNumber(const std::string& field) {
    char* end = nullptr;
    std::strtod(field.c_str(), &end);
    return end != field.c_str() && *end == '\0';
}

// The optional fifth column names the glass behind the surface: a number is its Abbe number Vd
// (column 3's N and Vd make a model glass), anything else a catalog glass name.
void parseGlass(LensTableRow& row, const std::string& field, const std::string& file, int line) {
    if (row.index == 0 || row.index == 1)
        throw LensTableError(file, line, "column 5 (glass or Vd) '" + field +
                                             "' on an air or stop row: only a glass (N > 1) has a name or an Abbe number");
    if (!isNumber(field)) {
        row.glass = field;
        return;
    }
    row.abbe = parseNumber(field, 4, file, line);
    if (row.abbe <= 0) throw LensTableError(file, line, "Abbe number Vd must be positive, found " + field);
}

// A last field coat=TEXT names the surface's coating (prescription/Coating.h; checked when the
// lens is built, where the default for rows without one is decided too).
std::string takeCoating(std::vector<std::string>& fields, const std::string& file, int line) {
    const auto isCoating = [](const std::string& f) { return f.size() >= 5 && (f.compare(0, 5, "coat=") == 0 || f.compare(0, 5, "COAT=") == 0); };
    if (fields.empty() || !isCoating(fields.back())) return "";
    std::string coating = fields.back().substr(5);
    fields.pop_back();
    for (const std::string& f : fields)
        if (isCoating(f)) throw LensTableError(file, line, "a second coat= field: a surface has one coating");
    if (coating.empty()) throw LensTableError(file, line, "coat= needs a coating: none, a material (MgF2, MgF2@550) or a stack");
    return coating;
}

LensTableRow parseRow(const std::string& content, const std::string& file, int line) {
    auto fields = splitFields(content);
    LensTableRow row;
    row.coating = takeCoating(fields, file, line);
    if (fields.size() != 4 && fields.size() != 5)
        throw LensTableError(file, line,
                             "expected 4 or 5 columns (radius, gap, N, diameter, optional glass or Vd), found " +
                                 std::to_string(fields.size()) + " (a coat= field may follow them)");
    row.line = line;
    row.radius = parseNumber(fields[0], 0, file, line);
    row.gap = parseNumber(fields[1], 1, file, line);
    row.index = parseNumber(fields[2], 2, file, line);
    row.diameter = parseNumber(fields[3], 3, file, line);
    row.stop = row.radius == 0 && row.index == 0;
    if (row.gap < 0) throw LensTableError(file, line, "negative gap " + quoted(fields[1]));
    if (row.diameter <= 0)
        throw LensTableError(file, line, "diameter must be positive, found " + fields[3]);
    if (row.index != 0 && row.index < 1)
        throw LensTableError(file, line, "refractive index " + fields[2] + " is below 1 (use 0 or 1 for air)");
    if (fields.size() == 5) parseGlass(row, fields[4], file, line);
    return row;
}

TableLayout decideLayout(const LensTable& t, std::optional<TableLayout> override) {
    const LensTableRow& first = t.rows.front();
    const LensTableRow& last = t.rows.back();
    if (override) {
        if (*override == TableLayout::GapBefore && first.gap != 0)
            throw LensTableError(t.name, first.line,
                                 "gap-before layout needs a first-row gap of 0 (nothing precedes the first surface)");
        return *override;
    }
    const bool firstZero = first.gap == 0, lastZero = last.gap == 0;
    if (t.rows.size() > 1 && firstZero && lastZero)
        throw LensTableError(t.name, first.line,
                             "ambiguous layout: both the first and the last gap are 0; pass --layout gap-before or gap-after");
    if (firstZero) return TableLayout::GapBefore;
    if (lastZero) return TableLayout::GapAfter;
    throw LensTableError(t.name, first.line,
                         "cannot tell the layout: neither the first gap (gap-before) nor the last gap "
                         "(gap-after) is 0; pass --layout gap-before or gap-after");
}

// A .zmx or .seq file's thickness is always the gap to the next surface.
LensTable parseDesignFile(const std::string& bytes, const std::string& name, std::optional<TableLayout> layout,
                         bool codeV) {
    if (layout == TableLayout::GapBefore)
        throw LensTableError(name, 0, std::string(codeV ? "a Code V file's thickness" : "a Zemax file's DISZ") +
                                          " is the gap to the next surface: the gap-before layout does not apply");
    LensTable table = codeV ? parseCodeV(bytes, name) : parseZemax(bytes, name);
    table.layoutDetected = !layout.has_value();
    return table;
}

// The text as UTF-8 when it is UTF-16 (design programs on Windows save it), else unchanged; a
// broken UTF-16 file is left to the reader that names its line.
std::string decodedForDetection(const std::string& bytes) {
    if (!startsWithUtf16ByteOrderMark(bytes)) return bytes;
    try {
        return toUtf8Text(bytes, "");
    } catch (const LensTableError&) {
        return "";
    }
}

}  // namespace

LensTable parseLensTable(const std::string& text, const std::string& name,
                         std::optional<TableLayout> layout) {
    const std::string decoded = decodedForDetection(text);
    if (looksLikeCodeV(decoded)) return parseDesignFile(text, name, layout, true);
    if (looksLikeZemax(text)) return parseDesignFile(text, name, layout, false);
    LensTable table;
    table.name = name;
    std::istringstream in(text);
    std::string raw;
    int lineNo = 0;
    std::size_t commentBytes = 0;
    while (std::getline(in, raw)) {
        ++lineNo;
        // Editors on Windows start UTF-8 files with a byte order mark; it is not part of the table.
        if (lineNo == 1 && raw.rfind(kUtf8ByteOrderMark, 0) == 0) raw.erase(0, kUtf8ByteOrderMark.size());
        if (!raw.empty() && raw.back() == '\r') raw.pop_back();
        std::string content = raw;
        if (auto hash = raw.find('#'); hash != std::string::npos) {
            content = raw.substr(0, hash);
            if (table.rows.empty() && content.find_first_not_of(" \t") == std::string::npos) {
                std::string comment = raw.substr(hash + 1);
                auto b = comment.find_first_not_of(" \t");
                auto e = comment.find_last_not_of(" \t\"");
                table.comments.push_back(b == std::string::npos ? "" : comment.substr(b, e - b + 1));
                commentBytes += table.comments.back().size();
                if (commentBytes > kMaxCommentBytes)
                    throw LensTableError(name, lineNo, "the comment lines before the table are longer than " +
                                                           std::to_string(kMaxCommentBytes) + " bytes");
            }
        }
        if (content.find_first_not_of(" \t\f\v") == std::string::npos) continue;
        if (int(table.rows.size()) == kMaxLensSurfaces)
            throw LensTableError(name, lineNo, "too many surfaces: a lens table may have at most " +
                                                   std::to_string(kMaxLensSurfaces) + " rows");
        table.rows.push_back(parseRow(content, name, lineNo));
    }
    if (table.rows.empty())
        throw LensTableError(name, std::max(lineNo, 1), "no surfaces: the table has no data rows");
    table.layout = decideLayout(table, layout);
    table.layoutDetected = !layout.has_value();
    return table;
}

namespace {

// Whether a name ends with a suffix, letters in any case (US08427765-1.ZMX).
bool endsWith(const std::string& s, const std::string& suffix) {
    if (s.size() <= suffix.size()) return false;
    for (std::size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) != suffix[i]) return false;
    return true;
}

}  // namespace

bool isLensFileName(const std::string& name) {
    return endsWith(name, ".dat") || endsWith(name, ".zmx") || endsWith(name, ".seq");
}

std::string lensFileStem(const std::string& name) {
    std::string base = name.substr(name.find_last_of('/') + 1);
    if (isLensFileName(base)) base.resize(base.size() - 4);
    return base;
}

LensTable readLensTable(const std::string& path, std::optional<TableLayout> layout) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw LensTableError(path, 0, "cannot open the file");
    std::ostringstream ss;
    ss << f.rdbuf();
    if (f.bad()) throw LensTableError(path, 0, "cannot read the file");
    LensTable table = parseLensTable(ss.str(), path, layout);
    // A substitution table beside the file (ray-optics' NAME.smx) is the file's own.
    if (const auto smx = substitutionFileFor(path)) {
        std::ifstream s(*smx, std::ios::binary);
        std::ostringstream text;
        text << s.rdbuf();
        if (!s) throw LensTableError(*smx, 0, "cannot read the file");
        const auto substitutes = parseSubstitutionFile(text.str(), *smx);
        table.substitutes.insert(table.substitutes.end(), substitutes.begin(), substitutes.end());
    }
    return table;
}

}  // namespace lenslab
