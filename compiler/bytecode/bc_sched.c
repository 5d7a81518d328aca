/* bc_sched.c: the temporaries' final registers (bc_alloc.c's packing), and when they are more
 * than the model has, the code reordered for fewer values live at once and packed again. The
 * generator writes statements in order: sixteen `float4 sK = tex2D(...)` then their sum hold
 * sixteen texels at once, where fxc samples each just before the add that reads it. */
#include "bytecode/bc_int.h"

static bool flow(const d3d9_inst *in) {
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    return !info || (info->flags & D3D9_OPF_FLOW);
}

static bool temp_write(const d3d9_inst *in) {
    return in->has_dst && in->op != D3D9_TEXKILL && in->dst.type == D3D9_REG_TEMP && !in->dst.relative;
}

static bool reads_reg(const d3d9_inst *in, unsigned type, unsigned num) {
    for (unsigned k = 0; k < in->src_count && k < 4; k++) {
        const d3d9_src *s = &in->src[k];
        if ((s->type == type && s->num == num) || (s->relative && s->rel_type == type && s->rel_num == num)) return true;
    }
    return in->op == D3D9_TEXKILL && in->dst.type == type && in->dst.num == num;
}

/* J may run before I (I moved below J): neither reads what the other writes, nor both write one register. */
static bool independent(const d3d9_inst *i, const d3d9_inst *j) {
    if (j->has_dst && j->op != D3D9_TEXKILL) {
        if (reads_reg(i, j->dst.type, j->dst.num) || j->dst.relative) return false;
        if (j->dst.type == i->dst.type && j->dst.num == i->dst.num) return false;
    }
    return !reads_reg(j, i->dst.type, i->dst.num);
}

/* Temporary num is read at or after instruction `from` before a write replaces it whole. */
static bool read_from(const bc_gen *g, uint32_t from, unsigned num) {
    for (uint32_t i = from; i < g->inst_count; i++) {
        const d3d9_inst *in = &g->insts[i];
        if (reads_reg(in, D3D9_REG_TEMP, num)) return true;
        if (temp_write(in) && in->dst.num == num && in->dst.mask == 0xf && !in->predicated) return false;
    }
    return false;
}

/* Instruction at moves down to just before `to`: its result is live for fewer instructions; a
 * temporary it reads that would have died at it lives on to `to` instead. Worth it when what
 * those sources add is no more than the components it writes. */
static bool worth(const bc_gen *g, uint32_t at, uint32_t to) {
    const d3d9_inst *in = &g->insts[at];
    unsigned cost = 0;
    for (unsigned k = 0; k < in->src_count && k < 4; k++) {
        const d3d9_src *s = &in->src[k];
        if (s->type == D3D9_REG_TEMP && s->num != in->dst.num && !read_from(g, to, s->num))
            cost += (unsigned)__builtin_popcount(hfx_bc_read_comps(g, in, k));
    }
    return cost <= (unsigned)__builtin_popcount(in->dst.mask);
}

/* Bottom up inside each block: every temporary's writer sinks to just before its first reader
 * (or whatever it must stay above), so a value is computed when it is needed. */
static void schedule(bc_gen *g) {
    for (uint32_t at = g->inst_count; at-- > 0;) {
        d3d9_inst *in = &g->insts[at];
        if (!temp_write(in) || in->predicated || flow(in)) continue;
        uint32_t to = at + 1;
        while (to < g->inst_count && !flow(&g->insts[to]) && independent(in, &g->insts[to])) to++;
        if (to == at + 1 || !worth(g, at, to)) continue;
        d3d9_inst moved = *in;
        memmove(in, in + 1, (to - at - 1) * sizeof *in);
        g->insts[to - 1] = moved;
    }
}

uint32_t hfx_bc_allocate(bc_gen *g) {
    uint32_t n = g->inst_count;
    d3d9_inst *copy = HFX_NEW_ARRAY(g->c->arena, d3d9_inst, n ? n : 1);
    if (copy) memcpy(copy, g->insts, n * sizeof *copy);
    uint32_t count = hfx_bc_renumber(g);
    if (count <= hfx_bc_temp_limit(g) || !copy) return count;
    memcpy(g->insts, copy, n * sizeof *copy); /* the first packing's rewrite undone */
    g->inst_count = n;
    schedule(g);
    uint32_t again = hfx_bc_renumber(g);
    if (again < count) return again;
    memcpy(g->insts, copy, n * sizeof *copy); /* no better: the first order, packed again */
    g->inst_count = n;
    return hfx_bc_renumber(g);
}
