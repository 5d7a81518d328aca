/* bc_gen.c: the entry's interface as registers, variables as register slots, statements: ifs
 * flattened into selects (both sides run; each variable either side writes takes the side's
 * value by the condition), loops unrolled (their counter a constant in each copy), calls inlined,
 * discard as texkill. Then the shader is encoded, decoded by compiler/d3d9 and held to the
 * model's limits. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bytecode/bc_int.h"

uint32_t hfx_bc_slots(const hfx_type *t, bool cols) {
    switch (t->kind) {
    case TY_SCALAR: case TY_VECTOR: case TY_SAMPLER: return 1;
    case TY_MATRIX: return cols ? t->cols : t->rows;
    case TY_ARRAY: return t->array_len * hfx_bc_slots(t->elem, cols);
    case TY_STRUCT: {
        uint32_t n = 0;
        for (uint32_t i = 0; i < t->st->field_count; i++) n += hfx_bc_slots(t->st->fields[i].type, cols);
        return n;
    }
    default: return 0;
    }
}

/* Components of slot k of type t. */
unsigned hfx_bc_slot_width(const hfx_type *t, bool cols, uint32_t k) {
    switch (t->kind) {
    case TY_SCALAR: case TY_SAMPLER: return 1;
    case TY_VECTOR: return t->cols;
    case TY_MATRIX: return cols ? t->rows : t->cols;
    case TY_ARRAY: return hfx_bc_slot_width(t->elem, cols, k % hfx_bc_slots(t->elem, cols));
    case TY_STRUCT:
        for (uint32_t i = 0; i < t->st->field_count; i++) {
            uint32_t n = hfx_bc_slots(t->st->fields[i].type, cols);
            if (k < n) return hfx_bc_slot_width(t->st->fields[i].type, cols, k);
            k -= n;
        }
        return 4;
    default: return 4;
    }
}

static bc_obj new_obj(bc_gen *g, uint32_t n) {
    bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, n ? n : 1), n, false};
    return o;
}

bc_obj hfx_bc_alloc_obj(bc_gen *g, const hfx_type *t) {
    bc_obj o = new_obj(g, hfx_bc_slots(t, false));
    for (uint32_t k = 0; k < o.count; k++) {
        int r = hfx_bc_temp(g);
        o.slot[k] = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(r < 0 ? 0 : r), hfx_bc_slot_width(t, false, k));
        o.slot[k].own = r >= 0;
    }
    return o;
}

/* src in temporaries of its own when it reads a temporary dst writes: an element-by-element copy
 * between the layouts must read everything before it writes (`m = transpose(m)` is a view of m's
 * own registers; copied in place, the later rows read elements the earlier ones overwrote). */
static bc_obj unalias(bc_gen *g, bc_obj dst, bc_obj src) {
    bool alias = false;
    for (uint32_t k = 0; k < dst.count && !alias; k++)
        for (uint32_t i = 0; i < src.count && !alias; i++)
            alias = dst.slot[k].type == D3D9_REG_TEMP && src.slot[i].type == D3D9_REG_TEMP && dst.slot[k].num == src.slot[i].num;
    if (!alias) return src;
    bc_obj c = new_obj(g, src.count);
    c.cols = src.cols;
    for (uint32_t i = 0; i < src.count; i++) {
        bc_val s = src.slot[i];
        s.own = false;
        c.slot[i] = hfx_bc_op1(g, D3D9_MOV, s.n, s);
    }
    hfx_bc_release_obj(g, src);
    return c;
}

/* Matrices are copied element by element when the layouts differ. */
void hfx_bc_assign(bc_gen *g, bc_obj dst, bc_obj src, const hfx_type *t, bool sat) {
    if (dst.cols != src.cols && t->kind != TY_MATRIX && hfx_bc_has_matrix(t)) { hfx_bc_assign_members(g, dst, src, t, sat); return; }
    if (t->kind == TY_MATRIX && dst.cols != src.cols) {
        src = unalias(g, dst, src);
        unsigned outer = dst.cols ? t->cols : t->rows, inner = dst.cols ? t->rows : t->cols;
        for (unsigned k = 0; k < outer && k < dst.count; k++)
            for (unsigned j = 0; j < inner; j++) {
                bc_val e = dst.cols ? hfx_bc_matrix_elem(src, j, k) : hfx_bc_matrix_elem(src, k, j);
                hfx_bc_store(g, hfx_bc_scalar_of(dst.slot[k], j), e, sat);
            }
        hfx_bc_release_obj(g, src);
        return;
    }
    for (uint32_t k = 0; k < dst.count && k < src.count; k++) {
        bc_val s = src.slot[k];
        hfx_bc_store(g, dst.slot[k], s, sat);
    }
}

bc_binding *hfx_bc_bind(bc_gen *g, const ir_var *v) {
    for (uint32_t i = g->bind_count; i-- > 0;)
        if (g->binds[i].var == v) return &g->binds[i];
    return NULL;
}

static bc_binding *add_bind(bc_gen *g, const ir_var *v, bc_obj o) {
    if (!HFX_ARENA_GROW(g->c->arena, g->binds, g->bind_count, g->bind_cap, 32)) return NULL;
    bc_binding *b = &g->binds[g->bind_count++];
    memset(b, 0, sizeof *b);
    b->var = v;
    b->obj = o;
    b->owned = ~0ull;
    for (uint32_t k = 0; k < o.count; k++) b->obj.slot[k].own = false; /* the binding owns them */
    return b;
}

/* --- the interface --- */

static void add_dcl(bc_gen *g, d3d9_inst in) {
    if (HFX_ARENA_GROW(g->c->arena, g->dcls, g->dcl_count, g->dcl_cap, 16)) g->dcls[g->dcl_count++] = in;
}

static int semantic_usage(const char *s, unsigned *index) {
    static const char *const names[] = {"POSITION", "BLENDWEIGHT", "BLENDINDICES", "NORMAL", "PSIZE", "TEXCOORD",
                                        "TANGENT", "BINORMAL", "TESSFACTOR", "POSITIONT", "COLOR", "FOG", "DEPTH"};
    size_t n = strlen(s);
    while (n && s[n - 1] >= '0' && s[n - 1] <= '9') n--;
    *index = (unsigned)atoi(s + n);
    for (int u = 0; u < (int)(sizeof names / sizeof *names); u++)
        if (strlen(names[u]) == n && strncmp(names[u], s, n) == 0) return u;
    return -1;
}

static unsigned comps_mask(const hfx_type *t) { return (1u << hfx_type_components(t)) - 1; }

/* The register an input leaf arrives in (its dcl added). */
static bc_val input_reg(bc_gen *g, const ir_leaf *l) {
    unsigned index, n = hfx_type_components(l->type);
    int usage = semantic_usage(l->semantic, &index);
    d3d9_inst d = {.op = D3D9_DCL, .has_dst = true};
    bc_val v = hfx_bc_reg(D3D9_REG_INPUT, 0, n);
    bool vpos = strcmp(l->semantic, "VPOS0") == 0, vface = strcmp(l->semantic, "VFACE0") == 0;
    if (g->stage == D3D9_PS && (vpos || vface)) {
        if (g->model < D3D9_SM(3, 0)) {
            hfx_bc_fail(g, l->loc, 4001, "%s is not available in %s: it needs ps_3_0", vpos ? "VPOS" : "VFACE", g->profile);
            return v;
        }
        v = hfx_bc_reg(D3D9_REG_MISC, vpos ? 0 : 1, n);
        if (vface) v.sw[1] = v.sw[2] = v.sw[3] = 0;
        d.dst = (d3d9_dst){.type = D3D9_REG_MISC, .num = v.num, .mask = (uint8_t)(vpos ? 3 : 0xf)};
    } else if (g->stage == D3D9_PS && g->model < D3D9_SM(3, 0)) {
        if (usage != 5 && usage != 10) { /* fxc drops such an input unless it is read */
            v.type = BC_REG_NONE;
            return v;
        }
        v = hfx_bc_reg(usage == 5 ? D3D9_REG_ADDR : D3D9_REG_INPUT, (uint16_t)index, n);
        d.dst = (d3d9_dst){.type = v.type, .num = v.num, .mask = (uint8_t)comps_mask(l->type)};
    } else {
        if (usage < 0) {
            hfx_bc_fail(g, l->loc, 4502, "invalid input semantic '%s'", l->semantic);
            return v;
        }
        v.num = (uint16_t)g->inputs++;
        d.usage = (uint8_t)usage;
        d.usage_index = (uint8_t)index;
        d.dst = (d3d9_dst){.type = D3D9_REG_INPUT, .num = v.num,
                           .mask = (uint8_t)(g->stage == D3D9_VS ? 0xf : comps_mask(l->type))};
    }
    add_dcl(g, d);
    return v;
}

static bc_val output_reg(bc_gen *g, const ir_leaf *l) {
    unsigned index, n = hfx_type_components(l->type);
    int usage = semantic_usage(l->semantic, &index);
    bc_val v = hfx_bc_reg(D3D9_REG_OUTPUT, 0, n);
    if (g->stage == D3D9_PS) {
        if (usage == 10 && index < 4) return hfx_bc_reg(D3D9_REG_COLOROUT, (uint16_t)index, n);
        if (usage == 12 && index == 0) return hfx_bc_reg(D3D9_REG_DEPTHOUT, 0, n);
        hfx_bc_fail(g, l->loc, 4503, "invalid output semantic '%s' for a pixel shader", l->semantic);
        return v;
    }
    if (g->model >= D3D9_SM(3, 0)) {
        if (usage < 0) { hfx_bc_fail(g, l->loc, 4503, "invalid output semantic '%s'", l->semantic); return v; }
        v.num = (uint16_t)g->outputs++;
        d3d9_inst d = {.op = D3D9_DCL, .has_dst = true, .usage = (uint8_t)usage, .usage_index = (uint8_t)index};
        d.dst = (d3d9_dst){.type = D3D9_REG_OUTPUT, .num = v.num,
                           .mask = (uint8_t)(usage == 0 || usage == 10 ? 0xf : comps_mask(l->type))};
        add_dcl(g, d);
        return v;
    }
    if (usage == 0 && index == 0) return hfx_bc_reg(D3D9_REG_RASTOUT, 0, n);
    if (usage == 11) return hfx_bc_reg(D3D9_REG_RASTOUT, 1, n);
    if (usage == 4) return hfx_bc_reg(D3D9_REG_RASTOUT, 2, n);
    if (usage == 10 && index < 2) return hfx_bc_reg(D3D9_REG_ATTROUT, (uint16_t)index, n);
    if (usage == 5 && index < 8) return hfx_bc_reg(D3D9_REG_OUTPUT, (uint16_t)index, n);
    hfx_bc_fail(g, l->loc, 4503, "invalid output semantic '%s' for %s", l->semantic, g->profile);
    return v;
}

/* The entry's leaves of one parameter (or of the return value), in ir_iface.c's order, placed
 * into the slots of its type: a matrix with a semantic takes a register per column (D3D9's
 * column_major packing: `float4x4 m : TEXCOORD1` is TEXCOORD1..4, its columns), an array a
 * register per element. */
typedef struct iface_walk { const ir_leaf *l; int n, at; const ir_var *p; bool out; } iface_walk;

static const ir_leaf *next_leaf(iface_walk *w) {
    while (w->at < w->n && w->l[w->at].root != w->p) w->at++;
    return w->at < w->n ? &w->l[w->at++] : NULL;
}

static bool place_leaf(bc_gen *g, iface_walk *w, bc_obj *o, uint32_t slot, unsigned width) {
    const ir_leaf *l = next_leaf(w);
    if (!l || slot >= o->count || hfx_type_components(l->type) != width) return false;
    o->slot[slot] = w->out ? output_reg(g, l) : input_reg(g, l);
    return true;
}

static bool place(bc_gen *g, iface_walk *w, const hfx_type *t, bc_obj *o, uint32_t slot) {
    switch (t->kind) {
    case TY_STRUCT:
        for (uint32_t i = 0; i < t->st->field_count && !g->failed; i++) {
            const hfx_field *f = &t->st->fields[i];
            bool none = w->out && !f->semantic && f->type->kind != TY_STRUCT; /* goes nowhere (ir_iface.c) */
            if (!none && !place(g, w, f->type, o, slot)) return false;
            slot += hfx_bc_slots(f->type, o->cols);
        }
        return true;
    case TY_ARRAY:
        for (uint32_t i = 0; i < t->array_len && !g->failed; i++)
            if (!place(g, w, t->elem, o, slot + i * hfx_bc_slots(t->elem, o->cols))) return false;
        return true;
    case TY_MATRIX:
        if (t->rows < 2 || t->cols < 2 || t->rows != t->cols) return false;
        for (uint32_t r = 0; r < t->rows && !g->failed; r++)
            if (!place_leaf(g, w, o, slot + r, t->cols)) return false;
        return true;
    case TY_SCALAR: case TY_VECTOR: return place_leaf(g, w, o, slot, hfx_type_components(t));
    default: return false;
    }
}

/* The registers of the entry's parameter p (or of its return value, p NULL). */
static bc_obj interface_obj(bc_gen *g, const ir_leaf *l, int n, const ir_var *p, const hfx_type *t, bool out) {
    bool cols = hfx_bc_has_matrix(t);
    bc_obj o = new_obj(g, hfx_bc_slots(t, cols));
    o.cols = cols;
    for (uint32_t k = 0; k < o.count; k++) o.slot[k] = hfx_bc_reg(D3D9_REG_TEMP, 0, hfx_bc_slot_width(t, cols, k));
    iface_walk w = {l, n, 0, p, out};
    if (!place(g, &w, t, &o, 0) && !g->failed) {
        const ir_leaf *at = w.at > 0 && w.at <= n ? &l[w.at - 1] : NULL;
        for (int i = 0; !at && i < n; i++) if (l[i].root == p) at = &l[i];
        hfx_bc_fail(g, at ? at->loc : g->loc, X_BC_UNSUPPORTED, "the bytecode writer does not handle '%s' here yet (a matrix with a semantic that is not square)",
                    at ? at->semantic : "?");
    }
    return o;
}

bool hfx_bc_straight_return(const ir_stmt *body) {
    if (!body || body->kind != IS_BLOCK) return false;
    for (uint32_t i = 0; i < body->count; i++) {
        const ir_stmt *s = body->body[i];
        if (s->kind == IS_RETURN) return i + 1 == body->count;
        if (hfx_ir_has_jumps(s)) return false;
    }
    return true;
}

/* The c register a parameter's `register(c#)` gives this shader (`register(vs, c13)` in a vertex
 * shader, `register(ps, c14)` in a pixel shader), or -1. */
static int explicit_const(const bc_gen *g, const ir_var *v) {
    char buf[32];
    const char *reg = hfx_register_for(v->decl ? v->decl->reg : NULL, g->profile, buf, sizeof buf);
    return reg && (reg[0] == 'c' || reg[0] == 'C') && reg[1] >= '0' && reg[1] <= '9' ? atoi(reg + 1) : -1;
}

/* Element k of a sampler array parameter, or -1 for a sampler of its own. */
static int sampler_element(const bc_gen *g, const ir_var *v) {
    const hfx_decl *d = v->decl;
    if (!d || d->type->kind != TY_ARRAY || !g->c->fx || d->index >= g->c->fx->param_count) return -1;
    return (int)(v->param - g->c->fx->params[d->index].first_child);
}

/* The s register of the stage's sampler global i. A sampler array takes one run of registers,
 * element k at the first + k, up to the last element the stage reads, named once in the CTAB
 * (fxc's form: D3DX binds element k of the parameter to register first + k). */
static unsigned sampler_register(bc_gen *g, uint32_t i) {
    const ir_var *v = g->sh->globals[i];
    int k = sampler_element(g, v);
    if (k < 0) {
        if (HFX_ARENA_GROW(g->c->arena, g->ctab, g->ctab_count, g->ctab_cap, 8))
            g->ctab[g->ctab_count++] = (bc_ctab){v->name, v->type, D3D9_RS_SAMPLER, (uint16_t)g->samplers, 1, false};
        return g->samplers++;
    }
    for (uint32_t j = 0; j < g->ctab_count; j++) /* the run an earlier element opened */
        if (g->ctab[j].set == D3D9_RS_SAMPLER && g->ctab[j].type == v->decl->type && strcmp(g->ctab[j].name, v->name) == 0)
            return g->ctab[j].reg + (unsigned)k;
    int last = k;
    for (uint32_t j = i + 1; j < g->sh->global_count; j++) {
        const ir_var *w = g->sh->globals[j];
        if (w->kind == IRV_SAMPLER && w->decl == v->decl && sampler_element(g, w) > last) last = sampler_element(g, w);
    }
    unsigned first = g->samplers;
    g->samplers += (uint32_t)last + 1;
    if (HFX_ARENA_GROW(g->c->arena, g->ctab, g->ctab_count, g->ctab_cap, 8))
        g->ctab[g->ctab_count++] = (bc_ctab){v->name, v->decl->type, D3D9_RS_SAMPLER, (uint16_t)first, (uint16_t)(last + 1), false};
    return first + (unsigned)k;
}

/* Parameters, samplers and private globals, in the order the stage lists them. A parameter
 * without a register takes the first free run that no later parameter's register asks for. */
void hfx_bc_bind_globals(bc_gen *g) {
    uint8_t reserved[BC_MAX_CONSTS] = {0};
    for (uint32_t i = 0; i < g->sh->global_count; i++) {
        const ir_var *v = g->sh->globals[i];
        int first = v->kind == IRV_UNIFORM ? explicit_const(g, v) : -1;
        bool cols = !(v->mods & MOD_ROW_MAJOR) && !(v->decl && (v->decl->mods & MOD_ROW_MAJOR));
        for (uint32_t k = 0; first >= 0 && k < hfx_bc_slots(v->type, cols) && first + k < BC_MAX_CONSTS; k++)
            reserved[first + k] = 1;
    }
    for (uint32_t i = 0; i < g->sh->global_count && !g->failed; i++) {
        const ir_var *v = g->sh->globals[i];
        if (v->kind == IRV_SAMPLER) {
            bc_obj o = new_obj(g, 1);
            o.slot[0] = hfx_bc_reg(D3D9_REG_SAMPLER, (uint16_t)sampler_register(g, i), 4);
            d3d9_inst d = {.op = D3D9_DCL, .has_dst = true};
            d.sampler_type = v->dim == DIM_CUBE ? 3 : v->dim == DIM_3D ? 4 : 2;
            d.dst = (d3d9_dst){.type = D3D9_REG_SAMPLER, .num = o.slot[0].num, .mask = 0xf};
            add_dcl(g, d);
            add_bind(g, v, o);
        } else if (v->kind == IRV_UNIFORM) {
            bool cols = !(v->mods & MOD_ROW_MAJOR) && !(v->decl && (v->decl->mods & MOD_ROW_MAJOR));
            uint32_t n = hfx_bc_slots(v->type, cols);
            int first = explicit_const(g, v);
            if (first < 0)
                for (uint32_t r = 0; r + n <= g->max_consts && first < 0; r++) {
                    uint32_t k = 0;
                    while (k < n && !g->cused[r + k] && !reserved[r + k]) k++;
                    if (k == n) first = (int)r;
                }
            if (first < 0 || !hfx_bc_reserve_consts(g, (uint16_t)first, (uint16_t)n)) {
                hfx_bc_fail(g, v->decl ? v->decl->loc : g->loc, X_BC_CONSTS,
                        "'%s' does not fit in the %u constant registers of %s", v->name, g->max_consts, g->profile);
                return;
            }
            bc_obj o = new_obj(g, n);
            o.cols = cols;
            for (uint32_t k = 0; k < n; k++) o.slot[k] = hfx_bc_reg(D3D9_REG_CONST, (uint16_t)(first + (int)k), hfx_bc_slot_width(v->type, cols, k));
            add_bind(g, v, o);
            if (HFX_ARENA_GROW(g->c->arena, g->ctab, g->ctab_count, g->ctab_cap, 8))
                g->ctab[g->ctab_count++] = (bc_ctab){v->name, v->type, D3D9_RS_FLOAT4, (uint16_t)first, (uint16_t)n, cols};
        }
    }
}

void hfx_bc_init_privates(bc_gen *g) {
    for (uint32_t i = 0; i < g->sh->global_count && !g->failed; i++) {
        const ir_var *v = g->sh->globals[i];
        if (v->kind != IRV_PRIVATE) continue;
        bc_binding *b = add_bind(g, v, hfx_bc_alloc_obj(g, v->type));
        if (!b) return;
        if (v->init) hfx_bc_assign(g, b->obj, hfx_bc_expr(g, v->init), v->type, false);
        else if (v->copy_of) {
            bc_binding *u = hfx_bc_bind(g, v->copy_of);
            if (u) hfx_bc_assign(g, b->obj, u->obj, v->type, false);
        }
    }
}

/* --- statements --- */

static void gen_stmt(bc_gen *g, const ir_stmt *s);

static void gen_block_from(bc_gen *g, const ir_stmt *b, uint32_t from);

/* if (c) { ... return; } rest: the rest is the if's else, so a return inside a flattened if needs no jump. */
static bool ends_in_return(const ir_stmt *s) {
    if (!s) return false;
    if (s->kind == IS_RETURN) return true;
    return s->kind == IS_BLOCK && s->count && ends_in_return(s->body[s->count - 1]);
}

/* Code inside a loop written as a loop (bc_flow.c), in the loop's own function. */
static bool in_real_loop(const bc_gen *g) { return g->loop_region && g->depth == g->loop_fn_depth; }

static void end_scope(bc_gen *g, uint32_t mark) {
    uint32_t n = mark;
    for (uint32_t i = mark; i < g->bind_count; i++) {
        bc_binding *b = &g->binds[i];
        if (b->var->kind == IRV_LOCAL || b->var->kind == IRV_PARAM) {
            for (uint32_t k = 0; k < b->obj.count; k++) {
                bc_val v = b->obj.slot[k];
                v.own = k >= 64 || (b->owned >> k & 1);
                if (v.type == D3D9_REG_TEMP) hfx_bc_release(g, v);
            }
        } else g->binds[n++] = *b;
    }
    g->bind_count = n;
}

static void gen_if(bc_gen *g, const ir_stmt *s, const ir_stmt *rest, uint32_t rest_from);

static void gen_block_from(bc_gen *g, const ir_stmt *b, uint32_t from) {
    uint32_t mark = g->bind_count;
    for (uint32_t i = from; i < b->count && !g->failed && !g->broke; i++) {
        const ir_stmt *s = b->body[i];
        g->loc = s->loc;
        if (s->kind == IS_IF && ends_in_return(s->then_s) && !s->else_s && i + 1 < b->count && !in_real_loop(g)) {
            gen_if(g, s, b, i + 1);
            break;
        }
        gen_stmt(g, s);
        if (s->kind == IS_RETURN) break;
    }
    end_scope(g, mark);
}

static void gen_body(bc_gen *g, const ir_stmt *s) {
    if (!s) return;
    if (s->kind == IS_BLOCK) gen_block_from(g, s, 0);
    else {
        uint32_t mark = g->bind_count;
        gen_stmt(g, s);
        end_scope(g, mark);
    }
}

static void gen_decl(bc_gen *g, const ir_stmt *s) {
    const ir_var *v = s->var;
    double k;
    if (s->expr && v->type->kind == TY_SCALAR && (v->type->base == B_INT || v->type->base == B_UINT) &&
        hfx_bc_try_const(g, s->expr, &k)) { /* a counter the unroller may step */
        bc_binding *b = add_bind(g, v, new_obj(g, 0));
        if (b) { b->is_const = true; b->konst = k; }
        return;
    }
    /* every slot starts as zero (a view of a def register, as the GLSL path zeroes it) and
     * takes a temporary of its own when written */
    bc_obj o = new_obj(g, hfx_bc_slots(v->type, false));
    for (uint32_t k = 0; k < o.count; k++) {
        unsigned n = hfx_bc_slot_width(v->type, false, k);
        o.slot[k] = hfx_bc_constf(g, 0);
        o.slot[k].n = (uint8_t)n;
        for (unsigned c = 1; c < 4; c++) o.slot[k].sw[c] = o.slot[k].sw[0];
    }
    bc_binding *b = add_bind(g, v, o);
    if (!b) return;
    b->owned = 0;
    if (s->expr) hfx_bc_init_binding(g, b, hfx_bc_expr(g, s->expr));
}

/* A binding's registers copied into fresh temporaries. */
static bc_obj copy_obj(bc_gen *g, bc_obj o) {
    bc_obj c = new_obj(g, o.count);
    c.cols = o.cols;
    for (uint32_t k = 0; k < o.count; k++) {
        bc_val t = o.slot[k];
        t.own = false;
        c.slot[k] = hfx_bc_immutable(g, &t) ? t : hfx_bc_op1(g, D3D9_MOV, t.n, t);
        c.slot[k].own = false;
    }
    return c;
}

/* The written variables' bindings that exist now (declared outside the if). */
static uint32_t written(bc_gen *g, const ir_stmt *s, uint32_t **out) {
    ir_var_set w = {0};
    hfx_ir_note_writes(g->c, (ir_stmt *)s, &w);
    if (w.unknown || w.calls) {
        /* calls may write private globals: take every binding of one */
        for (uint32_t i = 0; i < g->bind_count; i++)
            if (g->binds[i].var->kind == IRV_PRIVATE) hfx_ir_var_set_add(g->c, &w, g->binds[i].var);
    }
    uint32_t *b = HFX_NEW_ARRAY(g->c->arena, uint32_t, w.count ? w.count : 1);
    uint32_t n = 0;
    for (uint32_t i = 0; i < w.count; i++) {
        bc_binding *x = hfx_bc_bind(g, w.vars[i]);
        if (x && x->obj.count) b[n++] = (uint32_t)(x - g->binds); /* indexes: the array may move */
        else if (x && x->is_const) {
            hfx_bc_fail(g, s->loc, X_BC_LOOP, "unable to unroll loop: its counter changes under a condition");
            return 0;
        }
    }
    *out = b;
    return n;
}

/* The current condition and c (c is not consumed: the if still needs it). */
static bc_val and_cond(bc_gen *g, bc_val c) {
    c.own = false;
    if (!g->cond.n) return c;
    bc_val outer = g->cond;
    outer.own = false;
    return hfx_bc_op2(g, D3D9_MUL, 1, outer, c);
}

/* Both sides run; afterwards each variable they write holds cond ? then-value : else-value. */
static void gen_if(bc_gen *g, const ir_stmt *s, const ir_stmt *rest, uint32_t rest_from) {
    double k;
    if (hfx_bc_try_const(g, s->expr, &k)) {
        if (k != 0) gen_body(g, s->then_s);
        else if (rest) gen_block_from(g, rest, rest_from);
        else gen_body(g, s->else_s);
        return;
    }
    if (hfx_bc_flow_if(g, s)) return;
    uint32_t *wi;
    uint32_t n = written(g, s, &wi);
#define w(i) (&g->binds[wi[i]])
    bc_obj *saved = HFX_NEW_ARRAY(g->c->arena, bc_obj, n ? n : 1), *then_v = HFX_NEW_ARRAY(g->c->arena, bc_obj, n ? n : 1);
    bc_val c = hfx_bc_own(g, hfx_bc_expr1(g, s->expr));
    bc_val outer = g->cond;
    for (uint32_t i = 0; i < n; i++) saved[i] = copy_obj(g, w(i)->obj);
    g->cond = and_cond(g, c);
    bc_val cur = g->cond;
    gen_body(g, s->then_s);
    uint64_t *then_owned = HFX_NEW_ARRAY(g->c->arena, uint64_t, n ? n : 1);
    for (uint32_t i = 0; i < n; i++) {
        then_v[i] = w(i)->obj;
        then_owned[i] = w(i)->owned;
        w(i)->obj = saved[i];
        w(i)->owned = 0;
        for (uint32_t k = 0; k < saved[i].count && k < 64; k++)
            if (saved[i].slot[k].type == D3D9_REG_TEMP) w(i)->owned |= 1ull << k;
    }
    bc_val kc = c;
    kc.own = false;
    bc_val nc = hfx_bc_not(g, kc);
    g->cond = outer.n ? and_cond(g, nc) : nc;
    if (rest) gen_block_from(g, rest, rest_from);
    else gen_body(g, s->else_s);
    if (g->cond.num != nc.num || g->cond.type != nc.type) { bc_val x = g->cond; x.own = true; hfx_bc_release(g, x); }
    nc.own = true;
    hfx_bc_release(g, nc);
    if (cur.num != c.num || cur.type != c.type) { cur.own = true; hfx_bc_release(g, cur); }
    g->cond = outer;
    for (uint32_t i = 0; i < n && !g->failed; i++) {
        bc_obj o = w(i)->obj;
        for (uint32_t j = 0; j < o.count; j++) {
            bc_val t = then_v[i].slot[j], e = o.slot[j];
            t.own = e.own = false;
            bc_val x = c;
            x.own = false;
            bc_val sel = hfx_bc_select(g, x, t, e);
            if (!(w(i)->owned >> j & 1) || o.slot[j].type != D3D9_REG_TEMP) { /* a view: the select's temporary is the value */
                o.slot[j] = sel;
                o.slot[j].own = false;
                w(i)->owned |= 1ull << j;
            } else hfx_bc_store(g, o.slot[j], sel, false);
            t.own = j < 64 && (then_owned[i] >> j & 1);
            hfx_bc_release(g, t);
        }
    }
    hfx_bc_release(g, c);
}
#undef w

/* A step of an unrolled loop's counter (i++, i += k, i = i + k); false when it is not one. */
static bool const_step(bc_gen *g, const ir_expr *e) {
    if (!e) return true;
    if (e->kind == IE_COMMA) {
        for (uint32_t i = 0; i < e->n; i++) if (!const_step(g, e->a[i])) return false;
        return true;
    }
    const ir_expr *t = e->n ? e->a[0] : NULL;
    bc_binding *b = t && t->kind == IE_VAR ? hfx_bc_bind(g, t->var) : NULL;
    if (!b || !b->is_const) return false;
    double v;
    if (e->kind == IE_UNARY) {
        b->konst += e->op == OP_PREINC || e->op == OP_POSTINC ? 1 : e->op == OP_PREDEC || e->op == OP_POSTDEC ? -1 : 0;
        return e->op != OP_NEG && e->op != OP_NOT && e->op != OP_BITNOT;
    }
    if (e->kind != IE_ASSIGN || !hfx_bc_try_const(g, e->a[1], &v)) return false;
    switch (e->op) {
    case OP_NONE: b->konst = v; break;
    case OP_ADD: b->konst += v; break;
    case OP_SUB: b->konst -= v; break;
    case OP_MUL: b->konst *= v; break;
    default: return false;
    }
    return true;
}

enum { MAX_UNROLL = 1024 };

/* `int i; ... for (i = 0; ...)`: the counter declared before the loop starts at a constant as
 * one declared in it does, so the unroller can step it (and code after the loop reads its last
 * value, as fxc's unrolled code does). Only outside flattened or real flow: there its register
 * is pinned and must stay one. */
static bool counter_init(bc_gen *g, const ir_stmt *s) {
    const ir_expr *e = s && s->kind == IS_EXPR ? s->expr : NULL;
    double k;
    if (!e || e->kind != IE_ASSIGN || e->op != OP_NONE || e->a[0]->kind != IE_VAR || g->cond.n || g->loop_nest ||
        g->if_nest || g->loop_region)
        return false;
    const ir_var *v = e->a[0]->var;
    if (v->kind != IRV_LOCAL || v->type->kind != TY_SCALAR || (v->type->base != B_INT && v->type->base != B_UINT) ||
        !hfx_bc_try_const(g, e->a[1], &k))
        return false;
    bc_binding *b = hfx_bc_bind(g, v);
    if (!b) return false;
    b->is_const = true;
    b->konst = k;
    return true;
}

static void gen_loop(bc_gen *g, const ir_stmt *s) {
    uint32_t mark = g->bind_count;
    if (s->init && !counter_init(g, s->init)) gen_stmt(g, s->init);
    if (!g->failed && hfx_bc_flow_loop(g, s)) {
        end_scope(g, mark);
        return;
    }
    struct bc_region *outer = g->loop_region; /* its breaks are the unrolled loop's */
    g->loop_region = NULL;
    for (unsigned it = 0; !g->failed; it++) {
        double k = 1;
        if ((s->kind != IS_DO || it) && s->expr && !hfx_bc_try_const(g, s->expr, &k)) {
            hfx_bc_fail(g, s->loc, X_BC_LOOP, "unable to unroll loop, loop does not appear to terminate in a timely manner (%u iterations)", MAX_UNROLL);
            break;
        }
        if (!k) break;
        if (it >= MAX_UNROLL || (s->max_iterations && it >= s->max_iterations)) {
            if (it >= MAX_UNROLL)
                hfx_bc_fail(g, s->loc, X_BC_LOOP, "unable to unroll loop, loop does not appear to terminate in a timely manner (%u or more iterations)", MAX_UNROLL);
            break;
        }
        gen_body(g, s->then_s);
        if (g->broke) { g->broke = false; break; }
        if (s->step && !const_step(g, s->step)) {
            hfx_bc_fail(g, s->loc, X_BC_LOOP, "unable to unroll loop: its step is not a constant change of its counter");
            break;
        }
    }
    g->loop_region = outer;
    end_scope(g, mark);
}

static void gen_discard(bc_gen *g) {
    if (g->stage != D3D9_PS) { hfx_bc_fail(g, g->loc, X_BC_UNSUPPORTED, "discard in a vertex shader"); return; }
    bc_val c = g->cond;
    c.own = false;
    bc_val k = c.n ? hfx_bc_op1(g, D3D9_MOV, 4, hfx_bc_neg(c)) : hfx_bc_op1(g, D3D9_MOV, 4, hfx_bc_constf(g, -1));
    hfx_bc_emit(g, D3D9_TEXKILL, &k, 0xf, NULL, 0);
    hfx_bc_release(g, k);
}

/* A straight callee's value leaves as it is: temporaries of its locals are taken from their
 * bindings (so its scope's end keeps them), other registers are read where they are. */
static void capture_return(bc_gen *g, const ir_expr *e) {
    bc_obj o = hfx_bc_expr(g, e);
    for (uint32_t k = 0; k < o.count; k++) {
        bc_val *v = &o.slot[k];
        if (v->own || v->type != D3D9_REG_TEMP) continue;
        for (uint32_t i = g->capture_mark; i < g->bind_count && !v->own; i++) {
            bc_binding *b = &g->binds[i];
            for (uint32_t j = 0; j < b->obj.count && j < 64; j++)
                if ((b->owned >> j & 1) && b->obj.slot[j].type == v->type && b->obj.slot[j].num == v->num) {
                    b->owned &= ~(1ull << j);
                    v->own = true;
                    break;
                }
        }
    }
    *g->capture = o;
    g->capture = NULL;
}

/* A return in flattened code. Every side of every if runs, so after the first return under a
 * condition, g->done holds 1 where the function has returned, and a later return (after the if,
 * or in the next unrolled iteration) takes the return value only where the code runs (g->cond)
 * and done is 0, then adds that to done. The first return writes the value unmasked: before it
 * the value is undefined, and HLSL makes every path return, so where it did not run a later
 * return will. */
static void gen_return(bc_gen *g, const ir_expr *e) {
    bc_obj v = hfx_bc_expr(g, e);
    if (!g->done.n) {
        hfx_bc_assign(g, *g->ret, v, e->type, false);
        bc_val c = g->cond;
        c.own = false;
        if (c.n) g->done = hfx_bc_op1(g, D3D9_MOV, 1, c); /* a register of its own: later returns add to it */
        return;
    }
    bc_obj val = hfx_bc_alloc_obj(g, e->type);
    hfx_bc_assign(g, val, v, e->type, false);
    bc_val d = g->done, now = g->cond;
    d.own = now.own = false;
    bc_val not_done = hfx_bc_not(g, d);
    if (now.n) {
        bc_val nd = not_done;
        nd.own = false;
        now = hfx_bc_op2(g, D3D9_MUL, 1, now, nd); /* where this return runs and none ran before */
        not_done.own = true;
        hfx_bc_release(g, not_done);
    } else {
        now = not_done;
    }
    for (uint32_t k = 0; k < g->ret->count && k < val.count && !g->failed; k++) {
        bc_val x = now, t = val.slot[k], r = g->ret->slot[k];
        x.own = t.own = r.own = false;
        hfx_bc_store(g, g->ret->slot[k], hfx_bc_select(g, x, t, r), false);
    }
    for (uint32_t k = 0; k < val.count; k++) val.slot[k].own = true;
    hfx_bc_release_obj(g, val);
    bc_val n = now;
    n.own = false;
    hfx_bc_store(g, g->done, hfx_bc_op2(g, D3D9_ADD, 1, d, n), false);
    now.own = true;
    hfx_bc_release(g, now);
}

static void gen_stmt(bc_gen *g, const ir_stmt *s) {
    if (g->failed) return;
    g->loc = s->loc;
    switch (s->kind) {
    case IS_BLOCK: gen_block_from(g, s, 0); break;
    case IS_DECL: gen_decl(g, s); break;
    case IS_EXPR: {
        if (const_step(g, s->expr)) break; /* the counter's own changes */
        hfx_bc_release_obj(g, hfx_bc_expr(g, s->expr));
        break;
    }
    case IS_IF: gen_if(g, s, NULL, 0); break;
    case IS_FOR: case IS_WHILE: case IS_DO: gen_loop(g, s); break;
    case IS_RETURN:
        if (in_real_loop(g)) {
            hfx_bc_fail(g, s->loc, X_BC_UNSUPPORTED, "the bytecode writer does not handle a return inside a loop it does not unroll yet");
            break;
        }
        if (s->expr && g->capture) capture_return(g, s->expr);
        else if (s->expr && g->ret) gen_return(g, s->expr);
        break;
    case IS_DISCARD: gen_discard(g); break;
    case IS_BREAK:
        if (in_real_loop(g)) { hfx_bc_flow_break(g, s); break; }
        if (g->cond.n) hfx_bc_fail(g, s->loc, X_BC_LOOP, "unable to unroll loop: it breaks under a condition the compiler cannot fold");
        g->broke = true;
        break;
    default:
        hfx_bc_fail(g, s->loc, X_BC_UNSUPPORTED, "the bytecode writer does not handle this statement yet");
    }
}

/* An argument a written parameter may take as it is: inputs and constants (copied when written)
 * or fresh temporaries of its own, in the parameter's row layout. */
static bool cow_arg(bc_gen *g, bc_obj a) {
    if (a.cols || a.count > 64) return false;
    for (uint32_t k = 0; k < a.count; k++)
        if (!hfx_bc_immutable(g, &a.slot[k]) && !(a.slot[k].own && a.slot[k].type == D3D9_REG_TEMP && !a.slot[k].mod))
            return false;
    return true;
}

/* An inlined call: parameters bound to the arguments (or to copies, when the callee writes them). */
void hfx_bc_call(bc_gen *g, const ir_expr *e, bc_obj *out) {
    const ir_func *f = e->fn;
    if (g->depth > 32) { hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "calls nest too deep"); return; }
    uint32_t mark = g->bind_count;
    bc_obj *outs = HFX_NEW_ARRAY(g->c->arena, bc_obj, f->param_count ? f->param_count : 1);
    for (uint32_t i = 0; i < f->param_count && i < e->n && !g->failed; i++) {
        const ir_var *p = f->params[i];
        bool is_out = (p->mods & MOD_OUT) != 0;
        if (is_out) outs[i] = hfx_bc_expr(g, e->a[i]);  /* an l-value: its registers */
        if (is_out && !(p->mods & MOD_IN)) { add_bind(g, p, hfx_bc_alloc_obj(g, p->type)); continue; }
        bc_obj a = is_out ? outs[i] : hfx_bc_expr(g, e->a[i]);
        if (!hfx_bc_writes_param(g, f, p) && !is_out) { /* read only: the argument's registers serve */
            uint64_t owned = 0;
            for (uint32_t k = 0; k < a.count && k < 64; k++) if (a.slot[k].own) owned |= 1ull << k;
            bc_binding *b = add_bind(g, p, a);
            if (b) b->owned = owned;
            continue;
        }
        if (cow_arg(g, a)) { /* registers nothing else names: written in place or copied on write */
            uint64_t owned = 0;
            for (uint32_t k = 0; k < a.count && k < 64; k++) if (a.slot[k].own) owned |= 1ull << k;
            bc_binding *b = add_bind(g, p, a);
            if (b) b->owned = owned;
            continue;
        }
        bc_binding *b = add_bind(g, p, hfx_bc_alloc_obj(g, p->type));
        if (b) hfx_bc_assign(g, b->obj, a, p->type, false);
    }
    bc_obj *saved_ret = g->ret, *saved_capture = g->capture, ret = {0};
    uint32_t saved_mark = g->capture_mark;
    bool has_value = f->ret && f->ret->kind != TY_VOID, straight = has_value && hfx_bc_straight_return(f->body);
    if (has_value && !straight) ret = hfx_bc_alloc_obj(g, f->ret);
    g->ret = straight ? NULL : &ret;
    g->capture = straight ? &ret : NULL;
    g->capture_mark = g->bind_count;
    bc_val saved_done = g->done;
    g->done = (bc_val){0}; /* the callee's own returns */
    g->depth++;
    gen_body(g, f->body);
    g->depth--;
    if (g->done.n) { g->done.own = true; hfx_bc_release(g, g->done); }
    g->done = saved_done;
    g->ret = saved_ret;
    g->capture = saved_capture;
    g->capture_mark = saved_mark;
    for (uint32_t i = 0; i < f->param_count && i < e->n && !g->failed; i++) {
        const ir_var *p = f->params[i];
        if (!(p->mods & MOD_OUT)) continue;
        bc_binding *b = hfx_bc_bind(g, p);
        if (!b) continue;
        uint64_t owned = b->owned;
        b->owned = 0; /* its temporaries go to the argument */
        hfx_bc_assign_expr(g, e->a[i], b->obj, owned);
    }
    end_scope(g, mark);
    if (!straight) for (uint32_t k = 0; k < ret.count; k++) ret.slot[k].own = true;
    *out = ret;
}

bc_obj hfx_bc_obj_inputs(bc_gen *g, const ir_leaf *l, int n, const ir_var *p, const hfx_type *t) { return interface_obj(g, l, n, p, t, false); }
bc_obj hfx_bc_obj_outputs(bc_gen *g, const ir_leaf *l, int n, const ir_var *p, const hfx_type *t) { return interface_obj(g, l, n, p, t, true); }

void hfx_bc_bind_entry(bc_gen *g, const ir_var *p, bc_obj o, bool owned) {
    bc_binding *b = add_bind(g, p, o);
    if (b) b->owned = owned ? ~0ull : 0;
}

void hfx_bc_gen_body(bc_gen *g, const ir_stmt *body) { gen_body(g, body); }

bool hfx_bc_writes_param(bc_gen *g, const ir_func *f, const ir_var *p) {
    ir_var_set w = {0};
    if (f->body) hfx_ir_note_writes(g->c, f->body, &w);
    return w.unknown || hfx_ir_var_set_has(&w, p);
}
