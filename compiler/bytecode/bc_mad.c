/* bc_mad.c: a product added where it is read: `mul rT, a, b` whose temporary dies at the add
 * reading it becomes `mad d, a, b, c` in place of `add d, rT, c` (one slot, not two). Selection
 * writes mad for `a * b + c` in one expression; this catches products made in one statement and
 * summed in another (a sum of weighted samples, offsets built component by component). */
#include "bytecode/bc_int.h"

static bool flow(const d3d9_inst *in) {
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    return !info || (info->flags & D3D9_OPF_FLOW);
}

static bool reads_reg(const d3d9_inst *in, unsigned type, unsigned num) {
    for (unsigned k = 0; k < in->src_count && k < 4; k++) {
        const d3d9_src *s = &in->src[k];
        if ((s->type == type && s->num == num) || (s->relative && s->rel_type == type && s->rel_num == num)) return true;
    }
    return in->op == D3D9_TEXKILL && in->dst.type == type && in->dst.num == num;
}

static bool writes_any(const d3d9_inst *w, const d3d9_inst *in) {
    if (!w->has_dst || w->op == D3D9_TEXKILL) return false;
    return w->dst.relative || reads_reg(in, w->dst.type, w->dst.num) || (w->dst.type == in->dst.type && w->dst.num == in->dst.num);
}

/* The mad reads at most one register of each of the c, v and t files (the read ports). */
static bool ports_ok(const d3d9_src *s) {
    static const uint8_t files[] = {D3D9_REG_CONST, D3D9_REG_INPUT, D3D9_REG_ADDR}; /* ADDR: ps_2_x's t */
    for (unsigned f = 0; f < 3; f++)
        for (unsigned a = 0; a < 3; a++)
            for (unsigned b = a + 1; b < 3; b++)
                if (s[a].type == files[f] && s[b].type == files[f] && (s[a].num != s[b].num || s[a].relative || s[b].relative))
                    return false;
    return true;
}

static bool plain_mod(unsigned mod) {
    return mod == D3D9_SMOD_NONE || mod == D3D9_SMOD_NEG || mod == D3D9_SMOD_ABS || mod == D3D9_SMOD_ABSNEG;
}

/* What source s of the product gives at the positions the add reads through swizzle sw. */
static d3d9_src through(d3d9_src s, uint8_t sw, bool neg) {
    uint8_t out = 0;
    for (unsigned p = 0; p < 4; p++) out |= (uint8_t)((s.swizzle >> (2 * (sw >> (2 * p) & 3)) & 3) << (2 * p));
    s.swizzle = out;
    if (neg) s.mod = s.mod == D3D9_SMOD_NONE ? D3D9_SMOD_NEG : s.mod == D3D9_SMOD_NEG ? D3D9_SMOD_NONE
                   : s.mod == D3D9_SMOD_ABS ? D3D9_SMOD_ABSNEG : D3D9_SMOD_ABS;
    return s;
}

static bool fuse(bc_gen *g, uint32_t i, const uint8_t *live, uint32_t span) {
    const d3d9_inst *m = &g->insts[i];
    if (m->op != D3D9_MUL || !m->has_dst || m->dst.type != D3D9_REG_TEMP || m->dst.relative || m->predicated ||
        m->dst.mods || m->dst.shift || m->dst.num >= span || !plain_mod(m->src[0].mod) || !plain_mod(m->src[1].mod))
        return false;
    unsigned T = m->dst.num;
    uint32_t j = i + 1;
    for (; j < g->inst_count && !reads_reg(&g->insts[j], D3D9_REG_TEMP, T); j++)
        if (flow(&g->insts[j]) || writes_any(&g->insts[j], m)) return false;
    if (j == g->inst_count) return false;
    d3d9_inst *a = &g->insts[j];
    if (a->op != D3D9_ADD || a->predicated || a->dst.relative || (live[(size_t)j * span + T] & m->dst.mask)) return false;
    bool r0 = a->src[0].type == D3D9_REG_TEMP && a->src[0].num == T, r1 = a->src[1].type == D3D9_REG_TEMP && a->src[1].num == T;
    if (r0 == r1) return false;
    unsigned k = r0 ? 0 : 1;
    const d3d9_src *t = &a->src[k];
    if (t->relative || (t->mod != D3D9_SMOD_NONE && t->mod != D3D9_SMOD_NEG) ||
        (hfx_bc_read_comps(g, a, k) & ~(unsigned)m->dst.mask))
        return false;
    d3d9_src s[3] = {through(m->src[0], t->swizzle, t->mod == D3D9_SMOD_NEG), through(m->src[1], t->swizzle, false), a->src[1 - k]};
    if (!ports_ok(s)) return false;
    a->op = D3D9_MAD;
    a->src_count = 3;
    memcpy(a->src, s, sizeof s);
    return true;
}

void hfx_bc_fuse_mad(bc_gen *g) {
    uint32_t span, n = g->inst_count;
    const uint8_t *live = hfx_bc_liveness(g, NULL, &span);
    bool *del = HFX_NEW_ARRAY(g->c->arena, bool, n ? n : 1);
    if (!live || !del || g->failed) return;
    for (uint32_t i = 0; i < n; i++) del[i] = fuse(g, i, live, span);
    uint32_t k = 0;
    for (uint32_t i = 0; i < n; i++) if (!del[i]) g->insts[k++] = g->insts[i];
    g->inst_count = k;
}
