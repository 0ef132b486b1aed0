#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>

#include "ArgParser.h"
#include "Commands.h"
#include "LensDiagram.h"
#include "LensFlags.h"

namespace lenslab {

namespace {

// "WxH" in pixels.
void parseSize(const std::string& text, DiagramOptions& options) {
    int width = 0, height = 0;
    char x = 0, extra = 0;
    if (std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) != 3 || (x != 'x' && x != 'X'))
        throw UsageError("diagram: --size expects WIDTHxHEIGHT in pixels, got '" + text + "'");
    options.width = width;
    options.height = height;
}

}  // namespace

int runDiagramCommand(const std::vector<std::string>& args) {
    ArgParser p("diagram",
                "FILE -o OUT.png [--mode exact|thick|overlay] [--colour] [--fstop N] [--focus MM|inf] [--wavelength NM]\n"
                "        [--field MM] [--rays N] [--size WxH] [--backend osmesa|egl|auto]",
                "Draws the lens cross-section (front to the left) with ray fans traced forward from the object\n"
                "side on the axis and at one field, folded by any mirrors (their holes and obscurations drawn),\n"
                "the stop at the chosen f-number, F, F', P, P', the pupils and the film, offscreen with OpenGL,\n"
                "and writes a PNG. A mirror lens gets no thick-lens rays (the picture says so).");
    p.positional("FILE", "lens table (.dat) or Zemax prescription (.zmx)");
    p.option("-o", "OUT.png", "the PNG to write");
    p.option("--mode", "M", "exact (real rays), thick (thick-lens rays) or overlay (both); default exact");
    p.flag("--colour", "exact fans at the F, d and C lines in blue, yellow and red (the colour spread)");
    declareLensFlags(p);
    p.option("--field", "MM", "film height of the off-axis fan's chief ray in mm; 0 for the axial fan only (default: 70% of the largest field)");
    p.option("--rays", "N", "rays per fan (default 9)");
    p.option("--size", "WxH", "picture size in pixels (default 1200x600)");
    p.option("--backend", "B", "osmesa (default), egl, or auto (EGL, else OSMesa)");
    if (!p.parse(args)) {
        std::cout << p.help();
        return 0;
    }
    if (!p.has("-o")) throw UsageError("diagram: -o OUT.png is required");

    DiagramOptions options;
    if (p.has("--mode")) options.mode = parseDiagramMode(p.get("--mode"));
    if (p.has("--backend")) options.backend = parseDiagramBackend(p.get("--backend"));
    options.lens = lensFlags(p);
    options.colourFans = p.has("--colour");
    options.fieldHeight = p.number("--field");
    if (const auto rays = p.integer("--rays")) {
        if (*rays < 1 || *rays > std::numeric_limits<int>::max())
            throw UsageError("diagram: --rays must be a positive count, got " + p.get("--rays"));
        options.rays = static_cast<int>(*rays);
    }
    if (p.has("--size")) parseSize(p.get("--size"), options);

    const std::vector<std::uint8_t> png = drawLensDiagramPng(loadLensSystem(p.arg(0)), options);
    const std::string out = p.get("-o");
    std::ofstream file(out, std::ios::binary);
    file.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    if (!file.flush()) throw std::runtime_error("cannot write " + out);
    std::cout << "wrote " << out << " (" << options.width << "x" << options.height << ", " << png.size() << " bytes)\n";
    return 0;
}

}  // namespace lenslab
