/* bc_alloc.c: liveness of the temporaries, component by component, over the shader's flow (if /
 * else / loop / rep / break as successors, solved to a fixpoint), and the final allocation: each
 * value a register's writes and reads carry is a segment; segments take the fewest registers,
 * a scalar or a vec2 moving into the free components of a register another value holds (its
 * writers' masks and its readers' swizzles remapped), as fxc packs them. */
#include "bytecode/bc_int.h"

/* Instructions whose operands must stay where the generator put them: their masks or swizzles
 * are fixed by the model (sincos .xy, nrm / crs .xyz, texld's coordinates without swizzle in
 * ps_2_0, m4x4's rows), or they must not write a register they read. */
static bool fixed_op(unsigned op) {
    switch (op) {
    case D3D9_SINCOS: case D3D9_NRM: case D3D9_CRS: case D3D9_LIT: case D3D9_SGN: case D3D9_TEXKILL:
    case D3D9_M4X4: case D3D9_M4X3: case D3D9_M3X4: case D3D9_M3X3: case D3D9_M3X2:
        return true;
    default: {
        const d3d9_op_info *info = hfx_d3d9_op_find(op);
        return info && (info->flags & D3D9_OPF_TEX);
    }
    }
}

/* The result is one value for every component of the mask (dp3, rcp...), not per component. */
static bool replicated(const d3d9_inst *in) {
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    return in->op == D3D9_DP3 || in->op == D3D9_DP4 || in->op == D3D9_DP2ADD || (info && (info->flags & D3D9_OPF_SCALAR));
}

static bool componentwise(const d3d9_inst *in) {
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    return in->has_dst && info && !(info->flags & (D3D9_OPF_FLOW | D3D9_OPF_MATRIX)) && !fixed_op(in->op) && !replicated(in);
}

/* The swizzle positions source k reads. */
unsigned hfx_bc_read_positions(const bc_gen *g, const d3d9_inst *in, unsigned k) {
    switch (in->op) {
    case D3D9_DP3: case D3D9_NRM: case D3D9_CRS: return 0x7;
    case D3D9_DP4: return 0xf;
    case D3D9_DP2ADD: return k < 2 ? 0x3 : 0x1;
    case D3D9_LIT: return 0xb;
    case D3D9_TEX:
        if (k == 0 && in->control == 0 && in->src[1].type == D3D9_REG_SAMPLER) /* texld: as many as the sampler's dimensions */
            for (uint32_t d = 0; d < g->dcl_count; d++)
                if (g->dcls[d].dst.type == D3D9_REG_SAMPLER && g->dcls[d].dst.num == in->src[1].num)
                    return g->dcls[d].sampler_type == 2 ? 0x3 : 0x7;
        return 0xf;
    default: break;
    }
    if (componentwise(in)) return in->dst.mask;
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    if ((info && (info->flags & D3D9_OPF_SCALAR)) || in->op == D3D9_IFC || in->op == D3D9_BREAKC) return 0x1;
    return 0xf;
}

static unsigned comps_of(uint8_t swizzle, unsigned positions) {
    unsigned m = 0;
    for (unsigned c = 0; c < 4; c++)
        if (positions >> c & 1) m |= 1u << (swizzle >> (2 * c) & 3);
    return m;
}

unsigned hfx_bc_read_comps(const bc_gen *g, const d3d9_inst *in, unsigned k) {
    return comps_of(in->src[k].swizzle, hfx_bc_read_positions(g, in, k));
}

static bool is_temp(unsigned type, unsigned num) { return type == D3D9_REG_TEMP && num < BC_MAX_TEMPS; }

/* The components of temporary registers instruction i writes for sure (a predicated write may not). */
static bool kills(const d3d9_inst *in) {
    return in->has_dst && in->op != D3D9_TEXKILL && !in->predicated && is_temp(in->dst.type, in->dst.num);
}

/* An instruction that may go when nothing reads what it writes. */
bool hfx_bc_droppable(const d3d9_inst *in) {
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    return in->has_dst && in->op != D3D9_TEXKILL && is_temp(in->dst.type, in->dst.num) && info &&
           !(info->flags & D3D9_OPF_FLOW);
}

/* A temporary's write whose mask may lose the components nothing reads. */
static bool shrinkable(const d3d9_inst *in) {
    return hfx_bc_droppable(in) && !in->predicated && (componentwise(in) || replicated(in)) && in->op != D3D9_SINCOS;
}

/* Successors of each instruction (n: the end of the shader): the block structure's edges. */
static void successors(const bc_gen *g, uint32_t (*succ)[2]) {
    uint32_t n = g->inst_count, depth = 0;
    uint32_t *stack = HFX_NEW_ARRAY(g->c->arena, uint32_t, n ? n : 1), *mid = HFX_NEW_ARRAY(g->c->arena, uint32_t, n ? n : 1);
    uint32_t *end = HFX_NEW_ARRAY(g->c->arena, uint32_t, n ? n : 1);
    for (uint32_t i = 0; i < n; i++) end[i] = mid[i] = UINT32_MAX;
    for (uint32_t i = 0; i < n; i++) { /* pair the openers with their else and their end */
        unsigned op = g->insts[i].op;
        if (op == D3D9_IF || op == D3D9_IFC || op == D3D9_LOOP || op == D3D9_REP) stack[depth++] = i;
        else if (op == D3D9_ELSE && depth) mid[stack[depth - 1]] = i;
        else if ((op == D3D9_ENDIF || op == D3D9_ENDLOOP || op == D3D9_ENDREP) && depth) {
            end[stack[depth - 1]] = i;
            end[i] = stack[--depth];
        }
    }
    depth = 0;
    uint32_t *loops = stack; /* reused: the loops around i */
    for (uint32_t i = 0; i < n; i++) {
        unsigned op = g->insts[i].op;
        succ[i][0] = i + 1;
        succ[i][1] = UINT32_MAX;
        if ((op == D3D9_IF || op == D3D9_IFC) && end[i] != UINT32_MAX) succ[i][1] = mid[i] != UINT32_MAX ? mid[i] + 1 : end[i];
        else if (op == D3D9_ELSE) {
            for (uint32_t j = i; j-- > 0;) /* the if this else belongs to */
                if (mid[j] == i) { succ[i][0] = end[j]; break; }
        } else if ((op == D3D9_LOOP || op == D3D9_REP) && end[i] != UINT32_MAX) {
            succ[i][1] = end[i] + 1;
            loops[depth++] = i;
        } else if ((op == D3D9_ENDLOOP || op == D3D9_ENDREP) && end[i] != UINT32_MAX) {
            succ[i][1] = end[i] + 1;
            if (depth) depth--;
        } else if ((op == D3D9_BREAK || op == D3D9_BREAKC || op == D3D9_BREAKP) && depth) {
            succ[i][1] = end[loops[depth - 1]] + 1;
            if (op == D3D9_BREAK) succ[i][0] = succ[i][1];
        } else if (op == D3D9_RET) succ[i][0] = n;
    }
}

/* Unread swizzle positions as bc_emit.c's src_of leaves them (the read value when they all
 * read one, else their own component; dot products repeat their last). One position read (rcp,
 * rsq, exp, log, pow, dp2add's addend: D3D9 wants a replicate swizzle there) is replicated, in
 * the dot mode too: otherwise an x read was written as the identity, `rsq r1.x, r1`, which the
 * reader and MojoShader refuse. */
uint8_t hfx_bc_tidy(uint8_t sw, unsigned positions, bool dot) {
    uint8_t c[4];
    int first = -1, last = -1;
    bool same = true, ident = true;
    for (unsigned p = 0; p < 4; p++) {
        c[p] = sw >> (2 * p) & 3;
        if (!(positions >> p & 1)) continue;
        if (first < 0) first = (int)p; else same &= c[p] == c[first];
        ident &= c[p] == p;
        last = (int)p;
    }
    if (first == last) dot = false;
    for (unsigned p = 0; p < 4 && first >= 0; p++)
        if (!(positions >> p & 1)) c[p] = dot ? (ident ? (uint8_t)p : c[last]) : same ? c[first] : (uint8_t)p;
    return (uint8_t)(c[0] | c[1] << 2 | c[2] << 4 | c[3] << 6);
}

uint32_t hfx_bc_temp_span(const bc_gen *g) {
    uint32_t span = 0;
    for (uint32_t i = 0; i < g->inst_count; i++) {
        const d3d9_inst *in = &g->insts[i];
        if (in->has_dst && is_temp(in->dst.type, in->dst.num) && in->dst.num >= span) span = in->dst.num + 1u;
        for (unsigned k = 0; k < in->src_count && k < 4; k++)
            if (is_temp(in->src[k].type, in->src[k].num) && in->src[k].num >= span) span = in->src[k].num + 1u;
    }
    return span ? span : 1;
}

/* What instruction x needs live before it, given o live after it (*gone: x's writes are all dead). */
static void step_back(const bc_gen *g, const d3d9_inst *x, const uint8_t *o, uint8_t *v, uint32_t span, bool *gone) {
    memcpy(v, o, span);
    *gone = hfx_bc_droppable(x) && !(o[x->dst.num] & x->dst.mask);
    if (*gone) return;
    d3d9_inst t = *x; /* what it reads when it writes only the components read later */
    if (shrinkable(x)) t.dst.mask &= o[x->dst.num];
    if (kills(x)) v[x->dst.num] &= (uint8_t)~x->dst.mask;
    for (unsigned k = 0; k < x->src_count; k++)
        if (is_temp(x->src[k].type, x->src[k].num)) v[x->src[k].num] |= (uint8_t)hfx_bc_read_comps(g, &t, k);
    if (x->op == D3D9_TEXKILL && is_temp(x->dst.type, x->dst.num)) v[x->dst.num] |= x->dst.mask;
}

/* live[i][r]: the components of rN read after instruction i before being written, on some path.
 * An instruction whose written components are all dead reads nothing (so a chain that only
 * feeds dead code dies whole); *dead marks those. A loop keeps what is live at its top alive
 * through its whole body (the back edge). Rows of span bytes: the temporaries the code uses. */
uint8_t *hfx_bc_liveness(bc_gen *g, bool *dead, uint32_t *span_out) {
    uint32_t n = g->inst_count, span = hfx_bc_temp_span(g);
    size_t rows = (size_t)(n + 1) * span;
    uint8_t *out = (uint8_t *)hfx_arena_alloc_raw(g->c->arena, rows), *in = (uint8_t *)hfx_arena_alloc_raw(g->c->arena, rows);
    uint8_t *o = (uint8_t *)hfx_arena_alloc_raw(g->c->arena, 2 * (size_t)span), *v = o ? o + span : NULL;
    uint32_t (*succ)[2] = (uint32_t (*)[2])hfx_arena_alloc_raw(g->c->arena, (size_t)(n ? n : 1) * sizeof *succ);
    if (!out || !in || !o || !succ) return NULL;
    memset(out, 0, rows);
    memset(in, 0, rows);
    successors(g, succ);
    for (bool changed = true; changed;) {
        changed = false;
        for (uint32_t i = n; i-- > 0;) {
            memcpy(o, &in[(size_t)(succ[i][0] <= n ? succ[i][0] : n) * span], span);
            if (succ[i][1] <= n)
                for (uint32_t r = 0; r < span; r++) o[r] |= in[(size_t)succ[i][1] * span + r];
            bool gone;
            step_back(g, &g->insts[i], o, v, span, &gone);
            if (dead) dead[i] = gone;
            if (memcmp(o, &out[(size_t)i * span], span) || memcmp(v, &in[(size_t)i * span], span)) changed = true;
            memcpy(&out[(size_t)i * span], o, span);
            memcpy(&in[(size_t)i * span], v, span);
        }
    }
    if (dead) /* writes trimmed to what is read (dead code's caller keeps the result) */
        for (uint32_t i = 0; i < n; i++) {
            d3d9_inst *x = &g->insts[i];
            unsigned keep = shrinkable(x) ? x->dst.mask & out[(size_t)i * span + x->dst.num] : x->dst.mask;
            if (dead[i] || !keep || keep == x->dst.mask) continue;
            x->dst.mask = (uint8_t)keep;
            if (componentwise(x))
                for (unsigned k = 0; k < x->src_count; k++) x->src[k].swizzle = hfx_bc_tidy(x->src[k].swizzle, keep, false);
        }
    for (uint32_t i = 0; i < n; i++) /* the back edges: what the top of a body needs stays live through it */
        if ((g->insts[i].op == D3D9_LOOP || g->insts[i].op == D3D9_REP) && succ[i][1] <= n)
            for (uint32_t j = i; j < succ[i][1] - 1 && j < n; j++)
                for (uint32_t r = 0; r < span; r++) out[(size_t)j * span + r] |= in[(size_t)(i + 1) * span + r];
    if (span_out) *span_out = span;
    return out;
}

/* --- segments and their registers --- */

typedef struct seg {
    uint32_t start, end;
    uint8_t mask;       /* components it writes or reads */
    bool fixed;         /* touched by an instruction whose operands cannot move (fixed_op) */
    bool no_alias;      /* starts at a fixed instruction: its register must be free there whole */
    uint8_t phys, map[4];
} seg;

typedef struct segs { seg *s; uint32_t n, cap; int32_t *dst, *src; } segs;

static void touch(bc_gen *g, segs *S, int32_t *open, uint32_t i, unsigned r, unsigned comps, int32_t *slot) {
    if (open[r] < 0) {
        if (!HFX_ARENA_GROW(g->c->arena, S->s, S->n, S->cap, 64)) return;
        memset(&S->s[S->n], 0, sizeof *S->s);
        S->s[S->n].start = i;
        S->s[S->n].no_alias = fixed_op(g->insts[i].op);
        open[r] = (int32_t)S->n++;
    }
    seg *s = &S->s[open[r]];
    s->end = i;
    s->mask |= (uint8_t)comps;
    s->fixed |= fixed_op(g->insts[i].op);
    *slot = open[r];
}

/* A segment opens at its register's first touch and closes where none of its components is live. */
static bool build_segments(bc_gen *g, const uint8_t *live, uint32_t span, segs *S) {
    uint32_t n = g->inst_count;
    int32_t *open = HFX_NEW_ARRAY(g->c->arena, int32_t, span);
    S->dst = HFX_NEW_ARRAY(g->c->arena, int32_t, n ? n : 1);
    S->src = HFX_NEW_ARRAY(g->c->arena, int32_t, (n ? n : 1) * 4);
    if (!open || !S->dst || !S->src) return false;
    for (uint32_t r = 0; r < span; r++) open[r] = -1;
    for (uint32_t i = 0; i < n; i++) {
        const d3d9_inst *in = &g->insts[i];
        S->dst[i] = -1;
        for (unsigned k = 0; k < 4; k++) S->src[i * 4 + k] = -1;
        for (unsigned k = 0; k < in->src_count && k < 4; k++)
            if (is_temp(in->src[k].type, in->src[k].num))
                touch(g, S, open, i, in->src[k].num, hfx_bc_read_comps(g, in, k), &S->src[i * 4 + k]);
        if (in->has_dst && is_temp(in->dst.type, in->dst.num)) touch(g, S, open, i, in->dst.num, in->dst.mask, &S->dst[i]);
        for (uint32_t r = 0; r < span; r++)
            if (open[r] >= 0) {
                if (live[(size_t)i * span + r]) S->s[open[r]].end = i;
                else open[r] = -1;
            }
    }
    return true;
}

/* A segment that starts as a copy of one ending there takes the copy's source components (the
 * mov becomes mov rN.x, rN.x, dropped afterwards). */
static bool coalesce(const bc_gen *g, const segs *S, seg *s, int32_t (*busy)[4]) {
    const d3d9_inst *in = &g->insts[s->start];
    if (in->op != D3D9_MOV || in->predicated || in->dst.mods || S->dst[s->start] != (int32_t)(s - S->s) ||
        in->src[0].mod || S->src[s->start * 4] < 0 || s->mask != in->dst.mask)
        return false;
    const seg *t = &S->s[S->src[s->start * 4]];
    if (t == s || t->end != s->start) return false;
    uint8_t want[4] = {0, 1, 2, 3};
    unsigned used = 0;
    for (unsigned c = 0; c < 4; c++) {
        if (!(s->mask >> c & 1)) continue;
        want[c] = t->map[in->src[0].swizzle >> (2 * c) & 3];
        if ((used >> want[c] & 1) || busy[t->phys][want[c]] > (int32_t)s->start || (s->fixed && want[c] != c)) return false;
        used |= 1u << want[c];
    }
    s->phys = t->phys;
    memcpy(s->map, want, 4);
    for (unsigned c = 0; c < 4; c++)
        if (s->mask >> c & 1) busy[s->phys][s->map[c]] = (int32_t)s->end;
    return true;
}

/* Registers for the segments, first fit by start: a fixed segment needs its own components free,
 * a movable one as many free components as it has. busy[p][c]: the last instruction using it. */
static uint32_t color(const bc_gen *g, segs *S) {
    int32_t (*busy)[4] = (int32_t (*)[4])hfx_arena_alloc_raw(g->c->arena, (size_t)(S->n ? S->n : 1) * sizeof *busy);
    uint32_t count = 0; /* at most one register a segment */
    if (!busy) return BC_MAX_TEMPS + 1;
    for (uint32_t k = 0; k < S->n; k++) {
        seg *s = &S->s[k];
        if (coalesce(g, S, s, busy)) continue;
        unsigned need = (unsigned)__builtin_popcount(s->mask);
        uint32_t p = 0;
        for (;; p++) {
            if (p == count) {
                if (count == S->n || count == BC_MAX_TEMPS) return BC_MAX_TEMPS + 1;
                for (unsigned c = 0; c < 4; c++) busy[count][c] = -1;
                count++;
            }
            unsigned free = 0, all = 0xf;
            for (unsigned c = 0; c < 4; c++) {
                if (busy[p][c] <= (int32_t)s->start) free |= 1u << c; /* read at i, written at i: one register */
                if (busy[p][c] >= (int32_t)s->start) all = 0;
            }
            if (s->no_alias && !all) continue;
            if ((s->mask & free) == s->mask) break; /* where it is */
            if (!s->fixed && (unsigned)__builtin_popcount(free) >= need) break;
        }
        s->phys = (uint8_t)p;
        unsigned free = 0;
        for (unsigned c = 0; c < 4; c++) if (busy[p][c] <= (int32_t)s->start) free |= 1u << c;
        bool stay = (s->mask & free) == s->mask;
        for (unsigned c = 0, to = 0; c < 4; c++) {
            s->map[c] = (uint8_t)c;
            if (stay || !(s->mask >> c & 1)) continue;
            while (!(free >> to & 1)) to++;
            s->map[c] = (uint8_t)to++;
        }
        for (unsigned c = 0; c < 4; c++)
            if (s->mask >> c & 1) busy[p][s->map[c]] = (int32_t)s->end;
    }
    return count;
}

static bool identity_map(const seg *s) {
    for (unsigned c = 0; c < 4; c++) if ((s->mask >> c & 1) && s->map[c] != c) return false;
    return true;
}

static void rewrite(const bc_gen *g, d3d9_inst *in, const segs *S, uint32_t i) {
    const seg *d = S->dst[i] >= 0 ? &S->s[S->dst[i]] : NULL;
    unsigned pos[4];
    for (unsigned k = 0; k < in->src_count && k < 4; k++) pos[k] = hfx_bc_read_positions(g, in, k);
    bool moved = d && !identity_map(d);
    if (moved) {
        if (componentwise(in))
            for (unsigned k = 0; k < in->src_count && k < 4; k++) { /* positions follow the written components */
                uint8_t old = in->src[k].swizzle, nw = old;
                for (unsigned c = 0; c < 4; c++)
                    if (in->dst.mask >> c & 1) {
                        unsigned to = d->map[c];
                        nw = (uint8_t)((nw & ~(3u << (2 * to))) | ((old >> (2 * c) & 3u) << (2 * to)));
                    }
                in->src[k].swizzle = nw;
            }
        unsigned mask = 0;
        for (unsigned c = 0; c < 4; c++) if (in->dst.mask >> c & 1) mask |= 1u << d->map[c];
        in->dst.mask = (uint8_t)mask;
        for (unsigned k = 0; k < in->src_count && k < 4; k++) pos[k] = hfx_bc_read_positions(g, in, k);
    }
    if (d) in->dst.num = d->phys;
    for (unsigned k = 0; k < in->src_count && k < 4; k++) {
        const seg *s = S->src[i * 4 + k] >= 0 ? &S->s[S->src[i * 4 + k]] : NULL;
        bool remap = s && !identity_map(s);
        if (s) in->src[k].num = s->phys;
        if (remap) {
            uint8_t sw = in->src[k].swizzle, nw = 0;
            for (unsigned p = 0; p < 4; p++) nw |= (uint8_t)(s->map[sw >> (2 * p) & 3] << (2 * p));
            in->src[k].swizzle = nw;
        }
        if (remap || (moved && componentwise(in))) in->src[k].swizzle = hfx_bc_tidy(in->src[k].swizzle, pos[k], !componentwise(in));
    }
}

/* mov rN.xy, rN.xy: what coalescing leaves. */
static bool self_copy(const d3d9_inst *in) {
    if (in->op != D3D9_MOV || in->predicated || in->dst.mods || in->src[0].mod || in->src[0].relative ||
        in->dst.type != D3D9_REG_TEMP || in->src[0].type != D3D9_REG_TEMP || in->dst.num != in->src[0].num)
        return false;
    for (unsigned c = 0; c < 4; c++)
        if ((in->dst.mask >> c & 1) && (in->src[0].swizzle >> (2 * c) & 3) != c) return false;
    return true;
}

/* Temporaries renumbered: segments packed into the fewest registers; how many. */
uint32_t hfx_bc_renumber(bc_gen *g) {
    uint32_t span;
    uint8_t *live = hfx_bc_liveness(g, NULL, &span);
    segs S = {0};
    if (!live || !build_segments(g, live, span, &S)) return BC_MAX_TEMPS + 1;
    uint32_t count = color(g, &S);
    if (count > BC_MAX_TEMPS) return count;
    uint32_t k = 0;
    for (uint32_t i = 0; i < g->inst_count; i++) {
        rewrite(g, &g->insts[i], &S, i);
        if (!self_copy(&g->insts[i])) g->insts[k++] = g->insts[i];
    }
    g->inst_count = k;
    return count;
}
