#include "DesignInputs.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>

#include "CodeVWriter.h"
#include "DesignJson.h"
#include "LensTableWriter.h"
#include "SubstitutionFileWriter.h"
#include "ZemaxWriter.h"

namespace lenslab {

double processCpuSeconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

void declareDesignInputs(ArgParser& p) {
    p.positional("FILE", "lens table (.dat), Zemax (.zmx) or Code V (.seq) prescription");
    p.option("--merit", "M.json", "merit function (docs/design.md); default: spots at the file's fields, EFL held, thickness bounds");
    p.option("--layout", "L", "gap-before | gap-after (default: detect)");
}

LensTable designTable(const ArgParser& p) {
    std::optional<TableLayout> layout;
    if (p.has("--layout")) {
        layout = parseLayoutName(p.get("--layout"));
        if (!layout) throw UsageError("--layout must be gap-before or gap-after, got '" + p.get("--layout") + "'");
    }
    LensTable table = readLensTable(p.arg(0), layout);
    buildLensSystem(table);  // a lens that does not build is refused here, with its line
    return table;
}

nlohmann::json readJsonFile(const std::string& path, const std::string& what) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open the " + what + " file");
    try {
        return nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::runtime_error(path + ": not JSON (" + std::string(e.what()) + ")");
    }
}

MeritFunction designMerit(const ArgParser& p, const LensTable& table) {
    if (!p.has("--merit")) return defaultMerit(table);
    try {
        return meritFromJson(readJsonFile(p.get("--merit"), "merit"), table);
    } catch (const DesignInputError& e) {
        throw std::runtime_error(p.get("--merit") + ": " + e.what());
    }
}

void writeDesignTable(const LensTable& table, const std::string& path, const MeritFunction& merit) {
    const std::string extension = path.size() > 4 ? path.substr(path.size() - 4) : "";
    if (extension != ".zmx" && extension != ".seq" && extension != ".dat")
        throw UsageError("-o: the lens is written as .zmx, .seq or .dat, got '" + path + "'");
    // Glasses no catalog holds (an as-built lens's melts) go to the .smx file beside the lens, which
    // reading it takes up again.
    const LensTable stated = withoutSubstitutions(table);
    const std::string text = extension == ".zmx"   ? writeZemaxText(withRowCatalogsInTheFile(stated))
                             : extension == ".seq" ? writeCodeVText(stated)
                                                   : writeLensTableText(stated);
    const auto write = [](const std::string& file, const std::string& bytes) {
        std::ofstream out(file, std::ios::binary);
        if (!out || !(out << bytes)) throw std::runtime_error(file + ": cannot write the file");
    };
    const std::string smx = path.substr(0, path.size() - 4) + ".smx";
    std::remove(smx.c_str());
    if (!table.substitutes.empty()) write(smx, writeSubstitutionText(table));
    write(path, text);
    const MeritEvaluation before = evaluateMerit(table, merit);
    const MeritEvaluation after = evaluateMerit(readLensTable(path, table.layout), merit);
    for (std::size_t i = 0; before.valid && i < before.values.size(); ++i)
        if (!after.valid || std::fabs(after.values[i] - before.values[i]) > 1e-9 * std::max(1.0, std::fabs(before.values[i])))
            throw std::runtime_error(path + ": the written lens does not read back as the same lens (" +
                                     describeOperand(merit.operands[i]) + ")");
}

}  // namespace lenslab
