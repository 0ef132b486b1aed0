#pragma once
// Rasterises DrawLists with the GL context current on this thread: a multisampled framebuffer
// object, resolved and read back. The program, buffers and framebuffers are made once and kept,
// because compiling and allocating them costs more than drawing a diagram.
#include <cstdint>
#include <vector>

#include "DrawList.h"

namespace lenslab {

class GlCanvas {
public:
    GlCanvas();  // needs its context current; throws DiagramError if the shaders fail
    ~GlCanvas();  // needs its context current
    GlCanvas(const GlCanvas&) = delete;
    GlCanvas& operator=(const GlCanvas&) = delete;

    // Returns width*height RGBA8 pixels, top row first, drawn over `background`. Throws
    // DiagramError when the context cannot hold a framebuffer of that size.
    std::vector<std::uint8_t> rasterise(const DrawList& list, int width, int height, Rgba background);

private:
    void resize(int width, int height);
    void releaseFramebuffers();

    unsigned program_ = 0, vertexArray_ = 0, vertexBuffer_ = 0;
    unsigned multisampleFramebuffer_ = 0, resolveFramebuffer_ = 0;
    unsigned multisampleColour_ = 0, resolveColour_ = 0;
    int width_ = 0, height_ = 0;
    int pictureSizeLocation_ = -1;
};

}  // namespace lenslab
