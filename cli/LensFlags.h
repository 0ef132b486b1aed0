#pragma once
// The lens settings every subcommand takes the same way: --fstop N and --focus MM|inf, each
// carried with its flag's name so that optics' one check (analyzeLens) can blame the flag.
#include "ArgParser.h"
#include "settings/LensSettings.h"

namespace lenslab {

// Declares --fstop and --focus on `p` (call before parse()).
void declareLensFlags(ArgParser& p);
// The flags given, as settings (none given: the widest stop, focused at infinity).
LensSettings lensFlags(const ArgParser& p);

}  // namespace lenslab
