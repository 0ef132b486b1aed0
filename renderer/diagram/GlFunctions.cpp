#include "GlFunctions.h"

#include <string>

#include "LensDiagram.h"

namespace lenslab {

thread_local GlFunctions gl;

void loadGlFunctions(GlProcLoader loader) {
    GlFunctions table;
#define LENSLAB_GL_LOAD(type, member, symbol)                                               \
    table.member = reinterpret_cast<type>(loader(#symbol));                                  \
    if (!table.member) throw DiagramError("OpenGL entry point " #symbol " is not available");
    LENSLAB_GL_FUNCTIONS(LENSLAB_GL_LOAD)
#undef LENSLAB_GL_LOAD
    gl = table;
}

}  // namespace lenslab
