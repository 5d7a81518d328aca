/* fxlvm_write.c: a common/eval_code program (a state expression, a shader array's index) as
 * fxc's expression program (FXLVM, docs/fx2.md): the inverse of fxlvm.c, for fx_2_0's writer.
 *
 * The stack program runs once at write time over operands instead of numbers: a stack value is
 * up to 16 operands (an input register component c#, a literal, a temporary r#, or a relative
 * read c[base + r.x]); each operation writes fresh temporaries with one-component instructions,
 * which fxlvm.c (and D3DX) read like fxc's. Inputs get registers in parameter order, as fxc
 * gives them (`mov oc0.x, c[0 + c18.x].x` for XNA's `VSIndices[ShaderIndex]`). FXLVM computes
 * in float: integer conversions truncate with frc, comparisons give 0 / 1, and the final
 * conversion to the state's type is the reader's (D3DX truncates a float for an int state).
 * Bit operations, matrices products and the rarer intrinsics have no FXLVM form: an error. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect/fx2_int.h"
#include "effect/fx2_write.h"
#include "grow.h"
#include "eval_code.h"

enum { MAX_TEMPS = 1000, MAX_INPUTS = 64, FX_VERSION = 0x46580200u };

typedef struct opnd {
    uint32_t table, offset;
    bool indexed;
    uint32_t itable, ioffset;  /* the index register component (unindexed) */
    bool integral;             /* holds an integer value (int / bool parameter, literal, comparison) */
} opnd;

typedef struct value {
    uint32_t n;
    opnd c[HFX_EV_MAX_COMPONENTS];
    hfx_ev_base base;
} value;

typedef struct input {
    uint32_t param, reg, regs;
} input;

typedef struct wr {
    const hfx_fx_effect *fx;
    value stack[HFX_EVC_MAX_DEPTH];
    uint32_t depth;
    double *lit; uint32_t lit_count, lit_cap;
    uint32_t *code; uint32_t code_count, code_cap, instructions;
    input in[MAX_INPUTS]; uint32_t in_count;
    uint32_t temps;
    uint32_t uses[MAX_TEMPS];  /* reads of each temporary component */
    uint32_t def[MAX_TEMPS];   /* where its writing instruction's output table word is in code */
    char *err; size_t err_size;
    bool failed;
} wr;

static void fail(wr *w, const char *msg) {
    if (!w->failed && w->err) snprintf(w->err, w->err_size, "%s", msg);
    w->failed = true;
}

static void put(wr *w, uint32_t v) {
    if (w->failed) return;
    if (!hfx_grow((void **)&w->code, sizeof *w->code, w->code_count, &w->code_cap, 64, NULL, NULL)) {
        fail(w, "out of memory");
        return;
    }
    w->code[w->code_count++] = v;
}

/* --- operands -------------------------------------------------------------------------------- */

static bool whole(double v) { return v == floor(v) && fabs(v) <= 2147483647.0; }

/* A literal appended to CLIT (tables want their own run of registers). */
static uint32_t append_literal(wr *w, double v) {
    if (!hfx_grow((void **)&w->lit, sizeof *w->lit, w->lit_count, &w->lit_cap, 16, NULL, NULL)) {
        fail(w, "out of memory");
        return 0;
    }
    w->lit[w->lit_count] = v;
    return w->lit_count++;
}

static opnd literal(wr *w, double v) {
    for (uint32_t i = 0; i < w->lit_count; i++)
        if (memcmp(&w->lit[i], &v, sizeof v) == 0) return (opnd){.table = T_IMM, .offset = i, .integral = whole(v)};
    return (opnd){.table = T_IMM, .offset = append_literal(w, v), .integral = whole(v)};
}

static opnd temp(wr *w) {
    if (w->temps >= MAX_TEMPS) fail(w, "the expression needs more temporary registers than FXLVM has");
    return (opnd){.table = T_TEMP, .offset = w->temps++};
}

static void put_opnd(wr *w, const opnd *o) {
    put(w, o->indexed ? 1 : 0);
    if (o->indexed) put(w, o->itable), put(w, o->ioffset);
    put(w, o->table), put(w, o->offset);
    if (o->indexed && o->itable == T_TEMP && o->ioffset < MAX_TEMPS) w->uses[o->ioffset]++;
    if (o->table == T_TEMP && o->offset < MAX_TEMPS) w->uses[o->offset]++;
}

/* One one-component instruction over inputs x, into a fresh temporary. */
static opnd emit(wr *w, uint32_t op, const opnd *x, uint32_t n, bool integral) {
    opnd out = temp(w);
    out.integral = integral;
    put(w, op << 20 | 1u);
    put(w, n);
    for (uint32_t i = 0; i < n; i++) put_opnd(w, &x[i]);
    if (out.offset < MAX_TEMPS) w->def[out.offset] = w->code_count + 1;
    put(w, 0), put(w, out.table), put(w, out.offset);
    w->instructions++;
    return out;
}

static opnd op1(wr *w, uint32_t op, opnd a) { return emit(w, op, &a, 1, false); }
static opnd op2(wr *w, uint32_t op, opnd a, opnd b) { return emit(w, op, (opnd[]){a, b}, 2, false); }
static opnd op3(wr *w, uint32_t op, opnd a, opnd b, opnd c) { return emit(w, op, (opnd[]){a, b, c}, 3, false); }

static opnd boolean(opnd o) { o.integral = true; return o; }

/* A relative read is an operand, but not an index: copy it to a temporary first. */
static opnd plain(wr *w, opnd o) {
    if (!o.indexed) return o;
    bool i = o.integral;
    o = op1(w, FXLVM_MOV, o);
    o.integral = i;
    return o;
}

static opnd neg(wr *w, opnd a) { return op1(w, FXLVM_NEG, a); }
static opnd sub(wr *w, opnd a, opnd b) { return op2(w, FXLVM_ADD, a, neg(w, b)); }
static opnd absval(wr *w, opnd a) { return op2(w, FXLVM_MAX, a, neg(w, a)); }
static opnd floor_of(wr *w, opnd a) { return sub(w, a, op1(w, FXLVM_FRC, a)); }

/* Truncation toward zero: floor, plus one where a negative value had a fraction. */
static opnd trunc_of(wr *w, opnd a) {
    if (a.integral) return a;
    opnd f = op1(w, FXLVM_FRC, a), fl = sub(w, a, f), zero = literal(w, 0.0);
    opnd up = op2(w, FXLVM_MUL, op2(w, FXLVM_LT, a, zero), op2(w, FXLVM_LT, zero, f));
    return boolean(op2(w, FXLVM_ADD, fl, up));
}

/* x != 0 as 0 / 1. */
static opnd truth(wr *w, opnd a) {
    if (a.integral && a.table == T_TEMP) return a; /* comparisons already give 0 / 1 */
    return boolean(op2(w, FXLVM_LT, literal(w, 0.0), absval(w, a)));
}

/* --- inputs ---------------------------------------------------------------------------------- */

/* The top-level numeric parameter holding value word `word`. */
static uint32_t param_of(const hfx_fx_effect *fx, uint32_t word) {
    for (uint32_t i = 0; i < fx->top_param_count; i++) {
        const hfx_fx_param *p = &fx->params[i];
        if (p->klass != HFX_CLASS_OBJECT && p->klass != HFX_CLASS_STRUCT && word >= p->offset && word - p->offset < p->words)
            return i;
    }
    return HFX_NONE;
}

static uint32_t regs_of(const hfx_fx_param *p) {
    return (p->elements ? p->elements : 1) * (p->klass == HFX_CLASS_MATRIX ? p->rows : 1);
}

/* Every parameter the program reads gets registers, in parameter order. */
static void gather_inputs(wr *w, const uint32_t *code, uint32_t words) {
    bool used[4096] = {false};
    for (uint32_t at = 0; at < words; at = hfx_evc_next(code, at, words)) {
        uint32_t op = code[at] & 0xffu;
        if (op != HFX_EVC_PARAM && op != HFX_EVC_ELEMENT) continue;
        uint32_t p = param_of(w->fx, code[at + 1]);
        if (p == HFX_NONE || p >= 4096) return fail(w, "the expression reads a structure or a value that is no parameter");
        used[p] = true;
    }
    uint32_t reg = 0;
    for (uint32_t p = 0; p < w->fx->top_param_count && p < 4096; p++) {
        if (!used[p]) continue;
        if (w->in_count == MAX_INPUTS) return fail(w, "the expression reads too many parameters");
        w->in[w->in_count++] = (input){p, reg, regs_of(&w->fx->params[p])};
        reg += regs_of(&w->fx->params[p]);
    }
}

/* The input operand of value word `word` (register, component as a row-major matrix's). */
static opnd input_word(wr *w, uint32_t word) {
    uint32_t p = param_of(w->fx, word);
    for (uint32_t i = 0; i < w->in_count; i++) {
        if (w->in[i].param != p) continue;
        const hfx_fx_param *q = &w->fx->params[p];
        uint32_t rel = word - q->offset, per = q->words / (q->elements ? q->elements : 1), e = rel / per, k = rel % per;
        uint32_t reg = w->in[i].reg + e * (q->klass == HFX_CLASS_MATRIX ? q->rows : 1) + (q->klass == HFX_CLASS_MATRIX ? k / q->cols : 0);
        uint32_t comp = q->klass == HFX_CLASS_MATRIX ? k % q->cols : k;
        return (opnd){.table = T_CONST, .offset = reg * 4 + comp, .integral = q->type != HFX_TYPE_FLOAT};
    }
    fail(w, "internal: a parameter without registers");
    return (opnd){.table = T_CONST};
}

/* --- the stack ------------------------------------------------------------------------------- */

static value *push(wr *w, uint32_t n, hfx_ev_base base) {
    if (w->depth >= HFX_EVC_MAX_DEPTH || n > HFX_EV_MAX_COMPONENTS) {
        fail(w, "the expression is too deep");
        return &w->stack[0];
    }
    value *v = &w->stack[w->depth++];
    v->n = n, v->base = base;
    return v;
}

static value pop(wr *w) {
    if (!w->depth) {
        fail(w, "internal: the expression's stack underflows");
        return (value){0};
    }
    return w->stack[--w->depth];
}

static hfx_ev_base larger(hfx_ev_base a, hfx_ev_base b) { return a > b ? a : b; }

/* Component i of v, a scalar splatting. */
static opnd comp(const value *v, uint32_t i) { return v->c[v->n == 1 ? 0 : i]; }

static void binary(wr *w, hfx_ev_op op) {
    value y = pop(w), x = pop(w);
    uint32_t n = x.n > y.n ? x.n : y.n;
    hfx_ev_base base = larger(x.base, y.base);
    bool cmp = op >= HFX_EV_LT && op <= HFX_EV_OR;
    value *r = push(w, n, cmp ? HFX_EV_BOOL : base);
    for (uint32_t i = 0; i < n && !w->failed; i++) {
        opnd a = comp(&x, i), b = comp(&y, i), o;
        switch (op) {
        case HFX_EV_ADD: o = op2(w, FXLVM_ADD, a, b); break;
        case HFX_EV_SUB: o = sub(w, a, b); break;
        case HFX_EV_MUL: o = op2(w, FXLVM_MUL, a, b); break;
        case HFX_EV_DIV: o = op2(w, FXLVM_DIV, a, b); if (base != HFX_EV_FLOAT) o = trunc_of(w, o); break;
        case HFX_EV_MOD: { /* a - b * trunc(a / b): fmod, and % on ints */
            opnd q = trunc_of(w, op2(w, FXLVM_DIV, a, b));
            o = sub(w, a, op2(w, FXLVM_MUL, b, q));
            break;
        }
        case HFX_EV_LT: o = boolean(op2(w, FXLVM_LT, a, b)); break;
        case HFX_EV_GT: o = boolean(op2(w, FXLVM_LT, b, a)); break;
        case HFX_EV_LE: o = boolean(op2(w, FXLVM_GE, b, a)); break;
        case HFX_EV_GE: o = boolean(op2(w, FXLVM_GE, a, b)); break;
        case HFX_EV_EQ: o = boolean(op2(w, FXLVM_MUL, op2(w, FXLVM_GE, a, b), op2(w, FXLVM_GE, b, a))); break;
        case HFX_EV_NE: o = boolean(op2(w, FXLVM_ADD, op2(w, FXLVM_LT, a, b), op2(w, FXLVM_LT, b, a))); break;
        case HFX_EV_AND: o = boolean(op2(w, FXLVM_MUL, truth(w, a), truth(w, b))); break;
        case HFX_EV_OR: o = boolean(op2(w, FXLVM_MAX, truth(w, a), truth(w, b))); break;
        default: fail(w, "bit operations have no form in fxc's expressions"); return;
        }
        if (base != HFX_EV_FLOAT && (op == HFX_EV_ADD || op == HFX_EV_SUB || op == HFX_EV_MUL || op == HFX_EV_MOD))
            o.integral = a.integral && b.integral;
        r->c[i] = o;
    }
}

static void unary(wr *w, hfx_ev_op op) {
    value x = pop(w);
    value *r = push(w, x.n, op == HFX_EV_NOT ? HFX_EV_BOOL : x.base);
    for (uint32_t i = 0; i < x.n && !w->failed; i++) {
        if (op == HFX_EV_NEG) r->c[i] = neg(w, x.c[i]), r->c[i].integral = x.c[i].integral;
        else if (op == HFX_EV_POS) r->c[i] = x.c[i];
        else if (op == HFX_EV_NOT) r->c[i] = boolean(op2(w, FXLVM_GE, literal(w, 0.0), absval(w, x.c[i])));
        else fail(w, "bit operations have no form in fxc's expressions");
    }
}

/* One component of an intrinsic on arguments a[0..n). */
static opnd call_one(wr *w, hfx_ev_fn fn, const opnd *a) {
    static const struct { hfx_ev_fn fn; uint32_t op; } direct[] = {
        {HFX_EV_FN_MIN, FXLVM_MIN}, {HFX_EV_FN_MAX, FXLVM_MAX}, {HFX_EV_FN_SIN, FXLVM_SIN}, {HFX_EV_FN_COS, FXLVM_COS},
        {HFX_EV_FN_ASIN, FXLVM_ASIN}, {HFX_EV_FN_ACOS, FXLVM_ACOS}, {HFX_EV_FN_ATAN, FXLVM_ATAN}, {HFX_EV_FN_ATAN2, FXLVM_ATAN2},
        {HFX_EV_FN_EXP2, FXLVM_EXP}, {HFX_EV_FN_FRAC, FXLVM_FRC}, {HFX_EV_FN_RSQRT, FXLVM_RSQ}, {HFX_EV_FN_LOG2, FXLVM_LOG}};
    for (size_t i = 0; i < sizeof direct / sizeof *direct; i++)
        if (direct[i].fn == fn) return emit(w, direct[i].op, a, (uint32_t)hfx_ev_fn_args(fn), false);
    opnd zero = literal(w, 0.0), one = literal(w, 1.0);
    switch (fn) {
    case HFX_EV_FN_ABS: return absval(w, a[0]);
    case HFX_EV_FN_SQRT: return op1(w, FXLVM_RCP, op1(w, FXLVM_RSQ, a[0]));
    case HFX_EV_FN_FLOOR: return floor_of(w, a[0]);
    case HFX_EV_FN_CEIL: return neg(w, floor_of(w, neg(w, a[0])));
    case HFX_EV_FN_TRUNC: return trunc_of(w, a[0]);
    case HFX_EV_FN_ROUND: return floor_of(w, op2(w, FXLVM_ADD, a[0], literal(w, 0.5)));
    case HFX_EV_FN_SATURATE: return op2(w, FXLVM_MIN, op2(w, FXLVM_MAX, a[0], zero), one);
    case HFX_EV_FN_CLAMP: return op2(w, FXLVM_MIN, op2(w, FXLVM_MAX, a[0], a[1]), a[2]);
    case HFX_EV_FN_LERP: return op2(w, FXLVM_ADD, a[0], op2(w, FXLVM_MUL, a[2], sub(w, a[1], a[0])));
    case HFX_EV_FN_STEP: return boolean(op2(w, FXLVM_GE, a[1], a[0]));
    case HFX_EV_FN_SIGN: return sub(w, op2(w, FXLVM_LT, zero, a[0]), op2(w, FXLVM_LT, a[0], zero));
    case HFX_EV_FN_POW: return op1(w, FXLVM_EXP, op2(w, FXLVM_MUL, a[1], op1(w, FXLVM_LOG, a[0])));
    case HFX_EV_FN_EXP: return op1(w, FXLVM_EXP, op2(w, FXLVM_MUL, a[0], literal(w, 1.4426950408889634)));
    case HFX_EV_FN_LOG: return op2(w, FXLVM_MUL, op1(w, FXLVM_LOG, a[0]), literal(w, 0.69314718055994531));
    case HFX_EV_FN_TAN: return op2(w, FXLVM_DIV, op1(w, FXLVM_SIN, a[0]), op1(w, FXLVM_COS, a[0]));
    case HFX_EV_FN_DEGREES: return op2(w, FXLVM_MUL, a[0], literal(w, 57.295779513082323));
    case HFX_EV_FN_RADIANS: return op2(w, FXLVM_MUL, a[0], literal(w, 0.017453292519943295));
    default: fail(w, "an intrinsic with no form in fxc's expressions"); return zero;
    }
}

static void call(wr *w, hfx_ev_fn fn) {
    int n = hfx_ev_fn_args(fn);
    value args[3];
    if (n < 1 || n > 3) return fail(w, "internal: an intrinsic of no known arity");
    for (int i = n - 1; i >= 0; i--) args[i] = pop(w);
    if (fn == HFX_EV_FN_DOT) {
        value *r = push(w, 1, HFX_EV_FLOAT);
        opnd sum = op2(w, FXLVM_MUL, comp(&args[0], 0), comp(&args[1], 0));
        for (uint32_t i = 1; i < args[0].n; i++) sum = op2(w, FXLVM_ADD, sum, op2(w, FXLVM_MUL, comp(&args[0], i), comp(&args[1], i)));
        r->c[0] = sum;
        return;
    }
    uint32_t count = 1;
    for (int i = 0; i < n; i++) count = args[i].n > count ? args[i].n : count;
    value *r = push(w, count, HFX_EV_FLOAT);
    for (uint32_t c = 0; c < count && !w->failed; c++) {
        opnd a[3];
        for (int i = 0; i < n; i++) a[i] = comp(&args[i], c);
        r->c[c] = call_one(w, fn, a);
    }
}

static void convert(wr *w, hfx_ev_base base, uint32_t n) {
    value x = pop(w);
    value *r = push(w, n, base);
    for (uint32_t i = 0; i < n && !w->failed; i++) {
        opnd a = comp(&x, i);
        if (base == HFX_EV_FLOAT) r->c[i] = a;
        else if (base == HFX_EV_BOOL) r->c[i] = truth(w, a);
        else r->c[i] = trunc_of(w, plain(w, a));
    }
}

/* The index operand of a relative read, clamped into [0, count - 1] when it may leave it. */
static opnd index_of(wr *w, const value *v, uint32_t count, bool clamp) {
    opnd i = plain(w, v->c[0]);
    if (clamp) i = op2(w, FXLVM_MIN, op2(w, FXLVM_MAX, i, literal(w, 0.0)), literal(w, (double)(count - 1)));
    return i;
}

/* ELEMENT: n words at offset + index * stride of a parameter array, as c[reg + index]. */
static void element(wr *w, hfx_ev_base base, uint32_t n, uint32_t offset, uint32_t stride) {
    value idx = pop(w);
    uint32_t p = param_of(w->fx, offset);
    const hfx_fx_param *q = p != HFX_NONE ? &w->fx->params[p] : NULL;
    if (!q || !q->elements || q->klass == HFX_CLASS_MATRIX || stride != q->words / q->elements || n > 4)
        return fail(w, "a parameter array read that fxc's expressions cannot index (matrices, structures)");
    opnd first = input_word(w, offset), i = index_of(w, &idx, 0, false);
    value *r = push(w, n, base);
    for (uint32_t k = 0; k < n; k++)
        r->c[k] = (opnd){T_CONST, first.offset + k, true, i.table, i.offset, q->type != HFX_TYPE_FLOAT};
}

/* Component k of a CONST word of base `base`. */
static double const_value(hfx_ev_base base, uint32_t bits) {
    float f;
    memcpy(&f, &bits, sizeof f);
    return base == HFX_EV_FLOAT ? (double)f : base == HFX_EV_UINT ? (double)bits : (double)(int32_t)bits;
}

/* TABLE: a literal table, one register per entry, read relatively with the index clamped. */
static void table(wr *w, hfx_ev_base base, uint32_t n, uint32_t count, const uint32_t *entries) {
    value idx = pop(w);
    if (n > 4 || !count) return fail(w, "a table of more than 4 components");
    while (w->lit_count % 4 && !w->failed) append_literal(w, 0.0); /* entries start on a register */
    uint32_t first = w->lit_count;
    for (uint32_t e = 0; e < count && !w->failed; e++)
        for (uint32_t k = 0; k < 4; k++) append_literal(w, k < n ? const_value(base, entries[e * n + k]) : 0.0);
    opnd i = index_of(w, &idx, count, true);
    value *r = push(w, n, base);
    for (uint32_t k = 0; k < n; k++) r->c[k] = (opnd){T_IMM, first + k, true, i.table, i.offset, base != HFX_EV_FLOAT};
}

/* Is code[at] a TABLE of the identity 0 .. count - 1 ending the program (a selector's clamp,
 * which D3DX's own clamping of the index makes redundant)? */
static bool final_identity(const uint32_t *code, uint32_t at, uint32_t words) {
    uint32_t w0 = code[at];
    if ((w0 & 0xffu) != HFX_EVC_TABLE || (w0 >> 16 & 0xffu) != 1 || at + 2 > words) return false;
    uint32_t count = code[at + 1];
    if (at + 2 + count != words) return false;
    for (uint32_t i = 0; i < count; i++)
        if (const_value((hfx_ev_base)(w0 >> 8 & 0xffu), code[at + 2 + i]) != (double)i) return false;
    return true;
}

static void run(wr *w, const uint32_t *code, uint32_t words) {
    for (uint32_t at = 0; at < words && !w->failed; at = hfx_evc_next(code, at, words)) {
        uint32_t op = code[at] & 0xffu, a = code[at] >> 8 & 0xffu, b = code[at] >> 16 & 0xffu;
        bool last = hfx_evc_next(code, at, words) >= words;
        switch ((hfx_evc_op)op) {
        case HFX_EVC_CONST: {
            value *v = push(w, b, (hfx_ev_base)a);
            for (uint32_t k = 0; k < b; k++) v->c[k] = literal(w, const_value((hfx_ev_base)a, code[at + 1 + k]));
            break;
        }
        case HFX_EVC_PARAM: {
            value *v = push(w, b, (hfx_ev_base)a);
            for (uint32_t k = 0; k < b && !w->failed; k++) v->c[k] = input_word(w, code[at + 1] + k);
            break;
        }
        case HFX_EVC_SWIZZLE: case HFX_EVC_SHUFFLE: {
            value x = pop(w), *v = push(w, a, x.base);
            for (uint32_t k = 0; k < a; k++) {
                uint32_t src = (code[at + 1 + k / 8] >> (4 * (k % 8))) & 15u;
                if (src >= x.n) return fail(w, "internal: a swizzle past its value");
                v->c[k] = x.c[src];
            }
            break;
        }
        case HFX_EVC_CONVERT:
            if (!last) convert(w, (hfx_ev_base)a, b); /* the last one is the reader's, by the state's type */
            break;
        case HFX_EVC_UNARY: unary(w, (hfx_ev_op)a); break;
        case HFX_EVC_BINARY: binary(w, (hfx_ev_op)a); break;
        case HFX_EVC_CALL: call(w, (hfx_ev_fn)a); break;
        case HFX_EVC_TABLE:
            if (!final_identity(code, at, words)) table(w, (hfx_ev_base)a, b, code[at + 1], code + at + 2);
            break;
        case HFX_EVC_SELECT: {
            value c = pop(w), y = pop(w), x = pop(w);
            uint32_t n = x.n > y.n ? x.n : y.n;
            value *r = push(w, n, larger(x.base, y.base));
            for (uint32_t k = 0; k < n && !w->failed; k++) /* cmp: -truth(c) >= 0 (c false) takes y */
                r->c[k] = op3(w, FXLVM_CMP, neg(w, truth(w, comp(&c, k))), comp(&y, k), comp(&x, k));
            break;
        }
        case HFX_EVC_ELEMENT: element(w, (hfx_ev_base)a, b, code[at + 1], code[at + 3]); break;
        case HFX_EVC_CONCAT: {
            value y = pop(w), x = pop(w), *v = push(w, x.n + y.n, larger(x.base, y.base));
            if (x.n + y.n > HFX_EV_MAX_COMPONENTS) return fail(w, "internal: a value of more than 16 components");
            memcpy(v->c, x.c, x.n * sizeof *x.c);
            memcpy(v->c + x.n, y.c, y.n * sizeof *y.c);
            break;
        }
        default: return fail(w, "a matrix product has no form in fxc's expressions");
        }
    }
}

/* --- the token stream ------------------------------------------------------------------------ */

/* The CTAB comment: a shader's constant table layout, each input a float4 register range with
 * its type (class, type, rows, cols, elements), as fxlvm.c and MojoShader read it. */
/* A constant table lists its entries by name, as fxc's (insertion: a handful of inputs). */
static void sort_by_name(wr *w) {
    for (uint32_t i = 1; i < w->in_count; i++)
        for (uint32_t j = i; j > 0 && strcmp(w->fx->params[w->in[j - 1].param].name, w->fx->params[w->in[j].param].name) > 0; j--) {
            input t = w->in[j];
            w->in[j] = w->in[j - 1], w->in[j - 1] = t;
        }
}

static void put_ctab(wr *w, uint32_t *out, uint32_t *count, uint32_t cap) {
    sort_by_name(w);
    uint32_t names = 28 + 20 * w->in_count, len = 0, name_at[MAX_INPUTS];
    for (uint32_t i = 0; i < w->in_count; i++)
        name_at[i] = names + len, len += ((uint32_t)strlen(w->fx->params[w->in[i].param].name) + 4) & ~3u;
    uint32_t types = names + len, strings = types + 16 * w->in_count, bytes = strings + 4;
    uint32_t words = bytes / 4, n = 0;
    uint32_t *c = out + *count;
    if (*count + words > cap) return fail(w, "internal: the constant table does not fit");
    memset(c, 0, words * 4);
    c[n++] = 28, c[n++] = strings + 1 /* creator "hfx" */, c[n++] = FX_VERSION, c[n++] = w->in_count, c[n++] = 28,
    c[n++] = 0, c[n++] = strings /* target: "" */;
    for (uint32_t i = 0; i < w->in_count; i++) {
        c[n++] = name_at[i], c[n++] = 2u | w->in[i].reg << 16, c[n++] = w->in[i].regs, c[n++] = types + 16 * i, c[n++] = 0;
    }
    uint8_t *b = (uint8_t *)c;
    for (uint32_t i = 0; i < w->in_count; i++) {
        const hfx_fx_param *p = &w->fx->params[w->in[i].param];
        memcpy(b + name_at[i], p->name, strlen(p->name) + 1);
        uint16_t klass = p->klass == HFX_CLASS_MATRIX ? 2 : p->klass == HFX_CLASS_VECTOR ? 1 : 0;
        uint16_t t[8] = {klass, (uint16_t)p->type, (uint16_t)p->rows, (uint16_t)p->cols, (uint16_t)(p->elements ? p->elements : 1), 0, 0, 0};
        memcpy(b + types + 16 * i, t, 16);
    }
    memcpy(b + strings + 1, "hfx", 3);
    *count += words;
}

uint32_t *hfx_fxlvm_write(const hfx_fx_effect *fx, const uint32_t *code, uint32_t words, uint32_t *out_words, char *err,
                          size_t err_size) {
    wr w = {.fx = fx, .err = err, .err_size = err_size};
    if (hfx_evc_validate(code, words, fx->value_words, err, err_size) != 0) return NULL;
    gather_inputs(&w, code, words);
    run(&w, code, words);
    if (!w.failed && w.depth != 1) fail(&w, "internal: the expression leaves no single value");
    value v = w.failed ? (value){0} : w.stack[0];
    for (uint32_t k = 0; k < v.n && k < 4 && !w.failed; k++) { /* the outputs: oc0.xyzw */
        const opnd *o = &v.c[k];
        bool once = o->table == T_TEMP && !o->indexed && o->offset < MAX_TEMPS && !w.uses[o->offset];
        for (uint32_t j = 0; j < v.n && j < 4 && once; j++) once = j == k || v.c[j].table != T_TEMP || v.c[j].offset != o->offset;
        if (once) { /* a temporary nothing reads: its instruction writes the output itself, as fxc's */
            w.code[w.def[o->offset]] = T_OUT, w.code[w.def[o->offset] + 1] = k;
            w.uses[o->offset] = 1;
            continue;
        }
        put(&w, FXLVM_MOV << 20 | 1u), put(&w, 1), put_opnd(&w, &v.c[k]);
        put_opnd(&w, &(opnd){.table = T_OUT, .offset = k});
        w.instructions++;
    }
    if (!w.lit_count) literal(&w, 0.0); /* MojoShader wants a CLIT block; one literal is its smallest */
    uint32_t cap = 8 + w.lit_count * 2 + w.code_count + 64 + w.in_count * 12, n = 0;
    for (uint32_t i = 0; i < w.in_count; i++) cap += (uint32_t)strlen(fx->params[w.in[i].param].name) / 4 + 1;
    uint32_t *out = w.failed ? NULL : calloc(cap, sizeof *out);
    if (!out && !w.failed) fail(&w, "out of memory");
    if (!w.failed) {
        out[n++] = FX_VERSION;
        uint32_t head = n++;
        out[n++] = 0x42415443u; /* CTAB */
        put_ctab(&w, out, &n, cap);
        out[head] = 0xfffeu | (n - head - 1) << 16;
        out[n++] = 0xfffeu | (2 * w.lit_count + 2) << 16, out[n++] = FXLVM_CLIT, out[n++] = w.lit_count;
        memcpy(out + n, w.lit, w.lit_count * sizeof(double));
        n += 2 * w.lit_count;
        out[n++] = 0xfffeu | (w.code_count + 2) << 16, out[n++] = FXLVM_FXLC, out[n++] = w.instructions;
        memcpy(out + n, w.code, w.code_count * sizeof *w.code);
        n += w.code_count;
        out[n++] = 0x0000ffffu;
    }
    free(w.code);
    free(w.lit);
    if (w.failed) {
        free(out);
        return NULL;
    }
    *out_words = n;
    return out;
}
