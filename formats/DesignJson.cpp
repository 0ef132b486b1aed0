#include "DesignJson.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "FiniteOrNull.h"
#include "prescription/NumberText.h"

namespace lenslab {

using nlohmann::json;

namespace {

[[noreturn]] void refuse(const std::string& what) { throw DesignInputError(what); }

double numberAt(const json& j, const char* key, double fallback, const std::string& where) {
    if (!j.contains(key)) return fallback;
    const json& v = j.at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>())) refuse(where + ": \"" + key + "\" must be a finite number");
    return v.get<double>();
}

std::vector<double> numbersAt(const json& j, const char* key, const std::string& where) {
    std::vector<double> out;
    if (!j.contains(key)) return out;
    if (!j.at(key).is_array()) refuse(where + ": \"" + key + "\" must be an array of numbers");
    for (const json& v : j.at(key)) {
        if (!v.is_number() || !std::isfinite(v.get<double>())) refuse(where + ": \"" + key + "\" must hold finite numbers");
        out.push_back(v.get<double>());
    }
    return out;
}

std::string textAt(const json& j, const char* key, const std::string& fallback, const std::string& where) {
    if (!j.contains(key)) return fallback;
    if (!j.at(key).is_string()) refuse(where + ": \"" + key + "\" must be a string");
    return j.at(key).get<std::string>();
}

// A surface counted from 1 in the file's way, as a 0-based row.
int rowAt(const json& j, const LensTable& table, const std::string& where) {
    const double s = numberAt(j, "surface", 0, where);
    if (s != std::floor(s) || s < 1 || s > double(table.rows.size()))
        refuse(where + ": \"surface\" must be a whole number from 1 to " + std::to_string(table.rows.size()));
    return int(s) - 1;
}

MeritOperand operandFromJson(const json& j, const LensTable& table, const std::string& where) {
    if (!j.is_object()) refuse(where + " must be an object");
    MeritOperand op;
    const std::string type = textAt(j, "type", "", where);
    const std::optional<OperandKind> kind = parseOperandKind(type);
    if (!kind) refuse(where + ": unknown operand type '" + type.substr(0, 40) + "'");
    op.kind = *kind;
    const std::optional<OperandBound> bound = parseOperandBound(textAt(j, "bound", "=", where));
    if (!bound) refuse(where + ": \"bound\" must be \"=\", \"<\" or \">\"");
    op.bound = *bound;
    op.target = numberAt(j, "target", 0, where);
    op.weight = numberAt(j, "weight", 1, where);
    if (!(op.weight >= 0)) refuse(where + ": \"weight\" must be at least 0");
    op.fieldDegrees = numberAt(j, "field", 0, where);
    if (!(std::fabs(op.fieldDegrees) < 90)) refuse(where + ": \"field\" must lie between -90 and 90 degrees");
    op.wavelength = numberAt(j, "wavelength", 0, where);
    if (op.wavelength != 0 && !(op.wavelength >= 360 && op.wavelength <= 830))
        refuse(where + ": \"wavelength\" must be 0 (all) or 360 to 830 nm");
    if (operandUsesRow(op.kind)) op.row = rowAt(j, table, where);
    if (op.kind == OperandKind::Mtf) {
        op.frequency = numberAt(j, "frequency", 0, where);
        if (!(op.frequency > 0)) refuse(where + ": an MTF operand needs \"frequency\" > 0 (lp/mm)");
        const std::string direction = textAt(j, "direction", "tangential", where);
        if (direction != "tangential" && direction != "sagittal") refuse(where + ": \"direction\" must be tangential or sagittal");
        op.direction = direction == "sagittal" ? MtfDirection::Sagittal : MtfDirection::Tangential;
    }
    return op;
}

json operandJson(const MeritOperand& op) {
    json j = {{"type", operandKindName(op.kind)}, {"bound", operandBoundSymbol(op.bound)}, {"target", op.target},
              {"weight", op.weight}, {"description", describeOperand(op)}, {"unit", operandUnit(op.kind)}};
    if (operandUsesField(op.kind)) j["field"] = op.fieldDegrees;
    if (op.wavelength > 0) j["wavelength"] = op.wavelength;
    if (operandUsesRow(op.kind)) j["surface"] = op.row + 1;
    if (op.kind == OperandKind::Mtf) {
        j["frequency"] = op.frequency;
        j["direction"] = op.direction == MtfDirection::Sagittal ? "sagittal" : "tangential";
    }
    return j;
}

json distributionJson(const Distribution& d) {
    return {{"count", d.count}, {"mean", d.mean}, {"p50", d.p50}, {"p90", d.p90}, {"p98", d.p98},
            {"min", d.min},     {"max", d.max},   {"histogram", d.histogram}};
}

std::string fixed(double v, int digits) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
    return buffer;
}

std::string scientific(double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", v);
    return buffer;
}

std::string padded(const std::string& s, std::size_t width) { return s.size() >= width ? s + " " : s + std::string(width - s.size(), ' '); }

}  // namespace

MeritFunction meritFromJson(const json& j, const LensTable& table) {
    if (!j.is_object()) refuse("merit: the file must hold one JSON object");
    for (const auto& [key, value] : j.items()) {
        static const char* known[] = {"default", "wavelengths", "weights", "image_plane", "rings", "azimuths", "operands"};
        if (std::find(std::begin(known), std::end(known), key) == std::end(known)) refuse("merit: unknown key '" + key.substr(0, 40) + "'");
    }
    MeritFunction merit;
    if (j.contains("default")) {
        if (!j.at("default").is_boolean()) refuse("merit: \"default\" must be true or false");
        if (j.at("default").get<bool>()) merit = defaultMerit(table);
    } else if (!table.wavelengths.empty()) {
        merit.wavelengths = table.wavelengths;
        merit.weights = table.wavelengthWeights;
    }
    if (j.contains("wavelengths")) {
        merit.wavelengths = numbersAt(j, "wavelengths", "merit");
        merit.weights.clear();
        for (double w : merit.wavelengths)
            if (!(w >= 360 && w <= 830)) refuse("merit: wavelengths must lie between 360 and 830 nm");
        if (merit.wavelengths.empty()) refuse("merit: \"wavelengths\" is empty");
    }
    if (j.contains("weights")) {
        merit.weights = numbersAt(j, "weights", "merit");
        if (merit.weights.size() != merit.wavelengths.size()) refuse("merit: one weight per wavelength");
        for (double w : merit.weights)
            if (!(w >= 0)) refuse("merit: weights must be at least 0");
    }
    const std::string plane = textAt(j, "image_plane", "table", "merit");
    if (plane != "table" && plane != "paraxial") refuse("merit: \"image_plane\" must be table or paraxial");
    merit.imagePlane = plane == "table" ? MeritImagePlane::Table : MeritImagePlane::Paraxial;
    const double rings = numberAt(j, "rings", merit.sampling.rings, "merit"), azimuths = numberAt(j, "azimuths", merit.sampling.azimuths, "merit");
    if (rings != std::floor(rings) || rings < 1 || rings > 64) refuse("merit: \"rings\" must be a whole number from 1 to 64");
    if (azimuths != std::floor(azimuths) || azimuths < 4 || azimuths > 512) refuse("merit: \"azimuths\" must be a whole number from 4 to 512");
    merit.sampling = {int(rings), int(azimuths)};
    if (j.contains("operands")) {
        if (!j.at("operands").is_array()) refuse("merit: \"operands\" must be an array");
        constexpr std::size_t kMaxOperands = 500;
        if (j.at("operands").size() > kMaxOperands) refuse("merit: at most " + std::to_string(kMaxOperands) + " operands");
        int k = 0;
        for (const json& o : j.at("operands")) merit.operands.push_back(operandFromJson(o, table, "merit: operand " + std::to_string(++k)));
    }
    if (merit.operands.empty()) refuse("merit: no operands (list some, or \"default\": true)");
    return merit;
}

std::vector<DesignVariable> variablesFromText(const std::string& text, const LensTable& table) {
    std::vector<DesignVariable> out;
    const int rows = static_cast<int>(table.rows.size());
    const auto applies = [&](const DesignVariable& v) {
        try {
            checkVariable(table, v);
            return true;
        } catch (const std::invalid_argument&) {
            return false;
        }
    };
    // A flat surface between equal media (a flat stop, a dummy) bends nothing: its curvature is no
    // variable a designer means by "every curvature".
    const auto bends = [&](int i) {
        const LensTableRow& r = table.rows[i];
        const double before = i == 0 ? 1.0 : (table.rows[i - 1].index > 1 ? table.rows[i - 1].index : 1.0);
        const double after = r.index > 1 ? r.index : 1.0;
        return r.radius != 0 || r.mirror || !r.glass.empty() || (i > 0 && !table.rows[i - 1].glass.empty()) || before != after;
    };
    if (text.empty() || text == "all") {
        for (int i = 0; i < rows; ++i) {
            const DesignVariable v{VariableKind::Curvature, i};
            if (!table.rows[i].coordinateBreak && bends(i) && applies(v)) out.push_back(v);
        }
        const std::optional<double> distance = imageDistance(table);
        if (distance && *distance > 0) out.push_back({VariableKind::Thickness, rows - 1});
        return out;
    }
    std::stringstream items(text);
    std::string item;
    while (std::getline(items, item, ',')) {
        const std::size_t colon = item.find(':');
        if (colon == std::string::npos) refuse("variables: '" + item.substr(0, 40) + "' is not KIND:SURFACE (as in curvature:3)");
        std::string kindName = item.substr(0, colon);
        int term = 0;
        if (kindName.rfind("asphere", 0) == 0 && kindName.size() > 7) {
            const int power = std::atoi(kindName.c_str() + 7);
            if (power < 2 || power > 16 || power % 2) refuse("variables: asphereN needs an even N from 2 to 16, got '" + kindName.substr(0, 40) + "'");
            term = power / 2 - 1;
            kindName = "asphere";
        }
        const std::optional<VariableKind> kind = parseVariableKind(kindName);
        if (!kind) refuse("variables: unknown kind '" + kindName.substr(0, 40) + "' (curvature, thickness, conic, asphereN, index, abbe)");
        const std::string range = item.substr(colon + 1);
        int first = 0, last = 0;
        char dash = 0;
        std::istringstream r(range);
        if (!(r >> first)) refuse("variables: '" + item.substr(0, 40) + "' names no surface");
        last = first;
        if (r >> dash && !(dash == '-' && r >> last)) refuse("variables: '" + item.substr(0, 40) + "' is not a surface or a range N-M");
        if (first < 1 || last > rows || last < first) refuse("variables: '" + item.substr(0, 40) + "': surfaces run from 1 to " + std::to_string(rows));
        for (int s = first; s <= last; ++s) {
            const DesignVariable v{*kind, s - 1, term};
            if (first == last) {
                try {
                    checkVariable(table, v);
                } catch (const std::invalid_argument& e) {
                    refuse(std::string("variables: ") + e.what());
                }
                out.push_back(v);
            } else if (applies(v) && (v.kind != VariableKind::Curvature || bends(v.row))) {
                out.push_back(v);
            }
        }
    }
    return out;
}

ToleranceInputs defaultToleranceInputs(const LensTable& table) {
    ToleranceInputs in;
    in.spec.radiusFraction = 0.001;
    in.spec.thickness = 0.02;
    in.spec.decentre = 0.01;
    in.spec.tilt = 0.01;
    in.spec.index = 5e-4;
    const std::optional<double> distance = imageDistance(table);
    if (distance && *distance > 0) in.compensators.push_back({VariableKind::Thickness, int(table.rows.size()) - 1});
    return in;
}

ToleranceInputs toleranceInputsFromJson(const json& j, const LensTable& table, const MeritFunction& merit) {
    if (!j.is_object()) refuse("tolerances: the file must hold one JSON object");
    ToleranceInputs in;
    const std::string where = "tolerances";
    struct Limit {
        const char* key;
        double ToleranceSpec::*field;
    };
    static const Limit limits[] = {
        {"radius", &ToleranceSpec::radiusFraction}, {"power", &ToleranceSpec::powerFringes},
        {"astigmatism", &ToleranceSpec::astigmatismFringes}, {"thickness", &ToleranceSpec::thickness},
        {"decentre", &ToleranceSpec::decentre}, {"tilt", &ToleranceSpec::tilt},
        {"element_decentre", &ToleranceSpec::elementDecentre}, {"element_tilt", &ToleranceSpec::elementTilt},
        {"index", &ToleranceSpec::index}, {"abbe", &ToleranceSpec::abbeFraction},
    };
    for (const auto& item : j.items()) {
        const std::string& key = item.key();
        const bool known = std::any_of(std::begin(limits), std::end(limits), [&](const Limit& l) { return key == l.key; }) ||
                           key == "compensators" || key == "draw" || key == "specification" || key == "merit_limit";
        if (!known) refuse(where + ": unknown key '" + key.substr(0, 40) + "'");
    }
    for (const Limit& l : limits) {
        const double v = numberAt(j, l.key, 0, where);
        if (!(v >= 0)) refuse(where + ": \"" + l.key + "\" must be at least 0");
        in.spec.*l.field = v;
    }
    in.compensators = j.contains("compensators") ? variablesFromText(textAt(j, "compensators", "", where), table)
                                                 : defaultToleranceInputs(table).compensators;
    const std::string draw = textAt(j, "draw", "normal", where);
    if (draw != "normal" && draw != "uniform") refuse(where + ": \"draw\" must be normal or uniform");
    in.draw = draw == "normal" ? ToleranceDraw::Normal : ToleranceDraw::Uniform;
    if (j.contains("specification")) {
        if (!j.at("specification").is_array()) refuse(where + ": \"specification\" must be an array");
        for (const json& s : j.at("specification")) {
            const double operand = numberAt(s, "operand", 0, where + ": specification");
            if (operand != std::floor(operand) || operand < 1 || operand > double(merit.operands.size()))
                refuse(where + ": specification: \"operand\" must be a merit operand's number, 1 to " + std::to_string(merit.operands.size()));
            const bool max = s.contains("max"), min = s.contains("min");
            if (max == min) refuse(where + ": specification: give one of \"max\" and \"min\"");
            in.specification.push_back({int(operand) - 1, max ? OperandBound::AtMost : OperandBound::AtLeast,
                                        numberAt(s, max ? "max" : "min", 0, where + ": specification")});
        }
    }
    if (j.contains("merit_limit")) in.meritLimit = numberAt(j, "merit_limit", 0, where);
    return in;
}

json meritEvaluationJson(const MeritFunction& merit, const MeritEvaluation& e) {
    json operands = json::array();
    for (std::size_t i = 0; i < merit.operands.size(); ++i) {
        json o = operandJson(merit.operands[i]);
        if (e.valid) {
            o["value"] = e.values[i];
            o["residual"] = e.residuals[i];
        }
        operands.push_back(o);
    }
    json j = {{"valid", e.valid}, {"operands", operands}, {"sampling", {{"rings", e.sampling.rings}, {"azimuths", e.sampling.azimuths}}}};
    if (e.valid) j["merit"] = e.merit;
    else j["problem"] = e.problem;
    return j;
}

json optimiserResultJson(const DesignProblem& problem, const OptimiserResult& r) {
    json variables = json::array();
    const std::vector<double> start = startingValues(problem);
    for (std::size_t k = 0; k < problem.variables.size(); ++k)
        variables.push_back({{"variable", describeVariable(problem.start, problem.variables[k])},
                             {"kind", variableKindName(problem.variables[k].kind)},
                             {"surface", problem.variables[k].row + 1},
                             {"before", start[k]},
                             {"after", r.values[k]}});
    return {{"start", meritEvaluationJson(problem.merit, r.start)},
            {"end", meritEvaluationJson(problem.merit, r.end)},
            {"variables", variables},
            {"iterations", r.iterations},
            {"evaluations", r.evaluations},
            {"stop", stopReasonText(r.stop)},
            {"history", r.history}};
}

json monteCarloJson(const ToleranceProblem& problem, const MonteCarloResult& r) {
    json operands = json::array();
    for (std::size_t i = 0; i < problem.merit.operands.size() && i < r.operands.size(); ++i) {
        json o = operandJson(problem.merit.operands[i]);
        o["nominal"] = r.nominal.valid ? json(r.nominal.values[i]) : json(nullptr);
        o["distribution"] = distributionJson(r.operands[i]);
        operands.push_back(o);
    }
    json tolerances = json::array();
    for (const Tolerance& t : problem.tolerances) tolerances.push_back(describeTolerance(t));
    return {{"trials", r.trials.size()},   {"invalid", r.invalid},
            {"yield", r.yield},            {"nominal_merit", r.nominal.valid ? json(r.nominal.merit) : json(nullptr)},
            {"merit", distributionJson(r.merit)}, {"operands", operands},
            {"tolerances", tolerances},    {"cancelled", r.cancelled}};
}

json sensitivityJson(const ToleranceProblem& problem, const std::vector<SensitivityRow>& rows) {
    json out = json::array();
    for (const SensitivityRow& row : rows) {
        const auto side = [&](const MeritEvaluation& e) { return meritEvaluationJson(problem.merit, e); };
        out.push_back({{"tolerance", describeTolerance(row.tolerance)},
                       {"merit_change", finiteOrNull(row.meritChange)},
                       {"plus", side(row.plus)},
                       {"minus", side(row.minus)}});
    }
    return out;
}

std::string optimiserResultText(const DesignProblem& problem, const OptimiserResult& r) {
    std::ostringstream s;
    s << "merit " << scientific(r.start.merit) << " -> " << scientific(r.end.merit) << " in " << r.iterations << " iterations, "
      << r.evaluations << " evaluations: " << stopReasonText(r.stop) << "\n\n";
    s << padded("operand", 40) << padded("target", 14) << padded("before", 14) << "after\n";
    for (std::size_t i = 0; i < problem.merit.operands.size(); ++i) {
        const MeritOperand& op = problem.merit.operands[i];
        s << padded(describeOperand(op), 40) << padded(std::string(operandBoundSymbol(op.bound)) + " " + scientific(op.target), 14)
          << padded(scientific(r.start.values[i]), 14) << scientific(r.end.values[i]) << " " << operandUnit(op.kind) << "\n";
    }
    s << "\n" << padded("variable", 40) << padded("before", 22) << "after\n";
    const std::vector<double> start = startingValues(problem);
    for (std::size_t k = 0; k < problem.variables.size(); ++k) {
        const DesignVariable& v = problem.variables[k];
        std::string before = scientific(start[k]), after = scientific(r.values[k]);
        if (v.kind == VariableKind::Curvature) {
            before += start[k] != 0 ? " (R " + fixed(1 / start[k], 4) + ")" : " (flat)";
            after += r.values[k] != 0 ? " (R " + fixed(1 / r.values[k], 4) + ")" : " (flat)";
        }
        s << padded(describeVariable(problem.start, v), 40) << padded(before, 22) << after << "\n";
    }
    return s.str();
}

std::string monteCarloText(const ToleranceProblem& problem, const MonteCarloResult& r) {
    std::ostringstream s;
    s << r.trials.size() << " trials, " << r.invalid << " invalid; yield " << fixed(100 * r.yield, 1) << "%\n";
    s << padded("", 40) << padded("nominal", 14) << padded("mean", 14) << padded("50%", 14) << padded("90%", 14) << "98%\n";
    const auto line = [&](const std::string& name, double nominal, const Distribution& d) {
        s << padded(name, 40) << padded(scientific(nominal), 14) << padded(scientific(d.mean), 14) << padded(scientific(d.p50), 14)
          << padded(scientific(d.p90), 14) << scientific(d.p98) << "\n";
    };
    line("merit", r.nominal.merit, r.merit);
    for (std::size_t i = 0; i < r.operands.size(); ++i)
        line(describeOperand(problem.merit.operands[i]), r.nominal.valid ? r.nominal.values[i] : NAN, r.operands[i]);
    return s.str();
}

std::string sensitivityText(const std::vector<SensitivityRow>& rows, std::size_t most) {
    std::ostringstream s;
    s << padded("tolerance", 36) << padded("merit +", 14) << padded("merit -", 14) << "largest change\n";
    for (std::size_t k = 0; k < rows.size() && k < most; ++k) {
        const SensitivityRow& row = rows[k];
        const auto merit = [](const MeritEvaluation& e) { return e.valid ? scientific(e.merit) : std::string("invalid"); };
        s << padded(describeTolerance(row.tolerance), 36) << padded(merit(row.plus), 14) << padded(merit(row.minus), 14)
          << scientific(row.meritChange) << "\n";
    }
    return s.str();
}

}  // namespace lenslab
