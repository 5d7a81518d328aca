/* bc_vec.c: component-by-component operations on one register merged into one instruction, as
 * fxc writes them. `float2(-3 * o.x, -1 * o.y)` is selected as two muls, each into a component of
 * the vector once the copies are sunk (bc_peep.c): `mul r1.x, c1.z, r0.x` / `mul r1.y, c1.w, r0.y`;
 * a swizzle picks a component per lane, so when the two read the same registers in each operand
 * they are `mul r1.xy, c1.zw, r0.xy` (literals in different def registers are gathered into one).
 * Each lane computes what it computed alone, so values are the same to the bit. */
#include "bytecode/bc_int.h"

static bool flow(const d3d9_inst *in) {
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    return !info || (info->flags & D3D9_OPF_FLOW);
}

static bool lanewise(unsigned op) {
    switch (op) {
    case D3D9_MOV: case D3D9_ADD: case D3D9_MUL: case D3D9_MAD: case D3D9_MIN: case D3D9_MAX: case D3D9_SLT:
    case D3D9_SGE: case D3D9_CMP: case D3D9_FRC: case D3D9_LRP: case D3D9_ABS:
        return true;
    default: return false;
    }
}

static bool plain(const d3d9_inst *in) {
    if (!lanewise(in->op) || !in->has_dst || in->predicated || in->dst.relative) return false;
    for (unsigned k = 0; k < in->src_count && k < 4; k++)
        if (in->src[k].relative) return false;
    return true;
}

static int def_of(const bc_gen *g, const d3d9_src *s) {
    if (s->type != D3D9_REG_CONST) return -1;
    for (uint32_t d = 0; d < g->def_count; d++)
        if (g->defs[d].num == s->num) return (int)d;
    return -1;
}

/* Components of register (type, num) instruction `in` reads. */
static unsigned reads(const bc_gen *g, const d3d9_inst *in, unsigned type, unsigned num) {
    unsigned m = 0;
    for (unsigned k = 0; k < in->src_count && k < 4; k++) {
        const d3d9_src *s = &in->src[k];
        if (s->relative && s->rel_type == type && s->rel_num == num) m |= 0xf;
        if (s->type == type && s->num == num) m |= s->relative ? 0xf : hfx_bc_read_comps(g, in, k);
    }
    if (in->op == D3D9_TEXKILL && in->dst.type == type && in->dst.num == num) m |= 0xf;
    return m;
}

static unsigned writes(const d3d9_inst *in, unsigned type, unsigned num) {
    if (!in->has_dst || in->op == D3D9_TEXKILL || in->dst.type != type) return 0;
    return in->dst.relative || in->dst.num == num ? (in->dst.relative ? 0xf : in->dst.mask) : 0;
}

/* The instruction at `from` may move to `to` (either way) across what lies between (its partner
 * at `to` apart: the merged instruction reads before it writes): nothing there writes what it
 * reads, nor reads or writes the components it writes. */
static bool movable(const bc_gen *g, uint32_t from, uint32_t to) {
    const d3d9_inst *m = &g->insts[from];
    uint32_t lo = from < to ? from + 1 : to + 1, hi = from < to ? to : from;
    for (uint32_t i = lo; i < hi; i++) {
        const d3d9_inst *x = &g->insts[i];
        for (unsigned k = 0; k < m->src_count && k < 4; k++)
            if (writes(x, m->src[k].type, m->src[k].num) & hfx_bc_read_comps(g, m, k)) return false;
        if ((reads(g, x, m->dst.type, m->dst.num) | writes(x, m->dst.type, m->dst.num)) & m->dst.mask) return false;
    }
    return true;
}

/* Source k of a and b (a's lanes in ma, b's in mb) as one source over both, when one register
 * (or one def register gathering both literals) serves. */
static bool merge_source(bc_gen *g, const d3d9_src *a, unsigned ma, const d3d9_src *b, unsigned mb, d3d9_src *out) {
    if (a->type != b->type || a->mod != b->mod) return false;
    uint8_t sw = 0;
    for (unsigned p = 0; p < 4; p++)
        sw |= (uint8_t)(((mb >> p & 1) ? b->swizzle : a->swizzle) >> (2 * p) & 3) << (2 * p);
    *out = *a;
    if (a->num == b->num) {
        out->swizzle = hfx_bc_tidy(sw, ma | mb, false);
        return true;
    }
    int da = def_of(g, a), db = def_of(g, b);
    if (da < 0 || db < 0) return false;
    float v[4];
    unsigned n = 0;
    for (unsigned p = 0; p < 4; p++)
        if ((ma | mb) >> p & 1) v[n++] = g->defs[(mb >> p & 1) ? db : da].v[sw >> (2 * p) & 3];
    if (!hfx_bc_literal_fits(g, v, n)) return false;
    bc_val lit = hfx_bc_const(g, v, n);
    if (g->failed) return false;
    out->num = lit.num;
    sw = 0;
    for (unsigned p = 0, i = 0; p < 4; p++)
        if ((ma | mb) >> p & 1) sw |= (uint8_t)(lit.sw[i++] << (2 * p));
    out->swizzle = hfx_bc_tidy(sw, ma | mb, false);
    return true;
}

/* A copy as its partner's operation giving the same bits: x * 1 (-x as x * -1) for a mul, x + -0
 * for an add (-0 + -0 is -0, NaN stays NaN); the copied operand at position k. */
static bool as_op(bc_gen *g, const d3d9_inst *mov, unsigned op, unsigned k, d3d9_inst *out) {
    if (mov->op != D3D9_MOV || (op != D3D9_MUL && op != D3D9_ADD)) return false;
    bool neg = op == D3D9_MUL && mov->src[0].mod == D3D9_SMOD_NEG;
    float v = op == D3D9_ADD ? -0.0f : neg ? -1.0f : 1.0f;
    if (!hfx_bc_literal_fits(g, &v, 1)) return false;
    bc_val lit = hfx_bc_const(g, &v, 1);
    if (g->failed) return false;
    *out = *mov;
    out->op = (uint16_t)op;
    out->src_count = 2;
    out->src[k] = mov->src[0];
    if (neg) out->src[k].mod = D3D9_SMOD_NONE;
    out->src[1 - k] = (d3d9_src){.type = D3D9_REG_CONST, .num = lit.num, .swizzle = (uint8_t)(lit.sw[0] * 0x55u)};
    return true;
}

/* a and b (one operation, each on its lanes) as one instruction m. */
static bool combine(bc_gen *g, const d3d9_inst *a, const d3d9_inst *b, d3d9_inst *m) {
    if (b->op != a->op || b->src_count != a->src_count) return false;
    *m = *a;
    for (unsigned k = 0; k < a->src_count && k < 4; k++)
        if (!merge_source(g, &a->src[k], a->dst.mask, &b->src[k], b->dst.mask, &m->src[k])) return false;
    m->dst.mask = (uint8_t)(a->dst.mask | b->dst.mask);
    return true;
}

/* The def registers as they were before a merge was tried: literals it made for nothing go. */
typedef struct literals { uint32_t count; uint8_t last_used; } literals;

static void forget(bc_gen *g, const literals *l) {
    for (uint32_t d = l->count; d < g->def_count; d++)
        if (g->defs[d].num < BC_MAX_CONSTS) g->cused[g->defs[d].num] = 0;
    g->def_count = l->count;
    if (!l->count) return;
    bc_def *d = &g->defs[l->count - 1];
    for (unsigned k = l->last_used; k < 4; k++) d->v[k] = 0; /* the listing shows all four */
    d->used = l->last_used;
}

/* b (after a) computed with a as one instruction, at a's place (1) or at b's (2); 0: not. */
static int try_merge(bc_gen *g, uint32_t ia, uint32_t ib) {
    const d3d9_inst *a = &g->insts[ia], *b = &g->insts[ib];
    bool copy = (a->op == D3D9_MOV) != (b->op == D3D9_MOV) && (a->op == D3D9_MUL || a->op == D3D9_ADD ||
                                                                b->op == D3D9_MUL || b->op == D3D9_ADD);
    if ((b->op != a->op && !copy) || !plain(b) || b->dst.type != a->dst.type || b->dst.num != a->dst.num ||
        (b->dst.mask & a->dst.mask) || b->dst.mods != a->dst.mods || b->dst.shift != a->dst.shift || b->control != a->control)
        return 0;
    if (reads(g, b, a->dst.type, a->dst.num) & a->dst.mask) return 0; /* b reads a's result */
    bool at_a = movable(g, ib, ia), at_b = !at_a && movable(g, ia, ib);
    if (!at_a && !at_b) return 0;
    d3d9_inst m, c, d;
    literals before = {g->def_count, g->def_count ? g->defs[g->def_count - 1].used : 0};
    bool ok = combine(g, a, b, &m);
    for (unsigned k = 0; k < 2 && !ok && copy; k++) {
        if (as_op(g, a, b->op, k, &c)) ok = combine(g, &c, b, &m);
        else if (as_op(g, b, a->op, k, &c)) ok = combine(g, a, &c, &m);
    }
    if (!ok && a->op == D3D9_MOV && b->op == D3D9_MOV && as_op(g, a, D3D9_MUL, 0, &c) && as_op(g, b, D3D9_MUL, 0, &d))
        ok = combine(g, &c, &d, &m); /* copies of one register, negated in some lanes: one mul by +-1 */
    if (!ok) {
        forget(g, &before);
        return 0;
    }
    uint32_t keep = at_a ? ia : ib, drop = at_a ? ib : ia;
    g->insts[keep] = m;
    memmove(&g->insts[drop], &g->insts[drop + 1], (g->inst_count - drop - 1) * sizeof *g->insts);
    g->inst_count--;
    return at_a ? 1 : 2;
}

void hfx_bc_vectorize(bc_gen *g) {
    enum { WINDOW = 48 }; /* how far ahead a partner is looked for */
    for (uint32_t i = 0; i < g->inst_count && !g->failed;) {
        int moved = 0;
        for (uint32_t j = i + 1; plain(&g->insts[i]) && g->insts[i].dst.mask != 0xf && j < g->inst_count &&
                                 j <= i + WINDOW && !flow(&g->insts[j]) && !moved;) {
            int r = try_merge(g, i, j);
            if (r == 2) moved = 1; /* i went down to j's place: the instruction now at i is the next */
            else if (!r) j++;      /* r == 1: j went; the next one is at j now */
        }
        if (!moved) i++;
    }
}
