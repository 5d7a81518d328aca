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
