#pragma once
// What an optimisation may change in a prescription, and the rules that follow from it: variables
// (a row's curvature, the thickness after it, its conic, an aspheric term, a model glass's nd or Vd),
// pick-ups (a value that follows another's) and the marginal-ray solve for the image distance. The
// design works on the LensTable itself, so that every trial lens is built, checked and written by the
// same code as a lens read from a file.
#include <optional>
#include <string>
#include <vector>

#include "prescription/LensTable.h"

namespace lenslab {

enum class VariableKind {
    Curvature,  // 1 / radius of the row (0: flat), mm^-1: smooth through flat, unlike the radius
    Thickness,  // the gap after the row toward the film, mm; after the last row: the image distance
    Conic,      // conic constant k
    Asphere,    // even-asphere coefficient of r^(2 term + 2), term 0..7
    Index,      // the row's medium's nd (the glass becomes a model glass nd / Vd)
    Abbe,       // the row's medium's Vd (likewise)
};

const char* variableKindName(VariableKind kind);  // "curvature", "thickness", "conic", "asphere", "index", "abbe"
std::optional<VariableKind> parseVariableKind(const std::string& name);

struct DesignVariable {
    DesignVariable() = default;
    DesignVariable(VariableKind k, int r, int t = 0) : kind(k), row(r), term(t) {}

    VariableKind kind = VariableKind::Curvature;
    int row = 0;   // 0-based row of the table
    int term = 0;  // Asphere: which coefficient
    std::optional<double> lower, upper;  // the value is kept inside these

    bool operator==(const DesignVariable& o) const { return kind == o.kind && row == o.row && term == o.term; }
};

// "curvature 3", "thickness 6 (image distance)", "asphere r^6 2": surfaces counted from 1 as the
// file's readers count them.
std::string describeVariable(const LensTable& table, const DesignVariable& v);

// Throws std::invalid_argument naming the variable when it does not apply to the table (a row out
// of range, a thickness in a gap-before table's last row, a glass term on an air gap or a mirror).
void checkVariable(const LensTable& table, const DesignVariable& v);

double variableValue(const LensTable& table, const DesignVariable& v);

// Sets the value (clamped to the variable's bounds). A catalog glass whose nd or Vd is set becomes
// the model glass of its own nd and Vd first (modelGlassOf); a curvature of 0 makes the row flat.
void setVariableValue(LensTable& table, const DesignVariable& v, double value);

// The row's glass as a model glass of the catalog's nd and Vd (a no-op for one already so).
void makeModelGlass(LensTable& table, int row);

// A value that follows another: target = scale x source + offset (Zemax's pick-up solve).
struct Pickup {
    DesignVariable target, source;
    double scale = 1, offset = 0;
};

// What the design holds fixed while the variables move: pick-ups applied in order, then the
// image distance solved so that the paraxial marginal ray meets the axis on the image plane.
struct DesignRules {
    std::vector<Pickup> pickups;
    bool marginalRayImageSolve = false;  // needs a gap-after table: the last row's gap is the image distance
};

// Applies the rules to a table whose variables have been set. Throws OpticsError when the solve has
// no finite answer (an afocal lens).
void applyDesignRules(LensTable& table, const DesignRules& rules);

// The table's own image plane: the last row's gap in a gap-after table (nullopt for a gap-before
// table, which ends at its last surface).
std::optional<double> imageDistance(const LensTable& table);

}  // namespace lenslab
