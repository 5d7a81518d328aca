/* gl_fns.h: the GL entry points tests call themselves, in one table loaded through the test
 * context (test_gl_proc), so no test keeps a table of its own. */
#ifndef HFX_TEST_GL_FNS_H
#define HFX_TEST_GL_FNS_H

#include <GL/glcorearb.h>

/* GL 1.1's, by hand: a <GL/gl.h> included first hides glcorearb.h's typedefs for them. */
typedef void(APIENTRYP test_gl_draw_arrays)(GLenum, GLint, GLsizei);
typedef void(APIENTRYP test_gl_gen_textures)(GLsizei, GLuint *);
typedef void(APIENTRYP test_gl_delete_textures)(GLsizei, const GLuint *);
typedef void(APIENTRYP test_gl_bind_texture)(GLenum, GLuint);

#define TEST_GL_FNS(X) \
    X(PFNGLVIEWPORTPROC, Viewport) X(PFNGLCLEARCOLORPROC, ClearColor) X(PFNGLCLEARDEPTHPROC, ClearDepth) \
    X(PFNGLCLEARPROC, Clear) X(PFNGLENABLEPROC, Enable) X(PFNGLDISABLEPROC, Disable) \
    X(PFNGLISENABLEDPROC, IsEnabled) X(PFNGLCULLFACEPROC, CullFace) X(PFNGLFRONTFACEPROC, FrontFace) \
    X(PFNGLDEPTHFUNCPROC, DepthFunc) X(PFNGLDEPTHMASKPROC, DepthMask) X(PFNGLCOLORMASKPROC, ColorMask) \
    X(PFNGLBLENDFUNCPROC, BlendFunc) X(PFNGLBLENDEQUATIONPROC, BlendEquation) \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays) X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray) \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays) X(PFNGLGENBUFFERSPROC, GenBuffers) \
    X(PFNGLBINDBUFFERPROC, BindBuffer) X(PFNGLBUFFERDATAPROC, BufferData) X(PFNGLDELETEBUFFERSPROC, DeleteBuffers) \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer) \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
    X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray) X(test_gl_draw_arrays, DrawArrays) \
    X(test_gl_gen_textures, GenTextures) X(test_gl_delete_textures, DeleteTextures) \
    X(test_gl_bind_texture, BindTexture) X(PFNGLACTIVETEXTUREPROC, ActiveTexture) \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D) X(PFNGLTEXPARAMETERIPROC, TexParameteri) \
    X(PFNGLPIXELSTOREIPROC, PixelStorei) X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers) \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer) X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D) \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers) X(PFNGLGETSAMPLERPARAMETERIVPROC, GetSamplerParameteriv) \
    X(PFNGLGETSAMPLERPARAMETERFVPROC, GetSamplerParameterfv) X(PFNGLGETINTEGERVPROC, GetIntegerv) \
    X(PFNGLGETINTEGERI_VPROC, GetIntegeri_v) X(PFNGLGETFLOATVPROC, GetFloatv) \
    X(PFNGLGETBOOLEANI_VPROC, GetBooleani_v) X(PFNGLGETERRORPROC, GetError) X(PFNGLFINISHPROC, Finish) \
    X(PFNGLCREATESHADERPROC, CreateShader) X(PFNGLSHADERSOURCEPROC, ShaderSource) \
    X(PFNGLCOMPILESHADERPROC, CompileShader) X(PFNGLGETSHADERIVPROC, GetShaderiv) \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog) X(PFNGLDELETESHADERPROC, DeleteShader) \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram) X(PFNGLATTACHSHADERPROC, AttachShader) \
    X(PFNGLLINKPROGRAMPROC, LinkProgram) X(PFNGLGETPROGRAMIVPROC, GetProgramiv) \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog) X(PFNGLUSEPROGRAMPROC, UseProgram) \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram) X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation) \
    X(PFNGLGETUNIFORMFVPROC, GetUniformfv) X(PFNGLGETUNIFORMIVPROC, GetUniformiv) \
    X(PFNGLUNIFORM1IPROC, Uniform1i) X(PFNGLUNIFORM1IVPROC, Uniform1iv) X(PFNGLUNIFORM1FVPROC, Uniform1fv) \
    X(PFNGLUNIFORM2FVPROC, Uniform2fv) X(PFNGLUNIFORM3FVPROC, Uniform3fv) X(PFNGLUNIFORM4FVPROC, Uniform4fv) \
    X(PFNGLUNIFORMMATRIX2FVPROC, UniformMatrix2fv) X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv) \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv) X(PFNGLUNIFORMMATRIX3X4FVPROC, UniformMatrix3x4fv) \
    X(PFNGLUNIFORMMATRIX4X3FVPROC, UniformMatrix4x3fv) X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap) \
    X(PFNGLGETTEXPARAMETERIVPROC, GetTexParameteriv) X(PFNGLVERTEXATTRIB4FPROC, VertexAttrib4f) \
    X(PFNGLREADPIXELSPROC, ReadPixels) X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus) \
    X(PFNGLTEXIMAGE3DPROC, TexImage3D)

typedef struct test_gl_fns {
#define TEST_GL_FN_FIELD_(type, name) type name;
    TEST_GL_FNS(TEST_GL_FN_FIELD_)
#undef TEST_GL_FN_FIELD_
} test_gl_fns;

/* Fills f from the current test context; returns how many entry points it lacks. */
int test_gl_fns_load(test_gl_fns *f);

#endif
