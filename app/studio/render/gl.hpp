#pragma once
/// \file gl.hpp
/// The one table of OpenGL functions the studio calls, loaded from glfwGetProcAddress (window) or
/// OSMesaGetProcAddress (headless), so both modes draw through the same code.

#include <GL/glcorearb.h>

#include <string>

// OpenGL 1.1 entry points have no PFN typedefs in Mesa's glcorearb.h.
typedef void(APIENTRYP PAGOR_PFNGLGENTEXTURESPROC)(GLsizei n, GLuint* textures);
typedef void(APIENTRYP PAGOR_PFNGLBINDTEXTUREPROC)(GLenum target, GLuint texture);
typedef void(APIENTRYP PAGOR_PFNGLDELETETEXTURESPROC)(GLsizei n, const GLuint* textures);
typedef void(APIENTRYP PAGOR_PFNGLDRAWELEMENTSPROC)(GLenum mode, GLsizei count, GLenum type,
                                                    const void* indices);
typedef void(APIENTRYP PAGOR_PFNGLDRAWARRAYSPROC)(GLenum mode, GLint first, GLsizei count);

namespace pagor::studio {

using GetProcAddress = void* (*)(const char* name);

#define PAGOR_GL_FUNCTIONS(X)                                  \
  X(PFNGLGETSTRINGPROC, GetString)                             \
  X(PFNGLGETERRORPROC, GetError)                               \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                         \
  X(PFNGLVIEWPORTPROC, Viewport)                               \
  X(PFNGLCLEARCOLORPROC, ClearColor)                           \
  X(PFNGLCLEARPROC, Clear)                                     \
  X(PFNGLENABLEPROC, Enable)                                   \
  X(PFNGLDISABLEPROC, Disable)                                 \
  X(PFNGLBLENDEQUATIONPROC, BlendEquation)                     \
  X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)             \
  X(PFNGLSCISSORPROC, Scissor)                                 \
  X(PFNGLDEPTHFUNCPROC, DepthFunc)                             \
  X(PFNGLDEPTHMASKPROC, DepthMask)                             \
  X(PFNGLFINISHPROC, Finish)                                   \
  X(PFNGLREADPIXELSPROC, ReadPixels)                           \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                         \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                 \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                 \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)           \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                           \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                           \
  X(PFNGLBUFFERDATAPROC, BufferData)                           \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                     \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)         \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
  X(PFNGLCREATESHADERPROC, CreateShader)                       \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                       \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                     \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                         \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)               \
  X(PFNGLDELETESHADERPROC, DeleteShader)                       \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                     \
  X(PFNGLATTACHSHADERPROC, AttachShader)                       \
  X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation)           \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                         \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                       \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)             \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                     \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                           \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)           \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                             \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                             \
  X(PFNGLUNIFORM4FPROC, Uniform4f)                             \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)               \
  X(PAGOR_PFNGLGENTEXTURESPROC, GenTextures)                   \
  X(PAGOR_PFNGLBINDTEXTUREPROC, BindTexture)                   \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                           \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                     \
  X(PAGOR_PFNGLDELETETEXTURESPROC, DeleteTextures)             \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                     \
  X(PAGOR_PFNGLDRAWELEMENTSPROC, DrawElements)                 \
  X(PAGOR_PFNGLDRAWARRAYSPROC, DrawArrays)                     \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                 \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                 \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)       \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)   \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)           \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)               \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)               \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)         \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer) \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)

/// Function pointers, named without the `gl` prefix: `gl.Clear(GL_COLOR_BUFFER_BIT)`.
struct Gl {
#define PAGOR_GL_DECLARE(type, name) type name = nullptr;
  PAGOR_GL_FUNCTIONS(PAGOR_GL_DECLARE)
#undef PAGOR_GL_DECLARE

  /// Loads every function through `get`. Returns false and names the first missing function in
  /// `error`, or says when the context is older than OpenGL 3.3.
  bool load(GetProcAddress get, std::string& error);
  /// "OpenGL <version>, <renderer>" of the current context.
  std::string describe() const;
};

}  // namespace pagor::studio
