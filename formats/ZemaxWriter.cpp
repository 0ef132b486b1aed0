#include "ZemaxWriter.h"

#include "ExactNumberText.h"

namespace lenslab {

namespace {

// GLAS name solve pickup nd Vd: a catalog glass by name (nd as the table has it, 0: the catalog's),
// anything else a model glass (___BLANK, solve 1), air (index 0) no line at all.
std::string glassLine(const LensTableRow& row) {
    if (row.mirror) return "  GLAS MIRROR\n";
    if (!row.glass.empty()) return "  GLAS " + row.glass + " 0 0 " + exactNumberText(row.index) + " 0\n";
    if (row.index == 0) return "";
    return "  GLAS ___BLANK 1 0 " + exactNumberText(row.index) + " " + exactNumberText(row.abbe) + "\n";
}

std::string surfaceBlock(const LensTableRow& row, int number) {
    bool aspheric = false;
    for (double a : row.aspheric) aspheric = aspheric || a != 0;
    std::string out = "SURF " + std::to_string(number) + "\n";
    out += aspheric ? "  TYPE EVENASPH\n" : "  TYPE STANDARD\n";
    out += "  CURV " + exactNumberText(row.radius == 0 ? 0 : 1 / row.radius) + "\n";
    out += "  DISZ " + exactNumberText(row.gap) + "\n";
    out += glassLine(row);
    if (row.conic != 0) out += "  CONI " + exactNumberText(row.conic) + "\n";
    if (aspheric)
        for (int i = 0; i < kAsphericTerms; ++i)
            out += "  PARM " + std::to_string(i + 1) + " " + exactNumberText(row.aspheric[i]) + "\n";
    out += "  DIAM " + exactNumberText(row.diameter / 2) + "\n";
    if (row.obscurationDiameter > 0) out += "  OBSC 0 " + exactNumberText(row.obscurationDiameter / 2) + "\n";
    if (row.stop) out += "  STOP\n";
    if (!row.coating.empty()) out += "  COAT " + row.coating + "\n";
    return out;
}

}  // namespace

std::string writeZemaxText(const LensTable& table) {
    if (table.layout != TableLayout::GapAfter)
        throw LensTableError(table.name, 0, "a .zmx needs gap-after rows (DISZ is the thickness to the next surface)");
    std::string out = "VERS 190513 0 0\nMODE SEQ\n";
    if (!table.comments.empty()) out += "NAME " + table.comments.front() + "\n";
    for (std::size_t i = 1; i < table.comments.size(); ++i) out += "NOTE 0 " + table.comments[i] + "\n";
    out += "UNIT MM X W X CM MR CPMM\n";
    if (table.entrancePupilDiameter) out += "ENPD " + exactNumberText(*table.entrancePupilDiameter) + "\n";
    if (table.designFNumber) out += "FNUM " + exactNumberText(*table.designFNumber) + " 0\n";
    if (!table.catalogs.empty()) {
        out += "GCAT";
        for (const std::string& c : table.catalogs) out += " " + c;
        out += "\n";
    }
    for (std::size_t i = 0; i < table.wavelengths.size(); ++i) {
        out += "WAVM " + std::to_string(i + 1) + " " + exactNumberText(table.wavelengths[i] / 1000) + " 1\n";
        if (table.wavelengths[i] == table.primaryWavelength) out += "PWAV " + std::to_string(i + 1) + "\n";
    }
    out += "SURF 0\n  TYPE STANDARD\n  CURV 0\n  DISZ INFINITY\n";
    int number = 1;
    for (const LensTableRow& row : table.rows) out += surfaceBlock(row, number++);
    out += "SURF " + std::to_string(number) + "\n  TYPE STANDARD\n  CURV 0\n  DISZ 0\n";
    return out;
}

}  // namespace lenslab
