/* dce.c: removes what specialisation and folding made dead: branches of constant ifs, loops
 * that never run, statements after a return/break/continue, and functions no longer called.
 * This is what makes `mainPS(false)` stop sampling its texture. */
#include "ir/ir.h"

static ir_stmt *simplify(ir_ctx *c, ir_stmt *s, bool in_switch);

static ir_stmt *empty_block(ir_ctx *c, hfx_loc loc) {
    ir_stmt *b = HFX_NEW(c->arena, ir_stmt);
    b->kind = IS_BLOCK;
    b->loc = loc;
    return b;
}

static bool ends_flow(const ir_stmt *s) {
    return s->kind == IS_RETURN || s->kind == IS_BREAK || s->kind == IS_CONTINUE;
}

static void simplify_block(ir_ctx *c, ir_stmt *s, bool in_switch) {
    uint32_t kept = 0;
    for (uint32_t i = 0; i < s->count; i++) {
        ir_stmt *t = simplify(c, s->body[i], false);
        if (!t || (t->kind == IS_BLOCK && t->count == 0)) continue;
        s->body[kept++] = t;
        if (!in_switch && ends_flow(t)) break;
    }
    s->count = kept;
}

static ir_stmt *simplify(ir_ctx *c, ir_stmt *s, bool in_switch) {
    if (!s) return NULL;
    switch (s->kind) {
    case IS_BLOCK: simplify_block(c, s, false); return s;
    case IS_SWITCH: simplify_block(c, s, true); return s;
    case IS_IF:
        s->then_s = simplify(c, s->then_s, false);
        s->else_s = simplify(c, s->else_s, false);
        if (hfx_ir_is_const(s->expr) && !hfx_ir_has_side_effects(s->expr)) {
            ir_stmt *taken = hfx_ir_const_truth(s->expr) ? s->then_s : s->else_s;
            return taken ? taken : empty_block(c, s->loc);
        }
        if (!s->then_s) s->then_s = empty_block(c, s->loc);
        return s;
    case IS_WHILE: case IS_FOR:
        s->then_s = simplify(c, s->then_s, false);
        if (!s->then_s) s->then_s = empty_block(c, s->loc);
        if (s->expr && hfx_ir_is_const(s->expr) && !hfx_ir_const_truth(s->expr))
            return s->kind == IS_FOR && s->init ? s->init : empty_block(c, s->loc);
        return s;
    case IS_DO:
        s->then_s = simplify(c, s->then_s, false);
        if (!s->then_s) s->then_s = empty_block(c, s->loc);
        return s;
    default: return s;
    }
}

/* The functions the entry reaches: reached[i] for sh->funcs[i]; those not walked yet on the stack. */
typedef struct reach { const ir_shader *sh; bool *reached; ir_func **stack; uint32_t count; } reach;

static void mark(reach *r, ir_func *f) {
    uint32_t i = 0;
    while (i < r->sh->func_count && r->sh->funcs[i] != f) i++;
    if (i == r->sh->func_count || r->reached[i]) return;
    r->reached[i] = true;
    r->stack[r->count++] = f;
}

static void mark_call(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    if ((*slot)->kind == IE_CALL) mark(data, (*slot)->fn);
}

void hfx_ir_pass_dce(ir_ctx *c, ir_shader *sh) {
    for (uint32_t i = 0; i < sh->func_count; i++) simplify_block(c, sh->funcs[i]->body, false);
    reach r = {sh, HFX_NEW_ARRAY(c->arena, bool, sh->func_count + 1), HFX_NEW_ARRAY(c->arena, ir_func *, sh->func_count + 1), 0};
    mark(&r, sh->entry);
    if (!r.count) r.stack[r.count++] = sh->entry; /* not in the list: walked all the same */
    while (r.count) {
        ir_func *f = r.stack[--r.count];
        hfx_ir_walk_stmt_exprs(c, f->body, mark_call, &r);
    }
    for (uint32_t i = 0; i < sh->global_count; i++) /* static initialisers cannot call, but be safe */
        hfx_ir_walk_expr(c, &sh->globals[i]->init, mark_call, &r);
    uint32_t kept = 0;
    for (uint32_t i = 0; i < sh->func_count; i++)
        if (r.reached[i]) sh->funcs[kept++] = sh->funcs[i];
    sh->func_count = kept;
}
