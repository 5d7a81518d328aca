/* gl.h: the OpenGL 3.3 core entry points hfxview calls, loaded through a loader function
 * (OSMesaGetProcAddress, eglGetProcAddress, glfwGetProcAddress) into a table, so nothing links
 * libGL directly. */
#ifndef HFXVIEW_GL_H
#define HFXVIEW_GL_H

#include <GL/glcorearb.h>

#define HV_GL_FUNCTIONS(X) \
    X(PFNGLGETSTRINGPROC, GetString) X(PFNGLGETERRORPROC, GetError) X(PFNGLGETINTEGERVPROC, GetIntegerv) \
    X(PFNGLVIEWPORTPROC, Viewport) X(PFNGLCLEARCOLORPROC, ClearColor) X(PFNGLCLEARDEPTHPROC, ClearDepth) \
    X(PFNGLCLEARPROC, Clear) X(PFNGLENABLEPROC, Enable) X(PFNGLDISABLEPROC, Disable) \
    X(PFNGLCULLFACEPROC, CullFace) X(PFNGLFRONTFACEPROC, FrontFace) X(PFNGLDEPTHFUNCPROC, DepthFunc) \
    X(PFNGLDEPTHMASKPROC, DepthMask) X(PFNGLCOLORMASKPROC, ColorMask) X(PFNGLBLENDFUNCPROC, BlendFunc) \
    X(PFNGLBLENDEQUATIONPROC, BlendEquation) X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays) \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray) X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays) \
    X(PFNGLGENBUFFERSPROC, GenBuffers) X(PFNGLBINDBUFFERPROC, BindBuffer) X(PFNGLBUFFERDATAPROC, BufferData) \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers) X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer) \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray) \
    X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray) X(PFNGLVERTEXATTRIB4FPROC, VertexAttrib4f) \
    X(PFNGLDRAWELEMENTSPROC, DrawElements) X(PFNGLGENTEXTURESPROC, GenTextures) \
    X(PFNGLBINDTEXTUREPROC, BindTexture) X(PFNGLACTIVETEXTUREPROC, ActiveTexture) \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D) X(PFNGLTEXIMAGE3DPROC, TexImage3D) X(PFNGLTEXPARAMETERIPROC, TexParameteri) \
    X(PFNGLGENERATEMIPMAPPROC, GenerateMipmap) X(PFNGLDELETETEXTURESPROC, DeleteTextures) \
    X(PFNGLPIXELSTOREIPROC, PixelStorei) X(PFNGLREADPIXELSPROC, ReadPixels) X(PFNGLFINISHPROC, Finish) \
    X(PFNGLUSEPROGRAMPROC, UseProgram) X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers) \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer) X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers) \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus) X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers) \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer) X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers) \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage) \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)

typedef struct hv_gl {
#define HV_GL_MEMBER(type, name) type name;
    HV_GL_FUNCTIONS(HV_GL_MEMBER)
#undef HV_GL_MEMBER
} hv_gl;

typedef void *(*hv_gl_loader)(const char *name);

/* Fills the table; returns NULL, or the name of the first entry point the loader lacks. */
const char *hv_gl_load(hv_gl *gl, hv_gl_loader load);

#endif
