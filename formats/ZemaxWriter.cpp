#include "ZemaxWriter.h"

#include <algorithm>

#include "ExactNumberText.h"
#include "LineText.h"
#include "UnwrittenFeatures.h"
#include "prescription/Wavelength.h"

namespace lenslab {

namespace {

[[noreturn]] void refuse(const LensTable& table, int line, const std::string& what) {
    throw LensTableError(table.name, line, what + ": a .zmx cannot hold it");
}

// A name written as one word of a GLAS or GCAT line; MIRROR and ___BLANK are GLAS's own words.
const std::string& word(const LensTable& table, int line, const std::string& what, const std::string& name) {
    if (const auto problem = wordTextProblem(name)) refuse(table, line, what + " with " + *problem);
    if (name == "MIRROR" || name == "___BLANK") refuse(table, line, what + " '" + name + "' (a GLAS keyword)");
    return name;
}

// GLAS name solve pickup nd Vd: a catalog glass by name (nd as the table has it, 0: the catalog's),
// anything else a model glass (___BLANK, solve 1), air (index 0) no line at all.
std::string glassLine(const LensTable& table, const LensTableRow& row) {
    if (row.mirror) return "  GLAS MIRROR\n";
    if (!row.glass.empty())
        return "  GLAS " + word(table, row.line, "a glass name", row.glass) + " 0 0 " + exactNumberText(row.index) + " 0\n";
    if (row.index == 0) return "";
    return "  GLAS ___BLANK 1 0 " + exactNumberText(row.index) + " " + exactNumberText(row.abbe) + "\n";
}

std::string surfaceBlock(const LensTable& table, const LensTableRow& row, int number) {
    bool aspheric = false;
    for (double a : row.aspheric) aspheric = aspheric || a != 0;
    std::string out = "SURF " + std::to_string(number) + "\n";
    out += aspheric ? "  TYPE EVENASPH\n" : "  TYPE STANDARD\n";
    out += "  CURV " + (row.radius == 0 ? std::string("0") : exactReciprocalText(row.radius)) + "\n";
    out += "  DISZ " + exactNumberText(row.gap) + "\n";
    out += glassLine(table, row);
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

std::string noteLines(const LensTable& table) {
    std::string out;
    for (std::size_t i = 0; i < table.comments.size(); ++i) {
        if (const auto problem = lineTextProblem(table.comments[i]))
            refuse(table, 0, "comment " + std::to_string(i + 1) + " with " + *problem);
        out += (i == 0 ? "NAME " : "NOTE 0 ") + table.comments[i] + "\n";
    }
    return out;
}

// WAVM lines with the primary among them (added when the list lacks it), and PWAV naming it unless
// it is the d line a file without WAVM lines is read at.
std::string wavelengthLines(const LensTable& table) {
    std::vector<double> nm = table.wavelengths;
    if (std::find(nm.begin(), nm.end(), table.primaryWavelength) == nm.end() &&
        (!nm.empty() || table.primaryWavelength != kWavelengthD))
        nm.push_back(table.primaryWavelength);
    std::string out;
    for (std::size_t i = 0; i < nm.size(); ++i) {
        if (const auto problem = wavelengthProblem(nm[i])) refuse(table, 0, "the " + *problem);
        out += "WAVM " + std::to_string(i + 1) + " " + exactNumberText(nm[i] / 1000) + " 1\n";
    }
    if (!nm.empty())
        out += "PWAV " + std::to_string(std::find(nm.begin(), nm.end(), table.primaryWavelength) - nm.begin() + 1) + "\n";
    return out;
}

}  // namespace

std::string writeZemaxText(const LensTable& table) {
    if (table.layout != TableLayout::GapAfter)
        throw LensTableError(table.name, 0, "a .zmx needs gap-after rows (DISZ is the thickness to the next surface)");
    refuseUnwrittenFeatures(table, ".zmx");
    std::string out = "VERS 190513 0 0\nMODE SEQ\n" + noteLines(table) + "UNIT MM X W X CM MR CPMM\n";
    if (table.entrancePupilDiameter) out += "ENPD " + exactNumberText(*table.entrancePupilDiameter) + "\n";
    if (table.designFNumber) out += "FNUM " + exactNumberText(*table.designFNumber) + " 0\n";
    if (!table.catalogs.empty()) {
        out += "GCAT";
        for (const std::string& c : table.catalogs) out += " " + word(table, 0, "a catalog name", c);
        out += "\n";
    }
    out += wavelengthLines(table);
    out += "SURF 0\n  TYPE STANDARD\n  CURV 0\n  DISZ INFINITY\n";
    int number = 1;
    for (const LensTableRow& row : table.rows) out += surfaceBlock(table, row, number++);
    out += "SURF " + std::to_string(number) + "\n  TYPE STANDARD\n  CURV 0\n  DISZ 0\n";
    return out;
}

}  // namespace lenslab
