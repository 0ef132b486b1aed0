#pragma once
// The lens cross-section with its ray fans, drawn offscreen with OpenGL and returned as PNG.
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "settings/LensSettings.h"
#include "prescription/LensSystem.h"

namespace lenslab {

enum class DiagramMode { Exact, Thick, Overlay };
enum class DiagramBackendKind { OSMesa, EGL, Auto };

struct DiagramOptions {
    DiagramMode mode = DiagramMode::Exact;
    LensSettings lens;                  // aperture and focus (default: widest, at infinity)
    std::optional<double> fieldHeight;  // mm on the film for the off-axis fan; nullopt: automatic
    int rays = 9;                       // rays per fan
    bool colourFans = false;            // exact fans at the F, d and C lines, in their colours
    int width = 1200, height = 600;     // pixels
    DiagramBackendKind backend = DiagramBackendKind::OSMesa;
};

// Bad options or a backend that cannot start.
class DiagramError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Parses "exact|thick|overlay" and "osmesa|egl|auto"; DiagramError naming the choices otherwise.
DiagramMode parseDiagramMode(const std::string& name);
DiagramBackendKind parseDiagramBackend(const std::string& name);

// Draws the diagram and encodes it as PNG. Safe to call from many threads at once. Throws
// DiagramError (options, backend) or OpticsError (fstop or focus outside the lens's range).
std::vector<std::uint8_t> drawLensDiagramPng(const LensSystem& lens, const DiagramOptions& options);

}  // namespace lenslab
