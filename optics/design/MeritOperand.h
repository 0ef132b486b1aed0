#pragma once
// One term of a merit function (docs/design.md): a quantity of the lens, a target, a weight and the
// kind of goal (= held at the target, < kept at most at it, > kept at least at it). A bound costs
// nothing while it holds, and its excess squared when it does not, as Zemax and Code V treat them.
#include <optional>
#include <string>

#include "analysis/GeometricMtf.h"

namespace lenslab {

enum class OperandKind {
    EffectiveFocalLength,  // mm, at the primary wavelength
    FNumber,               // image-space paraxial f-number, EFL over the entrance pupil's diameter
    BackFocalDistance,     // mm, rear vertex to F'
    ImageDistance,         // mm, rear vertex to the image plane
    TotalTrack,            // mm, front vertex to the image plane
    Magnification,         // paraxial, image over object height (a finite object only)
    Distortion,            // percent at fieldDegrees: the primary chief ray's height against f tan(theta)
    RmsSpot,               // mm about the centroid, at fieldDegrees, one wavelength or all (weighted)
    RmsWavefront,          // waves, at fieldDegrees, one wavelength or the weighted mean of all
    Mtf,                   // diffraction MTF at `frequency` lp/mm, sagittal or tangential, one wavelength or all
    ChiefRayAngle,         // degrees, the primary chief ray's angle to the axis on the image
    CentreThickness,       // mm, the gap after `row` on the axis
    EdgeThickness,         // mm, the gap after `row` at the smaller clear semi-diameter of its two surfaces
    ApertureClearance,     // mm, the clear semi-diameter of `row` less the highest ray of every field there
    AxialColour,           // mm, paraxial image of C less that of F (primary axial colour)
    LateralColour,         // mm, chief-ray height of F less that of C at fieldDegrees on the image plane
};

enum class OperandBound { Equal, AtMost, AtLeast };

struct MeritOperand {
    OperandKind kind = OperandKind::RmsSpot;
    OperandBound bound = OperandBound::Equal;
    double target = 0;
    double weight = 1;
    double fieldDegrees = 0;   // field operands: the object-space angle of the chief ray
    double wavelength = 0;     // nm; 0: the merit's wavelengths with their weights (spot, wavefront, MTF)
    int row = -1;              // thickness and clearance operands: 0-based row of the table
    double frequency = 0;      // Mtf, lp/mm
    MtfDirection direction = MtfDirection::Tangential;
};

const char* operandKindName(OperandKind kind);  // "efl", "fnumber", "bfl", "image_distance", "total_track", ...
std::optional<OperandKind> parseOperandKind(const std::string& name);
const char* operandBoundSymbol(OperandBound bound);  // "=", "<", ">"
std::optional<OperandBound> parseOperandBound(const std::string& symbol);
// The unit its values are in: "mm", "%", "waves", "deg" or "" (f-number, magnification, MTF).
const char* operandUnit(OperandKind kind);
// What the operand needs besides the lens: a field, a row, a frequency.
bool operandUsesField(OperandKind kind);
bool operandUsesRow(OperandKind kind);

// "rms_spot 14 deg all wavelengths", "edge_thickness 3", for tables and progress lines.
std::string describeOperand(const MeritOperand& op);

// The signed residual sqrt(weight) x (value - target), or 0 for a bound that holds.
double operandResidual(const MeritOperand& op, double value);

}  // namespace lenslab
