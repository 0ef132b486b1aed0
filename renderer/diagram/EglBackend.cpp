// EGL without a window: Mesa's surfaceless platform, else the first EGL device. Without a GPU
// Mesa runs it on llvmpipe; with one, on the GPU.
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <mutex>
#include <string>

#include "DiagramBackend.h"
#include "GlLoader.h"

namespace lenslab {

namespace {

struct EglDisplay {
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string error;
};

EGLDisplay initialize(EGLDisplay display) {
    if (display == EGL_NO_DISPLAY) return EGL_NO_DISPLAY;
    EGLint major = 0, minor = 0;
    return eglInitialize(display, &major, &minor) ? display : EGL_NO_DISPLAY;
}

EGLDisplay openDeviceDisplay() {
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    if (!queryDevices) return EGL_NO_DISPLAY;
    EGLDeviceEXT device = nullptr;
    EGLint count = 0;
    if (!queryDevices(1, &device, &count) || count < 1) return EGL_NO_DISPLAY;
    return initialize(eglGetPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr));
}

// EGL displays are process-wide and eglTerminate is not reference counted, so the display is
// opened once and kept: a thread terminating it would pull it from under the others.
const EglDisplay& sharedDisplay() {
    static EglDisplay shared;
    static std::once_flag once;
    std::call_once(once, [] {
        shared.display = initialize(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
        if (shared.display == EGL_NO_DISPLAY) shared.display = openDeviceDisplay();
        if (shared.display == EGL_NO_DISPLAY)
            shared.error = "EGL backend: neither the surfaceless platform nor an EGL device could be initialised";
    });
    return shared;
}

class EglBackend : public DiagramBackend {
public:
    EglBackend() {
        const EglDisplay& shared = sharedDisplay();
        if (shared.display == EGL_NO_DISPLAY) throw DiagramError(shared.error);
        display_ = shared.display;
        if (!eglBindAPI(EGL_OPENGL_API)) throw DiagramError("EGL backend: desktop OpenGL is not available");
        const EGLint configAttributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                           EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (!eglChooseConfig(display_, configAttributes, &config, 1, &count) || count < 1)
            throw DiagramError("EGL backend: no RGB8 OpenGL configuration");
        const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                            EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                            EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttributes);
        if (context_ == EGL_NO_CONTEXT) throw DiagramError("EGL backend: cannot create an OpenGL 3.3 core context");
        try {
            makeCurrent();
        } catch (...) {
            release();
            throw;
        }
    }
    void makeCurrent() override {
        // Surfaceless: all drawing goes to framebuffer objects.
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw DiagramError("EGL backend: cannot make a context current without a surface");
        loadGlFunctions(eglGetProcAddress);
    }
    void releaseCurrent() override { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }
    ~EglBackend() override { release(); }
    const char* name() const override { return "egl"; }

private:
    void release() {
        releaseCurrent();
        eglDestroyContext(display_, context_);
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<DiagramBackend> createEglBackend() { return std::make_unique<EglBackend>(); }

}  // namespace lenslab
