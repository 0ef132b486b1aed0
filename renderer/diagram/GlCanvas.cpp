#include "GlCanvas.h"

#include <algorithm>
#include <cstddef>
#include <string>

#include "GlFunctions.h"
#include "LensDiagram.h"

namespace lenslab {

namespace {

// Picture y runs down and maps to framebuffer row y, so glReadPixels returns the top row first.
const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec2 position;
layout(location = 1) in vec4 colour;
uniform vec2 pictureSize;
out vec4 vertexColour;
void main() {
    gl_Position = vec4(2.0 * position / pictureSize - 1.0, 0.0, 1.0);
    vertexColour = colour;
})";

const char* const kFragmentShader = R"(#version 330 core
in vec4 vertexColour;
out vec4 fragmentColour;
void main() { fragmentColour = vertexColour; })";

constexpr int kWantedSamples = 8;

GLuint compileShader(GLenum kind, const char* source) {
    const GLuint shader = gl.CreateShader(kind);
    gl.ShaderSource(shader, 1, &source, nullptr);
    gl.CompileShader(shader);
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[512] = "";
        gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
        gl.DeleteShader(shader);
        throw DiagramError(std::string("diagram shader does not compile: ") + log);
    }
    return shader;
}

GLuint linkProgram() {
    const GLuint vertex = compileShader(GL_VERTEX_SHADER, kVertexShader);
    const GLuint fragment = compileShader(GL_FRAGMENT_SHADER, kFragmentShader);
    const GLuint program = gl.CreateProgram();
    gl.AttachShader(program, vertex);
    gl.AttachShader(program, fragment);
    gl.LinkProgram(program);
    gl.DeleteShader(vertex);
    gl.DeleteShader(fragment);
    GLint ok = GL_FALSE;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        gl.DeleteProgram(program);
        throw DiagramError("diagram shader program does not link");
    }
    return program;
}

void makeFramebuffer(GLuint& framebuffer, GLuint& colour, int samples, int width, int height) {
    gl.GenFramebuffers(1, &framebuffer);
    gl.GenRenderbuffers(1, &colour);
    gl.BindRenderbuffer(GL_RENDERBUFFER, colour);
    if (samples > 1) gl.RenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
    else gl.RenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    gl.BindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw DiagramError("cannot allocate a " + std::to_string(width) + "x" + std::to_string(height) +
                           " framebuffer (" + std::to_string(samples) + " samples)");
}

}  // namespace

GlCanvas::GlCanvas() {
    program_ = linkProgram();
    pictureSizeLocation_ = gl.GetUniformLocation(program_, "pictureSize");
    gl.GenVertexArrays(1, &vertexArray_);
    gl.BindVertexArray(vertexArray_);
    gl.GenBuffers(1, &vertexBuffer_);
    gl.BindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, x)));
    gl.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                           reinterpret_cast<void*>(offsetof(Vertex, colour)));
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(1);
}

GlCanvas::~GlCanvas() {
    releaseFramebuffers();
    gl.DeleteBuffers(1, &vertexBuffer_);
    gl.DeleteVertexArrays(1, &vertexArray_);
    gl.DeleteProgram(program_);
}

void GlCanvas::releaseFramebuffers() {
    gl.DeleteRenderbuffers(1, &resolveColour_);
    gl.DeleteRenderbuffers(1, &multisampleColour_);
    gl.DeleteFramebuffers(1, &resolveFramebuffer_);
    gl.DeleteFramebuffers(1, &multisampleFramebuffer_);
    resolveColour_ = multisampleColour_ = resolveFramebuffer_ = multisampleFramebuffer_ = 0;
    width_ = height_ = 0;
}

void GlCanvas::resize(int width, int height) {
    if (width == width_ && height == height_) return;
    releaseFramebuffers();
    GLint maxSize = 0, maxSamples = 0;
    gl.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
    gl.GetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    if (width > maxSize || height > maxSize)
        throw DiagramError("picture " + std::to_string(width) + "x" + std::to_string(height) +
                           " exceeds this OpenGL's largest framebuffer (" + std::to_string(maxSize) + ")");
    makeFramebuffer(resolveFramebuffer_, resolveColour_, 1, width, height);
    makeFramebuffer(multisampleFramebuffer_, multisampleColour_, std::min(kWantedSamples, static_cast<int>(maxSamples)),
                    width, height);
    width_ = width;
    height_ = height;
}

std::vector<std::uint8_t> GlCanvas::rasterise(const DrawList& list, int width, int height, Rgba background) {
    resize(width, height);
    gl.BindFramebuffer(GL_FRAMEBUFFER, multisampleFramebuffer_);
    gl.Viewport(0, 0, width, height);
    gl.ClearColor(background.r / 255.0f, background.g / 255.0f, background.b / 255.0f, background.a / 255.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT);

    gl.UseProgram(program_);
    gl.Uniform2f(pictureSizeLocation_, static_cast<float>(width), static_cast<float>(height));
    gl.BindVertexArray(vertexArray_);
    gl.BindBuffer(GL_ARRAY_BUFFER, vertexBuffer_);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(list.vertices.size() * sizeof(Vertex)),
                  list.vertices.data(), GL_STREAM_DRAW);
    gl.Enable(GL_BLEND);
    gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.DrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(list.vertices.size()));

    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, multisampleFramebuffer_);
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFramebuffer_);
    gl.BlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, resolveFramebuffer_);
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * height * 4);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    if (gl.GetError() != GL_NO_ERROR) throw DiagramError("OpenGL reported an error while drawing the diagram");
    return pixels;
}

}  // namespace lenslab
