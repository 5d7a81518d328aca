/* bc_aggregate.c: structs and arrays as values (their slots in order, each a register view or a
 * temporary), casts between shapes (components in order), and indexes the compiler cannot fold.
 * D3D9 cannot address a temporary (and ps_2_x / ps_3_0 outside a loop cannot address constants),
 * so, as fxc does, a computed read is a chain of selects over the elements (element k taken where
 * the index is at least k - 0.5: the last that holds wins) and a computed write updates every
 * element, each under "index == k". Vertex shaders read parameter arrays as c[a0.x + n]. */
#include "bytecode/bc_int.h"

static bc_obj new_obj(bc_gen *g, uint32_t n) {
    bc_obj o = {HFX_NEW_ARRAY(g->c->arena, bc_val, n ? n : 1), n, false};
    return o;
}

bool hfx_bc_has_matrix(const hfx_type *t) {
    switch (t->kind) {
    case TY_MATRIX: return true;
    case TY_ARRAY: return hfx_bc_has_matrix(t->elem);
    case TY_STRUCT:
        for (uint32_t i = 0; i < t->st->field_count; i++) if (hfx_bc_has_matrix(t->st->fields[i].type)) return true;
        return false;
    default: return false;
    }
}

/* --- components in order --- */

enum { MAX_COMPS = 1024 };

/* The one-component views of o (of type t, from slot *at) in HLSL's order: fields, elements,
 * matrices by rows. */
static void components(const bc_obj *o, const hfx_type *t, uint32_t *at, bc_val *out, uint32_t *n) {
    switch (t->kind) {
    case TY_ARRAY:
        for (uint32_t i = 0; i < t->array_len; i++) components(o, t->elem, at, out, n);
        return;
    case TY_STRUCT:
        for (uint32_t i = 0; i < t->st->field_count; i++) components(o, t->st->fields[i].type, at, out, n);
        return;
    case TY_MATRIX:
        for (unsigned r = 0; r < t->rows; r++)
            for (unsigned c = 0; c < t->cols; c++) {
                uint32_t k = *at + (o->cols ? c : r);
                if (k < o->count && *n < MAX_COMPS) out[(*n)++] = hfx_bc_scalar_of(o->slot[k], o->cols ? r : c);
            }
        *at += o->cols ? t->cols : t->rows;
        return;
    default: {
        unsigned w = t->kind == TY_VECTOR ? t->cols : 1;
        for (unsigned c = 0; c < w && *at < o->count && *n < MAX_COMPS; c++) out[(*n)++] = hfx_bc_scalar_of(o->slot[*at], c);
        (*at)++;
        return;
    }
    }
}

static bool same_reg(const bc_val *a, const bc_val *b) {
    return a->type == b->type && a->num == b->num && a->mod == b->mod && a->rel == b->rel && a->rel_aL == b->rel_aL;
}

/* One slot of n components: a view when they all come from one register (read as a swizzle),
 * else gathered into a temporary. */
static bc_val slot_of(bc_gen *g, const bc_val *parts, unsigned n, bool may_view) {
    bool one_reg = may_view;
    for (unsigned i = 1; i < n && one_reg; i++) one_reg = same_reg(&parts[i], &parts[0]);
    if (!one_reg) return hfx_bc_gather(g, parts, n);
    bc_val v = parts[0];
    for (unsigned i = 0; i < n; i++) v.sw[i] = parts[i].sw[0];
    for (unsigned i = n; i < 4; i++) v.sw[i] = v.sw[n - 1];
    v.n = (uint8_t)n;
    v.own = false;
    return v;
}

/* A value of type t (rows) from the components comps[*pos...]. */
static void regroup(bc_gen *g, const hfx_type *t, const bc_val *comps, uint32_t count, uint32_t *pos, bc_obj *o, bool may_view) {
    for (uint32_t k = 0; k < o->count && !g->failed; k++) {
        unsigned w = hfx_bc_slot_width(t, false, k);
        if (*pos + w > count) {
            hfx_bc_fail(g, g->loc, X_BC_UNSUPPORTED, "the bytecode writer found too few components for this cast");
            return;
        }
        o->slot[k] = slot_of(g, comps + *pos, w, may_view);
        *pos += w;
    }
}

/* Whether any slot of o owns its temporary (its views could not outlive it). */
static bool owns_any(const bc_obj *o) {
    for (uint32_t k = 0; k < o->count; k++) if (o->slot[k].own) return true;
    return false;
}

/* (T)x between shapes of as many components or fewer (a struct, an array, float1x4 from a
 * float4...): x's components regrouped into T's slots. */
bc_obj hfx_bc_reshape(bc_gen *g, const ir_expr *e) {
    const hfx_type *to = e->type, *from = e->a[0]->type;
    bc_obj src = hfx_bc_expr(g, e->a[0]);
    bc_val *comps = HFX_NEW_ARRAY(g->c->arena, bc_val, MAX_COMPS);
    uint32_t n = 0, at = 0, pos = 0;
    components(&src, from, &at, comps, &n);
    if (hfx_type_components(to) > n) {
        hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "the bytecode writer does not convert between these types yet");
        return src;
    }
    bool owned = owns_any(&src);
    bc_obj o = new_obj(g, hfx_bc_slots(to, false));
    regroup(g, to, comps, n, &pos, &o, !owned); /* an owned source is copied, then freed */
    if (owned) hfx_bc_release_obj(g, src);
    return o;
}

/* o in the row layout (a column_major member's columns turned into rows). */
static bc_obj rows_of(bc_gen *g, bc_obj o, const hfx_type *t) {
    if (!o.cols || !hfx_bc_has_matrix(t)) { o.cols = false; return o; }
    bc_val *comps = HFX_NEW_ARRAY(g->c->arena, bc_val, MAX_COMPS);
    uint32_t n = 0, at = 0, pos = 0;
    components(&o, t, &at, comps, &n);
    bool owned = owns_any(&o);
    bc_obj r = new_obj(g, hfx_bc_slots(t, false));
    regroup(g, t, comps, n, &pos, &r, !owned);
    if (owned) hfx_bc_release_obj(g, o);
    return r;
}

/* T(a, b, ...) for a struct (one argument per field) or an array (one per element): the
 * arguments' slots side by side, each keeping its temporary. */
bc_obj hfx_bc_construct_aggregate(bc_gen *g, const ir_expr *e) {
    bc_obj o = new_obj(g, hfx_bc_slots(e->type, false));
    uint32_t at = 0;
    for (uint32_t i = 0; i < e->n && !g->failed; i++) {
        bc_obj a = rows_of(g, hfx_bc_expr(g, e->a[i]), e->a[i]->type);
        uint32_t want = hfx_bc_slots(e->a[i]->type, false);
        for (uint32_t k = 0; k < want && k < a.count && at < o.count; k++) o.slot[at++] = a.slot[k];
    }
    if (at != o.count && !g->failed)
        hfx_bc_fail(g, e->loc, X_BC_UNSUPPORTED, "the bytecode writer does not construct this value yet");
    return o;
}

/* --- computed reads --- */

bool hfx_bc_addressable(const bc_gen *g, bc_obj o) {
    if (g->stage != D3D9_VS || !o.count) return false;
    for (uint32_t k = 0; k < o.count; k++) {
        const bc_val *v = &o.slot[k];
        if (v->type != D3D9_REG_CONST || v->rel || v->num != o.slot[0].num + k || v->sw[0] != 0) return false;
    }
    return true;
}

/* The element count of t and each element's slots (in o's layout). */
static uint32_t elements(const hfx_type *t, bool cols, uint32_t *per) {
    *per = t->kind == TY_ARRAY ? hfx_bc_slots(t->elem, cols) : 1;
    return t->kind == TY_ARRAY ? t->array_len : t->kind == TY_MATRIX ? t->rows : t->kind == TY_VECTOR ? t->cols : 1;
}

/* Slot s of element k: a component, a matrix row (gathered from columns), an array's slot. */
static bc_val element(bc_gen *g, bc_obj o, const hfx_type *t, uint32_t per, uint32_t k, uint32_t s) {
    if (t->kind == TY_VECTOR) return hfx_bc_scalar_of(o.slot[0], k);
    if (t->kind == TY_MATRIX) {
        bc_val r = hfx_bc_matrix_row(g, o, t, k);
        if (!o.cols) r.own = false;
        return r;
    }
    bc_val v = o.slot[k * per + s];
    v.own = false;
    return v;
}

/* A scalar that is >= 0 where index >= k - 0.5 (pixel: for cmp), or 1 there and 0 elsewhere
 * (vertex: for lrp). */
static bc_val at_least(bc_gen *g, bc_val i, uint32_t k) {
    i.own = false;
    if (g->stage == D3D9_PS) return hfx_bc_op2(g, D3D9_ADD, 1, i, hfx_bc_constf(g, 0.5f - (float)k));
    return hfx_bc_op2(g, D3D9_SGE, 1, i, hfx_bc_constf(g, (float)k - 0.5f));
}

bc_obj hfx_bc_index_select(bc_gen *g, bc_obj o, const hfx_type *t, const ir_expr *idx) {
    uint32_t per, n = elements(t, o.cols, &per);
    if (!n || !o.count) return o;
    bc_val i = hfx_bc_expr1(g, idx);
    bc_obj r = new_obj(g, per);
    r.cols = t->kind == TY_ARRAY && o.cols;
    for (uint32_t s = 0; s < per; s++) r.slot[s] = element(g, o, t, per, 0, s);
    for (uint32_t k = 1; k < n && !g->failed; k++) {
        bc_val d = at_least(g, i, k);
        for (uint32_t s = 0; s < per; s++) {
            bc_val x = element(g, o, t, per, k, s), dd = d;
            dd.own = false;
            r.slot[s] = hfx_bc_op3(g, g->stage == D3D9_PS ? D3D9_CMP : D3D9_LRP, x.n, dd, x, r.slot[s]);
        }
        hfx_bc_release(g, d);
    }
    hfx_bc_release(g, i);
    if (n > 1) hfx_bc_release_obj(g, o);
    return r;
}

/* --- computed writes --- */

/* The outermost index of the l-value e's path (fields, swizzles, indexes) the compiler cannot
 * fold, and how many steps down the path it is. */
static const ir_expr *computed_index(bc_gen *g, const ir_expr *e, uint32_t *depth) {
    *depth = 0;
    for (const ir_expr *p = e;; p = p->a[0], (*depth)++) {
        double k;
        if (p->kind == IE_INDEX && !hfx_bc_try_const(g, p->a[1], &k)) return p;
        if (p->kind != IE_INDEX && p->kind != IE_SWIZZLE && p->kind != IE_FIELD) return NULL;
    }
}

/* e with the index `depth` steps down its path replaced by the constant k. */
static ir_expr *with_index(bc_gen *g, const ir_expr *e, uint32_t depth, uint32_t k) {
    ir_expr *r = hfx_ir_clone_expr(g->c, e), *p = r;
    for (uint32_t d = 0; d < depth; d++) p = p->a[0];
    p->a[1] = hfx_ir_const_scalar(g->c, p->a[1]->type, k, p->a[1]->loc);
    return r;
}

/* 1 where i == k, else 0; raw (pixel shaders): -(i - k)^2, >= 0 only where i == k, for cmp. */
static bc_val equals(bc_gen *g, bc_val i, uint32_t k, bool raw) {
    i.own = false;
    bc_val d = k ? hfx_bc_op2(g, D3D9_ADD, 1, i, hfx_bc_constf(g, -(float)k)) : i, dd = d;
    dd.own = false;
    bc_val sq = hfx_bc_op2(g, D3D9_MUL, 1, d, dd), s2 = sq;
    s2.own = false;
    if (raw) return hfx_bc_neg(sq);
    if (g->stage == D3D9_VS) return hfx_bc_op2(g, D3D9_SGE, 1, hfx_bc_neg(sq), s2);
    return hfx_bc_op3(g, D3D9_CMP, 1, hfx_bc_neg(sq), hfx_bc_constf(g, 1), hfx_bc_constf(g, 0));
}

/* lhs (no computed index left) = cond ? lhs op src : lhs (raw: cond >= 0 instead of cond == 1). */
static void store_if(bc_gen *g, const ir_expr *lhs, hfx_op op, bc_obj src, bc_val cond, bool raw) {
    bc_lval l;
    if (!hfx_bc_lval(g, lhs, &l)) {
        hfx_bc_fail(g, lhs->loc, X_BC_UNSUPPORTED, "the bytecode writer does not write this l-value by a computed index yet");
        return;
    }
    bc_obj cur = op != OP_NONE ? hfx_bc_expr(g, lhs) : src;
    for (uint32_t s = 0; s < l.count && s < src.count && !g->failed; s++) {
        bc_val v = src.slot[s];
        v.own = false;
        if (op != OP_NONE) {
            bc_val c = cur.slot[s];
            c.own = false;
            v = hfx_bc_binary(g, op, c, v, lhs->type);
        }
        uint32_t at = l.first + s;
        hfx_bc_own_slot(g, l.b, at, true);
        bc_val t = l.b->obj.slot[at];
        if (l.n) {
            t.n = l.n;
            for (unsigned j = 0; j < l.n; j++) t.sw[j] = l.b->obj.slot[at].sw[l.comps[j]];
        }
        bc_val old = t, c = cond;
        old.own = c.own = false;
        hfx_bc_store(g, t, raw ? hfx_bc_op3(g, D3D9_CMP, t.n, c, v, old) : hfx_bc_select(g, c, v, old), false);
    }
}

/* lhs op= src, each element of the outermost computed index under "index == k" (and cond). */
static void store_dynamic(bc_gen *g, const ir_expr *lhs, hfx_op op, bc_obj src, bc_val cond) {
    uint32_t depth;
    const ir_expr *p = computed_index(g, lhs, &depth);
    if (!p) { store_if(g, lhs, op, src, cond, false); return; }
    uint32_t per, n = elements(p->a[0]->type, false, &per);
    bc_val i = hfx_bc_expr1(g, p->a[1]);
    uint32_t inner;
    bool raw = g->stage == D3D9_PS && !cond.n && !computed_index(g, with_index(g, lhs, depth, 0), &inner);
    for (uint32_t k = 0; k < n && !g->failed; k++) {
        bc_val c = equals(g, i, k, raw);
        if (raw) {
            store_if(g, with_index(g, lhs, depth, k), op, src, c, true);
            c.mod = 0;
            hfx_bc_release(g, c);
            continue;
        }
        if (cond.n) {
            bc_val oc = cond;
            oc.own = false;
            c = hfx_bc_op2(g, D3D9_MUL, 1, oc, c);
        }
        store_dynamic(g, with_index(g, lhs, depth, k), op, src, c);
        hfx_bc_release(g, c);
    }
    hfx_bc_release(g, i);
}

bool hfx_bc_assign_dynamic(bc_gen *g, const ir_expr *e, bc_obj *out) {
    uint32_t depth;
    if (!computed_index(g, e->a[0], &depth)) return false;
    bc_obj src = rows_of(g, hfx_bc_expr(g, e->a[1]), e->a[1]->type);
    store_dynamic(g, e->a[0], e->op, src, (bc_val){0});
    if (e->op == OP_NONE) { *out = src; return true; } /* the value assigned (no read back of every element) */
    hfx_bc_release_obj(g, src);
    *out = hfx_bc_expr(g, e->a[0]);
    return true;
}

/* --- layouts --- */

static void assign_member(bc_gen *g, bc_obj dst, bc_obj src, const hfx_type *t, bool sat, uint32_t *ds, uint32_t *ss) {
    if (t->kind == TY_STRUCT) {
        for (uint32_t i = 0; i < t->st->field_count; i++) assign_member(g, dst, src, t->st->fields[i].type, sat, ds, ss);
        return;
    }
    if (t->kind == TY_ARRAY) {
        for (uint32_t i = 0; i < t->array_len; i++) assign_member(g, dst, src, t->elem, sat, ds, ss);
        return;
    }
    uint32_t dn = hfx_bc_slots(t, dst.cols), sn = hfx_bc_slots(t, src.cols);
    if (*ds + dn <= dst.count && *ss + sn <= src.count)
        hfx_bc_assign(g, (bc_obj){dst.slot + *ds, dn, dst.cols}, (bc_obj){src.slot + *ss, sn, src.cols}, t, sat);
    *ds += dn;
    *ss += sn;
}

void hfx_bc_assign_members(bc_gen *g, bc_obj dst, bc_obj src, const hfx_type *t, bool sat) {
    uint32_t ds = 0, ss = 0;
    assign_member(g, dst, src, t, sat, &ds, &ss);
}
