#include "design/DesignVariable.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "firstorder/Chromatic.h"
#include "firstorder/FirstOrder.h"
#include "prescription/LensSystem.h"
#include "prescription/NumberText.h"
#include "prescription/OpticsError.h"
#include "prescription/RowMedium.h"

namespace lenslab {

namespace {

constexpr const char* kKindNames[] = {"curvature", "thickness", "conic", "asphere", "index", "abbe"};

bool isGlassKind(VariableKind kind) { return kind == VariableKind::Index || kind == VariableKind::Abbe; }

}  // namespace

const char* variableKindName(VariableKind kind) { return kKindNames[static_cast<int>(kind)]; }

std::optional<VariableKind> parseVariableKind(const std::string& name) {
    for (int k = 0; k < 6; ++k)
        if (name == kKindNames[k]) return static_cast<VariableKind>(k);
    return std::nullopt;
}

std::string describeVariable(const LensTable& table, const DesignVariable& v) {
    std::string text = variableKindName(v.kind);
    if (v.kind == VariableKind::Asphere) text += " r^" + std::to_string(2 * v.term + 2);
    text += " " + std::to_string(v.row + 1);
    if (v.kind == VariableKind::Thickness && v.row + 1 == int(table.rows.size())) text += " (image distance)";
    return text;
}

void checkVariable(const LensTable& table, const DesignVariable& v) {
    const int rows = static_cast<int>(table.rows.size());
    const auto refuse = [&](const std::string& why) {
        throw std::invalid_argument("variable " + describeVariable(table, v) + ": " + why);
    };
    if (v.row < 0 || v.row >= rows) refuse("the lens has surfaces 1 to " + std::to_string(rows));
    const LensTableRow& r = table.rows[v.row];
    if (r.coordinateBreak) refuse("the row is a coordinate break, not a surface");
    if (v.kind == VariableKind::Thickness && table.layout == TableLayout::GapBefore && v.row + 1 == rows)
        refuse("a gap-before table ends at its last surface: it has no image distance to vary");
    if (v.kind == VariableKind::Asphere && (v.term < 0 || v.term >= kAsphericTerms))
        refuse("aspheric terms are r^2 to r^16 (terms 0 to 7)");
    if ((v.kind == VariableKind::Conic || v.kind == VariableKind::Asphere) && !r.form.isEvenAsphere())
        refuse(std::string("the surface is a ") + surfaceKindName(r.form.kind) + ", not an even asphere");
    if (isGlassKind(v.kind) && (r.mirror || (r.glass.empty() && !(r.index > 1))))
        refuse("the row is followed by air or is a mirror: it has no glass to vary");
    if (v.lower && v.upper && !(*v.lower <= *v.upper)) refuse("its lower bound lies above its upper bound");
}

double variableValue(const LensTable& table, const DesignVariable& v) {
    const LensTableRow& r = table.rows[v.row];
    switch (v.kind) {
        case VariableKind::Curvature: return r.radius == 0 ? 0.0 : 1 / r.radius;
        case VariableKind::Thickness: return gapAfter(table, v.row);
        case VariableKind::Conic: return r.conic;
        case VariableKind::Asphere: return r.aspheric[v.term];
        case VariableKind::Index:
        case VariableKind::Abbe: {
            if (r.glass.empty()) return v.kind == VariableKind::Index ? r.index : r.abbe;
            std::vector<LensWarning> ignored;
            const Medium m = rowMedium(table, r, ignored);
            return v.kind == VariableKind::Index ? m.nd : m.vd;
        }
    }
    return 0;
}

void makeModelGlass(LensTable& table, int row) {
    LensTableRow& r = table.rows[row];
    if (r.glass.empty()) return;
    std::vector<LensWarning> ignored;
    const Medium m = rowMedium(table, r, ignored);
    r.glass.clear();
    r.glassCatalog.clear();
    r.index = m.nd;
    r.abbe = m.vd;
}

void setVariableValue(LensTable& table, const DesignVariable& v, double value) {
    if (v.lower) value = std::max(value, *v.lower);
    if (v.upper) value = std::min(value, *v.upper);
    LensTableRow& r = table.rows[v.row];
    switch (v.kind) {
        case VariableKind::Curvature: r.radius = value == 0 ? 0.0 : 1 / value; break;
        case VariableKind::Thickness: gapAfter(table, v.row) = value; break;
        case VariableKind::Conic: r.conic = value; break;
        case VariableKind::Asphere: r.aspheric[v.term] = value; break;
        case VariableKind::Index:
            makeModelGlass(table, v.row);
            r.index = value;
            break;
        case VariableKind::Abbe:
            makeModelGlass(table, v.row);
            r.abbe = value;
            break;
    }
}

std::optional<double> imageDistance(const LensTable& table) {
    if (table.layout != TableLayout::GapAfter || table.rows.empty()) return std::nullopt;
    return table.rows.back().gap;
}

void applyDesignRules(LensTable& table, const DesignRules& rules) {
    for (const Pickup& p : rules.pickups)
        setVariableValue(table, p.target, p.scale * variableValue(table, p.source) + p.offset);
    if (!rules.marginalRayImageSolve) return;
    if (table.layout != TableLayout::GapAfter)
        throw OpticsError("the marginal-ray image solve needs a gap-after table (its last gap is the image distance)");
    const LensSystem lens = buildLensSystem(table);
    const FirstOrder fo = computeFirstOrder(lens);
    const double imageZ = paraxialImageZ(lens, fo, lens.frontZ() + lens.objectDistance);
    if (!std::isfinite(imageZ)) throw OpticsError("the marginal-ray image solve has no finite image distance");
    table.rows.back().gap = lens.rearZ() - imageZ;
}

}  // namespace lenslab
