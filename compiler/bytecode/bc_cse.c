/* bc_cse.c: values computed twice are computed once, as fxc does. The generator writes each
 * expression where it appears: `sin(time * 3 + 10)` three times in one shader is three range
 * reductions and three sincos (8 slots each in ps_2_0), `float2(positions[i], 0)` written twice
 * per tap of a blur is two pairs of movs, and an if whose two sides compute the same colour
 * computes it twice before the cmp that picks one. Inside each block, every component of every
 * temporary is given a value number: an instruction's result on one component is known by its
 * operation and the value numbers of what it reads there (its whole operand for a dot product,
 * rcp..., sincos, texld). A reader of a temporary whose components hold values another temporary
 * computed first and still holds reads that one instead (the later computation then goes with
 * the dead code), through a copy with a modifier its source under both (`mov r1, -r0` read as
 * -r0), and values a constant or an input holds straight from that register (literals from one
 * def), the read ports allowing; an instruction writing into a register the values it already
 * holds goes at once; a copy of a constant or an input is that value (a copy of a temporary
 * stays a value of its own, which the allocator joins to its source); `cmp d, c, a, a` is a mov
 * of a. The same operations on the same values give the same bits: only the count changes. */
#include "bytecode/bc_int.h"

enum { K_NONE, K_LANEWISE, K_REPLICATED, K_PER_LANE };
enum { OP_LEAF = 0xffff, OP_FRESH = 0xfffe };

/* What one component's value is made of: the operation, the lane for per-lane results (nrm's y,
 * sincos's sin), modifiers, and the value numbers it reads (v[source][position]). */
typedef struct vkey {
    uint16_t op;
    uint8_t control, lane, dmods;
    int8_t shift;
    uint8_t smod[4];
    uint8_t pad[2];
    uint32_t v[4][4];
} vkey;

/* A temporary component that held a value, in the order they took it (next: the following one,
 * 0 none); it holds it still while vn says so. */
typedef struct holder { uint16_t reg; uint8_t comp; uint32_t next; } holder;
typedef struct chain { uint32_t first, last; } chain;

typedef struct cse {
    bc_gen *g;
    uint32_t span;
    uint32_t *vn;                       /* span * 4: each temporary component's value (0: not yet known) */
    vkey *keys; uint32_t nkeys, keys_cap; /* value number i + 1 is keys[i] */
    chain *chains; uint32_t chains_cap;   /* per value: its holders */
    holder *holders; uint32_t nholders, holders_cap; /* holders[i - 1] */
    uint32_t *slots, slot_cap;          /* hash table of keys: index + 1, 0 empty */
    int16_t def_of[BC_MAX_CONSTS];      /* c register -> g->defs index, or -1 */
    bool *del;
    bool failed, changed;
} cse;

static int kind(unsigned op) {
    switch (op) {
    case D3D9_MOV: case D3D9_ADD: case D3D9_MUL: case D3D9_MAD: case D3D9_MIN: case D3D9_MAX: case D3D9_SLT:
    case D3D9_SGE: case D3D9_CMP: case D3D9_FRC: case D3D9_LRP: case D3D9_ABS:
        return K_LANEWISE;
    case D3D9_DP3: case D3D9_DP4: case D3D9_DP2ADD: case D3D9_RCP: case D3D9_RSQ: case D3D9_EXP: case D3D9_LOG:
    case D3D9_POW: case D3D9_EXPP: case D3D9_LOGP:
        return K_REPLICATED;
    case D3D9_SINCOS: case D3D9_NRM: case D3D9_CRS: case D3D9_TEX: case D3D9_LIT: case D3D9_DST:
        return K_PER_LANE;
    default: return K_NONE;
    }
}

static bool flow(const d3d9_inst *in) {
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    return !info || (info->flags & D3D9_OPF_FLOW);
}

static bool temp_src(const d3d9_src *s) { return s->type == D3D9_REG_TEMP && !s->relative; }

/* An instruction whose result this pass numbers and whose sources it may redirect. */
static bool numbered(const d3d9_inst *in) {
    if (kind(in->op) == K_NONE || !in->has_dst || in->predicated || in->dst.relative || in->dst.type != D3D9_REG_TEMP)
        return false;
    for (unsigned k = 0; k < in->src_count && k < 4; k++)
        if (in->src[k].relative) return false;
    return true;
}

static uint32_t hash_key(const vkey *k) {
    const unsigned char *b = (const unsigned char *)k;
    uint32_t h = 2166136261u;
    for (size_t i = 0; i < sizeof *k; i++) h = (h ^ b[i]) * 16777619u;
    return h;
}

/* A new value number for key k (kept for lookups when hashed). */
static uint32_t add_value(cse *c, const vkey *k) {
    if (!HFX_ARENA_GROW(c->g->c->arena, c->keys, c->nkeys, c->keys_cap, 256) ||
        !HFX_ARENA_GROW(c->g->c->arena, c->chains, c->nkeys, c->chains_cap, 256)) {
        c->failed = true;
        return 0;
    }
    c->keys[c->nkeys] = *k;
    c->chains[c->nkeys] = (chain){0, 0};
    return ++c->nkeys;
}

static bool rehash(cse *c) {
    uint32_t cap = c->slot_cap ? c->slot_cap * 2 : 1024;
    uint32_t *s = HFX_NEW_ARRAY(c->g->c->arena, uint32_t, cap);
    if (!s) return false;
    for (uint32_t i = 0; i < c->nkeys; i++) {
        if (c->keys[i].op == OP_FRESH) continue;
        uint32_t h = hash_key(&c->keys[i]) & (cap - 1);
        while (s[h]) h = (h + 1) & (cap - 1);
        s[h] = i + 1;
    }
    c->slots = s;
    c->slot_cap = cap;
    return true;
}

/* The value number of key k: the one it already has, or a new one. */
static uint32_t value_of(cse *c, const vkey *k) {
    if (c->failed || ((c->nkeys + 1) * 2 > c->slot_cap && !rehash(c))) { c->failed = true; return 0; }
    uint32_t h = hash_key(k) & (c->slot_cap - 1);
    for (; c->slots[h]; h = (h + 1) & (c->slot_cap - 1))
        if (memcmp(&c->keys[c->slots[h] - 1], k, sizeof *k) == 0) return c->slots[h];
    uint32_t id = add_value(c, k);
    if (id) c->slots[h] = id;
    return id;
}

/* A value nothing else has (a temporary's component written before this block). */
static uint32_t fresh(cse *c) {
    vkey k;
    memset(&k, 0, sizeof k);
    k.op = OP_FRESH;
    return add_value(c, &k);
}

static void add_holder(cse *c, uint32_t v, unsigned reg, unsigned comp) {
    if (!HFX_ARENA_GROW(c->g->c->arena, c->holders, c->nholders, c->holders_cap, 256)) { c->failed = true; return; }
    c->holders[c->nholders++] = (holder){(uint16_t)reg, (uint8_t)comp, 0};
    chain *ch = &c->chains[v - 1];
    if (ch->last) c->holders[ch->last - 1].next = c->nholders; else ch->first = c->nholders;
    ch->last = c->nholders;
}

static uint32_t temp_value(cse *c, unsigned reg, unsigned comp) {
    uint32_t *v = &c->vn[(size_t)reg * 4 + comp];
    if (!*v && (*v = fresh(c)) != 0) add_holder(c, *v, reg, comp); /* its first holder: it stays where it is */
    return *v;
}

/* The value source s reads at position p (its modifier apart). */
static uint32_t operand(cse *c, const d3d9_src *s, unsigned p) {
    unsigned comp = s->swizzle >> (2 * p) & 3;
    if (s->type == D3D9_REG_TEMP && s->num < c->span) return temp_value(c, s->num, comp);
    vkey k;
    memset(&k, 0, sizeof k);
    k.op = OP_LEAF;
    if (s->type == D3D9_REG_CONST && s->num < BC_MAX_CONSTS && c->def_of[s->num] >= 0) {
        k.v[0][0] = 1; /* a def: by its bits, wherever it sits */
        memcpy(&k.v[0][1], &c->g->defs[c->def_of[s->num]].v[comp], sizeof(float));
    } else {
        k.v[0][0] = 2;
        k.v[0][1] = (uint32_t)s->type << 24 | (uint32_t)s->num << 2 | comp;
    }
    return value_of(c, &k);
}

/* The value instruction `in` writes on component p. */
static uint32_t result(cse *c, const d3d9_inst *in, unsigned p) {
    int kd = kind(in->op);
    if (in->op == D3D9_MOV && !in->dst.mods && !in->dst.shift && in->src[0].mod == D3D9_SMOD_NONE &&
        in->src[0].type != D3D9_REG_TEMP)
        return operand(c, &in->src[0], p); /* a copy of a constant or an input holds its value (a copy
                                            * of a temporary stays a value of its own: read through,
                                            * it would keep the allocator from joining the two) */
    vkey k;
    memset(&k, 0, sizeof k);
    k.op = in->op;
    k.control = in->control;
    k.dmods = in->dst.mods;
    k.shift = in->dst.shift;
    k.lane = kd == K_LANEWISE ? 0xfe : kd == K_REPLICATED ? 0xff : (uint8_t)p;
    for (unsigned s = 0; s < in->src_count && s < 4; s++) {
        k.smod[s] = in->src[s].mod;
        if (kd == K_LANEWISE) { k.v[s][0] = operand(c, &in->src[s], p); continue; }
        unsigned pos = hfx_bc_read_positions(c->g, in, s);
        for (unsigned q = 0; q < 4; q++)
            if (pos >> q & 1) k.v[s][q] = operand(c, &in->src[s], q);
    }
    return value_of(c, &k);
}

static bool holds(const cse *c, unsigned reg, unsigned comp, uint32_t v) { return c->vn[(size_t)reg * 4 + comp] == v; }

/* The component of reg holding v (its own comp first), or -1. */
static int comp_holding(const cse *c, unsigned reg, unsigned comp, uint32_t v) {
    if (holds(c, reg, comp, v)) return (int)comp;
    for (unsigned q = 0; q < 4; q++) if (holds(c, reg, q, v)) return (int)q;
    return -1;
}

/* The first temporary to hold val[first position] that holds, on every position of pos, val[p]
 * (the components in *sw, each lane's own first), when it is not `self`. */
static int older_holder(const cse *c, const uint32_t *val, uint8_t swizzle, unsigned pos, int self, uint8_t *sw) {
    uint32_t v0 = val[__builtin_ctz(pos)];
    unsigned walked = 0;
    for (uint32_t h = c->chains[v0 - 1].first; h && walked < 16; h = c->holders[h - 1].next, walked++) {
        unsigned reg = c->holders[h - 1].reg;
        if (!holds(c, reg, c->holders[h - 1].comp, v0)) continue; /* it held it once */
        if ((int)reg == self) return -1; /* the source's own register is the oldest that holds it */
        uint8_t nw = swizzle;
        bool all = true;
        for (unsigned p = 0; p < 4 && all; p++) {
            if (!(pos >> p & 1)) continue;
            int to = comp_holding(c, reg, swizzle >> (2 * p) & 3, val[p]);
            all = to >= 0;
            if (all) nw = (uint8_t)((nw & ~(3u << (2 * p))) | (unsigned)to << (2 * p));
        }
        if (all) { *sw = nw; return (int)reg; }
    }
    return -1;
}

/* v as modifier *m on value u, returned (a copy with a modifier, `mov r1, -r0`, is -r0). */
static uint32_t base_of(const cse *c, uint32_t v, uint8_t *m) {
    const vkey *k = &c->keys[v - 1];
    *m = D3D9_SMOD_NONE;
    if (k->op != D3D9_MOV || k->lane != 0xfe || k->dmods || k->shift ||
        (k->smod[0] != D3D9_SMOD_NEG && k->smod[0] != D3D9_SMOD_ABS && k->smod[0] != D3D9_SMOD_ABSNEG))
        return v;
    *m = k->smod[0];
    return k->v[0][0];
}

/* outer applied over inner (both of none, neg, abs, -abs). */
static uint8_t compose(unsigned outer, unsigned inner) {
    static const uint8_t neg[] = {[D3D9_SMOD_NONE] = D3D9_SMOD_NEG, [D3D9_SMOD_NEG] = D3D9_SMOD_NONE,
                                  [D3D9_SMOD_ABS] = D3D9_SMOD_ABSNEG, [D3D9_SMOD_ABSNEG] = D3D9_SMOD_ABS};
    if (outer == D3D9_SMOD_NONE) return (uint8_t)inner;
    if (outer == D3D9_SMOD_NEG) return neg[inner];
    return (uint8_t)outer; /* |x| and -|x| of x, -x, |x| or -|x| */
}

static bool plain_mod(unsigned m) {
    return m == D3D9_SMOD_NONE || m == D3D9_SMOD_NEG || m == D3D9_SMOD_ABS || m == D3D9_SMOD_ABSNEG;
}

/* No other source of `in` reads a different register of the file `type` (the read ports). */
static bool port_free(const d3d9_inst *in, unsigned k, unsigned type, unsigned num) {
    for (unsigned j = 0; j < in->src_count && j < 4; j++)
        if (j != k && in->src[j].type == type && (in->src[j].num != num || in->src[j].relative)) return false;
    return true;
}

/* Leaves u[] (a constant's, an input's or a def's components) read straight from their register:
 * the source rewritten, or false. */
static bool read_leaves(cse *c, d3d9_inst *in, unsigned k, const uint32_t *u, unsigned pos, uint8_t mod) {
    const vkey *first = &c->keys[u[__builtin_ctz(pos)] - 1];
    if (first->op != OP_LEAF) return false;
    float lit[4];
    unsigned n = 0, lane[4] = {0};
    for (unsigned p = 0; p < 4; p++) {
        if (!(pos >> p & 1)) continue;
        const vkey *l = &c->keys[u[p] - 1];
        if (l->op != OP_LEAF || l->v[0][0] != first->v[0][0]) return false;
        if (l->v[0][0] == 2) {
            if ((l->v[0][1] >> 2) != (first->v[0][1] >> 2)) return false; /* another register */
            lane[p] = l->v[0][1] & 3;
            continue;
        }
        float x;
        memcpy(&x, &l->v[0][1], sizeof x);
        unsigned i = 0;
        while (i < n && memcmp(&lit[i], &x, sizeof x)) i++;
        if (i == n) lit[n++] = x;
        lane[p] = i;
    }
    d3d9_src nw = {.mod = mod};
    if (first->v[0][0] == 2) {
        nw.type = (uint8_t)(first->v[0][1] >> 24);
        nw.num = (uint16_t)(first->v[0][1] >> 2 & 0x3fffff);
        if (nw.type != D3D9_REG_CONST && nw.type != D3D9_REG_INPUT && !(nw.type == D3D9_REG_ADDR && c->g->stage == D3D9_PS))
            return false; /* c, v and (pixel shaders') t registers */
        if (!port_free(in, k, nw.type, nw.num)) return false;
    } else {
        if (!port_free(in, k, D3D9_REG_CONST, 0xffff) || !hfx_bc_literal_fits(c->g, lit, n)) return false;
        bc_val r = hfx_bc_const(c->g, lit, n);
        if (c->g->failed) return false;
        nw.type = D3D9_REG_CONST;
        nw.num = r.num;
        for (unsigned p = 0; p < 4; p++) lane[p] = r.sw[lane[p]];
    }
    uint8_t sw = 0;
    for (unsigned p = 0; p < 4; p++) sw |= (uint8_t)(lane[p] << (2 * p));
    nw.swizzle = hfx_bc_tidy(sw, pos, kind(in->op) != K_LANEWISE);
    in->src[k] = nw;
    return true;
}

/* Source k of `in` reads what another register holds: the temporary that computed the values
 * first (per-lane instructions only where the components stay the same: texld's coordinates,
 * sincos's and nrm's operands are fixed in place); through a copy with a modifier, its source
 * under both modifiers; a constant's or an input's components, that register. */
static void redirect(cse *c, d3d9_inst *in, unsigned k) {
    d3d9_src *s = &in->src[k];
    if (!temp_src(s) || s->num >= c->span) return;
    unsigned pos = hfx_bc_read_positions(c->g, in, k);
    if (!pos) return;
    uint32_t w[4] = {0}, u[4] = {0};
    uint8_t m = 0xff, mp;
    for (unsigned p = 0; p < 4; p++)
        if (pos >> p & 1) {
            w[p] = temp_value(c, s->num, s->swizzle >> (2 * p) & 3);
            if (c->failed) return;
            u[p] = base_of(c, w[p], &mp);
            if (m != 0xff && mp != m) m = 0xfe; /* modifiers differ by lane */
            else if (m == 0xff) m = mp;
        }
    bool lanes = kind(in->op) != K_PER_LANE;
    uint8_t sw;
    int reg = older_holder(c, w, s->swizzle, pos, (int)s->num, &sw);
    if (reg >= 0 && (lanes || sw == s->swizzle)) {
        s->num = (uint16_t)reg;
        if (lanes) s->swizzle = hfx_bc_tidy(sw, pos, kind(in->op) != K_LANEWISE);
        c->changed = true;
        return;
    }
    if (!lanes || m == 0xfe || !plain_mod(s->mod)) return;
    uint8_t mod = compose(s->mod, m);
    if (m != D3D9_SMOD_NONE && (reg = older_holder(c, u, s->swizzle, pos, -1, &sw)) >= 0) {
        s->num = (uint16_t)reg;
        s->mod = mod;
        s->swizzle = hfx_bc_tidy(sw, pos, kind(in->op) != K_LANEWISE);
        c->changed = true;
        return;
    }
    if (read_leaves(c, in, k, u, pos, mod)) c->changed = true;
}

static bool same_src(const d3d9_src *a, const d3d9_src *b) {
    return a->type == b->type && a->num == b->num && a->mod == b->mod && a->swizzle == b->swizzle && !a->relative && !b->relative;
}

/* The block's values forgotten (an if, else, loop or break: another path may have written them). */
static void new_block(cse *c) { memset(c->vn, 0, (size_t)c->span * 4 * sizeof *c->vn); }

/* Component p of the destination now holds v. */
static void hold(cse *c, unsigned reg, unsigned p, uint32_t v) {
    c->vn[(size_t)reg * 4 + p] = v;
    if (v) add_holder(c, v, reg, p);
}

static void step(cse *c, uint32_t i) {
    d3d9_inst *in = &c->g->insts[i];
    if (flow(in)) { new_block(c); return; }
    bool num = numbered(in);
    if (kind(in->op) != K_NONE) {
        for (unsigned k = 0; k < in->src_count && k < 4; k++) redirect(c, in, k);
        if (in->op == D3D9_CMP && same_src(&in->src[1], &in->src[2])) {
            in->op = D3D9_MOV;
            in->src[0] = in->src[1];
            in->src_count = 1;
            c->changed = true;
        }
    }
    if (!in->has_dst || in->op == D3D9_TEXKILL || in->dst.type != D3D9_REG_TEMP || in->dst.relative || in->dst.num >= c->span)
        return;
    uint32_t v[4] = {0};
    bool held = num;
    for (unsigned p = 0; p < 4; p++) {
        if (!(in->dst.mask >> p & 1)) continue;
        v[p] = num ? result(c, in, p) : 0;
        held &= v[p] && c->vn[(size_t)in->dst.num * 4 + p] == v[p];
    }
    if (held) { c->del[i] = c->changed = true; return; } /* writes what its register holds already */
    for (unsigned p = 0; p < 4; p++)
        if (in->dst.mask >> p & 1) hold(c, in->dst.num, p, v[p] ? v[p] : fresh(c));
}

bool hfx_bc_cse(bc_gen *g) {
    uint32_t n = g->inst_count;
    if (!n || g->failed) return false;
    cse c = {.g = g, .span = hfx_bc_temp_span(g)};
    c.vn = HFX_NEW_ARRAY(g->c->arena, uint32_t, (size_t)c.span * 4);
    c.del = HFX_NEW_ARRAY(g->c->arena, bool, n);
    if (!c.vn || !c.del) return false;
    for (unsigned r = 0; r < BC_MAX_CONSTS; r++) c.def_of[r] = -1;
    for (uint32_t d = 0; d < g->def_count; d++)
        if (g->defs[d].num < BC_MAX_CONSTS) c.def_of[g->defs[d].num] = (int16_t)d;
    for (uint32_t i = 0; i < n && !c.failed; i++) step(&c, i);
    if (c.failed) return c.changed; /* out of memory part way: what was rewritten holds (each step is exact) */
    uint32_t k = 0;
    for (uint32_t i = 0; i < n; i++) if (!c.del[i]) g->insts[k++] = g->insts[i];
    g->inst_count = k;
    return c.changed;
}
