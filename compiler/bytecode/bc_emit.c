/* bc_emit.c: instructions as d3d9_inst records (so a later step may still retarget one),
 * temporaries, `def` constants, the CTAB comment and the token stream (Microsoft's "Shader Code
 * Format": instruction, destination and source parameter tokens, comments, END). */
#include <stdio.h>

#include "bytecode/bc_int.h"
#include "bytes.h"

void hfx_bc_fail(bc_gen *g, hfx_loc loc, unsigned code, const char *fmt, ...) {
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (!g->failed) hfx_error(g->c->diags, loc, code, "%s", msg);
    g->failed = true;
}

unsigned hfx_bc_temp_limit(const bc_gen *g) {
    if (g->model >= D3D9_SM(3, 0)) return 32;
    if (g->model == D3D9_SM(2, 1)) return g->stage == D3D9_VS ? 13 : strcmp(g->profile, "ps_2_a") == 0 ? 22 : 32;
    return 12;
}

/* Round robin: a register freed long ago rather than just now, so that copies can still be
 * sunk into their writers (bc_peep.c); hfx_bc_renumber gives the final, fewest numbers. The
 * numbers are virtual: when all of the space is held it doubles (the model's limit is checked
 * on the allocator's registers, not here). */
int hfx_bc_temp(bc_gen *g) {
    if (!g->temps_used) {
        g->temps_used = HFX_NEW_ARRAY(g->c->arena, uint8_t, BC_MAX_TEMPS);
        g->temp_space = 32;
        if (!g->temps_used) { hfx_bc_fail(g, g->loc, X_BC_TEMPS, "out of memory"); return -1; }
    }
    for (;;) {
        for (unsigned k = 0; k < g->temp_space; k++) {
            unsigned r = (g->next_temp + k) % g->temp_space;
            if (g->temps_used[r]) continue;
            g->next_temp = r + 1;
            g->temps_used[r] = 1;
            return (int)r;
        }
        if (g->temp_space == BC_MAX_TEMPS) break;
        g->next_temp = g->temp_space; /* the new half is all free */
        g->temp_space *= 2;
    }
    hfx_bc_fail(g, g->loc, X_BC_TEMPS, "this shader needs more than %u temporary registers at once", BC_MAX_TEMPS);
    return -1;
}

void hfx_bc_release(bc_gen *g, bc_val v) {
    if (v.own && v.type == D3D9_REG_TEMP && v.num < BC_MAX_TEMPS && g->temps_used) g->temps_used[v.num] = 0;
}

void hfx_bc_release_obj(bc_gen *g, bc_obj o) {
    for (uint32_t i = 0; i < o.count; i++) hfx_bc_release(g, o.slot[i]);
}

bc_val hfx_bc_reg(uint8_t type, uint16_t num, unsigned n) {
    bc_val v = {.type = type, .num = num, .n = (uint8_t)n, .sw = {0, 1, 2, 3}};
    return v;
}

bc_val hfx_bc_scalar_of(bc_val v, unsigned i) {
    bc_val s = v;
    s.n = 1;
    s.sw[0] = v.sw[i < v.n ? i : 0];
    s.own = false;
    return s;
}

bc_val hfx_bc_neg(bc_val v) {
    static const uint8_t flip[] = {[D3D9_SMOD_NONE] = D3D9_SMOD_NEG, [D3D9_SMOD_NEG] = D3D9_SMOD_NONE,
                                   [D3D9_SMOD_ABS] = D3D9_SMOD_ABSNEG, [D3D9_SMOD_ABSNEG] = D3D9_SMOD_ABS};
    v.mod = flip[v.mod];
    return v;
}

static d3d9_src src_of(const bc_val *v, unsigned mask, bool replicate) {
    d3d9_src s = {.type = v->type, .num = v->num, .mod = v->mod, .relative = v->rel};
    if (v->rel) { s.rel_type = v->rel_aL ? D3D9_REG_LOOP : D3D9_REG_ADDR; s.rel_comp = 0; }
    uint8_t sw[4];
    unsigned k = 0;
    bool identity = true;
    for (unsigned i = 0; i < v->n; i++) identity &= v->sw[i] == i;
    for (unsigned c = 0; c < 4; c++) {
        unsigned i = replicate || v->n == 1 ? 0 : k < v->n ? k : v->n - 1u;
        sw[c] = mask == 0xf && identity && k >= v->n && v->n > 1 ? (uint8_t)c : v->sw[i]; /* dp3 v0 reads v0.xyzw */
        if (mask & (1u << c)) k++;
    }
    /* components the mask skips: the replicated one (.x), else their own (.xyzw), as fxc's
     * assembler leaves them */
    bool same = true;
    int first = -1;
    for (unsigned c = 0; c < 4; c++)
        if (mask & (1u << c)) { if (first < 0) first = (int)c; else same &= sw[c] == sw[first]; }
    for (unsigned c = 0; c < 4 && first >= 0; c++)
        if (!(mask & (1u << c))) sw[c] = same ? sw[first] : (uint8_t)c;
    s.swizzle = (uint8_t)(sw[0] | sw[1] << 2 | sw[2] << 4 | sw[3] << 6);
    return s;
}

static bool grow(bc_gen *g) {
    return HFX_ARENA_GROW(g->c->arena, g->insts, g->inst_count, g->inst_cap, 64);
}

d3d9_inst *hfx_bc_emit(bc_gen *g, uint16_t op, const bc_val *dst, unsigned mask, const bc_val *src, unsigned n) {
    if (g->failed || !grow(g)) return NULL;
    const d3d9_op_info *info = hfx_d3d9_op_find(op);
    d3d9_inst *in = &g->insts[g->inst_count++];
    memset(in, 0, sizeof *in);
    in->op = op;
    in->has_dst = dst != NULL;
    if (dst) in->dst = (d3d9_dst){.type = dst->type, .num = dst->num, .mask = (uint8_t)mask};
    bool scalar = info && (info->flags & D3D9_OPF_SCALAR);
    bool dot = op == D3D9_DP3 || op == D3D9_DP4 || op == D3D9_DP2ADD || op == D3D9_TEX || op == D3D9_TEXLDL ||
               op == D3D9_TEXLDD || op == D3D9_NRM || op == D3D9_CRS || op == D3D9_TEXKILL;
    for (unsigned i = 0; i < n && i < 4; i++)
        if (src[i].type == BC_REG_NONE) {
            hfx_bc_fail(g, g->loc, 4502, "invalid input semantic for %s: a value read here has no input register in the model",
                    g->profile);
            return in;
        }
    for (unsigned i = 0; i < n && i < 4; i++) {
        bool rep = scalar || (op == D3D9_DP2ADD && i == 2);
        in->src[i] = src_of(&src[i], dot && !rep ? 0xf : mask, rep);
    }
    in->src_count = (uint8_t)n;
    g->last_fresh = -1;
    return in;
}

bool hfx_bc_can_sat(const bc_gen *g) { return g->stage == D3D9_PS || g->model >= D3D9_SM(3, 0); }

bool hfx_bc_is_zero(const bc_gen *g, const bc_val *v) {
    if (v->type != D3D9_REG_CONST || v->rel) return false;
    for (uint32_t d = 0; d < g->def_count; d++)
        if (g->defs[d].num == v->num) {
            for (unsigned i = 0; i < v->n; i++) if (g->defs[d].v[v->sw[i]] != 0) return false;
            return true;
        }
    return false;
}

static bc_val widened(bc_val v, unsigned n) {
    if (v.n == 1) for (unsigned c = 1; c < 4; c++) v.sw[c] = v.sw[0];
    v.n = (uint8_t)n;
    return v;
}

/* A def register's ones. */
static bool is_one(const bc_gen *g, const bc_val *v) {
    if (v->type != D3D9_REG_CONST || v->rel || v->mod) return false;
    for (uint32_t d = 0; d < g->def_count; d++)
        if (g->defs[d].num == v->num) {
            for (unsigned i = 0; i < v->n; i++) if (g->defs[d].v[v->sw[i]] != 1) return false;
            return true;
        }
    return false;
}

/* x * 0, dot(x, 0), x + 0, 0 * y + z, x * 1: no instruction (fxc folds them as well). */
static bool folded(bc_gen *g, uint16_t op, unsigned n, const bc_val *src, unsigned count, bc_val *out) {
    int keep = -1;
    bool zero = false;
    switch (op) {
    case D3D9_MUL:
        keep = is_one(g, &src[0]) && src[1].n >= src[0].n ? 1 : is_one(g, &src[1]) && src[0].n >= src[1].n ? 0 : -1;
        /* fall through */
    case D3D9_DP3: case D3D9_DP4:
        zero = hfx_bc_is_zero(g, &src[0]) || hfx_bc_is_zero(g, &src[1]);
        if (zero) keep = -1;
        break;
    case D3D9_DP2ADD: case D3D9_MAD:
        if (hfx_bc_is_zero(g, &src[0]) || hfx_bc_is_zero(g, &src[1])) keep = 2;
        break;
    case D3D9_ADD:
        keep = hfx_bc_is_zero(g, &src[0]) ? 1 : hfx_bc_is_zero(g, &src[1]) ? 0 : -1;
        break;
    default: break;
    }
    if (!zero && keep < 0) return false;
    for (unsigned i = 0; i < count; i++) if ((int)i != keep) hfx_bc_release(g, src[i]);
    *out = zero ? widened(hfx_bc_constf(g, 0), n) : widened(src[keep], n);
    return true;
}

bc_val hfx_bc_op(bc_gen *g, uint16_t op, unsigned n, const bc_val *src, unsigned count) {
    bc_val f;
    if (folded(g, op, n, src, count, &f)) return f;
    if (op == D3D9_MAD && hfx_bc_is_zero(g, &src[2])) { /* y * z + 0: a mul */
        hfx_bc_release(g, src[2]);
        return hfx_bc_op(g, D3D9_MUL, n, src, 2);
    }
    int r = hfx_bc_temp(g);
    bc_val d = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(r < 0 ? 0 : r), n);
    d.own = r >= 0;
    hfx_bc_emit(g, op, &d, (1u << n) - 1, src, count);
    for (unsigned i = 0; i < count; i++) hfx_bc_release(g, src[i]);
    g->last_fresh = g->failed ? -1 : (int)g->inst_count - 1;
    return d;
}

bc_val hfx_bc_op1(bc_gen *g, uint16_t op, unsigned n, bc_val a) { return hfx_bc_op(g, op, n, &a, 1); }
bc_val hfx_bc_op2(bc_gen *g, uint16_t op, unsigned n, bc_val a, bc_val b) {
    bc_val s[2] = {a, b};
    return hfx_bc_op(g, op, n, s, 2);
}
bc_val hfx_bc_op3(bc_gen *g, uint16_t op, unsigned n, bc_val a, bc_val b, bc_val c) {
    bc_val s[3] = {a, b, c};
    return hfx_bc_op(g, op, n, s, 3);
}

static int free_const(bc_gen *g) {
    for (unsigned r = 0; r < g->max_consts; r++)
        if (!g->cused[r]) return (int)r;
    return -1;
}

bool hfx_bc_reserve_consts(bc_gen *g, uint16_t first, uint16_t count) {
    if ((uint32_t)first + count > g->max_consts) return false;
    for (unsigned r = first; r < (unsigned)first + count; r++) g->cused[r] = 1;
    return true;
}

static bc_def *new_def(bc_gen *g) {
    int r = free_const(g);
    if (r < 0) {
        hfx_bc_fail(g, g->loc, X_BC_CONSTS, "%s has no constant register left for a literal (it has %u)", g->profile,
                g->max_consts);
        return NULL;
    }
    if (!HFX_ARENA_GROW(g->c->arena, g->defs, g->def_count, g->def_cap, 8)) return NULL;
    g->cused[r] = 1;
    bc_def *d = &g->defs[g->def_count++];
    memset(d, 0, sizeof *d);
    d->num = (uint16_t)r;
    return d;
}

static bool same_float(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

bool hfx_bc_literal_fits(const bc_gen *g, const float *v, unsigned n) {
    if (free_const((bc_gen *)g) >= 0) return true;
    for (uint32_t d = 0; d < g->def_count; d++) {
        unsigned k = 0;
        for (; k < n; k++) {
            unsigned c = 0;
            while (c < g->defs[d].used && !same_float(g->defs[d].v[c], v[k])) c++;
            if (c == g->defs[d].used) break;
        }
        if (k == n) return true;
    }
    return false;
}

/* A literal's components: taken from the def registers when one holds them all, else a new
 * register (scalars share registers, four to a register, as fxc packs them). */
bc_val hfx_bc_const(bc_gen *g, const float *v, unsigned n) {
    for (uint32_t d = 0; d < g->def_count; d++) {
        bc_val r = hfx_bc_reg(D3D9_REG_CONST, g->defs[d].num, n);
        unsigned k = 0;
        for (; k < n; k++) {
            unsigned c = 0;
            while (c < g->defs[d].used && !same_float(g->defs[d].v[c], v[k])) c++;
            if (c == g->defs[d].used) break;
            r.sw[k] = (uint8_t)c;
        }
        if (k == n) return r;
    }
    bc_def *d = g->def_count ? &g->defs[g->def_count - 1] : NULL;
    unsigned fresh = 0; /* the values the last def register lacks */
    for (unsigned k = 0; k < n && d; k++) {
        bool have = false;
        for (unsigned c = 0; c < d->used; c++) have |= same_float(d->v[c], v[k]);
        for (unsigned j = 0; j < k && !have; j++) have |= same_float(v[j], v[k]);
        fresh += !have;
    }
    if (!d || d->used + fresh > 4) d = new_def(g);
    if (!d) return hfx_bc_reg(D3D9_REG_CONST, 0, n);
    bc_val r = hfx_bc_reg(D3D9_REG_CONST, d->num, n);
    for (unsigned k = 0; k < n; k++) {
        unsigned c = 0;
        while (c < d->used && !same_float(d->v[c], v[k])) c++;
        if (c == d->used) d->v[d->used++] = v[k];
        r.sw[k] = (uint8_t)c;
    }
    return r;
}

bc_val hfx_bc_constf(bc_gen *g, float v) { return hfx_bc_const(g, &v, 1); }

/* The last instruction wrote v's fresh temporary whole: it may write t instead (no mov). */
static bool retarget(bc_gen *g, bc_val t, bc_val v, bool sat) {
    if (!v.own || v.mod || g->last_fresh != (int)g->inst_count - 1 || g->last_fresh < 0) return false;
    d3d9_inst *in = &g->insts[g->last_fresh];
    if (in->dst.type != D3D9_REG_TEMP || in->dst.num != v.num || t.rel) return false;
    if (g->stage == D3D9_PS && g->model < D3D9_SM(3, 0) && t.type != D3D9_REG_TEMP) return false;
    if (in->op == D3D9_SINCOS || in->op == D3D9_NRM || in->op == D3D9_CRS || in->op == D3D9_LIT) {
        if (t.type != D3D9_REG_TEMP) return false;
    }
    for (unsigned i = 0; i < v.n; i++) if (v.sw[i] != i) return false;
    if (in->dst.mask != (1u << v.n) - 1) return false;
    const d3d9_op_info *info = hfx_d3d9_op_find(in->op);
    bool dot = in->op == D3D9_DP3 || in->op == D3D9_DP4 || in->op == D3D9_DP2ADD || (info->flags & D3D9_OPF_SCALAR) ||
               (info->flags & D3D9_OPF_TEX) || in->op == D3D9_NRM || in->op == D3D9_CRS;
    unsigned mask = 0;
    for (unsigned i = 0; i < v.n; i++) mask |= 1u << t.sw[i];
    if (dot) {
        if (v.n != 1 && (in->op != D3D9_NRM && in->op != D3D9_CRS && !(info->flags & D3D9_OPF_TEX))) return false;
        if (v.n != 1) for (unsigned i = 0; i < v.n; i++) if (t.sw[i] != i) return false;
    } else {
        for (unsigned s = 0; s < in->src_count; s++) {
            uint8_t old = in->src[s].swizzle, nw = 0;
            uint8_t comp[4];
            for (unsigned c = 0; c < 4; c++) comp[c] = (uint8_t)(old >> (2 * c) & 3);
            uint8_t out[4] = {comp[0], comp[0], comp[0], comp[0]};
            for (unsigned i = 0; i < v.n; i++) out[t.sw[i]] = comp[i];
            for (int c = 2; c >= 0; c--) if (!(mask & (1u << c)) && (mask >> c)) out[c] = out[c + 1];
            for (unsigned c = 0; c < 4; c++) nw |= (uint8_t)(out[c] << (2 * c));
            in->src[s].swizzle = nw;
        }
    }
    in->dst.type = t.type;
    in->dst.num = t.num;
    in->dst.mask = (uint8_t)mask;
    if (sat) in->dst.mods |= D3D9_DMOD_SAT;
    hfx_bc_release(g, v);
    g->last_fresh = -1;
    return true;
}

void hfx_bc_store(bc_gen *g, bc_val t, bc_val v, bool sat) {
    if (g->failed) return;
    if (retarget(g, t, v, sat)) return;
    unsigned mask = 0;
    uint8_t sw[4] = {0, 0, 0, 0};
    for (unsigned i = 0; i < t.n; i++) {
        mask |= 1u << t.sw[i];
        sw[t.sw[i]] = v.sw[i < v.n ? i : 0];
    }
    bc_val src = v;
    src.n = 4;
    for (unsigned c = 0; c < 4; c++) src.sw[c] = sw[c];
    /* src_of walks set mask bits in order; give it the components in register order */
    unsigned k = 0;
    uint8_t packed[4] = {0, 0, 0, 0};
    for (unsigned c = 0; c < 4; c++) if (mask & (1u << c)) packed[k++] = sw[c];
    for (unsigned c = 0; c < 4; c++) src.sw[c] = packed[c < k ? c : k - 1];
    src.n = (uint8_t)k;
    bc_val dst = t;
    d3d9_inst *in = hfx_bc_emit(g, D3D9_MOV, &dst, mask, &src, 1);
    if (in && sat) in->dst.mods |= D3D9_DMOD_SAT;
    hfx_bc_release(g, v);
}

/* --- tokens --- */

typedef struct words { uint32_t *w; uint32_t n, cap; hfx_arena *a; } words;

static void put(words *o, uint32_t x) {
    if (HFX_ARENA_GROW(o->a, o->w, o->n, o->cap, 256)) o->w[o->n++] = x;
}

static uint32_t regt(unsigned t) { return ((t & 7u) << 28) | ((t & 0x18u) << 8); }

static uint32_t dst_token(const d3d9_dst *d) {
    return 0x80000000u | regt(d->type) | d->num | (uint32_t)d->mask << 16 | (uint32_t)d->mods << 20;
}

static void put_src(words *o, const d3d9_src *s) {
    put(o, 0x80000000u | regt(s->type) | s->num | (uint32_t)s->swizzle << 16 | (uint32_t)s->mod << 24 |
               (s->relative ? 1u << 13 : 0));
    if (s->relative) put(o, 0x80000000u | regt(s->rel_type) | s->rel_num | (uint32_t)(s->rel_comp * 0x55u) << 16);
}

static void put_inst(words *o, const d3d9_inst *in) {
    uint32_t at = o->n;
    put(o, in->op | (uint32_t)in->control << 16);
    if (in->op == D3D9_DCL) {
        put(o, in->dst.type == D3D9_REG_SAMPLER ? 0x80000000u | (uint32_t)in->sampler_type << 27
                                                 : 0x80000000u | in->usage | (uint32_t)in->usage_index << 16);
    }
    if (in->has_dst) put(o, dst_token(&in->dst));
    if (in->op == D3D9_DEF || in->op == D3D9_DEFI)
        for (int k = 0; k < 4; k++) put(o, in->value.u[k]);
    for (unsigned i = 0; i < in->src_count; i++) put_src(o, &in->src[i]);
    if (at < o->n) o->w[at] |= (o->n - at - 1) << 24;
}

/* --- the constant table --- */

typedef struct bytes { unsigned char *b; uint32_t n, cap; hfx_arena *a; } bytes;

static uint32_t reserve(bytes *o, uint32_t n) {
    uint32_t at = o->n;
    for (uint32_t i = 0; i < n; i++)
        if (HFX_ARENA_GROW(o->a, o->b, o->n, o->cap, 256)) o->b[o->n++] = 0;
    return at;
}
static void set16(bytes *o, uint32_t at, uint32_t v) { if (at + 2 <= o->n) { o->b[at] = (unsigned char)v; o->b[at + 1] = (unsigned char)(v >> 8); } }
static void set32(bytes *o, uint32_t at, uint32_t v) { set16(o, at, v & 0xffff); set16(o, at + 2, v >> 16); }
static uint32_t put_str(bytes *o, const char *s) {
    uint32_t n = (uint32_t)strlen(s) + 1, at = reserve(o, n);
    if (at + n <= o->n) memcpy(o->b + at, s, n);
    return at;
}

/* A D3DXSHADER_TYPEINFO for t (struct members after it); returns its offset. */
static uint32_t put_type(bytes *o, const hfx_type *t, bool cols) {
    uint32_t elems = 1;
    while (t->kind == TY_ARRAY) { elems *= t->array_len; t = t->elem; }
    uint32_t at = reserve(o, 16);
    unsigned cls = t->kind == TY_SCALAR ? 0 : t->kind == TY_VECTOR ? 1 : t->kind == TY_MATRIX ? (cols ? 3 : 2)
                 : t->kind == TY_STRUCT ? 5 : 4;
    unsigned type = t->kind == TY_SAMPLER ? (t->dim == DIM_1D ? 11 : t->dim == DIM_3D ? 13 : t->dim == DIM_CUBE ? 14 : 12)
                  : t->base == B_BOOL ? 1 : t->base == B_INT || t->base == B_UINT ? 2 : t->kind == TY_STRUCT ? 0 : 3;
    set16(o, at, cls);
    set16(o, at + 2, type);
    set16(o, at + 4, t->kind == TY_STRUCT || t->kind == TY_SAMPLER ? 1 : t->rows ? t->rows : 1);
    set16(o, at + 6, t->kind == TY_STRUCT ? hfx_type_components(t) : t->kind == TY_SAMPLER ? 1 : t->cols ? t->cols : 1);
    set16(o, at + 8, elems);
    if (t->kind == TY_STRUCT) {
        uint32_t n = t->st->field_count, members = reserve(o, 8 * n);
        set16(o, at + 10, n);
        set32(o, at + 12, members - 4);
        for (uint32_t i = 0; i < n; i++) {
            set32(o, members + 8 * i, put_str(o, t->st->fields[i].name) - 4);
            set32(o, members + 8 * i + 4, put_type(o, t->st->fields[i].type, cols) - 4);
        }
    }
    return at;
}

/* The CTAB comment: offsets count from the byte after the fourcc (our byte 4). */
static void put_ctab(bc_gen *g, words *o, uint32_t version) {
    bytes b = {NULL, 0, 0, g->c->arena};
    reserve(&b, 4 + 28 + 20 * g->ctab_count);
    b.b[0] = 'C'; b.b[1] = 'T'; b.b[2] = 'A'; b.b[3] = 'B';
    set32(&b, 4, 28);
    set32(&b, 8, put_str(&b, "hfxc 0.1.0 (D3D9 bytecode)") - 4);
    set32(&b, 12, version);
    set32(&b, 16, g->ctab_count);
    set32(&b, 20, 28);
    set32(&b, 28, put_str(&b, g->profile) - 4);
    for (uint32_t i = 0; i < g->ctab_count; i++) {
        const bc_ctab *k = &g->ctab[i];
        uint32_t at = 4 + 28 + 20 * i;
        set32(&b, at, put_str(&b, k->name) - 4);
        set16(&b, at + 4, k->set);
        set16(&b, at + 6, k->reg);
        set16(&b, at + 8, k->count);
        set32(&b, at + 12, put_type(&b, k->type, k->cols) - 4);
    }
    while (b.n % 4) reserve(&b, 1);
    put(o, 0xfffeu | (b.n / 4) << 16);
    for (uint32_t i = 0; i + 4 <= b.n; i += 4) put(o, hfx_le32(b.b + i));
}

const uint32_t *hfx_bc_encode(bc_gen *g, uint32_t *count) {
    words o = {NULL, 0, 0, g->c->arena};
    unsigned major = g->model >> 4, minor = g->model & 15;
    uint32_t version = (g->stage == D3D9_VS ? 0xfffe0000u : 0xffff0000u) | major << 8 | minor;
    put(&o, version);
    put_ctab(g, &o, version);
    for (uint32_t i = 0; i < g->def_count; i++) {
        d3d9_inst d = {.op = D3D9_DEF, .has_dst = true};
        d.dst = (d3d9_dst){.type = D3D9_REG_CONST, .num = g->defs[i].num, .mask = 0xf};
        memcpy(d.value.f, g->defs[i].v, sizeof d.value.f);
        put_inst(&o, &d);
    }
    for (uint32_t i = 0; i < g->defi_count; i++) { /* loop counts: `defi iN, count, start, step, 0` */
        d3d9_inst d = {.op = D3D9_DEFI, .has_dst = true};
        d.dst = (d3d9_dst){.type = D3D9_REG_CONSTINT, .num = g->defis[i].num, .mask = 0xf};
        memcpy(d.value.i, g->defis[i].v, sizeof d.value.i);
        put_inst(&o, &d);
    }
    for (int pass = 0; pass < 2; pass++) /* inputs and outputs, then samplers, as fxc lists them */
        for (uint32_t i = 0; i < g->dcl_count; i++)
            if ((g->dcls[i].dst.type == D3D9_REG_SAMPLER) == (pass == 1)) put_inst(&o, &g->dcls[i]);
    for (uint32_t i = 0; i < g->inst_count; i++) put_inst(&o, &g->insts[i]);
    put(&o, 0x0000ffffu);
    *count = o.n;
    return o.w;
}
