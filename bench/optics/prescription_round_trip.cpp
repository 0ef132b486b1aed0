// Every prescription in a folder read, written as .zmx, read back and compared field by field
// (formats/LensTableDifference.h), and the built lenses where the rows differ; and the same lens
// through the live editor's JSON (sent as text, read back, written as .zmx: the same table and the
// same file, or the same refusal): the table in docs/prescriptions.md ("Writing prescriptions"). Not
// a benchmark: a check of the .zmx writer against files from elsewhere
// (../shared/realworld/prescriptions), which are not in the repository.
//
//   prescription_round_trip FOLDER
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "LensTableDifference.h"
#include "PrescriptionJson.h"
#include "ZemaxWriter.h"
#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"
#include "prescription/NumberText.h"
#include "prescription/ZemaxFile.h"
#include "trace/AxisRay.h"

namespace {

using namespace lenslab;

// EFL and BFD of the built lens (along its axis ray, as lenslab reports a decentred lens's) as
// text, or why there are none.
std::string firstOrderText(const LensTable& table) {
    try {
        const FirstOrder f = computeFirstOrder(alongAxisRay(buildLensSystem(table)));
        return "EFL " + formatNumber(f.efl, 17) + ", BFD " + formatNumber(f.backFocalDistance, 17);
    } catch (const std::exception& e) {
        return std::string("no first order (") + e.what() + ")";
    }
}

// The .zmx the lens's own table writes, or its refusal.
std::string zemaxTextOrRefusal(const LensTable& table) {
    try {
        return writeZemaxText(table);
    } catch (const LensTableError& e) {
        return "refused: line " + std::to_string(e.line()) + ": " + e.problem();
    }
}

// The lens as the editor sends it back: the same table, and the same .zmx as the stored lens's.
std::string throughTheEditor(const LensTable& original) {
    LensTable edited;
    try {
        edited = prescriptionFromJson(nlohmann::json::parse(prescriptionJson(original).dump()), "edited lens");
    } catch (const LensTableError& e) {
        return "**refused** (" + e.problem() + ")";
    }
    if (const auto difference = lensTableDifference(original, edited)) return "**differs** (" + *difference + ")";
    if (zemaxTextOrRefusal(edited) != zemaxTextOrRefusal(original)) return "**another .zmx**";
    return "same table, same .zmx";
}

std::string roundTrip(const std::string& path) {
    LensTable original;
    try {
        original = withGapAfterRows(readLensTable(path));
        buildLensSystem(original);
    } catch (const LensTableError& e) {
        return "does not read | " + e.problem() + " | ";
    }
    const std::string editor = " | " + throughTheEditor(original);
    std::string written;
    try {
        written = writeZemaxText(original);
    } catch (const LensTableError& e) {
        return "**refused** | line " + std::to_string(e.line()) + ": " + e.problem() + editor;
    }
    LensTable again;
    try {
        again = parseZemax(written, "written.zmx");
    } catch (const LensTableError& e) {
        return "**unreadable** | the written file, line " + std::to_string(e.line()) + ": " + e.problem() + editor;
    }
    const std::string before = firstOrderText(original), after = firstOrderText(again);
    const bool catalogsMoved = withRowCatalogsInTheFile(original).catalogs != original.catalogs;
    const auto difference = lensTableDifference(withRowCatalogsInTheFile(original), again);
    if (!difference)
        return std::string("round-trips | every field equal") + (catalogsMoved ? " (the rows' Code V catalogs as GCAT)" : "") +
               "; " + (before == after ? "same " : "**first order differs** ") + before + editor;
    const auto lensDifference = builtLensDifference(original, again, 1e-12);
    if (!lensDifference)
        return "same lens | the built lenses agree surface for surface and ray for ray (1e-12); the rows differ (" +
               *difference + ")" + editor;
    return "**differs** | " + *difference + "; the built lens: " + *lensDifference + editor;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: prescription_round_trip FOLDER\n";
        return 2;
    }
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(argv[1]))
        if (isLensFileName(entry.path().string())) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    std::cout << "| file | .zmx round trip | detail | through the editor's JSON |\n|---|---|---|---|\n";
    for (const auto& f : files) std::cout << "| " << f.filename().string() << " | " << roundTrip(f.string()) << " |\n";
}
