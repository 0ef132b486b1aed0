#pragma once
// The OpenGL entry points the diagram uses, loaded per thread from the current backend (OSMesa or
// EGL). lenslab links libOSMesa and libEGL but not libGL/libOpenGL: calling gl* symbols directly
// would bind them to one dispatch library, and OSMesa contexts would then silently draw nothing.
// The table is thread_local because threads may use different backends at the same time.
#include <GL/glcorearb.h>

#include "GlLoader.h"

namespace lenslab {

#define LENSLAB_GL_FUNCTIONS(X)                                              \
    X(PFNGLGETSTRINGPROC, GetString, glGetString)                           \
    X(PFNGLGETINTEGERVPROC, GetIntegerv, glGetIntegerv)                     \
    X(PFNGLGETERRORPROC, GetError, glGetError)                              \
    X(PFNGLVIEWPORTPROC, Viewport, glViewport)                              \
    X(PFNGLCLEARCOLORPROC, ClearColor, glClearColor)                        \
    X(PFNGLCLEARPROC, Clear, glClear)                                       \
    X(PFNGLENABLEPROC, Enable, glEnable)                                    \
    X(PFNGLBLENDFUNCPROC, BlendFunc, glBlendFunc)                           \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers, glGenFramebuffers)         \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers, glDeleteFramebuffers) \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer, glBindFramebuffer)         \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus, glCheckFramebufferStatus) \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer, glFramebufferRenderbuffer) \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers, glGenRenderbuffers)      \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers, glDeleteRenderbuffers) \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer, glBindRenderbuffer)      \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage, glRenderbufferStorage) \
    X(PFNGLRENDERBUFFERSTORAGEMULTISAMPLEPROC, RenderbufferStorageMultisample, glRenderbufferStorageMultisample) \
    X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer, glBlitFramebuffer)         \
    X(PFNGLREADPIXELSPROC, ReadPixels, glReadPixels)                        \
    X(PFNGLPIXELSTOREIPROC, PixelStorei, glPixelStorei)                     \
    X(PFNGLCREATESHADERPROC, CreateShader, glCreateShader)                  \
    X(PFNGLSHADERSOURCEPROC, ShaderSource, glShaderSource)                  \
    X(PFNGLCOMPILESHADERPROC, CompileShader, glCompileShader)               \
    X(PFNGLGETSHADERIVPROC, GetShaderiv, glGetShaderiv)                     \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog, glGetShaderInfoLog)      \
    X(PFNGLDELETESHADERPROC, DeleteShader, glDeleteShader)                  \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram, glCreateProgram)               \
    X(PFNGLATTACHSHADERPROC, AttachShader, glAttachShader)                  \
    X(PFNGLLINKPROGRAMPROC, LinkProgram, glLinkProgram)                     \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv, glGetProgramiv)                  \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog, glGetProgramInfoLog)   \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram, glDeleteProgram)               \
    X(PFNGLUSEPROGRAMPROC, UseProgram, glUseProgram)                        \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation, glGetUniformLocation) \
    X(PFNGLUNIFORM2FPROC, Uniform2f, glUniform2f)                           \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays, glGenVertexArrays)         \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays, glDeleteVertexArrays) \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray, glBindVertexArray)         \
    X(PFNGLGENBUFFERSPROC, GenBuffers, glGenBuffers)                        \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers, glDeleteBuffers)               \
    X(PFNGLBINDBUFFERPROC, BindBuffer, glBindBuffer)                        \
    X(PFNGLBUFFERDATAPROC, BufferData, glBufferData)                        \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer, glVertexAttribPointer) \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray, glEnableVertexAttribArray) \
    X(PFNGLDRAWARRAYSPROC, DrawArrays, glDrawArrays)

struct GlFunctions {
#define LENSLAB_GL_MEMBER(type, member, symbol) type member = nullptr;
    LENSLAB_GL_FUNCTIONS(LENSLAB_GL_MEMBER)
#undef LENSLAB_GL_MEMBER
};

// The table for the context current on this thread.
extern thread_local GlFunctions gl;

}  // namespace lenslab
