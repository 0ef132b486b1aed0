#pragma once
// A merit function (docs/design.md): operands over a lens at the merit's wavelengths, on an image
// plane of its choosing, the spots on the analysis's own pupil quadrature. Its value is the sum of
// the operands' squared residuals, weight x (value - target)^2 (bounds that hold cost nothing).
// Evaluating it also checks that the lens is physically valid; an invalid lens has no merit.
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "analysis/PupilSampling.h"
#include "design/DesignVariable.h"
#include "design/MeritOperand.h"
#include "prescription/LensTable.h"

namespace lenslab {

enum class MeritImagePlane {
    Table,     // the table's own image plane (a gap-after table's last gap); else paraxial
    Paraxial,  // the paraxial image of the object at the primary wavelength
};

struct MeritFunction {
    std::vector<MeritOperand> operands;
    std::vector<double> wavelengths{kWavelengthF, kWavelengthD, kWavelengthC};  // nm
    std::vector<double> weights;  // per wavelength; empty: equal
    MeritImagePlane imagePlane = MeritImagePlane::Table;
    // The spots' quadrature. Held fixed through an optimisation (so the merit is a smooth function of
    // the lens); settled like the analysis's (doubled until an RMS radius moves by at most
    // samplingTolerance) where `settle` is set, as for the figures reported before and after.
    PupilQuadrature sampling;
    bool settle = false;
    double samplingTolerance = 0.002;
    int maxAzimuths = 512;
};

class TracedLens;  // the rays an evaluation traced, kept to measure the same lens on another image plane

struct MeritEvaluation {
    bool valid = false;
    std::string problem;           // why not: surfaces that cross, a field no ray reaches, a lens that does not build
    std::vector<double> values;    // per operand, in its unit
    std::vector<double> residuals; // per operand
    double merit = std::numeric_limits<double>::quiet_NaN();
    PupilQuadrature sampling;      // the finest quadrature a spot used (settled or not)
    std::shared_ptr<const TracedLens> traced;  // valid evaluations: what evaluateMeritAtImageDistance reuses
};

// The rules (pick-ups, the image solve) are applied to the table first; a rule without an answer (the
// image solve of an afocal lens) makes an invalid lens, with its reason.
MeritEvaluation evaluateMerit(const LensTable& table, const MeritFunction& merit, const DesignRules& rules = {});

// The lens of a valid evaluation with only its image distance changed (a gap-after table's last gap,
// on the merit's Table image plane): every ray is a straight move of one already traced, so a back
// focus compensator or variable costs no tracing. The same numbers as evaluateMerit of that table
// (the sampling held: not for a settled merit, whose sampling depends on the plane).
MeritEvaluation evaluateMeritAtImageDistance(const MeritEvaluation& base, double imageDistance, const MeritFunction& merit);

// The design's own figures as a merit: the polychromatic RMS spot at each of the table's fields
// (0, 0.7 and 1 of the lens's largest field when it lists none; the axis alone for a lens that defines
// no field) with their weights, at its wavelengths and weights (F, d, C when it lists none), on its
// image plane (its paraxial focus where the table states no image distance); the EFL held at its
// present value; glass at least 1 mm thick at the centre and 0.5 mm at the edge, air gaps at least 0
// at both. Throws OpticsError for a lens without a focal length.
MeritFunction defaultMerit(const LensTable& table);

// The operands' residuals' sum of squares.
double meritValue(const std::vector<double>& residuals);

}  // namespace lenslab
