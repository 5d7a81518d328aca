/* Conversion rules (conv.c) and intrinsic signature matching (intrinsics.c), without parsing:
 * the expectations are HLSL's rules as fxc applies them for SM2/SM3. */
#include "check/conv.h"
#include "check/intrinsics.h"
#include "test.h"

static hfx_arena arena;
static hfx_types *T;

static const hfx_type *f(unsigned n) { return n == 1 ? hfx_type_scalar(T, B_FLOAT) : hfx_type_vector(T, B_FLOAT, n); }
static const hfx_type *fm(unsigned r, unsigned c) { return hfx_type_matrix(T, B_FLOAT, r, c); }
static const hfx_type *in(unsigned n) { return n == 1 ? hfx_type_scalar(T, B_INT) : hfx_type_vector(T, B_INT, n); }

static void vector_conversions(void) {
    hfx_conv c = hfx_conv_classify(f(4), f(3), false);
    CHECK(c.ok && c.truncates && c.shape == CONV_SHAPE_TRUNC);
    c = hfx_conv_classify(f(3), f(4), false);
    CHECK(!c.ok);
    c = hfx_conv_classify(f(1), f(4), false);
    CHECK(c.ok && !c.truncates && c.shape == CONV_SHAPE_SPLAT);
    c = hfx_conv_classify(f(4), f(1), false); /* float4 -> float: truncation */
    CHECK(c.ok && c.truncates);
    c = hfx_conv_classify(in(3), f(3), false);
    CHECK(c.ok && c.shape == CONV_SHAPE_EXACT && c.base == CONV_BASE_CONVERT);
    c = hfx_conv_classify(hfx_type_vector(T, B_HALF, 3), f(3), false);
    CHECK(c.ok && c.base == CONV_BASE_PROMOTE);
    c = hfx_conv_classify(hfx_type_scalar(T, B_BOOL), f(1), false);
    CHECK(c.ok && c.base == CONV_BASE_BOOL);
}

static void matrix_conversions(void) {
    hfx_conv c = hfx_conv_classify(fm(4, 4), fm(3, 3), false);
    CHECK(c.ok && c.truncates);
    CHECK(!hfx_conv_classify(fm(3, 3), fm(4, 4), false).ok);
    CHECK(!hfx_conv_classify(fm(4, 3), fm(3, 4), false).ok);
    c = hfx_conv_classify(f(4), fm(1, 4), false);
    CHECK(c.ok && !c.truncates && c.shape == CONV_SHAPE_RESHAPE);
    c = hfx_conv_classify(f(4), fm(4, 1), false);
    CHECK(c.ok && c.shape == CONV_SHAPE_RESHAPE);
    c = hfx_conv_classify(fm(1, 4), f(4), false);
    CHECK(c.ok && c.shape == CONV_SHAPE_RESHAPE);
    /* float4x4 -> float4 is an error in fxc ("cannot implicitly convert") */
    CHECK(!hfx_conv_classify(fm(4, 4), f(4), false).ok);
    CHECK(hfx_conv_classify(fm(4, 4), f(1), false).truncates);
    /* an explicit cast may reshape a 2x2 into 4 components and back */
    CHECK(hfx_conv_classify(fm(2, 2), f(4), true).ok);
}

static void object_conversions(void) {
    const hfx_type *s = hfx_type_object(T, TY_SAMPLER, DIM_GENERIC), *s2 = hfx_type_object(T, TY_SAMPLER, DIM_2D);
    const hfx_type *s3 = hfx_type_object(T, TY_SAMPLER, DIM_3D);
    CHECK(hfx_conv_classify(s, s2, false).ok);
    CHECK(hfx_conv_classify(s2, s, false).ok);
    CHECK(!hfx_conv_classify(s3, s2, false).ok);
    CHECK(!hfx_conv_classify(s2, f(1), false).ok);
    CHECK(!hfx_conv_classify(f(1), s2, false).ok);
}

static void ranking(void) {
    unsigned exact = hfx_conv_cost(hfx_conv_classify(f(3), f(3), false));
    unsigned promote = hfx_conv_cost(hfx_conv_classify(hfx_type_vector(T, B_HALF, 3), f(3), false));
    unsigned convert = hfx_conv_cost(hfx_conv_classify(in(3), f(3), false));
    unsigned splat = hfx_conv_cost(hfx_conv_classify(f(1), f(3), false));
    unsigned trunc = hfx_conv_cost(hfx_conv_classify(f(4), f(3), false));
    CHECK_INT(exact, 0);
    CHECK(exact < promote && promote < convert && convert < splat && splat < trunc);
}

static void common_shapes(void) {
    bool tr;
    CHECK(hfx_common_shape(T, f(3), f(4), B_FLOAT, &tr) == f(3) && tr);   /* float3 - float4 -> float3 */
    CHECK(hfx_common_shape(T, f(1), f(4), B_FLOAT, &tr) == f(4) && !tr);
    CHECK(hfx_common_shape(T, fm(4, 4), fm(3, 4), B_FLOAT, &tr) == fm(3, 4) && tr);
    CHECK(hfx_common_shape(T, f(3), fm(4, 4), B_FLOAT, &tr) == NULL);
    CHECK(hfx_common_shape(T, f(2), fm(1, 3), B_FLOAT, &tr) == f(2) && tr);
    CHECK_INT(hfx_base_common(B_INT, B_FLOAT), B_FLOAT);
    CHECK_INT(hfx_base_common(B_BOOL, B_INT), B_INT);
    CHECK_INT(hfx_base_common(B_HALF, B_FLOAT), B_FLOAT);
    CHECK_INT(hfx_base_common(B_UINT, B_INT), B_UINT);
}

static bool match(const char *name, const hfx_type *a, const hfx_type *b, const hfx_type *c, unsigned n,
                  hfx_intrinsic_match *m) {
    const hfx_type *args[3] = {a, b, c};
    return hfx_intrinsic_match_args(T, hfx_intrinsic_find(name), args, n, m);
}

static void mul_shapes(void) {
    hfx_intrinsic_match m;
    /* scalar * scalar, scalar * vector, vector * scalar, scalar * matrix */
    CHECK(match("mul", f(1), f(1), NULL, 2, &m) && m.ret == f(1));
    CHECK(match("mul", f(1), f(3), NULL, 2, &m) && m.ret == f(3));
    CHECK(match("mul", f(4), f(1), NULL, 2, &m) && m.ret == f(4));
    CHECK(match("mul", f(1), fm(3, 2), NULL, 2, &m) && m.ret == fm(3, 2));
    /* vector . vector is a dot product */
    CHECK(match("mul", f(3), f(3), NULL, 2, &m) && m.ret == f(1));
    /* row vector times matrix: float4 * float4x3 -> float3 */
    CHECK(match("mul", f(4), fm(4, 3), NULL, 2, &m) && m.ret == f(3) && m.params[1] == fm(4, 3));
    /* matrix times column vector: float3x4 * float4 -> float3 */
    CHECK(match("mul", fm(3, 4), f(4), NULL, 2, &m) && m.ret == f(3));
    /* matrix * matrix: float2x3 * float3x4 -> float2x4 */
    CHECK(match("mul", fm(2, 3), fm(3, 4), NULL, 2, &m) && m.ret == fm(2, 4));
    /* the seeds' mul(float3, float4x4): the matrix is clamped to float3x4, the result is float4 */
    CHECK(match("mul", f(3), fm(4, 4), NULL, 2, &m) && m.ret == f(4) && m.params[0] == f(3) && m.params[1] == fm(3, 4));
    /* mul(float4, float3x4): the vector is clamped to float3 */
    CHECK(match("mul", f(4), fm(3, 4), NULL, 2, &m) && m.ret == f(4) && m.params[0] == f(3));
    CHECK(!m.truncates);
    /* int operands stay int */
    CHECK(match("mul", in(2), in(2), NULL, 2, &m) && m.ret == in(1));
}

static void intrinsic_returns(void) {
    hfx_intrinsic_match m;
    const hfx_type *s2 = hfx_type_object(T, TY_SAMPLER, DIM_2D), *s = hfx_type_object(T, TY_SAMPLER, DIM_GENERIC);
    const hfx_type *scube = hfx_type_object(T, TY_SAMPLER, DIM_CUBE);
    CHECK(match("dot", f(3), f(3), NULL, 2, &m) && m.ret == f(1));
    CHECK(match("dot", f(3), f(4), NULL, 2, &m) && m.ret == f(1) && m.truncates && m.params[1] == f(3));
    CHECK(match("normalize", f(3), NULL, NULL, 1, &m) && m.ret == f(3));
    CHECK(!match("normalize", fm(3, 3), NULL, NULL, 1, &m));
    CHECK(match("length", f(3), NULL, NULL, 1, &m) && m.ret == f(1));
    CHECK(match("distance", f(3), f(3), NULL, 2, &m) && m.ret == f(1));
    CHECK(match("saturate", in(3), NULL, NULL, 1, &m) && m.ret == f(3)); /* int made float */
    CHECK(match("abs", in(2), NULL, NULL, 1, &m) && m.ret == in(2));     /* abs keeps int */
    CHECK(match("pow", f(1), in(1), NULL, 2, &m) && m.ret == f(1) && m.params[1] == f(1));
    CHECK(match("lerp", f(3), f(3), f(1), 3, &m) && m.ret == f(3) && m.params[2] == f(3));
    CHECK(match("max", f(3), f(1), NULL, 2, &m) && m.ret == f(3));
    CHECK(match("cross", f(3), f(3), NULL, 2, &m) && m.ret == f(3));
    CHECK(match("all", f(3), NULL, NULL, 1, &m) && m.ret == hfx_type_scalar(T, B_BOOL));
    CHECK(match("isnan", f(2), NULL, NULL, 1, &m) && m.ret == hfx_type_vector(T, B_BOOL, 2));
    CHECK(match("transpose", fm(2, 3), NULL, NULL, 1, &m) && m.ret == fm(3, 2));
    CHECK(match("determinant", fm(3, 3), NULL, NULL, 1, &m) && m.ret == f(1));
    CHECK(!match("determinant", fm(3, 2), NULL, NULL, 1, &m));
    CHECK(match("lit", f(1), f(1), f(1), 3, &m) && m.ret == f(4));
    CHECK(match("clip", f(4), NULL, NULL, 1, &m) && m.ret->kind == TY_VOID);
    CHECK(match("sincos", f(2), f(2), f(2), 3, &m) && m.ret->kind == TY_VOID && m.out[1] && m.out[2]);
    CHECK(!match("sincos", f(2), f(3), f(2), 3, &m)); /* out arguments must match exactly */
    CHECK(match("modf", f(1), f(1), NULL, 2, &m) && m.ret == f(1) && m.out[1]);
    CHECK(match("D3DCOLORtoUBYTE4", f(4), NULL, NULL, 1, &m) && m.ret == in(4));
    CHECK(match("refract", f(3), f(3), f(1), 3, &m) && m.ret == f(3) && m.params[2] == f(1));
    CHECK(match("asint", f(2), NULL, NULL, 1, &m) && m.ret == in(2));
    /* textures */
    CHECK(match("tex2D", s2, f(2), NULL, 2, &m) && m.ret == f(4));
    CHECK(match("tex2D", s, f(2), NULL, 2, &m) && m.ret == f(4)); /* generic sampler */
    CHECK(match("tex2D", s, f(3), NULL, 2, &m) && m.truncates);
    CHECK(match("tex2D", s2, f(1), NULL, 2, &m)); /* a scalar splats to float2 */
    CHECK(!match("tex2D", scube, f(2), NULL, 2, &m));       /* wrong sampler dimension */
    CHECK(!match("tex2D", f(2), f(2), NULL, 2, &m));
    CHECK(!match("tex2D", s2, f(2), f(2), 3, &m));
    CHECK(match("tex2Dlod", s2, f(4), NULL, 2, &m) && m.params[1] == f(4));
    CHECK(!match("tex2Dlod", s2, f(2), NULL, 2, &m));        /* needs a float4 */
    CHECK(match("tex2Dproj", s2, f(4), NULL, 2, &m) && m.ret == f(4));
    CHECK(match("texCUBE", scube, f(3), NULL, 2, &m) && m.params[1] == f(3));
    CHECK(match("tex1D", hfx_type_object(T, TY_SAMPLER, DIM_1D), f(1), NULL, 2, &m) && m.params[1] == f(1));
    const hfx_type *g[4] = {s2, f(2), f(2), f(2)};
    CHECK(hfx_intrinsic_match_args(T, hfx_intrinsic_find("tex2Dgrad"), g, 4, &m) && m.params[3] == f(2));
    CHECK(hfx_intrinsic_match_args(T, hfx_intrinsic_find("tex2D"), g, 4, &m));
}

static void table_lookup(void) {
    CHECK(hfx_intrinsic_find("mul") >= 0);
    CHECK_STR(hfx_intrinsic_name(hfx_intrinsic_find("D3DCOLORtoUBYTE4")), "D3DCOLORtoUBYTE4");
    CHECK_INT(hfx_intrinsic_find("Mul"), -1); /* names are case-sensitive */
    CHECK_INT(hfx_intrinsic_find("nosuch"), -1);
    CHECK(hfx_intrinsic_name(HFX_INTR_COUNT) == NULL);
    /* wrong counts never match */
    hfx_intrinsic_match m;
    CHECK(!match("dot", f(3), NULL, NULL, 1, &m));
    CHECK(!match("sin", f(3), f(3), NULL, 2, &m));
}

int main(void) {
    hfx_arena_init(&arena);
    T = hfx_types_new(&arena);
    RUN(vector_conversions);
    RUN(matrix_conversions);
    RUN(object_conversions);
    RUN(ranking);
    RUN(common_shapes);
    RUN(mul_shapes);
    RUN(intrinsic_returns);
    RUN(table_lookup);
    hfx_arena_free(&arena);
    return test_summary();
}
