#pragma once
// Lenses written row by row in a test (gap-after, like a .zmx): plain rows, the stop, and the
// Cartesian plano-convex singlet that several tests use as their aberration-free reference.
#include <cmath>
#include <string>
#include <vector>

#include "prescription/LensSystem.h"

namespace lenslab::test {

inline LensTableRow row(double radius, double gap, double index, double diameter) {
    LensTableRow r;
    r.radius = radius;
    r.gap = gap;
    r.index = index;
    r.diameter = diameter;
    return r;
}

inline LensTableRow stopRow(double gap, double diameter) {
    LensTableRow r = row(0, gap, 0, diameter);
    r.stop = true;
    return r;
}

// The rows as a gap-after table named `name`, each on its own line.
inline LensTable tableOfRows(std::vector<LensTableRow> rows, const std::string& name = "test-rows") {
    LensTable t;
    t.name = name;
    t.layout = TableLayout::GapAfter;
    for (std::size_t i = 0; i < rows.size(); ++i) rows[i].line = int(i) + 1;
    t.rows = std::move(rows);
    return t;
}

// The same, built into a lens.
inline LensSystem buildRows(std::vector<LensTableRow> rows, const std::string& name = "test-rows") {
    return buildLensSystem(tableOfRows(std::move(rows), name));
}

// Stop, flat face, then the convex face leaving glass of index n (centre of curvature on the scene
// side: a negative radius); paraxial f = R / (n - 1). Conic -n^2 makes the axial image perfect.
inline LensSystem planoConvex(double n, double f, double conic) {
    const double radius = -(n - 1) * f, diameter = 0.8 * std::fabs(radius);
    LensTableRow back = row(radius, 0, 0, diameter);
    back.conic = conic;
    return buildRows({stopRow(1, diameter), row(0, 8, n, diameter), back});
}

}  // namespace lenslab::test
