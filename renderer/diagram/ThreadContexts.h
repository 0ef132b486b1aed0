#pragma once
// One GL context and canvas per thread and backend, made on first use and kept until the thread
// ends: a fresh llvmpipe context recompiles its shaders and pipeline, which costs several times
// the drawing itself. Server worker threads thus pay it once.
#include "GlCanvas.h"
#include "LensDiagram.h"

namespace lenslab {

// This thread's canvas for `kind` (Auto: EGL, else OSMesa), with its context made current.
// Throws DiagramError when the backend cannot start.
GlCanvas& threadCanvas(DiagramBackendKind kind);

}  // namespace lenslab
