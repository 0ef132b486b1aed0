#pragma once
// The design's inputs and results as JSON and text (docs/design.md): merit functions, variable
// lists, tolerance specifications, and what an optimisation or a tolerance analysis found. The command
// line and the API read and write these shapes. Rows are counted from 1 (as the files count
// surfaces), 0-based inside optics/.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "design/DampedLeastSquares.h"
#include "design/ToleranceAnalysis.h"

namespace lenslab {

// A problem with a design input: the message names the field and what was wrong.
class DesignInputError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// {"default": true, "wavelengths": [nm...], "weights": [...], "image_plane": "table"|"paraxial",
//  "rings": 8, "azimuths": 16, "operands": [{"type": "rms_spot", "field": 14, "wavelength": 550,
//  "target": 0, "weight": 1, "bound": "=", "surface": 3, "frequency": 50, "direction": "tangential"}]}.
// "default" starts from defaultMerit(table) and adds the operands listed. Throws DesignInputError.
MeritFunction meritFromJson(const nlohmann::json& j, const LensTable& table);

// "curvature:1-6,thickness:6,conic:3,asphere4:5,index:1,abbe:1" (surfaces from 1; asphereN: the r^N
// term; a range covers every surface it names that the kind applies to). "all" or empty: every curvature
// of a refracting surface and the image distance (where the table states one). Throws DesignInputError.
std::vector<DesignVariable> variablesFromText(const std::string& text, const LensTable& table);

// {"radius": 0.001, "power": 1, "astigmatism": 0.5, "thickness": 0.02, "decentre": 0.01, "tilt": 0.01,
//  "element_decentre": 0.02, "element_tilt": 0.02, "index": 5e-4, "abbe": 0.008,
//  "compensators": "thickness:6", "draw": "normal"|"uniform",
//  "specification": [{"operand": 1, "max": 0.02}], "merit_limit": 1e-4}: abbe is a fraction of Vd;
// operands in the specification are counted from 1. Throws DesignInputError.
struct ToleranceInputs {
    ToleranceSpec spec;
    std::vector<DesignVariable> compensators;
    ToleranceDraw draw = ToleranceDraw::Normal;
    std::vector<OperandLimit> specification;
    std::optional<double> meritLimit;
};
ToleranceInputs toleranceInputsFromJson(const nlohmann::json& j, const LensTable& table, const MeritFunction& merit);

// The default tolerances of issue-style designs: radius 0.1%, thickness 0.02 mm, decentre 0.01 mm,
// tilt 0.01 deg, index 5e-4, the image distance as compensator (where the table states one).
ToleranceInputs defaultToleranceInputs(const LensTable& table);

nlohmann::json meritEvaluationJson(const MeritFunction& merit, const MeritEvaluation& e);
nlohmann::json optimiserResultJson(const DesignProblem& problem, const OptimiserResult& r);
nlohmann::json monteCarloJson(const ToleranceProblem& problem, const MonteCarloResult& r);
nlohmann::json sensitivityJson(const ToleranceProblem& problem, const std::vector<SensitivityRow>& rows);

// The terminal's tables: each operand before and after, and each variable's change.
std::string optimiserResultText(const DesignProblem& problem, const OptimiserResult& r);
std::string monteCarloText(const ToleranceProblem& problem, const MonteCarloResult& r);
std::string sensitivityText(const std::vector<SensitivityRow>& rows, std::size_t most);

}  // namespace lenslab
