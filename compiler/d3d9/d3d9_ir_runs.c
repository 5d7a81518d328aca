/* d3d9_ir_runs.c: fxc's scalar instructions read back as the vector operation the source said.
 * exp, log, rcp and rsq take one component (the replicate swizzle), so fxc writes exp2(v) of a
 * float4 as four instructions, `exp r2.x, r0.x; exp r2.y, r0.y; ...`. Translated one by one,
 * each is a splat, a call and a component pick; drivers compile the one vector call several
 * times faster (bench/bench_fx2_load: DigitalRise's Blur computes four logs and four exps a
 * tap). Component k of the vector form is the instruction's own result, so nothing changes. */
#include "d3d9/d3d9_ir.h"

static bool scalar_op(unsigned op) { return op == D3D9_EXP || op == D3D9_LOG || op == D3D9_RCP || op == D3D9_RSQ; }

/* The one component a mask writes, or -1. */
static int single(unsigned mask) {
    return mask == 1 ? 0 : mask == 2 ? 1 : mask == 4 ? 2 : mask == 8 ? 3 : -1;
}

static bool same_register(const d3d9_src *a, const d3d9_src *b) {
    return a->type == b->type && a->num == b->num && a->mod == b->mod && a->relative == b->relative &&
           a->rel_type == b->rel_type && a->rel_comp == b->rel_comp && a->rel_num == b->rel_num;
}

/* Whether `in` can be part of a run headed by `first` (itself included), writing a component
 * not yet written (`written`, a mask) and reading one the run has not overwritten. */
static bool joins(const d3d9_inst *first, const d3d9_inst *in, unsigned written) {
    int k = single(in->dst.mask);
    if (in->op != first->op || in->predicated || in->coissue || in->dst.shift || in->dst.relative || k < 0 ||
        (written & in->dst.mask) || in->dst.type != first->dst.type || in->dst.num != first->dst.num ||
        in->dst.mods != first->dst.mods || !same_register(&in->src[0], &first->src[0]))
        return false;
    const d3d9_src *x = &in->src[0];
    bool reads_dst = !x->relative && x->type == in->dst.type && x->num == in->dst.num;
    return !reads_dst || !(written & (1u << (x->swizzle & 3)));
}

/* The length of the run of one scalar operation at instruction i (2 to 4), or 0. */
static unsigned run_length(const d3d9_tx *t, uint32_t i) {
    const d3d9_inst *first = &t->s->insts[i];
    if (!scalar_op(first->op) || !joins(first, first, 0)) return 0;
    unsigned n = 0, written = 0;
    while (i + n < t->s->inst_count && n < 4 && joins(first, &t->s->insts[i + n], written))
        written |= t->s->insts[i + n++].dst.mask;
    return n >= 2 ? n : 0;
}

/* The operation on every component of v (float4), as arith in d3d9_ir_ops.c does on one. */
static ir_expr *apply(d3d9_tx *t, unsigned op, ir_expr *v) {
    if (op == D3D9_RCP) return hfx_ir_new_binary(t->c, OP_DIV, t->f4, hfx_ir_const_scalar(t->c, t->f4, 1, t->loc), v);
    if (op == D3D9_LOG || op == D3D9_RSQ) { /* both take |x| */
        ir_expr *a = hfx_ir_new_expr(t->c, IE_INTRIN, t->f4, t->loc, 1);
        a->intrin = HFX_INTR_ABS;
        a->a[0] = v;
        v = a;
    }
    ir_expr *e = hfx_ir_new_expr(t->c, IE_INTRIN, t->f4, t->loc, 1);
    e->intrin = op == D3D9_EXP ? HFX_INTR_EXP2 : op == D3D9_LOG ? HFX_INTR_LOG2 : HFX_INTR_RSQRT;
    e->a[0] = v;
    return e;
}

unsigned hfx_d3d9_tx_scalar_run(d3d9_tx *t, uint32_t i) {
    unsigned n = run_length(t, i);
    if (!n) return 0;
    const d3d9_inst *first = &t->s->insts[i];
    d3d9_src x = first->src[0];
    d3d9_dst d = first->dst;
    unsigned swz = 0, from = x.swizzle & 3;
    for (unsigned k = 0; k < 4; k++) swz |= from << (2 * k); /* unwritten components: any, the first's */
    for (unsigned m = 0; m < n; m++) {
        const d3d9_inst *in = &t->s->insts[i + m];
        unsigned k = (unsigned)single(in->dst.mask);
        swz = (swz & ~(3u << (2 * k))) | (unsigned)(in->src[0].swizzle & 3) << (2 * k);
        d.mask = (uint8_t)(d.mask | in->dst.mask);
    }
    x.swizzle = (uint8_t)swz;
    ir_expr *v = hfx_d3d9_tx_read(t, &x);
    if (v) hfx_d3d9_tx_write(t, &d, apply(t, first->op, v));
    else if (!t->failed) hfx_d3d9_tx_fail(t, "%s could not be translated", hfx_d3d9_op_find(first->op)->name);
    return n;
}
