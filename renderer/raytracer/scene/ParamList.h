#pragma once
// A directive's parameter list ("TYPE NAME" value ...) read from the tokens, with pbrt-v3's and
// pbrt-v2's type names. Spectral values ("spectrum" pairs or .spd files, "blackbody", "xyz")
// arrive as RGB, the renderer's colour space.
#include "core/ParamSet.h"
#include "scene/TokenCursor.h"

namespace lenslab {

ParamSet readParamList(TokenCursor& in, const SourceLocation& where, const PathResolver& resolve);

}  // namespace lenslab
