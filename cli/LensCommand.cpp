#include <iostream>
#include <limits>

#include "ArgParser.h"
#include "Commands.h"
#include "settings/LensAnalysis.h"
#include "LensFlags.h"
#include "LensJson.h"
#include "LensText.h"
#include "prescription/OpticsError.h"

namespace lenslab {

int runLensCommand(const std::vector<std::string>& args) {
    ArgParser p("lens", "FILE [--fstop N] [--focus MM|inf] [--layout gap-before|gap-after] [--json]",
                "Prints a lens's first-order data: focal length, cardinal points, stop, pupils,\n"
                "f-number range and the film position for a focus distance (mm from the front vertex).");
    p.positional("FILE", "lens table (.dat), Zemax (.zmx) or Code V (.seq) prescription");
    declareLensFlags(p);
    p.option("--layout", "L", "gap-before | gap-after (default: detect)");
    p.flag("--json", "print one JSON object");
    if (!p.parse(args)) {
        std::cout << p.help();
        return 0;
    }
    std::optional<TableLayout> layout;
    if (p.has("--layout")) {
        layout = parseLayoutName(p.get("--layout"));
        if (!layout) throw UsageError("lens: --layout must be gap-before or gap-after, got '" + p.get("--layout") + "'");
    }
    const LensAnalysis a = describeLens(loadLensSystem(p.arg(0), layout), lensFlags(p));
    if (p.has("--json")) std::cout << lensAnalysisJson(a).dump(2) << "\n";
    else std::cout << lensAnalysisText(a);
    return 0;
}

}  // namespace lenslab
