#pragma once
// Loading this thread's GL function table, declared without any GL header so the backends can
// include their platform headers (osmesa.h pulls in GL/gl.h, which clashes with glcorearb.h).

namespace lenslab {

using GlProcLoader = void (*(*)(const char* name))();

// Fills this thread's table (GlFunctions.h) from the backend's loader. Throws DiagramError naming
// the first entry point the loader does not provide.
void loadGlFunctions(GlProcLoader loader);

}  // namespace lenslab
