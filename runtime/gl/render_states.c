/* render_states.c: D3D9 render states to GL. The device keeps the D3D value of every render
 * state (a pass's states stay set after it, as in D3D9); Apply recomputes the GL state of the
 * groups the pass touches and writes only what differs.
 *
 * Winding: the shaders keep D3D's clip space (no y flip), so a triangle looks the same on
 * screen in both APIs and D3D's "clockwise on screen" is GL's GL_CW in window coordinates.
 * D3D's front faces are clockwise, so the device sets glFrontFace(GL_CW) (which also keeps
 * gl_FrontFacing equal to D3D's VFACE) and CullMode = CCW culls GL_BACK. Drawing into a
 * framebuffer object the shaders flip y (D3D9's row order, hfx_pos_fixup.z), so GL_CCW. */
#include <string.h>

#include "eval_code.h"
#include "gl/gl_int.h"

uint32_t hfx_rs_group(uint32_t id) {
    switch (id) {
    case HFX_ST_CULLMODE: return G_CULL;
    case HFX_ST_FILLMODE: return G_FILL;
    case HFX_ST_ZENABLE: case HFX_ST_ZWRITEENABLE: case HFX_ST_ZFUNC: return G_DEPTH;
    case HFX_ST_ALPHABLENDENABLE: case HFX_ST_SRCBLEND: case HFX_ST_DESTBLEND: case HFX_ST_BLENDOP:
    case HFX_ST_SEPARATEALPHABLENDENABLE: case HFX_ST_SRCBLENDALPHA: case HFX_ST_DESTBLENDALPHA:
    case HFX_ST_BLENDOPALPHA: case HFX_ST_BLENDFACTOR: return G_BLEND;
    case HFX_ST_COLORWRITEENABLE: case HFX_ST_COLORWRITEENABLE1: case HFX_ST_COLORWRITEENABLE2:
    case HFX_ST_COLORWRITEENABLE3: return G_COLORMASK;
    case HFX_ST_STENCILENABLE: case HFX_ST_STENCILFAIL: case HFX_ST_STENCILZFAIL: case HFX_ST_STENCILPASS:
    case HFX_ST_STENCILFUNC: case HFX_ST_STENCILREF: case HFX_ST_STENCILMASK: case HFX_ST_STENCILWRITEMASK:
    case HFX_ST_TWOSIDEDSTENCILMODE: case HFX_ST_CCW_STENCILFAIL: case HFX_ST_CCW_STENCILZFAIL:
    case HFX_ST_CCW_STENCILPASS: case HFX_ST_CCW_STENCILFUNC: return G_STENCIL;
    case HFX_ST_SCISSORTESTENABLE: return G_SCISSOR;
    case HFX_ST_DEPTHBIAS: case HFX_ST_SLOPESCALEDEPTHBIAS: return G_DEPTHBIAS;
    case HFX_ST_MULTISAMPLEANTIALIAS: return G_MSAA;
    case HFX_ST_SRGBWRITEENABLE: return G_SRGB;
    case HFX_ST_DITHERENABLE: return G_DITHER;
    case HFX_ST_ANTIALIASEDLINEENABLE: return G_LINESMOOTH;
    case HFX_ST_MULTISAMPLEMASK: return G_SAMPLEMASK;
    case HFX_ST_CLIPPLANEENABLE: return G_CLIP;
    case HFX_ST_ALPHATESTENABLE: case HFX_ST_ALPHAREF: case HFX_ST_ALPHAFUNC: return G_ALPHATEST;
    default: return 0;
    }
}

static GLenum gl_compare(int32_t d3d) {
    static const GLenum map[] = {GL_ALWAYS, GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                 GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    return d3d >= 1 && d3d <= 8 ? map[d3d] : GL_ALWAYS;
}

static GLenum gl_blend(int32_t d3d) {
    switch (d3d) {
    case 1: return GL_ZERO;
    case 2: return GL_ONE;
    case 3: return GL_SRC_COLOR;
    case 4: return GL_ONE_MINUS_SRC_COLOR;
    case 5: return GL_SRC_ALPHA;
    case 6: return GL_ONE_MINUS_SRC_ALPHA;
    case 7: return GL_DST_ALPHA;
    case 8: return GL_ONE_MINUS_DST_ALPHA;
    case 9: return GL_DST_COLOR;
    case 10: return GL_ONE_MINUS_DST_COLOR;
    case 11: return GL_SRC_ALPHA_SATURATE;
    case 14: return GL_CONSTANT_COLOR;
    case 15: return GL_ONE_MINUS_CONSTANT_COLOR;
    case 16: return GL_SRC1_COLOR;
    case 17: return GL_ONE_MINUS_SRC1_COLOR;
    default: return GL_ONE;
    }
}

static GLenum gl_blend_op(int32_t d3d) {
    static const GLenum map[] = {GL_FUNC_ADD, GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
    return d3d >= 1 && d3d <= 5 ? map[d3d] : GL_FUNC_ADD;
}

static GLenum gl_stencil_op(int32_t d3d) {
    static const GLenum map[] = {GL_KEEP, GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR,
                                 GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
    return d3d >= 1 && d3d <= 8 ? map[d3d] : GL_KEEP;
}

/* D3DBLEND_BOTHSRCALPHA / BOTHINVSRCALPHA set the source and overrule the destination. */
static void blend_pair(int32_t src, int32_t dst, GLenum *s, GLenum *d) {
    if (src == 12) src = 5, dst = 6;
    else if (src == 13) src = 6, dst = 5;
    *s = gl_blend(src);
    *d = gl_blend(dst);
}

static void want_blend(const hfx_rs_value *rs, const hfx_device *dev, hfx_glstate *w) {
    w->blend = rs[HFX_ST_ALPHABLENDENABLE].i ? GL_TRUE : GL_FALSE;
    blend_pair(rs[HFX_ST_SRCBLEND].i, rs[HFX_ST_DESTBLEND].i, &w->src_rgb, &w->dst_rgb);
    w->eq_rgb = gl_blend_op(rs[HFX_ST_BLENDOP].i);
    if (rs[HFX_ST_SEPARATEALPHABLENDENABLE].i) {
        blend_pair(rs[HFX_ST_SRCBLENDALPHA].i, rs[HFX_ST_DESTBLENDALPHA].i, &w->src_a, &w->dst_a);
        w->eq_a = gl_blend_op(rs[HFX_ST_BLENDOPALPHA].i);
    } else {
        w->src_a = w->src_rgb, w->dst_a = w->dst_rgb, w->eq_a = w->eq_rgb;
    }
    memcpy(w->blend_color, rs[HFX_ST_BLENDFACTOR].f, sizeof w->blend_color);
    (void)dev;
}

/* Front (D3D's clockwise) faces use the Stencil* states; back faces the CCW_* ones when
 * TwoSidedStencilMode is on, else the same. Ref and masks are shared, as in D3D9. */
static void want_stencil(const hfx_rs_value *rs, hfx_glstate *w) {
    w->stencil = rs[HFX_ST_STENCILENABLE].i ? GL_TRUE : GL_FALSE;
    int two = rs[HFX_ST_TWOSIDEDSTENCILMODE].i != 0;
    for (int f = 0; f < 2; f++) {
        int ccw = f == 1 && two;
        w->face[f].func = gl_compare(rs[ccw ? HFX_ST_CCW_STENCILFUNC : HFX_ST_STENCILFUNC].i);
        w->face[f].fail = gl_stencil_op(rs[ccw ? HFX_ST_CCW_STENCILFAIL : HFX_ST_STENCILFAIL].i);
        w->face[f].zfail = gl_stencil_op(rs[ccw ? HFX_ST_CCW_STENCILZFAIL : HFX_ST_STENCILZFAIL].i);
        w->face[f].pass = gl_stencil_op(rs[ccw ? HFX_ST_CCW_STENCILPASS : HFX_ST_STENCILPASS].i);
        w->face[f].ref = rs[HFX_ST_STENCILREF].i;
        w->face[f].mask = (GLuint)rs[HFX_ST_STENCILMASK].i;
        w->face[f].write = (GLuint)rs[HFX_ST_STENCILWRITEMASK].i;
    }
}

static void want_groups(const hfx_device *dev, uint32_t groups, hfx_glstate *w) {
    const hfx_rs_value *rs = dev->rs;
    if (groups & G_CULL) {
        int32_t c = rs[HFX_ST_CULLMODE].i;
        w->cull = c == 2 || c == 3;
        w->front_face = dev->gl->flip ? GL_CCW : GL_CW;
        w->provoking = GL_FIRST_VERTEX_CONVENTION;
        if (w->cull) w->cull_face = c == 3 ? GL_BACK : GL_FRONT;
    }
    if (groups & G_FILL) {
        int32_t m = rs[HFX_ST_FILLMODE].i;
        w->polygon_mode = m == 1 ? GL_POINT : m == 2 ? GL_LINE : GL_FILL;
    }
    if (groups & G_DEPTH) {
        w->depth_test = rs[HFX_ST_ZENABLE].i != 0; /* USEW (2) is reported at load, then treated as TRUE */
        w->depth_mask = rs[HFX_ST_ZWRITEENABLE].i ? GL_TRUE : GL_FALSE;
        w->depth_func = gl_compare(rs[HFX_ST_ZFUNC].i);
    }
    if (groups & G_BLEND) want_blend(rs, dev, w);
    if (groups & G_COLORMASK) {
        w->color_mask[0] = (uint8_t)(rs[HFX_ST_COLORWRITEENABLE].i & 15);
        w->color_mask[1] = (uint8_t)(rs[HFX_ST_COLORWRITEENABLE1].i & 15);
        w->color_mask[2] = (uint8_t)(rs[HFX_ST_COLORWRITEENABLE2].i & 15);
        w->color_mask[3] = (uint8_t)(rs[HFX_ST_COLORWRITEENABLE3].i & 15);
    }
    if (groups & G_STENCIL) want_stencil(rs, w);
    if (groups & G_SCISSOR) w->scissor = rs[HFX_ST_SCISSORTESTENABLE].i != 0;
    if (groups & G_DEPTHBIAS) {
        float bias = rs[HFX_ST_DEPTHBIAS].f[0], slope = rs[HFX_ST_SLOPESCALEDEPTHBIAS].f[0];
        GLboolean on = bias != 0.0f || slope != 0.0f;
        w->offset_fill = w->offset_line = w->offset_point = on;
        w->offset_factor = slope;
        w->offset_units = bias * dev->gl->depth_bias_scale;
    }
    if (groups & G_MSAA) w->multisample = rs[HFX_ST_MULTISAMPLEANTIALIAS].i != 0;
    if (groups & G_SRGB) w->srgb = rs[HFX_ST_SRGBWRITEENABLE].i != 0;
    if (groups & G_DITHER) w->dither = rs[HFX_ST_DITHERENABLE].i != 0;
    if (groups & G_LINESMOOTH) w->line_smooth = rs[HFX_ST_ANTIALIASEDLINEENABLE].i != 0;
    if (groups & G_SAMPLEMASK) {
        w->sample_mask_value = (GLuint)rs[HFX_ST_MULTISAMPLEMASK].i;
        w->sample_mask = w->sample_mask_value != 0xffffffffu;
    }
    if (groups & G_CLIP) w->clip_planes = (uint8_t)(rs[HFX_ST_CLIPPLANEENABLE].i & 63);
}

void hfx_rs_apply(hfx_effect *fx, const hfx_rt_pass *pass) {
    hfx_device *dev = fx->dev;
    const hfx_fx_effect *cfx = fx->sh->fx;
    for (uint32_t i = 0; i < pass->render_state_count; i++) {
        const hfx_fx_state *st = &cfx->states[pass->render_states[i]];
        hfx_rs_resolve(fx, st, &dev->rs[st->id]);
    }
    uint32_t groups = pass->groups & ~G_ALPHATEST;
    if (!groups) return;
    hfx_glstate want = dev->gl->state;
    want_groups(dev, groups, &want);
    hfx_rt_write_state(dev, &want);
}

/* D3D's front faces are clockwise; y flipped into a framebuffer object, GL sees them CCW. */
void hfx_rs_front_face(hfx_device *dev) {
    GLenum want = dev->gl->flip ? GL_CCW : GL_CW;
    if (dev->gl->state.front_face != want) dev->gl->fn.FrontFace(dev->gl->state.front_face = want);
}

/* The codegen's alpha test: hfx_alpha_func is the D3DCMP value (ALWAYS when the test is off),
 * hfx_alpha_ref the reference scaled to 0..1 as D3D compares against AlphaRef / 255. */
void hfx_rs_alpha_test(hfx_device *dev, hfx_rt_program *p) {
    int32_t func = dev->rs[HFX_ST_ALPHATESTENABLE].i ? dev->rs[HFX_ST_ALPHAFUNC].i : 8;
    float ref = (float)(dev->rs[HFX_ST_ALPHAREF].i & 255) / 255.0f;
    if (func != p->alpha_func && p->alpha_func_loc >= 0) {
        dev->gl->fn.Uniform1iv(p->alpha_func_loc, 1, &func);
        p->alpha_func = func;
    }
    if (ref != p->alpha_ref && p->alpha_ref_loc >= 0) {
        dev->gl->fn.Uniform1fv(p->alpha_ref_loc, 1, &ref);
        p->alpha_ref = ref;
    }
}

/* What load reports about a render state GL cannot honour; NULL when mapped. */
static const char *unsupported(uint32_t id, const hfx_rs_value *v, int has_alpha_test) {
    switch (id) {
    case HFX_ST_ZENABLE: return v->i == 2 ? "ZEnable = UseW (w-buffering) is not available in GL; using a z-buffer" : NULL;
    case HFX_ST_ALPHATESTENABLE: case HFX_ST_ALPHAREF: case HFX_ST_ALPHAFUNC:
        return has_alpha_test ? NULL : "alpha test needs the pass's pixel shader to carry it (no hfx_alpha_func uniform); ignored";
    case HFX_ST_LASTPIXEL: return v->i ? "LastPixel = TRUE: GL never draws the last pixel of a line" : NULL;
    case HFX_ST_SHADEMODE: return NULL; /* FLAT: the compiler made the pass's COLOR varyings flat */
    case HFX_ST_CLIPPING: return v->i ? NULL : "Clipping = FALSE cannot be turned off in GL; ignored";
    case HFX_ST_CLIPPLANEENABLE: return v->i ? "ClipPlaneEnable enables GL clip distances; the shaders must write gl_ClipDistance" : NULL;
    case HFX_ST_FOGENABLE: return v->i ? "fixed-function fog is not available in GL core; ignored" : NULL;
    default: break;
    }
    if (hfx_rs_group(id)) return NULL;
    if (id >= HFX_ST_WRAP0 && id <= HFX_ST_WRAP7) return v->i ? "cylindrical texture wrapping (Wrap0..15) is not available in GL; ignored" : NULL;
    if (id >= HFX_ST_WRAP8 && id <= HFX_ST_WRAP15) return v->i ? "cylindrical texture wrapping (Wrap0..15) is not available in GL; ignored" : NULL;
    switch (id) {
    case HFX_ST_SPECULARENABLE: case HFX_ST_FOGCOLOR: case HFX_ST_FOGTABLEMODE: case HFX_ST_FOGSTART:
    case HFX_ST_FOGEND: case HFX_ST_FOGDENSITY: case HFX_ST_RANGEFOGENABLE: case HFX_ST_TEXTUREFACTOR:
    case HFX_ST_LIGHTING: case HFX_ST_AMBIENT: case HFX_ST_FOGVERTEXMODE: case HFX_ST_COLORVERTEX:
    case HFX_ST_LOCALVIEWER: case HFX_ST_NORMALIZENORMALS: case HFX_ST_DIFFUSEMATERIALSOURCE:
    case HFX_ST_SPECULARMATERIALSOURCE: case HFX_ST_AMBIENTMATERIALSOURCE: case HFX_ST_EMISSIVEMATERIALSOURCE:
    case HFX_ST_VERTEXBLEND: case HFX_ST_INDEXEDVERTEXBLENDENABLE: case HFX_ST_TWEENFACTOR:
        return "fixed-function state; shaders do this work, so it has no effect (as in D3D9 with shaders)";
    default:
        return "not available in GL; ignored";
    }
}

static const char *scope_note(const hfx_state_info *info) {
    switch (info->scope) {
    case HFX_SS_STAGE: return "texture-stage state is fixed-function; it has no effect with shaders";
    case HFX_SS_FIXED: return "fixed-function state (lights, materials, transforms, shader constants) is not available in GL; ignored";
    default: return NULL;
    }
}

/* Reports, once at load, a pass state GL cannot honour, with its position. */
void hfx_rs_check(hfx_shared *sh, const hfx_fx_state *st, uint32_t program) {
    const hfx_state_info *info = hfx_state_by_id(st->id);
    if (!info) {
        hfx_shared_warn(sh, st, "unknown state id %u; ignored", (unsigned)st->id);
        return;
    }
    if (st->kind == HFX_FX_VALUE_UNSUPPORTED) {
        hfx_shared_warn(sh, st, "'%s': this value cannot be expressed in GL; ignored", info->name);
        return;
    }
    const char *note = scope_note(info);
    if (!note && info->scope == HFX_SS_RENDER) {
        hfx_rs_value v;
        memset(&v, 0, sizeof v);
        if (st->kind == HFX_FX_VALUE_PARAM || st->kind == HFX_FX_VALUE_EXPR) v.i = 1; /* unknown until Apply */
        else if (st->kind == HFX_FX_VALUE_FLOAT) v.i = hfx_ev_int(st->f[0]);
        else v.i = st->i;
        int alpha = program != HFX_NONE && (sh->fx->programs[program].flags & HFX_FX_PROGRAM_ALPHA_TEST);
        if (st->id == HFX_ST_ALPHATESTENABLE && !v.i) return; /* turning it off needs nothing */
        note = unsupported(st->id, &v, alpha);
    }
    if (note) hfx_shared_warn(sh, st, "'%s': %s", info->name, note);
}
