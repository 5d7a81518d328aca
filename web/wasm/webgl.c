/* webgl.c: hfx's GL table on WebGL 2 (see webgl.h). */
#include "webgl.h"

#include <GLES3/gl3.h>
#include <emscripten/html5.h>
#include <string.h>

/* Core-profile enums the runtime asks about that GLES 3.0's header does not name. */
#define HFXW_PROVOKING_VERTEX 0x8E4F
#define HFXW_LAST_VERTEX_CONVENTION 0x8E4E
#define HFXW_POLYGON_MODE 0x0B40
#define HFXW_FILL 0x1B02
#define HFXW_SAMPLE_MASK_VALUE 0x8E52
#define HFXW_TEXTURE_BINDING_1D 0x8068
#define HFXW_TEXTURE_1D 0x0DE0
#define HFXW_MAX_TEXTURE_MAX_ANISOTROPY 0x84FF
#define HFXW_NUM_PROGRAM_BINARY_FORMATS 0x87FE
#define HFXW_TEXTURE_WIDTH 0x1000
#define HFXW_TEXTURE_HEIGHT 0x1001
#define HFXW_TEXTURE_DEPTH 0x8071
#define HFXW_CLAMP_TO_BORDER 0x812D
#define HFXW_MIRROR_CLAMP_TO_EDGE 0x8743

/* The page's textures: one WebGL context, one session (the library keeps no such table). */
enum { HFXW_MAX_TEXTURES = 256 };
static struct { unsigned name; int width, height; } notes[HFXW_MAX_TEXTURES];

void hfxw_gl_note_texture(unsigned texture, int width, int height) {
    for (int i = 0; i < HFXW_MAX_TEXTURES; i++)
        if (notes[i].name == texture || notes[i].name == 0) {
            notes[i].name = texture, notes[i].width = width, notes[i].height = height;
            return;
        }
}

/* Capabilities WebGL 2 has; glEnable of any other is an INVALID_ENUM there, and GL 3.3's
 * defaults (off) are what the runtime should read back for them. */
static int webgl_cap(GLenum cap) {
    switch (cap) {
    case GL_BLEND: case GL_CULL_FACE: case GL_DEPTH_TEST: case GL_DITHER: case GL_POLYGON_OFFSET_FILL:
    case GL_SAMPLE_ALPHA_TO_COVERAGE: case GL_SAMPLE_COVERAGE: case GL_SCISSOR_TEST: case GL_STENCIL_TEST:
    case GL_RASTERIZER_DISCARD:
        return 1;
    default:
        return 0;
    }
}

static void GL_APIENTRY enable(GLenum cap) { if (webgl_cap(cap)) glEnable(cap); }
static void GL_APIENTRY disable(GLenum cap) { if (webgl_cap(cap)) glDisable(cap); }
static GLboolean GL_APIENTRY is_enabled(GLenum cap) { return webgl_cap(cap) ? glIsEnabled(cap) : GL_FALSE; }

static void GL_APIENTRY get_integerv(GLenum pname, GLint *data) {
    switch (pname) {
    case HFXW_PROVOKING_VERTEX: data[0] = HFXW_LAST_VERTEX_CONVENTION; return; /* GLES's fixed rule */
    case HFXW_POLYGON_MODE: data[0] = data[1] = HFXW_FILL; return;
    case HFXW_TEXTURE_BINDING_1D: case HFXW_NUM_PROGRAM_BINARY_FORMATS: data[0] = 0; return;
    case GL_MAJOR_VERSION: data[0] = 3; return; /* WebGL 2 answers only through getParameter(VERSION) */
    case GL_MINOR_VERSION: data[0] = 0; return;
    default: glGetIntegerv(pname, data);
    }
}

static void GL_APIENTRY get_integeri_v(GLenum target, GLuint index, GLint *data) {
    if (target == HFXW_SAMPLE_MASK_VALUE) data[0] = -1; /* every sample */
    else glGetIntegeri_v(target, index, data);
}

static void GL_APIENTRY get_floatv(GLenum pname, GLfloat *data) {
    if (pname == HFXW_MAX_TEXTURE_MAX_ANISOTROPY) data[0] = 1.0f; /* the extension is not enabled */
    else glGetFloatv(pname, data);
}

/* One colour mask for the one draw buffer the canvas has. */
static void GL_APIENTRY get_booleani_v(GLenum target, GLuint index, GLboolean *data) {
    GLboolean m[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    if (target == GL_COLOR_WRITEMASK && index == 0) glGetBooleanv(GL_COLOR_WRITEMASK, m);
    memcpy(data, m, sizeof m);
}

static void GL_APIENTRY color_maski(GLuint i, GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
    if (i == 0) glColorMask(r, g, b, a);
}

static void GL_APIENTRY provoking_vertex(GLenum mode) { (void)mode; }
static void GL_APIENTRY polygon_mode(GLenum face, GLenum mode) { (void)face, (void)mode; }
static void GL_APIENTRY sample_maski(GLuint index, GLbitfield mask) { (void)index, (void)mask; }

/* Level sizes of the texture bound to target: the page's textures have full chains. */
static void GL_APIENTRY get_tex_level_parameteriv(GLenum target, GLint level, GLenum pname, GLint *params) {
    GLint bound = 0;
    glGetIntegerv(target == GL_TEXTURE_3D ? GL_TEXTURE_BINDING_3D
                  : target == GL_TEXTURE_2D ? GL_TEXTURE_BINDING_2D : GL_TEXTURE_BINDING_CUBE_MAP, &bound);
    params[0] = 0;
    for (int i = 0; i < HFXW_MAX_TEXTURES && notes[i].name; i++) {
        if (notes[i].name != (unsigned)bound) continue;
        int size = pname == HFXW_TEXTURE_WIDTH ? notes[i].width : pname == HFXW_TEXTURE_HEIGHT ? notes[i].height : 1;
        params[0] = size >> level > 0 ? size >> level : 1;
        if ((notes[i].width >> level) == 0 && (notes[i].height >> level) == 0) params[0] = 0;
    }
}

/* Wrap modes and parameters WebGL 2 lacks become their nearest relative, or are dropped. */
static GLint webgl_wrap(GLint mode) {
    if (mode == HFXW_CLAMP_TO_BORDER) return GL_CLAMP_TO_EDGE;
    if (mode == HFXW_MIRROR_CLAMP_TO_EDGE) return GL_MIRRORED_REPEAT;
    return mode;
}

static int webgl_sampler_param(GLenum pname) {
    switch (pname) {
    case GL_TEXTURE_MIN_FILTER: case GL_TEXTURE_MAG_FILTER: case GL_TEXTURE_WRAP_S: case GL_TEXTURE_WRAP_T:
    case GL_TEXTURE_WRAP_R: case GL_TEXTURE_MIN_LOD: case GL_TEXTURE_MAX_LOD: case GL_TEXTURE_COMPARE_MODE:
    case GL_TEXTURE_COMPARE_FUNC:
        return 1;
    default:
        return 0;
    }
}

static void GL_APIENTRY sampler_parameteri(GLuint s, GLenum pname, GLint v) {
    if (webgl_sampler_param(pname)) glSamplerParameteri(s, pname, webgl_wrap(v));
}
static void GL_APIENTRY sampler_parameterf(GLuint s, GLenum pname, GLfloat v) {
    if (webgl_sampler_param(pname)) glSamplerParameterf(s, pname, v);
}
static void GL_APIENTRY sampler_parameterfv(GLuint s, GLenum pname, const GLfloat *v) {
    if (webgl_sampler_param(pname)) glSamplerParameterf(s, pname, v[0]);
}
static void GL_APIENTRY tex_parameteri(GLenum target, GLenum pname, GLint v) {
    if (webgl_sampler_param(pname) || pname == GL_TEXTURE_BASE_LEVEL || pname == GL_TEXTURE_MAX_LEVEL)
        glTexParameteri(target, pname, webgl_wrap(v));
}

/* 1D textures are 2D ones of height 1 in hfx (docs/conventions.md); WebGL has no 1D target to
 * restore a binding on. */
static void GL_APIENTRY bind_texture(GLenum target, GLuint texture) {
    if (target != HFXW_TEXTURE_1D) glBindTexture(target, texture);
}

/* GL 3.3's double-precision clear depth (hfxview's hv_clear calls it); GLES has only the float one. */
static void GL_APIENTRY clear_depth(double depth) { glClearDepthf((GLfloat)depth); }

static const struct { const char *name; void *fn; } stand_ins[] = {
    {"glClearDepth", (void *)clear_depth},
    {"glBindTexture", (void *)bind_texture},
    {"glEnable", (void *)enable}, {"glDisable", (void *)disable}, {"glIsEnabled", (void *)is_enabled},
    {"glGetIntegerv", (void *)get_integerv}, {"glGetIntegeri_v", (void *)get_integeri_v},
    {"glGetFloatv", (void *)get_floatv}, {"glGetBooleani_v", (void *)get_booleani_v},
    {"glColorMaski", (void *)color_maski}, {"glProvokingVertex", (void *)provoking_vertex},
    {"glPolygonMode", (void *)polygon_mode}, {"glSampleMaski", (void *)sample_maski},
    {"glGetTexLevelParameteriv", (void *)get_tex_level_parameteriv},
    {"glSamplerParameteri", (void *)sampler_parameteri}, {"glSamplerParameterf", (void *)sampler_parameterf},
    {"glSamplerParameterfv", (void *)sampler_parameterfv}, {"glTexParameteri", (void *)tex_parameteri},
};

void *hfxw_gl_proc(const char *name) {
    for (size_t i = 0; i < sizeof stand_ins / sizeof stand_ins[0]; i++)
        if (strcmp(stand_ins[i].name, name) == 0) return stand_ins[i].fn;
    return emscripten_webgl_get_proc_address(name);
}
