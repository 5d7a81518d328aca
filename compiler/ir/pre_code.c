/* pre_code.c: the one writer of common/eval_code programs. A uniform-only expression
 * (parameters and constants, no varyings, textures or locals) as a program the runtime runs on
 * the CPU: a preshader, as fxc makes them, rerun when one of its parameters changed, and a
 * state value that reads parameters (effect/build_code.c builds it as IR), run at Apply. Also
 * the readable HLSL for the comment the GLSL carries beside a preshader's register.
 * lower/preshade.c decides what is hoisted. */
#include <string.h>

#include "base/sbuf.h"
#include "eval_code.h"
#include "ir/ir.h"

/* ---- which expressions a preshader computes ---- */

static bool numeric_base(const hfx_type *t) { return hfx_type_is_numeric(t) && t->base != B_UINT && t->base < B_NONE; }

/* A parameter read whole (PARAM): a numeric non-array top-level parameter. (A uniform the
 * stage writes is read through its private copy, so a read of the uniform itself is the
 * parameter.) */
static bool param_leaf(const ir_ctx *c, const ir_var *v) {
    if (v->kind != IRV_UNIFORM || v->param == HFX_NONE || v->param >= c->fx->param_count) return false;
    const hfx_fx_param *p = &c->fx->params[v->param];
    return !p->elements && hfx_fx_param_evaluable(p) && numeric_base(v->type) && p->words == hfx_type_components(v->type);
}

/* A parameter array of numeric elements (ELEMENT), read at an index. */
static const hfx_fx_param *param_array(const ir_ctx *c, const ir_expr *e) {
    if (e->kind != IE_VAR || e->var->kind != IRV_UNIFORM || e->var->param >= c->fx->param_count) return NULL;
    const hfx_fx_param *p = &c->fx->params[e->var->param];
    if (!p->elements || p->first_child == HFX_NONE || e->type->kind != TY_ARRAY || !numeric_base(e->type->elem)) return NULL;
    const hfx_fx_param *el = &c->fx->params[p->first_child];
    return hfx_fx_param_evaluable(el) && el->words == hfx_type_components(e->type->elem) ? p : NULL;
}

/* Inner sizes agree (the checker made them: a truncated matrix is an explicit conversion). */
static bool mul_shapes(const ir_expr *e) {
    if (e->n != 2) return false;
    const hfx_type *x = e->a[0]->type, *y = e->a[1]->type;
    if (!hfx_type_is_numeric(x) || !hfx_type_is_numeric(y)) return false;
    if (x->kind == TY_SCALAR || y->kind == TY_SCALAR) return true;
    unsigned inner = y->kind == TY_VECTOR ? y->cols : y->rows;
    return x->cols == inner && x->rows <= 4 && inner <= 4 && y->cols <= 4;
}

static bool intrinsic_ok(const ir_expr *e) {
    if (e->intrin == HFX_INTR_MUL) return mul_shapes(e);
    if (e->intrin == HFX_INTR_TRANSPOSE) return e->n == 1;
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of((int)e->intrin);
    return info && info->fold != HFX_EV_FN_NONE && (int)e->n == hfx_ev_fn_args(info->fold);
}

/* value: a state value's operation, not a preshader's. */
static bool binary_ok(const ir_expr *e, bool value) {
    hfx_ev_op op;
    if (!hfx_op_ev(e->op, &op)) return false;
    /* an integer division by zero has no value the CPU could agree with the GPU on; a state
     * value has no GPU side (`VertexShader = (VSArray[Index / 2]);`): the runtime does not fold
     * one by zero and keeps the state's last value */
    return value || !((op == HFX_EV_DIV || op == HFX_EV_MOD) && e->type->base != B_FLOAT && e->type->base != B_HALF);
}

/* e computes from operands the writer computes (hfx_ir_pre_node); value: in a state value. */
static bool node_ok(const ir_ctx *c, const ir_expr *e, bool value) {
    if (e->kind != IE_INDEX && e->kind != IE_VAR && !numeric_base(e->type)) return false;
    switch (e->kind) {
    case IE_CONST: return true;
    case IE_VAR: return param_leaf(c, e->var) || param_array(c, e) != NULL;
    case IE_UNARY: return e->op == OP_NEG || e->op == OP_POS || e->op == OP_NOT || e->op == OP_BITNOT;
    case IE_BINARY: return binary_ok(e, value);
    case IE_SELECT: case IE_CONSTRUCT: case IE_SWIZZLE: return true;
    case IE_CONVERT: return hfx_type_is_numeric(e->a[0]->type);
    case IE_INTRIN: return intrinsic_ok(e);
    case IE_INDEX:
        if (!numeric_base(e->type)) return false;
        if (e->a[0]->kind == IE_VAR && param_array(c, e->a[0])) return true;
        return e->a[1]->kind == IE_CONST && (e->a[0]->type->kind == TY_VECTOR || e->a[0]->type->kind == TY_MATRIX);
    default: return false;
    }
}

bool hfx_ir_pre_node(const ir_ctx *c, const ir_expr *e) { return node_ok(c, e, false); }

bool hfx_ir_pre_only(const ir_ctx *c, const ir_expr *e) {
    for (uint32_t i = 0; i < e->n; i++)
        if (!hfx_ir_pre_only(c, e->a[i])) return false;
    return hfx_ir_pre_node(c, e);
}

bool hfx_ir_pre_work(const ir_expr *e) {
    return e->kind == IE_UNARY || e->kind == IE_BINARY || e->kind == IE_SELECT || e->kind == IE_INTRIN ||
           (e->kind == IE_INDEX && e->a[1]->kind != IE_CONST);
}

/* ---- the program ---- */

/* A constant array (a state value's `static const` table: `FillMode = (Modes[Index]);`): every
 * element one constant of at most 16 components. Shader code reads its arrays through variables,
 * so only values outside shader code have these. */
static bool const_array(const ir_expr *a) {
    if (a->kind != IE_CONSTRUCT || a->type->kind != TY_ARRAY || !a->n || a->n != a->type->array_len) return false;
    for (uint32_t i = 0; i < a->n; i++)
        if (!hfx_ir_is_const(a->a[i]) || !hfx_type_is_numeric(a->a[i]->type) || hfx_type_components(a->a[i]->type) > 16)
            return false;
    return true;
}

static bool table_read(const ir_expr *e) { return e->kind == IE_INDEX && const_array(e->a[0]); }

typedef struct pc {
    ir_ctx *c;
    uint32_t *w; uint32_t n, cap;
    bool ok;
    bool value;   /* a state value's program, not a preshader's */
} pc;

/* What the writer can write: a preshader's nodes (a value's integer divisions too), and table reads. */
static bool writable(const pc *p, const ir_expr *e) {
    return table_read(e) || node_ok(p->c, e, p->value);
}

static void put(pc *p, uint32_t w) {
    if (!p->ok || !HFX_ARENA_GROW(p->c->arena, p->w, p->n, p->cap, 32)) {
        p->ok = false;
        return;
    }
    p->w[p->n++] = w;
}

static hfx_ev_base base_of(const hfx_type *t) { return hfx_base_ev(t->kind == TY_ARRAY ? t->elem->base : t->base); }

static void emit(pc *p, const ir_expr *e);

static void constant(pc *p, const ir_expr *e) {
    unsigned n = hfx_type_components(e->type);
    hfx_ev_base b = base_of(e->type);
    put(p, hfx_evc_word(HFX_EVC_CONST, b, n));
    for (unsigned i = 0; i < n; i++) put(p, hfx_evc_bits(b, e->cval[i]));
}

static void param(pc *p, const ir_var *v) {
    const hfx_fx_param *fp = &p->c->fx->params[v->param];
    put(p, hfx_evc_word(HFX_EVC_PARAM, base_of(v->type), fp->words));
    put(p, fp->offset);
}

/* Components of x picked by comps[0 .. n): SWIZZLE for up to 4, else SHUFFLE. */
static void pick(pc *p, const uint8_t *comps, unsigned n) {
    uint32_t w[2] = {0, 0};
    for (unsigned i = 0; i < n; i++) w[i / 8] |= (uint32_t)(comps[i] & 15u) << (4 * (i % 8));
    if (n <= 4) {
        put(p, hfx_evc_word(HFX_EVC_SWIZZLE, n, 0));
        put(p, w[0]);
        return;
    }
    put(p, hfx_evc_word(HFX_EVC_SHUFFLE, n, 0));
    put(p, w[0]);
    put(p, w[1]);
}

static void convert_to(pc *p, const hfx_type *t) {
    put(p, hfx_evc_word(HFX_EVC_CONVERT, base_of(t), hfx_type_components(t)));
}

/* (float3x3)M of a larger matrix keeps the upper-left rows and columns. */
static void convert(pc *p, const ir_expr *e) {
    const hfx_type *from = e->a[0]->type, *to = e->type;
    emit(p, e->a[0]);
    if (from->kind == TY_MATRIX && to->kind == TY_MATRIX && (from->rows != to->rows || from->cols != to->cols)) {
        uint8_t comps[16];
        unsigned n = 0;
        for (unsigned r = 0; r < to->rows; r++)
            for (unsigned k = 0; k < to->cols; k++) comps[n++] = (uint8_t)(r * from->cols + k);
        pick(p, comps, n);
    }
    convert_to(p, to);
}

static void construct(pc *p, const ir_expr *e) {
    unsigned total = 0;
    for (uint32_t i = 0; i < e->n; i++) {
        emit(p, e->a[i]);
        total += hfx_type_components(e->a[i]->type);
        if (i) put(p, hfx_evc_word(HFX_EVC_CONCAT, 0, total));
    }
    convert_to(p, e->type);
}

/* TABLE: the index, then the elements, ints or floats (a bool element is the int 0 or 1). */
static void table(pc *p, const ir_expr *e) {
    const ir_expr *arr = e->a[0];
    unsigned n = hfx_type_components(arr->a[0]->type);
    hfx_ev_base b = base_of(arr->a[0]->type) == HFX_EV_FLOAT ? HFX_EV_FLOAT : HFX_EV_INT;
    emit(p, e->a[1]);
    put(p, hfx_evc_word(HFX_EVC_TABLE, b, n));
    put(p, arr->n);
    for (uint32_t i = 0; i < arr->n; i++)
        for (unsigned k = 0; k < n; k++) put(p, hfx_evc_bits(b, arr->a[i]->cval[k]));
}

/* ELEMENT: the index, clamped into the array (a state value's selector, as D3D9 indexes it). */
static void element(pc *p, const ir_expr *e, const hfx_fx_param *arr) {
    const hfx_fx_param *el = &p->c->fx->params[arr->first_child];
    emit(p, e->a[1]);
    put(p, hfx_evc_word(HFX_EVC_ELEMENT, base_of(e->type), el->words));
    put(p, el->offset);
    put(p, arr->elements);
    put(p, arr->words / arr->elements);
}

/* A preshader's element read: zero past either end, as the shader it stands for reads it (the
 * GLSL printer's guarded reads; D3D9: "reads from out-of-range registers return (0.0, 0.0, 0.0,
 * 0.0)"), so that moving the read to the CPU does not change its value:
 * (int)i >= 0 && (int)i < count ? arr[i] : 0. */
static void guarded_element(pc *p, const ir_expr *e, const hfx_fx_param *arr) {
    ir_ctx *c = p->c;
    const hfx_type *it = hfx_type_scalar(c->types, B_INT), *bt = hfx_type_scalar(c->types, B_BOOL);
    ir_expr *i = hfx_ir_new_convert(c, it, e->a[1]);
    ir_expr *zero = hfx_ir_new_expr(c, IE_CONST, e->type, e->loc, 0);
    ir_expr *low = hfx_ir_new_binary(c, OP_GE, bt, i, hfx_ir_const_scalar(c, it, 0, e->loc));
    ir_expr *high = hfx_ir_new_binary(c, OP_LT, bt, i, hfx_ir_const_scalar(c, it, arr->elements, e->loc));
    ir_expr *in = low && high ? hfx_ir_new_binary(c, OP_AND, bt, low, high) : NULL;
    if (!zero || !in) { p->ok = false; return; }
    element(p, e, arr);
    emit(p, zero); /* a new constant's components are 0 */
    emit(p, in);
    put(p, hfx_evc_word(HFX_EVC_SELECT, 0, 0));
}

/* A vector element or a matrix row at a constant index; an element of a parameter array. */
static void index_of(pc *p, const ir_expr *e) {
    if (table_read(e)) { table(p, e); return; }
    const hfx_fx_param *arr = param_array(p->c, e->a[0]);
    if (arr) {
        if (!p->value) { guarded_element(p, e, arr); return; }
        element(p, e, arr);
        return;
    }
    const hfx_type *t = e->a[0]->type;
    unsigned width = t->kind == TY_MATRIX ? t->cols : 1, count = t->kind == TY_MATRIX ? t->rows : t->cols;
    double i = e->a[1]->cval[0];
    unsigned k = hfx_ev_uint(i) >= count ? count - 1 : hfx_ev_uint(i); /* NaN and negatives: 0 */
    uint8_t comps[4];
    for (unsigned j = 0; j < width; j++) comps[j] = (uint8_t)(k * width + j);
    emit(p, e->a[0]);
    pick(p, comps, width);
}

/* mul(x, y): a scalar scales; two vectors make a dot product; else rows times columns. */
static void mul(pc *p, const ir_expr *e) {
    const hfx_type *x = e->a[0]->type, *y = e->a[1]->type;
    emit(p, e->a[0]);
    emit(p, e->a[1]);
    if (x->kind == TY_SCALAR || y->kind == TY_SCALAR) {
        put(p, hfx_evc_word(HFX_EVC_BINARY, HFX_EV_MUL, 0));
    } else if (x->kind == TY_VECTOR && y->kind == TY_VECTOR) {
        put(p, hfx_evc_word(HFX_EVC_CALL, HFX_EV_FN_DOT, 0));
    } else {
        unsigned r = x->kind == TY_VECTOR ? 1 : x->rows, k = x->cols, cols = y->kind == TY_VECTOR ? 1 : y->cols;
        put(p, hfx_evc_word(HFX_EVC_MATMUL, r | k << 4, cols));
    }
    convert_to(p, e->type);
}

static void transpose(pc *p, const ir_expr *e) {
    const hfx_type *t = e->a[0]->type;
    uint8_t comps[16];
    unsigned n = 0, rows = t->kind == TY_MATRIX ? t->rows : 1, cols = t->cols;
    for (unsigned k = 0; k < cols; k++)
        for (unsigned r = 0; r < rows; r++) comps[n++] = (uint8_t)(r * cols + k);
    emit(p, e->a[0]);
    pick(p, comps, n);
}

static void intrinsic(pc *p, const ir_expr *e) {
    if (e->intrin == HFX_INTR_MUL) { mul(p, e); return; }
    if (e->intrin == HFX_INTR_TRANSPOSE) { transpose(p, e); return; }
    for (uint32_t i = 0; i < e->n; i++) emit(p, e->a[i]);
    put(p, hfx_evc_word(HFX_EVC_CALL, (uint32_t)hfx_intrinsic_info_of((int)e->intrin)->fold, 0));
    convert_to(p, e->type); /* the checker's result type: a float function of ints stays float */
}

static void operation(pc *p, const ir_expr *e) {
    hfx_ev_op op;
    hfx_op_ev(e->op, &op);
    for (uint32_t i = 0; i < e->n; i++) emit(p, e->a[i]);
    put(p, hfx_evc_word(e->kind == IE_UNARY ? HFX_EVC_UNARY : HFX_EVC_BINARY, op, 0));
}

static void emit(pc *p, const ir_expr *e) {
    if (!p->ok || !writable(p, e)) { p->ok = false; return; }
    switch (e->kind) {
    case IE_CONST: constant(p, e); break;
    case IE_VAR:
        if (param_leaf(p->c, e->var)) param(p, e->var);
        else p->ok = false; /* an array is only read through index_of */
        break;
    case IE_UNARY: case IE_BINARY: operation(p, e); break;
    case IE_SELECT:
        emit(p, e->a[1]);
        emit(p, e->a[2]);
        emit(p, e->a[0]);
        put(p, hfx_evc_word(HFX_EVC_SELECT, 0, 0));
        break;
    case IE_CONSTRUCT: construct(p, e); break;
    case IE_CONVERT: convert(p, e); break;
    case IE_SWIZZLE: emit(p, e->a[0]); pick(p, e->comps, e->comp_count); break;
    case IE_INDEX: index_of(p, e); break;
    default: intrinsic(p, e); break;
    }
}

/* e's program; count > 0: then the table 0 .. count - 1 that clamps it (TABLE clamps as D3D9). */
static uint32_t *program(ir_ctx *c, const ir_expr *e, bool value, uint32_t count, uint32_t *words) {
    pc p = {c, NULL, 0, 0, true, value};
    emit(&p, e);
    if (count) {
        put(&p, hfx_evc_word(HFX_EVC_TABLE, HFX_EV_INT, 1));
        put(&p, count);
        for (uint32_t i = 0; i < count; i++) put(&p, i);
    }
    if (!p.ok || hfx_evc_validate(p.w, p.n, c->fx->value_words, NULL, 0) != 0) return NULL;
    *words = p.n;
    return p.w;
}

uint32_t *hfx_ir_pre_code(ir_ctx *c, const ir_expr *e, uint32_t *words) { return program(c, e, false, 0, words); }

uint32_t *hfx_ir_value_code(ir_ctx *c, const ir_expr *e, uint32_t clamp, uint32_t *words) {
    return program(c, e, true, clamp, words);
}

/* ---- the comment ---- */

static const char *op_text(hfx_op op) {
    static const char *const t[] = {
        [OP_NEG] = "-", [OP_POS] = "+", [OP_NOT] = "!", [OP_BITNOT] = "~", [OP_ADD] = " + ", [OP_SUB] = " - ",
        [OP_MUL] = " * ", [OP_DIV] = " / ", [OP_MOD] = " % ", [OP_SHL] = " << ", [OP_SHR] = " >> ",
        [OP_BITAND] = " & ", [OP_BITOR] = " | ", [OP_BITXOR] = " ^ ", [OP_LT] = " < ", [OP_GT] = " > ",
        [OP_LE] = " <= ", [OP_GE] = " >= ", [OP_EQ] = " == ", [OP_NE] = " != ", [OP_AND] = " && ", [OP_OR] = " || ",
    };
    return op < sizeof t / sizeof *t && t[op] ? t[op] : " ? ";
}

static void text(sbuf *b, hfx_arena *a, const ir_expr *e);

static void binary_text(sbuf *b, hfx_arena *a, const ir_expr *e) {
    text(b, a, e->a[0]);
    hfx_sb_put(b, op_text(e->op));
    text(b, a, e->a[1]);
}

/* An argument list's commas bracket enough: a binary argument needs no parentheses. */
static void args(sbuf *b, hfx_arena *a, const ir_expr *e) {
    hfx_sb_put(b, "(");
    for (uint32_t i = 0; i < e->n; i++) {
        if (i) hfx_sb_put(b, ", ");
        if (e->a[i]->kind == IE_BINARY) binary_text(b, a, e->a[i]);
        else text(b, a, e->a[i]);
    }
    hfx_sb_put(b, ")");
}

static void constant_text(sbuf *b, hfx_arena *a, const ir_expr *e) {
    unsigned n = hfx_type_components(e->type);
    if (n > 1) hfx_sb_printf(b, "%s(", hfx_type_name(a, e->type));
    for (unsigned i = 0; i < n; i++) hfx_sb_printf(b, "%s%g", i ? ", " : "", e->cval[i]);
    if (n > 1) hfx_sb_put(b, ")");
}

static void swizzle_text(sbuf *b, const ir_expr *e) {
    const hfx_type *t = e->a[0]->type;
    hfx_sb_put(b, ".");
    for (unsigned i = 0; i < e->comp_count; i++) {
        unsigned k = e->comps[i];
        if (t->kind == TY_MATRIX) hfx_sb_printf(b, "_m%u%u", k / t->cols, k % t->cols);
        else hfx_sb_printf(b, "%c", "xyzw"[k & 3]);
    }
}

static void text(sbuf *b, hfx_arena *a, const ir_expr *e) {
    switch (e->kind) {
    case IE_CONST: constant_text(b, a, e); return;
    case IE_VAR: hfx_sb_put(b, e->var->name); return;
    case IE_UNARY: hfx_sb_put(b, op_text(e->op)); text(b, a, e->a[0]); return;
    case IE_BINARY: hfx_sb_put(b, "("); binary_text(b, a, e); hfx_sb_put(b, ")"); return;
    case IE_SELECT:
        hfx_sb_put(b, "(");
        text(b, a, e->a[0]); hfx_sb_put(b, " ? "); text(b, a, e->a[1]); hfx_sb_put(b, " : "); text(b, a, e->a[2]);
        hfx_sb_put(b, ")");
        return;
    case IE_CONSTRUCT: hfx_sb_put(b, hfx_type_name(a, e->type)); args(b, a, e); return;
    case IE_CONVERT: hfx_sb_printf(b, "(%s)", hfx_type_name(a, e->type)); text(b, a, e->a[0]); return;
    case IE_SWIZZLE: text(b, a, e->a[0]); swizzle_text(b, e); return;
    case IE_INDEX: text(b, a, e->a[0]); hfx_sb_put(b, "["); text(b, a, e->a[1]); hfx_sb_put(b, "]"); return;
    case IE_INTRIN: hfx_sb_put(b, hfx_intrinsic_name((int)e->intrin) ? hfx_intrinsic_name((int)e->intrin) : "?"); args(b, a, e); return;
    default: hfx_sb_put(b, "?"); return;
    }
}

const char *hfx_ir_pre_text(ir_ctx *c, const ir_expr *e) {
    sbuf b = {.arena = c->arena};
    text(&b, c->arena, e);
    return b.oom || !b.d ? "?" : b.d; /* arena text: nothing to free */
}
