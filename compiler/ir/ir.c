/* ir.c: copies the checked AST of one entry point and everything it calls into the IR.
 * The copy is per stage of each pass, so specialisation never touches the shared tree. */
#include "ir/ir.h"
#include "check/conv.h"
#include "states.h"

#include <string.h>
#include <strings.h>


typedef struct builder {
    ir_ctx *c;
    ir_shader *sh;
    ir_var_map globals, locals, funcs; /* by declaration / function: what the IR has for it */
    ir_func *fn;                 /* the function being built */
    const char **names; uint32_t name_count, name_cap; /* GLSL names taken in fn */
    ir_var **closed_for_vars; uint32_t closed_count, closed_cap; /* for-init vars whose loop ended */
    int depth;
    bool failed;
    const ir_value_src *value;   /* building a value outside shader code (hfx_ir_build_value) */
} builder;

/* Growable arrays in the arena (hfx_grow): the old block is simply abandoned. */
static void *grow(hfx_arena *a, void *old, uint32_t *cap, uint32_t count, size_t elem) {
    void *items = old;
    return hfx_grow(&items, elem, count, cap, 8, hfx_arena_grow, a) ? items : NULL;
}

ir_expr *hfx_ir_new_expr(ir_ctx *c, ir_expr_kind k, const hfx_type *ty, hfx_loc loc, uint32_t n) {
    ir_expr *e = HFX_NEW(c->arena, ir_expr);
    e->kind = k;
    e->type = ty;
    e->loc = loc;
    e->n = n;
    if (n) e->a = HFX_NEW_ARRAY(c->arena, ir_expr *, n);
    return e;
}

ir_expr *hfx_ir_new_binary(ir_ctx *c, hfx_op op, const hfx_type *ty, ir_expr *a, ir_expr *b) {
    ir_expr *e = hfx_ir_new_expr(c, IE_BINARY, ty, a->loc, 2);
    e->op = op;
    e->a[0] = a;
    e->a[1] = b;
    return e;
}

ir_expr *hfx_ir_new_convert(ir_ctx *c, const hfx_type *ty, ir_expr *x) {
    ir_expr *e = hfx_ir_new_expr(c, IE_CONVERT, ty, x->loc, 1);
    e->a[0] = x;
    return e;
}

ir_stmt *hfx_ir_new_stmt(ir_ctx *c, ir_stmt_kind k, hfx_loc loc) {
    ir_stmt *s = HFX_NEW(c->arena, ir_stmt);
    if (!s) return NULL;
    s->kind = k;
    s->loc = loc;
    return s;
}

ir_expr *hfx_ir_const_scalar(ir_ctx *c, const hfx_type *ty, double v, hfx_loc loc) {
    ir_expr *e = hfx_ir_new_expr(c, IE_CONST, ty, loc, 0);
    unsigned n = hfx_type_components(ty);
    for (unsigned i = 0; i < n && i < 16; i++) e->cval[i] = v;
    return e;
}

bool hfx_ir_is_const(const ir_expr *e) { return e && e->kind == IE_CONST; }
bool hfx_ir_const_truth(const ir_expr *e) { return e->cval[0] != 0; }

static void fail(builder *b, hfx_loc loc, const char *what) {
    if (!b->value) hfx_error(b->c->diags, loc, X_UNSUPPORTED, "%s", what); /* a value that is not one: the caller says */
    b->failed = true;
}

/* key's IR in one of the builder's maps; out of memory fails the build. */
static void remember(builder *b, ir_var_map *m, const void *key, void *val) {
    if (!hfx_ir_var_map_put(b->c, m, key, val)) b->failed = true;
}

/* A GLSL name for a local, unique in its function so that HLSL's looser scoping (for-loop
 * variables outliving the loop) can be printed by hoisting without clashes. */
static const char *local_name(builder *b, const char *name) {
    const char *base = hfx_glsl_name(b->c->arena, name);
    const char *n = base;
    for (int k = 1;; k++) {
        bool taken = false;
        for (uint32_t i = 0; i < b->name_count && !taken; i++) taken = strcmp(b->names[i], n) == 0;
        if (!taken) break;
        n = hfx_arena_printf(b->c->arena, "%s_%d", base, k);
    }
    b->names = grow(b->c->arena, b->names, &b->name_cap, b->name_count, sizeof *b->names);
    b->names[b->name_count++] = n;
    return n;
}

static ir_var *new_var(builder *b, ir_var_kind k, const hfx_decl *d, const hfx_type *ty) {
    ir_var *v = HFX_NEW(b->c->arena, ir_var);
    v->kind = k;
    v->decl = d;
    v->name = d ? d->name : "tmp";
    v->type = ty;
    v->mods = d ? d->mods : 0;
    v->param = HFX_NONE;
    return v;
}

static ir_expr *build_expr(builder *b, const hfx_expr *e);

static void add_global(builder *b, ir_var *v) {
    ir_shader *sh = b->sh;
    sh->globals = grow(b->c->arena, sh->globals, &sh->global_cap, sh->global_count, sizeof *sh->globals);
    sh->globals[sh->global_count++] = v;
}

static ir_var *global_var(builder *b, const hfx_decl *d, hfx_loc use) {
    ir_var *v = hfx_ir_var_map_get(&b->globals, d);
    if (v) return v;
    const hfx_fx_effect *fx = b->c->fx;
    bool is_static = (d->mods & MOD_STATIC) != 0;
    /* without an effect (IR tests), non-static globals are uniforms that name no parameter */
    bool has_param = !is_static && (!fx || d->index < fx->top_param_count);
    uint32_t param = fx ? d->index : HFX_NONE;
    if (d->type->kind == TY_SAMPLER && has_param) {
        v = new_var(b, IRV_SAMPLER, d, d->type);
        v->param = param;
        v->dim = d->type->dim;
        v->glsl = fx && fx->params[param].glsl_name ? fx->params[param].glsl_name : hfx_glsl_name(b->c->arena, d->name);
    } else if (d->type->kind == TY_SAMPLER || d->type->kind == TY_TEXTURE || d->type->kind == TY_STRING ||
               d->type->kind == TY_VERTEXSHADER || d->type->kind == TY_PIXELSHADER) {
        fail(b, use, hfx_arena_printf(b->c->arena, "'%s': this object cannot be used in shader code", d->name));
        return NULL;
    } else if (has_param) {
        v = new_var(b, IRV_UNIFORM, d, d->type);
        v->param = param;
        v->glsl = fx && fx->params[param].glsl_name ? fx->params[param].glsl_name : hfx_glsl_name(b->c->arena, d->name);
    } else {
        /* static globals (and globals without a parameter) are private, set at main's start */
        v = new_var(b, IRV_PRIVATE, d, d->type);
        v->glsl = hfx_arena_printf(b->c->arena, "hfx_static_%s", d->name);
    }
    remember(b, &b->globals, d, v);
    add_global(b, v);
    if (v->kind == IRV_PRIVATE && d->init) {
        ir_func *saved = b->fn;
        b->fn = NULL;
        v->init = build_expr(b, d->init);
        b->fn = saved;
    }
    return v;
}

static ir_var *lookup_var(builder *b, const hfx_expr *e) {
    const hfx_decl *d = e->sym;
    if (!d) {
        fail(b, e->loc, hfx_arena_printf(b->c->arena, "'%s': unresolved name", e->name ? e->name : "?"));
        return NULL;
    }
    ir_var *v = hfx_ir_var_map_get(&b->locals, d);
    if (v) {
        for (uint32_t i = 0; i < b->closed_count; i++)
            if (b->closed_for_vars[i] == v) v->hoisted = true;
        return v;
    }
    if (d->is_global) return global_var(b, d, e->loc);
    fail(b, e->loc, hfx_arena_printf(b->c->arena, "'%s': unresolved name", d->name));
    return NULL;
}

static ir_func *build_func(builder *b, const hfx_func *f, hfx_loc use);

/* Element k of the sampler array parameter d (in range): each element of `sampler S[2] = {...}`
 * is a sampler of the effect, one GLSL sampler per element read. NULL: out of memory. */
ir_var *hfx_ir_sampler_element(ir_ctx *c, ir_shader *sh, const hfx_decl *d, uint32_t k) {
    uint32_t param = c->fx->params[d->index].first_child + k;
    for (uint32_t i = 0; i < sh->global_count; i++)
        if (sh->globals[i]->kind == IRV_SAMPLER && sh->globals[i]->param == param) return sh->globals[i];
    ir_var *v = HFX_NEW(c->arena, ir_var);
    ir_var **globals = grow(c->arena, sh->globals, &sh->global_cap, sh->global_count, sizeof *sh->globals);
    if (!v || !globals) return NULL;
    *v = (ir_var){.kind = IRV_SAMPLER, .name = d->name, .type = d->type->elem, .mods = d->mods, .param = param,
                  .decl = d, .dim = d->type->elem->dim};
    v->glsl = hfx_arena_printf(c->arena, "%s_%u", hfx_glsl_name(c->arena, d->name), (unsigned)k);
    sh->globals = globals;
    sh->globals[sh->global_count++] = v;
    return v;
}

/* `S[1]` of a sampler array parameter with a constant index: the element's own sampler. NULL
 * when e is no such read (lower/samplers.c takes the indexes that fold to constants later). */
static ir_expr *sampler_element(builder *b, const hfx_expr *e) {
    const hfx_expr *base = e->args[0], *index = e->args[1];
    const hfx_decl *d = base->kind == EX_IDENT ? base->sym : NULL;
    const hfx_fx_effect *fx = b->c->fx;
    if (!d || !d->is_global || !fx || d->index >= fx->top_param_count || d->type->kind != TY_ARRAY ||
        d->type->elem->kind != TY_SAMPLER || index->kind != EX_INT || index->ival < 0 ||
        index->ival >= (int64_t)fx->params[d->index].child_count)
        return NULL;
    ir_var *v = hfx_ir_sampler_element(b->c, b->sh, d, (uint32_t)index->ival);
    if (!v) return NULL;
    ir_expr *r = hfx_ir_new_expr(b->c, IE_VAR, v->type, e->loc, 0);
    r->var = v;
    return r;
}

static ir_expr *build_call(builder *b, const hfx_expr *e) {
    ir_expr *r;
    if (e->fn && b->value) {
        fail(b, e->loc, "a value cannot call a function");
        return NULL;
    }
    if (e->fn) {
        ir_func *f = build_func(b, e->fn, e->loc);
        if (!f) return NULL;
        r = hfx_ir_new_expr(b->c, IE_CALL, e->type, e->loc, e->arg_count);
        r->fn = f;
    } else {
        int id = e->intrinsic; /* the checker resolved it: ids are intrinsics.def's */
        if (id < 0 || id >= HFX_INTR_COUNT) {
            fail(b, e->loc, hfx_arena_printf(b->c->arena, "'%s': unknown function", e->name ? e->name : "?"));
            return NULL;
        }
        r = hfx_ir_new_expr(b->c, IE_INTRIN, e->type, e->loc, e->arg_count);
        r->intrin = (ir_intrin)id;
    }
    for (uint32_t i = 0; i < e->arg_count; i++)
        if (!(r->a[i] = build_expr(b, e->args[i]))) return NULL;
    return r;
}

/* Regroups a flat list of scalars/vectors into the shape of ty (brace initialisers). */
static ir_expr *regroup(builder *b, const hfx_type *ty, ir_expr **flat, uint32_t n, uint32_t *pos, hfx_loc loc) {
    if (ty->kind == TY_ARRAY || ty->kind == TY_STRUCT) {
        uint32_t count = ty->kind == TY_ARRAY ? ty->array_len : ty->st->field_count;
        ir_expr *r = hfx_ir_new_expr(b->c, IE_CONSTRUCT, ty, loc, count);
        for (uint32_t i = 0; i < count; i++) {
            const hfx_type *et = ty->kind == TY_ARRAY ? ty->elem : ty->st->fields[i].type;
            if (!(r->a[i] = regroup(b, et, flat, n, pos, loc))) return NULL;
        }
        return r;
    }
    unsigned want = hfx_type_components(ty), have = 0;
    uint32_t start = *pos;
    while (have < want && *pos < n) have += hfx_type_components(flat[(*pos)++]->type);
    if (have != want) {
        fail(b, loc, "initializer does not match the declared type");
        return NULL;
    }
    if (*pos - start == 1 && hfx_type_equal(flat[start]->type, ty)) return flat[start];
    ir_expr *r = hfx_ir_new_expr(b->c, IE_CONSTRUCT, ty, loc, *pos - start);
    for (uint32_t i = start; i < *pos; i++) r->a[i - start] = flat[i];
    return r;
}

/* The scalar components of x in order (fields, elements, rows), each reading x again. */
static void scalars_of(builder *b, ir_expr *x, ir_expr **out, uint32_t *n) {
    const hfx_type *ty = x->type;
    if (ty->kind == TY_STRUCT || ty->kind == TY_ARRAY) {
        uint32_t count = ty->kind == TY_ARRAY ? ty->array_len : ty->st->field_count;
        for (uint32_t i = 0; i < count; i++) {
            const hfx_type *et = ty->kind == TY_ARRAY ? ty->elem : ty->st->fields[i].type;
            ir_expr *part = hfx_ir_new_expr(b->c, ty->kind == TY_ARRAY ? IE_INDEX : IE_FIELD, et, x->loc, ty->kind == TY_ARRAY ? 2 : 1);
            part->a[0] = hfx_ir_clone_expr(b->c, x);
            if (ty->kind == TY_ARRAY) part->a[1] = hfx_ir_const_scalar(b->c, hfx_type_scalar(b->c->types, B_INT), i, x->loc);
            else part->field = i;
            scalars_of(b, part, out, n);
        }
        return;
    }
    unsigned count = hfx_type_components(ty);
    if (count == 1) { out[(*n)++] = x; return; }
    for (unsigned i = 0; i < count; i++) {
        ir_expr *one = hfx_ir_new_expr(b->c, IE_SWIZZLE, hfx_type_scalar(b->c->types, ty->base), x->loc, 1);
        one->a[0] = hfx_ir_clone_expr(b->c, x);
        one->comp_count = 1;
        one->comps[0] = (uint8_t)i; /* row-major for matrices */
        out[(*n)++] = one;
    }
}

/* A value of type ty from scalars[*pos...], each converted to ty's element type. */
static ir_expr *rebuild(builder *b, const hfx_type *ty, ir_expr **scalars, uint32_t *pos, hfx_loc loc) {
    uint32_t count = ty->kind == TY_ARRAY ? ty->array_len : ty->kind == TY_STRUCT ? ty->st->field_count : hfx_type_components(ty);
    ir_expr *r = hfx_ir_new_expr(b->c, IE_CONSTRUCT, ty, loc, count);
    for (uint32_t i = 0; i < count; i++) {
        if (ty->kind == TY_ARRAY || ty->kind == TY_STRUCT) {
            r->a[i] = rebuild(b, ty->kind == TY_ARRAY ? ty->elem : ty->st->fields[i].type, scalars, pos, loc);
            continue;
        }
        ir_expr *s = scalars[(*pos)++];
        const hfx_type *want = hfx_type_scalar(b->c->types, ty->base);
        if (s->type != want) {
            ir_expr *conv = hfx_ir_new_expr(b->c, IE_CONVERT, want, loc, 1);
            conv->a[0] = s;
            s = conv;
        }
        r->a[i] = s;
    }
    if (count == 1 && hfx_type_is_numeric(ty)) return r->a[0];
    return r;
}

/* Whether a cast from -> to takes the components one by one: to or from a struct, and to or
 * from an array where no plain conversion applies ((float4)arr, (float[2])v4). A scalar fills. */
static bool restructures(const hfx_type *from, const hfx_type *to) {
    /* A one-component struct or array to another one-component type (`T t = s;` with
     * struct S { float a; } and struct T { float b; }) takes its one component too; a scalar
     * source fills instead, elsewhere. */
    if (hfx_type_components(from) <= 1)
        return (from->kind == TY_STRUCT || from->kind == TY_ARRAY) && hfx_type_components(to) == 1 &&
               !hfx_type_equal(from, to);
    if (from->kind == TY_STRUCT || to->kind == TY_STRUCT) return true;
    if (from->kind != TY_ARRAY && to->kind != TY_ARRAY) return false;
    return !hfx_conv_classify(from, to, true).ok;
}

/* (S2)s1, (float4)s, (S)v: the source's components in order, rebuilt as the target type. */
static ir_expr *build_restructure(builder *b, const hfx_expr *e) {
    ir_expr *x = build_expr(b, e->args[0]);
    if (!x) return NULL;
    if (hfx_ir_has_side_effects(x)) {
        fail(b, e->loc, "a cast to or from a struct of an expression with side effects is not supported");
        return NULL;
    }
    uint32_t n = 0, pos = 0;
    ir_expr **scalars = HFX_NEW_ARRAY(b->c->arena, ir_expr *, hfx_type_components(x->type));
    scalars_of(b, x, scalars, &n);
    return rebuild(b, e->type, scalars, &pos, e->loc);
}

static ir_expr *build_init_list(builder *b, const hfx_expr *e) {
    ir_expr **flat = HFX_NEW_ARRAY(b->c->arena, ir_expr *, e->arg_count ? e->arg_count : 1);
    for (uint32_t i = 0; i < e->arg_count; i++)
        if (!(flat[i] = build_expr(b, e->args[i]))) return NULL;
    uint32_t pos = 0;
    return regroup(b, e->type, flat, e->arg_count, &pos, e->loc);
}

static ir_expr *build_children(builder *b, const hfx_expr *e, ir_expr_kind k, const hfx_type *ty) {
    ir_expr *r = hfx_ir_new_expr(b->c, k, ty, e->loc, e->arg_count);
    r->op = e->op;
    for (uint32_t i = 0; i < e->arg_count; i++)
        if (!(r->a[i] = build_expr(b, e->args[i]))) return NULL;
    return r;
}

static ir_expr *value_expr(builder *b, const hfx_expr *e);

/* One node of shader code (or of a value: value_expr calls it for what is not a leaf). */
static ir_expr *build_node(builder *b, const hfx_expr *e) {
    ir_expr *r;
    switch (e->kind) {
    case EX_INT: case EX_BOOL:
        return hfx_ir_const_scalar(b->c, e->type, (double)e->ival, e->loc);
    case EX_FLOAT:
        return hfx_ir_const_scalar(b->c, e->type, e->fval, e->loc);
    case EX_IDENT: {
        ir_var *v = lookup_var(b, e);
        if (!v) return NULL;
        r = hfx_ir_new_expr(b->c, IE_VAR, v->type, e->loc, 0);
        r->var = v;
        return r;
    }
    case EX_UNARY:
        if (e->op == OP_POS) return build_expr(b, e->args[0]);
        return build_children(b, e, IE_UNARY, e->type);
    case EX_BINARY: return build_children(b, e, IE_BINARY, e->type);
    case EX_ASSIGN: return build_children(b, e, IE_ASSIGN, e->type);
    case EX_TERNARY: return build_children(b, e, IE_SELECT, e->type);
    case EX_COMMA: return build_children(b, e, IE_COMMA, e->type);
    case EX_CALL: return build_call(b, e);
    case EX_CONSTRUCT:
        r = build_children(b, e, IE_CONSTRUCT, e->type);
        if (r && r->n == 1 && hfx_type_equal(r->a[0]->type, r->type)) return r->a[0];
        return r;
    case EX_CAST:
        if (restructures(e->args[0]->type, e->type)) return build_restructure(b, e);
        r = build_children(b, e, IE_CONVERT, e->type);
        if (r && r->n == 1 && hfx_type_equal(r->a[0]->type, r->type)) return r->a[0];
        return r;
    case EX_INDEX:
        if ((r = sampler_element(b, e))) return r;
        return build_children(b, e, IE_INDEX, e->type);
    case EX_SWIZZLE:
        r = build_children(b, e, IE_SWIZZLE, e->type);
        if (r) {
            memcpy(r->comps, e->comps, sizeof r->comps);
            r->comp_count = e->comp_count;
        }
        return r;
    case EX_FIELD:
        r = build_children(b, e, IE_FIELD, e->type);
        if (r) r->field = e->field;
        return r;
    case EX_INIT_LIST: return build_init_list(b, e);
    case EX_ASM:
        fail(b, e->loc, "asm blocks are not supported");
        return NULL;
    default:
        fail(b, e->loc, "this expression cannot be used in shader code");
        return NULL;
    }
}

static ir_expr *build_expr(builder *b, const hfx_expr *e) {
    if (!e) return NULL;
    return b->value ? value_expr(b, e) : build_node(b, e);
}

/* ---- values outside shader code (hfx_ir_build_value) ---- */

/* A state's named value (`SrcAlpha`) as the int the state takes. */
static ir_expr *state_name(builder *b, const hfx_expr *e) {
    int32_t v;
    if (!b->value->names || !e->name || hfx_state_value_lookup(b->value->names, e->name, &v) != 0) return NULL;
    return hfx_ir_const_scalar(b->c, hfx_type_scalar(b->c->types, B_INT), v, e->loc);
}

/* The parameter e reads (a whole one, or an array's element at a constant index) as a uniform. */
static ir_expr *value_param(builder *b, const hfx_expr *e) {
    uint32_t p = b->value->param_of ? b->value->param_of(b->value->data, e) : HFX_NONE;
    if (p == HFX_NONE || !e->type) return NULL;
    ir_var *v = new_var(b, IRV_UNIFORM, e->kind == EX_INDEX ? NULL : e->sym, e->type);
    v->name = b->c->fx && p < b->c->fx->param_count ? b->c->fx->params[p].name : "param";
    v->param = p;
    ir_expr *r = hfx_ir_new_expr(b->c, IE_VAR, e->type, e->loc, 0);
    r->var = v;
    return r;
}

/* A name in a value: a state's named value, a parameter, or a constant's initialiser (fxc
 * folds `static const` globals into the value); nothing else has a value outside a shader. */
static ir_expr *value_name(builder *b, const hfx_expr *e) {
    ir_expr *r = state_name(b, e);
    if (!r) r = value_param(b, e);
    const hfx_decl *d = e->sym;
    if (!r && d && d->kind == DECL_VAR && d->init && (d->mods & MOD_CONST) && b->depth++ < 64) {
        r = build_expr(b, d->init);
        b->depth--;
    }
    if (!r) fail(b, e->loc, "not a value");
    return r;
}

static ir_expr *value_expr(builder *b, const hfx_expr *e) {
    ir_expr *r;
    if (!e->type) { /* never checked (a hostile or broken tree): no value, rather than a crash */
        fail(b, e->loc, "not a value");
        return NULL;
    }
    if (e->kind == EX_IDENT || e->kind == EX_STATE_REF) r = value_name(b, e);
    else if (e->kind == EX_INDEX && (r = value_param(b, e))) return r;
    else r = build_node(b, e);
    /* the checker leaves state constants' operations untyped (`Red | Green`): ints, as D3D's */
    if (r && (!r->type || r->type->kind == TY_VOID)) r->type = hfx_type_scalar(b->c->types, B_INT);
    return r;
}

ir_expr *hfx_ir_build_value(ir_ctx *c, const hfx_expr *e, const ir_value_src *src) {
    builder b = {0};
    b.c = c;
    b.sh = HFX_NEW(c->arena, ir_shader);
    b.value = src;
    ir_expr *r = build_expr(&b, e);
    return b.failed ? NULL : r;
}

static ir_stmt *new_stmt(builder *b, ir_stmt_kind k, hfx_loc loc) { return hfx_ir_new_stmt(b->c, k, loc); }

typedef struct stmt_list { ir_stmt **items; uint32_t count, cap; } stmt_list;

static void list_add(builder *b, stmt_list *l, ir_stmt *s) {
    if (!s) return;
    l->items = grow(b->c->arena, l->items, &l->cap, l->count, sizeof *l->items);
    l->items[l->count++] = s;
}

static void build_stmt_into(builder *b, const hfx_stmt *s, stmt_list *out);

static ir_stmt *build_block_of(builder *b, hfx_stmt **body, uint32_t count, hfx_loc loc, ir_stmt_kind k) {
    stmt_list l = {0};
    for (uint32_t i = 0; i < count; i++) build_stmt_into(b, body[i], &l);
    ir_stmt *r = new_stmt(b, k, loc);
    r->body = l.items;
    r->count = l.count;
    return r;
}

/* A statement that must be a single one (loop bodies, if branches, for-init). */
static ir_stmt *build_single(builder *b, const hfx_stmt *s) {
    if (!s) return NULL;
    stmt_list l = {0};
    build_stmt_into(b, s, &l);
    if (l.count == 1 && (s->kind != ST_DECL)) return l.items[0];
    ir_stmt *r = new_stmt(b, IS_BLOCK, s->loc);
    r->body = l.items;
    r->count = l.count;
    return r;
}

static void build_decls(builder *b, const hfx_stmt *s, stmt_list *out) {
    for (uint32_t i = 0; i < s->decl_count; i++) {
        const hfx_decl *d = s->decls[i];
        if (d->kind != DECL_VAR) continue; /* local struct / typedef declarations: types only */
        if (d->type && d->type->kind == TY_STRING) continue; /* `string s = "x";`: nothing a shader computes with */
        ir_var *v = new_var(b, IRV_LOCAL, d, d->type);
        v->glsl = local_name(b, d->name);
        ir_stmt *st = new_stmt(b, IS_DECL, d->loc);
        st->var = v;
        if (d->init && !(st->expr = build_expr(b, d->init))) return;
        remember(b, &b->locals, d, v);
        list_add(b, out, st);
    }
}

static const char *hint_of(const hfx_stmt *s) {
    return s->attr_count ? s->attrs[0].name : NULL;
}

/* n of [unroll(n)]: fxc unrolls n iterations and stops there, even when the loop would run more. */
static uint32_t unroll_limit(const hfx_stmt *s) {
    for (uint32_t i = 0; i < s->attr_count; i++) {
        const hfx_attribute *a = &s->attrs[i];
        if (strcasecmp(a->name, "unroll") == 0 && a->arg_count == 1 && a->args[0]->kind == EX_INT && a->args[0]->ival > 0)
            return a->args[0]->ival > UINT32_MAX ? UINT32_MAX : (uint32_t)a->args[0]->ival;
    }
    return 0;
}

static ir_stmt *build_for(builder *b, const hfx_stmt *s) {
    ir_stmt *r = new_stmt(b, IS_FOR, s->loc);
    r->hint = hint_of(s);
    r->max_iterations = unroll_limit(s);
    if (s->init) {
        stmt_list l = {0};
        build_stmt_into(b, s->init, &l);
        if (l.count == 1) r->init = l.items[0];
        else if (l.count > 1) { /* several declarators: hoist them into a block around the loop */
            ir_stmt *blk = new_stmt(b, IS_BLOCK, s->loc);
            for (uint32_t i = 0; i < l.count; i++) if (l.items[i]->var) l.items[i]->var->hoisted = true;
            blk->body = l.items;
            blk->count = l.count;
            r->init = blk;
        }
    }
    if (s->expr) r->expr = build_expr(b, s->expr);
    if (s->step) r->step = build_expr(b, s->step);
    r->then_s = build_single(b, s->then_stmt);
    if (r->init && r->init->kind == IS_DECL) { /* later uses of the variable need it hoisted */
        b->closed_for_vars = grow(b->c->arena, b->closed_for_vars, &b->closed_cap, b->closed_count,
                                  sizeof *b->closed_for_vars);
        b->closed_for_vars[b->closed_count++] = r->init->var;
    }
    return r;
}

static void build_stmt_into(builder *b, const hfx_stmt *s, stmt_list *out) {
    if (!s || b->failed) return;
    ir_stmt *r = NULL;
    switch (s->kind) {
    case ST_BLOCK: r = build_block_of(b, s->body, s->body_count, s->loc, IS_BLOCK); break;
    case ST_DECL: build_decls(b, s, out); return;
    case ST_EXPR:
        if (!s->expr) return;
        r = new_stmt(b, IS_EXPR, s->loc);
        r->expr = build_expr(b, s->expr);
        break;
    case ST_IF:
        r = new_stmt(b, IS_IF, s->loc);
        r->hint = hint_of(s);
        r->expr = build_expr(b, s->expr);
        r->then_s = build_single(b, s->then_stmt);
        r->else_s = build_single(b, s->else_stmt);
        break;
    case ST_FOR: r = build_for(b, s); break;
    case ST_WHILE: case ST_DO:
        r = new_stmt(b, s->kind == ST_WHILE ? IS_WHILE : IS_DO, s->loc);
        r->hint = hint_of(s);
        r->expr = build_expr(b, s->expr);
        r->then_s = build_single(b, s->then_stmt);
        break;
    case ST_SWITCH:
        r = build_block_of(b, s->body, s->body_count, s->loc, IS_SWITCH);
        r->expr = build_expr(b, s->expr);
        break;
    case ST_CASE: r = new_stmt(b, IS_CASE, s->loc); r->expr = build_expr(b, s->expr); break;
    case ST_DEFAULT: r = new_stmt(b, IS_DEFAULT, s->loc); break;
    case ST_BREAK: r = new_stmt(b, IS_BREAK, s->loc); break;
    case ST_CONTINUE: r = new_stmt(b, IS_CONTINUE, s->loc); break;
    case ST_DISCARD: r = new_stmt(b, IS_DISCARD, s->loc); b->sh->uses_discard = true; break;
    case ST_RETURN:
        r = new_stmt(b, IS_RETURN, s->loc);
        if (s->expr) r->expr = build_expr(b, s->expr);
        break;
    case ST_EMPTY: return;
    case ST_ASM: fail(b, s->loc, "asm blocks are not supported"); return;
    }
    list_add(b, out, r);
}

static void add_func(builder *b, ir_func *f) {
    ir_shader *sh = b->sh;
    sh->funcs = grow(b->c->arena, sh->funcs, &sh->func_cap, sh->func_count, sizeof *sh->funcs);
    sh->funcs[sh->func_count++] = f;
}

/* Builds f (once per shader) and, first, every function it calls. */
static ir_func *build_func(builder *b, const hfx_func *f, hfx_loc use) {
    if (f->definition) f = f->definition;
    ir_func *r = hfx_ir_var_map_get(&b->funcs, f);
    if (r) {
        if (!r->body) fail(b, use, hfx_arena_printf(b->c->arena, "'%s': recursive calls are not allowed", f->name));
        return r->body ? r : NULL;
    }
    if (!f->body) {
        fail(b, use, hfx_arena_printf(b->c->arena, "'%s': function is declared but not defined", f->name));
        return NULL;
    }
    if (b->depth > 64) {
        fail(b, use, "functions nest too deeply");
        return NULL;
    }
    r = HFX_NEW(b->c->arena, ir_func);
    r->name = f->name;
    r->glsl = hfx_glsl_name(b->c->arena, f->name);
    r->ret = f->ret;
    r->ret_semantic = f->ret_semantic;
    r->src = f;
    remember(b, &b->funcs, f, r);

    /* a fresh local scope; the caller's is restored afterwards */
    ir_var_map saved_locals = b->locals;
    const char **saved_names = b->names;
    uint32_t saved_nc = b->name_count, saved_ncap = b->name_cap;
    ir_var **saved_closed = b->closed_for_vars;
    uint32_t saved_cc = b->closed_count, saved_ccap = b->closed_cap;
    ir_func *saved_fn = b->fn;
    b->locals = (ir_var_map){0};
    b->names = NULL;
    b->name_count = b->name_cap = 0;
    b->closed_for_vars = NULL;
    b->closed_count = b->closed_cap = 0;
    b->fn = r;
    b->depth++;
    r->param_count = f->param_count;
    r->params = HFX_NEW_ARRAY(b->c->arena, ir_var *, f->param_count ? f->param_count : 1);
    for (uint32_t i = 0; i < f->param_count; i++) {
        const hfx_decl *d = f->params[i];
        ir_var *v = new_var(b, IRV_PARAM, d, d->type);
        v->glsl = local_name(b, d->name);
        r->params[i] = v;
        remember(b, &b->locals, d, v);
    }
    ir_stmt *body = build_block_of(b, f->body->body, f->body->body_count, f->body->loc, IS_BLOCK);
    b->locals = saved_locals;
    b->names = saved_names;
    b->name_count = saved_nc;
    b->name_cap = saved_ncap;
    b->closed_for_vars = saved_closed;
    b->closed_count = saved_cc;
    b->closed_cap = saved_ccap;
    b->fn = saved_fn;
    b->depth--;
    if (b->failed) return NULL;
    r->body = body;
    add_func(b, r);
    return r;
}

/* The entry named by `compile profile name(args)`: the definition whose uniform parameters
 * take the arguments (fxc picks by the number of compile arguments). */
static const hfx_func *find_entry(ir_ctx *c, const hfx_expr *compile) {
    const hfx_func *best = NULL;
    if (!compile->name || !c->ast) return NULL;
    for (uint32_t i = 0; i < c->ast->decl_count; i++) {
        const hfx_decl *d = c->ast->decls[i];
        if (d->kind != DECL_FUNC || !d->func || !d->func->body || strcmp(d->name, compile->name) != 0) continue;
        uint32_t uniforms = 0;
        for (uint32_t k = 0; k < d->func->param_count; k++)
            if (d->func->params[k]->mods & MOD_UNIFORM) uniforms++;
        if (uniforms >= compile->arg_count && (!best || uniforms == compile->arg_count)) best = d->func;
    }
    return best;
}

/* Binds the entry's uniform parameters to the compile arguments (or their defaults): sh->args,
 * which specialise puts in. */
static bool bind_uniform_params(builder *b, const hfx_expr *compile, ir_func *entry) {
    uint32_t next = 0;
    for (uint32_t i = 0; i < entry->param_count; i++) {
        ir_var *v = entry->params[i];
        if (!(v->mods & MOD_UNIFORM)) continue;
        const hfx_expr *arg = next < compile->arg_count ? compile->args[next++] : v->decl->init;
        if (!arg) {
            hfx_error(b->c->diags, compile->loc, X_UNSUPPORTED,
                      "'%s': uniform parameter '%s' of the entry point has no value", compile->name, v->name);
            return false;
        }
        b->fn = NULL;
        ir_expr *val = build_expr(b, arg);
        if (!val) return false;
        if (!hfx_type_equal(val->type, v->type)) {
            ir_expr *cv = hfx_ir_new_expr(b->c, IE_CONVERT, v->type, arg->loc, 1);
            cv->a[0] = val;
            val = cv;
        }
        if (!hfx_ir_var_map_put(b->c, &b->sh->args, v, val)) return false;
    }
    return true;
}

/* The compile arguments were built after the entry, and the functions they call with them
 * (`strokePS(fadeout(t, m, f))`): the entry, which now reads them, goes back to the end. */
static void move_entry_last(ir_shader *sh, ir_func *entry) {
    uint32_t at = 0;
    while (at < sh->func_count && sh->funcs[at] != entry) at++;
    if (at == sh->func_count) return;
    memmove(&sh->funcs[at], &sh->funcs[at + 1], sizeof *sh->funcs * (sh->func_count - at - 1));
    sh->funcs[sh->func_count - 1] = entry;
}

ir_shader *hfx_ir_build(ir_ctx *c, const hfx_expr *compile, ir_stage stage) {
    const hfx_func *f = compile->fn ? compile->fn : find_entry(c, compile);
    if (!f) {
        hfx_error(c->diags, compile->loc, X_UNDECLARED, "'%s': entry point not found", compile->name ? compile->name : "?");
        return NULL;
    }
    builder b = {0};
    b.c = c;
    b.sh = HFX_NEW(c->arena, ir_shader);
    b.sh->stage = stage;
    b.sh->compile = compile;
    ir_func *entry = build_func(&b, f, compile->loc);
    if (!entry || b.failed) return NULL;
    entry->is_entry = true;
    if (!bind_uniform_params(&b, compile, entry)) return NULL;
    move_entry_last(b.sh, entry);
    b.sh->entry = entry;
    return b.failed ? NULL : b.sh;
}
