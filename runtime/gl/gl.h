/* gl.h: the OpenGL entry points the runtime calls, as an X-macro list, loaded through the
 * caller's hfx_gl_loader into a table the device owns (no global GL state). Tests reuse the
 * list to build counting wrappers. V: returns void; R: returns a value.
 *   V(Name, (parameters), (arguments))      R(ReturnType, Name, (parameters), (arguments))
 * The GL name is "gl" + Name. All are core in GL 3.3. */
#ifndef HFX_RUNTIME_GL_H
#define HFX_RUNTIME_GL_H

#include <GL/glcorearb.h>

#include "hfx/hfx.h"

#define HFX_GL_FUNCS(V, R) \
    R(GLenum, GetError, (void), ()) \
    R(const GLubyte *, GetString, (GLenum name), (name)) \
    R(const GLubyte *, GetStringi, (GLenum name, GLuint index), (name, index)) \
    V(GetIntegerv, (GLenum pname, GLint *data), (pname, data)) \
    V(GetFloatv, (GLenum pname, GLfloat *data), (pname, data)) \
    V(GetBooleani_v, (GLenum target, GLuint index, GLboolean *data), (target, index, data)) \
    V(GetIntegeri_v, (GLenum target, GLuint index, GLint *data), (target, index, data)) \
    R(GLboolean, IsEnabled, (GLenum cap), (cap)) \
    V(Enable, (GLenum cap), (cap)) \
    V(Disable, (GLenum cap), (cap)) \
    R(GLuint, CreateShader, (GLenum type), (type)) \
    V(ShaderSource, (GLuint shader, GLsizei count, const GLchar *const *string, const GLint *length), \
      (shader, count, string, length)) \
    V(CompileShader, (GLuint shader), (shader)) \
    V(GetShaderiv, (GLuint shader, GLenum pname, GLint *params), (shader, pname, params)) \
    V(GetShaderInfoLog, (GLuint shader, GLsizei size, GLsizei *length, GLchar *log), (shader, size, length, log)) \
    V(DeleteShader, (GLuint shader), (shader)) \
    R(GLuint, CreateProgram, (void), ()) \
    V(AttachShader, (GLuint program, GLuint shader), (program, shader)) \
    V(DetachShader, (GLuint program, GLuint shader), (program, shader)) \
    V(BindAttribLocation, (GLuint program, GLuint index, const GLchar *name), (program, index, name)) \
    V(LinkProgram, (GLuint program), (program)) \
    V(GetProgramiv, (GLuint program, GLenum pname, GLint *params), (program, pname, params)) \
    V(GetProgramInfoLog, (GLuint program, GLsizei size, GLsizei *length, GLchar *log), (program, size, length, log)) \
    V(DeleteProgram, (GLuint program), (program)) \
    V(UseProgram, (GLuint program), (program)) \
    R(GLint, GetUniformLocation, (GLuint program, const GLchar *name), (program, name)) \
    V(GetActiveUniform, (GLuint program, GLuint index, GLsizei size, GLsizei *length, GLint *count, GLenum *type, \
      GLchar *name), (program, index, size, length, count, type, name)) \
    V(Uniform1i, (GLint location, GLint v0), (location, v0)) \
    V(Uniform1fv, (GLint location, GLsizei count, const GLfloat *v), (location, count, v)) \
    V(Uniform2fv, (GLint location, GLsizei count, const GLfloat *v), (location, count, v)) \
    V(Uniform3fv, (GLint location, GLsizei count, const GLfloat *v), (location, count, v)) \
    V(Uniform4fv, (GLint location, GLsizei count, const GLfloat *v), (location, count, v)) \
    V(Uniform1iv, (GLint location, GLsizei count, const GLint *v), (location, count, v)) \
    V(Uniform2iv, (GLint location, GLsizei count, const GLint *v), (location, count, v)) \
    V(Uniform3iv, (GLint location, GLsizei count, const GLint *v), (location, count, v)) \
    V(Uniform4iv, (GLint location, GLsizei count, const GLint *v), (location, count, v)) \
    V(Uniform1uiv, (GLint location, GLsizei count, const GLuint *v), (location, count, v)) \
    V(Uniform2uiv, (GLint location, GLsizei count, const GLuint *v), (location, count, v)) \
    V(Uniform3uiv, (GLint location, GLsizei count, const GLuint *v), (location, count, v)) \
    V(Uniform4uiv, (GLint location, GLsizei count, const GLuint *v), (location, count, v)) \
    V(UniformMatrix2fv, (GLint location, GLsizei count, GLboolean t, const GLfloat *v), (location, count, t, v)) \
    V(UniformMatrix3fv, (GLint location, GLsizei count, GLboolean t, const GLfloat *v), (location, count, t, v)) \
    V(UniformMatrix4fv, (GLint location, GLsizei count, GLboolean t, const GLfloat *v), (location, count, t, v)) \
    V(UniformMatrix2x3fv, (GLint location, GLsizei count, GLboolean t, const GLfloat *v), (location, count, t, v)) \
    V(UniformMatrix3x2fv, (GLint location, GLsizei count, GLboolean t, const GLfloat *v), (location, count, t, v)) \
    V(UniformMatrix2x4fv, (GLint location, GLsizei count, GLboolean t, const GLfloat *v), (location, count, t, v)) \
    V(UniformMatrix4x2fv, (GLint location, GLsizei count, GLboolean t, const GLfloat *v), (location, count, t, v)) \
    V(UniformMatrix3x4fv, (GLint location, GLsizei count, GLboolean t, const GLfloat *v), (location, count, t, v)) \
    V(UniformMatrix4x3fv, (GLint location, GLsizei count, GLboolean t, const GLfloat *v), (location, count, t, v)) \
    V(ActiveTexture, (GLenum texture), (texture)) \
    V(BindTexture, (GLenum target, GLuint texture), (target, texture)) \
    V(GetTexParameteriv, (GLenum target, GLenum pname, GLint *params), (target, pname, params)) \
    V(GetTexLevelParameteriv, (GLenum target, GLint level, GLenum pname, GLint *params), (target, level, pname, params)) \
    V(TexParameteri, (GLenum target, GLenum pname, GLint param), (target, pname, param)) \
    V(GenSamplers, (GLsizei n, GLuint *samplers), (n, samplers)) \
    V(DeleteSamplers, (GLsizei n, const GLuint *samplers), (n, samplers)) \
    V(BindSampler, (GLuint unit, GLuint sampler), (unit, sampler)) \
    V(SamplerParameteri, (GLuint sampler, GLenum pname, GLint param), (sampler, pname, param)) \
    V(SamplerParameterf, (GLuint sampler, GLenum pname, GLfloat param), (sampler, pname, param)) \
    V(SamplerParameterfv, (GLuint sampler, GLenum pname, const GLfloat *param), (sampler, pname, param)) \
    V(CullFace, (GLenum mode), (mode)) \
    V(FrontFace, (GLenum mode), (mode)) \
    V(ProvokingVertex, (GLenum mode), (mode)) \
    V(PolygonMode, (GLenum face, GLenum mode), (face, mode)) \
    V(DepthFunc, (GLenum func), (func)) \
    V(DepthMask, (GLboolean flag), (flag)) \
    V(BlendFuncSeparate, (GLenum sr, GLenum dr, GLenum sa, GLenum da), (sr, dr, sa, da)) \
    V(BlendEquationSeparate, (GLenum rgb, GLenum alpha), (rgb, alpha)) \
    V(BlendColor, (GLfloat r, GLfloat g, GLfloat b, GLfloat a), (r, g, b, a)) \
    V(ColorMaski, (GLuint i, GLboolean r, GLboolean g, GLboolean b, GLboolean a), (i, r, g, b, a)) \
    V(StencilFuncSeparate, (GLenum face, GLenum func, GLint ref, GLuint mask), (face, func, ref, mask)) \
    V(StencilOpSeparate, (GLenum face, GLenum sfail, GLenum dpfail, GLenum dppass), (face, sfail, dpfail, dppass)) \
    V(StencilMaskSeparate, (GLenum face, GLuint mask), (face, mask)) \
    V(PolygonOffset, (GLfloat factor, GLfloat units), (factor, units)) \
    V(SampleMaski, (GLuint index, GLbitfield mask), (index, mask)) \
    V(Viewport, (GLint x, GLint y, GLsizei width, GLsizei height), (x, y, width, height))

/* Entry points hfx uses when the driver has them (GL 4.1 / ARB_get_program_binary): NULL
 * otherwise, and the feature that needs them is off. */
#define HFX_GL_OPTIONAL_FUNCS(V, R) \
    V(ProgramParameteri, (GLuint program, GLenum pname, GLint value), (program, pname, value)) \
    V(GetProgramBinary, (GLuint program, GLsizei size, GLsizei *length, GLenum *format, void *binary), \
      (program, size, length, format, binary)) \
    V(ProgramBinary, (GLuint program, GLenum format, const void *binary, GLsizei length), (program, format, binary, length))

#ifndef APIENTRYP
#define APIENTRYP APIENTRY *
#endif

typedef struct hfx_gl {
#define HFX_GL_V_(name, params, args) void(APIENTRYP name) params;
#define HFX_GL_R_(ret, name, params, args) ret(APIENTRYP name) params;
    HFX_GL_FUNCS(HFX_GL_V_, HFX_GL_R_)
    HFX_GL_OPTIONAL_FUNCS(HFX_GL_V_, HFX_GL_R_)
#undef HFX_GL_V_
#undef HFX_GL_R_
} hfx_gl;

/* Fills the table; returns NULL, or the name of the first required entry point the loader
 * lacks (optional ones stay NULL). */
const char *hfx_gl_load(hfx_gl *gl, hfx_gl_loader load);

/* Whether the context lists extension name (glGetStringi, GL 3.0's way). */
int hfx_gl_has_extension(const hfx_gl *gl, const char *name);

#endif
