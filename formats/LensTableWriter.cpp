#include "LensTableWriter.h"

#include "ExactNumberText.h"
#include "prescription/GlassCatalog.h"

namespace lenslab {

namespace {

bool isAir(const LensTableRow& row) { return row.glass.empty() && row.abbe == 0 && (row.index == 0 || row.index == 1); }

void refuseWhatATableCannotHold(const LensTable& table, const LensTableRow& row) {
    const auto refuse = [&](const std::string& what) {
        throw LensTableError(table.name, row.line, what + ": a lens table (.dat) cannot hold it; write a .zmx instead");
    };
    if (row.conic != 0) refuse("a conic constant");
    for (double a : row.aspheric)
        if (a != 0) refuse("aspheric terms");
    if (row.mirror) refuse("a mirror");
    if (row.obscurationDiameter > 0) refuse("a central obscuration");
    if (row.stop && (row.radius != 0 || !isAir(row))) refuse("a stop on a curved or glass surface");
    if (row.glass.find_first_of(" \t#") != std::string::npos) refuse("the glass name '" + row.glass + "' with spaces");
    if (row.coating.find_first_of(" \t#") != std::string::npos) refuse("the coating '" + row.coating + "' with spaces");
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
    std::string out;
    for (const std::string& comment : table.comments) out += "# " + comment + "\n";
    out += std::string("# radius  gap (") + layoutName(table.layout) + ")  N  diameter  glass or Vd  coat=coating\n";
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
