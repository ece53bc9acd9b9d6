#pragma once
// Per-context table of the OpenGL 3.3 core entry points SDF Workbench uses.
//
// libOSMesa and libGL both export every gl* symbol, so a binary that called
// GL through linked symbols would reach whichever library the linker picked,
// not the context that is current. Every GL call in the project therefore
// goes through a GlFunctions table filled from the loader of the context it
// belongs to: `gl.CompileShader(shader)`. There are no global gl symbols.

// GL/gl.h declares GL 1.0/1.1 and defines GL_VERSION_1_1, so a glcorearb.h
// included after it skips the typedefs of those functions (PFNGLDRAWARRAYSPROC
// and others), and the table below fails to compile with puzzling errors.
#if defined(__gl_h_) && !defined(__gl_glcorearb_h_)
#error "GL/gl.h was included before glcontext/gl_functions.h; define GLFW_INCLUDE_NONE before <GLFW/glfw3.h>, or include this header first"
#endif
#include <GL/glcorearb.h>

#include <functional>

#include "glcontext/gl_error.h"

namespace sdfwb::glcontext {

// An entry point as loaders return it (GLFW's GLFWglproc, OSMesa's OSMESAproc).
using GlProc = void (*)();

// Looks up an entry point by its full name ("glCompileShader"); returns null
// when the context does not have it. glfwGetProcAddress and
// OSMesaGetProcAddress fit as they are.
using ProcLoader = std::function<GlProc(const char* name)>;

// The entry points, each listed once: X(PFN type from glcorearb.h, name
// without the "gl" prefix). The struct members and the loader are both
// generated from this list, so they cannot drift apart.
#define SDFWB_GL_FUNCTIONS(X)                                          \
  /* Shaders and programs */                                           \
  X(PFNGLCREATESHADERPROC, CreateShader)                               \
  X(PFNGLSHADERSOURCEPROC, ShaderSource)                               \
  X(PFNGLCOMPILESHADERPROC, CompileShader)                             \
  X(PFNGLGETSHADERIVPROC, GetShaderiv)                                 \
  X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                       \
  X(PFNGLDELETESHADERPROC, DeleteShader)                               \
  X(PFNGLCREATEPROGRAMPROC, CreateProgram)                             \
  X(PFNGLATTACHSHADERPROC, AttachShader)                               \
  X(PFNGLDETACHSHADERPROC, DetachShader)                               \
  X(PFNGLLINKPROGRAMPROC, LinkProgram)                                 \
  X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                               \
  X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)                     \
  X(PFNGLUSEPROGRAMPROC, UseProgram)                                   \
  X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                             \
  X(PFNGLBINDATTRIBLOCATIONPROC, BindAttribLocation)                   \
  X(PFNGLBINDFRAGDATALOCATIONPROC, BindFragDataLocation)               \
  X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation)                     \
  /* Uniforms and uniform blocks */                                    \
  X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)                   \
  X(PFNGLGETUNIFORMINDICESPROC, GetUniformIndices)                     \
  X(PFNGLGETACTIVEUNIFORMSIVPROC, GetActiveUniformsiv)                 \
  X(PFNGLUNIFORM1IPROC, Uniform1i)                                     \
  X(PFNGLUNIFORM2IPROC, Uniform2i)                                     \
  X(PFNGLUNIFORM3IPROC, Uniform3i)                                     \
  X(PFNGLUNIFORM4IPROC, Uniform4i)                                     \
  X(PFNGLUNIFORM1UIPROC, Uniform1ui)                                   \
  X(PFNGLUNIFORM1FPROC, Uniform1f)                                     \
  X(PFNGLUNIFORM2FPROC, Uniform2f)                                     \
  X(PFNGLUNIFORM3FPROC, Uniform3f)                                     \
  X(PFNGLUNIFORM4FPROC, Uniform4f)                                     \
  X(PFNGLUNIFORM1IVPROC, Uniform1iv)                                   \
  X(PFNGLUNIFORM1FVPROC, Uniform1fv)                                   \
  X(PFNGLUNIFORM2FVPROC, Uniform2fv)                                   \
  X(PFNGLUNIFORM3FVPROC, Uniform3fv)                                   \
  X(PFNGLUNIFORM4FVPROC, Uniform4fv)                                   \
  X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                       \
  X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                       \
  X(PFNGLGETUNIFORMBLOCKINDEXPROC, GetUniformBlockIndex)               \
  X(PFNGLGETACTIVEUNIFORMBLOCKIVPROC, GetActiveUniformBlockiv)         \
  X(PFNGLUNIFORMBLOCKBINDINGPROC, UniformBlockBinding)                 \
  /* Buffers */                                                        \
  X(PFNGLGENBUFFERSPROC, GenBuffers)                                   \
  X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                             \
  X(PFNGLBINDBUFFERPROC, BindBuffer)                                   \
  X(PFNGLBINDBUFFERBASEPROC, BindBufferBase)                           \
  X(PFNGLBINDBUFFERRANGEPROC, BindBufferRange)                         \
  X(PFNGLBUFFERDATAPROC, BufferData)                                   \
  X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                             \
  X(PFNGLMAPBUFFERRANGEPROC, MapBufferRange)                           \
  X(PFNGLUNMAPBUFFERPROC, UnmapBuffer)                                 \
  /* Textures, including buffer textures and float formats */          \
  X(PFNGLGENTEXTURESPROC, GenTextures)                                 \
  X(PFNGLDELETETEXTURESPROC, DeleteTextures)                           \
  X(PFNGLBINDTEXTUREPROC, BindTexture)                                 \
  X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                             \
  X(PFNGLTEXIMAGE2DPROC, TexImage2D)                                   \
  X(PFNGLTEXSUBIMAGE2DPROC, TexSubImage2D)                             \
  X(PFNGLTEXPARAMETERIPROC, TexParameteri)                             \
  X(PFNGLTEXBUFFERPROC, TexBuffer)                                     \
  X(PFNGLGETTEXIMAGEPROC, GetTexImage)                                 \
  X(PFNGLPIXELSTOREIPROC, PixelStorei)                                 \
  /* Framebuffers and renderbuffers */                                 \
  X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                         \
  X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)                   \
  X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                         \
  X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)               \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)           \
  X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                                 \
  X(PFNGLREADBUFFERPROC, ReadBuffer)                                   \
  X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                         \
  X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                             \
  X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                       \
  X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)                 \
  X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                       \
  X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)                 \
  X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)         \
  /* Vertex arrays and drawing */                                      \
  X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                         \
  X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)                   \
  X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                         \
  X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)         \
  X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)                 \
  X(PFNGLDRAWARRAYSPROC, DrawArrays)                                   \
  /* Fixed-function state */                                           \
  X(PFNGLVIEWPORTPROC, Viewport)                                       \
  X(PFNGLSCISSORPROC, Scissor)                                         \
  X(PFNGLENABLEPROC, Enable)                                           \
  X(PFNGLDISABLEPROC, Disable)                                         \
  X(PFNGLBLENDFUNCPROC, BlendFunc)                                     \
  X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)                     \
  X(PFNGLBLENDEQUATIONPROC, BlendEquation)                             \
  X(PFNGLCOLORMASKPROC, ColorMask)                                     \
  X(PFNGLCLEARCOLORPROC, ClearColor)                                   \
  X(PFNGLCLEARPROC, Clear)                                             \
  /* Reading back and queries */                                       \
  X(PFNGLREADPIXELSPROC, ReadPixels)                                   \
  X(PFNGLGETSTRINGPROC, GetString)                                     \
  X(PFNGLGETSTRINGIPROC, GetStringi)                                   \
  X(PFNGLGETINTEGERVPROC, GetIntegerv)                                 \
  X(PFNGLGETINTEGER64VPROC, GetInteger64v)                             \
  X(PFNGLGETERRORPROC, GetError)                                       \
  /* Synchronisation */                                                \
  X(PFNGLFLUSHPROC, Flush)                                             \
  X(PFNGLFINISHPROC, Finish)                                           \
  X(PFNGLFENCESYNCPROC, FenceSync)                                     \
  X(PFNGLCLIENTWAITSYNCPROC, ClientWaitSync)                           \
  X(PFNGLWAITSYNCPROC, WaitSync)                                       \
  X(PFNGLDELETESYNCPROC, DeleteSync)                                   \
  /* Timer queries */                                                  \
  X(PFNGLGENQUERIESPROC, GenQueries)                                   \
  X(PFNGLDELETEQUERIESPROC, DeleteQueries)                             \
  X(PFNGLBEGINQUERYPROC, BeginQuery)                                   \
  X(PFNGLENDQUERYPROC, EndQuery)                                       \
  X(PFNGLQUERYCOUNTERPROC, QueryCounter)                               \
  X(PFNGLGETQUERYOBJECTIVPROC, GetQueryObjectiv)                       \
  X(PFNGLGETQUERYOBJECTUI64VPROC, GetQueryObjectui64v)

// The entry points of one context. Calling one is valid only while the
// context it was loaded for is current on the calling thread. Plain data:
// copy it freely.
struct GlFunctions {
#define SDFWB_GL_DECLARE_MEMBER(type, name) type name = nullptr;
  SDFWB_GL_FUNCTIONS(SDFWB_GL_DECLARE_MEMBER)
#undef SDFWB_GL_DECLARE_MEMBER

  // Fills every entry point from `loader`. Throws GlError naming the first
  // entry point the loader does not provide ("OpenGL entry point glFenceSync
  // is missing"). Makes no GL call, so it does not check the context's
  // version: a loader may return stubs for functions the context lacks
  // (OSMesa does), see requireVersion() in gl_context.h.
  static GlFunctions load(const ProcLoader& loader);
};

}  // namespace sdfwb::glcontext
