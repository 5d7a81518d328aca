/* eval_code.c: validating and running eval_code.h's programs. */
#include "eval_code.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static uint32_t op_of(uint32_t w) { return w & 0xffu; }
static uint32_t a_of(uint32_t w) { return (w >> 8) & 0xffu; }
static uint32_t b_of(uint32_t w) { return (w >> 16) & 0xffu; }

/* Operand words after the instruction word; 0 for a TABLE whose count is not there yet. */
static uint64_t operand_words(const uint32_t *code, uint32_t at, uint32_t words) {
    uint32_t w = code[at];
    switch (op_of(w)) {
    case HFX_EVC_CONST: return b_of(w);
    case HFX_EVC_PARAM: case HFX_EVC_SWIZZLE: return 1;
    case HFX_EVC_ELEMENT: return 3;
    case HFX_EVC_SHUFFLE: return 2;
    case HFX_EVC_TABLE: return at + 1 < words ? 1 + (uint64_t)code[at + 1] * b_of(w) : 1;
    default: return 0;
    }
}

/* The stack values an instruction takes and leaves. */
static void stack_effect(uint32_t w, int *pops, int *pushes) {
    static const int take[HFX_EVC_OP_COUNT] = {0, 0, 1, 1, 1, 2, 0, 1, 3, 1, 1, 2, 2};
    *pops = op_of(w) == HFX_EVC_CALL ? hfx_ev_fn_args((hfx_ev_fn)a_of(w)) : take[op_of(w)];
    *pushes = 1;
}

static bool valid_n(uint32_t n) { return n >= 1 && n <= HFX_EV_MAX_COMPONENTS; }

/* ELEMENT's offset, count and stride: every element's n words inside the values. */
static bool element_ok(const uint32_t *w, uint32_t base, uint32_t n, uint32_t value_words) {
    uint64_t last = (uint64_t)w[0] + (uint64_t)(w[1] ? w[1] - 1 : 0) * w[2] + n;
    return base < HFX_EV_BASE_COUNT && valid_n(n) && w[1] >= 1 && last <= value_words;
}

/* r x k times k x c, each 1..4. */
static bool matmul_ok(uint32_t a, uint32_t c) {
    uint32_t r = a & 15u, k = a >> 4;
    return r >= 1 && r <= 4 && k >= 1 && k <= 4 && c >= 1 && c <= 4;
}

/* The instruction's own fields; NULL when they are right, else what is wrong. */
static const char *check_fields(const uint32_t *code, uint32_t at, uint32_t value_words) {
    uint32_t w = code[at], a = a_of(w), b = b_of(w);
    switch (op_of(w)) {
    case HFX_EVC_CONST: return a < HFX_EV_BASE_COUNT && valid_n(b) ? NULL : "a constant of a wrong shape";
    case HFX_EVC_PARAM:
        if (a >= HFX_EV_BASE_COUNT || !valid_n(b)) return "a parameter of a wrong shape";
        return code[at + 1] <= value_words && b <= value_words - code[at + 1] ? NULL : "a parameter outside the values";
    case HFX_EVC_SWIZZLE: return a >= 1 && a <= 4 ? NULL : "a swizzle of a wrong size";
    case HFX_EVC_CONVERT: return a < HFX_EV_BASE_COUNT && valid_n(b) ? NULL : "a conversion to a wrong shape";
    case HFX_EVC_UNARY: return a <= HFX_EV_BITNOT ? NULL : "an unknown unary operator";
    case HFX_EVC_BINARY: return a > HFX_EV_BITNOT && a < HFX_EV_OP_COUNT ? NULL : "an unknown binary operator";
    case HFX_EVC_CALL: return a < HFX_EV_FN_COUNT ? NULL : "an unknown function";
    case HFX_EVC_TABLE: return a < HFX_EV_BASE_COUNT && valid_n(b) && code[at + 1] >= 1 ? NULL : "a table of a wrong shape";
    case HFX_EVC_SELECT: return NULL;
    case HFX_EVC_ELEMENT: return element_ok(code + at + 1, a, b, value_words) ? NULL : "an element outside the values";
    case HFX_EVC_SHUFFLE: return valid_n(a) ? NULL : "a shuffle of a wrong size";
    case HFX_EVC_CONCAT: return valid_n(b) ? NULL : "a concatenation of a wrong size";
    case HFX_EVC_MATMUL: return matmul_ok(a, b) ? NULL : "a matrix product of a wrong shape";
    default: return "an unknown instruction";
    }
}

static int invalid(char *err, size_t err_size, uint32_t at, const char *why) {
    if (err && err_size) snprintf(err, err_size, "expression word %u: %s", at, why);
    return -1;
}

int hfx_evc_validate(const uint32_t *code, uint32_t words, uint32_t value_words, char *err, size_t err_size) {
    int depth = 0;
    if (!code || !words || words > HFX_EVC_MAX_WORDS) return invalid(err, err_size, 0, "an empty or oversized program");
    for (uint32_t at = 0; at < words;) {
        if (op_of(code[at]) >= HFX_EVC_OP_COUNT) return invalid(err, err_size, at, "an unknown instruction");
        uint64_t operands = operand_words(code, at, words);
        if (operands >= (uint64_t)words - at) return invalid(err, err_size, at, "operands past the end");
        const char *why = check_fields(code, at, value_words);
        if (why) return invalid(err, err_size, at, why);
        int pops, pushes;
        stack_effect(code[at], &pops, &pushes);
        if (depth < pops) return invalid(err, err_size, at, "takes more values than the stack holds");
        depth += pushes - pops;
        if (depth > HFX_EVC_MAX_DEPTH) return invalid(err, err_size, at, "the stack grows too deep");
        at += 1 + (uint32_t)operands;
    }
    return depth == 1 ? 0 : invalid(err, err_size, words, "the program does not leave exactly one value");
}

/* ---- running ---- */

static double from_bits(hfx_ev_base b, uint32_t w) {
    if (b == HFX_EV_FLOAT) {
        float f;
        memcpy(&f, &w, sizeof f);
        return f;
    }
    if (b == HFX_EV_UINT) return w;
    return b == HFX_EV_BOOL ? w != 0 : (double)(int32_t)w;
}

uint32_t hfx_evc_bits(hfx_ev_base b, double v) {
    if (b != HFX_EV_FLOAT) return b == HFX_EV_UINT ? hfx_ev_uint(v) : (uint32_t)hfx_ev_int(v);
    float f = (float)v;
    uint32_t w;
    memcpy(&w, &f, sizeof w);
    return w;
}

static void load(hfx_ev_value *v, hfx_ev_base b, uint32_t n, const uint32_t *words) {
    memset(v, 0, sizeof *v);
    v->base = b;
    v->n = (uint8_t)n;
    for (uint32_t i = 0; i < n; i++) v->c[i] = from_bits(b, words[i]);
}

static bool swizzle(hfx_ev_value *v, uint32_t n, uint32_t comps) {
    hfx_ev_value r = {v->base, (uint8_t)n, {0}};
    for (uint32_t i = 0; i < n; i++) {
        uint32_t k = (comps >> (4 * i)) & 15u;
        if (k >= v->n) return false;
        r.c[i] = v->c[k];
    }
    *v = r;
    return true;
}

/* Both to the larger base (bool < int < uint < float), as HLSL's binary operators promote. */
static void promote(hfx_ev_value *x, hfx_ev_value *y) {
    hfx_ev_base b = x->base > y->base ? x->base : y->base;
    hfx_ev_fit(x, b, x->n, x);
    hfx_ev_fit(y, b, y->n, y);
}

static bool call(hfx_ev_fn fn, hfx_ev_value *args, unsigned n, hfx_ev_value *out) {
    for (unsigned i = 1; i < n; i++) promote(&args[0], &args[i]);
    for (unsigned i = 1; i < n; i++) promote(&args[0], &args[i]); /* a later argument may have raised the base */
    if (hfx_ev_call(fn, args, n, out)) return true;
    for (unsigned i = 0; i < n; i++) hfx_ev_fit(&args[i], HFX_EV_FLOAT, args[i].n, &args[i]);
    return hfx_ev_call(fn, args, n, out); /* float-only functions of int arguments */
}

/* An index of base b as D3D9 takes it into an array of count: truncated, clamped into it. */
static uint32_t clamped_index(hfx_ev_base b, double i, uint32_t count) {
    int32_t k = hfx_ev_int(hfx_ev_convert(b, HFX_EV_INT, i));
    return k < 0 ? 0 : (uint32_t)k >= count ? count - 1 : (uint32_t)k;
}

uint32_t hfx_evc_index(const hfx_ev_value *v, uint32_t last) {
    if (!v->n) return 0;
    if (v->base == HFX_EV_UINT) return v->c[0] > last ? last : hfx_ev_uint(v->c[0]);
    int32_t k = hfx_ev_int(hfx_ev_convert(v->base, HFX_EV_INT, v->c[0]));
    return k < 0 ? 0 : (uint32_t)k > last ? last : (uint32_t)k;
}

static bool table(hfx_ev_value *index, hfx_ev_base b, uint32_t n, const uint32_t *data) {
    uint32_t k = clamped_index(index->base, index->c[0], data[0]);
    load(index, b, n, data + 1 + (size_t)k * n);
    return true;
}

static bool element(hfx_ev_value *index, hfx_ev_base b, uint32_t n, const uint32_t *w, const uint32_t *values) {
    uint32_t k = clamped_index(index->base, index->c[0], w[1]);
    load(index, b, n, values + w[0] + (size_t)k * w[2]);
    return true;
}

/* Component i of the result is nibble i of the two words. */
static bool shuffle(hfx_ev_value *v, uint32_t n, const uint32_t *w) {
    hfx_ev_value r = {v->base, (uint8_t)n, {0}};
    for (uint32_t i = 0; i < n; i++) {
        uint32_t k = (w[i / 8] >> (4 * (i % 8))) & 15u;
        if (k >= v->n) return false;
        r.c[i] = v->c[k];
    }
    *v = r;
    return true;
}

static bool concat(hfx_ev_value *x, const hfx_ev_value *y_in, uint32_t n) {
    hfx_ev_value y = *y_in;
    promote(x, &y);
    if ((uint32_t)x->n + y.n != n) return false;
    memcpy(x->c + x->n, y.c, y.n * sizeof *y.c);
    x->n = (uint8_t)n;
    return true;
}

/* Float products summed in order, each step rounded to float as the GPU's mad chain rounds. */
static bool matmul(hfx_ev_value *x, const hfx_ev_value *y_in, uint32_t a, uint32_t c) {
    uint32_t r = a & 15u, k = a >> 4;
    hfx_ev_value y = *y_in;
    if (x->n != r * k || y.n != k * c) return false;
    hfx_ev_fit(x, HFX_EV_FLOAT, x->n, x);
    hfx_ev_fit(&y, HFX_EV_FLOAT, y.n, &y);
    hfx_ev_value out = {HFX_EV_FLOAT, (uint8_t)(r * c), {0}};
    for (uint32_t i = 0; i < r; i++)
        for (uint32_t j = 0; j < c; j++) {
            float sum = 0.0f;
            for (uint32_t m = 0; m < k; m++) sum += (float)x->c[i * k + m] * (float)y.c[m * c + j];
            out.c[i * c + j] = sum;
        }
    *x = out;
    return true;
}

static bool select_value(hfx_ev_value *s) {
    hfx_ev_value *x = &s[0], *y = &s[1], *c = &s[2];
    promote(x, y);
    unsigned n = x->n > y->n ? x->n : y->n;
    if ((x->n != 1 && x->n != n) || (y->n != 1 && y->n != n) || (c->n != 1 && c->n != n)) return false;
    hfx_ev_value r = {x->base, (uint8_t)n, {0}};
    for (unsigned i = 0; i < n; i++) r.c[i] = c->c[c->n == 1 ? 0 : i] != 0 ? x->c[x->n == 1 ? 0 : i] : y->c[y->n == 1 ? 0 : i];
    *x = r;
    return true;
}

/* One instruction on the stack (sp values); false when its arithmetic does not fold. */
static bool step(const uint32_t *code, uint32_t at, const uint32_t *values, hfx_ev_value *stack, int *sp) {
    uint32_t w = code[at], a = a_of(w), b = b_of(w);
    hfx_ev_value *top = &stack[*sp - 1];
    int pops, pushes;
    stack_effect(w, &pops, &pushes);
    switch (op_of(w)) {
    case HFX_EVC_CONST: load(&stack[(*sp)++], (hfx_ev_base)a, b, code + at + 1); return true;
    case HFX_EVC_PARAM: load(&stack[(*sp)++], (hfx_ev_base)a, b, values + code[at + 1]); return true;
    case HFX_EVC_SWIZZLE: return swizzle(top, a, code[at + 1]);
    case HFX_EVC_CONVERT: return hfx_ev_fit(top, (hfx_ev_base)a, b, top);
    case HFX_EVC_UNARY: return hfx_ev_apply((hfx_ev_op)a, top, NULL, top);
    case HFX_EVC_BINARY:
        promote(top - 1, top);
        (*sp)--;
        return hfx_ev_apply((hfx_ev_op)a, top - 1, top, top - 1);
    case HFX_EVC_CALL:
        *sp -= pops;
        return call((hfx_ev_fn)a, &stack[*sp], (unsigned)pops, &stack[*sp]) && ++*sp;
    case HFX_EVC_TABLE: return table(top, (hfx_ev_base)a, b, code + at + 1);
    case HFX_EVC_ELEMENT: return element(top, (hfx_ev_base)a, b, code + at + 1, values);
    case HFX_EVC_SHUFFLE: return shuffle(top, a, code + at + 1);
    case HFX_EVC_CONCAT: (*sp)--; return concat(top - 1, top, b);
    case HFX_EVC_MATMUL: (*sp)--; return matmul(top - 1, top, a, b);
    default: /* SELECT */
        *sp -= 2;
        return select_value(top - 2);
    }
}

uint32_t hfx_evc_next(const uint32_t *code, uint32_t at, uint32_t words) {
    return at + 1 + (uint32_t)operand_words(code, at, words);
}

bool hfx_evc_run(const uint32_t *code, uint32_t words, const uint32_t *values, hfx_ev_value *out) {
    hfx_ev_value stack[HFX_EVC_MAX_DEPTH + 1];
    int sp = 0;
    for (uint32_t at = 0; at < words; at += 1 + (uint32_t)operand_words(code, at, words))
        if (!step(code, at, values, stack, &sp)) return false;
    *out = stack[0];
    return sp == 1;
}
