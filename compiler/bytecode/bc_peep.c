/* bc_peep.c: after instruction selection, a copy `mov X, rT` whose temporary dies there is
 * folded into the instructions that computed rT: they write X themselves (fxc's `dp4 oPos.x, v0,
 * c0` where a plain walk of the tree computes into a temporary and moves it). */
#include "bytecode/bc_int.h"

static bool reads(const d3d9_inst *in, unsigned type, unsigned num) {
    for (unsigned i = 0; i < in->src_count; i++) {
        const d3d9_src *s = &in->src[i];
        if (s->type == type && s->num == num) return true;
        if (s->relative && s->rel_type == type && s->rel_num == num) return true;
    }
    if (in->op == D3D9_TEXKILL && in->dst.type == type && in->dst.num == num) return true;
    return false;
}

static bool flow(const d3d9_inst *in) {
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    return info && (info->flags & D3D9_OPF_FLOW);
}

static bool writes(const d3d9_inst *in, unsigned type, unsigned num) {
    return in->has_dst && in->op != D3D9_TEXKILL && in->dst.type == type && in->dst.num == num;
}

/* Instructions whose destination must stay a temporary (or has a fixed mask). */
static bool movable_writer(const bc_gen *g, const d3d9_inst *in, unsigned to_type) {
    switch (in->op) {
    case D3D9_NRM: /* into an output: written as dp3 / rsq / mul (expand_nrm) */
        return !in->dst.relative && !in->predicated && !in->dst.mods;
    case D3D9_SINCOS: case D3D9_CRS: case D3D9_LIT: case D3D9_MOVA: case D3D9_TEXKILL:
    case D3D9_TEX: case D3D9_TEXLDL: case D3D9_TEXLDD: case D3D9_DSX: case D3D9_DSY:
        return to_type == D3D9_REG_TEMP && in->op != D3D9_MOVA && in->op != D3D9_TEXKILL && in->op != D3D9_SINCOS &&
               !(g->stage == D3D9_PS && g->model < D3D9_SM(3, 0) && (in->op == D3D9_TEX)) ;
    default: return in->has_dst && !in->dst.relative && !in->predicated;
    }
}

/* Components of temporary T instruction `in` reads (0xf: read as an index). */
static unsigned reads_temp(const bc_gen *g, const d3d9_inst *in, unsigned T) {
    unsigned m = 0;
    for (unsigned k = 0; k < in->src_count && k < 4; k++) {
        const d3d9_src *s = &in->src[k];
        if (s->relative && s->rel_type == D3D9_REG_TEMP && s->rel_num == T) m |= 0xf;
        if (s->type == D3D9_REG_TEMP && s->num == T) m |= s->relative ? 0xf : hfx_bc_read_comps(g, in, k);
    }
    if (in->op == D3D9_TEXKILL && in->dst.type == D3D9_REG_TEMP && in->dst.num == T) m |= 0xf;
    return m;
}

/* The temporary's components in mask are not read after instruction at (before being rewritten). */
static bool dead_after(const bc_gen *g, uint32_t at, unsigned num, unsigned mask) {
    for (uint32_t i = at + 1; i < g->inst_count; i++) {
        const d3d9_inst *in = &g->insts[i];
        if (reads_temp(g, in, num) & mask) return false;
        if (writes(in, D3D9_REG_TEMP, num)) {
            mask &= ~(unsigned)in->dst.mask;
            if (!mask) return true;
        }
        if (flow(in)) { /* a loop may read it again at its top: ask the liveness that follows the flow */
            uint32_t span;
            const uint8_t *live = hfx_bc_liveness((bc_gen *)g, NULL, &span);
            return live && num < span && !(live[(size_t)at * span + num] & mask);
        }
    }
    return true;
}

/* A plain copy of a temporary; *moved: the one component it moves elsewhere (-1: none). */
static bool plain_copy(const d3d9_inst *m, int *from) {
    const d3d9_src *s = &m->src[0];
    *from = -1;
    if (m->op != D3D9_MOV || s->type != D3D9_REG_TEMP || s->mod || s->relative || m->dst.mods || m->predicated) return false;
    bool identity = true;
    for (unsigned c = 0; c < 4; c++)
        if ((m->dst.mask >> c & 1) && (s->swizzle >> (2 * c) & 3) != c) identity = false;
    if (identity) return true;
    /* one component copied into every lane of the mask (`mov oD1.xyz, r0.x`) */
    unsigned d = 0;
    while (d < 4 && !(m->dst.mask >> d & 1)) d++;
    *from = s->swizzle >> (2 * d) & 3;
    for (unsigned c = d; c < 4; c++)
        if ((m->dst.mask >> c & 1) && (s->swizzle >> (2 * c) & 3) != (unsigned)*from) return false;
    return true;
}

/* A replicated result (dp4, rcp...) or a componentwise operation: one value in any lanes. */
static bool replicable(const d3d9_inst *w) {
    const d3d9_op_info *info = hfx_d3d9_op_find(w->op);
    switch (w->op) {
    case D3D9_DP3: case D3D9_DP4: case D3D9_MOV: case D3D9_ADD: case D3D9_MUL: case D3D9_MAD: case D3D9_MIN:
    case D3D9_MAX: case D3D9_SLT: case D3D9_SGE: case D3D9_CMP: case D3D9_FRC: case D3D9_LRP: case D3D9_ABS:
        return true;
    default: return info && (info->flags & D3D9_OPF_SCALAR) && w->op != D3D9_SINCOS;
    }
}

/* Writer w of component `from` writes the components of `to` instead: a replicated result (dp4,
 * rcp...) just changes its mask; a componentwise one reads its sources' component for `from` in
 * each of them. */
static void move_component(d3d9_inst *w, unsigned from, unsigned to) {
    const d3d9_op_info *info = hfx_d3d9_op_find(w->op);
    bool replicated = w->op == D3D9_DP3 || w->op == D3D9_DP4 || w->op == D3D9_DP2ADD || (info->flags & D3D9_OPF_SCALAR);
    if (!replicated)
        for (unsigned i = 0; i < w->src_count; i++) {
            unsigned c = w->src[i].swizzle >> (2 * from) & 3;
            w->src[i].swizzle = (uint8_t)(c * 0x55u);
        }
    w->dst.mask = (uint8_t)to;
}

/* nrm rT.xyz, S whose value only a copy into output X reads: dp3 rT.x, S, S / rsq rT.x, rT.x /
 * mul X.xyz, rT.x, S where the nrm was, as fxc writes a normal into an output (3 slots, against
 * nrm's 3 and the mov). S must not be rT (the dp3 would overwrite what the mul reads). */
static bool expand_nrm(bc_gen *g, uint32_t w, uint32_t at) {
    d3d9_inst nrm = g->insts[w], mov = g->insts[at];
    const d3d9_src *S = &nrm.src[0];
    if (nrm.dst.type != D3D9_REG_TEMP || (S->type == D3D9_REG_TEMP && S->num == nrm.dst.num)) return false;
    if (!HFX_ARENA_GROW(g->c->arena, g->insts, g->inst_count, g->inst_cap, 64)) return false;
    memmove(&g->insts[at], &g->insts[at + 1], (g->inst_count - at - 1) * sizeof *g->insts); /* the mov goes */
    memmove(&g->insts[w + 3], &g->insts[w + 1], (g->inst_count - 1 - w - 1) * sizeof *g->insts);
    g->inst_count++;
    d3d9_src t = {.type = D3D9_REG_TEMP, .num = nrm.dst.num}; /* rT.x */
    d3d9_inst *dp = &g->insts[w], *rsq = dp + 1, *mul = dp + 2;
    *dp = nrm;
    dp->op = D3D9_DP3;
    dp->dst.mask = 1;
    dp->src[1] = *S;
    dp->src_count = 2;
    *rsq = nrm;
    rsq->op = D3D9_RSQ;
    rsq->dst.mask = 1;
    rsq->src[0] = t;
    rsq->src_count = 1;
    *mul = nrm;
    mul->op = D3D9_MUL;
    mul->dst = mov.dst;
    mul->src[0] = t;
    mul->src[1] = *S;
    mul->src_count = 2;
    return true;
}

/* The copy at `at` of temporary T into (to, num): the instructions back to `first` that computed
 * what it copies, found walking back (what they read of T computed there too: an accumulation
 * `mul T, ...` / `mad T, ..., T` is renamed whole). 0 writers: not possible. */
static uint32_t chain(const bc_gen *g, uint32_t at, unsigned T, unsigned mask, uint32_t *writers, uint32_t *first) {
    const d3d9_inst *m = &g->insts[at];
    unsigned to = m->dst.type, need = mask;
    uint32_t n = 0;
    for (uint32_t i = at; i-- > 0 && need;) {
        const d3d9_inst *in = &g->insts[i];
        if (flow(in)) return 0; /* writers in another block: not this copy's */
        bool w = writes(in, D3D9_REG_TEMP, T);
        unsigned r = reads_temp(g, in, T);
        if (r && to != D3D9_REG_TEMP) return 0; /* outputs are write only */
        if (w && ((in->dst.mask & ~mask) || !movable_writer(g, in, to) || n == 64)) return 0;
        if (w && !(in->dst.mask & need)) return 0; /* a dead write of components a later writer replaces: leave it */
        if (w) writers[n++] = i;
        if (w) need &= ~(unsigned)in->dst.mask;
        need |= r;
        /* the target must be left alone while the writers run (the first of them may read it:
         * it reads before it writes) */
        if ((writes(in, to, m->dst.num) && !w && (in->dst.mask & m->dst.mask)) || (reads(in, to, m->dst.num) && need))
            return 0;
        *first = i;
    }
    return need ? 0 : n;
}

static bool try_sink(bc_gen *g, uint32_t at) {
    d3d9_inst *m = &g->insts[at];
    int from;
    if (!plain_copy(m, &from) || m->dst.relative) return false;
    unsigned to = m->dst.type, T = m->src[0].num, mask = from >= 0 ? 1u << from : m->dst.mask;
    if (g->stage == D3D9_PS && g->model < D3D9_SM(3, 0) && to != D3D9_REG_TEMP) return false;
    if (to == D3D9_REG_TEMP && m->dst.num == T) return false;
    if (!dead_after(g, at, T, mask)) return false;
    unsigned target_mask = m->dst.mask;
    uint32_t writers[64], first = at, n = chain(g, at, T, mask, writers, &first);
    if (!n) return false;
    bool reread = false;
    for (uint32_t i = first; i < at; i++) reread |= reads_temp(g, &g->insts[i], T) != 0;
    if (g->insts[writers[0]].op == D3D9_NRM && to != D3D9_REG_TEMP)
        return n == 1 && from < 0 && expand_nrm(g, writers[0], at);
    if (from >= 0) {
        d3d9_inst *w = &g->insts[writers[0]];
        const d3d9_op_info *info = hfx_d3d9_op_find(w->op);
        if (n != 1 || reread || !info || (info->flags & (D3D9_OPF_TEX | D3D9_OPF_MATRIX)) || w->op == D3D9_DP2ADD) return false;
        if ((target_mask & (target_mask - 1)) && !replicable(w)) return false;
        move_component(w, (unsigned)from, target_mask);
    }
    for (uint32_t k = 0; k < n; k++) {
        g->insts[writers[k]].dst.type = (uint8_t)to;
        g->insts[writers[k]].dst.num = m->dst.num;
    }
    for (uint32_t i = first; i < at && reread; i++)
        for (unsigned k = 0; k < g->insts[i].src_count && k < 4; k++)
            if (g->insts[i].src[k].type == D3D9_REG_TEMP && g->insts[i].src[k].num == T) {
                g->insts[i].src[k].type = (uint8_t)to;
                g->insts[i].src[k].num = m->dst.num;
            }
    memmove(m, m + 1, (g->inst_count - at - 1) * sizeof *m);
    g->inst_count--;
    return true;
}

void hfx_bc_sink(bc_gen *g) {
    for (uint32_t i = 0; i < g->inst_count;)
        if (!try_sink(g, i)) i++;
}

/* Instructions whose temporaries nothing reads afterwards are dropped (a variant's unused
 * outputs, a select's unread side), over the shader's flow (bc_alloc.c's liveness). */
void hfx_bc_dead_code(bc_gen *g) {
    uint32_t n = g->inst_count;
    bool *drop = HFX_NEW_ARRAY(g->c->arena, bool, n ? n : 1);
    if (!drop || !hfx_bc_liveness(g, drop, NULL)) return;
    uint32_t k = 0;
    for (uint32_t i = 0; i < n; i++) if (!drop[i]) g->insts[k++] = g->insts[i];
    g->inst_count = k;
}

/* Parameters and def registers the remaining code never reads leave the table, and a parameter's
 * entry ends at the last register the code reads, as fxc's tables do: FNA's stock effects place
 * WorldInverseTranspose at c19, inside a float4x4 World at c16 whose fourth register no shader
 * reads; a table claiming c16..c19 for World would have the loader upload World's fourth row
 * over it (and a reader looking c19 up would find World). */
void hfx_bc_prune_constants(bc_gen *g) {
    bool read[BC_MAX_CONSTS] = {false}, relative = false;
    for (uint32_t i = 0; i < g->inst_count; i++)
        for (unsigned s = 0; s < g->insts[i].src_count; s++) {
            const d3d9_src *x = &g->insts[i].src[s];
            if (x->type == D3D9_REG_CONST && x->num < BC_MAX_CONSTS) read[x->num] = true;
            relative |= x->type == D3D9_REG_CONST && x->relative;
            if (x->type == D3D9_REG_SAMPLER && x->num < BC_MAX_CONSTS) read[x->num] |= false;
        }
    if (relative) return; /* c[a0.x + n] may read any of them */
    uint32_t k = 0;
    for (uint32_t i = 0; i < g->ctab_count; i++) {
        bc_ctab c = g->ctab[i];
        if (c.set != D3D9_RS_FLOAT4) { g->ctab[k++] = c; continue; }
        unsigned last = 0;
        bool used = false;
        for (unsigned r = c.reg; r < (unsigned)c.reg + c.count && r < BC_MAX_CONSTS; r++)
            if (read[r]) used = true, last = r;
        if (!used) continue;
        c.count = (uint16_t)(last - c.reg + 1);
        for (uint32_t j = 0; j < g->ctab_count; j++) { /* another parameter's registers start inside */
            const bc_ctab *o = &g->ctab[j];
            if (o->set == D3D9_RS_FLOAT4 && o->reg > c.reg && o->reg < c.reg + c.count) c.count = (uint16_t)(o->reg - c.reg);
        }
        g->ctab[k++] = c;
    }
    g->ctab_count = k;
    k = 0;
    for (uint32_t i = 0; i < g->def_count; i++)
        if (g->defs[i].num < BC_MAX_CONSTS && read[g->defs[i].num]) g->defs[k++] = g->defs[i];
    g->def_count = k;
}

/* D3D9's scalar instructions (rcp, rsq, exp, log, pow, sincos) must read their sources with a
 * replicate swizzle (`rsq r1.x, r1.x`); the reader and MojoShader refuse any other. After the
 * passes that renumber components, make each such source the replicate of the component its
 * first position names, the one these instructions read. */
void hfx_bc_replicate_scalars(bc_gen *g) {
    for (uint32_t i = 0; i < g->inst_count; i++)
        for (unsigned k = 0, n = hfx_d3d9_scalar_sources(&g->insts[i]); k < n; k++)
            g->insts[i].src[k].swizzle = (uint8_t)((g->insts[i].src[k].swizzle & 3u) * 0x55u);
}
