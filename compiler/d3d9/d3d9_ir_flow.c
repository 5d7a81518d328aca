/* d3d9_ir_flow.c: D3D9's flow control as structured IR. `if b0` / `if_cmp a, b` / `if p0.x` open an
 * IS_IF, `else` moves to its else block; `rep i0` runs i0.x times; `loop aL, i0` runs i0.x times
 * with aL = i0.y + k * i0.z; `break`, `break_cmp`, `breakp` leave the innermost loop; setp writes
 * p0 and a predicated instruction keeps the old value where its predicate is false. */
#include "d3d9/d3d9_ir.h"

static hfx_op compare_op(unsigned control) {
    static const hfx_op ops[] = {OP_NONE, OP_GT, OP_EQ, OP_GE, OP_LT, OP_NE, OP_LE, OP_NONE};
    return ops[control & 7];
}

/* a.x op b.x, for if_cmp and break_cmp (their sources carry replicate swizzles). */
static ir_expr *scalar_compare(d3d9_tx *t, const d3d9_inst *in) {
    hfx_op op = compare_op(in->control);
    ir_expr *a = hfx_d3d9_tx_read(t, &in->src[0]), *b = hfx_d3d9_tx_read(t, &in->src[1]);
    if (!a || !b) return NULL;
    if (op == OP_NONE) { hfx_d3d9_tx_fail(t, "comparison %u is not one of D3D9's", in->control); return NULL; }
    static const uint8_t x = 0;
    return hfx_ir_new_binary(t->c, op, hfx_type_scalar(t->c->types, B_BOOL), hfx_d3d9_tx_swizzle(t, a, &x, 1),
                         hfx_d3d9_tx_swizzle(t, b, &x, 1));
}

/* The condition of `if`: a b register or a predicate component. */
static ir_expr *bool_source(d3d9_tx *t, const d3d9_src *s) {
    if (s->type == D3D9_REG_CONSTBOOL) {
        ir_expr *b = hfx_d3d9_tx_bool(t, s->num);
        if (b && s->mod == D3D9_SMOD_NOT) {
            ir_expr *n = hfx_ir_new_expr(t->c, IE_UNARY, b->type, t->loc, 1);
            n->op = OP_NOT;
            n->a[0] = b;
            b = n;
        }
        return b;
    }
    if (s->type != D3D9_REG_PREDICATE) { hfx_d3d9_tx_fail(t, "a condition in register type %u is not supported", s->type); return NULL; }
    ir_expr *p = hfx_d3d9_tx_read(t, s);
    static const uint8_t x = 0;
    return p ? hfx_d3d9_tx_swizzle(t, p, &x, 1) : NULL;
}

static bool push(d3d9_tx *t, ir_stmt *s, ir_stmt *block) {
    if (t->depth + 1 >= D3D9_MAX_DEPTH + 2) { hfx_d3d9_tx_fail(t, "flow control nests too deeply"); return false; }
    hfx_d3d9_tx_add(t, t->depth, s);
    t->depth++;
    t->blocks[t->depth].s = block;
    t->blocks[t->depth].cap = 0;
    t->open[t->depth] = s;
    return true;
}

static void open_if(d3d9_tx *t, ir_expr *cond) {
    if (!cond) return;
    ir_stmt *s = hfx_ir_new_stmt(t->c, IS_IF, t->loc);
    s->expr = cond;
    s->then_s = hfx_ir_new_stmt(t->c, IS_BLOCK, t->loc);
    push(t, s, s->then_s);
}

/* for (int k = 0; k < count.x; k++) { [aL = count.y + k * count.z;] ... } */
static void open_loop(d3d9_tx *t, const d3d9_src *counter, bool with_aL) {
    if (counter->type != D3D9_REG_CONSTINT) { hfx_d3d9_tx_fail(t, "a loop counted by register type %u", counter->type); return; }
    ir_expr *i4 = hfx_d3d9_tx_int4(t, counter->num);
    if (!i4) return;
    ir_var *k = HFX_NEW(t->c->arena, ir_var);
    k->kind = IRV_LOCAL;
    k->name = k->glsl = hfx_arena_printf(t->c->arena, "hfx_k%u", t->loop_count++);
    k->type = t->i1;
    k->param = HFX_NONE;
    hfx_decl *d = HFX_NEW(t->c->arena, hfx_decl);
    d->kind = DECL_VAR;
    d->loc = t->loc;
    d->name = k->name;
    d->type = t->i1;
    k->decl = d;
    ir_stmt *s = hfx_ir_new_stmt(t->c, IS_FOR, t->loc);
    s->init = hfx_ir_new_stmt(t->c, IS_DECL, t->loc);
    s->init->var = k;
    s->init->expr = hfx_ir_const_scalar(t->c, t->i1, 0, t->loc);
    static const uint8_t cx = 0, cy = 1, cz = 2;
    s->expr = hfx_ir_new_binary(t->c, OP_LT, hfx_type_scalar(t->c->types, B_BOOL), hfx_d3d9_tx_var(t, k),
                            hfx_d3d9_tx_swizzle(t, i4, &cx, 1));
    ir_expr *step = hfx_ir_new_expr(t->c, IE_ASSIGN, t->i1, t->loc, 2);
    step->op = OP_NONE;
    step->a[0] = hfx_d3d9_tx_var(t, k);
    step->a[1] = hfx_ir_new_binary(t->c, OP_ADD, t->i1, hfx_d3d9_tx_var(t, k), hfx_ir_const_scalar(t->c, t->i1, 1, t->loc));
    s->step = step;
    s->then_s = hfx_ir_new_stmt(t->c, IS_BLOCK, t->loc);
    if (!push(t, s, s->then_s) || !with_aL) return;
    if (!t->aL) t->aL = hfx_d3d9_tx_local(t, "hfx_aL", t->i1);
    ir_expr *as = hfx_ir_new_expr(t->c, IE_ASSIGN, t->i1, t->loc, 2);
    as->op = OP_NONE;
    as->a[0] = hfx_d3d9_tx_var(t, t->aL);
    as->a[1] = hfx_ir_new_binary(t->c, OP_ADD, t->i1, hfx_d3d9_tx_swizzle(t, hfx_ir_clone_expr(t->c, i4), &cy, 1),
                             hfx_ir_new_binary(t->c, OP_MUL, t->i1, hfx_d3d9_tx_var(t, k),
                                           hfx_d3d9_tx_swizzle(t, hfx_ir_clone_expr(t->c, i4), &cz, 1)));
    hfx_d3d9_tx_emit(t, as);
}

static void add_break(d3d9_tx *t, ir_expr *cond) {
    ir_stmt *b = hfx_ir_new_stmt(t->c, IS_BREAK, t->loc);
    if (!cond) { hfx_d3d9_tx_add(t, t->depth, b); return; }
    ir_stmt *s = hfx_ir_new_stmt(t->c, IS_IF, t->loc);
    s->expr = cond;
    s->then_s = b;
    hfx_d3d9_tx_add(t, t->depth, s);
}

static void close_block(d3d9_tx *t, ir_stmt_kind want, const char *what) {
    if (t->depth <= 1 || t->open[t->depth]->kind != want) { hfx_d3d9_tx_fail(t, "%s closes nothing", what); return; }
    t->depth--;
}

bool hfx_d3d9_tx_flow(d3d9_tx *t, const d3d9_inst *in) {
    switch (in->op) {
    case D3D9_IF: open_if(t, bool_source(t, &in->src[0])); return true;
    case D3D9_IFC: open_if(t, scalar_compare(t, in)); return true;
    case D3D9_ELSE: {
        ir_stmt *s = t->depth > 1 ? t->open[t->depth] : NULL;
        if (!s || s->kind != IS_IF || s->else_s) { hfx_d3d9_tx_fail(t, "else without an if"); return true; }
        s->else_s = hfx_ir_new_stmt(t->c, IS_BLOCK, t->loc);
        t->blocks[t->depth].s = s->else_s;
        t->blocks[t->depth].cap = 0;
        return true;
    }
    case D3D9_ENDIF: close_block(t, IS_IF, "endif"); return true;
    case D3D9_REP: open_loop(t, &in->src[0], false); return true;
    case D3D9_LOOP: open_loop(t, &in->src[1], true); return true;
    case D3D9_ENDREP: close_block(t, IS_FOR, "endrep"); return true;
    case D3D9_ENDLOOP: close_block(t, IS_FOR, "endloop"); return true;
    case D3D9_BREAK: add_break(t, NULL); return true;
    case D3D9_BREAKC: { ir_expr *c = scalar_compare(t, in); if (c) add_break(t, c); return true; }
    case D3D9_BREAKP: { ir_expr *c = bool_source(t, &in->src[0]); if (c) add_break(t, c); return true; }
    default: return false; /* call / callnz / label / ret */
    }
}

/* (p0.swz) op dst, ...: where the predicate is false the destination keeps its value. */
ir_expr *hfx_d3d9_tx_predicate(d3d9_tx *t, const d3d9_inst *in, ir_expr *value) {
    d3d9_src p = in->pred;
    bool negate = p.mod == D3D9_SMOD_NOT;
    p.mod = D3D9_SMOD_NONE;
    ir_expr *cond = hfx_d3d9_tx_read(t, &p);
    ir_expr *old = hfx_d3d9_tx_reg(t, in->dst.type, in->dst.num);
    if (!cond || !old || !value) return NULL;
    if (value->type->base != B_FLOAT) { hfx_d3d9_tx_fail(t, "a predicated write of this register is not supported yet"); return NULL; }
    ir_expr *e = hfx_ir_new_expr(t->c, IE_SELECT, t->f4, t->loc, 3);
    e->a[0] = cond;
    e->a[1] = negate ? old : value;
    e->a[2] = negate ? value : old;
    return e;
}
