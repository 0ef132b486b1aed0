#pragma once
// Lens tables for the design tests (tableOfRows: the tables themselves, not built lenses, since the
// design varies the table), and the Cooke triplet they start from.
#include <string>
#include <vector>

#include "PrescriptionRows.h"

namespace lenslab::test {

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
