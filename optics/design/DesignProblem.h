#pragma once
// A design task: the starting lens, what may change in it (variables and the rules that follow
// them) and the merit that says how good it is. A point of the design space is the variables' values.
#include <vector>

#include "design/DesignVariable.h"
#include "design/MeritFunction.h"

namespace lenslab {

struct DesignProblem {
    LensTable start;
    std::vector<DesignVariable> variables;
    DesignRules rules;
    MeritFunction merit;
};

// The variables' values in the starting lens.
std::vector<double> startingValues(const DesignProblem& problem);

// The starting lens with the variables set to `values` and the rules applied. Throws OpticsError
// where a rule has no answer (the image solve of an afocal lens).
LensTable designLens(const DesignProblem& problem, const std::vector<double>& values);

// The lens of `values` evaluated (evaluateMerit with the problem's rules): a rule without an answer is
// an invalid lens, with its reason.
MeritEvaluation evaluateDesign(const DesignProblem& problem, const std::vector<double>& values);

// Checks every variable and pick-up against the lens (checkVariable), and the merit's wavelengths:
// throws std::invalid_argument naming the first that does not apply. (An operand naming a row the
// lens lacks throws the same from its first evaluation.)
void checkDesignProblem(const DesignProblem& problem);

}  // namespace lenslab
