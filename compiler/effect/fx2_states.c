/* fx2_states.c: fx_2_0's states onto hfx's (common/states.h), the resource table that says
 * what an object-valued or computed state holds (a parameter's name, shader bytecode, an
 * expression, a shader array picked by an expression), and the passes' programs. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect/build.h"
#include "effect/fx2_int.h"
#include "eval_code.h"
#include "glsl/glslang.h"
#include "ir/ir.h"
#include "states.h"

/* The state operations in D3DX's order (the number a state record stores), spelled as
 * common/state_list.h spells them (fxc's names; hfx_state_lookup ignores case). */
static const char *const op_names[OP_COUNT] = {
    /* render states */
    "ZEnable", "FillMode", "ShadeMode", "ZWriteEnable", "AlphaTestEnable", "LastPixel", "SrcBlend", "DestBlend",
    "CullMode", "ZFunc", "AlphaRef", "AlphaFunc", "DitherEnable", "AlphaBlendEnable", "FogEnable", "SpecularEnable",
    "FogColor", "FogTableMode", "FogStart", "FogEnd", "FogDensity", "RangeFogEnable", "StencilEnable", "StencilFail",
    "StencilZFail", "StencilPass", "StencilFunc", "StencilRef", "StencilMask", "StencilWriteMask", "TextureFactor",
    "Wrap0", "Wrap1", "Wrap2", "Wrap3", "Wrap4", "Wrap5", "Wrap6", "Wrap7", "Wrap8", "Wrap9", "Wrap10", "Wrap11",
    "Wrap12", "Wrap13", "Wrap14", "Wrap15", "Clipping", "Lighting", "Ambient", "FogVertexMode", "ColorVertex",
    "LocalViewer", "NormalizeNormals", "DiffuseMaterialSource", "SpecularMaterialSource", "AmbientMaterialSource",
    "EmissiveMaterialSource", "VertexBlend", "ClipPlaneEnable", "PointSize", "PointSize_Min", "PointSize_Max",
    "PointSpriteEnable", "PointScaleEnable", "PointScale_A", "PointScale_B", "PointScale_C", "MultiSampleAntiAlias",
    "MultiSampleMask", "PatchEdgeStyle", "DebugMonitorToken", "IndexedVertexBlendEnable", "ColorWriteEnable",
    "TweenFactor", "BlendOp", "PositionDegree", "NormalDegree", "ScissorTestEnable", "SlopeScaleDepthBias",
    "AntiAliasedLineEnable", "MinTessellationLevel", "MaxTessellationLevel", "AdaptiveTess_X", "AdaptiveTess_Y",
    "AdaptiveTess_Z", "AdaptiveTess_W", "EnableAdaptiveTessellation", "TwoSidedStencilMode", "CCW_StencilFail",
    "CCW_StencilZFail", "CCW_StencilPass", "CCW_StencilFunc", "ColorWriteEnable1", "ColorWriteEnable2",
    "ColorWriteEnable3", "BlendFactor", "SRGBWriteEnable", "DepthBias", "SeparateAlphaBlendEnable", "SrcBlendAlpha",
    "DestBlendAlpha", "BlendOpAlpha",
    /* texture stage states */
    "ColorOp", "ColorArg0", "ColorArg1", "ColorArg2", "AlphaOp", "AlphaArg0", "AlphaArg1", "AlphaArg2", "ResultArg",
    "BumpEnvMat00", "BumpEnvMat01", "BumpEnvMat10", "BumpEnvMat11", "TexCoordIndex", "BumpEnvLScale",
    "BumpEnvLOffset", "TextureTransformFlags", "Constant",
    /* fixed function */
    "NPatchMode", "FVF", "ProjectionTransform", "ViewTransform", "WorldTransform", "TextureTransform",
    "MaterialDiffuse", "MaterialAmbient", "MaterialSpecular", "MaterialEmissive", "MaterialPower", "LightType",
    "LightDiffuse", "LightSpecular", "LightAmbient", "LightPosition", "LightDirection", "LightRange", "LightFalloff",
    "LightAttenuation0", "LightAttenuation1", "LightAttenuation2", "LightTheta", "LightPhi", "LightEnable",
    /* shaders and their constants */
    "VertexShader", "PixelShader", "VertexShaderConstantF", "VertexShaderConstantB", "VertexShaderConstantI",
    "VertexShaderConstant", "VertexShaderConstant1", "VertexShaderConstant2", "VertexShaderConstant3",
    "VertexShaderConstant4", "PixelShaderConstantF", "PixelShaderConstantB", "PixelShaderConstantI",
    "PixelShaderConstant", "PixelShaderConstant1", "PixelShaderConstant2", "PixelShaderConstant3",
    "PixelShaderConstant4",
    /* textures and sampler states */
    "Texture", "AddressU", "AddressV", "AddressW", "BorderColor", "MagFilter", "MinFilter", "MipFilter",
    "MipMapLodBias", "MaxMipLevel", "MaxAnisotropy", "SRGBTexture", "ElementIndex", "DMapOffset", "Sampler"};

const char *hfx_fx2_op_name(uint32_t op) { return op < OP_COUNT ? op_names[op] : NULL; }

uint32_t hfx_fx2_state_id(uint32_t op) {
    const hfx_state_info *st = op < OP_COUNT ? hfx_state_lookup(op_names[op]) : NULL;
    return st ? st->id : 0;
}

static bool is_shader_op(uint32_t op) { return op == OP_VERTEXSHADER || op == OP_PIXELSHADER; }

void hfx_fx2_state_value(fx2_reader *r, const fx2_raw *raw, hfx_fx_state *st) {
    fx2_raw *rw = (fx2_raw *)raw;
    memset(st, 0, sizeof *st);
    st->id = hfx_fx2_state_id(raw->op);
    st->index = raw->index;
    st->col = hfx_fx2_file_at(r, raw->at); /* load-time reports locate the state in the file */
    rw->object = HFX_NONE;
    if (!st->id) {
        hfx_fx2_fatal(r, raw->at, "unknown state operation %u", raw->op);
        return;
    }
    const fx2_type *t = &raw->type;
    if (t->klass == PC_OBJECT && t->type >= PT_SAMPLER && t->type <= PT_SAMPLERCUBE) {
        /* A sampler's value is a block (state count, records): fxc's `Sampler[0] = <S>` leaves it
         * empty and names S in a resource; a block of its own is not read (hfx has no inline one). */
        uint32_t count;
        if (!hfx_fx2_u32(r, raw->value_at, &count, "state value")) return;
        st->kind = count ? HFX_FX_VALUE_UNSUPPORTED : HFX_FX_VALUE_PARAM;
        st->ref = HFX_NONE;
        return;
    }
    if (t->klass == PC_OBJECT) {
        uint32_t id;
        if (!hfx_fx2_u32(r, raw->value_at, &id, "state value")) return;
        if (id >= r->object_count) {
            hfx_fx2_fatal(r, raw->at + 12, "state %s: object %u is outside the object table (%u objects)",
                          op_names[raw->op], id, r->object_count);
            return;
        }
        rw->object = id;
        r->objects[id].type = t->type;
        st->kind = is_shader_op(raw->op) ? HFX_FX_VALUE_PROGRAM : HFX_FX_VALUE_PARAM;
        st->ref = HFX_NONE;
        return;
    }
    uint32_t n = t->words * (t->elements ? t->elements : 1);
    if (t->klass == PC_STRUCT || n > 4) { /* transforms (matrices): fixed function that hfx does not run */
        st->kind = HFX_FX_VALUE_UNSUPPORTED;
        return;
    }
    uint32_t w[4] = {0};
    for (uint32_t i = 0; i < n; i++)
        if (!hfx_fx2_u32(r, raw->value_at + 4 * i, &w[i], "state value")) return;
    st->count = n;
    if (t->type == PT_FLOAT) {
        st->kind = HFX_FX_VALUE_FLOAT;
        memcpy(st->f, w, n * sizeof(float));
    } else {
        st->kind = HFX_FX_VALUE_INT;
        st->i = (int32_t)w[0];
        st->count = 1;
    }
}

/* --- resources ------------------------------------------------------------------------------- */

/* The raw state a resource record names: (technique, pass, -, state) or (-1, parameter, element, state). */
static fx2_raw *resource_raw(fx2_reader *r, uint32_t at, const uint32_t w[4]) {
    const hfx_fx_effect *fx = r->fx;
    if (w[0] == HFX_NONE) {
        uint32_t p = w[1];
        if (p >= fx->top_param_count) {
            hfx_fx2_fatal(r, at + 4, "resource: parameter %u is outside the parameters (%u)", p, fx->top_param_count);
            return NULL;
        }
        if (fx->params[p].elements && w[2] != HFX_NONE) {
            if (w[2] >= fx->params[p].child_count) {
                hfx_fx2_fatal(r, at + 8, "resource: element %u of '%s' (%u elements)", w[2], fx->params[p].name,
                              fx->params[p].child_count);
                return NULL;
            }
            p = fx->params[p].first_child + w[2];
        }
        if (w[3] >= r->param_raw_count[p]) {
            hfx_fx2_fatal(r, at + 12, "resource: state %u of sampler '%s' (%u states)", w[3], fx->params[p].name,
                          r->param_raw_count[p]);
            return NULL;
        }
        return &r->raws[r->param_raw_first[p] + w[3]];
    }
    if (w[0] >= fx->technique_count) {
        hfx_fx2_fatal(r, at, "resource: technique %u is outside the techniques (%u)", w[0], fx->technique_count);
        return NULL;
    }
    const hfx_fx_technique *t = &fx->techniques[w[0]];
    if (w[1] >= t->pass_count) {
        hfx_fx2_fatal(r, at + 4, "resource: pass %u of technique '%s' (%u passes)", w[1], t->name, t->pass_count);
        return NULL;
    }
    uint32_t pass = t->first_pass + w[1];
    if (w[3] >= fx->passes[pass].state_count) {
        hfx_fx2_fatal(r, at + 12, "resource: state %u of pass '%s' (%u states)", w[3], fx->passes[pass].name,
                      fx->passes[pass].state_count);
        return NULL;
    }
    return &r->raws[r->pass_raw_first[pass] + w[3]];
}

bool hfx_fx2_resources(fx2_reader *r, uint32_t off, uint32_t count) {
    if (count > (r->size - (off < r->size ? off : r->size)) / 24) {
        hfx_fx2_fatal(r, off, "%u resources do not fit the data", count);
        return false;
    }
    for (uint32_t i = 0; i < count && !r->failed; i++) {
        uint32_t w[6];
        for (int k = 0; k < 6; k++)
            if (!hfx_fx2_u32(r, off + 4u * (uint32_t)k, &w[k], "resource")) return false;
        uint32_t usage = w[4], size = w[5];
        if (usage > USE_SELECTOR) {
            hfx_fx2_fatal(r, off + 16, "resource %u: unknown usage %u", i, usage);
            return false;
        }
        if (size > r->size - off - 24) {
            hfx_fx2_fatal(r, off + 20, "resource %u: %u bytes run past the end of the data", i, size);
            return false;
        }
        fx2_raw *raw = resource_raw(r, off, w);
        if (!raw) return false;
        raw->usage = (int)usage;
        raw->blob = (fx2_blob){r->data + off + 24, size, hfx_fx2_file_at(r, off + 24)};
        off += 24 + ((size + 3) & ~3u);
        if (off > r->size) off = r->size;
    }
    return true;
}

/* --- states after the resources -------------------------------------------------------------- */

/* The NUL-terminated name at the start of a blob, or NULL (with a located error). */
static const char *blob_name(fx2_reader *r, const fx2_blob *b, uint32_t skip) {
    if (b->size <= skip || !memchr(b->data + skip, 0, b->size - skip)) {
        hfx_error(r->diags, (hfx_loc){r->file, 0, b->at}, X_FX2_BINARY, "a parameter name without its end");
        r->failed = true;
        return NULL;
    }
    return (const char *)b->data + skip;
}

static const char *state_name(const fx2_raw *raw) { return op_names[raw->op]; }

/* `State = <name>`: the parameter it names. */
static uint32_t named_param(fx2_reader *r, const fx2_raw *raw) {
    const char *name = blob_name(r, &raw->blob, 0);
    if (!name) return HFX_NONE;
    uint32_t p = hfx_fx2_param_by_name(r, name);
    if (p == HFX_NONE) {
        hfx_error(r->diags, (hfx_loc){r->file, 0, raw->blob.at}, X_FX2_BINARY, "state %s: no parameter '%s'",
                  state_name(raw), name);
        r->failed = true;
    }
    return p;
}

/* A computed value (usage 0 on a numeric state, or the index of a selector). */
static void expression(fx2_reader *r, const fx2_raw *raw, hfx_fx_state *st, const fx2_blob *code, uint32_t n,
                       hfx_ev_base base) {
    uint32_t first, words;
    if (!hfx_fxlvm_translate(r, code, n, base, &first, &words)) return;
    st->kind = HFX_FX_VALUE_EXPR;
    st->ref = first;
    st->count = words;
    (void)raw;
}

/* The selector `(Array[expression])`: the blob holds the array's name (length first), then the
 * expression; the state becomes the index. */
static void selector(fx2_reader *r, fx2_raw *raw, hfx_fx_state *st) {
    uint32_t len = hfx_fx2_name_len(&raw->blob);
    if (len > raw->blob.size - 4 || raw->blob.size < 4) {
        hfx_error(r->diags, (hfx_loc){r->file, 0, raw->blob.at}, X_FX2_BINARY, "state %s: a shader array selector "
                  "of %u bytes names an array of %u", state_name(raw), raw->blob.size, len);
        r->failed = true;
        return;
    }
    const char *name = blob_name(r, &raw->blob, 4);
    uint32_t p = name ? hfx_fx2_param_by_name(r, name) : HFX_NONE;
    if (name && (p == HFX_NONE || !r->fx->params[p].elements)) {
        hfx_error(r->diags, (hfx_loc){r->file, 0, raw->blob.at + 4}, X_FX2_BINARY, "state %s: '%s' is not an array "
                  "parameter", state_name(raw), name);
        r->failed = true;
    }
    if (r->failed) return;
    uint32_t skip = 4 + ((len + 3) & ~3u);
    if (skip > raw->blob.size) skip = raw->blob.size; /* the name's padding may be cut: the code is then empty */
    fx2_blob code = {raw->blob.data + skip, raw->blob.size - skip, raw->blob.at + skip};
    raw->object = p; /* the array, for the passes' programs */
    expression(r, raw, st, &code, 1, HFX_EV_INT);
    st->source = p + 1;
}

static void resolve(fx2_reader *r, fx2_raw *raw) {
    hfx_fx_effect *fx = r->fx;
    hfx_fx_state scratch, *st = raw->state != HFX_NONE ? &fx->states[raw->state] : &scratch;
    if (raw->usage == USE_NONE) return;
    if (raw->usage == USE_SELECTOR) {
        if (!is_shader_op(raw->op)) {
            hfx_error(r->diags, (hfx_loc){r->file, 0, raw->blob.at}, X_FX2_BINARY, "state %s: an array selector on a "
                      "state that takes no shader", state_name(raw));
            r->failed = true;
            return;
        }
        selector(r, raw, st);
    } else if (raw->usage == USE_PARAM) {
        uint32_t p = named_param(r, raw);
        if (p == HFX_NONE) return;
        if (raw->op == OP_TEXTURE && raw->state == HFX_NONE) { /* a sampler's Texture */
            for (uint32_t s = 0; s < fx->sampler_count; s++)
                if (raw >= &r->raws[r->param_raw_first[fx->samplers[s].param]] &&
                    raw < &r->raws[r->param_raw_first[fx->samplers[s].param] + r->param_raw_count[fx->samplers[s].param]])
                    fx->samplers[s].texture_param = p;
            return;
        }
        if (is_shader_op(raw->op)) { /* `VertexShader = <vs>`: the parameter's bytecode */
            raw->object = r->param_object[p];
            st->source = p + 1;
            return;
        }
        const hfx_fx_param *q = &fx->params[p];
        if (raw->op != OP_TEXTURE && raw->op != OP_SAMPLER && (q->klass == HFX_CLASS_OBJECT || !q->words)) {
            hfx_error(r->diags, (hfx_loc){r->file, 0, raw->blob.at}, X_FX2_BINARY, "state %s: parameter '%s' holds no "
                      "value for it", state_name(raw), q->name);
            r->failed = true;
            return;
        }
        st->kind = HFX_FX_VALUE_PARAM;
        st->ref = p;
    } else if (!is_shader_op(raw->op)) { /* usage 0 on a value: an expression of parameters */
        if (raw->type.klass == PC_OBJECT) return; /* a texture's data: nothing to compute */
        uint32_t n = raw->type.words ? raw->type.words : 1;
        if (n > 4) n = 4;
        expression(r, raw, st, &raw->blob, n, raw->type.type == PT_FLOAT ? HFX_EV_FLOAT : HFX_EV_INT);
    }
}

/* --- programs -------------------------------------------------------------------------------- */

/* What a pass gives one stage: nothing, one shader's bytecode, or an array picked at Apply. */
typedef struct stage_src {
    const fx2_blob *blob;     /* NULL: no shader (fixed function or NULL) */
    uint32_t array;           /* a selector's array parameter, else HFX_NONE */
    uint32_t state;           /* the selector's state */
    uint32_t at;
} stage_src;

/* What made a program: the two shaders' bytecode (NULL: none) and the pass's ShadeMode. */
typedef struct fx2_program_key {
    const uint8_t *vs, *ps;
    bool flat;
} fx2_program_key;

/* GLSL names, as build.c gives compiled parameters: the top-level numerics and samplers, and
 * struct members (by their own names); elements, textures, strings and shaders have none. */
static void glsl_names(fx2_reader *r) {
    hfx_fx_effect *fx = r->fx;
    for (uint32_t i = 0; i < fx->param_count; i++) {
        hfx_fx_param *p = &fx->params[i];
        bool member = p->parent != HFX_NONE && !fx->params[p->parent].elements;
        bool readable = p->klass != HFX_CLASS_OBJECT || (p->type >= HFX_TYPE_SAMPLER && p->type <= HFX_TYPE_SAMPLERCUBE);
        if ((p->parent == HFX_NONE || member) && readable && !p->glsl_name)
            p->glsl_name = hfx_fx2_strdup(r, hfx_glsl_name(r->arena, p->name));
    }
}

/* Whether some pass turns the alpha test on (its pixel shaders then carry it, as build.c's). */
static bool enables_alpha_test(const hfx_fx_effect *fx) {
    for (uint32_t i = 0; i < fx->state_count; i++)
        if (fx->states[i].id == HFX_ST_ALPHATESTENABLE &&
            !(fx->states[i].kind == HFX_FX_VALUE_INT && fx->states[i].i == 0))
            return true;
    return false;
}

static bool pass_is_flat(const hfx_fx_effect *fx, uint32_t pass) {
    const hfx_fx_pass *pa = &fx->passes[pass];
    for (uint32_t i = 0; i < pa->state_count; i++) {
        const hfx_fx_state *st = &fx->states[pa->first_state + i];
        if (st->id == HFX_ST_SHADEMODE && st->kind == HFX_FX_VALUE_INT && st->i == 1) return true; /* D3DSHADE_FLAT */
    }
    return false;
}

/* One shader's bytecode decoded (compiler/d3d9), with its PRES block's registers. */
static d3d9_shader *decode_shader(fx2_reader *r, const fx2_blob *b) {
    if (!b || r->failed) return NULL;
    d3d9_input in = {b->data, b->size, r->file, b->at};
    d3d9_shader *s = hfx_d3d9_decode(r->arena, r->diags, &in);
    if (!s) {
        r->failed = true;
        return NULL;
    }
    for (uint32_t i = 0; i < s->comment_count; i++) {
        const d3d9_comment *c = &s->comments[i];
        if (c->fourcc != 0x53455250u /* PRES */ || c->word_count < 2) continue;
        fx2_blob pres = {b->data + c->offset + 8, (c->word_count - 1) * 4, b->at + c->offset + 8};
        d3d9_preshader_out *outs;
        uint32_t n;
        if (!hfx_fxlvm_preshader(r, &pres, &outs, &n)) return NULL;
        s->pres = outs, s->pre_count = n;
    }
    return s;
}

static void clear_pending(void *p) { hfx_fx_program_clear(p); }

/* A copy of a shader's bytecode in the effect (malloc'ed): what fx_2_0's writer writes back. */
static bool keep_bytecode(fx2_reader *r, hfx_fx_code *c, const fx2_blob *b) {
    if (!b->size) return true;
    if (!(c->data = malloc(b->size))) {
        hfx_error(r->diags, (hfx_loc){r->file, 0, 0}, X_MEMORY_LIMIT, "out of memory reading the effect");
        r->oom = true;
        return false;
    }
    memcpy(c->data, b->data, b->size);
    c->size = b->size;
    return true;
}

/* The bytecode of every shader parameter (and array element) with some. */
static void shader_params(fx2_reader *r) {
    hfx_fx_effect *fx = r->fx;
    for (uint32_t i = 0; i < fx->param_count && !r->failed; i++) {
        hfx_fx_param *p = &fx->params[i];
        uint32_t id = r->param_object[i];
        if ((p->type != HFX_TYPE_VERTEXSHADER && p->type != HFX_TYPE_PIXELSHADER) || p->child_count || id >= r->object_count ||
            !r->objects[id].has_data)
            continue;
        if (!keep_bytecode(r, &p->d3d9, &r->objects[id].blob)) r->failed = true;
    }
}

/* The one place shader bytecode becomes a program: compiler/d3d9 reads and translates each
 * stage, the code generator builds the pass's program as for a compiled effect. A pair made
 * before is shared. */
static uint32_t shader_program(fx2_reader *r, const fx2_blob *vs, const fx2_blob *ps, uint32_t pass, uint32_t at) {
    hfx_fx_effect *fx = r->fx;
    if (!vs && !ps) {
        hfx_fx2_error(r, at, "pass '%s': the shader array entries it picks have no bytecode", fx->passes[pass].name);
        r->failed = true;
        return HFX_NONE;
    }
    bool flat = pass_is_flat(fx, pass);
    for (uint32_t i = 0; i < fx->program_count; i++)
        if (r->keys[i].vs == (vs ? vs->data : NULL) && r->keys[i].ps == (ps ? ps->data : NULL) && r->keys[i].flat == flat)
            return i;
    if (!r->cg) {
        glsl_names(r);
        r->cg = hfx_codegen_new(r->arena, r->diags, hfx_types_new(r->arena), NULL, fx,
                                hfx_build_code_targets(r->targets), /* SPIR-V: hfx_fx2_finish */
                                (r->diags->flags & HFXC_PACK_UNIFORMS) != 0, NULL, NULL);
        if (!r->cg) {
            hfx_fx2_error(r, at, "the code generator could not start");
            r->failed = true;
            return HFX_NONE;
        }
        hfx_codegen_set_alpha_test(r->cg, enables_alpha_test(fx));
    }
    d3d9_shader *v = decode_shader(r, vs), *p = decode_shader(r, ps);
    if (r->failed) return HFX_NONE;
    hfx_fx_program *pending = HFX_NEW(r->arena, hfx_fx_program);
    hfx_arena_cleanup *cleanup = hfx_arena_on_escape(r->arena, clear_pending, pending);
    int rc = hfx_codegen_d3d9_program(r->cg, v, p, flat, pending);
    hfx_arena_forget(r->arena, cleanup);
    uint32_t cap = r->program_cap;
    if (rc < 0 || !FX2_GROW(r, fx->programs, fx->program_count, r->program_cap)) {
        hfx_fx_program_clear(pending);
        r->failed = true;
        return HFX_NONE;
    }
    if (cap != r->program_cap || !r->keys) {
        fx2_program_key *keys = HFX_NEW_ARRAY(r->arena, fx2_program_key, r->program_cap);
        if (r->keys) memcpy(keys, r->keys, fx->program_count * sizeof *keys);
        r->keys = keys;
    }
    r->keys[fx->program_count] = (fx2_program_key){vs ? vs->data : NULL, ps ? ps->data : NULL, flat};
    const fx2_blob *blobs[HFX_STAGE_COUNT] = {vs, ps};
    for (int s = 0; s < HFX_STAGE_COUNT; s++) /* the bytecode itself, for the fx_2_0 writer */
        if (blobs[s] && !keep_bytecode(r, &pending->d3d9[s], blobs[s])) {
            hfx_fx_program_clear(pending);
            r->failed = true;
            return HFX_NONE;
        }
    fx->programs[fx->program_count] = *pending;
    return fx->program_count++;
}

/* Every GLSL shader made, through glslang (unless HFXC_NO_SELF_CHECK), as build.c checks a
 * compiled effect's: a rejection is hfx's own bug, never handed to a driver. */
static void self_check(fx2_reader *r) {
    const hfx_fx_effect *fx = r->fx;
    if ((r->diags->flags & HFXC_NO_SELF_CHECK) || !fx->program_count || !hfx_glslang_available()) return;
    hfx_arena_escape_off(r->arena); /* glslang holds its own memory */
    if (!hfx_glslang_begin()) {
        hfx_error(r->diags, (hfx_loc){r->file, 0, 0}, X_INTERNAL, "internal: glslang could not start for the self-check");
        r->failed = true;
        hfx_arena_escape_on(r->arena);
        return;
    }
    for (uint32_t i = 0; i < fx->program_count; i++)
        for (int s = 0; s < HFX_STAGE_COUNT; s++)
            for (int t = 0; t < HFX_TARGET_SPIRV; t++) {
                char *log = NULL;
                const hfx_fx_code *code = &fx->programs[i].code[s][t];
                if (!code->data || hfx_glslang_check(code->data, s, (hfx_target)t, &log) == 0) continue;
                const char *e = log && strstr(log, "ERROR:") ? strstr(log, "ERROR:") : "glslang gave no reason";
                hfx_error(r->diags, (hfx_loc){r->file, 0, 0}, X_INTERNAL, "internal: the %s shader hfx made from "
                          "program %u's bytecode does not compile (target %d): %.*s", s ? "pixel" : "vertex", i, t,
                          (int)strcspn(e, "\n"), e);
                free(log);
                r->failed = true;
            }
    hfx_glslang_end();
    hfx_arena_escape_on(r->arena);
}

/* The targets every program carries code for. */
static unsigned present_targets(const hfx_fx_effect *fx, unsigned asked) {
    for (uint32_t i = 0; i < fx->program_count; i++) {
        unsigned here = 0;
        for (int t = 0; t < HFX_TARGET_COUNT; t++)
            for (int s = 0; s < HFX_STAGE_COUNT; s++)
                if (fx->programs[i].code[s][t].data) here |= 1u << t;
        asked &= here;
    }
    return asked;
}

static const fx2_blob *object_blob(fx2_reader *r, uint32_t id) {
    return id < r->object_count && r->objects[id].has_data && r->objects[id].blob.size ? &r->objects[id].blob : NULL;
}

static stage_src stage_of(fx2_reader *r, const fx2_raw *raw) {
    stage_src s = {NULL, HFX_NONE, raw->state, raw->at};
    if (raw->usage == USE_SELECTOR) s.array = raw->object;
    else if (raw->usage == USE_DATA) s.blob = raw->blob.size ? &raw->blob : NULL;
    else s.blob = object_blob(r, raw->object);
    return s;
}

/* The shader of array element i (clamped as D3D9 clamps the index). */
static const fx2_blob *element_blob(fx2_reader *r, uint32_t array, uint32_t i) {
    const hfx_fx_param *p = &r->fx->params[array];
    if (!p->child_count) return NULL;
    if (i >= p->child_count) i = p->child_count - 1;
    return object_blob(r, r->param_object[p->first_child + i]);
}

/* The index a selector gives for these values. */
static uint32_t selected(const hfx_fx_effect *fx, const stage_src *s, const uint32_t *values) {
    if (s->array == HFX_NONE) return HFX_NONE;
    const hfx_fx_state *st = &fx->states[s->state];
    hfx_ev_value v;
    uint32_t entries = fx->params[s->array].child_count;
    return hfx_evc_run(fx->exprs + st->ref, st->count, values, &v) ? hfx_evc_index(&v, entries ? entries - 1 : 0) : 0;
}

/* The int parameter the selectors read (XNA's ShaderIndex): the one top-level scalar they
 * read whole, HFX_NONE for none. False when they read more than one. */
static bool driver_of(const hfx_fx_effect *fx, const stage_src s[2], uint32_t *driver) {
    *driver = HFX_NONE;
    for (int k = 0; k < 2; k++) {
        if (s[k].array == HFX_NONE) continue;
        const hfx_fx_state *st = &fx->states[s[k].state];
        const uint32_t *code = fx->exprs + st->ref;
        for (uint32_t at = 0; at < st->count; at = hfx_evc_next(code, at, st->count)) {
            uint32_t p = hfx_fx_param_read_at(fx, code, at);
            if (p == HFX_NONE || (code[at] & 0xff) != HFX_EVC_PARAM || fx->params[p].elements) continue;
            if (*driver != HFX_NONE && *driver != p) return false;
            *driver = p;
        }
    }
    return true;
}

enum { MAX_DRIVER_VALUE = 256 }; /* the values a driving parameter is tried with, as the builder does */

/* A pass drawn from shader arrays: a variant per pair of entries the driver reaches. */
static void pass_variants(fx2_reader *r, uint32_t pass, const stage_src s[2]) {
    hfx_fx_effect *fx = r->fx;
    uint32_t driver;
    if (!driver_of(fx, s, &driver)) {
        hfx_fx2_error(r, s[0].array != HFX_NONE ? s[0].at : s[1].at, "pass '%s': shader arrays chosen by more than one "
                      "parameter are not supported", fx->passes[pass].name);
        r->failed = true;
        return;
    }
    uint32_t *values = HFX_NEW_ARRAY(r->arena, uint32_t, fx->value_words ? fx->value_words : 1);
    memcpy(values, fx->values, fx->value_words * sizeof *values);
    for (int v = 0; v < (driver == HFX_NONE ? 1 : MAX_DRIVER_VALUE) && !r->failed; v++) {
        if (driver != HFX_NONE) values[fx->params[driver].offset] = (uint32_t)v;
        uint32_t idx[2] = {selected(fx, &s[0], values), selected(fx, &s[1], values)};
        bool known = false;
        for (uint32_t i = 0; i < fx->variant_count; i++)
            known |= fx->variants[i].pass == pass && fx->variants[i].vs == idx[0] && fx->variants[i].ps == idx[1];
        if (known) continue;
        const fx2_blob *b[2];
        for (int k = 0; k < 2; k++) b[k] = s[k].array != HFX_NONE ? element_blob(r, s[k].array, idx[k]) : s[k].blob;
        uint32_t prog = shader_program(r, b[0], b[1], pass, s[s[0].array == HFX_NONE].at);
        if (prog == HFX_NONE || !FX2_GROW(r, fx->variants, fx->variant_count, r->variant_cap)) return;
        fx->variants[fx->variant_count++] = (hfx_fx_variant){pass, idx[0], idx[1], prog};
    }
}

/* The stages the passes of a technique have set so far: a pass that names no VertexShader
 * (or PixelShader) keeps the previous pass's, as a D3D9 device keeps its shaders between
 * passes (the builder's keep_held, docs/conventions.md); a stage picked from an array at
 * Apply is not carried. */
typedef struct held_stages {
    stage_src s[2];
    bool held[2];
} held_stages;

static void pass_program(fx2_reader *r, uint32_t pass, held_stages *held) {
    hfx_fx_effect *fx = r->fx;
    hfx_fx_pass *pa = &fx->passes[pass];
    stage_src s[2] = {{NULL, HFX_NONE, HFX_NONE, 0}, {NULL, HFX_NONE, HFX_NONE, 0}};
    bool any = false, set[2] = {false, false};
    for (uint32_t i = 0; i < pa->state_count; i++) {
        const fx2_raw *raw = &r->raws[r->pass_raw_first[pass] + i];
        if (!is_shader_op(raw->op)) continue;
        s[raw->op == OP_PIXELSHADER] = stage_of(r, raw);
        set[raw->op == OP_PIXELSHADER] = any = true;
    }
    for (int k = 0; k < 2; k++) {
        if (!set[k] && held->held[k]) s[k] = held->s[k], any = true;
        if (set[k]) held->s[k] = s[k], held->held[k] = s[k].array == HFX_NONE;
    }
    if (!any) return;
    if (s[0].array != HFX_NONE || s[1].array != HFX_NONE) {
        pass_variants(r, pass, s);
        return;
    }
    if (!s[0].blob && !s[1].blob) return;
    pa->program = shader_program(r, s[0].blob, s[1].blob, pass, 0);
    for (uint32_t i = 0; i < pa->state_count; i++) {
        hfx_fx_state *st = &fx->states[pa->first_state + i];
        if (st->kind == HFX_FX_VALUE_PROGRAM) st->ref = pa->program;
    }
}

bool hfx_fx2_finish(fx2_reader *r) {
    for (uint32_t i = 0; i < r->raw_count && !r->failed; i++) resolve(r, &r->raws[i]);
    if (r->flags & HFX_FX2_DECODE_ONLY) return !r->failed;
    shader_params(r);
    for (uint32_t t = 0; t < r->fx->technique_count && !r->failed; t++) {
        const hfx_fx_technique *te = &r->fx->techniques[t];
        held_stages held = {{{NULL, HFX_NONE, HFX_NONE, 0}, {NULL, HFX_NONE, HFX_NONE, 0}}, {false, false}};
        for (uint32_t p = te->first_pass; p < te->first_pass + te->pass_count && !r->failed; p++)
            pass_program(r, p, &held);
    }
    if (!r->failed && !r->diags->errors) self_check(r);
    if (!r->failed && !r->diags->errors) { /* the SPIR-V step of compiled effects, glslang's memory its own */
        hfx_arena_escape_off(r->arena);
        hfx_build_spirv(r->diags, (hfx_loc){r->file, 0, 0}, r->fx, r->targets);
        hfx_arena_escape_on(r->arena);
    }
    r->fx->targets = present_targets(r->fx, r->targets);
    return !r->failed;
}
