// libFuzzer target: arbitrary bytes as a Code V .seq file, parsed directly and through the content
// dispatch of parseLensTable, then built into a lens. Refusals must be LensTableError with a
// message (OpticsError from the geometry); an accepted table must hold what the builder relies on.
// Anything else escaping, a crash or a sanitizer report is a finding.
#include <cmath>
#include <cstdint>
#include <string>

#include "PrescriptionInvariants.h"
#include "prescription/CodeVFile.h"
#include "prescription/LensSystem.h"
#include "prescription/OpticsError.h"

using namespace lenslab;
using lenslab::fuzz::check;

namespace {

void checkTable(const LensTable& t) {
    check(t.format == "seq" && t.layout == TableLayout::GapAfter, "a .seq is a gap-after seq table");
    int stops = 0;
    for (const LensTableRow& r : t.rows) {
        stops += r.stop;
        fuzz::checkRowGeometry(r);
        fuzz::checkRowDiameter(r);
        check(r.index == 0 || r.index > 1, "index 0 (air) or > 1");
        fuzz::checkRowMedium(r);
        if (r.frame) {
            for (double d : r.frame->decentre) check(std::isfinite(d), "finite decentres");
            for (double a : r.frame->tiltDegrees) check(std::isfinite(a), "finite tilts");
        }
    }
    fuzz::checkTableWhole(t, stops);
    check(t.wavelengths.size() == t.wavelengthWeights.size(), "a weight per wavelength");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const LensTable t = parseCodeV(bytes, "fuzz.seq");
        checkTable(t);
        try {
            const LensSystem lens = buildLensSystem(t);
            for (const Surface& s : lens.surfaces) check(std::isfinite(s.z) && s.apertureRadius >= 0, "finite geometry built");
        } catch (const LensTableError& e) {
            check(!e.problem().empty(), "a refusal says why");
        } catch (const OpticsError& e) {
            check(*e.what() != 0, "a refusal says why");
        }
    } catch (const LensTableError& e) {
        check(!e.problem().empty(), "a refusal says why");
    }
    try {
        const LensTable t = parseLensTable(bytes, "fuzz.seq");
        check(t.format == "seq" || t.format == "zmx" || t.format == "table", "a known format");
    } catch (const LensTableError& e) {
        check(!e.problem().empty(), "a refusal says why");
    }
    return 0;
}
