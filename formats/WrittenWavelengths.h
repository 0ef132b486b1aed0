#pragma once
// The wavelengths a prescription writer lists (.zmx WAVM, .seq WL): the table's, with its primary
// among them, so that the file can name it (PWAV, REF).
#include <algorithm>
#include <vector>

#include "prescription/LensTable.h"

namespace lenslab {

// The table's wavelengths, the primary added at the end where the list lacks it; none where the
// table lists none and its primary is the d line, which a file without wavelengths is read at.
inline std::vector<double> writtenWavelengths(const LensTable& table) {
    std::vector<double> nm = table.wavelengths;
    if (std::find(nm.begin(), nm.end(), table.primaryWavelength) == nm.end() &&
        (!nm.empty() || table.primaryWavelength != kWavelengthD))
        nm.push_back(table.primaryWavelength);
    return nm;
}

}  // namespace lenslab
