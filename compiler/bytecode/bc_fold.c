/* bc_fold.c: constants folded component by component after instruction selection, as fxc folds
 * them. Selection folds a value whose every component is a literal (bc_emit.c); this pass follows
 * the literals into single components of temporaries: XNA's lighting builds its three lights as
 * float3x3 rows that stay zero for the lights a variant leaves out, so dot(row, n) is 0 in one
 * component, step(0, 0) is 1, 0 * x is 0 and x + 0 * y is x. A component whose value is known
 * is not computed; its readers read a def register instead, and an instruction left with no
 * component to compute goes. Known values hold inside a block only (cleared at each if / loop /
 * break). */
#include <math.h>

#include "bytecode/bc_int.h"

typedef struct known { uint8_t mask; float v[4]; } known;

typedef struct fold {
    bc_gen *g;
    known *t;                      /* what each temporary's components hold at this point (span of them) */
    uint32_t span;                 /* temporaries the code uses */
    known (*src)[4];               /* per instruction: its sources' registers as they were read */
    uint8_t *res;                  /* per instruction: the components whose result is known */
    bool *del;
} fold;

static bool flow(const d3d9_inst *in) {
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    return info && (info->flags & D3D9_OPF_FLOW);
}

static bool is_temp(const d3d9_src *s) { return s->type == D3D9_REG_TEMP && s->num < BC_MAX_TEMPS && !s->relative; } /* below span */

/* Operations this pass evaluates or whose operands it may replace by literals. */
static bool lanewise(unsigned op) {
    switch (op) {
    case D3D9_MOV: case D3D9_ADD: case D3D9_MUL: case D3D9_MAD: case D3D9_MIN: case D3D9_MAX:
    case D3D9_SGE: case D3D9_SLT: case D3D9_CMP: case D3D9_FRC: return true;
    default: return false;
    }
}
static bool dotlike(unsigned op) {
    switch (op) {
    case D3D9_DP3: case D3D9_DP4: case D3D9_RCP: case D3D9_RSQ: case D3D9_EXP: case D3D9_LOG: case D3D9_POW:
        return true;
    default: return false;
    }
}
static bool eligible(const d3d9_inst *in) {
    return (lanewise(in->op) || dotlike(in->op)) && in->has_dst && !in->predicated && !in->dst.relative &&
           !(in->dst.mods & ~(D3D9_DMOD_SAT | D3D9_DMOD_PP)) && in->dst.shift == 0;
}

/* The register component position p of source k reads, with its modifier, when it is known. */
static bool lane(const fold *f, const d3d9_inst *in, unsigned k, unsigned p, float *out) {
    const d3d9_src *s = &in->src[k];
    unsigned c = s->swizzle >> (2 * p) & 3;
    float v;
    if (is_temp(s)) {
        if (!(f->t[s->num].mask >> c & 1)) return false;
        v = f->t[s->num].v[c];
    } else if (s->type == D3D9_REG_CONST && !s->relative) {
        uint32_t d = 0;
        while (d < f->g->def_count && f->g->defs[d].num != s->num) d++;
        if (d == f->g->def_count) return false;
        v = f->g->defs[d].v[c];
    } else return false;
    switch (s->mod) {
    case D3D9_SMOD_NONE: break;
    case D3D9_SMOD_NEG: v = -v; break;
    case D3D9_SMOD_ABS: v = v < 0 ? -v : v; break;
    case D3D9_SMOD_ABSNEG: v = v < 0 ? v : -v; break;
    default: return false;
    }
    *out = v;
    return true;
}

/* Source k is the literal z at every position of mask. */
static bool all_lanes(const fold *f, const d3d9_inst *in, unsigned k, unsigned mask, float z) {
    for (unsigned p = 0; p < 4; p++) {
        float v;
        if ((mask >> p & 1) && (!lane(f, in, k, p, &v) || v != z)) return false;
    }
    return true;
}

/* The product of positions p of sources a and b: both known, or either 0 (fxc folds 0 * x). */
static bool product(const fold *f, const d3d9_inst *in, unsigned a, unsigned b, unsigned p, float *out) {
    float x, y;
    bool kx = lane(f, in, a, p, &x), ky = lane(f, in, b, p, &y);
    if ((kx && x == 0) || (ky && y == 0)) { *out = 0; return true; }
    if (!kx || !ky) return false;
    *out = x * y;
    return true;
}

/* The result of lane p, when known. */
static bool evaluate(const fold *f, const d3d9_inst *in, unsigned p, float *out) {
    float a, b, c;
    switch (in->op) {
    case D3D9_MOV: return lane(f, in, 0, p, out);
    case D3D9_FRC: if (!lane(f, in, 0, p, &a)) return false; *out = a - floorf(a); return true;
    case D3D9_MUL: return product(f, in, 0, 1, p, out);
    case D3D9_MAD:
        if (!product(f, in, 0, 1, p, &a) || !lane(f, in, 2, p, &c)) return false;
        *out = a + c;
        return true;
    case D3D9_DP3: case D3D9_DP4: {
        float sum = 0;
        for (unsigned q = 0; q < (in->op == D3D9_DP3 ? 3u : 4u); q++) {
            if (!product(f, in, 0, 1, q, &a)) return false;
            sum += a;
        }
        *out = sum;
        return true;
    }
    case D3D9_CMP:
        if (!lane(f, in, 0, p, &a)) return false;
        return lane(f, in, a >= 0 ? 1 : 2, p, out);
    default: break;
    }
    if (in->src_count != 2 || !lanewise(in->op) || !lane(f, in, 0, p, &a) || !lane(f, in, 1, p, &b)) return false;
    switch (in->op) {
    case D3D9_ADD: *out = a + b; return true;
    case D3D9_MIN: *out = a < b ? a : b; return true;
    case D3D9_MAX: *out = a > b ? a : b; return true;
    case D3D9_SGE: *out = a >= b ? 1.0f : 0.0f; return true;
    case D3D9_SLT: *out = a < b ? 1.0f : 0.0f; return true;
    default: return false;
    }
}

/* x + 0 * y, x * 1, x + 0 on every written component: a mov of x; dp4 with 0 * w: dp3. */
static void simplify(const fold *f, d3d9_inst *in) {
    unsigned m = in->dst.mask;
    int keep = -1;
    if (in->op == D3D9_MAD) {
        bool zero = true;
        for (unsigned p = 0; p < 4 && zero; p++) {
            float v;
            zero = !(m >> p & 1) || (product(f, in, 0, 1, p, &v) && v == 0);
        }
        keep = zero ? 2 : -1;
    } else if (in->op == D3D9_MUL) keep = all_lanes(f, in, 1, m, 1) ? 0 : all_lanes(f, in, 0, m, 1) ? 1 : -1;
    else if (in->op == D3D9_ADD) keep = all_lanes(f, in, 1, m, 0) ? 0 : all_lanes(f, in, 0, m, 0) ? 1 : -1;
    else if (in->op == D3D9_DP4) { /* the w products 0 (a normal widened to float4 with 0): dp3 */
        float w;
        if (product(f, in, 0, 1, 3, &w) && w == 0) in->op = D3D9_DP3;
    }
    if (keep < 0 || in->predicated) return;
    in->op = D3D9_MOV;
    in->src[0] = in->src[keep];
    in->src_count = 1;
}

static bool self_copy(const d3d9_inst *in) {
    if (in->op != D3D9_MOV || in->predicated || in->dst.mods || in->src[0].mod || !is_temp(&in->src[0]) ||
        in->dst.type != D3D9_REG_TEMP || in->dst.num != in->src[0].num)
        return false;
    for (unsigned c = 0; c < 4; c++)
        if ((in->dst.mask >> c & 1) && (in->src[0].swizzle >> (2 * c) & 3) != c) return false;
    return true;
}

/* Forward: what every component holds; each instruction's known results, simplified forms. */
static void forward(fold *f) {
    bc_gen *g = f->g;
    for (uint32_t i = 0; i < g->inst_count; i++) {
        d3d9_inst *in = &g->insts[i];
        if (flow(in)) { memset(f->t, 0, f->span * sizeof *f->t); continue; }
        if (eligible(in)) simplify(f, in);
        for (unsigned k = 0; k < in->src_count && k < 4; k++)
            if (is_temp(&in->src[k])) f->src[i][k] = f->t[in->src[k].num];
        known r = {0};
        for (unsigned p = 0; p < 4 && eligible(in); p++)
            if ((in->dst.mask >> p & 1) && evaluate(f, in, dotlike(in->op) ? 0 : p, &r.v[p])) {
                if (in->dst.mods & D3D9_DMOD_SAT) r.v[p] = r.v[p] < 0 ? 0 : r.v[p] > 1 ? 1 : r.v[p];
                r.mask |= (uint8_t)(1u << p);
            }
        if (dotlike(in->op) && in->op != D3D9_DP3 && in->op != D3D9_DP4) r.mask = 0; /* rcp, exp...: not folded */
        f->res[i] = r.mask;
        f->del[i] = self_copy(in);
        if (!in->has_dst || in->op == D3D9_TEXKILL || in->dst.type != D3D9_REG_TEMP || in->dst.num >= BC_MAX_TEMPS) continue;
        known *t = &f->t[in->dst.num];
        for (unsigned p = 0; p < 4; p++)
            if (in->dst.mask >> p & 1) {
                t->mask &= (uint8_t)~(1u << p);
                if ((r.mask >> p & 1) && !in->predicated) { t->mask |= (uint8_t)(1u << p); t->v[p] = r.v[p]; }
            }
    }
}

/* Source k read as a def register holding its known values, unless the instruction would then
 * read two constant registers (vs_2_0's read port; fxc copies one into a temporary). */
static bool to_literal(fold *f, d3d9_inst *in, unsigned k, const known *kn, unsigned comps) {
    if ((comps & kn->mask) != comps || !comps) return false;
    for (unsigned j = 0; j < in->src_count; j++)
        if (j != k && in->src[j].type == D3D9_REG_CONST) return false;
    float v[4];
    unsigned first = (unsigned)__builtin_ctz(comps);
    for (unsigned p = 0; p < 4; p++) {
        unsigned c = in->src[k].swizzle >> (2 * p) & 3;
        v[p] = kn->v[comps >> c & 1 ? c : first];
    }
    bc_val lit = hfx_bc_const(f->g, v, 4);
    if (f->g->failed) return false;
    in->src[k].type = D3D9_REG_CONST;
    in->src[k].num = lit.num;
    in->src[k].swizzle = (uint8_t)(lit.sw[0] | lit.sw[1] << 2 | lit.sw[2] << 4 | lit.sw[3] << 6);
    return true;
}

/* Backward: a known component is dropped from its writer's mask when no reader still needs it in
 * the register (a reader that reads only known components reads a literal). */
static void backward(fold *f) {
    bc_gen *g = f->g;
    uint8_t *need = HFX_NEW_ARRAY(g->c->arena, uint8_t, f->span);
    if (!need) return;
    for (uint32_t i = g->inst_count; i-- > 0;) {
        d3d9_inst *in = &g->insts[i];
        if (f->del[i]) continue;
        if (flow(in)) { memset(need, 0xf, f->span); continue; }
        bool temp_dst = in->has_dst && in->op != D3D9_TEXKILL && in->dst.type == D3D9_REG_TEMP &&
                        in->dst.num < BC_MAX_TEMPS && !in->dst.relative;
        unsigned mask = in->dst.mask;
        if (temp_dst && eligible(in)) {
            unsigned keep = mask & ~(f->res[i] & ~(unsigned)need[in->dst.num]);
            need[in->dst.num] &= (uint8_t)~mask;
            if (!keep) { f->del[i] = true; continue; }
            if (keep != mask) {
                in->dst.mask = (uint8_t)keep;
                if (lanewise(in->op))
                    for (unsigned k = 0; k < in->src_count; k++) in->src[k].swizzle = hfx_bc_tidy(in->src[k].swizzle, keep, false);
            }
        } else if (temp_dst && !in->predicated) need[in->dst.num] &= (uint8_t)~mask;
        for (unsigned k = 0; k < in->src_count && k < 4; k++) {
            if (!is_temp(&in->src[k])) continue;
            unsigned comps = hfx_bc_read_comps(g, in, k), num = in->src[k].num;
            if (eligible(in) && to_literal(f, in, k, &f->src[i][k], comps)) continue;
            need[num] |= (uint8_t)comps;
        }
        if (in->op == D3D9_TEXKILL && in->dst.type == D3D9_REG_TEMP && in->dst.num < BC_MAX_TEMPS) need[in->dst.num] |= in->dst.mask;
    }
}

/* A reader's modifier over the copy's: what it reads of the copy's source (false: none). */
static bool compose(unsigned outer, unsigned inner, uint8_t *out) {
    static const uint8_t neg[] = {[D3D9_SMOD_NONE] = D3D9_SMOD_NEG, [D3D9_SMOD_NEG] = D3D9_SMOD_NONE,
                                  [D3D9_SMOD_ABS] = D3D9_SMOD_ABSNEG, [D3D9_SMOD_ABSNEG] = D3D9_SMOD_ABS};
    if (inner != D3D9_SMOD_NONE && inner != D3D9_SMOD_NEG && inner != D3D9_SMOD_ABS && inner != D3D9_SMOD_ABSNEG) return false;
    switch (outer) {
    case D3D9_SMOD_NONE: *out = (uint8_t)inner; return true;
    case D3D9_SMOD_NEG: *out = neg[inner]; return true;
    case D3D9_SMOD_ABS: *out = D3D9_SMOD_ABS; return true;
    case D3D9_SMOD_ABSNEG: *out = D3D9_SMOD_ABSNEG; return true;
    default: return false;
    }
}

/* Reader source s reads the copy's source instead; not when the reader already reads another
 * register of that file (the models' read ports: one c or v register an instruction in vs_2_0). */
static bool forward_read(const d3d9_inst *copy, d3d9_inst *rd, unsigned k) {
    const d3d9_src *from = &copy->src[0];
    for (unsigned j = 0; j < rd->src_count; j++)
        if (j != k && rd->src[j].type == from->type &&
            (rd->src[j].num != from->num || rd->src[j].relative || from->relative))
            return false;
    uint8_t mod;
    if (!compose(rd->src[k].mod, from->mod, &mod)) return false;
    uint8_t sw = 0;
    for (unsigned p = 0; p < 4; p++) sw |= (uint8_t)((from->swizzle >> (2 * (rd->src[k].swizzle >> (2 * p) & 3)) & 3) << (2 * p));
    d3d9_src nw = *from;
    nw.mod = mod;
    nw.swizzle = sw;
    rd->src[k] = nw;
    return true;
}

/* A copy `mov rT, X` of a constant or an input read before rT or X changes: its readers read X (the copy then dies):
 * `x *= y` on a parameter's value no longer moves the parameter into a temporary first. */
static void forward_copies(bc_gen *g) {
    for (uint32_t i = 0; i < g->inst_count; i++) {
        const d3d9_inst *m = &g->insts[i];
        if (m->op != D3D9_MOV || m->predicated || m->dst.mods || m->dst.type != D3D9_REG_TEMP || m->dst.relative ||
            m->dst.num >= BC_MAX_TEMPS || m->src[0].type == D3D9_REG_TEMP ||
            (m->src[0].relative && m->src[0].rel_type != D3D9_REG_ADDR))
            continue; /* a temporary's copy: the allocator coalesces it where its source ends */
        unsigned valid = m->dst.mask, T = m->dst.num;
        for (uint32_t j = i + 1; j < g->inst_count && valid; j++) {
            d3d9_inst *rd = &g->insts[j];
            if (flow(rd)) break;
            for (unsigned k = 0; k < rd->src_count && k < 4 && eligible(rd); k++)
                if (is_temp(&rd->src[k]) && rd->src[k].num == T && (hfx_bc_read_comps(g, rd, k) & ~valid) == 0)
                    forward_read(m, rd, k);
            if (!rd->has_dst || rd->op == D3D9_TEXKILL) continue;
            if (rd->dst.type == m->src[0].type && (rd->dst.num == m->src[0].num || rd->dst.relative)) break;
            if (rd->op == D3D9_MOVA && m->src[0].relative) break;
            if (rd->dst.type == D3D9_REG_TEMP && rd->dst.num == T) valid &= ~(unsigned)rd->dst.mask;
        }
    }
}

/* A temporary no instruction touches (a scratch register; the allocator packs it), or -1. */
static int unused_temp(const bc_gen *g) {
    uint32_t span = hfx_bc_temp_span(g);
    return span < BC_MAX_TEMPS ? (int)span : -1; /* renumbered later */
}

/* `mul rX.x, vI.c, K; mova a0.x, rX.x` with rX.x read by the mova only: one bone's index. */
static bool index_pair(const bc_gen *g, uint32_t at, uint32_t end) {
    const d3d9_inst *w = &g->insts[at], *m = &g->insts[at + 1];
    if (at + 1 >= end || w->op != D3D9_MUL || w->predicated || w->dst.mods || w->dst.type != D3D9_REG_TEMP ||
        w->dst.mask != 1 || w->src[0].type != D3D9_REG_INPUT || w->src[0].relative || w->src[0].mod ||
        w->src[1].type != D3D9_REG_CONST || w->src[1].relative || m->op != D3D9_MOVA || m->predicated ||
        m->dst.mask != 1 || m->src[0].type != D3D9_REG_TEMP || m->src[0].num != w->dst.num || m->src[0].mod ||
        (m->src[0].swizzle & 3) != 0)
        return false;
    for (uint32_t j = at + 2; j < g->inst_count; j++) {
        const d3d9_inst *in = &g->insts[j];
        if (flow(in)) return false;
        for (unsigned k = 0; k < in->src_count && k < 4; k++)
            if (in->src[k].type == D3D9_REG_TEMP && in->src[k].num == w->dst.num && (hfx_bc_read_comps(g, in, k) & 1)) return false;
        if (in->has_dst && in->dst.type == D3D9_REG_TEMP && in->dst.num == w->dst.num && (in->dst.mask & 1)) return true;
    }
    return true;
}

/* Bones' indices scaled and moved into a0 one by one (mul, mova per bone) become one mul and one
 * mova of up to four components, as fxc writes skinning: each bone's reads take its own a0
 * component (c[a0.y + n]). The indices come from one input register, scaled by one constant. */
void hfx_bc_merge_mova(bc_gen *g) {
    if (g->stage != D3D9_VS) return;
    uint32_t pairs[4], n = 0, end = g->inst_count;
    for (uint32_t i = 0; i < end; i++) {
        const d3d9_inst *in = &g->insts[i];
        if (flow(in)) { if (n) end = i; break; }
        if (in->op == D3D9_MOVA || (in->has_dst && in->dst.type == D3D9_REG_ADDR)) {
            if (i == 0 || !index_pair(g, i - 1, end) || n == 4) { if (n) end = i; break; }
            pairs[n++] = i - 1;
        }
    }
    if (n < 2) return;
    const d3d9_inst *first = &g->insts[pairs[0]];
    unsigned mask = 0;
    for (uint32_t k = 0; k < n; k++) {
        const d3d9_inst *w = &g->insts[pairs[k]];
        unsigned comp = w->src[0].swizzle & 3;
        if (w->src[0].num != first->src[0].num || w->src[1].num != first->src[1].num ||
            w->src[1].swizzle != first->src[1].swizzle || w->src[1].mod != first->src[1].mod || (mask >> comp & 1))
            return;
        mask |= 1u << comp;
    }
    int t = unused_temp(g);
    if (t < 0) return;
    uint32_t next = 1;
    for (uint32_t i = pairs[0]; i < g->inst_count; i++) { /* a0.x's readers: the lane of the bone before them */
        d3d9_inst *in = &g->insts[i];
        if (next < n && i == pairs[next]) next++;
        uint8_t lane = (uint8_t)(g->insts[pairs[next - 1]].src[0].swizzle & 3);
        for (unsigned k = 0; k < in->src_count && k < 4; k++)
            if (in->src[k].relative && in->src[k].rel_type == D3D9_REG_ADDR) in->src[k].rel_comp = lane;
        if (in->dst.relative && in->dst.rel_type == D3D9_REG_ADDR) in->dst.rel_comp = lane;
    }
    d3d9_inst *w = &g->insts[pairs[0]], *m = &g->insts[pairs[0] + 1];
    w->dst.num = (uint16_t)t;
    w->dst.mask = (uint8_t)mask;
    w->src[0].swizzle = 0xe4;
    w->src[1].swizzle = hfx_bc_tidy(w->src[1].swizzle, 1, false);
    m->dst.mask = (uint8_t)mask;
    m->src[0].num = (uint16_t)t;
    m->src[0].swizzle = 0xe4;
    uint32_t k = 0;
    for (uint32_t i = 0, p = 1; i < g->inst_count; i++) {
        if (p < n && i == pairs[p]) { i++; p++; continue; }
        g->insts[k++] = g->insts[i];
    }
    g->inst_count = k;
}

void hfx_bc_fold(bc_gen *g) {
    uint32_t n = g->inst_count;
    if (!n || g->failed) return;
    fold f = {.g = g, .span = hfx_bc_temp_span(g)};
    f.t = HFX_NEW_ARRAY(g->c->arena, known, f.span);
    f.src = (known (*)[4])hfx_arena_alloc_raw(g->c->arena, (size_t)n * sizeof *f.src);
    f.res = HFX_NEW_ARRAY(g->c->arena, uint8_t, n);
    f.del = HFX_NEW_ARRAY(g->c->arena, bool, n);
    if (!f.t || !f.src || !f.res || !f.del) return;
    memset(f.src, 0, (size_t)n * sizeof *f.src);
    forward(&f);
    backward(&f);
    uint32_t k = 0;
    for (uint32_t i = 0; i < n; i++) if (!f.del[i]) g->insts[k++] = g->insts[i];
    g->inst_count = k;
    forward_copies(g);
}
