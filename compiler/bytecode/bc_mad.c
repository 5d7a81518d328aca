/* bc_mad.c: a product kept in a variable and added afterwards (`float4 e = tex * a; ... e - c`)
 * is one mad, as fxc writes it (`mad r0.xyz, r0, r1.w, -r1`): selection sees a product plus a sum
 * only inside one expression. `add D, rT, B` whose rT a `mul rT, X, Y` of the same block wrote,
 * and that nothing reads afterwards, becomes `mad D, X, Y, B` (X and Y unchanged between, their
 * swizzles composed with the add's); the mul, now unread, goes with the dead code. */
#include "bytecode/bc_int.h"

static bool flow(const d3d9_inst *in) {
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    return !info || (info->flags & D3D9_OPF_FLOW);
}

static bool writes_reg(const d3d9_inst *in, const d3d9_src *s) {
    return in->has_dst && in->op != D3D9_TEXKILL && in->dst.type == s->type && in->dst.num == s->num;
}

/* The mul writing what source k of the add reads, between which nothing changes its sources or
 * that register; -1: none. */
static int product_of(const bc_gen *g, uint32_t at, unsigned k) {
    const d3d9_src *t = &g->insts[at].src[k];
    if (t->type != D3D9_REG_TEMP || t->relative || (t->mod != D3D9_SMOD_NONE && t->mod != D3D9_SMOD_NEG)) return -1;
    unsigned need = hfx_bc_read_comps(g, &g->insts[at], k);
    for (uint32_t i = at; i-- > 0;) {
        const d3d9_inst *m = &g->insts[i];
        if (flow(m)) return -1;
        if (!writes_reg(m, t)) continue;
        if (m->op != D3D9_MUL || m->predicated || m->dst.mods || (need & ~(unsigned)m->dst.mask)) return -1;
        for (unsigned s = 0; s < 2; s++) {
            const d3d9_src *x = &m->src[s];
            if (x->relative || (x->mod != D3D9_SMOD_NONE && x->mod != D3D9_SMOD_NEG) ||
                (x->type == t->type && x->num == t->num))
                return -1;
            for (uint32_t j = i + 1; j < at; j++) if (writes_reg(&g->insts[j], x)) return -1;
        }
        return (int)i;
    }
    return -1;
}

/* The add at `at` as a mad of the mul at m (its source k the product). */
static void fuse(bc_gen *g, uint32_t at, unsigned k, uint32_t m) {
    d3d9_inst *add = &g->insts[at];
    const d3d9_inst *mul = &g->insts[m];
    d3d9_src other = add->src[1 - k], p = add->src[k], x[2];
    for (unsigned s = 0; s < 2; s++) {
        x[s] = mul->src[s];
        uint8_t sw = 0;
        for (unsigned c = 0; c < 4; c++) sw |= (uint8_t)((mul->src[s].swizzle >> (2 * (p.swizzle >> (2 * c) & 3)) & 3) << (2 * c));
        x[s].swizzle = hfx_bc_tidy(sw, add->dst.mask, false);
    }
    if (p.mod == D3D9_SMOD_NEG) x[0].mod = x[0].mod == D3D9_SMOD_NEG ? D3D9_SMOD_NONE : D3D9_SMOD_NEG;
    add->op = D3D9_MAD;
    add->src[0] = x[0];
    add->src[1] = x[1];
    add->src[2] = other;
    add->src_count = 3;
}

void hfx_bc_fuse_mad(bc_gen *g) {
    for (uint32_t i = 0; i < g->inst_count; i++) {
        d3d9_inst *in = &g->insts[i];
        if (in->op != D3D9_ADD || in->predicated) continue;
        for (unsigned k = 0; k < 2; k++) {
            int m = product_of(g, i, k);
            if (m < 0) continue;
            uint32_t span;
            const uint8_t *live = hfx_bc_liveness(g, NULL, &span);
            const d3d9_src *t = &in->src[k];
            if (!live || t->num >= span || (live[(size_t)i * span + t->num] & hfx_bc_read_comps(g, in, k))) continue; /* read again later */
            bool again = false; /* read between the mul and the add */
            for (uint32_t j = (uint32_t)m + 1; j < i && !again; j++)
                for (unsigned s = 0; s < g->insts[j].src_count; s++)
                    again |= g->insts[j].src[s].type == t->type && g->insts[j].src[s].num == t->num;
            if (again) continue;
            fuse(g, i, k, (uint32_t)m);
            break;
        }
    }
}

/* The source of the add at `at` reading temporary T (the other must not); -1: none or both. */
static int reads_once(const d3d9_inst *in, unsigned T) {
    int k = -1;
    for (unsigned s = 0; s < in->src_count && s < 4; s++) {
        const d3d9_src *x = &in->src[s];
        if (x->relative && x->rel_type == D3D9_REG_TEMP && x->rel_num == T) return -2;
        if (x->type != D3D9_REG_TEMP || x->num != T) continue;
        if (k >= 0) return -2;
        k = (int)s;
    }
    return k;
}

/* The instruction after nrm at w where its value dies, when every instruction reading it before
 * is an add reading it once (S unchanged until then, the adds' other operands sharing a read
 * port with S); 0: not so. */
static uint32_t adds_reading(bc_gen *g, uint32_t w) {
    const d3d9_inst *n = &g->insts[w];
    const d3d9_src *S = &n->src[0];
    unsigned T = n->dst.num, mask = n->dst.mask, s_comps = hfx_bc_read_comps(g, n, 0);
    uint32_t span;
    const uint8_t *live = hfx_bc_liveness(g, NULL, &span);
    if (!live || T >= span || !(live[(size_t)w * span + T] & mask)) return 0;
    for (uint32_t i = w + 1; i < g->inst_count; i++) {
        const d3d9_inst *in = &g->insts[i];
        int k = reads_once(in, T);
        if (flow(in) || k == -2 || (in->op == D3D9_TEXKILL && in->dst.type == D3D9_REG_TEMP && in->dst.num == T) ||
            (in->has_dst && in->dst.type == D3D9_REG_TEMP && in->dst.num == T))
            return 0;
        if (k >= 0) {
            const d3d9_src *x = &in->src[k], *y = &in->src[1 - k];
            if (in->op != D3D9_ADD || in->predicated || (x->mod != D3D9_SMOD_NONE && x->mod != D3D9_SMOD_NEG) ||
                (hfx_bc_read_comps(g, in, (unsigned)k) & ~mask))
                return 0;
            if (S->type != D3D9_REG_TEMP && y->type == S->type && y->num != S->num) return 0; /* one read port */
        }
        bool dies = !(live[(size_t)i * span + T] & mask);
        if (!dies && writes_reg(in, S) && (in->dst.mask & s_comps)) return 0;
        if (dies) return k >= 0 ? i : 0;
    }
    return 0;
}

/* nrm rT, S whose value only adds read (three lights' half vectors, `normalize(eye - p) - L`):
 * `dp3 rT.x, S, S` / `rsq rT.x, rT.x`, each add `add D, rT, Y` a `mad D, S, rT.x, Y`, as fxc
 * writes it: nrm's mul folded into the adds, one slot fewer. */
static bool nrm_into_adds(bc_gen *g, uint32_t w) {
    d3d9_inst *n = &g->insts[w];
    const d3d9_src S = n->src[0];
    if (n->op != D3D9_NRM || n->predicated || n->dst.mods || n->dst.shift || n->dst.type != D3D9_REG_TEMP ||
        n->dst.relative || S.relative || (S.mod != D3D9_SMOD_NONE && S.mod != D3D9_SMOD_NEG) ||
        (S.type == D3D9_REG_TEMP && S.num == n->dst.num))
        return false;
    uint32_t last = adds_reading(g, w);
    if (!last || !HFX_ARENA_GROW(g->c->arena, g->insts, g->inst_count, g->inst_cap, 64)) return false;
    n = &g->insts[w];
    unsigned T = n->dst.num, c0 = (unsigned)__builtin_ctz(n->dst.mask);
    memmove(&g->insts[w + 2], &g->insts[w + 1], (g->inst_count - w - 1) * sizeof *g->insts);
    g->inst_count++;
    d3d9_src scale = {.type = D3D9_REG_TEMP, .num = (uint16_t)T, .swizzle = (uint8_t)(c0 * 0x55u)};
    n->op = D3D9_DP3;
    n->dst.mask = (uint8_t)(1u << c0);
    n->src[1] = S;
    n->src_count = 2;
    d3d9_inst *rsq = &g->insts[w + 1];
    *rsq = *n;
    rsq->op = D3D9_RSQ;
    rsq->src[0] = scale;
    rsq->src_count = 1;
    for (uint32_t i = w + 2; i <= last + 1; i++) {
        d3d9_inst *in = &g->insts[i];
        int k = reads_once(in, T);
        if (k < 0) continue;
        d3d9_src x = in->src[k], y = in->src[1 - k], s = S;
        uint8_t sw = 0;
        for (unsigned c = 0; c < 4; c++) sw |= (uint8_t)((S.swizzle >> (2 * (x.swizzle >> (2 * c) & 3)) & 3) << (2 * c));
        s.swizzle = hfx_bc_tidy(sw, in->dst.mask, false);
        if (x.mod == D3D9_SMOD_NEG) s.mod = s.mod == D3D9_SMOD_NEG ? D3D9_SMOD_NONE : D3D9_SMOD_NEG;
        in->op = D3D9_MAD;
        in->src[0] = s;
        in->src[1] = scale;
        in->src[2] = y;
        in->src_count = 3;
    }
    return true;
}

void hfx_bc_nrm_into_adds(bc_gen *g) {
    for (uint32_t i = 0; i < g->inst_count && !g->failed; i++) nrm_into_adds(g, i);
}
