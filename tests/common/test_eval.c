/* test_eval.c: common/eval, the one evaluator, against values worked out by hand from
 * Direct3D's rules (eval.h): 32-bit wrap, shifts by the low 5 bits, truncating conversions
 * that clamp, single-precision floats, and every intrinsic it folds. NAN / INFINITY rows say
 * what IEEE arithmetic gives. A row with ok = 0 must not fold. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "eval.h"
#include "test.h"

enum { B = HFX_EV_BOOL, I = HFX_EV_INT, U = HFX_EV_UINT, F = HFX_EV_FLOAT };

static int same(double got, double want) {
    if (isnan(want)) return isnan(got);
    return got == want;
}

/* (float)x: the single-precision value of x, as D3D holds it. */
static double f32(double x) { return (double)(float)x; }

static void conversions(void) {
    static const struct { int from, to; double v, want; } rows[] = {
        {F, I, 2.7, 2}, {F, I, -2.7, -2},               /* toward zero */
        {F, I, NAN, 0}, {F, I, 3e9, 2147483647}, {F, I, -3e9, -2147483648.0}, /* NaN 0, clamp */
        {F, U, -1.5, 0}, {F, U, 7.9, 7}, {F, U, 4.9e9, 4294967295.0},
        {I, U, -1, 4294967295.0}, {U, I, 4294967295.0, -1}, {U, I, 2147483648.0, -2147483648.0}, /* bits kept */
        {I, F, 16777217, 16777216},                      /* 2^24 + 1 has no float: rounds to even */
        {F, B, 0.0, 0}, {F, B, -0.5, 1}, {F, B, NAN, 1}, {I, B, -7, 1}, {B, F, 1, 1},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double got = hfx_ev_convert((hfx_ev_base)rows[i].from, (hfx_ev_base)rows[i].to, rows[i].v);
        if (!same(got, rows[i].want)) printf("  conversion row %zu: %.17g\n", i, got);
        CHECK(same(got, rows[i].want));
    }
    /* literals: 4294967295 and 0xffffffff as int are -1; 3000000000 is 3e9 - 2^32 */
    CHECK(same(hfx_ev_normalise(HFX_EV_INT, 4294967295.0), -1));
    CHECK(same(hfx_ev_normalise(HFX_EV_INT, 3000000000.0), -1294967296.0));
    CHECK(same(hfx_ev_normalise(HFX_EV_UINT, -1), 4294967295.0));
    CHECK(same(hfx_ev_normalise(HFX_EV_UINT, 3000000000.0), 3000000000.0));
    CHECK(same(hfx_ev_normalise(HFX_EV_FLOAT, 0.1), f32(0.1)));
    CHECK(same(hfx_ev_normalise(HFX_EV_INT, 2.5), 2));
}

typedef struct { hfx_ev_op op; int base; double x, y, want; int ok; } binary_row;

static const binary_row binary_rows[] = {
    /* int: wraps, truncating division, shifts by count & 31, arithmetic >> */
    {HFX_EV_ADD, I, 2147483647, 1, -2147483648.0, 1}, {HFX_EV_SUB, I, -2147483648.0, 1, 2147483647, 1},
    {HFX_EV_MUL, I, 65536, 65536, 0, 1}, {HFX_EV_MUL, I, 65537, 65537, 131073, 1}, /* 2^32 + 2^17 + 1 */
    {HFX_EV_DIV, I, 7, -2, -3, 1}, {HFX_EV_MOD, I, -7, 3, -1, 1}, {HFX_EV_DIV, I, 1, 0, 0, 0},
    {HFX_EV_MOD, I, 1, 0, 0, 0}, {HFX_EV_DIV, I, -2147483648.0, -1, 0, 0},
    {HFX_EV_SHL, I, 1, 33, 2, 1}, {HFX_EV_SHL, I, 1, 31, -2147483648.0, 1}, {HFX_EV_SHR, I, -8, 1, -4, 1},
    {HFX_EV_SHR, I, -1, 31, -1, 1}, {HFX_EV_SHR, I, 5, 32, 5, 1}, {HFX_EV_SHL, I, 3, -1, -2147483648.0, 1},
    {HFX_EV_BITAND, I, 6, 3, 2, 1}, {HFX_EV_BITOR, I, 6, 3, 7, 1}, {HFX_EV_BITXOR, I, 6, 3, 5, 1},
    {HFX_EV_BITAND, I, -1, 255, 255, 1}, {HFX_EV_LT, I, -3, 5, 1, 1}, {HFX_EV_GE, I, -3, 5, 0, 1},
    {HFX_EV_EQ, I, 4, 4, 1, 1}, {HFX_EV_AND, I, 2, 0, 0, 1}, {HFX_EV_OR, I, 2, 0, 1, 1},
    /* uint: wraps, logical >>, no division by zero */
    {HFX_EV_SUB, U, 0, 1, 4294967295.0, 1}, {HFX_EV_SHR, U, 4294967295.0, 31, 1, 1},
    {HFX_EV_DIV, U, 4294967295.0, 2, 2147483647, 1}, {HFX_EV_MOD, U, 7, 0, 0, 0},
    {HFX_EV_LT, U, 4294967295.0, 1, 0, 1}, {HFX_EV_ADD, U, 4294967295.0, 2, 1, 1},
    /* float: single precision, IEEE division, fmod, NaN compares false except != */
    {HFX_EV_ADD, F, 1.5, 2.25, 3.75, 1}, {HFX_EV_ADD, F, 16777216, 1, 16777216, 1},
    {HFX_EV_DIV, F, 1, 3, 0.3333333432674408, 1}, {HFX_EV_DIV, F, 1, 0, INFINITY, 1},
    {HFX_EV_DIV, F, 0, 0, NAN, 1}, {HFX_EV_MOD, F, -7.5, 2, -1.5, 1}, {HFX_EV_MOD, F, 7.5, -2, 1.5, 1},
    {HFX_EV_LT, F, NAN, 1, 0, 1}, {HFX_EV_GE, F, NAN, 1, 0, 1}, {HFX_EV_EQ, F, NAN, NAN, 0, 1},
    {HFX_EV_NE, F, NAN, NAN, 1, 1}, {HFX_EV_GT, F, INFINITY, 1e38, 1, 1},
    {HFX_EV_SHL, F, 1, 2, 0, 0}, {HFX_EV_BITAND, F, 1, 1, 0, 0}, {HFX_EV_AND, F, 0.5, NAN, 1, 1},
    /* bool: comparisons and logic only */
    {HFX_EV_EQ, B, 1, 1, 1, 1}, {HFX_EV_OR, B, 0, 1, 1, 1}, {HFX_EV_ADD, B, 1, 1, 0, 0},
};

/* Comparisons with NaN and infinities as Direct3D 10's "Floating-point rules" give them (the
 * one rule Microsoft documents): EQ, GT, GE, LT, LE with a NaN are false, NE is true; +INF is
 * above every finite value. The folder and the preshaders compute with these. */
static void nan_comparisons(void) {
    static const struct { hfx_ev_op op; double x, y, want; } rows[] = {
        {HFX_EV_LT, NAN, 1, 0}, {HFX_EV_GT, NAN, -1, 0}, {HFX_EV_LE, 1, NAN, 0}, {HFX_EV_GE, NAN, NAN, 0},
        {HFX_EV_EQ, NAN, NAN, 0}, {HFX_EV_NE, NAN, NAN, 1}, {HFX_EV_NE, NAN, 1, 1},
        {HFX_EV_GT, INFINITY, FLT_MAX, 1}, {HFX_EV_LT, -INFINITY, -FLT_MAX, 1}, {HFX_EV_EQ, INFINITY, INFINITY, 1},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double got = -1;
        CHECK(hfx_ev_binary(rows[i].op, HFX_EV_FLOAT, rows[i].x, rows[i].y, &got));
        CHECK(got == rows[i].want);
    }
}

static void binary_operators(void) {
    for (size_t i = 0; i < sizeof binary_rows / sizeof binary_rows[0]; i++) {
        const binary_row *r = &binary_rows[i];
        double got = -12345;
        int ok = hfx_ev_binary(r->op, (hfx_ev_base)r->base, r->x, r->y, &got);
        if (ok != r->ok || (ok && !same(got, r->want))) printf("  binary row %zu: ok %d, %.17g\n", i, ok, got);
        CHECK_INT(ok, r->ok);
        if (r->ok) CHECK(same(got, r->want));
    }
    CHECK_INT(hfx_ev_result_base(HFX_EV_LT, HFX_EV_FLOAT), HFX_EV_BOOL);
    CHECK_INT(hfx_ev_result_base(HFX_EV_ADD, HFX_EV_UINT), HFX_EV_UINT);
}

static void unary_operators(void) {
    static const struct { hfx_ev_op op; int base; double x, want; int ok; } rows[] = {
        {HFX_EV_NEG, I, -2147483648.0, -2147483648.0, 1}, {HFX_EV_NEG, U, 1, 4294967295.0, 1},
        {HFX_EV_NEG, F, 0.5, -0.5, 1}, {HFX_EV_NOT, F, 0.0, 1, 1}, {HFX_EV_NOT, I, 3, 0, 1},
        {HFX_EV_BITNOT, I, 0, -1, 1}, {HFX_EV_BITNOT, U, 0, 4294967295.0, 1}, {HFX_EV_BITNOT, F, 1, 0, 0},
        {HFX_EV_POS, I, 7, 7, 1}, {HFX_EV_NEG, B, 1, 0, 0},
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double got = -12345;
        int ok = hfx_ev_unary(rows[i].op, (hfx_ev_base)rows[i].base, rows[i].x, &got);
        CHECK_INT(ok, rows[i].ok);
        if (rows[i].ok) CHECK(same(got, rows[i].want));
    }
}

static hfx_ev_value v4(int base, int n, double a, double b, double c, double d) {
    hfx_ev_value v = {(hfx_ev_base)base, (uint8_t)n, {a, b, c, d}};
    return v;
}

/* One-component intrinsics on floats, and the ones defined on ints too. */
static void scalar_intrinsics(void) {
    const double pi = 3.14159265358979323846;
    static const struct { hfx_ev_fn fn; int base; double a, b, c, want; int ok; } rows[] = {
        {HFX_EV_FN_ABS, F, -2.5, 0, 0, 2.5, 1}, {HFX_EV_FN_ABS, I, -2147483648.0, 0, 0, -2147483648.0, 1},
        {HFX_EV_FN_ACOS, F, 1, 0, 0, 0, 1}, /* fxc's polynomial, sqrt taking |1 - |x||: acos(2) = p(2) * 1 */
        {HFX_EV_FN_ACOS, F, 2, 0, 0, 1.293709635734558, 1}, {HFX_EV_FN_ASIN, F, 0, 0, 0, 1.57079637f - 1.57072878f, 1},
        {HFX_EV_FN_ATAN, F, 0, 0, 0, 0, 1}, {HFX_EV_FN_CEIL, F, 1.2, 0, 0, 2, 1}, {HFX_EV_FN_CEIL, F, -1.2, 0, 0, -1, 1},
        {HFX_EV_FN_FLOOR, F, -1.2, 0, 0, -2, 1}, {HFX_EV_FN_FRAC, F, -1.25, 0, 0, 0.75, 1},
        {HFX_EV_FN_ROUND, F, 2.5, 0, 0, 3, 1}, {HFX_EV_FN_ROUND, F, -2.5, 0, 0, -2, 1}, /* floor(x + 0.5) */
        {HFX_EV_FN_TRUNC, F, -1.7, 0, 0, -1, 1}, {HFX_EV_FN_COS, F, 0, 0, 0, 1, 1}, {HFX_EV_FN_COSH, F, 0, 0, 0, 1, 1},
        {HFX_EV_FN_SIN, F, 0, 0, 0, 0, 1}, {HFX_EV_FN_SINH, F, 0, 0, 0, 0, 1}, {HFX_EV_FN_TAN, F, 0, 0, 0, 0, 1},
        {HFX_EV_FN_TANH, F, 0, 0, 0, 0, 1}, {HFX_EV_FN_EXP, F, 0, 0, 0, 1, 1}, {HFX_EV_FN_EXP2, F, 3, 0, 0, 8, 1},
        {HFX_EV_FN_LOG, F, 1, 0, 0, 0, 1}, {HFX_EV_FN_LOG, F, 0, 0, 0, (double)(float)(-FLT_MAX * 0.69314718055994531), 1} /* D3D9's log: -FLT_MAX at 0, scaled by ln 2 */, {HFX_EV_FN_LOG2, F, 8, 0, 0, 3, 1},
        {HFX_EV_FN_LOG10, F, 1000, 0, 0, 3, 1}, {HFX_EV_FN_SQRT, F, 16, 0, 0, 4, 1}, {HFX_EV_FN_SQRT, F, -4, 0, 0, 2, 1} /* rcp(rsq(x)): rsq takes |x| */,
        {HFX_EV_FN_RSQRT, F, 4, 0, 0, 0.5, 1}, {HFX_EV_FN_RSQRT, F, 0, 0, 0, FLT_MAX, 1} /* D3D9's rsq: FLT_MAX at 0 */,
        {HFX_EV_FN_LOG2, F, -8, 0, 0, 3, 1}, {HFX_EV_FN_RSQRT, F, -4, 0, 0, 0.5, 1},
        {HFX_EV_FN_SATURATE, F, 1.5, 0, 0, 1, 1}, {HFX_EV_FN_SATURATE, F, -0.5, 0, 0, 0, 1},
        {HFX_EV_FN_SATURATE, F, NAN, 0, 0, 0, 1}, {HFX_EV_FN_SIGN, F, -3.5, 0, 0, -1, 1}, {HFX_EV_FN_SIGN, I, 0, 0, 0, 0, 1},
        {HFX_EV_FN_SIGN, I, 9, 0, 0, 1, 1}, {HFX_EV_FN_MIN, F, NAN, 1, 0, 1, 1}, {HFX_EV_FN_MAX, F, 1, NAN, 0, 1, 1},
        {HFX_EV_FN_MIN, I, -3, 2, 0, -3, 1}, {HFX_EV_FN_MAX, U, 4294967295.0, 2, 0, 4294967295.0, 1},
        {HFX_EV_FN_CLAMP, F, 5, 0, 3, 3, 1}, {HFX_EV_FN_CLAMP, F, NAN, 0, 1, 0, 1}, {HFX_EV_FN_CLAMP, I, -4, -2, 2, -2, 1},
        {HFX_EV_FN_FMOD, F, 7, 3, 0, 1, 1}, {HFX_EV_FN_FMOD, F, -7, 3, 0, -1, 1}, {HFX_EV_FN_POW, F, 2, 10, 0, 1024, 1},
        {HFX_EV_FN_POW, F, -2, 2, 0, 4, 1}, {HFX_EV_FN_POW, F, -8, 1.0 / 3, 0, 2, 1}, /* |x|^y */ {HFX_EV_FN_POW, F, 0, 0, 0, 1, 1}, {HFX_EV_FN_ATAN2, F, 0, 1, 0, 0, 1},
        {HFX_EV_FN_LERP, F, 0, 10, 0.25, 2.5, 1}, {HFX_EV_FN_SMOOTHSTEP, F, 0, 1, 0.5, 0.5, 1},
        {HFX_EV_FN_SMOOTHSTEP, F, 0, 1, 2, 1, 1}, {HFX_EV_FN_STEP, F, 0.5, 0.4, 0, 0, 1}, {HFX_EV_FN_STEP, F, 0.5, 0.5, 0, 1, 1},
        {HFX_EV_FN_FLOOR, I, 1, 0, 0, 0, 0}, /* float-only functions on ints: the checker converts first */
    };
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        hfx_ev_value args[3] = {v4(rows[i].base, 1, rows[i].a, 0, 0, 0), v4(rows[i].base, 1, rows[i].b, 0, 0, 0),
                                v4(rows[i].base, 1, rows[i].c, 0, 0, 0)};
        hfx_ev_value out = {0};
        int ok = hfx_ev_call(rows[i].fn, args, (unsigned)hfx_ev_fn_args(rows[i].fn), &out);
        if (ok != rows[i].ok || (ok && !same(out.c[0], rows[i].want)))
            printf("  %s row %zu: ok %d, %.17g\n", hfx_ev_fn_name(rows[i].fn), i, ok, out.c[0]);
        CHECK_INT(ok, rows[i].ok);
        if (rows[i].ok) CHECK(same(out.c[0], rows[i].want) && out.n == 1);
    }
    /* results are single precision: atan2(1, 1) is fxc's polynomial at 1, (((0.0208350997 -
     * 0.0851330012) + 0.180141002) - 0.330299497) + 0.999866009 = 0.78540963, not pi / 4;
     * degrees(1) 180 / pi */
    hfx_ev_value one = v4(F, 1, 1, 0, 0, 0), two[2] = {one, one}, out;
    CHECK(hfx_ev_call(HFX_EV_FN_ATAN2, two, 2, &out) && fabs(out.c[0] - 0.78540963) < 1e-7);
    CHECK(hfx_ev_call(HFX_EV_FN_DEGREES, &one, 1, &out) && same(out.c[0], f32(180 / pi)));
    CHECK(hfx_ev_call(HFX_EV_FN_RADIANS, &one, 1, &out) && same(out.c[0], f32(pi / 180)));
    CHECK(!hfx_ev_call(HFX_EV_FN_ATAN2, two, 1, &out)); /* wrong argument count */
}

static void vector_intrinsics(void) {
    hfx_ev_value a = v4(F, 3, 1, 2, 3, 0), b = v4(F, 3, 4, 5, 6, 0), out, ab[2] = {a, b};
    CHECK(hfx_ev_call(HFX_EV_FN_DOT, ab, 2, &out) && out.n == 1 && out.c[0] == 32); /* 4 + 10 + 18 */
    hfx_ev_value x = v4(F, 3, 1, 0, 0, 0), y = v4(F, 3, 0, 1, 0, 0), xy[2] = {x, y};
    CHECK(hfx_ev_call(HFX_EV_FN_CROSS, xy, 2, &out) && out.n == 3 && out.c[0] == 0 && out.c[1] == 0 && out.c[2] == 1);
    hfx_ev_value p = v4(F, 2, 3, 4, 0, 0), q = v4(F, 2, 4, 5, 0, 0), pq[2] = {v4(F, 2, 1, 1, 0, 0), q};
    CHECK(hfx_ev_call(HFX_EV_FN_LENGTH, &p, 1, &out) && out.c[0] == 5);
    CHECK(hfx_ev_call(HFX_EV_FN_DISTANCE, pq, 2, &out) && out.c[0] == 5); /* (3, 4) apart */
    hfx_ev_value n = v4(F, 3, 3, 0, 4, 0);
    CHECK(hfx_ev_call(HFX_EV_FN_NORMALIZE, &n, 1, &out) && out.n == 3 && out.c[0] == f32(0.6) && out.c[2] == f32(0.8));
    hfx_ev_value bits = v4(B, 2, 1, 0, 0, 0);
    CHECK(hfx_ev_call(HFX_EV_FN_ALL, &bits, 1, &out) && out.base == HFX_EV_BOOL && out.c[0] == 0);
    CHECK(hfx_ev_call(HFX_EV_FN_ANY, &bits, 1, &out) && out.c[0] == 1);
    hfx_ev_value ia = v4(I, 2, 65536, 3, 0, 0), ib = v4(I, 2, 65536, 2, 0, 0), iab[2] = {ia, ib};
    CHECK(hfx_ev_call(HFX_EV_FN_DOT, iab, 2, &out) && out.base == HFX_EV_INT && out.c[0] == 6); /* 2^32 wraps to 0 */
    hfx_ev_value mixed[2] = {a, p};
    CHECK(!hfx_ev_call(HFX_EV_FN_DOT, mixed, 2, &out)); /* 3 and 2 components */
    /* componentwise with a scalar splat: max((1, 2, 3), 2) = (2, 2, 3) */
    hfx_ev_value m[2] = {a, v4(F, 1, 2, 0, 0, 0)};
    CHECK(hfx_ev_call(HFX_EV_FN_MAX, m, 2, &out) && out.n == 3 && out.c[0] == 2 && out.c[1] == 2 && out.c[2] == 3);
    CHECK_STR(hfx_ev_fn_name(HFX_EV_FN_NORMALIZE), "NORMALIZE");
    CHECK(hfx_ev_fn_name(HFX_EV_FN_COUNT) == NULL);
}

static void whole_values(void) {
    hfx_ev_value a = v4(I, 3, 1, 2, 3, 0), one = v4(I, 1, 1, 0, 0, 0), out;
    CHECK(hfx_ev_apply(HFX_EV_ADD, &a, &one, &out) && out.n == 3 && out.c[0] == 2 && out.c[2] == 4);
    hfx_ev_value two = v4(I, 2, 1, 1, 0, 0);
    CHECK(!hfx_ev_apply(HFX_EV_ADD, &a, &two, &out));
    CHECK(hfx_ev_apply(HFX_EV_LT, &a, &one, &out) && out.base == HFX_EV_BOOL && out.c[0] == 0 && out.c[1] == 0);
    CHECK(hfx_ev_apply(HFX_EV_NEG, &a, NULL, &out) && out.c[1] == -2);
    hfx_ev_value zero = v4(I, 1, 0, 0, 0, 0);
    CHECK(!hfx_ev_apply(HFX_EV_DIV, &a, &zero, &out));
    /* fit: a scalar splats, a longer value truncates, a shorter one does not fit */
    hfx_ev_value f = v4(F, 1, -2.5, 0, 0, 0), four = v4(F, 4, 1.5, 2.5, 3.5, 4.5);
    CHECK(hfx_ev_fit(&f, HFX_EV_INT, 3, &out) && out.n == 3 && out.c[2] == -2 && out.base == HFX_EV_INT);
    CHECK(hfx_ev_fit(&four, HFX_EV_FLOAT, 2, &out) && out.n == 2 && out.c[1] == 2.5);
    CHECK(!hfx_ev_fit(&two, HFX_EV_INT, 3, &out));
}

/* hfx_ev_int / hfx_ev_uint, the one float-to-integer conversion of the libraries: where C's cast
 * is undefined (NaN, infinities, beyond the type) it gives the clamp of the rule above. */
static void to_integers(void) {
    static const struct { double v; int32_t i; uint32_t u; } rows[] = {
        {2.9, 2, 2}, {-2.9, -2, 0}, {-0.5, 0, 0}, {0.0, 0, 0},           /* toward zero; uint: negatives 0 */
        {NAN, 0, 0}, {INFINITY, INT32_MAX, UINT32_MAX}, {-INFINITY, INT32_MIN, 0},
        {1e30, INT32_MAX, UINT32_MAX}, {-1e30, INT32_MIN, 0}, {1e10, INT32_MAX, UINT32_MAX},
        {FLT_MAX, INT32_MAX, UINT32_MAX}, {FLT_TRUE_MIN, 0, 0},            /* a denormal */
        {2147483647.9, INT32_MAX, 2147483647u}, {2147483648.0, INT32_MAX, 2147483648u},
        {-2147483648.9, INT32_MIN, 0}, {4294967295.9, INT32_MAX, UINT32_MAX}, {3e9, INT32_MAX, 3000000000u},
    };
    for (size_t k = 0; k < sizeof rows / sizeof *rows; k++) {
        CHECK_INT(hfx_ev_int(rows[k].v), rows[k].i);
        CHECK_INT(hfx_ev_uint(rows[k].v), rows[k].u);
    }
    /* int <-> uint keep the low 32 bits, also of integral values beyond 64 bits (no cast of them) */
    CHECK(hfx_ev_convert(HFX_EV_INT, HFX_EV_UINT, 1e20) == 1661992960.0); /* 1e20 mod 2^32 */
    CHECK(hfx_ev_convert(HFX_EV_UINT, HFX_EV_INT, -4294967297.0) == -1.0);
    CHECK(hfx_ev_convert(HFX_EV_INT, HFX_EV_UINT, INFINITY) == 0.0);
}

int main(void) {
    RUN(conversions);
    RUN(to_integers);
    RUN(binary_operators);
    RUN(nan_comparisons);
    RUN(unary_operators);
    RUN(scalar_intrinsics);
    RUN(vector_intrinsics);
    RUN(whole_values);
    return test_summary();
}
