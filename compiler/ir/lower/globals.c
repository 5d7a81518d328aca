/* globals.c: copy-on-write of uniforms. D3D9 lets a shader assign to a global (the effect's
 * parameter is only its starting value); GLSL uniforms are read-only, so a uniform some
 * function of this stage writes gets a private global, set from the uniform at main's start,
 * and every use of the uniform in this stage reads the copy. */
#include "ir/ir.h"


/* What find_writes found: whether some uniform is written (and so has a private copy). */
typedef struct writes { bool copies; } writes;

static void mark_written(ir_ctx *c, writes *w, const ir_expr *lv) {
    ir_var *v = hfx_ir_lvalue_root(lv);
    if (!v || v->kind != IRV_UNIFORM) return;
    w->copies = true;
    if (v->priv) return;
    ir_var *p = HFX_NEW(c->arena, ir_var);
    *p = *v;
    p->kind = IRV_PRIVATE;
    p->copy_of = v;
    p->priv = NULL;
    p->glsl = hfx_arena_printf(c->arena, "hfx_priv_%s", v->glsl);
    v->priv = p;
}

static void find_writes(ir_ctx *c, ir_expr **slot, void *data) {
    writes *w = data;
    ir_expr *e = *slot;
    for (uint32_t i = 0; i < e->n; i++) {
        if (!hfx_ir_writes_operand(e, i)) continue;
        const ir_expr *t = e->a[i];
        if (e->kind == IE_ASSIGN && t->kind == IE_CONSTRUCT) /* float4(a, b) = v: each argument */
            for (uint32_t k = 0; k < t->n; k++) mark_written(c, w, t->a[k]);
        else
            mark_written(c, w, t);
    }
}

static void use_copies(ir_ctx *c, ir_expr **slot, void *data) {
    ir_expr *e = *slot;
    if (e->kind == IE_VAR && e->var->kind == IRV_UNIFORM && e->var->priv) e->var = e->var->priv;
}

/* The second walk only when some uniform is written: priv is set here and nowhere else. */
void hfx_ir_pass_globals(ir_ctx *c, ir_shader *sh) {
    writes w = {false};
    for (uint32_t i = 0; i < sh->func_count; i++) hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, find_writes, &w);
    if (!w.copies) return;
    for (uint32_t i = 0; i < sh->func_count; i++) hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, use_copies, NULL);
    for (uint32_t i = 0; i < sh->global_count; i++) hfx_ir_walk_expr(c, &sh->globals[i]->init, use_copies, NULL);
}
