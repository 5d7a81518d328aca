/* test_eval_code.c: the runtime's expression programs (common/eval_code): what they compute
 * (values worked out by hand), D3D9's clamped table index, and a validator that refuses every
 * malformed program, so one read from a hostile .hfxo never runs out of bounds (the random
 * changes at the end run under ASan in CI). */
#include <math.h>
#include <string.h>

#include "eval_code.h"
#include "test.h"

#define W(op, a, b) hfx_evc_word(HFX_EVC_##op, a, b)
enum { F = HFX_EV_FLOAT, I = HFX_EV_INT };

static uint32_t fbits(float f) {
    uint32_t w;
    memcpy(&w, &f, sizeof w);
    return w;
}

/* values: [0] Ref = 0.5f, [1] index = 2, [2..5] v = (1, 2, 3, 4), [6] zero = 0 */
static uint32_t values[7];

static void setup(void) {
    values[0] = fbits(0.5f);
    values[1] = 2;
    for (int i = 0; i < 4; i++) values[2 + i] = fbits((float)(i + 1));
    values[6] = 0;
}

static int run(const uint32_t *code, uint32_t n, hfx_ev_value *out) {
    char err[128];
    if (hfx_evc_validate(code, n, 7, err, sizeof err) != 0) {
        printf("  invalid: %s\n", err);
        return 0;
    }
    return hfx_evc_run(code, n, values, out);
}

/* AlphaRef = (Ref * 255): 0.5 * 255 = 127.5 */
static void parameter_times_constant(void) {
    const uint32_t code[] = {W(PARAM, F, 1), 0, W(CONST, F, 1), fbits(255.0f), W(BINARY, HFX_EV_MUL, 0)};
    hfx_ev_value v;
    CHECK(run(code, 5, &v) && v.base == HFX_EV_FLOAT && v.n == 1 && v.c[0] == 127.5);
}

/* VSIndices[ShaderIndex] with VSIndices = {10, 20, 30, 40}: index 2 reads 30; -1 and 9 clamp
 * to the first and the last element, as D3D9 clamps an out-of-range array index. */
static void table_index_clamps(void) {
    uint32_t code[] = {W(PARAM, I, 1), 1, W(TABLE, I, 1), 4, 10, 20, 30, 40};
    hfx_ev_value v;
    CHECK(run(code, 8, &v) && v.base == HFX_EV_INT && v.c[0] == 30);
    values[1] = (uint32_t)-1;
    CHECK(run(code, 8, &v) && v.c[0] == 10);
    values[1] = 9;
    CHECK(run(code, 8, &v) && v.c[0] == 40);
    values[1] = 2;
}

/* A float index (a hostile program) goes through the rule of eval.h before the clamp: Ref = NaN
 * is 0 (10), +inf and 1e30 clamp to the last element (40), -inf to the first, 2.9 truncates to 2. */
static void float_table_index(void) {
    const uint32_t code[] = {W(PARAM, F, 1), 0, W(TABLE, I, 1), 4, 10, 20, 30, 40};
    const struct { float ref; double want; } rows[] = {{NAN, 10}, {INFINITY, 40}, {1e30f, 40}, {-INFINITY, 10}, {2.9f, 30}};
    hfx_ev_value v;
    for (size_t k = 0; k < sizeof rows / sizeof *rows; k++) {
        values[0] = fbits(rows[k].ref);
        CHECK(run(code, 8, &v) && v.c[0] == rows[k].want);
    }
    values[0] = fbits(0.5f);
}

/* hfx_evc_index, a selector's value as a shader-array entry in [0, last] (last = 2 here). */
static void selector_index(void) {
    const struct { int b; double v; uint32_t want; } rows[] = {
        {F, 1e30, 2}, {F, NAN, 0}, {F, -INFINITY, 0}, {F, INFINITY, 2}, {F, 1.9, 1}, {F, -0.5, 0},
        {I, -3, 0}, {I, 1, 1}, {HFX_EV_UINT, 4294967295.0, 2}, {HFX_EV_BOOL, 1, 1},
    };
    for (size_t k = 0; k < sizeof rows / sizeof *rows; k++) {
        hfx_ev_value v = {(hfx_ev_base)rows[k].b, 1, {rows[k].v}};
        CHECK_INT(hfx_evc_index(&v, 2), rows[k].want);
    }
}

/* v.wx = (4, 1); an int plus a float is a float: 2 + 0.5; normalize((0, 3, 4)) = (0, 0.6, 0.8) */
static void swizzle_promotion_and_calls(void) {
    const uint32_t sw[] = {W(PARAM, F, 4), 2, W(SWIZZLE, 2, 0), 0x03u};
    hfx_ev_value v;
    CHECK(run(sw, 4, &v) && v.n == 2 && v.c[0] == 4 && v.c[1] == 1);
    const uint32_t mix[] = {W(PARAM, I, 1), 1, W(CONST, F, 1), fbits(0.5f), W(BINARY, HFX_EV_ADD, 0)};
    CHECK(run(mix, 5, &v) && v.base == HFX_EV_FLOAT && v.c[0] == 2.5);
    const uint32_t norm[] = {W(CONST, F, 3), 0, fbits(3), fbits(4), W(CALL, HFX_EV_FN_NORMALIZE, 0)};
    CHECK(run(norm, 5, &v) && v.n == 3 && v.c[1] == (double)0.6f && v.c[2] == (double)0.8f);
    /* length of an int vector: computed in float, sqrt(3 * 3 + 4 * 4) = 5 */
    const uint32_t len[] = {W(CONST, I, 2), 3, 4, W(CALL, HFX_EV_FN_LENGTH, 0)};
    CHECK(run(len, 4, &v) && v.base == HFX_EV_FLOAT && v.c[0] == 5);
}

/* Ref > 0.25 ? 7 : 9 = 7; an integer division by zero does not fold: the run says so. */
static void select_and_failures(void) {
    const uint32_t sel[] = {W(CONST, I, 1), 7, W(CONST, I, 1), 9, W(PARAM, F, 1), 0, W(CONST, F, 1), fbits(0.25f),
                            W(BINARY, HFX_EV_GT, 0), W(SELECT, 0, 0)};
    hfx_ev_value v;
    CHECK(run(sel, 10, &v) && v.c[0] == 7);
    const uint32_t div[] = {W(CONST, I, 1), 1, W(PARAM, I, 1), 6, W(BINARY, HFX_EV_DIV, 0)};
    CHECK(!run(div, 5, &v));
}

static void check_invalid(const uint32_t *code, uint32_t n, const char *why) {
    char err[128] = "";
    CHECK_INT(hfx_evc_validate(code, n, 7, err, sizeof err), -1);
    if (!strstr(err, why)) printf("  got '%s', want '%s'\n", err, why);
    CHECK(strstr(err, why) != NULL);
}

static void validator_refuses(void) {
    const uint32_t one[] = {W(CONST, F, 1), 0};
    check_invalid(one, 0, "an empty or oversized program");
    const uint32_t bad_op[] = {99};
    check_invalid(bad_op, 1, "word 0: an unknown instruction");
    const uint32_t short_const[] = {W(CONST, F, 3), 0};
    check_invalid(short_const, 2, "word 0: operands past the end");
    const uint32_t far_param[] = {W(PARAM, F, 4), 5};
    check_invalid(far_param, 2, "word 0: a parameter outside the values"); /* 5 + 4 > 7 */
    uint32_t wide[18] = {W(CONST, F, 17)}; /* 17 components: more than a value holds */
    check_invalid(wide, 18, "a constant of a wrong shape");
    const uint32_t base[] = {W(CONST, 9, 1), 0};
    check_invalid(base, 2, "a constant of a wrong shape");
    const uint32_t underflow[] = {W(CONST, F, 1), 0, W(BINARY, HFX_EV_ADD, 0)};
    check_invalid(underflow, 3, "word 2: takes more values than the stack holds");
    const uint32_t two[] = {W(CONST, F, 1), 0, W(CONST, F, 1), 0};
    check_invalid(two, 4, "does not leave exactly one value");
    uint32_t deep[2 * (HFX_EVC_MAX_DEPTH + 1)]; /* one constant more than the stack holds */
    for (int i = 0; i <= HFX_EVC_MAX_DEPTH; i++) deep[2 * i] = W(CONST, F, 1), deep[2 * i + 1] = 0;
    check_invalid(deep, 2 * (HFX_EVC_MAX_DEPTH + 1), "word 32: the stack grows too deep"); /* 16 deep */
    const uint32_t empty_table[] = {W(CONST, I, 1), 0, W(TABLE, I, 1), 0};
    check_invalid(empty_table, 4, "a table of a wrong shape");
    const uint32_t huge_table[] = {W(CONST, I, 1), 0, W(TABLE, I, 16), 0xffffffffu, 1};
    check_invalid(huge_table, 5, "word 2: operands past the end");
    const uint32_t bad_fn[] = {W(CONST, F, 1), 0, W(CALL, 200, 0)};
    check_invalid(bad_fn, 3, "an unknown function");
    const uint32_t unary_add[] = {W(CONST, F, 1), 0, W(UNARY, HFX_EV_ADD, 0)};
    check_invalid(unary_add, 3, "an unknown unary operator");
    const uint32_t binary_neg[] = {W(CONST, F, 1), 0, W(CONST, F, 1), 0, W(BINARY, HFX_EV_NEG, 0)};
    check_invalid(binary_neg, 5, "an unknown binary operator");
    const uint32_t swz[] = {W(CONST, F, 1), 0, W(SWIZZLE, 5, 0), 0};
    check_invalid(swz, 4, "a swizzle of a wrong size");
    const uint32_t shf[] = {W(CONST, F, 1), 0, W(SHUFFLE, 17, 0), 0, 0};
    check_invalid(shf, 5, "a shuffle of a wrong size");
    const uint32_t cat[] = {W(CONST, F, 1), 0, W(CONST, F, 1), 0, W(CONCAT, 0, 0)};
    check_invalid(cat, 5, "a concatenation of a wrong size");
    const uint32_t mm[] = {W(CONST, F, 1), 0, W(CONST, F, 1), 0, W(MATMUL, 1 | 5 << 4, 1)};
    check_invalid(mm, 5, "a matrix product of a wrong shape");
}

/* Random word changes to a valid program: whatever the validator passes runs in bounds. */
static void random_changes_never_run_out_of_bounds(void) {
    const uint32_t base[] = {W(PARAM, I, 1), 1, W(TABLE, F, 2), 3, fbits(1), fbits(2), fbits(3), fbits(4), fbits(5),
                             fbits(6), W(PARAM, F, 4), 2, W(SWIZZLE, 2, 0), 0x21u, W(BINARY, HFX_EV_MUL, 0),
                             W(CALL, HFX_EV_FN_LENGTH, 0)};
    enum { N = sizeof base / sizeof base[0] };
    uint32_t code[N];
    uint32_t seed = 12345, accepted = 0;
    hfx_ev_value v;
    CHECK_INT(hfx_evc_validate(base, N, 7, NULL, 0), 0);
    for (int round = 0; round < 20000; round++) {
        memcpy(code, base, sizeof code);
        for (int k = 0; k < 1 + round % 3; k++) {
            seed = seed * 1664525u + 1013904223u;
            uint32_t at = (seed >> 8) % N;
            seed = seed * 1664525u + 1013904223u;
            code[at] = (round & 1) ? seed : code[at] ^ (1u << (seed >> 27));
        }
        uint32_t len = round % 5 == 0 ? (seed >> 4) % N + 1 : N;
        if (hfx_evc_validate(code, len, 7, NULL, 0) == 0) {
            accepted++;
            (void)hfx_evc_run(code, len, values, &v);
        }
    }
    CHECK(accepted > 0); /* some changes keep a valid program: those ran */
}

/* Preshader operations. mul(float2(1, 2), M) with M = (1 2 3; 4 5 6) (2x3): a row vector times
 * M is (1 + 8, 2 + 10, 3 + 12) = (9, 12, 15); mul(M, float3(1, 0, -1)) is a column: (1 - 3, 4 - 6)
 * = (-2, -2); the 2x2 product of (1 2; 3 4) with itself is (7 10; 15 22). */
static void matrix_products(void) {
    const uint32_t M[] = {W(CONST, F, 6), fbits(1), fbits(2), fbits(3), fbits(4), fbits(5), fbits(6)};
    uint32_t code[32], n = 0;
    code[n++] = W(CONST, I, 2); code[n++] = 1; code[n++] = 2;
    for (unsigned i = 0; i < 7; i++) code[n++] = M[i];
    code[n++] = W(MATMUL, 1 | 2 << 4, 3);
    hfx_ev_value v;
    CHECK(run(code, n, &v) && v.base == HFX_EV_FLOAT && v.n == 3 && v.c[0] == 9 && v.c[1] == 12 && v.c[2] == 15);
    n = 0;
    for (unsigned i = 0; i < 7; i++) code[n++] = M[i];
    code[n++] = W(CONST, F, 3); code[n++] = fbits(1); code[n++] = fbits(0); code[n++] = fbits(-1);
    code[n++] = W(MATMUL, 2 | 3 << 4, 1);
    CHECK(run(code, n, &v) && v.n == 2 && v.c[0] == -2 && v.c[1] == -2);
    const uint32_t sq[] = {W(CONST, F, 4), fbits(1), fbits(2), fbits(3), fbits(4),
                           W(CONST, F, 4), fbits(1), fbits(2), fbits(3), fbits(4), W(MATMUL, 2 | 2 << 4, 2)};
    CHECK(run(sq, 11, &v) && v.n == 4 && v.c[0] == 7 && v.c[1] == 10 && v.c[2] == 15 && v.c[3] == 22);
    /* shapes that do not match the operands do not run */
    const uint32_t bad[] = {W(CONST, F, 2), fbits(1), fbits(2), W(CONST, F, 2), fbits(1), fbits(2), W(MATMUL, 2 | 2 << 4, 2)};
    CHECK(!run(bad, 7, &v));
}

/* float4(v.xyz, Ref) = (1, 2, 3, 0.5); the int index 2 joined to it first is a float; the
 * 3x3 upper-left of a 4x4 (components 0 1 2, 4 5 6, 8 9 10) picked by SHUFFLE. */
static void concat_and_shuffle(void) {
    const uint32_t c4[] = {W(PARAM, F, 4), 2, W(SWIZZLE, 3, 0), 0x210u, W(PARAM, F, 1), 0, W(CONCAT, 0, 4)};
    hfx_ev_value v;
    CHECK(run(c4, 7, &v) && v.n == 4 && v.c[0] == 1 && v.c[2] == 3 && v.c[3] == 0.5);
    const uint32_t c2[] = {W(PARAM, I, 1), 1, W(PARAM, F, 1), 0, W(CONCAT, 0, 2)};
    CHECK(run(c2, 5, &v) && v.base == HFX_EV_FLOAT && v.n == 2 && v.c[0] == 2 && v.c[1] == 0.5);
    const uint32_t wrong[] = {W(PARAM, I, 1), 1, W(PARAM, F, 1), 0, W(CONCAT, 0, 3)};
    CHECK(!run(wrong, 5, &v));
    uint32_t m[20], n = 0;
    m[n++] = W(CONST, F, 16);
    for (unsigned i = 0; i < 16; i++) m[n++] = fbits((float)i);
    m[n++] = W(SHUFFLE, 9, 0);
    m[n++] = 0x98654210u; /* components 0 1 2 4 5 6 8 9 */
    m[n++] = 0xau;        /* and 10 */
    CHECK(run(m, n, &v) && v.n == 9 && v.c[0] == 0 && v.c[3] == 4 && v.c[5] == 6 && v.c[6] == 8 && v.c[8] == 10);
}

/* cross((0.5, -1.5, 2), (0.25, 3, -0.75)) = (1.125 - 6, 0.5 + 0.375, 1.5 + 0.375): the run
 * writes the result over its first argument, which must not change what the later
 * components read. */
static void cross_over_its_argument(void) {
    const uint32_t code[] = {W(CONST, F, 3), fbits(0.5f), fbits(-1.5f), fbits(2), W(CONST, F, 3), fbits(0.25f), fbits(3),
                             fbits(-0.75f), W(CALL, HFX_EV_FN_CROSS, 0)};
    hfx_ev_value v;
    CHECK(run(code, 9, &v) && v.n == 3 && v.c[0] == -4.875 && v.c[1] == 0.875 && v.c[2] == 1.875);
}

int main(void) {
    setup();
    RUN(parameter_times_constant);
    RUN(table_index_clamps);
    RUN(float_table_index);
    RUN(selector_index);
    RUN(swizzle_promotion_and_calls);
    RUN(select_and_failures);
    RUN(matrix_products);
    RUN(cross_over_its_argument);
    RUN(concat_and_shuffle);
    RUN(validator_refuses);
    RUN(random_changes_never_run_out_of_bounds);
    return test_summary();
}
