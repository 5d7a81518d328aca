/* device.c: the device (one per GL context): its GL table, its error message, and the shadow
 * of the GL state it sets, written through functions that skip calls GL would not notice. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl_int.h"

const char *hfx_gl_load(hfx_gl *gl, hfx_gl_loader load) {
#define HFX_GL_V_(name, params, args) \
    if (!(*(void **)&gl->name = load("gl" #name))) return "gl" #name;
#define HFX_GL_R_(ret, name, params, args) HFX_GL_V_(name, params, args)
    HFX_GL_FUNCS(HFX_GL_V_, HFX_GL_R_)
#undef HFX_GL_V_
#undef HFX_GL_R_
#define HFX_GL_V_(name, params, args) *(void **)&gl->name = load("gl" #name);
#define HFX_GL_R_(ret, name, params, args) HFX_GL_V_(name, params, args)
    HFX_GL_OPTIONAL_FUNCS(HFX_GL_V_, HFX_GL_R_)
#undef HFX_GL_V_
#undef HFX_GL_R_
    return NULL;
}

int hfx_gl_has_extension(const hfx_gl *gl, const char *name) {
    GLint n = 0;
    gl->GetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; i++) {
        const char *e = (const char *)gl->GetStringi(GL_EXTENSIONS, (GLuint)i);
        if (e && strcmp(e, name) == 0) return 1;
    }
    return 0;
}

/* D3D's DepthBias is in depth-buffer units of 0..1; glPolygonOffset's units are the smallest
 * resolvable difference, 1 / (2^24 - 1) for the 24-bit depth buffers hfx targets (GL core has
 * no query for the default framebuffer's depth size that every driver answers). */
static float depth_bias_scale(void) { return 16777215.0f; }

static void read_caps(hfx_device *dev) {
    GLint major = 0, minor = 0;
    dev->gl->fn.GetIntegerv(GL_MAJOR_VERSION, &major);
    dev->gl->fn.GetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor >= 46 || hfx_gl_has_extension(&dev->gl->fn, "GL_EXT_texture_filter_anisotropic") ||
        hfx_gl_has_extension(&dev->gl->fn, "GL_ARB_texture_filter_anisotropic"))
        dev->gl->fn.GetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY, &dev->max_anisotropy);
    dev->gl->srgb_decode = hfx_gl_has_extension(&dev->gl->fn, "GL_EXT_texture_sRGB_decode");
    dev->gl->depth_bias_scale = depth_bias_scale();
}

/* Reads the bindings the device shadows, so the shadow starts true. */
static void read_bindings(hfx_device *dev) {
    GLint v = 0;
    dev->gl->fn.GetIntegerv(GL_CURRENT_PROGRAM, &v);
    dev->gl->program = (GLuint)v;
    dev->gl->fn.GetIntegerv(GL_ACTIVE_TEXTURE, &v);
    dev->gl->active_unit = (GLenum)v;
    for (int u = 0; u < HFX_MAX_UNITS; u++) {
        dev->gl->units[u].texture = 0;
        dev->gl->units[u].target = 0; /* unknown: the first bind on a unit always happens */
        dev->gl->units[u].sampler = (GLuint)-1;
    }
}

/* docs/conventions.md: D3D9 pixel centres sit half a pixel up-left of GL's; in a framebuffer
 * object D3D9's first row is the top, so y flips there (and with it the front face). */
static void compute_fixup(hfx_device *dev, GLint width, GLint height) {
    float f[4] = {0, 0, 0, 0};
    if (width > 0 && height > 0) {
        f[0] = 1.0f / (float)width;
        f[1] = (dev->gl->flip ? 1.0f : -1.0f) / (float)height;
        f[2] = dev->gl->flip ? 1.0f : 0.0f;
        f[3] = (float)height;
    }
    if (memcmp(f, dev->gl->pos_fixup, sizeof f) == 0) return;
    memcpy(dev->gl->pos_fixup, f, sizeof f);
    dev->gl->pos_fixup_serial++; /* programs compare their copy on their next Apply */
}

/* Reads the viewport and the draw framebuffer, which the fixup follows. */
void hfx_rt_read_target(hfx_device *dev) {
    GLint vp[4] = {0}, fbo = 0;
    dev->applied = NULL;
    dev->gl->fn.GetIntegerv(GL_VIEWPORT, vp);
    dev->gl->fn.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
    dev->gl->flip = fbo != 0;
    compute_fixup(dev, vp[2], vp[3]);
}

void hfx_device_set_viewport(hfx_device *dev, int x, int y, int width, int height) {
    if (!dev || dev->be != &hfx_gl_backend) return; /* Vulkan: hfx_vk_target's size */
    dev->applied = NULL; /* the front face and hfx_pos_fixup may change */
    dev->gl->fn.Viewport(x, y, width, height);
    GLint fbo = 0;
    dev->gl->fn.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
    dev->gl->flip = fbo != 0;
    compute_fixup(dev, width, height);
}

/* The application set GL state itself: the shadow forgets what it believed. Texture units are
 * marked unknown (rebound on first use) rather than read back: 32 units x 4 targets of queries
 * would cost more than the binds they could save. */
void hfx_device_sync(hfx_device *dev) {
    if (!dev || dev->be != &hfx_gl_backend) return; /* Vulkan: nothing is shadowed */
    dev->applied = NULL;
    hfx_rt_read_state(dev, &dev->gl->state);
    hfx_rt_read_target(dev);
    read_bindings(dev);
}

hfx_device *hfx_device_create_gl(hfx_gl_loader load) {
    if (!load) return NULL;
    hfx_device *dev = calloc(1, sizeof *dev);
    if (dev) dev->gl = calloc(1, sizeof *dev->gl);
    if (!dev || !dev->gl || hfx_gl_load(&dev->gl->fn, load) != NULL) {
        if (dev) free(dev->gl);
        free(dev);
        return NULL;
    }
    dev->be = &hfx_gl_backend;
    dev->gl->pos_fixup_serial = 1; /* programs start at 0: they compare on their first Apply */
    while (dev->gl->fn.GetError() != GL_NO_ERROR) {}
    read_caps(dev);
    /* Cube maps filter across face edges, as Vulkan and WebGL 2 always do (and D3D9 on current
     * hardware): the same picture on every back end. GL 3.2's core switch, the context's state. */
    dev->gl->fn.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    hfx_rt_spirv_init(dev, load);
    read_bindings(dev);
    hfx_rt_read_target(dev);
    hfx_rt_read_state(dev, &dev->gl->state);
    hfx_rs_defaults(dev->rs);
    while (dev->gl->fn.GetError() != GL_NO_ERROR) {}
    return dev;
}

void hfx_gl_device_destroy(hfx_device *dev) {
    hfx_rt_textures_free(dev);
    free(dev->gl->scratch);
    free(dev->gl->program_cache);
    free(dev->gl);
    free(dev);
}


void hfx_rt_bind_unit(hfx_device *dev, int unit, GLenum target, GLuint texture, GLuint sampler) {
    hfx_unit_state *u = &dev->gl->units[unit];
    if (u->texture != texture || u->target != target) {
        /* Not shadowed: applications switch units for their own uploads all the time. */
        dev->gl->fn.ActiveTexture(GL_TEXTURE0 + (GLenum)unit);
        dev->gl->active_unit = GL_TEXTURE0 + (GLenum)unit;
        /* Unbinding the previous target keeps one texture per unit, as D3D has. */
        if (u->target && u->target != target && u->texture) dev->gl->fn.BindTexture(u->target, 0);
        dev->gl->fn.BindTexture(target, texture);
        hfx_rt_texture_check(dev, target, texture);
        u->texture = texture;
        u->target = target;
    }
    if (u->sampler != sampler) {
        dev->gl->fn.BindSampler((GLuint)unit, sampler);
        u->sampler = sampler;
    }
}

static GLboolean enabled(hfx_device *dev, GLenum cap) { return dev->gl->fn.IsEnabled(cap) ? GL_TRUE : GL_FALSE; }

static GLenum get_enum(hfx_device *dev, GLenum pname) {
    GLint v[4] = {0};
    dev->gl->fn.GetIntegerv(pname, v);
    return (GLenum)v[0];
}

void hfx_rt_read_state(hfx_device *dev, hfx_glstate *s) {
    hfx_gl *gl = &dev->gl->fn;
    memset(s, 0, sizeof *s);
    s->cull = enabled(dev, GL_CULL_FACE);
    s->cull_face = get_enum(dev, GL_CULL_FACE_MODE);
    s->front_face = get_enum(dev, GL_FRONT_FACE);
    s->provoking = get_enum(dev, GL_PROVOKING_VERTEX);
    s->polygon_mode = get_enum(dev, GL_POLYGON_MODE);
    s->depth_test = enabled(dev, GL_DEPTH_TEST);
    GLboolean b[4] = {0};
    GLint v = 0;
    gl->GetIntegerv(GL_DEPTH_WRITEMASK, &v);
    s->depth_mask = v ? GL_TRUE : GL_FALSE;
    s->depth_func = get_enum(dev, GL_DEPTH_FUNC);
    s->blend = enabled(dev, GL_BLEND);
    s->src_rgb = get_enum(dev, GL_BLEND_SRC_RGB);
    s->dst_rgb = get_enum(dev, GL_BLEND_DST_RGB);
    s->src_a = get_enum(dev, GL_BLEND_SRC_ALPHA);
    s->dst_a = get_enum(dev, GL_BLEND_DST_ALPHA);
    s->eq_rgb = get_enum(dev, GL_BLEND_EQUATION_RGB);
    s->eq_a = get_enum(dev, GL_BLEND_EQUATION_ALPHA);
    gl->GetFloatv(GL_BLEND_COLOR, s->blend_color);
    for (GLuint i = 0; i < 4; i++) {
        memset(b, 0, sizeof b);
        gl->GetBooleani_v(GL_COLOR_WRITEMASK, i, b);
        s->color_mask[i] = (uint8_t)((b[0] ? 1 : 0) | (b[1] ? 2 : 0) | (b[2] ? 4 : 0) | (b[3] ? 8 : 0));
    }
    s->stencil = enabled(dev, GL_STENCIL_TEST);
    static const GLenum q[2][7] = {
        {GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_WRITEMASK, GL_STENCIL_FAIL,
         GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS},
        {GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_REF, GL_STENCIL_BACK_VALUE_MASK, GL_STENCIL_BACK_WRITEMASK,
         GL_STENCIL_BACK_FAIL, GL_STENCIL_BACK_PASS_DEPTH_FAIL, GL_STENCIL_BACK_PASS_DEPTH_PASS}};
    for (int f = 0; f < 2; f++) {
        s->face[f].func = get_enum(dev, q[f][0]);
        gl->GetIntegerv(q[f][1], &v);
        s->face[f].ref = v;
        s->face[f].mask = get_enum(dev, q[f][2]);
        s->face[f].write = get_enum(dev, q[f][3]);
        s->face[f].fail = get_enum(dev, q[f][4]);
        s->face[f].zfail = get_enum(dev, q[f][5]);
        s->face[f].pass = get_enum(dev, q[f][6]);
    }
    s->scissor = enabled(dev, GL_SCISSOR_TEST);
    s->offset_fill = enabled(dev, GL_POLYGON_OFFSET_FILL);
    s->offset_line = enabled(dev, GL_POLYGON_OFFSET_LINE);
    s->offset_point = enabled(dev, GL_POLYGON_OFFSET_POINT);
    gl->GetFloatv(GL_POLYGON_OFFSET_FACTOR, &s->offset_factor);
    gl->GetFloatv(GL_POLYGON_OFFSET_UNITS, &s->offset_units);
    s->multisample = enabled(dev, GL_MULTISAMPLE);
    s->srgb = enabled(dev, GL_FRAMEBUFFER_SRGB);
    s->dither = enabled(dev, GL_DITHER);
    s->line_smooth = enabled(dev, GL_LINE_SMOOTH);
    s->sample_mask = enabled(dev, GL_SAMPLE_MASK);
    GLint mask = 0;
    gl->GetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &mask);
    s->sample_mask_value = (GLuint)mask;
    for (int i = 0; i < 6; i++)
        if (enabled(dev, GL_CLIP_DISTANCE0 + (GLenum)i)) s->clip_planes |= (uint8_t)(1u << i);
}

static void set_cap(hfx_device *dev, GLenum cap, GLboolean *have, GLboolean want) {
    if (*have == want) return;
    if (want) dev->gl->fn.Enable(cap);
    else dev->gl->fn.Disable(cap);
    *have = want;
}

static void write_blend(hfx_device *dev, hfx_glstate *s, const hfx_glstate *w) {
    set_cap(dev, GL_BLEND, &s->blend, w->blend);
    if (s->src_rgb != w->src_rgb || s->dst_rgb != w->dst_rgb || s->src_a != w->src_a || s->dst_a != w->dst_a) {
        dev->gl->fn.BlendFuncSeparate(w->src_rgb, w->dst_rgb, w->src_a, w->dst_a);
        s->src_rgb = w->src_rgb, s->dst_rgb = w->dst_rgb, s->src_a = w->src_a, s->dst_a = w->dst_a;
    }
    if (s->eq_rgb != w->eq_rgb || s->eq_a != w->eq_a) {
        dev->gl->fn.BlendEquationSeparate(w->eq_rgb, w->eq_a);
        s->eq_rgb = w->eq_rgb, s->eq_a = w->eq_a;
    }
    if (memcmp(s->blend_color, w->blend_color, sizeof s->blend_color) != 0) {
        dev->gl->fn.BlendColor(w->blend_color[0], w->blend_color[1], w->blend_color[2], w->blend_color[3]);
        memcpy(s->blend_color, w->blend_color, sizeof s->blend_color);
    }
    for (GLuint i = 0; i < 4; i++)
        if (s->color_mask[i] != w->color_mask[i]) {
            uint8_t m = w->color_mask[i];
            dev->gl->fn.ColorMaski(i, (m & 1) != 0, (m & 2) != 0, (m & 4) != 0, (m & 8) != 0);
            s->color_mask[i] = m;
        }
}

static void write_stencil(hfx_device *dev, hfx_glstate *s, const hfx_glstate *w) {
    static const GLenum faces[2] = {GL_FRONT, GL_BACK};
    set_cap(dev, GL_STENCIL_TEST, &s->stencil, w->stencil);
    for (int f = 0; f < 2; f++) {
        if (s->face[f].func != w->face[f].func || s->face[f].ref != w->face[f].ref ||
            s->face[f].mask != w->face[f].mask) {
            dev->gl->fn.StencilFuncSeparate(faces[f], w->face[f].func, w->face[f].ref, w->face[f].mask);
            s->face[f].func = w->face[f].func, s->face[f].ref = w->face[f].ref, s->face[f].mask = w->face[f].mask;
        }
        if (s->face[f].fail != w->face[f].fail || s->face[f].zfail != w->face[f].zfail ||
            s->face[f].pass != w->face[f].pass) {
            dev->gl->fn.StencilOpSeparate(faces[f], w->face[f].fail, w->face[f].zfail, w->face[f].pass);
            s->face[f].fail = w->face[f].fail, s->face[f].zfail = w->face[f].zfail, s->face[f].pass = w->face[f].pass;
        }
        if (s->face[f].write != w->face[f].write) {
            dev->gl->fn.StencilMaskSeparate(faces[f], w->face[f].write);
            s->face[f].write = w->face[f].write;
        }
    }
}

void hfx_rt_write_state(hfx_device *dev, const hfx_glstate *w) {
    hfx_glstate *s = &dev->gl->state;
    set_cap(dev, GL_CULL_FACE, &s->cull, w->cull);
    if (s->cull_face != w->cull_face) dev->gl->fn.CullFace(s->cull_face = w->cull_face);
    if (s->front_face != w->front_face) dev->gl->fn.FrontFace(s->front_face = w->front_face);
    if (s->provoking != w->provoking) dev->gl->fn.ProvokingVertex(s->provoking = w->provoking);
    if (s->polygon_mode != w->polygon_mode) dev->gl->fn.PolygonMode(GL_FRONT_AND_BACK, s->polygon_mode = w->polygon_mode);
    set_cap(dev, GL_DEPTH_TEST, &s->depth_test, w->depth_test);
    if (s->depth_mask != w->depth_mask) dev->gl->fn.DepthMask(s->depth_mask = w->depth_mask);
    if (s->depth_func != w->depth_func) dev->gl->fn.DepthFunc(s->depth_func = w->depth_func);
    write_blend(dev, s, w);
    write_stencil(dev, s, w);
    set_cap(dev, GL_SCISSOR_TEST, &s->scissor, w->scissor);
    set_cap(dev, GL_POLYGON_OFFSET_FILL, &s->offset_fill, w->offset_fill);
    set_cap(dev, GL_POLYGON_OFFSET_LINE, &s->offset_line, w->offset_line);
    set_cap(dev, GL_POLYGON_OFFSET_POINT, &s->offset_point, w->offset_point);
    if (s->offset_factor != w->offset_factor || s->offset_units != w->offset_units) {
        dev->gl->fn.PolygonOffset(w->offset_factor, w->offset_units);
        s->offset_factor = w->offset_factor, s->offset_units = w->offset_units;
    }
    set_cap(dev, GL_MULTISAMPLE, &s->multisample, w->multisample);
    set_cap(dev, GL_FRAMEBUFFER_SRGB, &s->srgb, w->srgb);
    set_cap(dev, GL_DITHER, &s->dither, w->dither);
    set_cap(dev, GL_LINE_SMOOTH, &s->line_smooth, w->line_smooth);
    set_cap(dev, GL_SAMPLE_MASK, &s->sample_mask, w->sample_mask);
    if (s->sample_mask_value != w->sample_mask_value) dev->gl->fn.SampleMaski(0, s->sample_mask_value = w->sample_mask_value);
    for (int i = 0; i < 6; i++) {
        GLboolean have = (s->clip_planes >> i) & 1, want = (w->clip_planes >> i) & 1;
        if (have == want) continue;
        if (want) dev->gl->fn.Enable(GL_CLIP_DISTANCE0 + (GLenum)i);
        else dev->gl->fn.Disable(GL_CLIP_DISTANCE0 + (GLenum)i);
    }
    s->clip_planes = w->clip_planes;
}
