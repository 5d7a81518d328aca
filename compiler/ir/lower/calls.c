/* calls.c: a call with constant arguments (or a sampler array) gets a copy of its callee with
 * those parameters bound, as fxc (which inlines every call) sees it: PS(uv, ray, LightTypePoint) compiles only
 * the point-light branch, so what the other branches sample, and their errors, vanish (fold
 * and dce then remove them). A parameter the callee writes stays a parameter. Copies are
 * shared by calls with the same constants, and named <callee>_hfxK. */
#include <string.h>

#include "ir/ir.h"

enum { MAX_COPIES = 256 }; /* per shader: past it, calls keep the general function */

typedef struct copy { ir_func *from, *to; ir_expr **args; } copy;

typedef struct var_map { ir_var **from, **to; uint32_t count, cap; } var_map;

/* The parameters a function writes, as a bit mask (params 0..63), found once per function. */
typedef struct writes { const ir_func *fn; uint64_t mask; } writes;

typedef struct specialiser {
    ir_shader *sh;
    copy copies[MAX_COPIES];
    uint32_t copy_count;
    writes *writes; uint32_t write_count, write_cap;
    const ir_func **call_free; uint32_t call_free_count, call_free_cap; /* walked, no call seen */
    uint32_t calls_seen;        /* in the function being walked */
    bool changed;
} specialiser;

/* ---- whether a parameter is written ---- */

/* An `in` numeric parameter: what a constant argument may replace. */
static bool bindable_param(const ir_var *p) { return !(p->mods & MOD_OUT) && hfx_type_is_numeric(p->type); }

static bool sampler_array(const hfx_type *t) { return t->kind == TY_ARRAY && t->elem->kind == TY_SAMPLER; }

/* A sampler array passed whole: the callee's S[i] must name one of the effect's samplers (D3D9
 * has no indexed sampler registers), so the copy reads the caller's array itself, as fxc's
 * inlining does; the samplers pass then resolves each index. */
static bool sampler_array_argument(const ir_var *p, const ir_expr *a) {
    return sampler_array(p->type) && a->kind == IE_VAR && a->var->kind == IRV_UNIFORM && hfx_type_equal(a->type, p->type);
}

/* What one walk over a function finds: which of its parameters (the first 64) it writes. */
typedef struct param_writes { const ir_func *fn; uint64_t mask; } param_writes;

/* Sets the bit of the parameter that the l-value e writes into, if it is one. */
static void mark_written(param_writes *w, const ir_expr *e) {
    const ir_var *v = hfx_ir_lvalue_root(e);
    if (!v) return;
    for (uint32_t i = 0; i < w->fn->param_count && i < 64; i++)
        if (w->fn->params[i] == v) w->mask |= (uint64_t)1 << i;
}

static void note_write(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    const ir_expr *e = *slot;
    param_writes *w = data;
    bool writes = e->kind == IE_ASSIGN || (e->kind == IE_UNARY && e->op >= OP_PREINC && e->op <= OP_POSTDEC);
    if (writes) mark_written(w, e->a[0]);
    if (e->kind == IE_CALL) /* passed on as an out argument */
        for (uint32_t i = 0; i < e->n && i < e->fn->param_count; i++)
            if (e->fn->params[i]->mods & MOD_OUT) mark_written(w, e->a[i]);
    if (e->kind == IE_INTRIN && hfx_ir_has_side_effects(e)) /* sincos, modf, frexp write their later arguments */
        for (uint32_t i = 1; i < e->n; i++) mark_written(w, e->a[i]);
}

/* One walk for all the parameters, none when no parameter could be bound anyway. */
static uint64_t written_mask(ir_ctx *c, specialiser *sp, const ir_func *f) {
    for (uint32_t i = 0; i < sp->write_count; i++)
        if (sp->writes[i].fn == f) return sp->writes[i].mask;
    uint64_t bindable = 0;
    for (uint32_t i = 0; i < f->param_count && i < 64; i++)
        if (bindable_param(f->params[i])) bindable |= (uint64_t)1 << i;
    param_writes w = {f, 0};
    if (bindable) hfx_ir_walk_stmt_exprs(c, f->body, note_write, &w);
    uint64_t mask = w.mask & bindable;
    if (HFX_ARENA_GROW(c->arena, sp->writes, sp->write_count, sp->write_cap, 16))
        sp->writes[sp->write_count++] = (writes){f, mask};
    return mask;
}

/* Argument i can be bound: a constant for an `in` numeric parameter the callee never writes. */
static bool bindable(ir_ctx *c, specialiser *sp, const ir_func *f, const ir_expr *call, uint32_t i) {
    const ir_var *p = f->params[i];
    if (sampler_array_argument(p, call->a[i])) return true;
    return hfx_ir_is_const(call->a[i]) && bindable_param(p) && hfx_type_equal(call->a[i]->type, p->type) &&
           !(written_mask(c, sp, f) & ((uint64_t)1 << i));
}

/* ---- copying a function ---- */

static ir_var *mapped(const var_map *m, ir_var *v) {
    for (uint32_t i = 0; i < m->count; i++)
        if (m->from[i] == v) return m->to[i];
    return v; /* globals are shared */
}

static void map_add(ir_ctx *c, var_map *m, ir_var *from, ir_var *to) {
    uint32_t cap = m->cap;
    if (!HFX_ARENA_GROW(c->arena, m->from, m->count, m->cap, 16)) return;
    if (cap != m->cap) { /* keep the parallel array as long */
        ir_var **t = HFX_NEW_ARRAY(c->arena, ir_var *, m->cap);
        if (!t) return;
        if (m->count) memcpy(t, m->to, sizeof *t * m->count);
        m->to = t;
    }
    m->from[m->count] = from;
    m->to[m->count++] = to;
}

static ir_var *copy_var(ir_ctx *c, var_map *m, ir_var *v) {
    ir_var *n = HFX_NEW(c->arena, ir_var);
    if (!n) return v;
    *n = *v;
    map_add(c, m, v, n);
    return n;
}

/* The copy's variables for the original's, and the constant arguments its bound parameters take. */
typedef struct remap { const var_map *map; ir_var_map bound; } remap;

static void remap_var(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    const remap *r = data;
    if (e->kind == IE_VAR) {
        ir_var *v = mapped(r->map, e->var);
        const ir_expr *value = hfx_ir_var_map_get(&r->bound, v);
        if (value) *slot = hfx_ir_clone_expr(c, value);
        else e->var = v;
    }
}

static ir_stmt *copy_stmt(ir_ctx *c, var_map *m, const ir_stmt *s) {
    if (!s) return NULL;
    ir_stmt *n = HFX_NEW(c->arena, ir_stmt);
    if (!n) return NULL;
    *n = *s;
    if (s->kind == IS_DECL) n->var = copy_var(c, m, s->var);
    n->expr = hfx_ir_clone_expr(c, s->expr);
    n->step = hfx_ir_clone_expr(c, s->step);
    n->init = copy_stmt(c, m, s->init);
    n->then_s = copy_stmt(c, m, s->then_s);
    n->else_s = copy_stmt(c, m, s->else_s);
    if (s->count) {
        n->body = HFX_NEW_ARRAY(c->arena, ir_stmt *, s->count);
        for (uint32_t i = 0; i < s->count; i++) n->body[i] = copy_stmt(c, m, s->body[i]);
    }
    return n;
}

/* f with the bindable arguments of call bound; the call's other arguments stay parameters. */
static ir_func *copy_func(ir_ctx *c, specialiser *sp, ir_func *f, const ir_expr *call, const bool *bind) {
    ir_func *n = HFX_NEW(c->arena, ir_func);
    var_map m = {0};
    remap r = {&m, {0}};
    if (!n) return NULL;
    *n = *f;
    n->glsl = hfx_arena_printf(c->arena, "%s_hfx%u", f->glsl, sp->copy_count + 1);
    n->params = HFX_NEW_ARRAY(c->arena, ir_var *, f->param_count ? f->param_count : 1);
    n->param_count = 0;
    for (uint32_t i = 0; i < f->param_count; i++) {
        ir_var *p = copy_var(c, &m, f->params[i]);
        if (!bind[i]) n->params[n->param_count++] = p;
        else if (!hfx_ir_var_map_put(c, &r.bound, p, call->a[i])) return NULL;
    }
    n->body = copy_stmt(c, &m, f->body);
    hfx_ir_walk_stmt_exprs(c, n->body, remap_var, &r);
    return n;
}

/* ---- calls ---- */

static bool same_constants(const copy *k, const ir_func *f, const ir_expr *call, const bool *bind) {
    if (k->from != f) return false;
    for (uint32_t i = 0; i < f->param_count; i++) {
        if (bind[i] != (k->args[i] != NULL)) return false;
        if (!bind[i]) continue;
        if (k->args[i]->kind == IE_VAR ? k->args[i]->var != call->a[i]->var
                                       : memcmp(k->args[i]->cval, call->a[i]->cval, sizeof call->a[i]->cval) != 0)
            return false;
    }
    return true;
}

/* Puts the copy right after its original: after its callees, before every caller. */
static void insert_after(ir_ctx *c, ir_shader *sh, const ir_func *f, ir_func *n) {
    if (!HFX_ARENA_GROW(c->arena, sh->funcs, sh->func_count, sh->func_cap, 8)) return;
    uint32_t at = 0;
    while (at < sh->func_count && sh->funcs[at] != f) at++;
    at = at < sh->func_count ? at + 1 : 0;
    memmove(&sh->funcs[at + 1], &sh->funcs[at], sizeof *sh->funcs * (sh->func_count - at));
    sh->funcs[at] = n;
    sh->func_count++;
}

static ir_func *copy_for(ir_ctx *c, specialiser *sp, ir_func *f, const ir_expr *call, const bool *bind) {
    for (uint32_t i = 0; i < sp->copy_count; i++)
        if (same_constants(&sp->copies[i], f, call, bind)) return sp->copies[i].to;
    if (sp->copy_count == MAX_COPIES) return NULL;
    ir_func *n = copy_func(c, sp, f, call, bind);
    ir_expr **args = HFX_NEW_ARRAY(c->arena, ir_expr *, f->param_count ? f->param_count : 1);
    if (!n || !args) return NULL;
    for (uint32_t i = 0; i < f->param_count; i++) args[i] = bind[i] ? call->a[i] : NULL;
    sp->copies[sp->copy_count++] = (copy){f, n, args};
    insert_after(c, sp->sh, f, n);
    return n;
}

static void specialise_call(ir_ctx *c, ir_expr **slot, void *data) {
    specialiser *sp = data;
    ir_expr *e = *slot;
    if (e->kind != IE_CALL) return;
    sp->calls_seen++;
    if (e->n != e->fn->param_count || e->n > 64) return;
    bool bind[64], any = false;
    for (uint32_t i = 0; i < e->n; i++) any |= bind[i] = bindable(c, sp, e->fn, e, i);
    if (!any) return;
    ir_func *n = copy_for(c, sp, e->fn, e, bind);
    if (!n) return;
    uint32_t kept = 0;
    for (uint32_t i = 0; i < e->n; i++)
        if (!bind[i]) e->a[kept++] = e->a[i];
    e->n = kept;
    e->fn = n;
    sp->changed = true;
}

static bool known_call_free(const specialiser *sp, const ir_func *f) {
    for (uint32_t i = 0; i < sp->call_free_count; i++)
        if (sp->call_free[i] == f) return true;
    return false;
}

/* One round over every function, callees first; true when some call changed. A function seen
 * without calls is not walked again: nothing here or in fold makes a call. */
static bool round_of(ir_ctx *c, specialiser *sp) {
    ir_shader *sh = sp->sh;
    uint32_t n = sh->func_count;
    ir_func **funcs = HFX_NEW_ARRAY(c->arena, ir_func *, n ? n : 1);
    if (!funcs) return false;
    memcpy(funcs, sh->funcs, sizeof *funcs * n);
    sp->changed = false;
    for (uint32_t i = 0; i < n; i++) {
        if (known_call_free(sp, funcs[i])) continue;
        sp->calls_seen = 0;
        hfx_ir_walk_stmt_exprs(c, funcs[i]->body, specialise_call, sp);
        if (!sp->calls_seen && HFX_ARENA_GROW(c->arena, sp->call_free, sp->call_free_count, sp->call_free_cap, 8))
            sp->call_free[sp->call_free_count++] = funcs[i];
    }
    return sp->changed;
}

/* Rounds until no call changes: a bound parameter folds, which can make the copy's own calls'
 * arguments constant. */
void hfx_ir_pass_calls(ir_ctx *c, ir_shader *sh) {
    specialiser *sp = HFX_NEW(c->arena, specialiser);
    if (!sp) return;
    sp->sh = sh;
    for (int round = 0; round < 8 && round_of(c, sp); round++) hfx_ir_pass_fold(c, sh);
}
