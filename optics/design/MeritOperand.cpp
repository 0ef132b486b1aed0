#include "design/MeritOperand.h"

#include <cmath>

#include "prescription/NumberText.h"

namespace lenslab {

namespace {

struct OperandKindInfo {
    OperandKind kind;
    const char* name;
    const char* unit;
};

constexpr OperandKindInfo kOperandKinds[] = {
    {OperandKind::EffectiveFocalLength, "efl", "mm"},
    {OperandKind::FNumber, "fnumber", ""},
    {OperandKind::BackFocalDistance, "bfl", "mm"},
    {OperandKind::ImageDistance, "image_distance", "mm"},
    {OperandKind::TotalTrack, "total_track", "mm"},
    {OperandKind::Magnification, "magnification", ""},
    {OperandKind::Distortion, "distortion", "%"},
    {OperandKind::RmsSpot, "rms_spot", "mm"},
    {OperandKind::RmsWavefront, "rms_wavefront", "waves"},
    {OperandKind::Mtf, "mtf", ""},
    {OperandKind::ChiefRayAngle, "chief_ray_angle", "deg"},
    {OperandKind::CentreThickness, "centre_thickness", "mm"},
    {OperandKind::EdgeThickness, "edge_thickness", "mm"},
    {OperandKind::ApertureClearance, "aperture_clearance", "mm"},
    {OperandKind::AxialColour, "axial_colour", "mm"},
    {OperandKind::LateralColour, "lateral_colour", "mm"},
};

const OperandKindInfo& info(OperandKind kind) {
    for (const OperandKindInfo& k : kOperandKinds)
        if (k.kind == kind) return k;
    return kOperandKinds[0];
}

}  // namespace

const char* operandKindName(OperandKind kind) { return info(kind).name; }
const char* operandUnit(OperandKind kind) { return info(kind).unit; }

std::optional<OperandKind> parseOperandKind(const std::string& name) {
    for (const OperandKindInfo& k : kOperandKinds)
        if (name == k.name) return k.kind;
    return std::nullopt;
}

const char* operandBoundSymbol(OperandBound bound) {
    return bound == OperandBound::Equal ? "=" : bound == OperandBound::AtMost ? "<" : ">";
}

std::optional<OperandBound> parseOperandBound(const std::string& symbol) {
    if (symbol == "=") return OperandBound::Equal;
    if (symbol == "<") return OperandBound::AtMost;
    if (symbol == ">") return OperandBound::AtLeast;
    return std::nullopt;
}

bool operandUsesField(OperandKind kind) {
    switch (kind) {
        case OperandKind::Distortion:
        case OperandKind::RmsSpot:
        case OperandKind::RmsWavefront:
        case OperandKind::Mtf:
        case OperandKind::ChiefRayAngle:
        case OperandKind::LateralColour: return true;
        default: return false;
    }
}

bool operandUsesRow(OperandKind kind) {
    return kind == OperandKind::CentreThickness || kind == OperandKind::EdgeThickness ||
           kind == OperandKind::ApertureClearance;
}

std::string describeOperand(const MeritOperand& op) {
    std::string text = operandKindName(op.kind);
    if (operandUsesRow(op.kind)) text += " " + std::to_string(op.row + 1);
    if (op.kind == OperandKind::Mtf)
        text += std::string(" ") + formatNumber(op.frequency) + " lp/mm " +
                (op.direction == MtfDirection::Sagittal ? "sagittal" : "tangential");
    if (operandUsesField(op.kind)) text += " " + formatNumber(op.fieldDegrees) + " deg";
    if (op.kind == OperandKind::RmsSpot || op.kind == OperandKind::RmsWavefront || op.kind == OperandKind::Mtf)
        text += op.wavelength > 0 ? " " + formatNumber(op.wavelength) + " nm" : " polychromatic";
    return text;
}

double operandResidual(const MeritOperand& op, double value) {
    const double excess = value - op.target;
    const bool holds = (op.bound == OperandBound::AtMost && excess <= 0) || (op.bound == OperandBound::AtLeast && excess >= 0);
    return holds ? 0.0 : std::sqrt(op.weight) * excess;
}

}  // namespace lenslab
