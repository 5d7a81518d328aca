/* bc_flow.c: flow control as the model has it, for the loops the unroller cannot unroll (their
 * condition is not a constant). SM3: `loop aL, iN` over `defi iN, 255, start, step, 0` with a
 * `break_comp` on the negated condition, the counter kept in a temporary and the arrays it
 * indexes read as c[aL + n] (fxc's pattern); when those arrays' elements differ in size, aL
 * cannot follow them all, and the loop runs the smallest array's length of guarded copies
 * (`if_comp` on the condition). vs_2_0 / vs_2_a: `rep iN` over an int parameter (a static loop;
 * arrays read through a0). ps_2_x has no loops: X3511, as fxc says it.
 * A loop or if writes its variables into registers fixed before it ("pinned"): each pass moves
 * what the body computed back into them, so every pass, and the code after, finds them there. */
#include "bytecode/bc_int.h"

typedef struct bc_region { uint32_t n; uint32_t *idx; bc_obj *regs; uint64_t *owned; } bc_region;

enum { CMP_GT = 1, CMP_EQ = 2, CMP_GE = 3, CMP_LT = 4, CMP_NE = 5, CMP_LE = 6 };
enum { X_BC_NESTING = 5301 }; /* hfx's own code: flow nesting beyond the model's limit */

static bool same_val(const bc_val *a, const bc_val *b) {
    if (a->type != b->type || a->num != b->num || a->mod != b->mod || a->rel != b->rel || a->n != b->n) return false;
    for (unsigned i = 0; i < a->n; i++) if (a->sw[i] != b->sw[i]) return false;
    return true;
}

static bool owns(const bc_binding *x, uint32_t k) { return k >= 64 || (x->owned >> k & 1); }

/* The bindings s writes get temporaries of their own (a constant counter a register); their
 * registers are the region's. `skip`: a counter the caller keeps constant. */
static bc_region pin(bc_gen *g, const ir_stmt *s, const ir_var *skip) {
    ir_var_set w = {0};
    hfx_ir_note_writes(g->c, (ir_stmt *)s, &w);
    if (w.unknown || w.calls)
        for (uint32_t i = 0; i < g->bind_count; i++)
            if (g->binds[i].var->kind == IRV_PRIVATE) hfx_ir_var_set_add(g->c, &w, g->binds[i].var);
    uint32_t cap = w.count ? w.count : 1;
    bc_region r = {0, HFX_NEW_ARRAY(g->c->arena, uint32_t, cap), HFX_NEW_ARRAY(g->c->arena, bc_obj, cap),
                   HFX_NEW_ARRAY(g->c->arena, uint64_t, cap)};
    for (uint32_t i = 0; i < w.count && !g->failed; i++) {
        bc_binding *x = w.vars[i] ? hfx_bc_bind(g, w.vars[i]) : NULL;
        if (!x || x->var == skip) continue;
        if (x->is_const) {
            bc_val v = hfx_bc_own(g, hfx_bc_constf(g, (float)x->konst));
            x->is_const = false;
            x->obj = (bc_obj){HFX_NEW(g->c->arena, bc_val), 1, false};
            x->obj.slot[0] = v;
            x->obj.slot[0].own = false;
            x->owned = ~0ull;
        }
        if (!x->obj.count) continue;
        bc_val *slots = HFX_NEW_ARRAY(g->c->arena, bc_val, x->obj.count);
        memcpy(slots, x->obj.slot, x->obj.count * sizeof *slots);
        x->obj.slot = slots;
        for (uint32_t k = 0; k < x->obj.count; k++) {
            bc_val v = slots[k];
            if (v.type == D3D9_REG_TEMP && owns(x, k) && !v.rel) continue;
            int t = hfx_bc_temp(g);
            bc_val d = hfx_bc_reg(D3D9_REG_TEMP, (uint16_t)(t < 0 ? 0 : t), v.n);
            v.own = false;
            hfx_bc_store(g, d, v, false);
            slots[k] = d;
            if (k < 64) x->owned |= 1ull << k;
        }
        bc_obj c = {HFX_NEW_ARRAY(g->c->arena, bc_val, x->obj.count), x->obj.count, x->obj.cols};
        memcpy(c.slot, slots, x->obj.count * sizeof *slots);
        r.idx[r.n] = (uint32_t)(x - g->binds);
        r.regs[r.n] = c;
        r.owned[r.n++] = x->owned;
    }
    return r;
}

/* What the bindings hold now, moved into the region's registers. */
static void sync(bc_gen *g, const bc_region *r) {
    for (uint32_t i = 0; i < r->n && !g->failed; i++) {
        bc_binding *x = &g->binds[r->idx[i]];
        for (uint32_t k = 0; k < x->obj.count && k < r->regs[i].count; k++) {
            bc_val cur = x->obj.slot[k], want = r->regs[i].slot[k];
            if (same_val(&cur, &want)) continue;
            cur.own = false;
            hfx_bc_store(g, want, cur, false);
        }
    }
}

static bool in_region(const bc_region *r, uint16_t num) {
    for (uint32_t i = 0; i < r->n; i++)
        for (uint32_t k = 0; k < r->regs[i].count; k++)
            if (r->regs[i].slot[k].type == D3D9_REG_TEMP && r->regs[i].slot[k].num == num) return true;
    return false;
}

/* The bindings name the region's registers again; temporaries they took meanwhile are freed. */
static void restore(bc_gen *g, const bc_region *r) {
    for (uint32_t i = 0; i < r->n; i++) {
        bc_binding *x = &g->binds[r->idx[i]];
        for (uint32_t k = 0; k < x->obj.count && k < r->regs[i].count; k++) {
            bc_val cur = x->obj.slot[k];
            if (!same_val(&cur, &r->regs[i].slot[k]) && cur.type == D3D9_REG_TEMP && owns(x, k) && !in_region(r, cur.num)) {
                cur.own = true;
                hfx_bc_release(g, cur);
            }
        }
        bc_val *slots = HFX_NEW_ARRAY(g->c->arena, bc_val, r->regs[i].count ? r->regs[i].count : 1);
        memcpy(slots, r->regs[i].slot, r->regs[i].count * sizeof *slots);
        x->obj = (bc_obj){slots, r->regs[i].count, r->regs[i].cols};
        x->owned = r->owned[i];
    }
}

static d3d9_inst *emit_flow(bc_gen *g, uint16_t op, const bc_val *src, unsigned n) {
    g->has_flow = true;
    d3d9_inst *in = hfx_bc_emit(g, op, NULL, 0, src, n);
    for (unsigned i = 0; in && i < n; i++)
        if (src[i].type == D3D9_REG_LOOP || src[i].type == D3D9_REG_CONSTINT) in->src[i].swizzle = 0xe4;
    return in;
}

static const ir_expr *strip(const ir_expr *e) {
    while (e && e->kind == IE_CONVERT && e->type->kind == TY_SCALAR) e = e->a[0];
    return e;
}

static bool relational(hfx_op op) { return op == OP_LT || op == OP_LE || op == OP_GT || op == OP_GE || op == OP_EQ || op == OP_NE; }

/* break_comp / if_comp on e (negated: on !e): a scalar comparison as its own comparison,
 * anything else as e != 0. */
static void cond_op(bc_gen *g, const ir_expr *e, bool negate, uint16_t op) {
    static const uint8_t ctl[][2] = {[OP_LT] = {CMP_LT, CMP_GE}, [OP_LE] = {CMP_LE, CMP_GT}, [OP_GT] = {CMP_GT, CMP_LE},
                                     [OP_GE] = {CMP_GE, CMP_LT}, [OP_EQ] = {CMP_EQ, CMP_NE}, [OP_NE] = {CMP_NE, CMP_EQ}};
    bc_val s[2];
    uint8_t control;
    if (e->kind == IE_BINARY && relational(e->op) && e->a[0]->type->kind == TY_SCALAR && e->a[1]->type->kind == TY_SCALAR) {
        s[0] = hfx_bc_expr1(g, e->a[0]);
        s[1] = hfx_bc_expr1(g, e->a[1]);
        control = ctl[e->op][negate];
    } else {
        s[0] = hfx_bc_expr1(g, e);
        s[0] = hfx_bc_scalar_of(s[0], 0);
        s[0].own = false;
        s[1] = hfx_bc_constf(g, 0);
        control = negate ? CMP_EQ : CMP_NE;
    }
    d3d9_inst *in = emit_flow(g, op, s, 2);
    if (in) in->control = control;
    hfx_bc_release(g, s[0]);
    hfx_bc_release(g, s[1]);
}

/* --- what a loop looks like --- */

/* for (i = start; i op bound; i += step) with i a constant counter the body leaves alone and a
 * bound of parameters or literals. */
typedef struct shape { const ir_var *i; double start, step; hfx_op op; const ir_expr *bound; } shape;

static bool invariant(const ir_expr *e) {
    e = strip(e);
    return e->kind == IE_CONST || (e->kind == IE_VAR && e->var->kind == IRV_UNIFORM);
}

static bool canonical(bc_gen *g, const ir_stmt *s, shape *sh) {
    const ir_expr *c = s->expr, *st = s->step;
    if (s->kind != IS_FOR || !c || !st || c->kind != IE_BINARY || !relational(c->op)) return false;
    const ir_expr *v = strip(c->a[0]);
    if (v->kind != IE_VAR || !invariant(c->a[1])) return false;
    bc_binding *b = hfx_bc_bind(g, v->var);
    if (!b || !b->is_const) return false;
    const ir_expr *t = st->n ? st->a[0] : NULL;
    if (!t || t->kind != IE_VAR || t->var != v->var) return false;
    double k = 0;
    if (st->kind == IE_UNARY && (st->op == OP_PREINC || st->op == OP_POSTINC)) k = 1;
    else if (st->kind == IE_UNARY && (st->op == OP_PREDEC || st->op == OP_POSTDEC)) k = -1;
    else if (st->kind == IE_ASSIGN && (st->op == OP_ADD || st->op == OP_SUB) && hfx_bc_try_const(g, st->a[1], &k)) k = st->op == OP_SUB ? -k : k;
    else return false;
    if (k == 0 || k != (double)hfx_ev_int(k)) return false;
    ir_var_set w = {0};
    hfx_ir_note_writes(g->c, s->then_s, &w);
    if (w.unknown || hfx_ir_var_set_has(&w, v->var)) return false;
    *sh = (shape){v->var, b->konst, k, c->op, c->a[1]};
    return true;
}

/* The arrays the body indexes by the counter: how many, their elements' registers (0: they
 * differ), the shortest length, and whether each is a parameter aL can index. */
typedef struct uses { bc_gen *g; const ir_var *i; uint32_t count, per, len; bool params; } uses;

static void note_index(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    uses *u = data;
    const ir_expr *e = *slot, *ix;
    if (e->kind != IE_INDEX || e->a[0]->type->kind != TY_ARRAY) return;
    ix = strip(e->a[1]);
    if (ix->kind != IE_VAR || ix->var != u->i) return;
    const ir_expr *base = e->a[0];
    bc_binding *b = base->kind == IE_VAR ? hfx_bc_bind(u->g, base->var) : NULL;
    bool param = b && b->var->kind == IRV_UNIFORM;
    uint32_t per = hfx_bc_slots(base->type->elem, b ? b->obj.cols : false);
    u->params &= param;
    u->per = u->count == 0 ? per : u->per == per ? per : 0;
    if (!u->count || base->type->array_len < u->len) u->len = base->type->array_len;
    u->count++;
}

/* A break of this loop in s (not of loops inside it). */
static bool breaks(const ir_stmt *s) {
    if (!s) return false;
    switch (s->kind) {
    case IS_BREAK: return true;
    case IS_BLOCK:
        for (uint32_t i = 0; i < s->count; i++) if (breaks(s->body[i])) return true;
        return false;
    case IS_IF: return breaks(s->then_s) || breaks(s->else_s);
    default: return false;
    }
}

static bool nest(bc_gen *g, hfx_loc loc, bool loop) {
    unsigned limit = loop ? (g->model == D3D9_SM(2, 0) ? 1 : 4) : 24, depth = loop ? g->loop_nest : g->if_nest;
    if (depth < limit) return true;
    hfx_bc_fail(g, loc, X_BC_NESTING, "%s nesting exceeds the limit of %s (%u)", loop ? "loop" : "dynamic if",
                g->profile, limit);
    return false;
}

static uint16_t defi(bc_gen *g, int32_t a, int32_t b, int32_t c) {
    for (uint32_t i = 0; i < g->defi_count; i++)
        if (g->defis[i].v[0] == a && g->defis[i].v[1] == b && g->defis[i].v[2] == c) return g->defis[i].num;
    if (!HFX_ARENA_GROW(g->c->arena, g->defis, g->defi_count, g->defi_cap, 4)) return 0;
    g->defis[g->defi_count] = (struct bc_defi){{a, b, c, 0}, g->next_int};
    g->defi_count++;
    return g->next_int++;
}

/* The i register of an int parameter (CTAB: INT4 set). */
static uint16_t int_param(bc_gen *g, const ir_var *v) {
    for (uint32_t i = 0; i < g->ctab_count; i++)
        if (g->ctab[i].set == D3D9_RS_INT4 && strcmp(g->ctab[i].name, v->name) == 0) return g->ctab[i].reg;
    uint16_t r = g->next_int++;
    if (HFX_ARENA_GROW(g->c->arena, g->ctab, g->ctab_count, g->ctab_cap, 8))
        g->ctab[g->ctab_count++] = (bc_ctab){v->name, v->type, D3D9_RS_INT4, r, 1, false};
    return r;
}

enum loop_kind { LOOP_AL, LOOP_REP, LOOP_REP_PARAM };

typedef struct reads { const ir_var *v; bool found; } reads;
static void note_read(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    reads *r = data;
    r->found |= (*slot)->kind == IE_VAR && (*slot)->var == r->v;
}

static void real_loop(bc_gen *g, const ir_stmt *s, const shape *sh, enum loop_kind kind, uint32_t per) {
    if (!nest(g, s->loc, true)) return;
    reads rd = {sh->i, kind != LOOP_REP_PARAM}; /* rep counts by itself: a counter nothing reads is not kept */
    if (!rd.found) hfx_ir_walk_stmt_exprs(g->c, s->then_s, note_read, &rd);
    bc_region r = pin(g, s, rd.found ? NULL : sh->i);
    bc_val src[2] = {hfx_bc_reg(D3D9_REG_LOOP, 0, 4), hfx_bc_reg(D3D9_REG_CONSTINT, 0, 4)};
    if (kind == LOOP_AL) src[1].num = defi(g, 255, hfx_ev_int(sh->start * per), hfx_ev_int(sh->step * per));
    else if (kind == LOOP_REP) src[1].num = defi(g, 255, 0, 0);
    else src[1].num = int_param(g, strip(sh->bound)->var);
    if (kind == LOOP_AL) emit_flow(g, D3D9_LOOP, src, 2);
    else emit_flow(g, D3D9_REP, src + 1, 1);
    const ir_var *aL = g->aL_var;
    uint32_t aL_per = g->aL_per, fn = g->loop_fn_depth;
    bc_region *outer = g->loop_region;
    if (kind == LOOP_AL) { g->aL_var = sh->i; g->aL_per = per; }
    g->loop_region = &r;
    g->loop_fn_depth = g->depth;
    g->loop_nest++;
    if (kind != LOOP_REP_PARAM) cond_op(g, s->expr, true, D3D9_BREAKC);
    hfx_bc_gen_body(g, s->then_s);
    g->broke = false;
    if (s->step && rd.found && !g->failed) hfx_bc_release_obj(g, hfx_bc_expr(g, s->step));
    sync(g, &r);
    emit_flow(g, kind == LOOP_AL ? D3D9_ENDLOOP : D3D9_ENDREP, NULL, 0);
    restore(g, &r);
    g->loop_nest--;
    g->loop_region = outer;
    g->loop_fn_depth = fn;
    g->aL_var = aL;
    g->aL_per = aL_per;
}

/* Copies k = 0 .. len - 1 of the body, each under `if_comp` on the condition with the counter
 * a constant: a counter that moves towards its bound fails its test once and for good. */
static void guarded(bc_gen *g, const ir_stmt *s, const shape *sh, uint32_t len) {
    bc_region *outer = g->loop_region;
    g->loop_region = NULL;
    for (uint32_t it = 0; it < len && !g->failed; it++) {
        double k;
        if (hfx_bc_try_const(g, s->expr, &k) && !k) break;
        if (!nest(g, s->loc, false)) break;
        bc_region r = pin(g, s->then_s, sh->i);
        cond_op(g, s->expr, false, D3D9_IFC);
        g->if_nest++;
        hfx_bc_gen_body(g, s->then_s);
        sync(g, &r);
        emit_flow(g, D3D9_ENDIF, NULL, 0);
        restore(g, &r);
        g->if_nest--;
        bc_binding *b = hfx_bc_bind(g, sh->i);
        if (b) b->konst += sh->step;
    }
    g->loop_region = outer;
}

bool hfx_bc_flow_loop(bc_gen *g, const ir_stmt *s) {
    double k;
    if (s->kind == IS_DO || !s->expr || hfx_bc_try_const(g, s->expr, &k)) return false;
    shape sh = {0};
    bool canon = canonical(g, s, &sh);
    uses u = {g, canon ? sh.i : NULL, 0, 0, 0, true};
    if (canon) hfx_ir_walk_stmt_exprs(g->c, (ir_stmt *)s->then_s, note_index, &u);
    if (g->model >= D3D9_SM(3, 0)) {
        uint32_t per = u.count ? u.per : 1;
        bool fits = per && sh.start * per >= 0 && sh.start * per <= 255 && sh.step * per >= -128 && sh.step * per <= 127;
        bool toward = (sh.step > 0 && (sh.op == OP_LT || sh.op == OP_LE)) || (sh.step < 0 && (sh.op == OP_GT || sh.op == OP_GE));
        if (canon && u.params && fits) real_loop(g, s, &sh, LOOP_AL, per);
        else if (canon && u.count && toward && !breaks(s->then_s)) guarded(g, s, &sh, u.len);
        else real_loop(g, s, &sh, LOOP_REP, 1);
        return true;
    }
    const ir_expr *bound = canon ? strip(sh.bound) : NULL;
    if (g->stage == D3D9_VS && canon && sh.start == 0 && sh.step == 1 && sh.op == OP_LT && bound->kind == IE_VAR &&
        bound->type->kind == TY_SCALAR && (bound->type->base == B_INT || bound->type->base == B_UINT) && !breaks(s->then_s)) {
        real_loop(g, s, &sh, LOOP_REP_PARAM, 1);
        return true;
    }
    hfx_bc_fail(g, s->loc, X_BC_LOOP, "unable to unroll loop, loop does not appear to terminate in a timely manner (1024 iterations)");
    return true;
}

bool hfx_bc_flow_if(bc_gen *g, const ir_stmt *s) {
    if (!g->loop_region || g->depth != g->loop_fn_depth || !breaks(s)) return false;
    const ir_stmt *t = s->then_s;
    while (t && t->kind == IS_BLOCK && t->count == 1) t = t->body[0];
    if (!s->else_s && t && t->kind == IS_BREAK) { /* if (c) break; */
        sync(g, g->loop_region);
        cond_op(g, s->expr, false, D3D9_BREAKC);
        return true;
    }
    if (!nest(g, s->loc, false)) return true;
    bc_region r = pin(g, s, NULL);
    cond_op(g, s->expr, false, D3D9_IFC);
    g->if_nest++;
    hfx_bc_gen_body(g, s->then_s);
    g->broke = false;
    sync(g, &r);
    if (s->else_s) {
        emit_flow(g, D3D9_ELSE, NULL, 0);
        restore(g, &r);
        hfx_bc_gen_body(g, s->else_s);
        g->broke = false;
        sync(g, &r);
    }
    emit_flow(g, D3D9_ENDIF, NULL, 0);
    restore(g, &r);
    g->if_nest--;
    return true;
}

void hfx_bc_flow_break(bc_gen *g, const ir_stmt *s) {
    (void)s;
    sync(g, g->loop_region);
    emit_flow(g, D3D9_BREAK, NULL, 0);
    g->broke = true;
}

bool hfx_bc_loop_index(bc_gen *g, bc_obj o, const ir_expr *idx, uint32_t per, bc_obj *out) {
    idx = strip(idx);
    if (!g->aL_var || idx->kind != IE_VAR || idx->var != g->aL_var || per != g->aL_per || !o.count ||
        o.slot[0].type != D3D9_REG_CONST || o.slot[0].rel)
        return false;
    *out = (bc_obj){HFX_NEW_ARRAY(g->c->arena, bc_val, per), per, o.cols};
    for (uint32_t k = 0; k < per; k++) {
        out->slot[k] = o.slot[k];
        out->slot[k].rel = out->slot[k].rel_aL = true;
        out->slot[k].own = false;
    }
    return true;
}
