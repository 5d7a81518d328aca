/* build_states.c: sampler_state blocks, techniques and passes. Every state assignment is
 * resolved against the D3D9 state table (common/states.h) into an hfx_fx_state; the shader
 * states of a pass become one program through the codegen. */
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "effect/build_int.h"
#include "eval_code.h"

static uint32_t add_state(hfx_builder *b, const hfx_fx_state *st) {
    hfx_fx_effect *fx = b->fx;
    if (!HFX_BUILD_GROW(b, fx->states, fx->state_count, b->state_cap)) return HFX_NONE;
    fx->states[fx->state_count] = *st;
    return fx->state_count++;
}

static const char *param_type_name(hfx_builder *b, uint32_t p) {
    return hfx_type_name(b->arena, b->param_types[p]);
}

static bool is_object_param(hfx_builder *b, uint32_t p, hfx_type_kind kind) {
    const hfx_type *ty = hfx_build_innermost(b->param_types[p], NULL);
    return ty && ty->kind == kind;
}

/* `Texture = <t>`, `(t)`, `t`; a texture or sampler state's value must name such a param. */
static bool object_value(hfx_builder *b, const hfx_state_info *info, const hfx_expr *v, hfx_fx_state *out) {
    hfx_type_kind want = info->kind == HFX_SV_TEXTURE ? TY_TEXTURE : TY_SAMPLER;
    out->kind = HFX_FX_VALUE_PARAM;
    out->ref = HFX_NONE;
    if (v->kind == EX_NULL || (v->kind == EX_INT && v->ival == 0)) return true;
    uint32_t p = hfx_build_param_of(b, v);
    if (p == HFX_NONE) {
        if (v->name) hfx_error(b->diags, v->loc, X_UNDECLARED, "undeclared identifier '%s'", v->name);
        else hfx_error(b->diags, v->loc, X_TYPE_MISMATCH, "%s expects a %s parameter", info->name,
                       want == TY_TEXTURE ? "texture" : "sampler");
        return false;
    }
    if (!is_object_param(b, p, want)) {
        hfx_error(b->diags, v->loc, X_TYPE_MISMATCH, "%s expects a %s, '%s' is %s", info->name,
                  want == TY_TEXTURE ? "texture" : "sampler", b->fx->params[p].name, param_type_name(b, p));
        return false;
    }
    out->ref = p;
    return true;
}

/* Folds constant components into the state's value by the kind of value it takes. */
static bool constant_value(hfx_builder *b, const hfx_state_info *info, const hfx_cvec *c, hfx_fx_state *out) {
    switch (info->kind) {
    case HFX_SV_BOOL:
        out->kind = HFX_FX_VALUE_INT;
        out->i = c->v[0] != 0.0;
        return true;
    case HFX_SV_FLOAT:
        out->kind = HFX_FX_VALUE_FLOAT;
        out->count = 1;
        out->f[0] = (float)c->v[0];
        return true;
    case HFX_SV_COLOR: case HFX_SV_VECTOR:
        if (info->kind == HFX_SV_COLOR && c->n == 1 && c->integral) break; /* a D3DCOLOR DWORD */
        out->kind = HFX_FX_VALUE_FLOAT;
        out->count = c->n < 4 ? c->n : 4;
        for (uint32_t i = 0; i < out->count; i++) out->f[i] = (float)c->v[i];
        return true;
    case HFX_SV_MATRIX:
        out->kind = HFX_FX_VALUE_UNSUPPORTED;
        return true;
    default:
        break;
    }
    out->kind = HFX_FX_VALUE_INT;
    double v = c->v[0];
    out->i = v > 2147483647.0 ? (int32_t)hfx_ev_uint(v) : hfx_ev_int(v); /* a uint keeps its bits (colours) */
    return true;
}

static bool is_name(const hfx_expr *v) { return v->kind == EX_IDENT || v->kind == EX_STATE_REF; }

/* The value of `Name = value;` for a state that is not a shader. */
static bool state_value(hfx_builder *b, const hfx_state_info *info, const hfx_expr *v, hfx_fx_state *out) {
    if (info->kind == HFX_SV_TEXTURE || info->kind == HFX_SV_SAMPLER) return object_value(b, info, v, out);
    if (v->kind == EX_ASM || v->kind == EX_COMPILE || v->kind == EX_SAMPLER_STATE) {
        hfx_error(b->diags, v->loc, X_TYPE_MISMATCH, "%s cannot take this value", info->name);
        return false;
    }
    hfx_cvec c = {0};
    const hfx_state_info *names = info->values || info->kind == HFX_SV_BOOL ? info : NULL;
    bool folded = hfx_build_eval(b, v, &c, names);
    bool ok = folded && constant_value(b, info, &c, out);
    hfx_cvec_free(&c);
    if (folded) return ok;
    /* A parameter read when the pass is applied: `ZEnable = <p>;`, `AlphaRef = (p);`. */
    uint32_t p = is_name(v) || v->kind == EX_INDEX ? hfx_build_param_of(b, v) : HFX_NONE;
    if (p != HFX_NONE) {
        const hfx_fx_param *param = &b->fx->params[p];
        bool numeric = param->klass == HFX_CLASS_SCALAR || param->klass == HFX_CLASS_VECTOR ||
                       param->klass == HFX_CLASS_MATRIX;
        if (!numeric || param->elements) {
            hfx_error(b->diags, v->loc, X_TYPE_MISMATCH, "%s cannot take '%s', which is %s", info->name, param->name,
                      param_type_name(b, p));
            return false;
        }
        out->kind = HFX_FX_VALUE_PARAM;
        out->ref = p;
        return true;
    }
    if (is_name(v) && v->name) {
        hfx_error(b->diags, v->loc, X_UNDECLARED, "undeclared identifier '%s'", v->name);
        return false;
    }
    /* An expression of parameters, computed when the pass is applied: `AlphaRef = (Ref * 255);`. */
    if (info->kind != HFX_SV_MATRIX && hfx_build_code(b, v, names, &out->ref, &out->count)) {
        out->kind = HFX_FX_VALUE_EXPR;
        return true;
    }
    hfx_warning(b->diags, v->loc, X_UNSUPPORTED, "%s: state expressions that are not constant are not supported",
                info->name);
    out->kind = HFX_FX_VALUE_UNSUPPORTED;
    return true;
}

/* Looks the state up and checks its [index]. NULL (reported) when unknown. */
static const hfx_state_info *lookup_state(hfx_builder *b, const hfx_state_assign *sa, uint32_t *index) {
    const hfx_state_info *info = sa->name ? hfx_state_lookup(sa->name) : NULL;
    if (!info) {
        hfx_error(b->diags, sa->loc, X_UNKNOWN_STATE, "unrecognized state '%s'", sa->name ? sa->name : "");
        return NULL;
    }
    *index = 0;
    if (!sa->index) return info;
    hfx_cvec c = {0};
    bool ok = hfx_build_eval(b, sa->index, &c, NULL) && c.integral && c.v[0] >= 0 && c.v[0] <= info->max_index;
    if (ok) *index = hfx_ev_uint(c.v[0]);
    hfx_cvec_free(&c);
    if (!ok) {
        hfx_error(b->diags, sa->index->loc, X_INVALID_SUBSCRIPT, "'%s': state index must be a constant from 0 to %u",
                  info->name, info->max_index);
        return NULL;
    }
    return info;
}

/* --- samplers ------------------------------------------------------------------------------ */

static hfx_fx_dim sampler_dim(const hfx_type *ty) {
    switch (ty->dim) {
    case DIM_1D: return HFX_FX_DIM_1D;
    case DIM_3D: return HFX_FX_DIM_3D;
    case DIM_CUBE: return HFX_FX_DIM_CUBE;
    default: return HFX_FX_DIM_2D;
    }
}

/* The D3DTEXTUREFILTERTYPE of a Direct3D 10 filter word: POINT 1, LINEAR 2, ANISOTROPIC 3. */
static int32_t filter_type(const char *word, size_t len) {
    if (len == 5 && strncasecmp(word, "POINT", 5) == 0) return 1;
    if (len == 6 && strncasecmp(word, "LINEAR", 6) == 0) return 2;
    return 0;
}

/* `Filter = MIN_LINEAR_MAG_MIP_POINT;`, Direct3D 10's one filter state, in a sampler an effect
 * shares with Direct3D 9: MinFilter, MagFilter and MipFilter from the POINT / LINEAR word after
 * each of MIN, MAG and MIP; ANISOTROPIC (and COMPARISON_ANISOTROPIC) is anisotropic min and mag
 * filtering with linear mips. True when sa was a Filter state (taken, or reported). */
static bool d3d10_filter(hfx_builder *b, const hfx_state_assign *sa) {
    if (!sa->name || strcasecmp(sa->name, "Filter") != 0 || !sa->value) return false;
    const char *v = is_name(sa->value) ? sa->value->name : NULL;
    int32_t f[3] = {0, 0, 0}; /* min, mag, mip */
    if (v && strncasecmp(v, "COMPARISON_", 11) == 0) v += 11;
    if (v && strcasecmp(v, "ANISOTROPIC") == 0) {
        f[0] = f[1] = 3;
        f[2] = 2;
    }
    bool pending[3] = {false, false, false};
    for (const char *w = v; w && *w && !f[2];) {
        size_t len = strcspn(w, "_");
        int32_t type = filter_type(w, len);
        for (int k = 0; k < 3; k++) {
            static const char *const names[3] = {"MIN", "MAG", "MIP"};
            if (len == 3 && strncasecmp(w, names[k], 3) == 0) pending[k] = true;
            if (type && pending[k]) f[k] = type, pending[k] = false;
        }
        w += len + (w[len] == '_');
    }
    if (!f[0] || !f[1] || !f[2]) {
        hfx_error(b->diags, sa->value->loc, X_TYPE_MISMATCH, "Filter cannot take this value");
        return true;
    }
    static const char *const states[3] = {"MinFilter", "MagFilter", "MipFilter"};
    for (int k = 0; k < 3; k++)
        add_state(b, &(hfx_fx_state){.id = hfx_state_lookup(states[k])->id, .kind = HFX_FX_VALUE_INT, .i = f[k],
                                     .line = sa->loc.line, .col = sa->loc.col});
    return true;
}

/* A state name fxc does not know, in a sampler block: fxc skips it, so an effect that also
 * targets Direct3D 10 (MaxAnisotropy's D3D10 spelling, ComparisonFunc...) still loads. */
static bool unknown_sampler_state(hfx_builder *b, const hfx_state_assign *sa) {
    if (!sa->name || hfx_state_lookup(sa->name)) return false;
    hfx_warning(b->diags, sa->loc, X_UNKNOWN_STATE, "unrecognized sampler state '%s' ignored", sa->name);
    return true;
}

static void sampler_block(hfx_builder *b, hfx_fx_sampler *s, const hfx_expr *block) {
    s->first_state = b->fx->state_count;
    for (uint32_t i = 0; i < block->state_count; i++) {
        const hfx_state_assign *sa = &block->states[i];
        if (d3d10_filter(b, sa) || unknown_sampler_state(b, sa)) continue;
        uint32_t index;
        const hfx_state_info *info = lookup_state(b, sa, &index);
        if (!info || !sa->value) continue;
        hfx_fx_state st = {.id = info->id, .index = index, .line = sa->loc.line, .col = sa->loc.col};
        if (info->scope == HFX_SS_TEXTURE) {
            if (object_value(b, info, sa->value, &st)) s->texture_param = st.ref;
            continue;
        }
        if (info->scope != HFX_SS_SAMPLER) {
            hfx_error(b->diags, sa->loc, X_UNKNOWN_STATE, "'%s' is not a sampler state", info->name);
            continue;
        }
        if (state_value(b, info, sa->value, &st)) add_state(b, &st);
    }
    s->state_count = b->fx->state_count - s->first_state;
}

/* The sampler_state block initializing element `e` of a sampler (array) param, or NULL. */
static const hfx_expr *sampler_init(const hfx_decl *d, uint32_t e, bool element) {
    const hfx_expr *init = d ? d->init : NULL;
    if (!init) return NULL;
    if (element && init->kind == EX_INIT_LIST) init = e < init->arg_count ? init->args[e] : NULL;
    return init && init->kind == EX_SAMPLER_STATE ? init : NULL;
}

static void add_sampler(hfx_builder *b, uint32_t p, const hfx_expr *block) {
    hfx_fx_effect *fx = b->fx;
    if (!HFX_BUILD_GROW(b, fx->samplers, fx->sampler_count, b->sampler_cap)) return;
    hfx_fx_sampler *s = &fx->samplers[fx->sampler_count];
    s->param = p;
    s->texture_param = HFX_NONE;
    s->dim = sampler_dim(hfx_build_innermost(b->param_types[p], NULL));
    s->first_state = fx->state_count;
    fx->params[p].sampler = fx->sampler_count++;
    if (block) sampler_block(b, &fx->samplers[fx->params[p].sampler], block);
}

bool hfx_build_samplers(hfx_builder *b) {
    hfx_fx_effect *fx = b->fx;
    for (uint32_t p = 0; p < fx->param_count; p++) {
        const hfx_type *ty = b->param_types[p];
        if (!ty || ty->kind != TY_SAMPLER) continue;
        hfx_fx_param *param = &fx->params[p];
        bool element = param->parent != HFX_NONE;
        uint32_t top = element ? param->parent : p;
        if (element && fx->params[top].parent != HFX_NONE) {
            add_sampler(b, p, NULL); /* a sampler inside a struct: no initializer to read */
            continue;
        }
        uint32_t e = element ? p - fx->params[top].first_child : 0;
        add_sampler(b, p, sampler_init(b->param_decls[top], e, element));
    }
    return !b->failed_alloc;
}

/* --- shaders and programs ------------------------------------------------------------------ */

/* A shader array indexed by an expression of parameters: D3D9 picks the entry at Apply. */
typedef struct shader_select {
    const hfx_expr *array;    /* its initializer list */
    const hfx_expr *index;
    uint32_t param;           /* the array parameter (HFX_NONE: not one), for fx_2_0's writer */
} shader_select;

/* Follows a shader state's value to its `compile` expression: through shader variables and
 * constant indices into shader arrays. 1 found, 0 NULL (no shader), -1 reported, 2 an array
 * indexed by a non-constant expression (*sel filled; sel NULL: not allowed here). */
static int shader_compile(hfx_builder *b, const hfx_expr *v, const hfx_expr **out, shader_select *sel, int depth) {
    *out = NULL;
    if (!v || depth > 16) return -1;
    switch (v->kind) {
    case EX_COMPILE: *out = v; return 1;
    case EX_NULL: return 0;
    case EX_INT: if (v->ival == 0) return 0; break;
    case EX_IDENT: case EX_STATE_REF: {
        const hfx_decl *d = v->kind == EX_IDENT && v->sym ? v->sym : hfx_build_global(b, v->name);
        if (!d) {
            hfx_error(b->diags, v->loc, X_UNDECLARED, "undeclared identifier '%s'", v->name ? v->name : "");
            return -1;
        }
        if (!d->init) return 0;
        return shader_compile(b, d->init, out, sel, depth + 1);
    }
    case EX_INDEX: {
        if (v->arg_count != 2) break;
        hfx_cvec c = {0};
        bool constant = hfx_build_eval(b, v->args[1], &c, NULL) && c.integral;
        int64_t i = constant ? hfx_ev_int(c.v[0]) : -1;
        hfx_cvec_free(&c);
        const hfx_expr *arr = v->args[0];
        const hfx_decl *d = arr->kind == EX_IDENT && arr->sym ? arr->sym : hfx_build_global(b, arr->name);
        const hfx_expr *init = d ? d->init : NULL;
        if (!constant && init && init->kind == EX_INIT_LIST && init->arg_count && sel) {
            sel->array = init; /* chosen at Apply: the pass gets a variant per reachable index */
            sel->index = v->args[1];
            sel->param = hfx_build_param_of(b, arr);
            return 2;
        }
        if (!init || init->kind != EX_INIT_LIST || i < 0 || i >= init->arg_count) {
            hfx_error(b->diags, v->loc, X_INVALID_SUBSCRIPT, "shader array index %lld is out of bounds", (long long)i);
            return -1;
        }
        return shader_compile(b, init->args[i], out, NULL, depth + 1);
    }
    case EX_ASM:
        hfx_warning(b->diags, v->loc, X_UNSUPPORTED, "asm shaders are not supported; the pass sets no shader");
        return -1;
    default: break;
    }
    hfx_error(b->diags, v->loc, X_TYPE_MISMATCH, "a shader state takes compile, NULL or a shader variable");
    return -1;
}

static bool same_compile_args(hfx_builder *b, const hfx_expr *x, const hfx_expr *y) {
    if (x == y) return true;
    hfx_cvec cx = {0}, cy = {0};
    bool same = hfx_build_eval(b, x, &cx, NULL) && hfx_build_eval(b, y, &cy, NULL) && cx.n == cy.n &&
                memcmp(cx.v, cy.v, sizeof *cx.v * cx.n) == 0;
    hfx_cvec_free(&cx);
    hfx_cvec_free(&cy);
    return same;
}

static bool same_compile(hfx_builder *b, const hfx_expr *x, const hfx_expr *y) {
    if (x == y) return true;
    if (!x || !y || !x->name || !y->name || !x->profile || !y->profile) return false;
    if (strcmp(x->name, y->name) != 0 || strcasecmp(x->profile, y->profile) != 0) return false;
    if (x->fn != y->fn || x->arg_count != y->arg_count) return false;
    for (uint32_t i = 0; i < x->arg_count; i++)
        if (!same_compile_args(b, x->args[i], y->args[i])) return false;
    return true;
}

static bool same_compile_cb(void *b, const hfx_expr *x, const hfx_expr *y) { return same_compile(b, x, y); }

/* Does a pass enable D3D9's alpha test (AlphaTestEnable = anything but a constant false)? Render
 * states are set only by passes (and stay set for the next), so when none does, no program
 * needs the test's code, and an effect that never uses it never pays for it. */
static bool pass_enables_alpha_test(hfx_builder *b, const hfx_pass_ast *pass) {
    for (uint32_t i = 0; i < pass->state_count; i++) {
        const hfx_state_assign *s = &pass->states[i];
        if (strcasecmp(s->name, "AlphaTestEnable") != 0 || !s->value) continue;
        hfx_cvec v = {0};
        bool off = hfx_build_eval(b, s->value, &v, hfx_state_lookup(s->name)) && v.n >= 1 && v.v[0] == 0;
        hfx_cvec_free(&v);
        if (!off) return true;
    }
    return false;
}

static bool effect_enables_alpha_test(hfx_builder *b) {
    for (uint32_t i = 0; i < b->ast->decl_count; i++) {
        const hfx_decl *d = b->ast->decls[i];
        if (d->kind != DECL_TECHNIQUE || !d->technique) continue;
        for (uint32_t k = 0; k < d->technique->pass_count; k++)
            if (pass_enables_alpha_test(b, &d->technique->passes[k])) return true;
    }
    return false;
}

/* The program for a (vs, ps) pair: an earlier identical one, or a new one from the codegen. */
static uint32_t program_for(hfx_builder *b, const hfx_expr *vs, const hfx_expr *ps, bool flat, hfx_loc loc) {
    hfx_fx_effect *fx = b->fx;
    for (uint32_t i = 0; i < fx->program_count; i++)
        if (same_compile(b, b->keys[i].vs, vs) && same_compile(b, b->keys[i].ps, ps) && b->keys[i].flat_colors == flat) return i;
    if (!b->cg)
        b->cg = hfx_codegen_new(b->arena, b->diags, b->types, b->ast, fx, b->targets,
                                (b->diags->flags & HFXC_PACK_UNIFORMS) != 0, /* the diags carry hfxc_options.flags */
                                same_compile_cb, b);
    if (b->cg) hfx_codegen_set_alpha_test(b->cg, effect_enables_alpha_test(b));
    if (!b->cg) {
        hfx_error(b->diags, loc, X_UNSUPPORTED, "the code generator could not start");
        return HFX_NONE;
    }
    hfx_fx_program *prog = &b->pending; /* the builder's, so an escaping failure frees it */
    if (hfx_codegen_program(b->cg, vs, ps, flat, prog) != 0) {
        hfx_fx_program_clear(prog);
        /* a stage shared by many passes reports its errors once, at its first pass */
        if (b->diags->errors == 0)
            hfx_error(b->diags, loc, X_UNSUPPORTED, "code generation failed for this pass");
        return HFX_NONE;
    }
    /* the keys have their own capacity (in the arena): a failure between the two growths
     * once left them shorter than the programs (found by tests/alloc) */
    if (!HFX_ARENA_GROW(b->arena, b->keys, fx->program_count, b->key_cap, 8) ||
        !HFX_BUILD_GROW(b, fx->programs, fx->program_count, b->program_cap)) {
        b->failed_alloc = true;
        hfx_fx_program_clear(prog);
        return HFX_NONE;
    }
    b->keys[fx->program_count] = (hfx_program_key){vs, ps, flat};
    fx->programs[fx->program_count] = *prog;
    memset(prog, 0, sizeof *prog);
    return fx->program_count++;
}

/* --- passes and techniques ----------------------------------------------------------------- */

typedef struct pass_shaders {
    const hfx_expr *vs, *ps;  /* the compile expressions the pass's shader states lead to */
    bool any;                 /* a shader state was set (even to NULL) */
    bool set[2];              /* vertex, pixel: the pass names that stage's shader (even NULL) */
    bool flat_colors;         /* ShadeMode = FLAT: COLOR varyings are not interpolated */
    shader_select sel[2];     /* vertex, pixel: a shader array chosen at Apply (array NULL: none) */
    uint32_t sel_state[2];    /* the EXPR state computing that index */
} pass_shaders;

static void pass_state(hfx_builder *b, const hfx_state_assign *sa, pass_shaders *sh) {
    uint32_t index;
    const hfx_state_info *info = lookup_state(b, sa, &index);
    if (!info || !sa->value) return;
    hfx_fx_state st = {.id = info->id, .index = index, .line = sa->loc.line, .col = sa->loc.col};
    if (info->kind == HFX_SV_SHADER) {
        const hfx_expr *c;
        bool vertex = strcasecmp(info->name, "VertexShader") == 0;
        shader_select *sel = &sh->sel[vertex ? 0 : 1];
        int found = shader_compile(b, sa->value, &c, sel, 0);
        if (found == 2 && hfx_build_selector(b, sel->index, sel->array->arg_count, &st.ref, &st.count)) {
            st.kind = HFX_FX_VALUE_EXPR;
            st.source = sel->param != HFX_NONE ? sel->param + 1 : 0;
            sh->sel_state[vertex ? 0 : 1] = b->fx->state_count;
            sh->any = true;
            add_state(b, &st);
            return;
        }
        if (found == 2) {
            hfx_error(b->diags, sel->index->loc, X_UNSUPPORTED,
                      "a shader array index must be an expression of parameters and constants");
            sel->array = NULL;
            found = -1;
        }
        sh->set[vertex ? 0 : 1] = true;
        if (found < 0) {
            st.kind = HFX_FX_VALUE_UNSUPPORTED;
        } else {
            if (vertex) sh->vs = c;
            else sh->ps = c;
            sh->any = true;
            st.kind = HFX_FX_VALUE_PROGRAM;
            st.ref = HFX_NONE; /* set once the pass's program is known */
        }
        add_state(b, &st);
        return;
    }
    if (!state_value(b, info, sa->value, &st)) return;
    if (info->id == HFX_ST_SHADEMODE && st.kind == HFX_FX_VALUE_INT) sh->flat_colors = st.i == 1; /* D3DSHADE_FLAT */
    add_state(b, &st);
}

/* --- shader arrays chosen at Apply ---------------------------------------------------------- */

/* The top-level parameter whose value words start at `offset`, or HFX_NONE. */
static uint32_t param_at(const hfx_fx_effect *fx, uint32_t offset) {
    for (uint32_t i = 0; i < fx->top_param_count; i++)
        if (fx->params[i].offset == offset && fx->params[i].words) return i;
    return HFX_NONE;
}

/* The one scalar int parameter the selectors read directly (ShaderIndex), HFX_NONE when they
 * read none; false when they read several (not enumerated). */
static bool selector_driver(const hfx_fx_effect *fx, const pass_shaders *sh, uint32_t *driver) {
    *driver = HFX_NONE;
    for (int s = 0; s < 2; s++) {
        if (!sh->sel[s].array) continue;
        const hfx_fx_state *st = &fx->states[sh->sel_state[s]];
        const uint32_t *code = fx->exprs + st->ref;
        for (uint32_t at = 0; at < st->count; at = hfx_evc_next(code, at, st->count)) {
            if ((code[at] & 0xffu) != HFX_EVC_PARAM) continue;
            uint32_t p = param_at(fx, code[at + 1]);
            if (p == HFX_NONE || fx->params[p].klass != HFX_CLASS_SCALAR || fx->params[p].type != HFX_TYPE_INT) return false;
            if (*driver != HFX_NONE && *driver != p) return false;
            *driver = p;
        }
    }
    return true;
}

/* The index selector s gives with these parameter values (HFX_NONE: that stage is fixed). */
static uint32_t selected(const hfx_fx_effect *fx, const pass_shaders *sh, int s, const uint32_t *values) {
    if (!sh->sel[s].array) return HFX_NONE;
    const hfx_fx_state *st = &fx->states[sh->sel_state[s]];
    hfx_ev_value v;
    return hfx_evc_run(fx->exprs + st->ref, st->count, values, &v) ? hfx_evc_index(&v, HFX_NONE - 1) : 0;
}

/* The program of one pair of array entries (or the pass's fixed shader for a fixed stage). */
static uint32_t variant_program(hfx_builder *b, const pass_shaders *sh, const uint32_t idx[2], hfx_loc loc) {
    const hfx_expr *c[2] = {sh->vs, sh->ps};
    for (int s = 0; s < 2; s++)
        if (idx[s] != HFX_NONE && shader_compile(b, sh->sel[s].array->args[idx[s]], &c[s], NULL, 0) < 0) return HFX_NONE;
    return program_for(b, c[0], c[1], sh->flat_colors, loc);
}

static void add_variant(hfx_builder *b, uint32_t pass, const uint32_t idx[2], uint32_t program) {
    hfx_fx_effect *fx = b->fx;
    for (uint32_t i = 0; i < fx->variant_count; i++)
        if (fx->variants[i].pass == pass && fx->variants[i].vs == idx[0] && fx->variants[i].ps == idx[1]) return;
    if (!HFX_BUILD_GROW(b, fx->variants, fx->variant_count, b->variant_cap)) return;
    fx->variants[fx->variant_count++] = (hfx_fx_variant){pass, idx[0], idx[1], program};
}

enum { MAX_DRIVER_VALUE = 256 }; /* ShaderIndex values tried; tables clamp beyond their ends */

/* Every pair of entries the selectors reach as their driving parameter takes each value, the
 * others keeping their defaults (XNA's classes set ShaderIndex alone): one program each. */
static void build_variants(hfx_builder *b, const pass_shaders *sh, uint32_t pass, hfx_loc loc) {
    hfx_fx_effect *fx = b->fx;
    uint32_t driver;
    if (!selector_driver(fx, sh, &driver)) {
        hfx_error(b->diags, loc, X_UNSUPPORTED, "shader arrays chosen by more than one int parameter are not supported");
        return;
    }
    uint32_t *values = HFX_NEW_ARRAY(b->arena, uint32_t, fx->value_words ? fx->value_words : 1);
    if (!values) { b->failed_alloc = true; return; }
    memcpy(values, fx->values, fx->value_words * sizeof *values);
    for (int v = 0; v < (driver == HFX_NONE ? 1 : MAX_DRIVER_VALUE); v++) {
        if (driver != HFX_NONE) values[fx->params[driver].offset] = (uint32_t)v;
        uint32_t idx[2] = {selected(fx, sh, 0, values), selected(fx, sh, 1, values)}, prog;
        bool known = false;
        for (uint32_t i = 0; i < fx->variant_count; i++)
            known |= fx->variants[i].pass == pass && fx->variants[i].vs == idx[0] && fx->variants[i].ps == idx[1];
        if (!known && (prog = variant_program(b, sh, idx, loc)) != HFX_NONE) add_variant(b, pass, idx, prog);
    }
}

/* The shaders a D3D9 device holds after a pass: a pass that names no vertex (pixel) shader keeps
 * the one the previous pass of the technique set, as the device keeps it between passes (XNA
 * effects that set VertexShader in pass 0 only). A stage chosen from a shader array at Apply is
 * not carried over (which entry the device holds is known only then). */
typedef struct held_shaders { const hfx_expr *c[2]; bool held[2]; } held_shaders;

static void keep_held(pass_shaders *sh, held_shaders *held) {
    const hfx_expr **c[2] = {&sh->vs, &sh->ps};
    for (int s = 0; s < 2; s++) {
        if (!sh->set[s] && held->held[s]) {
            *c[s] = held->c[s];
            sh->any = true;
        }
        if (sh->set[s]) {
            held->c[s] = *c[s];
            held->held[s] = !sh->sel[s].array;
        }
    }
}

static void build_pass(hfx_builder *b, const hfx_pass_ast *pa, hfx_fx_pass *pass, uint32_t index, held_shaders *held) {
    pass->name = hfx_build_strdup(b, pa->name ? pa->name : "");
    pass->annotation_count = hfx_build_annotations(b, pa->annotations, pa->annotation_count, &pass->first_annotation);
    pass->first_state = b->fx->state_count;
    pass->program = HFX_NONE;
    pass_shaders sh = {0};
    for (uint32_t i = 0; i < pa->state_count; i++) pass_state(b, &pa->states[i], &sh);
    pass->state_count = b->fx->state_count - pass->first_state;
    keep_held(&sh, held);
    if (sh.sel[0].array || sh.sel[1].array) build_variants(b, &sh, index, pa->loc);
    else if (sh.any && (sh.vs || sh.ps)) pass->program = program_for(b, sh.vs, sh.ps, sh.flat_colors, pa->loc);
    for (uint32_t i = 0; i < pass->state_count; i++) {
        hfx_fx_state *st = &b->fx->states[pass->first_state + i];
        if (st->kind == HFX_FX_VALUE_PROGRAM) st->ref = pass->program;
    }
}

void hfx_build_technique(hfx_builder *b, const hfx_technique_ast *ta) {
    hfx_fx_effect *fx = b->fx;
    if (!HFX_BUILD_GROW(b, fx->techniques, fx->technique_count, b->technique_cap)) return;
    uint32_t t = fx->technique_count++;
    fx->techniques[t].name = hfx_build_strdup(b, ta->name ? ta->name : "");
    fx->techniques[t].annotation_count =
        hfx_build_annotations(b, ta->annotations, ta->annotation_count, &fx->techniques[t].first_annotation);
    fx->techniques[t].first_pass = fx->pass_count;
    held_shaders held = {{NULL, NULL}, {false, false}};
    for (uint32_t i = 0; i < ta->pass_count; i++) {
        if (!HFX_BUILD_GROW(b, fx->passes, fx->pass_count, b->pass_cap)) return;
        /* built in its slot, already counted, so that the effect owns its name at once (an
         * escaping allocation failure frees it with the effect); build_pass may grow other
         * arrays but not passes, so the slot stays where it is */
        hfx_fx_pass *pass = &fx->passes[fx->pass_count];
        memset(pass, 0, sizeof *pass);
        build_pass(b, &ta->passes[i], pass, fx->pass_count++, &held);
        fx->techniques[t].pass_count++;
    }
}

/* technique10 / technique11: an effect written for Direct3D 9 and 10 keeps both kinds side by
 * side; fx_2_0 loads the Direct3D 9 ones and skips these (checked, not built), with a warning. */
static bool is_d3d10_technique(hfx_builder *b, const hfx_decl *d) {
    const char *k = d->technique->keyword;
    if (!k || (strcasecmp(k, "technique10") != 0 && strcasecmp(k, "technique11") != 0)) return false;
    hfx_warning(b->diags, d->loc, X_UNSUPPORTED, "'%s': %s is Direct3D 10 effect syntax, ignored in fx_2_0",
                d->technique->name ? d->technique->name : "", k);
    return true;
}

bool hfx_build_techniques(hfx_builder *b) {
    for (uint32_t i = 0; i < b->ast->decl_count; i++) {
        const hfx_decl *d = b->ast->decls[i];
        if (d->kind == DECL_TECHNIQUE && d->technique && !is_d3d10_technique(b, d)) hfx_build_technique(b, d->technique);
    }
    return !b->failed_alloc;
}
