// OSMesa: Mesa's software rasteriser (llvmpipe) with no display and no GPU; the default backend.
#include <GL/osmesa.h>

#include "DiagramBackend.h"
#include "GlLoader.h"

namespace lenslab {

namespace {

class OSMesaBackend : public DiagramBackend {
public:
    OSMesaBackend() {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0,
                                  OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
        context_ = OSMesaCreateContextAttribs(attributes, nullptr);
        if (!context_) throw DiagramError("OSMesa backend: cannot create an OpenGL 3.3 core context");
        try {
            makeCurrent();
        } catch (...) {
            release();
            throw;
        }
    }
    void makeCurrent() override {
        // Drawing goes to framebuffer objects; OSMesa only needs some buffer to make current.
        if (!OSMesaMakeCurrent(context_, &pixel_, GL_UNSIGNED_BYTE, 1, 1))
            throw DiagramError("OSMesa backend: cannot make the context current");
        loadGlFunctions(OSMesaGetProcAddress);
    }
    void releaseCurrent() override { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }
    ~OSMesaBackend() override { release(); }
    const char* name() const override { return "osmesa"; }

private:
    void release() {
        releaseCurrent();
        OSMesaDestroyContext(context_);
    }

    OSMesaContext context_ = nullptr;
    unsigned int pixel_ = 0;
};

}  // namespace

std::unique_ptr<DiagramBackend> createOSMesaBackend() { return std::make_unique<OSMesaBackend>(); }

}  // namespace lenslab
