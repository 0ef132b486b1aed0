// libFuzzer target: arbitrary bytes as a Zemax glass catalog (.agf). Refusals must be
// LensTableError with a message; every glass accepted has a name, a formula with a finite index at
// the d line, and a wavelength range that is either absent or ordered. Anything else escaping, a
// crash or a sanitizer report is a finding.
#include <cmath>
#include <cstdint>
#include <string>

#include "FuzzCheck.h"
#include "prescription/GlassCatalogFile.h"
#include "prescription/LensTable.h"

using namespace lenslab;
using lenslab::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string bytes(reinterpret_cast<const char*>(data), size);
    try {
        const GlassCatalogFile catalog = parseGlassCatalogFile(bytes, "FUZZ.AGF");
        check(catalog.name == "FUZZ" && !catalog.glasses.empty(), "a named catalog with glasses");
        for (const Medium& glass : catalog.glasses) {
            check(!glass.name.empty() && glass.catalog == "FUZZ", "glasses are named and catalogued");
            check(glass.nd >= 1 && std::isfinite(glass.vd), "nd >= 1, finite Vd");
            const double n = refractiveIndex(glass, kWavelengthD);
            check(std::isfinite(n) && n > 0, "a finite index at the d line");
            check((glass.minNm == 0 && glass.maxNm == 0) || glass.maxNm > glass.minNm, "an ordered range");
        }
    } catch (const LensTableError& e) {
        check(!e.problem().empty(), "a refusal says why");
    }
    return 0;
}
