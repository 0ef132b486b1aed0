#pragma once
// Lens tables for the design tests, written row by row (gap-after, like a .zmx): the tables
// themselves, not built lenses, since the design varies the table.
#include <string>
#include <vector>

#include "PrescriptionRows.h"

namespace lenslab::test {

inline LensTable tableOfRows(std::vector<LensTableRow> rows, const std::string& name = "design-rows") {
    LensTable t;
    t.name = name;
    t.layout = TableLayout::GapAfter;
    for (std::size_t i = 0; i < rows.size(); ++i) rows[i].line = int(i) + 1;
    t.rows = std::move(rows);
    return t;
}

// A row whose clear aperture is left to the program (sized from the beam, clipping nothing).
inline LensTableRow openRow(double radius, double gap, double index, double abbe = 0) {
    LensTableRow r = row(radius, gap, index, 0);
    r.abbe = abbe;
    r.automaticDiameter = true;
    return r;
}

// The table with its stop's clear aperture stated (the other apertures stay automatic).
inline LensTable withStopDiameter(LensTable table, double diameter) {
    for (LensTableRow& r : table.rows)
        if (r.stop) {
            r.automaticDiameter = false;
            r.diameter = diameter;
        }
    return table;
}

inline const char* cookeTripletPath() { return LENSLAB_SOURCE_DIR "/lenses/design/cooke-triplet-50mm.zmx"; }

}  // namespace lenslab::test
