// Bad requests give clear errors, never a crash or a picture.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "DiagramTestSupport.h"
#include "prescription/LensTable.h"
#include "prescription/OpticsError.h"

namespace lenslab::test {
namespace {

template <class Error>
std::string messageOf(const LensSystem& lens, const DiagramOptions& options) {
    try {
        drawLensDiagramPng(lens, options);
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error thrown";
    return "";
}

TEST(DiagramBadInput, UnknownLensFileNamesThePath) {
    try {
        loadLensSystem("/no/such/lens.dat");
        FAIL() << "no error";
    } catch (const LensTableError& e) {
        EXPECT_NE(std::string(e.what()).find("/no/such/lens.dat"), std::string::npos) << e.what();
    }
}

TEST(DiagramBadInput, InvalidFstop) {
    const LensSystem lens = loadBundledLens("dgauss.50mm");
    DiagramOptions o;
    // Optics checks every f-number, and the message starts with where it came from.
    for (double bad : {0.0, -2.0, std::nan(""), std::numeric_limits<double>::infinity(), 1.0, 64.5}) {
        o.lens.fstop = Setting{bad, "--fstop"};
        const std::string message = messageOf<OpticsError>(lens, o);
        EXPECT_EQ(message.rfind("--fstop: f-number", 0), 0u) << message;
        EXPECT_NE(message.find("range f/2.02 to f/64"), std::string::npos) << message;
    }
}

TEST(DiagramBadInput, AbsurdSizes) {
    const LensSystem lens = loadBundledLens("dgauss.50mm");
    for (auto [w, h] : {std::pair{0, 0}, std::pair{100000, 100000}, std::pair{1200, 0}, std::pair{-5, 600}}) {
        DiagramOptions o;
        o.width = w;
        o.height = h;
        const std::string message = messageOf<DiagramError>(lens, o);
        EXPECT_NE(message.find(std::to_string(w) + "x" + std::to_string(h)), std::string::npos) << message;
    }
}

TEST(DiagramBadInput, RaysFocusAndField) {
    const LensSystem lens = loadBundledLens("dgauss.50mm");
    DiagramOptions o;
    o.rays = 0;
    EXPECT_NE(messageOf<DiagramError>(lens, o).find("rays"), std::string::npos);
    o = {};
    o.lens.focusDistance = Setting{-10, "--focus"};
    EXPECT_EQ(messageOf<OpticsError>(lens, o).rfind("--focus: ", 0), 0u);
    o = {};
    o.lens.focusDistance = Setting{5, "--focus"};  // inside the front focal length
    EXPECT_EQ(messageOf<OpticsError>(lens, o).rfind("--focus: ", 0), 0u);
    o = {};
    o.fieldHeight = -1;
    EXPECT_NE(messageOf<DiagramError>(lens, o).find("field"), std::string::npos);
}

TEST(DiagramBadInput, UnknownModeAndBackendNameTheChoices) {
    EXPECT_EQ(parseDiagramMode("overlay"), DiagramMode::Overlay);
    EXPECT_EQ(parseDiagramBackend("egl"), DiagramBackendKind::EGL);
    try {
        parseDiagramMode("wireframe");
        FAIL();
    } catch (const DiagramError& e) {
        EXPECT_NE(std::string(e.what()).find("exact, thick or overlay"), std::string::npos);
    }
    try {
        parseDiagramBackend("vulkan");
        FAIL();
    } catch (const DiagramError& e) {
        EXPECT_NE(std::string(e.what()).find("osmesa, egl or auto"), std::string::npos);
    }
}

}  // namespace
}  // namespace lenslab::test
