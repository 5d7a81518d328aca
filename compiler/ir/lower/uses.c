/* uses.c: the globals a stage reads, in first-use order (a walk from the entry in statement
 * order, entering each callee at its first call). Sampler units are given in this order, and
 * a generic `sampler` takes its dimension from the tex* intrinsic that reads it, or from the
 * parameter it is passed to (`samplerCUBE shadowMap`, or a generic one the callee samples). */
#include "ir/ir.h"

typedef struct uses {
    ir_shader *sh;
    ir_var **list; uint32_t count, cap;
    ir_var_map listed;       /* the variables in list */
    ir_func **seen; uint32_t seen_count;
} uses;

static void walk_func(ir_ctx *c, uses *u, ir_func *f);
static void visit(ir_ctx *c, ir_expr **slot, void *data);

static void add(ir_ctx *c, uses *u, ir_var *v) {
    if (hfx_ir_var_map_get(&u->listed, v) || !hfx_ir_var_map_put(c, &u->listed, v, v)) return;
    if (v->copy_of) add(c, u, v->copy_of);
    if (v->init) hfx_ir_walk_expr(c, &v->init, visit, u);
    if (!HFX_ARENA_GROW(c->arena, u->list, u->count, u->cap, 16)) return;
    u->list[u->count++] = v;
}

static hfx_dim tex_dim(ir_intrin i) {
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of((int)i);
    return info && info->sig == SIG_TEX ? info->dim : DIM_GENERIC;
}

static bool generic_sampler(const ir_expr *x) {
    return x->kind == IE_VAR && (x->var->kind == IRV_SAMPLER || x->var->kind == IRV_PARAM) &&
           x->var->type->kind == TY_SAMPLER && x->var->dim == DIM_GENERIC;
}

/* The dimension a sampler parameter is declared with, or the one its body samples it as. */
static hfx_dim param_dim(const ir_var *p) {
    if (p->type->kind != TY_SAMPLER) return DIM_GENERIC;
    return p->type->dim != DIM_GENERIC ? p->type->dim : p->dim;
}

static void visit(ir_ctx *c, ir_expr **slot, void *data) {
    uses *u = data;
    ir_expr *e = *slot;
    if (e->kind == IE_VAR && e->var->kind != IRV_LOCAL && e->var->kind != IRV_PARAM) add(c, u, e->var);
    if (e->kind == IE_INTRIN && e->n && generic_sampler(e->a[0])) e->a[0]->var->dim = tex_dim(e->intrin);
    if (e->kind != IE_CALL) return;
    walk_func(c, u, e->fn);
    for (uint32_t i = 0; i < e->n && i < e->fn->param_count; i++)
        if (generic_sampler(e->a[i])) e->a[i]->var->dim = param_dim(e->fn->params[i]);
}

static void walk_func(ir_ctx *c, uses *u, ir_func *f) {
    for (uint32_t i = 0; i < u->seen_count; i++)
        if (u->seen[i] == f) return;
    u->seen[u->seen_count++] = f;
    hfx_ir_walk_stmt_exprs(c, f->body, visit, u);
}

void hfx_ir_pass_uses(ir_ctx *c, ir_shader *sh) {
    uses u = { sh, NULL, 0, 0, {0}, HFX_NEW_ARRAY(c->arena, ir_func *, sh->func_count + 1), 0 };
    walk_func(c, &u, sh->entry);
    sh->globals = u.list;
    sh->global_count = sh->global_cap = u.count;
}
