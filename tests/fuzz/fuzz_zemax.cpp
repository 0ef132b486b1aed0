// libFuzzer target: arbitrary bytes as a Zemax .zmx file, parsed directly and through the
// content dispatch of parseLensTable. Refusals must be LensTableError with a message; an accepted
// table must hold what the geometry builder relies on. Anything else escaping, a crash or a
// sanitizer report is a finding.
#include <cmath>
#include <cstdint>
#include <string>

#include "PrescriptionInvariants.h"
#include "prescription/LensTable.h"
#include "prescription/ZemaxFile.h"

using namespace lenslab;
using lenslab::fuzz::check;

namespace {

void checkTable(const LensTable& t) {
    check(t.format == "zmx" && t.layout == TableLayout::GapAfter, "a .zmx is a gap-after zmx table");
    int stops = 0, mirrors = 0;
    for (const LensTableRow& r : t.rows) {
        stops += r.stop;
        mirrors += r.mirror;
        fuzz::checkRowGeometry(r);
        if (r.coordinateBreak) {
            check(r.frame.has_value() && r.diameter == 0, "a coordinate break carries a frame, no aperture");
            continue;
        }
        fuzz::checkRowDiameter(r);
        check(r.obscurationDiameter >= 0 && (r.automaticDiameter || r.obscurationDiameter < r.diameter),
              "obscuration inside the aperture");
        check(r.index == 0 || r.index >= 1, "index 0 (air) or >= 1");
        fuzz::checkRowMedium(r);
        check(r.gap >= 0 || mirrors % 2 == 1, "negative gaps only after an odd number of mirrors");
    }
    fuzz::checkTableWhole(t, stops);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        checkTable(parseZemax(bytes, "fuzz.zmx"));
    } catch (const LensTableError& e) {
        check(!e.problem().empty(), "a refusal says why");
    }
    try {
        const LensTable t = parseLensTable(bytes, "fuzz.zmx");
        check(looksLikeZemax(bytes) == (t.format == "zmx"), "dispatch by content");
    } catch (const LensTableError& e) {
        check(!e.problem().empty(), "a refusal says why");
    }
    return 0;
}
