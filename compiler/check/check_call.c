/* check_call.c: calls (user overloads ranked like fxc, then intrinsics), constructors,
 * `compile` expressions, initializers (brace lists flattened to components) and state values. */
#include <string.h>
#include <strings.h>

#include "check/check_ctx.h"
#include "check/intrinsics.h"

enum { MAX_OVERLOADS = 64, MAX_ARGS = 64 };

static const hfx_type *set_type(hfx_expr *e, const hfx_type *t) {
    e->type = t;
    return t;
}

static bool check_args(check_ctx *c, hfx_expr *e) {
    bool ok = true;
    for (uint32_t i = 0; i < e->arg_count; i++)
        if (hfx_ck_is_err(c, hfx_ck_expr(c, e->args[i]))) ok = false;
    return ok;
}

static bool is_out(const hfx_decl *p) { return (p->mods & MOD_OUT) != 0; }

/* ---- user functions ---- */

/* Per-argument costs of calling f with e's arguments; false when f cannot take them. */
static bool candidate_costs(const hfx_func *f, const hfx_expr *e, unsigned *costs) {
    if (e->arg_count > f->param_count) return false;
    for (uint32_t i = e->arg_count; i < f->param_count; i++)
        if (!f->params[i]->init) return false;
    for (uint32_t i = 0; i < e->arg_count; i++) {
        const hfx_type *pt = f->params[i]->type;
        hfx_conv conv = hfx_conv_classify(e->args[i]->type, pt, false);
        if (!conv.ok) return false;
        if (is_out(f->params[i]) && !hfx_type_equal(e->args[i]->type, pt)) return false;
        costs[i] = hfx_conv_cost(conv);
    }
    return true;
}

/* a is better than b: no argument converts worse, one converts better. */
static bool dominates(const unsigned *a, const unsigned *b, uint32_t n) {
    bool better = false;
    for (uint32_t i = 0; i < n; i++) {
        if (a[i] > b[i]) return false;
        if (a[i] < b[i]) better = true;
    }
    return better;
}

/* The best overload: 0 none fits, 1 found (*best), 2 ambiguous. */
static int pick_overload(hfx_decl **cands, uint32_t n, const hfx_expr *e, hfx_decl **best) {
    unsigned costs[MAX_OVERLOADS][MAX_ARGS];
    bool viable[MAX_OVERLOADS];
    uint32_t nargs = e->arg_count < MAX_ARGS ? e->arg_count : MAX_ARGS;
    uint32_t count = 0;
    for (uint32_t i = 0; i < n; i++) {
        viable[i] = e->arg_count <= MAX_ARGS && candidate_costs(cands[i]->func, e, costs[i]);
        count += viable[i];
    }
    if (!count) return 0;
    hfx_decl *found = NULL;
    uint32_t winners = 0;
    for (uint32_t i = 0; i < n; i++) {
        if (!viable[i]) continue;
        bool beaten = false;
        for (uint32_t j = 0; j < n && !beaten; j++)
            if (j != i && viable[j] && dominates(costs[j], costs[i], nargs)) beaten = true;
        if (!beaten) found = cands[i], winners++;
    }
    *best = found;
    return winners == 1 ? 1 : 2;
}

static void convert_args(check_ctx *c, hfx_expr *e, const hfx_type *const *params, const bool *outs, bool warn) {
    for (uint32_t i = 0; i < e->arg_count; i++) {
        if (outs[i]) hfx_ck_lvalue(c, e->args[i]);
        else e->args[i] = hfx_ck_convert_arg(c, e->args[i], params[i], warn, e);
    }
}

/* f(x) of `float f(float x, float y = 3)`: the call gets the default values as arguments, so
 * later phases see every parameter bound (the defaults are shared, checked once). */
static void append_defaults(check_ctx *c, hfx_expr *e, const hfx_func *f) {
    if (e->arg_count >= f->param_count) return;
    hfx_expr **args = HFX_NEW_ARRAY(c->arena, hfx_expr *, f->param_count);
    if (!args) return;
    for (uint32_t i = 0; i < f->param_count; i++) {
        if (i < e->arg_count) { args[i] = e->args[i]; continue; }
        hfx_expr *init = f->params[i]->init;
        args[i] = hfx_ck_is_err(c, hfx_ck_expr(c, init)) ? init : hfx_ck_convert_arg(c, init, f->params[i]->type, true, e);
    }
    e->args = args;
    e->arg_count = f->param_count;
}

static const hfx_type *call_user(check_ctx *c, hfx_expr *e, hfx_decl *fd) {
    hfx_func *f = fd->func;
    const hfx_type *params[MAX_ARGS];
    bool outs[MAX_ARGS];
    for (uint32_t i = 0; i < e->arg_count && i < MAX_ARGS; i++) {
        params[i] = f->params[i]->type;
        outs[i] = is_out(f->params[i]);
    }
    e->fn = f;
    hfx_ck_record_call(c, f, e->loc, false);
    convert_args(c, e, params, outs, true);
    append_defaults(c, e, f);
    return set_type(e, f->ret);
}

static const hfx_type *call_intrinsic(check_ctx *c, hfx_expr *e, int id) {
    const hfx_type *args[4] = {0};
    hfx_intrinsic_match m;
    for (uint32_t i = 0; i < e->arg_count && i < 4; i++) args[i] = e->args[i]->type;
    if (e->arg_count > 4 || !hfx_intrinsic_match_args(c->types, id, args, e->arg_count, &m)) {
        hfx_error(c->diags, e->loc, X_NO_OVERLOAD, "'%s': no matching %u parameter intrinsic function",
                  e->name, e->arg_count);
        return set_type(e, c->err);
    }
    e->intrinsic = id;
    convert_args(c, e, m.params, m.out, hfx_intrinsic_info_of(id)->sig != SIG_MUL);
    return set_type(e, m.ret);
}

/* A user function named like an intrinsic competes with it: the intrinsic wins only when it
 * matches strictly better (saturate(float) against a user saturate(float3)). */
static bool intrinsic_beats(check_ctx *c, int id, const hfx_func *f, const hfx_expr *e) {
    const hfx_type *args[4] = {0};
    unsigned user[4], intr[4];
    hfx_intrinsic_match m;
    if (e->arg_count > 4) return false;
    for (uint32_t i = 0; i < e->arg_count; i++) args[i] = e->args[i]->type;
    if (!hfx_intrinsic_match_args(c->types, id, args, e->arg_count, &m) || !candidate_costs(f, e, user)) return false;
    for (uint32_t i = 0; i < e->arg_count; i++) intr[i] = hfx_conv_cost(hfx_conv_classify(args[i], m.params[i], false));
    return dominates(intr, user, e->arg_count);
}

/* technique10/11 pass syntax: `SetVertexShader(CompileShader(vs_4_0, VS(1)))`. CompileShader
 * becomes an EX_COMPILE like `compile vs_4_0 VS(1)`; Set*Shader and Set*State calls keep
 * their (state-checked) arguments for the builder and take the type of the first one. */
static const hfx_type *state_call(check_ctx *c, hfx_expr *e) {
    if (strcmp(e->name, "CompileShader") == 0 && e->arg_count == 2 && e->args[0]->kind == EX_IDENT &&
        e->args[1]->kind == EX_CALL) {
        hfx_expr *entry = e->args[1];
        e->kind = EX_COMPILE;
        e->loc = entry->loc; /* errors about the entry point at its name */
        e->profile = e->args[0]->name;
        e->name = entry->name;
        e->args = entry->args;
        e->arg_count = entry->arg_count;
        return hfx_ck_compile(c, e);
    }
    size_t n = strlen(e->name);
    if (strncmp(e->name, "Set", 3) == 0 && n > 8 && strcmp(e->name + n - 5, "State") == 0)
        return set_type(e, hfx_type_void(c->types)); /* SetBlendState(bs, ...): the state objects are dropped */
    check_args(c, e);
    return set_type(e, e->arg_count ? e->args[0]->type : hfx_type_void(c->types));
}

const hfx_type *hfx_ck_call(check_ctx *c, hfx_expr *e) {
    if (!e->name) return set_type(e, c->err);
    if (c->in_state && !hfx_ck_lookup_funcs(c, e->name, (hfx_decl *[1]){0}, 1) && hfx_intrinsic_find(e->name) < 0)
        return state_call(c, e);
    bool args_ok = check_args(c, e);
    hfx_decl *cands[MAX_OVERLOADS];
    uint32_t n = hfx_ck_lookup_funcs(c, e->name, cands, MAX_OVERLOADS);
    int id = hfx_intrinsic_find(e->name);
    if (!n && id < 0) {
        hfx_error(c->diags, e->loc, X_UNDECLARED, "undeclared identifier '%s'", e->name);
        return set_type(e, c->err);
    }
    if (!args_ok) return set_type(e, c->err);
    if (n) {
        hfx_decl *best = NULL;
        int r = pick_overload(cands, n, e, &best);
        if (r == 1 && !(id >= 0 && intrinsic_beats(c, id, best->func, e))) return call_user(c, e, best);
        if (r == 1) return call_intrinsic(c, e, id);
        if (r == 2) {
            hfx_error(c->diags, e->loc, X_AMBIGUOUS, "'%s': ambiguous function call", e->name);
            return set_type(e, c->err);
        }
        if (id < 0) {
            hfx_error(c->diags, e->loc, X_NO_OVERLOAD, "'%s': no matching %u parameter function", e->name,
                      e->arg_count);
            return set_type(e, c->err);
        }
    }
    return call_intrinsic(c, e, id);
}

/* ---- constructors ---- */

const hfx_type *hfx_ck_construct(check_ctx *c, hfx_expr *e) {
    const hfx_type *t = hfx_ck_resolve_type(c, e->cast_type, e->loc);
    e->cast_type = t;
    if (!check_args(c, e)) return set_type(e, c->err);
    if (!hfx_type_is_numeric(t)) {
        hfx_error(c->diags, e->loc, 3037, "constructors only defined for numeric base types");
        return set_type(e, c->err);
    }
    unsigned total = 0;
    for (uint32_t i = 0; i < e->arg_count; i++) {
        const hfx_type *at = e->args[i]->type;
        if (!hfx_type_is_numeric(at)) {
            hfx_error(c->diags, hfx_ck_start(e->args[i]), X_TYPE_MISMATCH, "cannot implicitly convert from '%s' to '%s'",
                      hfx_ck_type_name(c, at), hfx_ck_type_name(c, t));
            return set_type(e, c->err);
        }
        total += hfx_type_components(at);
    }
    if (total != hfx_type_components(t)) {
        hfx_error(c->diags, e->loc, X_CTOR_ARGS, "incorrect number of arguments to numeric-type constructor");
        return set_type(e, c->err);
    }
    for (uint32_t i = 0; i < e->arg_count; i++)
        e->args[i] = hfx_ck_implicit_cast(c, e->args[i], hfx_type_with_base(c->types, e->args[i]->type, t->base));
    return set_type(e, t);
}

/* ---- compile expressions: the entry point and its uniform parameters ---- */

static uint32_t uniform_count(const hfx_func *f) {
    uint32_t n = 0;
    for (uint32_t i = 0; i < f->param_count; i++) n += (f->params[i]->mods & MOD_UNIFORM) != 0;
    return n;
}

/* Whether e's arguments bind f's uniform parameters in order (converting). */
static bool binds_uniforms(const hfx_func *f, const hfx_expr *e) {
    if (uniform_count(f) != e->arg_count) return false;
    uint32_t k = 0;
    for (uint32_t i = 0; i < f->param_count; i++) {
        if (!(f->params[i]->mods & MOD_UNIFORM)) continue;
        if (!hfx_conv_classify(e->args[k++]->type, f->params[i]->type, false).ok) return false;
    }
    return true;
}

static bool known_profile(const char *p) {
    static const char *const ok[] = {"vs_1_1", "vs_2_0", "vs_2_a", "vs_2_sw", "vs_3_0", "vs_3_sw", "ps_1_1",
                                     "ps_1_2", "ps_1_3", "ps_1_4", "ps_2_0", "ps_2_a", "ps_2_b", "ps_2_sw",
                                     "ps_3_0", "ps_3_sw", "vs_4_0", "vs_4_1", "vs_5_0", "ps_4_0", "ps_4_1",
                                     "ps_5_0", "vs_4_0_level_9_1", "vs_4_0_level_9_3", "ps_4_0_level_9_1",
                                     "ps_4_0_level_9_3", "gs_4_0", "gs_4_1", "gs_5_0"};
    for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++)
        if (strcasecmp(ok[i], p) == 0) return true;
    return false;
}

const hfx_type *hfx_ck_compile(check_ctx *c, hfx_expr *e) {
    bool saved = c->in_state;
    c->in_state = false; /* the arguments are expressions, not state values */
    bool args_ok = check_args(c, e);
    c->in_state = saved;
    const char *profile = e->profile ? e->profile : "";
    bool pixel = profile[0] == 'p' || profile[0] == 'P';
    const hfx_type *t = hfx_type_object(c->types, pixel ? TY_PIXELSHADER : TY_VERTEXSHADER, DIM_GENERIC);
    if (!known_profile(e->profile ? e->profile : "")) {
        hfx_error(c->diags, e->loc, X_SYNTAX, "invalid profile '%s'", profile);
        return set_type(e, c->err);
    }
    hfx_decl *cands[MAX_OVERLOADS];
    uint32_t n = hfx_ck_lookup_funcs(c, e->name ? e->name : "", cands, MAX_OVERLOADS);
    if (!n) {
        hfx_error(c->diags, e->loc, X_UNDECLARED, "undeclared identifier '%s'", e->name ? e->name : "");
        return set_type(e, c->err);
    }
    if (!args_ok) return set_type(e, c->err);
    hfx_decl *best = NULL;
    for (uint32_t i = 0; i < n && !best; i++)
        if (binds_uniforms(cands[i]->func, e)) best = cands[i];
    if (!best) {
        hfx_error(c->diags, e->loc, X_NO_OVERLOAD, "'%s': no matching %u parameter function", e->name, e->arg_count);
        return set_type(e, c->err);
    }
    hfx_func *f = best->func;
    e->fn = f->definition ? f->definition : f;
    hfx_ck_record_call(c, f, e->loc, true);
    uint32_t k = 0;
    for (uint32_t i = 0; i < f->param_count; i++)
        if (f->params[i]->mods & MOD_UNIFORM) {
            e->args[k] = hfx_ck_convert_arg(c, e->args[k], f->params[i]->type, true, e);
            k++;
        }
    return set_type(e, t);
}

/* ---- initializers ---- */

typedef struct leaf_list {
    const hfx_type **types;   /* the scalar (or object) type of each component of the target */
    uint32_t count, cap;
} leaf_list;

static void add_leaf(check_ctx *c, leaf_list *l, const hfx_type *t) {
    if (!HFX_ARENA_GROW(c->arena, l->types, l->count, l->cap, 16)) { c->oom = true; return; }
    l->types[l->count++] = t;
}

/* The component types of `t` in memory order (row-major for matrices). */
static void target_leaves(check_ctx *c, leaf_list *l, const hfx_type *t) {
    switch (t->kind) {
    case TY_SCALAR: case TY_VECTOR: case TY_MATRIX:
        for (unsigned i = 0; i < (unsigned)t->rows * t->cols; i++) add_leaf(c, l, hfx_type_scalar(c->types, t->base));
        break;
    case TY_ARRAY:
        for (uint32_t i = 0; i < t->array_len; i++) target_leaves(c, l, t->elem);
        break;
    case TY_STRUCT:
        for (uint32_t i = 0; i < t->st->field_count; i++) target_leaves(c, l, t->st->fields[i].type);
        break;
    default:
        add_leaf(c, l, t);
        break;
    }
}

typedef struct expr_list {
    hfx_expr **items;
    uint32_t count, cap;
} expr_list;

static void add_expr(check_ctx *c, expr_list *l, hfx_expr *e) {
    if (!HFX_ARENA_GROW(c->arena, l->items, l->count, l->cap, 16)) { c->oom = true; return; }
    l->items[l->count++] = e;
}

/* One component of a checked expression: its scalar element as a swizzle (vectors, matrices)
 * or field/index chain (structs, arrays). The source node is shared, so it must be pure. */
static hfx_expr *component_node(check_ctx *c, hfx_expr *src, hfx_expr_kind kind, uint32_t k, const hfx_type *t) {
    hfx_expr *e = HFX_NEW(c->arena, hfx_expr);
    hfx_expr **args = HFX_NEW_ARRAY(c->arena, hfx_expr *, 2);
    if (!e || !args) { c->oom = true; return src; }
    e->kind = kind;
    e->loc = src->loc;
    e->type = t;
    e->intrinsic = -1;
    e->args = args;
    e->args[0] = src;
    e->arg_count = 1;
    if (kind == EX_SWIZZLE) {
        e->comps[0] = (uint8_t)k;
        e->comp_count = 1;
    } else if (kind == EX_FIELD) {
        e->field = k;
    } else { /* EX_INDEX */
        hfx_expr *idx = HFX_NEW(c->arena, hfx_expr);
        if (!idx) { c->oom = true; return src; }
        idx->kind = EX_INT;
        idx->ival = k;
        idx->loc = src->loc;
        idx->intrinsic = -1;
        idx->type = hfx_type_scalar(c->types, B_INT);
        e->args[1] = idx;
        e->arg_count = 2;
    }
    return e;
}

/* Splits a checked value into its components (numeric leaves scalar; objects whole). */
static void split_value(check_ctx *c, expr_list *out, hfx_expr *v) {
    const hfx_type *t = v->type;
    switch (t->kind) {
    case TY_SCALAR:
        add_expr(c, out, v);
        break;
    case TY_VECTOR: case TY_MATRIX:
        for (unsigned i = 0; i < (unsigned)t->rows * t->cols; i++)
            add_expr(c, out, component_node(c, v, EX_SWIZZLE, i, hfx_type_scalar(c->types, t->base)));
        break;
    case TY_ARRAY:
        for (uint32_t i = 0; i < t->array_len; i++) split_value(c, out, component_node(c, v, EX_INDEX, i, t->elem));
        break;
    case TY_STRUCT:
        for (uint32_t i = 0; i < t->st->field_count; i++)
            split_value(c, out, component_node(c, v, EX_FIELD, i, t->st->fields[i].type));
        break;
    default:
        add_expr(c, out, v);
        break;
    }
}

/* Checks every item of a (nested) brace list and collects their components. */
static bool flatten_list(check_ctx *c, expr_list *out, hfx_expr *list) {
    bool ok = true;
    for (uint32_t i = 0; i < list->arg_count; i++) {
        hfx_expr *item = list->args[i];
        if (item->kind == EX_INIT_LIST) {
            ok &= flatten_list(c, out, item);
            continue;
        }
        if (hfx_ck_is_err(c, hfx_ck_expr(c, item))) { ok = false; continue; }
        split_value(c, out, item);
    }
    return ok;
}

static const char *count_name(check_ctx *c, uint32_t n) {
    return n == 1 ? "float" : hfx_arena_printf(c->arena, n <= 4 ? "float%u" : "float[%u]", n);
}

static void init_list(check_ctx *c, hfx_decl *d) {
    hfx_expr *list = d->init;
    expr_list items = {0};
    if (!flatten_list(c, &items, list)) {
        list->type = c->err;
        return;
    }
    const hfx_type *t = d->type;
    if (t->kind == TY_ARRAY && t->array_len == 0) { /* float a[] = {...}: sized by its initializer */
        unsigned per = hfx_type_components(t->elem);
        if (per == 0) per = 1;
        t = d->type = hfx_type_array(c->types, t->elem, (uint32_t)((items.count + per - 1) / per));
    }
    leaf_list leaves = {0};
    target_leaves(c, &leaves, t);
    if (leaves.count != items.count) {
        hfx_error(c->diags, list->loc, X_TYPE_MISMATCH, "'%s': cannot implicitly convert from '%s' to '%s'", d->name,
                  count_name(c, items.count), hfx_ck_type_name(c, t));
        list->type = c->err;
        return;
    }
    for (uint32_t i = 0; i < items.count; i++) items.items[i] = hfx_ck_convert(c, items.items[i], leaves.types[i], false);
    list->args = items.items;
    list->arg_count = items.count;
    list->type = t;
}

void hfx_ck_init(check_ctx *c, hfx_decl *d) {
    hfx_expr *init = d->init;
    if (!init || hfx_ck_is_err(c, d->type)) return;
    if (init->kind == EX_INIT_LIST) {
        init_list(c, d);
        return;
    }
    if (init->kind == EX_ASM) {
        hfx_error(c->diags, init->loc, X_UNSUPPORTED, "asm shaders are not supported");
        init->type = c->err;
        return;
    }
    const hfx_type *t = hfx_ck_expr(c, init);
    if (hfx_ck_is_err(c, t)) return;
    if (init->kind == EX_SAMPLER_STATE) {
        if (d->type->kind != TY_SAMPLER)
            hfx_error(c->diags, hfx_ck_start(init), X_TYPE_MISMATCH, "cannot implicitly convert from 'sampler' to '%s'",
                      hfx_ck_type_name(c, d->type));
        return;
    }
    d->init = hfx_ck_convert(c, init, d->type, true);
}

/* ---- state values ---- */

void hfx_ck_state_value(check_ctx *c, hfx_state_assign *s) {
    bool saved = c->in_state;
    c->in_state = true;
    if (s->index) hfx_ck_expr(c, s->index);
    if (s->value) hfx_ck_expr(c, s->value);
    c->in_state = saved;
}
