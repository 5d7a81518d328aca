/* bc_ports.c: D3D9's read ports. One instruction may read only so many different registers of a
 * type (hfx_d3d9_read_ports: one c, one v, one t in SM2 and SM3), and D3D9's runtime refuses a
 * shader whose instruction reads more. Where one does, the registers over the limit are copied
 * into a temporary just before it, as fxc does (`mov r3.xyz, c0` then `mad oD0.xyz, r0, r3, c1`):
 * a register an earlier copy of the same block still holds first (the copy widened to the
 * components now read: no new instruction), else the one it reads the fewest components of (the
 * first read on a tie); its reads keep their swizzles and modifiers. Runs on renumbered
 * temporaries: copies take registers nothing uses, renumbered again to pack them where they fit;
 * when the kept copies need more temporaries than the model has, each instruction gets its own. */
#include "bytecode/bc_int.h"

enum { MAX_COPIES = 8 };

/* The copies a block has made so far: register, the temporary holding it, the mov writing it. */
typedef struct copy { d3d9_src reg; uint16_t temp; uint32_t mov; } copy;
typedef struct copies {
    copy c[MAX_COPIES];
    unsigned n;
    unsigned top;             /* the first temporary after the kept copies' */
    bool reuse;
} copies;

/* The components `in` reads of the register source k names, through all its sources. */
static unsigned comps_read(const bc_gen *g, const d3d9_inst *in, unsigned k) {
    unsigned m = 0;
    for (unsigned j = 0; j < in->src_count; j++)
        if (hfx_d3d9_port_source(in, g->model, j) && hfx_d3d9_same_register(&in->src[j], &in->src[k]))
            m |= hfx_bc_read_comps(g, in, j);
    return m ? m : 0xf;
}

static int held(const copies *C, const d3d9_src *reg) {
    for (unsigned i = 0; i < C->n; i++)
        if (hfx_d3d9_same_register(&C->c[i].reg, reg)) return (int)i;
    return -1;
}

/* The source naming the register to copy: of type `type`; one already copied, else the fewest
 * components read, the first on a tie. */
static int cheapest(const bc_gen *g, const copies *C, const d3d9_inst *in, unsigned type) {
    int best = -1;
    unsigned best_n = 6;
    for (unsigned k = 0; k < in->src_count; k++) {
        if (in->src[k].type != type || !hfx_d3d9_port_source(in, g->model, k)) continue;
        bool first = true; /* each register once, at its first read */
        for (unsigned j = 0; j < k && first; j++) first = !hfx_d3d9_same_register(&in->src[j], &in->src[k]);
        unsigned n = held(C, &in->src[k]) >= 0 ? 0 : (unsigned)__builtin_popcount(comps_read(g, in, k));
        if (first && n < best_n) {
            best = (int)k;
            best_n = n;
        }
    }
    return best;
}

static void retarget(const bc_gen *g, d3d9_inst *in, const d3d9_src *from, unsigned temp) {
    for (unsigned j = 0; j < in->src_count; j++)
        if (hfx_d3d9_port_source(in, g->model, j) && hfx_d3d9_same_register(&in->src[j], from)) {
            d3d9_src *s = &in->src[j];
            *s = (d3d9_src){.type = D3D9_REG_TEMP, .num = (uint16_t)temp, .mod = s->mod, .swizzle = s->swizzle};
        }
}

/* `mov rT.<what in reads>, X` inserted before instruction at; false: out of memory. */
static bool copy_before(bc_gen *g, uint32_t at, const d3d9_src *from, unsigned mask, unsigned temp) {
    if (!HFX_ARENA_GROW(g->c->arena, g->insts, g->inst_count, g->inst_cap, 64)) return false;
    memmove(&g->insts[at + 1], &g->insts[at], (g->inst_count - at) * sizeof *g->insts);
    g->inst_count++;
    d3d9_inst *mov = &g->insts[at];
    memset(mov, 0, sizeof *mov);
    mov->op = D3D9_MOV;
    mov->has_dst = true;
    mov->dst = (d3d9_dst){.type = D3D9_REG_TEMP, .num = (uint16_t)temp, .mask = (uint8_t)mask};
    mov->src[0] = *from;
    mov->src[0].mod = D3D9_SMOD_NONE;
    mov->src[0].swizzle = hfx_bc_tidy(0xe4, mask, false);
    mov->src_count = 1;
    return true;
}

/* One register of instruction *at over the ports read from a temporary; false: none free. */
static bool fix_one(bc_gen *g, copies *C, uint32_t *at, unsigned type, unsigned *next) {
    d3d9_inst *in = &g->insts[*at];
    int k = cheapest(g, C, in, type);
    if (k < 0) return false;
    d3d9_src from = in->src[k];
    unsigned mask = comps_read(g, in, (unsigned)k);
    int h = held(C, &from);
    if (h >= 0) { /* the earlier copy widened */
        d3d9_inst *mov = &g->insts[C->c[h].mov];
        mov->dst.mask |= (uint8_t)mask;
        mov->src[0].swizzle = hfx_bc_tidy(0xe4, mov->dst.mask, false);
        retarget(g, in, &from, C->c[h].temp);
        return true;
    }
    if (*next >= BC_MAX_TEMPS || !copy_before(g, *at, &from, mask, *next)) return false;
    for (unsigned i = 0; i < C->n; i++) if (C->c[i].mov >= *at) C->c[i].mov++;
    (*at)++;
    retarget(g, &g->insts[*at], &from, *next);
    if (C->reuse && !from.relative && C->n < MAX_COPIES) /* c[a0.x + n] moves with a0: not kept */
        C->c[C->n++] = (copy){from, (uint16_t)*next, *at - 1};
    (*next)++;
    if (C->n && C->c[C->n - 1].temp >= C->top) C->top = C->c[C->n - 1].temp + 1u;
    return true;
}

/* Every instruction over the ports fixed; whether any was. */
static bool fix_all(bc_gen *g, unsigned spare, bool reuse) {
    copies C = {.top = spare, .reuse = reuse};
    bool changed = false;
    for (uint32_t i = 0; i < g->inst_count; i++) {
        const d3d9_op_info *info = hfx_d3d9_op_find(g->insts[i].op);
        /* a copy stays within its block; its temporaries are numbered afresh when they run out */
        if ((info && (info->flags & D3D9_OPF_FLOW)) || C.top + 3 > BC_MAX_TEMPS) {
            C.n = 0;
            C.top = spare;
        }
        unsigned count, next = C.top;
        int type;
        while ((type = hfx_d3d9_port_excess(g->stage, g->model, &g->insts[i], &count)) >= 0)
            if (!fix_one(g, &C, &i, (unsigned)type, &next)) return changed;
            else changed = true;
    }
    return changed;
}

static int def_index(const bc_gen *g, const d3d9_src *s) {
    if (s->type != D3D9_REG_CONST || s->relative) return -1;
    for (uint32_t d = 0; d < g->def_count; d++)
        if (g->defs[d].num == s->num) return (int)d;
    return -1;
}

/* An instruction reading literals from two def registers (`cmp r0, r1, c3.z, c2.w`: a 1 and a 0
 * packed apart) reads them from one def holding both: no copy, no slot. Only when every constant
 * it reads is a literal (a parameter would still need its port). */
static void gather_one(bc_gen *g, d3d9_inst *in) {
    unsigned count;
    if (hfx_d3d9_port_excess(g->stage, g->model, in, &count) != D3D9_REG_CONST) return;
    float v[4];
    unsigned n = 0;
    for (unsigned k = 0; k < in->src_count && k < 4; k++) {
        if (!hfx_d3d9_port_source(in, g->model, k) || in->src[k].type != D3D9_REG_CONST) continue;
        int d = def_index(g, &in->src[k]);
        if (d < 0) return;
        unsigned pos = hfx_bc_read_positions(g, in, k);
        for (unsigned p = 0; p < 4; p++) {
            if (!(pos >> p & 1)) continue;
            float x = g->defs[d].v[in->src[k].swizzle >> (2 * p) & 3];
            unsigned i = 0;
            while (i < n && memcmp(&v[i], &x, sizeof x)) i++;
            if (i == n && n == 4) return;
            if (i == n) v[n++] = x;
        }
    }
    if (!hfx_bc_literal_fits(g, v, n)) return;
    bc_val lit = hfx_bc_const(g, v, n);
    if (g->failed) return;
    for (unsigned k = 0; k < in->src_count && k < 4; k++) {
        d3d9_src *s = &in->src[k];
        if (!hfx_d3d9_port_source(in, g->model, k) || s->type != D3D9_REG_CONST) continue;
        const bc_def *d = &g->defs[def_index(g, s)];
        unsigned pos = hfx_bc_read_positions(g, in, k);
        uint8_t sw = s->swizzle;
        for (unsigned p = 0; p < 4; p++) {
            if (!(pos >> p & 1)) continue;
            float x = d->v[s->swizzle >> (2 * p) & 3];
            unsigned i = 0;
            while (memcmp(&v[i], &x, sizeof x)) i++;
            sw = (uint8_t)((sw & ~(3u << (2 * p))) | (unsigned)lit.sw[i] << (2 * p));
        }
        s->num = lit.num;
        s->swizzle = hfx_bc_tidy(sw, pos, in->op == D3D9_DP3 || in->op == D3D9_DP4 || in->op == D3D9_DP2ADD);
    }
}

void hfx_bc_gather_literals(bc_gen *g) {
    for (uint32_t i = 0; i < g->inst_count && !g->failed; i++) gather_one(g, &g->insts[i]);
}

uint32_t hfx_bc_read_ports(bc_gen *g, uint32_t temps) {
    if (temps >= BC_MAX_TEMPS) return temps;
    uint32_t n = g->inst_count;
    d3d9_inst *saved = HFX_NEW_ARRAY(g->c->arena, d3d9_inst, n ? n : 1);
    if (!saved) return temps;
    memcpy(saved, g->insts, n * sizeof *saved);
    if (!fix_all(g, temps, true)) return temps;
    uint32_t t = hfx_bc_renumber(g);
    if (t <= hfx_bc_temp_limit(g)) return t;
    memcpy(g->insts, saved, n * sizeof *saved); /* the kept copies cost a register too many */
    g->inst_count = n;
    fix_all(g, temps, false);
    return hfx_bc_renumber(g);
}
