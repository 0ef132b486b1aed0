#include "design/DesignProblem.h"

#include <stdexcept>


namespace lenslab {

std::vector<double> startingValues(const DesignProblem& problem) {
    std::vector<double> values;
    for (const DesignVariable& v : problem.variables) values.push_back(variableValue(problem.start, v));
    return values;
}

namespace {

LensTable withValues(const DesignProblem& problem, const std::vector<double>& values) {
    LensTable table = problem.start;
    for (std::size_t j = 0; j < problem.variables.size(); ++j) setVariableValue(table, problem.variables[j], values[j]);
    return table;
}

}  // namespace

LensTable designLens(const DesignProblem& problem, const std::vector<double>& values) {
    LensTable table = withValues(problem, values);
    applyDesignRules(table, problem.rules);
    return table;
}

MeritEvaluation evaluateDesign(const DesignProblem& problem, const std::vector<double>& values) {
    return evaluateMerit(withValues(problem, values), problem.merit, problem.rules);
}

void checkDesignProblem(const DesignProblem& problem) {
    for (const DesignVariable& v : problem.variables) checkVariable(problem.start, v);
    for (std::size_t a = 0; a < problem.variables.size(); ++a)
        for (std::size_t b = a + 1; b < problem.variables.size(); ++b)
            if (problem.variables[a] == problem.variables[b])
                throw std::invalid_argument("variable " + describeVariable(problem.start, problem.variables[a]) + " is given twice");
    for (const Pickup& p : problem.rules.pickups) {
        checkVariable(problem.start, p.target);
        checkVariable(problem.start, p.source);
        for (const DesignVariable& v : problem.variables)
            if (v == p.target)
                throw std::invalid_argument("variable " + describeVariable(problem.start, v) + " is also a pick-up's target");
    }
    if (problem.merit.operands.empty()) throw std::invalid_argument("the merit function has no operands");
    if (problem.merit.wavelengths.empty()) throw std::invalid_argument("the merit function has no wavelengths");
    if (!problem.merit.weights.empty() && problem.merit.weights.size() != problem.merit.wavelengths.size())
        throw std::invalid_argument("the merit function has " + std::to_string(problem.merit.weights.size()) +
                                    " weights for " + std::to_string(problem.merit.wavelengths.size()) + " wavelengths");
    if (problem.rules.marginalRayImageSolve && problem.start.layout != TableLayout::GapAfter)
        throw std::invalid_argument("the marginal-ray image solve needs a gap-after table (its last gap is the image distance)");
}

}  // namespace lenslab
