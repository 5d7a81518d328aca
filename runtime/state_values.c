/* state_values.c: D3D9 render and sampler states as data, for every back end: D3D9's defaults,
 * and a pass or sampler state resolved to its current value (a constant, a parameter, or an
 * expression run by common/eval_code.c over the instance's values). */
#include <string.h>

#include "eval_code.h"
#include "internal.h"

static void set_i(hfx_rs_value *rs, uint32_t id, int32_t v) { rs[id].i = v; }

/* D3D9's defaults (IDirect3DDevice9 documentation). */
void hfx_rs_defaults(hfx_rs_value *rs) {
    memset(rs, 0, sizeof(hfx_rs_value) * HFX_ST_COUNT_);
    set_i(rs, HFX_ST_ZENABLE, 1);
    set_i(rs, HFX_ST_FILLMODE, 3);
    set_i(rs, HFX_ST_SHADEMODE, 2);
    set_i(rs, HFX_ST_ZWRITEENABLE, 1);
    set_i(rs, HFX_ST_LASTPIXEL, 1);
    set_i(rs, HFX_ST_SRCBLEND, 2);
    set_i(rs, HFX_ST_DESTBLEND, 1);
    set_i(rs, HFX_ST_CULLMODE, 3);
    set_i(rs, HFX_ST_ZFUNC, 4);
    set_i(rs, HFX_ST_ALPHAFUNC, 8);
    set_i(rs, HFX_ST_STENCILFAIL, 1);
    set_i(rs, HFX_ST_STENCILZFAIL, 1);
    set_i(rs, HFX_ST_STENCILPASS, 1);
    set_i(rs, HFX_ST_STENCILFUNC, 8);
    set_i(rs, HFX_ST_STENCILMASK, -1);
    set_i(rs, HFX_ST_STENCILWRITEMASK, -1);
    set_i(rs, HFX_ST_CCW_STENCILFAIL, 1);
    set_i(rs, HFX_ST_CCW_STENCILZFAIL, 1);
    set_i(rs, HFX_ST_CCW_STENCILPASS, 1);
    set_i(rs, HFX_ST_CCW_STENCILFUNC, 8);
    set_i(rs, HFX_ST_CLIPPING, 1);
    set_i(rs, HFX_ST_MULTISAMPLEANTIALIAS, 1);
    set_i(rs, HFX_ST_MULTISAMPLEMASK, -1);
    set_i(rs, HFX_ST_COLORWRITEENABLE, 15);
    set_i(rs, HFX_ST_COLORWRITEENABLE1, 15);
    set_i(rs, HFX_ST_COLORWRITEENABLE2, 15);
    set_i(rs, HFX_ST_COLORWRITEENABLE3, 15);
    set_i(rs, HFX_ST_BLENDOP, 1);
    set_i(rs, HFX_ST_SRCBLENDALPHA, 2);
    set_i(rs, HFX_ST_DESTBLENDALPHA, 1);
    set_i(rs, HFX_ST_BLENDOPALPHA, 1);
    for (int c = 0; c < 4; c++) rs[HFX_ST_BLENDFACTOR].f[c] = 1.0f;
}

/* A D3DCOLOR (0xAARRGGBB) as RGBA floats. */
static void unpack_color(uint32_t c, float out[4]) {
    out[0] = (float)((c >> 16) & 255) / 255.0f;
    out[1] = (float)((c >> 8) & 255) / 255.0f;
    out[2] = (float)(c & 255) / 255.0f;
    out[3] = (float)(c >> 24) / 255.0f;
}

/* The state's value, converted to what its kind wants (ints, a float, or an RGBA colour). */
static void convert_value(const hfx_state_info *info, int is_float, int32_t i, const float *f, uint32_t n,
                          hfx_rs_value *out) {
    memset(out, 0, sizeof *out);
    hfx_state_value_kind kind = info ? info->kind : HFX_SV_INT;
    if (kind == HFX_SV_COLOR || kind == HFX_SV_VECTOR) {
        if (is_float) {
            for (uint32_t c = 0; c < 4; c++) out->f[c] = c < n ? f[c] : (c == 3 && n < 4 ? 1.0f : 0.0f);
            if (n == 1) out->f[1] = out->f[2] = out->f[3] = f[0];
        } else {
            unpack_color((uint32_t)i, out->f);
        }
        out->i = is_float ? hfx_ev_int(f[0]) : i;
    } else if (kind == HFX_SV_FLOAT) {
        out->f[0] = is_float ? f[0] : (float)i;
        out->i = hfx_ev_int(out->f[0]);
    } else {
        out->i = is_float ? hfx_ev_int(f[0]) : i;
        out->f[0] = (float)out->i;
    }
}

/* An EXPR state: its program (validated when the effect was loaded) over the current values.
 * When the arithmetic does not fold (an integer division by zero) the state keeps its value. */
static void resolve_expr(const hfx_effect *fx, const hfx_state_info *info, const hfx_fx_state *st, hfx_rs_value *out) {
    const hfx_fx_effect *e = fx->sh->fx;
    hfx_ev_value v;
    if (!hfx_evc_run(e->exprs + st->ref, st->count, fx->values, &v)) return;
    if (v.base != HFX_EV_FLOAT) {
        convert_value(info, 0, (int32_t)hfx_evc_bits(v.base, v.c[0]), NULL, 1, out);
        return;
    }
    float f[4] = {0};
    uint32_t n = v.n > 4 ? 4 : v.n;
    for (uint32_t i = 0; i < n; i++) f[i] = (float)v.c[i];
    convert_value(info, 1, 0, f, n, out);
}

void hfx_rs_resolve(const hfx_effect *fx, const hfx_fx_state *st, hfx_rs_value *out) {
    const hfx_state_info *info = hfx_state_by_id(st->id);
    if (st->kind == HFX_FX_VALUE_EXPR) {
        resolve_expr(fx, info, st, out);
    } else if (st->kind == HFX_FX_VALUE_FLOAT) {
        convert_value(info, 1, 0, st->f, st->count ? st->count : 1, out);
    } else if (st->kind == HFX_FX_VALUE_PARAM && st->ref < fx->sh->fx->param_count) {
        const hfx_fx_param *p = &fx->sh->fx->params[st->ref];
        const uint32_t *w = fx->values + p->offset;
        uint32_t n = p->words > 4 ? 4 : p->words;
        if (n == 0) {
            convert_value(info, 0, 0, NULL, 0, out);
        } else if (p->type == HFX_TYPE_FLOAT) {
            float f[4];
            memcpy(f, w, n * sizeof(float));
            convert_value(info, 1, 0, f, n, out);
        } else {
            convert_value(info, 0, (int32_t)w[0], NULL, 1, out);
        }
    } else {
        convert_value(info, 0, st->i, NULL, 1, out);
    }
}

uint32_t hfx_rs_selected(const hfx_effect *fx, uint32_t state, uint32_t pass, int stage) {
    const hfx_fx_effect *e = fx->sh->fx;
    if (state >= e->state_count) return HFX_NONE;
    uint32_t last = 0;
    for (uint32_t i = 0; i < e->variant_count; i++) {
        uint32_t k = stage ? e->variants[i].ps : e->variants[i].vs;
        if (e->variants[i].pass == pass && k != HFX_NONE && k > last) last = k;
    }
    const hfx_fx_state *st = &e->states[state];
    hfx_ev_value v;
    return hfx_evc_run(e->exprs + st->ref, st->count, fx->values, &v) ? hfx_evc_index(&v, last) : 0;
}

void hfx_sampler_desc_default(hfx_sampler_desc *d) {
    memset(d, 0, sizeof *d);
    d->address[0] = d->address[1] = d->address[2] = 1; /* Wrap */
    d->mag = d->min = 1;                               /* Point */
    d->mip = 0;                                        /* None */
    d->max_anisotropy = 1;
}

void hfx_sampler_desc_apply(hfx_sampler_desc *d, uint32_t id, const hfx_rs_value *v) {
    switch (id) {
    case HFX_ST_ADDRESSU: d->address[0] = v->i; break;
    case HFX_ST_ADDRESSV: d->address[1] = v->i; break;
    case HFX_ST_ADDRESSW: d->address[2] = v->i; break;
    case HFX_ST_MAGFILTER: d->mag = v->i; break;
    case HFX_ST_MINFILTER: d->min = v->i; break;
    case HFX_ST_MIPFILTER: d->mip = v->i; break;
    case HFX_ST_MAXMIPLEVEL: d->max_mip_level = v->i; break;
    case HFX_ST_MAXANISOTROPY: d->max_anisotropy = v->i; break;
    case HFX_ST_SRGBTEXTURE: d->srgb = v->i != 0, d->srgb_set = 1; break;
    case HFX_ST_MIPMAPLODBIAS: d->lod_bias = v->f[0]; break;
    case HFX_ST_BORDERCOLOR: memcpy(d->border, v->f, sizeof d->border); break;
    default: break;
    }
}

/* Adds a state to a sampler being built: constants into the description, PARAM and EXPR ones
 * (computed at Apply) to dyn. */
void hfx_sampler_state_add(const hfx_fx_state *st, hfx_sampler_desc *d, const hfx_fx_state **dyn, uint32_t *n) {
    if (st->kind == HFX_FX_VALUE_UNSUPPORTED) return; /* the back end reports it at load */
    if (st->kind == HFX_FX_VALUE_PARAM || st->kind == HFX_FX_VALUE_EXPR) {
        if (*n < 32) dyn[(*n)++] = st;
        return;
    }
    hfx_rs_value v;
    hfx_rs_resolve(NULL, st, &v);
    hfx_sampler_desc_apply(d, st->id, &v);
}

/* Shared by the back ends: GL makes sampler objects of it, Vulkan keeps it for its cache. */
void hfx_sampler_desc_of(const hfx_fx_effect *fx, uint32_t sampler, hfx_sampler_desc *d, const hfx_fx_state **dyn,
                         uint32_t *n) {
    hfx_sampler_desc_default(d);
    *n = 0;
    if (sampler >= fx->sampler_count) return;
    const hfx_fx_sampler *s = &fx->samplers[sampler];
    for (uint32_t i = 0; i < s->state_count && s->first_state + i < fx->state_count; i++) {
        const hfx_fx_state *st = &fx->states[s->first_state + i];
        if (st->id != HFX_ST_TEXTURE) hfx_sampler_state_add(st, d, dyn, n);
    }
}
