#include "LensTableWriter.h"

#include <cstdlib>

#include "ExactNumberText.h"
#include "LineText.h"
#include "UnwrittenFeatures.h"
#include "prescription/GlassCatalog.h"
#include "prescription/NumberText.h"

namespace lenslab {

namespace {

bool isAir(const LensTableRow& row) { return row.glass.empty() && row.abbe == 0 && (row.index == 0 || row.index == 1); }

// The comment naming the columns. Read back it is one more comment, so a table written again
// leaves out the header lines it already holds (this one, or one written before the coat= field
// existed): a lens saved over and over keeps one.
std::string columnHeader(TableLayout layout) {
    return std::string("radius  gap (") + layoutName(layout) + ")  N  diameter  glass or Vd  coat=coating";
}

bool isColumnHeader(const std::string& comment) {
    for (const TableLayout layout : {TableLayout::GapBefore, TableLayout::GapAfter}) {
        const std::string header = columnHeader(layout);
        if (comment == header || comment == header.substr(0, header.rfind("  coat="))) return true;
    }
    return false;
}

[[noreturn]] void refuseForDat(const LensTable& table, int line, const std::string& what) {
    throw LensTableError(table.name, line, what + ": a lens table (.dat) cannot hold it; write a .zmx instead");
}

bool isNumber(const std::string& text) {
    char* end = nullptr;
    std::strtod(text.c_str(), &end);
    return end != text.c_str() && *end == '\0';
}

// The glass a row's name finds as the table reads it back (no catalog order) must be the one it
// finds now, with the row's own catalog (Code V's N-BK7_SCHOTT) and the file's (GCAT) first.
void refuseCatalogOrderThatMatters(const LensTable& table, const LensTableRow& row) {
    if (table.catalogs.empty() && row.glassCatalog.empty()) return;
    std::vector<std::string> order = table.catalogs;
    if (!row.glassCatalog.empty()) order.insert(order.begin(), row.glassCatalog);
    const GlassLookup preferred = findGlass(row.glass, order), plain = findGlass(row.glass, {});
    if (preferred.glass && plain.glass &&
        (preferred.glass->catalog != plain.glass->catalog || preferred.glass->name != plain.glass->name))
        refuseForDat(table, row.line, std::string(row.glassCatalog.empty() ? "the catalog order (GCAT)" : "the row's catalog") +
                                    " that makes '" + row.glass + "' " + preferred.glass->catalog + " " +
                                    preferred.glass->name + " rather than " + plain.glass->catalog + " " + plain.glass->name);
}

void refuseWhatATableCannotHold(const LensTable& table, const LensTableRow& row) {
    if (row.conic != 0) refuseForDat(table, row.line, "a conic constant");
    for (double a : row.aspheric)
        if (a != 0) refuseForDat(table, row.line, "aspheric terms");
    if (row.mirror) refuseForDat(table, row.line, "a mirror");
    if (row.obscurationDiameter > 0) refuseForDat(table, row.line, "a central obscuration");
    if (row.stop && (row.radius != 0 || !isAir(row))) refuseForDat(table, row.line, "a stop on a curved or glass surface");
    if (!row.coating.empty()) {
        if (const auto problem = wordTextProblem(row.coating)) refuseForDat(table, row.line, "a coating with " + *problem);
        if (row.coating.find('#') != std::string::npos) refuseForDat(table, row.line, "a coating with '#' (a comment)");
    }
    if (row.glass.empty()) return;
    if (const auto problem = wordTextProblem(row.glass)) refuseForDat(table, row.line, "a glass name with " + *problem);
    if (row.glass.find('#') != std::string::npos) refuseForDat(table, row.line, "a glass name with '#' (a comment)");
    if (isNumber(row.glass)) refuseForDat(table, row.line, "the glass name '" + row.glass + "' (it would read as an Abbe number)");
    refuseCatalogOrderThatMatters(table, row);
}

void refuseWhatItsHeaderCannotHold(const LensTable& table) {
    refuseUnwrittenFeatures(table, ".dat");
    for (std::size_t i = 0; i < table.comments.size(); ++i)
        if (const auto problem = lineTextProblem(table.comments[i]))
            refuseForDat(table, 0, "comment " + std::to_string(i + 1) + " with " + *problem);
    if (table.primaryWavelength != kWavelengthD)
        refuseForDat(table, 0, "the primary wavelength " + formatNumber(table.primaryWavelength, 9) +
                             " nm (a table is read at the d line, " + formatNumber(kWavelengthD, 9) + " nm)");
}

// Column 3 of a glass row must be its nd: a .zmx catalog glass may leave it to the catalog (0).
double tableIndex(const LensTable& table, const LensTableRow& row) {
    if (row.stop) return 0;                  // a table marks its stop by radius 0, N 0
    if (isAir(row)) return 1;                // a flat N 0 row would read as a stop
    if (row.index != 0 || row.glass.empty()) return row.index;
    const GlassLookup found = findGlass(row.glass, table.catalogs);
    if (!found.glass) throw LensTableError(table.name, row.line, "glass '" + row.glass + "' is not in the catalog");
    return refractiveIndex(*found.glass, kWavelengthD);
}

}  // namespace

std::string writeLensTableText(const LensTable& table) {
    refuseWhatItsHeaderCannotHold(table);
    std::string out;
    for (const std::string& comment : table.comments)
        if (!isColumnHeader(comment)) out += "# " + comment + "\n";
    out += "# " + columnHeader(table.layout) + "\n";
    for (const LensTableRow& row : table.rows) {
        refuseWhatATableCannotHold(table, row);
        out += exactNumberText(row.radius) + " " + exactNumberText(row.gap) + " " + exactNumberText(tableIndex(table, row)) +
               " " + exactNumberText(row.diameter);
        if (!row.glass.empty()) out += " " + row.glass;
        else if (row.abbe > 0) out += " " + exactNumberText(row.abbe);
        if (!row.coating.empty()) out += " coat=" + row.coating;
        out += "\n";
    }
    return out;
}

}  // namespace lenslab
