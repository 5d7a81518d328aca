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

static bool writes(const d3d9_inst *in, unsigned type, unsigned num) {
    return in->has_dst && in->op != D3D9_TEXKILL && in->dst.type == type && in->dst.num == num;
}

/* Instructions whose destination must stay a temporary (or has a fixed mask). */
static bool movable_writer(const bc_gen *g, const d3d9_inst *in, unsigned to_type) {
    switch (in->op) {
    case D3D9_SINCOS: case D3D9_NRM: case D3D9_CRS: case D3D9_LIT: case D3D9_MOVA: case D3D9_TEXKILL:
    case D3D9_TEX: case D3D9_TEXLDL: case D3D9_TEXLDD: case D3D9_DSX: case D3D9_DSY:
        return to_type == D3D9_REG_TEMP && in->op != D3D9_MOVA && in->op != D3D9_TEXKILL && in->op != D3D9_SINCOS &&
               !(g->stage == D3D9_PS && g->model < D3D9_SM(3, 0) && (in->op == D3D9_TEX)) ;
    default: return in->has_dst && !in->dst.relative && !in->predicated;
    }
}

/* The temporary's components in mask are not read after instruction at (before being rewritten). */
static bool dead_after(const bc_gen *g, uint32_t at, unsigned num, unsigned mask) {
    for (uint32_t i = at + 1; i < g->inst_count; i++) {
        const d3d9_inst *in = &g->insts[i];
        if (reads(in, D3D9_REG_TEMP, num)) return false;
        if (writes(in, D3D9_REG_TEMP, num)) {
            mask &= ~(unsigned)in->dst.mask;
            if (!mask) return true;
        }
        if (hfx_d3d9_op_find(in->op)->flags & D3D9_OPF_FLOW) return false; /* the value may flow elsewhere */
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
    unsigned d = 0;
    while (d < 4 && !(m->dst.mask >> d & 1)) d++;
    if (m->dst.mask != 1u << d) return false;
    *from = s->swizzle >> (2 * d) & 3;
    return true;
}

/* Writer w of component `from` writes component `to` instead: a replicated result (dp4, rcp...)
 * just changes its mask; a componentwise one reads its sources' component for `to` too. */
static void move_component(d3d9_inst *w, unsigned from, unsigned to) {
    const d3d9_op_info *info = hfx_d3d9_op_find(w->op);
    bool replicated = w->op == D3D9_DP3 || w->op == D3D9_DP4 || w->op == D3D9_DP2ADD || (info->flags & D3D9_OPF_SCALAR);
    if (!replicated)
        for (unsigned i = 0; i < w->src_count; i++) {
            unsigned c = w->src[i].swizzle >> (2 * from) & 3;
            w->src[i].swizzle = (uint8_t)(c * 0x55u);
        }
    w->dst.mask = (uint8_t)(1u << to);
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
    uint32_t writers[64], n = 0;
    unsigned remaining = mask;
    for (uint32_t i = at; i-- > 0 && remaining;) {
        d3d9_inst *in = &g->insts[i];
        if (hfx_d3d9_op_find(in->op)->flags & D3D9_OPF_FLOW) return false; /* writers in this block only */
        bool w = writes(in, D3D9_REG_TEMP, T);
        if (reads(in, D3D9_REG_TEMP, T)) return false;
        /* the target must be left alone while the writers run (the first writer may read it:
         * it reads before it writes) */
        bool completes = w && !(remaining & ~(unsigned)in->dst.mask);
        if ((writes(in, to, m->dst.num) && !w && (in->dst.mask & target_mask)) || (reads(in, to, m->dst.num) && !completes))
            return false;
        if (!w) continue;
        if ((in->dst.mask & ~mask) || !movable_writer(g, in, to) || n == 64) return false;
        if (in->dst.mask & remaining) writers[n++] = i;
        else return false; /* a dead write of components a later writer replaces: leave it */
        remaining &= ~(unsigned)in->dst.mask;
    }
    if (remaining || !n || (from >= 0 && n != 1)) return false;
    if (from >= 0) {
        const d3d9_op_info *info = hfx_d3d9_op_find(g->insts[writers[0]].op);
        if (!info || (info->flags & (D3D9_OPF_TEX | D3D9_OPF_MATRIX)) || g->insts[writers[0]].op == D3D9_DP2ADD) return false;
        move_component(&g->insts[writers[0]], (unsigned)from, __builtin_ctz(target_mask));
    }
    for (uint32_t k = 0; k < n; k++) {
        g->insts[writers[k]].dst.type = (uint8_t)to;
        g->insts[writers[k]].dst.num = m->dst.num;
    }
    memmove(m, m + 1, (g->inst_count - at - 1) * sizeof *m);
    g->inst_count--;
    return true;
}

void hfx_bc_sink(bc_gen *g) {
    for (uint32_t i = 0; i < g->inst_count;)
        if (!try_sink(g, i)) i++;
}


/* Temporaries renumbered by the values they hold: a register's value ends where none of its
 * components is read again (backward liveness; the code has no loops), the next write starts
 * another; values are then given the fewest registers, first come first served. */
uint32_t hfx_bc_renumber(bc_gen *g) {
    uint32_t n = g->inst_count;
    uint8_t (*live_after)[BC_MAX_TEMPS] = (uint8_t (*)[BC_MAX_TEMPS])hfx_arena_alloc_raw(g->c->arena, (size_t)(n ? n : 1) * BC_MAX_TEMPS);
    unsigned live[BC_MAX_TEMPS] = {0};
    if (g->has_flow) hfx_bc_live(g, live_after);
    for (uint32_t i = g->has_flow ? 0 : n; i-- > 0;) {
        const d3d9_inst *in = &g->insts[i];
        for (unsigned r = 0; r < BC_MAX_TEMPS; r++) live_after[i][r] = (uint8_t)live[r];
        if (writes(in, D3D9_REG_TEMP, in->dst.num) && in->dst.type == D3D9_REG_TEMP && in->dst.num < BC_MAX_TEMPS && !in->predicated)
            live[in->dst.num] &= ~(unsigned)in->dst.mask;
        for (unsigned k = 0; k < in->src_count; k++)
            if (in->src[k].type == D3D9_REG_TEMP && in->src[k].num < BC_MAX_TEMPS) live[in->src[k].num] |= hfx_bc_read_comps(in, &in->src[k]);
        if (in->op == D3D9_TEXKILL && in->dst.type == D3D9_REG_TEMP && in->dst.num < BC_MAX_TEMPS) live[in->dst.num] |= 0xf;
    }
    enum { MAX_SEGS = 4096 };
    int32_t open[BC_MAX_TEMPS];
    for (unsigned r = 0; r < BC_MAX_TEMPS; r++) open[r] = -1;
    int32_t *seg_start = HFX_NEW_ARRAY(g->c->arena, int32_t, MAX_SEGS), *seg_end = HFX_NEW_ARRAY(g->c->arena, int32_t, MAX_SEGS);
    int32_t *dst_seg = HFX_NEW_ARRAY(g->c->arena, int32_t, n ? n : 1), *src_seg = HFX_NEW_ARRAY(g->c->arena, int32_t, (n ? n : 1) * 4);
    uint32_t segs = 0, held[BC_MAX_TEMPS] = {0};
    for (uint32_t i = 0; i < n; i++) {
        const d3d9_inst *in = &g->insts[i];
        if (g->has_flow && hfx_bc_hold_segments(g, i, live_after, open, held, seg_start, seg_end, &segs, MAX_SEGS))
            return BC_MAX_TEMPS + 1;
        dst_seg[i] = -1;
        for (unsigned k = 0; k < 4; k++) src_seg[i * 4 + k] = -1;
        for (unsigned r = 0; r < BC_MAX_TEMPS; r++) {
            bool dst = in->has_dst && in->dst.type == D3D9_REG_TEMP && in->dst.num == r;
            bool src = false;
            for (unsigned k = 0; k < in->src_count; k++) src |= in->src[k].type == D3D9_REG_TEMP && in->src[k].num == r;
            if (!dst && !src) continue;
            if (open[r] < 0) {
                if (segs == MAX_SEGS) return BC_MAX_TEMPS + 1;
                open[r] = (int32_t)segs;
                seg_start[segs] = (int32_t)i;
                segs++;
            }
            if (seg_end[open[r]] < (int32_t)i) seg_end[open[r]] = (int32_t)i;
            if (dst) dst_seg[i] = open[r];
            for (unsigned k = 0; k < in->src_count; k++)
                if (in->src[k].type == D3D9_REG_TEMP && in->src[k].num == r) src_seg[i * 4 + k] = open[r];
            if (!live_after[i][r] && i >= held[r]) open[r] = -1;
        }
    }
    int32_t *color = HFX_NEW_ARRAY(g->c->arena, int32_t, segs ? segs : 1);
    int32_t busy_until[BC_MAX_TEMPS];
    uint32_t count = 0;
    for (uint32_t s = 0; s < segs; s++) { /* segments are numbered by start */
        unsigned c = 0;
        while (c < count && busy_until[c] > seg_start[s]) c++; /* read at i, written at i: one register */
        if (c == count) {
            if (count == BC_MAX_TEMPS) return BC_MAX_TEMPS + 1;
            count++;
        }
        color[s] = (int32_t)c;
        busy_until[c] = seg_end[s];
    }
    for (uint32_t i = 0; i < n; i++) {
        d3d9_inst *in = &g->insts[i];
        if (dst_seg[i] >= 0) in->dst.num = (uint16_t)color[dst_seg[i]];
        for (unsigned k = 0; k < in->src_count; k++)
            if (src_seg[i * 4 + k] >= 0) in->src[k].num = (uint16_t)color[src_seg[i * 4 + k]];
    }
    return count;
}

/* The source components an instruction reads (componentwise: those its mask writes). */
unsigned hfx_bc_read_comps(const d3d9_inst *in, const d3d9_src *s) {
    unsigned mask = 0;
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    bool componentwise = in->has_dst && info && !(info->flags & (D3D9_OPF_TEX | D3D9_OPF_SCALAR | D3D9_OPF_MATRIX)) &&
                         in->op != D3D9_DP3 && in->op != D3D9_DP4 && in->op != D3D9_DP2ADD && in->op != D3D9_NRM &&
                         in->op != D3D9_CRS && in->op != D3D9_SINCOS && in->op != D3D9_LIT && in->op != D3D9_TEXKILL;
    for (unsigned c = 0; c < 4; c++)
        if (!componentwise || (in->dst.mask >> c & 1)) mask |= 1u << (s->swizzle >> (2 * c) & 3);
    return mask;
}

/* Instructions whose temporaries nothing reads afterwards are dropped (a variant's unused
 * outputs, a select's unread side); the code has no loops, so one walk back suffices. */
void hfx_bc_dead_code(bc_gen *g) {
    if (g->has_flow) { hfx_bc_dead_code_flow(g); return; }
    unsigned live[BC_MAX_TEMPS] = {0};
    uint32_t n = g->inst_count;
    bool *drop = HFX_NEW_ARRAY(g->c->arena, bool, n ? n : 1);
    for (uint32_t i = n; i-- > 0;) {
        d3d9_inst *in = &g->insts[i];
        bool temp = in->has_dst && in->op != D3D9_TEXKILL && in->dst.type == D3D9_REG_TEMP && in->dst.num < BC_MAX_TEMPS;
        if (temp && !(live[in->dst.num] & in->dst.mask) && !(hfx_d3d9_op_find(in->op)->flags & D3D9_OPF_FLOW)) {
            drop[i] = true;
            continue;
        }
        if (temp && !in->predicated) live[in->dst.num] &= ~(unsigned)in->dst.mask;
        for (unsigned k = 0; k < in->src_count; k++)
            if (in->src[k].type == D3D9_REG_TEMP && in->src[k].num < BC_MAX_TEMPS) live[in->src[k].num] |= hfx_bc_read_comps(in, &in->src[k]);
        if (in->op == D3D9_TEXKILL && in->dst.type == D3D9_REG_TEMP && in->dst.num < BC_MAX_TEMPS) live[in->dst.num] |= 0xf;
    }
    uint32_t k = 0;
    for (uint32_t i = 0; i < n; i++) if (!drop[i]) g->insts[k++] = g->insts[i];
    g->inst_count = k;
}

/* Parameters and def registers the remaining code never reads leave the table. */
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
        const bc_ctab *c = &g->ctab[i];
        bool used = c->set != D3D9_RS_FLOAT4;
        for (unsigned r = c->reg; r < (unsigned)c->reg + c->count && r < BC_MAX_CONSTS && !used; r++) used = read[r];
        if (used) g->ctab[k++] = *c;
    }
    g->ctab_count = k;
    k = 0;
    for (uint32_t i = 0; i < g->def_count; i++)
        if (g->defs[i].num < BC_MAX_CONSTS && read[g->defs[i].num]) g->defs[k++] = g->defs[i];
    g->def_count = k;
}
