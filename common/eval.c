/* eval.c: Direct3D's arithmetic on constants (see eval.h for the rules). */
#include "eval.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* ---- conversions ---- */

static double round_float(double v) { return (double)(float)v; }

static double float_to_int(double v) {
    if (isnan(v)) return 0;
    if (v >= 2147483647.0) return 2147483647.0;
    if (v <= -2147483648.0) return -2147483648.0;
    return trunc(v);
}

static double float_to_uint(double v) {
    if (isnan(v) || v <= 0) return 0;
    return v >= 4294967295.0 ? 4294967295.0 : trunc(v);
}

/* The only casts from a floating type to an integer one in the libraries: v is already
 * truncated into the target's range, so the cast is defined. */
int32_t hfx_ev_int(double v) { return (int32_t)float_to_int(v); }
uint32_t hfx_ev_uint(double v) { return (uint32_t)float_to_uint(v); }

/* The low 32 bits of an integral double, as int or uint (fmod is exact; NaN and infinities,
 * which no int holds, give 0). */
static uint32_t bits_u(double v) {
    double m = fmod(trunc(v), 4294967296.0);
    return hfx_ev_uint(m < 0 ? m + 4294967296.0 : m);
}
static int32_t bits_i(double v) { return (int32_t)bits_u(v); }

double hfx_ev_convert(hfx_ev_base from, hfx_ev_base to, double v) {
    switch (to) {
    case HFX_EV_BOOL: return v != 0;
    case HFX_EV_FLOAT: return round_float(v);
    case HFX_EV_INT: return from == HFX_EV_FLOAT ? float_to_int(v) : (double)bits_i(v);
    case HFX_EV_UINT: return from == HFX_EV_FLOAT ? float_to_uint(v) : (double)bits_u(v);
    default: return v;
    }
}

static bool is_wrappable(double v) { return v == trunc(v) && fabs(v) < 9.2e18; }

double hfx_ev_normalise(hfx_ev_base b, double v) {
    if (b == HFX_EV_INT || b == HFX_EV_UINT)
        return hfx_ev_convert(is_wrappable(v) ? HFX_EV_INT : HFX_EV_FLOAT, b, v);
    return hfx_ev_convert(HFX_EV_FLOAT, b, v);
}

hfx_ev_base hfx_ev_result_base(hfx_ev_op op, hfx_ev_base b) {
    return op == HFX_EV_NOT || op >= HFX_EV_LT ? HFX_EV_BOOL : b;
}

/* ---- operators ---- */

bool hfx_ev_unary(hfx_ev_op op, hfx_ev_base b, double x, double *out) {
    switch (op) {
    case HFX_EV_POS: *out = x; return b != HFX_EV_BOOL;
    case HFX_EV_NOT: *out = x == 0; return true;
    case HFX_EV_NEG:
        if (b == HFX_EV_FLOAT) *out = -x;
        else if (b == HFX_EV_INT) *out = (double)(int32_t)(0u - (uint32_t)bits_i(x));
        else *out = (double)(0u - bits_u(x));
        return b != HFX_EV_BOOL;
    case HFX_EV_BITNOT:
        *out = b == HFX_EV_INT ? (double)~bits_i(x) : (double)~bits_u(x);
        return b == HFX_EV_INT || b == HFX_EV_UINT;
    default: return false;
    }
}

static bool compare(hfx_ev_op op, double x, double y, double *out) {
    switch (op) {
    case HFX_EV_LT: *out = x < y; return true;
    case HFX_EV_GT: *out = x > y; return true;
    case HFX_EV_LE: *out = x <= y; return true;
    case HFX_EV_GE: *out = x >= y; return true;
    case HFX_EV_EQ: *out = x == y; return true;
    case HFX_EV_NE: *out = x != y; return true;
    case HFX_EV_AND: *out = x != 0 && y != 0; return true;
    case HFX_EV_OR: *out = x != 0 || y != 0; return true;
    default: return false;
    }
}

static bool float_op(hfx_ev_op op, double x, double y, double *out) {
    switch (op) {
    case HFX_EV_ADD: *out = round_float(x + y); return true;
    case HFX_EV_SUB: *out = round_float(x - y); return true;
    case HFX_EV_MUL: *out = round_float(x * y); return true;
    case HFX_EV_DIV: *out = round_float(x / y); return true;
    case HFX_EV_MOD: *out = round_float(fmod(x, y)); return true;
    default: return compare(op, x, y, out);
    }
}

/* Bit operations on 32 bits, shared by int and uint (the caller reads the bits back). */
static bool bits_op(hfx_ev_op op, uint32_t x, uint32_t y, uint32_t *out) {
    switch (op) {
    case HFX_EV_ADD: *out = x + y; return true;
    case HFX_EV_SUB: *out = x - y; return true;
    case HFX_EV_MUL: *out = x * y; return true;
    case HFX_EV_SHL: *out = x << (y & 31); return true;
    case HFX_EV_BITAND: *out = x & y; return true;
    case HFX_EV_BITOR: *out = x | y; return true;
    case HFX_EV_BITXOR: *out = x ^ y; return true;
    default: return false;
    }
}

static bool int_op(hfx_ev_op op, double dx, double dy, double *out) {
    int32_t x = bits_i(dx), y = bits_i(dy);
    uint32_t u;
    if (op == HFX_EV_DIV || op == HFX_EV_MOD) {
        if (y == 0 || (x == INT32_MIN && y == -1)) return false;
        *out = op == HFX_EV_DIV ? x / y : x % y;
        return true;
    }
    if (op == HFX_EV_SHR) { /* arithmetic, without C's implementation-defined >> on negatives */
        uint32_t s = (uint32_t)y & 31, ux = (uint32_t)x;
        *out = (double)(int32_t)(x < 0 ? ~(~ux >> s) : ux >> s);
        return true;
    }
    if (bits_op(op, (uint32_t)x, (uint32_t)y, &u)) { *out = (double)(int32_t)u; return true; }
    return compare(op, x, y, out);
}

static bool uint_op(hfx_ev_op op, double dx, double dy, double *out) {
    uint32_t x = bits_u(dx), y = bits_u(dy), u;
    if (op == HFX_EV_DIV || op == HFX_EV_MOD) {
        if (y == 0) return false;
        *out = op == HFX_EV_DIV ? x / y : x % y;
        return true;
    }
    if (op == HFX_EV_SHR) { *out = x >> (y & 31); return true; }
    if (bits_op(op, x, y, &u)) { *out = u; return true; }
    return compare(op, x, y, out);
}

bool hfx_ev_binary(hfx_ev_op op, hfx_ev_base b, double x, double y, double *out) {
    switch (b) {
    case HFX_EV_FLOAT: return float_op(op, x, y, out);
    case HFX_EV_INT: return int_op(op, x, y, out);
    case HFX_EV_UINT: return uint_op(op, x, y, out);
    default: return op >= HFX_EV_LT && compare(op, x != 0, y != 0, out);
    }
}

bool hfx_ev_apply(hfx_ev_op op, const hfx_ev_value *x, const hfx_ev_value *y, hfx_ev_value *out) {
    unsigned n = y && y->n > x->n ? y->n : x->n;
    if (!n || n > HFX_EV_MAX_COMPONENTS || (y && x->n != n && x->n != 1) || (y && y->n != n && y->n != 1)) return false;
    hfx_ev_value r = {hfx_ev_result_base(op, x->base), (uint8_t)n, {0}};
    for (unsigned i = 0; i < n; i++) {
        double a = x->c[x->n == 1 ? 0 : i];
        bool ok = y ? hfx_ev_binary(op, x->base, a, y->c[y->n == 1 ? 0 : i], &r.c[i]) : hfx_ev_unary(op, x->base, a, &r.c[i]);
        if (!ok) return false;
    }
    *out = r;
    return true;
}

bool hfx_ev_fit(const hfx_ev_value *x, hfx_ev_base b, unsigned n, hfx_ev_value *out) {
    if (!n || n > HFX_EV_MAX_COMPONENTS || (x->n != 1 && x->n < n)) return false;
    hfx_ev_value r = {b, (uint8_t)n, {0}};
    for (unsigned i = 0; i < n; i++) r.c[i] = hfx_ev_convert(x->base, b, x->c[x->n == 1 ? 0 : i]);
    *out = r;
    return true;
}

/* ---- intrinsics ---- */

/* A row's place is its number in files: moving or inserting a row would change what stored
 * programs call. */
#define HFX_EV_FUNC(name, number, args) \
    _Static_assert(HFX_EV_FN_##name == (number), "eval_funcs.def: " #name " must keep its stored number");
#include "eval_funcs.def"
#undef HFX_EV_FUNC

static const struct {
    const char *name;
    int args;
} funcs[HFX_EV_FN_COUNT] = {
#define HFX_EV_FUNC(name, number, args) [HFX_EV_FN_##name] = {#name, args},
#include "eval_funcs.def"
#undef HFX_EV_FUNC
};

int hfx_ev_fn_args(hfx_ev_fn fn) { return fn >= 0 && fn < HFX_EV_FN_COUNT ? funcs[fn].args : 0; }
const char *hfx_ev_fn_name(hfx_ev_fn fn) { return fn >= 0 && fn < HFX_EV_FN_COUNT ? funcs[fn].name : NULL; }

static double saturate(double x) { return x > 0 ? (x < 1 ? x : 1) : 0; } /* NaN gives 0 */
static double sign_of(double x) { return (x > 0) - (x < 0); }

/* D3D9's log instruction: log2 of |x|, -FLT_MAX at 0; log and log10 scale it, sqrt takes |x|
 * (fxc builds it from rsq, which does). */
static double d3d_log2(double x) { return x != 0 ? log2(fabs(x)) : -FLT_MAX; }
static double d3d_log(double x) { return d3d_log2(x) * 0.69314718055994531; }
static double d3d_log10(double x) { return d3d_log2(x) * 0.30102999566398120; }
static double d3d_sqrt(double x) { return sqrt(fabs(x)); }

/* asin, acos, atan and atan2 as fxc expands them into instructions (Direct3D 9 has none for
 * them): fixed polynomials in single precision, the printer's hfx_acos... (glsl_intrin.c), so
 * a value folded or preshaded is the value the GPU computes. */
static double fxc_acos(double x) {
    double a = fabs(x);
    double p = round_float(round_float(round_float(round_float(a * -0.0187292993f) + 0.0742610022f) * a) - 0.212114394f);
    p = round_float(round_float(p * a) + 1.57072878f);
    double r = round_float(p * round_float(sqrt(fabs(round_float(1.0 - a)))));
    return x < -x ? round_float(r + round_float(round_float(r * -2.0) + 3.14159274f)) : r;
}
static double fxc_asin(double x) { return round_float(1.57079637f - fxc_acos(x)); }
/* atan of a = min / max in 0..1, folded to the octant the caller says */
static double fxc_atan01(double a) {
    double s = round_float(a * a);
    double p = round_float(round_float(s * 0.0208350997f) - 0.0851330012f);
    p = round_float(round_float(p * s) + 0.180141002f);
    p = round_float(round_float(p * s) - 0.330299497f);
    p = round_float(round_float(p * s) + 0.999866009f);
    return round_float(a * p);
}
static double fxc_atan(double x) {
    double ax = fabs(x), r = fxc_atan01(round_float(fmin(ax, 1.0) * round_float(1.0 / fmax(ax, 1.0))));
    if (1.0 < ax) r = round_float(r + round_float(round_float(r * -2.0) + 1.57079637f));
    return x < -x ? -r : r;
}
static double fxc_atan2(double y, double x) {
    double ax = fabs(x), ay = fabs(y);
    double r = fxc_atan01(round_float(fmin(ax, ay) * round_float(1.0 / fmax(ax, ay))));
    if (ax < ay) r = round_float(r + round_float(round_float(r * -2.0) + 1.57079637f));
    if (x < -x) r = round_float(r - 3.14159274f);
    double lo = fmin(x, y), hi = fmax(x, y);
    return lo < -lo && hi >= -hi ? -r : r;
}

/* Componentwise float functions of one argument. */
static bool float1(hfx_ev_fn fn, double x, double *out) {
    static double (*const libm[])(double) = {
        [HFX_EV_FN_ACOS] = fxc_acos, [HFX_EV_FN_ASIN] = fxc_asin, [HFX_EV_FN_ATAN] = fxc_atan, [HFX_EV_FN_CEIL] = ceil,
        [HFX_EV_FN_COS] = cos, [HFX_EV_FN_COSH] = cosh, [HFX_EV_FN_EXP] = exp, [HFX_EV_FN_EXP2] = exp2,
        [HFX_EV_FN_FLOOR] = floor, [HFX_EV_FN_LOG] = d3d_log, [HFX_EV_FN_LOG10] = d3d_log10, [HFX_EV_FN_LOG2] = d3d_log2,
        [HFX_EV_FN_SIN] = sin, [HFX_EV_FN_SINH] = sinh, [HFX_EV_FN_SQRT] = d3d_sqrt, [HFX_EV_FN_TAN] = tan,
        [HFX_EV_FN_TANH] = tanh, [HFX_EV_FN_TRUNC] = trunc, [HFX_EV_FN_ABS] = fabs, [HFX_EV_FN_SATURATE] = saturate,
        [HFX_EV_FN_SIGN] = sign_of};
    if ((size_t)fn < sizeof libm / sizeof libm[0] && libm[fn]) *out = libm[fn](x);
    else if (fn == HFX_EV_FN_DEGREES) *out = x * (180.0 / 3.14159265358979323846);
    else if (fn == HFX_EV_FN_RADIANS) *out = x * (3.14159265358979323846 / 180.0);
    else if (fn == HFX_EV_FN_FRAC) *out = x - floor(x);
    else if (fn == HFX_EV_FN_ROUND) *out = floor(x + 0.5);
    else if (fn == HFX_EV_FN_RSQRT) *out = x != 0 ? 1.0 / sqrt(fabs(x)) : FLT_MAX; /* D3D9's rsq */
    else return false;
    *out = round_float(*out);
    return true;
}

/* Componentwise float functions of two and three arguments. */
static bool float23(hfx_ev_fn fn, const double *a, double *out) {
    switch (fn) {
    case HFX_EV_FN_ATAN2: *out = fxc_atan2(a[0], a[1]); break;
    case HFX_EV_FN_FMOD: *out = fmod(a[0], a[1]); break;
    case HFX_EV_FN_POW: *out = pow(fabs(a[0]), a[1]); break; /* D3D9's pow instruction takes |x| */
    case HFX_EV_FN_STEP: *out = a[1] >= a[0]; break;
    case HFX_EV_FN_LERP: *out = a[0] + a[2] * (a[1] - a[0]); break;
    case HFX_EV_FN_SMOOTHSTEP: {
        double t = saturate((a[2] - a[0]) / (a[1] - a[0]));
        *out = t * t * (3 - 2 * t);
        break;
    }
    default: return false;
    }
    *out = round_float(*out);
    return true;
}

/* min and max give the other operand when one is NaN, as Direct3D 10's min / max do. */
static double min_of(double x, double y) { return x < y || isnan(y) ? x : y; }
static double max_of(double x, double y) { return x > y || isnan(y) ? x : y; }

/* min, max, clamp, abs, sign: defined on int and uint too. */
static bool any_base(hfx_ev_fn fn, hfx_ev_base b, const double *a, double *out) {
    switch (fn) {
    case HFX_EV_FN_MIN: *out = min_of(a[0], a[1]); return true;
    case HFX_EV_FN_MAX: *out = max_of(a[0], a[1]); return true;
    case HFX_EV_FN_CLAMP: *out = min_of(max_of(a[0], a[1]), a[2]); return true;
    case HFX_EV_FN_SIGN: *out = sign_of(a[0]); return true;
    case HFX_EV_FN_ABS:
        if (b == HFX_EV_FLOAT) return float1(fn, a[0], out);
        *out = b == HFX_EV_INT ? (double)bits_i(fabs(a[0])) : a[0]; /* abs(INT_MIN) wraps to INT_MIN */
        return true;
    default: return b == HFX_EV_FLOAT && (float1(fn, a[0], out) || float23(fn, a, out));
    }
}

static bool componentwise(hfx_ev_fn fn, const hfx_ev_value *args, unsigned n, hfx_ev_value *out) {
    unsigned m = 1;
    for (unsigned i = 0; i < n; i++) {
        if (args[i].n != 1 && m != 1 && args[i].n != m) return false;
        if (args[i].n > m) m = args[i].n;
    }
    hfx_ev_value r = {args[0].base, (uint8_t)m, {0}};
    for (unsigned k = 0; k < m; k++) {
        double a[3] = {0};
        for (unsigned i = 0; i < n; i++) a[i] = args[i].c[args[i].n == 1 ? 0 : k];
        if (!any_base(fn, args[0].base, a, &r.c[k])) return false;
    }
    *out = r;
    return true;
}

static double dot_of(const hfx_ev_value *x, const hfx_ev_value *y) {
    double s = 0;
    for (unsigned i = 0; i < x->n; i++) s += x->c[i] * y->c[i];
    return s;
}

static void scalar(hfx_ev_value *out, hfx_ev_base b, double v) {
    memset(out, 0, sizeof *out);
    out->base = b;
    out->n = 1;
    out->c[0] = v;
}

/* dot, length, distance, normalize, cross, all, any: functions of whole vectors. */
static bool vector_fn(hfx_ev_fn fn, const hfx_ev_value *a, unsigned n, hfx_ev_value *out) {
    hfx_ev_base b = a[0].base;
    if (n == 2 && a[0].n != a[1].n) return false;
    if (fn == HFX_EV_FN_DOT) {
        scalar(out, b, b == HFX_EV_FLOAT ? round_float(dot_of(&a[0], &a[1])) : hfx_ev_normalise(b, dot_of(&a[0], &a[1])));
        return b != HFX_EV_BOOL;
    }
    if (fn == HFX_EV_FN_ALL || fn == HFX_EV_FN_ANY) {
        bool all = true, any = false;
        for (unsigned i = 0; i < a[0].n; i++) all = all && a[0].c[i] != 0, any = any || a[0].c[i] != 0;
        scalar(out, HFX_EV_BOOL, fn == HFX_EV_FN_ALL ? all : any);
        return true;
    }
    if (b != HFX_EV_FLOAT) return false;
    if (fn == HFX_EV_FN_LENGTH) { scalar(out, b, round_float(sqrt(dot_of(&a[0], &a[0])))); return true; }
    if (fn == HFX_EV_FN_DISTANCE) {
        hfx_ev_value d;
        if (!hfx_ev_apply(HFX_EV_SUB, &a[0], &a[1], &d)) return false;
        scalar(out, b, round_float(sqrt(dot_of(&d, &d))));
        return true;
    }
    *out = a[0];
    if (fn == HFX_EV_FN_NORMALIZE) {
        double len = sqrt(dot_of(&a[0], &a[0]));
        for (unsigned i = 0; i < a[0].n; i++) out->c[i] = round_float(a[0].c[i] / len);
        return true;
    }
    if (fn != HFX_EV_FN_CROSS || a[0].n != 3) return false;
    const double *x = a[0].c, *y = a[1].c; /* out may be a[0]: all three before any is written */
    double c0 = x[1] * y[2] - x[2] * y[1], c1 = x[2] * y[0] - x[0] * y[2], c2 = x[0] * y[1] - x[1] * y[0];
    out->c[0] = round_float(c0);
    out->c[1] = round_float(c1);
    out->c[2] = round_float(c2);
    return true;
}

static bool is_vector_fn(hfx_ev_fn fn) {
    return fn == HFX_EV_FN_DOT || fn == HFX_EV_FN_CROSS || fn == HFX_EV_FN_LENGTH || fn == HFX_EV_FN_DISTANCE ||
           fn == HFX_EV_FN_NORMALIZE || fn == HFX_EV_FN_ALL || fn == HFX_EV_FN_ANY;
}

bool hfx_ev_call(hfx_ev_fn fn, const hfx_ev_value *args, unsigned n, hfx_ev_value *out) {
    if ((int)n != hfx_ev_fn_args(fn)) return false;
    for (unsigned i = 0; i < n; i++)
        if (args[i].base != args[0].base || !args[i].n || args[i].n > HFX_EV_MAX_COMPONENTS) return false;
    return is_vector_fn(fn) ? vector_fn(fn, args, n, out) : componentwise(fn, args, n, out);
}
