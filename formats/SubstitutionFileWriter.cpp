#include "SubstitutionFileWriter.h"

#include <nlohmann/json.hpp>

#include "ExactNumberText.h"

namespace lenslab {

std::string writeSubstitutionText(const LensTable& table) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (const GlassSubstitute& s : table.substitutes) {
        if (!s.medium) {
            j[s.name] = {s.glass, s.catalog};
            continue;
        }
        const Medium& m = *s.medium;
        if (m.formula == DispersionFormula::Constant) {
            j[s.name] = "om.ConstantIndex(" + exactNumberText(m.coefficients[0]) + ", '" + s.name + "')";
        } else if (m.formula == DispersionFormula::Tabulated) {
            std::string pairs;
            for (const auto& [nm, n] : m.table) pairs += (pairs.empty() ? "(" : ", (") + exactNumberText(nm) + ", " + exactNumberText(n) + ")";
            j[s.name] = "om.InterpolatedMedium('" + s.name + "', pairs=[" + pairs + "])";
        } else {
            throw LensTableError(table.name, 0, "glass '" + s.name + "' is given by a dispersion formula, which a .smx file cannot hold");
        }
    }
    return j.dump(1) + "\n";
}

LensTable withoutSubstitutions(LensTable table) {
    table.substitutes.clear();
    return table;
}

}  // namespace lenslab
