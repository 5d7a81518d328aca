/* test_params.c: parameters, annotations, techniques and clones on a hand-built effect, with
 * XNA's semantics for every set and get. */
#include "gl_context.h"
#include "internal.h"
#include "rt_support.h"
#include "test.h"

static test_gl *gl;
static hfx_device *dev;

enum { P_B, P_I, P_F, P_V, P_M, P_M3, P_M43, P_ARR, P_SPOTS, P_TEX, P_SAMP, P_IVEC, P_BOOLS, P_TOP };

static hfx_fx_effect *build(void) {
    hfx_fx_effect *fx = tb_new();
    tb_param(fx, "b", "b", HFX_CLASS_SCALAR, HFX_TYPE_BOOL, 1, 1, 0, HFX_NONE, 0, 1);
    tb_param(fx, "i", "i", HFX_CLASS_SCALAR, HFX_TYPE_INT, 1, 1, 0, HFX_NONE, 1, 1);
    tb_param(fx, "f", "f", HFX_CLASS_SCALAR, HFX_TYPE_FLOAT, 1, 1, 0, HFX_NONE, 2, 1);
    tb_param(fx, "v", "v", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 3, 4);
    tb_param(fx, "m", "m", HFX_CLASS_MATRIX, HFX_TYPE_FLOAT, 4, 4, 0, HFX_NONE, 7, 16);
    tb_param(fx, "m3", "m3", HFX_CLASS_MATRIX, HFX_TYPE_FLOAT, 3, 3, 0, HFX_NONE, 23, 9);
    tb_param(fx, "m43", "m43", HFX_CLASS_MATRIX, HFX_TYPE_FLOAT, 4, 3, 0, HFX_NONE, 32, 12);
    tb_param(fx, "arr", "arr", HFX_CLASS_SCALAR, HFX_TYPE_FLOAT, 1, 1, 4, HFX_NONE, 44, 4);
    tb_param(fx, "spots", "spots", HFX_CLASS_STRUCT, HFX_TYPE_VOID, 0, 0, 2, HFX_NONE, 48, 14);
    tb_param(fx, "tex", NULL, HFX_CLASS_OBJECT, HFX_TYPE_TEXTURE2D, 0, 0, 0, HFX_NONE, 0, 0);
    tb_param(fx, "samp", "samp", HFX_CLASS_OBJECT, HFX_TYPE_SAMPLER2D, 0, 0, 0, HFX_NONE, 0, 0);
    tb_param(fx, "ivec", "ivec", HFX_CLASS_VECTOR, HFX_TYPE_INT, 1, 3, 0, HFX_NONE, 62, 3);
    tb_param(fx, "bools", "bools", HFX_CLASS_SCALAR, HFX_TYPE_BOOL, 1, 1, 3, HFX_NONE, 65, 3);
    uint32_t first = fx->param_count;
    for (uint32_t e = 0; e < 4; e++) tb_param(fx, "", NULL, HFX_CLASS_SCALAR, HFX_TYPE_FLOAT, 1, 1, 0, P_ARR, 44 + e, 1);
    tb_children(fx, P_ARR, first, 4);
    uint32_t s0 = tb_param(fx, "", NULL, HFX_CLASS_STRUCT, HFX_TYPE_VOID, 0, 0, 0, P_SPOTS, 48, 7);
    uint32_t s1 = tb_param(fx, "", NULL, HFX_CLASS_STRUCT, HFX_TYPE_VOID, 0, 0, 0, P_SPOTS, 55, 7);
    tb_children(fx, P_SPOTS, s0, 2);
    for (uint32_t e = 0; e < 2; e++) {
        uint32_t base = 48 + 7 * e;
        uint32_t a = tb_param(fx, "Posicion", "Posicion", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 3, 0, s0 + e, base, 3);
        tb_param(fx, "Color", "Color", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, s0 + e, base + 3, 4);
        tb_children(fx, s0 + e, a, 2);
    }
    (void)s1;
    for (uint32_t e = 0; e < 3; e++) tb_param(fx, "", NULL, HFX_CLASS_SCALAR, HFX_TYPE_BOOL, 1, 1, 0, P_BOOLS, 65 + e, 1);
    tb_children(fx, P_BOOLS, fx->param_count - 3, 3);
    fx->values[0] = 1;        /* bool b = true */
    tb_set_float(fx, 2, 0.25f); /* float f = 0.25 */
    fx->params[P_M].semantic = strdup("WorldViewProjection");
    fx->params[P_F].first_annotation = tb_annotation_s(fx, "UIName", "Scale");
    float half = 0.5f;
    tb_annotation_f(fx, "UIMin", &half, 1);
    tb_annotation_i(fx, "UIStep", HFX_TYPE_INT, 3);
    fx->params[P_F].annotation_count = 3;
    float four[4] = {1, 2, 3, 4};
    uint32_t ta = tb_annotation_f(fx, "Tint", four, 4);
    tb_technique(fx, "A");
    fx->techniques[0].first_annotation = ta;
    fx->techniques[0].annotation_count = 1;
    tb_pass(fx, "P0", HFX_NONE, 0, 0);
    tb_pass(fx, "P1", HFX_NONE, 0, 0);
    tb_technique(fx, "B");
    tb_pass(fx, "Only", HFX_NONE, 0, 0);
    return fx;
}

static hfx_effect *load(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_rt_effect_from_fx(dev, build(), NULL, &errors);
    CHECK(fx != NULL);
    CHECK(errors == NULL);
    hfx_free(errors);
    return fx;
}

static void test_description(void) {
    hfx_effect *fx = load();
    CHECK_INT(hfx_effect_param_count(fx), P_TOP);
    hfx_param *m43 = hfx_effect_param(fx, "m43");
    CHECK_INT(hfx_param_get_class(m43), HFX_CLASS_MATRIX);
    CHECK_INT(hfx_param_get_type(m43), HFX_TYPE_FLOAT);
    CHECK_INT(hfx_param_rows(m43), 4);
    CHECK_INT(hfx_param_columns(m43), 3);
    CHECK_INT(hfx_param_elements(m43), 0);
    hfx_param *spots = hfx_effect_param(fx, "spots");
    CHECK_INT(hfx_param_get_class(spots), HFX_CLASS_STRUCT);
    CHECK_INT(hfx_param_elements(spots), 2);
    CHECK_INT(hfx_param_member_count(spots), 0); /* an array has elements, not members */
    hfx_param *s1 = hfx_param_element(spots, 1);
    CHECK_INT(hfx_param_member_count(s1), 2);
    CHECK_STR(hfx_param_name(hfx_param_member_at(s1, 1)), "Color");
    CHECK_INT(hfx_param_get_type(hfx_effect_param(fx, "tex")), HFX_TYPE_TEXTURE2D);
    CHECK_INT(hfx_param_get_class(hfx_effect_param(fx, "samp")), HFX_CLASS_OBJECT);
    CHECK_STR(hfx_param_semantic(hfx_effect_param(fx, "m")), "WorldViewProjection");
    CHECK_STR(hfx_param_semantic(hfx_effect_param(fx, "f")), "");
    CHECK(hfx_effect_param_by_semantic(fx, "worldviewPROJECTION") == hfx_effect_param(fx, "m"));
    CHECK(hfx_effect_param_at(fx, P_V) == hfx_effect_param(fx, "v"));
    CHECK_STR(hfx_param_name(hfx_effect_param_at(fx, P_IVEC)), "ivec");
    hfx_effect_destroy(fx);
}

static void test_scalars_and_defaults(void) {
    hfx_effect *fx = load();
    int b = -1, i = -1;
    float f = -1;
    CHECK_INT(hfx_param_get_bool(hfx_effect_param(fx, "b"), &b), HFX_OK);
    CHECK_INT(b, 1);
    CHECK_INT(hfx_param_get_float(hfx_effect_param(fx, "f"), &f), HFX_OK);
    CHECK_NEAR(f, 0.25, 0);
    CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "b"), 7), HFX_OK);
    CHECK_INT(hfx_param_get_bool(hfx_effect_param(fx, "b"), &b), HFX_OK);
    CHECK_INT(b, 1);
    CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "b"), 0), HFX_OK);
    CHECK_INT(hfx_param_get_bool(hfx_effect_param(fx, "b"), &b), HFX_OK);
    CHECK_INT(b, 0);
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "i"), -42), HFX_OK);
    CHECK_INT(hfx_param_get_int(hfx_effect_param(fx, "i"), &i), HFX_OK);
    CHECK_INT(i, -42);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "f"), 3.5f), HFX_OK);
    CHECK_INT(hfx_param_get_float(hfx_effect_param(fx, "f"), &f), HFX_OK);
    CHECK_NEAR(f, 3.5, 0);
    hfx_effect_destroy(fx);
}

static void test_vectors_and_arrays(void) {
    hfx_effect *fx = load();
    float v[4] = {1, -2, 3.5f, 4}, out[4] = {0};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "v"), v, 4), HFX_OK);
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(fx, "v"), out, 4), HFX_OK);
    for (int k = 0; k < 4; k++) CHECK_NEAR(out[k], v[k], 0);
    int iv[3] = {7, 8, 9}, iout[3] = {0};
    CHECK_INT(hfx_param_set_ints(hfx_effect_param(fx, "ivec"), iv, 3), HFX_OK);
    CHECK_INT(hfx_param_get_ints(hfx_effect_param(fx, "ivec"), iout, 3), HFX_OK);
    CHECK_INT(iout[2], 9);
    /* arrays: the whole, a prefix (as XNA allows), one element through its handle */
    hfx_param *arr = hfx_effect_param(fx, "arr");
    float a[4] = {10, 11, 12, 13};
    CHECK_INT(hfx_param_set_floats(arr, a, 4), HFX_OK);
    float two[2] = {20, 21};
    CHECK_INT(hfx_param_set_floats(arr, two, 2), HFX_OK);
    CHECK_INT(hfx_param_set_float(hfx_param_element(arr, 3), 33), HFX_OK);
    CHECK_INT(hfx_param_get_floats(arr, out, 4), HFX_OK);
    CHECK_NEAR(out[0], 20, 0);
    CHECK_NEAR(out[1], 21, 0);
    CHECK_NEAR(out[2], 12, 0);
    CHECK_NEAR(out[3], 33, 0);
    float e2 = 0;
    CHECK_INT(hfx_param_get_float(hfx_param_element(arr, 2), &e2), HFX_OK);
    CHECK_NEAR(e2, 12, 0);
    /* bool arrays store 0/1 */
    int bv[3] = {5, 0, -1}, bo[3] = {9, 9, 9};
    CHECK_INT(hfx_param_set_ints(hfx_effect_param(fx, "bools"), bv, 3), HFX_OK);
    CHECK_INT(hfx_param_get_ints(hfx_effect_param(fx, "bools"), bo, 3), HFX_OK);
    CHECK_INT(bo[0], 1);
    CHECK_INT(bo[1], 0);
    CHECK_INT(bo[2], 1);
    int eb = 9;
    CHECK_INT(hfx_param_get_bool(hfx_param_element(hfx_effect_param(fx, "bools"), 2), &eb), HFX_OK);
    CHECK_INT(eb, 1);
    hfx_effect_destroy(fx);
}

static void test_struct_arrays(void) {
    hfx_effect *fx = load();
    hfx_param *spots = hfx_effect_param(fx, "spots");
    hfx_param *pos1 = hfx_param_member(hfx_param_element(spots, 1), "Posicion");
    hfx_param *col0 = hfx_param_member(hfx_param_element(spots, 0), "Color");
    CHECK(pos1 != NULL && col0 != NULL);
    float p[3] = {1, 2, 3}, c[4] = {0.1f, 0.2f, 0.3f, 1}, out[4];
    CHECK_INT(hfx_param_set_floats(pos1, p, 3), HFX_OK);
    CHECK_INT(hfx_param_set_floats(col0, c, 4), HFX_OK);
    CHECK_INT(hfx_param_get_floats(pos1, out, 3), HFX_OK);
    CHECK_NEAR(out[2], 3, 0);
    /* the layout: spots[1].Posicion is words 7..9 of the struct array, spots[0].Color 3..6 */
    CHECK_NEAR(((float *)fx->values)[48 + 7 + 1], 2, 0);
    CHECK_NEAR(((float *)fx->values)[48 + 3 + 2], 0.3, 1e-7);
    CHECK(hfx_param_member(hfx_param_element(spots, 1), "Nope") == NULL);
    CHECK_STR(hfx_device_last_error(dev), "parameter '' has no member 'Nope'");
    CHECK(hfx_param_member(spots, "Color") == NULL); /* an array, not a struct */
    CHECK(hfx_param_element(spots, 2) == NULL);
    hfx_effect_destroy(fx);
}

static void test_matrices(void) {
    hfx_effect *fx = load();
    float m[16], out[16];
    for (int k = 0; k < 16; k++) m[k] = (float)k;
    hfx_param *pm = hfx_effect_param(fx, "m");
    CHECK_INT(hfx_param_set_matrix(pm, m), HFX_OK);
    CHECK_INT(hfx_param_get_floats(pm, out, 16), HFX_OK);
    for (int k = 0; k < 16; k++) CHECK_NEAR(out[k], k, 0); /* stored as given: translation at 12..14 */
    CHECK_INT(hfx_param_set_matrix_transpose(pm, m), HFX_OK);
    CHECK_INT(hfx_param_get_matrix(pm, out), HFX_OK);
    CHECK_NEAR(out[1], 4, 0);  /* row 0, col 1 = m[col 1 * 4 + row 0] */
    CHECK_NEAR(out[12], 3, 0);
    CHECK_NEAR(out[14], 11, 0);
    /* float3x3 takes the top-left 3x3 */
    hfx_param *m3 = hfx_effect_param(fx, "m3");
    CHECK_INT(hfx_param_set_matrix(m3, m), HFX_OK);
    float f9[9];
    CHECK_INT(hfx_param_get_floats(m3, f9, 9), HFX_OK);
    const float want9[9] = {0, 1, 2, 4, 5, 6, 8, 9, 10};
    for (int k = 0; k < 9; k++) CHECK_NEAR(f9[k], want9[k], 0);
    CHECK_INT(hfx_param_get_matrix(m3, out), HFX_OK);
    CHECK_NEAR(out[5], 5, 0);
    CHECK_NEAR(out[3], 0, 0);
    CHECK_NEAR(out[15], 0, 0);
    /* float4x3: four rows of three */
    hfx_param *m43 = hfx_effect_param(fx, "m43");
    CHECK_INT(hfx_param_set_matrix(m43, m), HFX_OK);
    float f12[12];
    CHECK_INT(hfx_param_get_floats(m43, f12, 12), HFX_OK);
    const float want12[12] = {0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14};
    for (int k = 0; k < 12; k++) CHECK_NEAR(f12[k], want12[k], 0);
    hfx_effect_destroy(fx);
}

static void test_textures(void) {
    hfx_effect *fx = load();
    unsigned t = 99;
    CHECK_INT(hfx_param_get_texture(hfx_effect_param(fx, "tex"), &t), HFX_OK);
    CHECK_INT(t, 0);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "tex"), 5), HFX_OK);
    CHECK_INT(hfx_param_get_texture(hfx_effect_param(fx, "tex"), &t), HFX_OK);
    CHECK_INT(t, 5);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "samp"), 6), HFX_OK);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "f"), 6), HFX_ERR_TYPE);
    CHECK_INT(hfx_param_get_texture(hfx_effect_param(fx, "v"), &t), HFX_ERR_TYPE);
    hfx_effect_destroy(fx);
}

static void test_bad_calls_change_nothing(void) {
    hfx_effect *fx = load();
    float f = 0;
    hfx_param *pf = hfx_effect_param(fx, "f");
    uint64_t stamp = fx->stamps[P_F];
    CHECK_INT(hfx_param_set_int(pf, 3), HFX_ERR_TYPE);
    CHECK_STR(hfx_device_last_error(dev), "parameter 'f': not an int");
    CHECK_INT(hfx_param_set_bool(pf, 1), HFX_ERR_TYPE);
    CHECK_INT(hfx_param_set_matrix(pf, (float[16]){0}), HFX_ERR_TYPE);
    CHECK_INT(hfx_param_set_ints(pf, (int[1]){1}, 1), HFX_ERR_TYPE);
    CHECK_INT(hfx_param_get_float(pf, &f), HFX_OK);
    CHECK_NEAR(f, 0.25, 0);
    CHECK(fx->stamps[P_F] == stamp);
    float v3[3] = {9, 9, 9};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "v"), v3, 3), HFX_ERR_COUNT);
    CHECK_STR(hfx_device_last_error(dev), "parameter 'v': wrong number of values");
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "arr"), (float[5]){0}, 5), HFX_ERR_COUNT);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "v"), NULL, 4), HFX_ERR_NULL);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "spots"), v3, 3), HFX_ERR_TYPE);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "ivec"), v3, 3), HFX_ERR_TYPE);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "v"), (float[16]){0}), HFX_ERR_TYPE);
    CHECK_INT(hfx_param_set_float(NULL, 1), HFX_ERR_NULL);
    CHECK_INT(hfx_param_get_float(pf, NULL), HFX_ERR_NULL);
    CHECK(hfx_effect_param(fx, "nope") == NULL);
    CHECK_STR(hfx_device_last_error(dev), "no parameter named 'nope'");
    CHECK(hfx_effect_param(fx, NULL) == NULL);
    CHECK(hfx_effect_param(NULL, "f") == NULL);
    CHECK(hfx_effect_param_at(fx, 100) == NULL);
    CHECK(hfx_effect_param_by_semantic(fx, "POSITION") == NULL);
    CHECK(hfx_param_element(pf, 0) == NULL);
    CHECK(hfx_param_member(NULL, "x") == NULL);
    CHECK_STR(hfx_param_name(NULL), "");
    float v[4];
    CHECK_INT(hfx_param_get_floats(hfx_effect_param(fx, "v"), v, 4), HFX_OK);
    CHECK_NEAR(v[0], 0, 0);
    hfx_effect_destroy(fx);
}

static void test_unchanged_value_keeps_version(void) {
    hfx_effect *fx = load();
    hfx_param *pf = hfx_effect_param(fx, "f");
    uint64_t s0 = fx->stamps[P_F];
    CHECK_INT(hfx_param_set_float(pf, 0.25f), HFX_OK); /* same as the default */
    CHECK(fx->stamps[P_F] == s0);
    CHECK_INT(hfx_param_set_float(pf, 0.5f), HFX_OK);
    CHECK(fx->stamps[P_F] != s0);
    uint64_t sp = fx->stamps[P_SPOTS];
    CHECK_INT(hfx_param_set_floats(hfx_param_member(hfx_param_element(hfx_effect_param(fx, "spots"), 1), "Color"),
                                   (float[4]){1, 1, 1, 1}, 4), HFX_OK);
    CHECK(fx->stamps[P_SPOTS] != sp); /* a member's change is its top-level parameter's */
    hfx_effect_destroy(fx);
}

static void test_annotations(void) {
    hfx_effect *fx = load();
    hfx_param *pf = hfx_effect_param(fx, "f");
    CHECK_INT(hfx_param_annotation_count(pf), 3);
    hfx_annotation *name = hfx_param_annotation(pf, "UIName");
    CHECK_STR(hfx_annotation_string(name), "Scale");
    CHECK_INT(hfx_annotation_type(name), HFX_TYPE_STRING);
    float f = 0;
    CHECK_INT(hfx_annotation_float(name, &f), HFX_ERR_TYPE);
    hfx_annotation *min = hfx_param_annotation(pf, "UIMin");
    CHECK(hfx_annotation_string(min) == NULL);
    CHECK_INT(hfx_annotation_float(min, &f), HFX_OK);
    CHECK_NEAR(f, 0.5, 0);
    int i = 9;
    CHECK_INT(hfx_annotation_int(min, &i), HFX_OK);
    CHECK_INT(i, 0);
    hfx_annotation *step = hfx_param_annotation_at(pf, 2);
    CHECK_STR(hfx_annotation_name(step), "UIStep");
    CHECK_INT(hfx_annotation_float(step, &f), HFX_OK);
    CHECK_NEAR(f, 3, 0);
    CHECK(hfx_param_annotation(pf, "Missing") == NULL);
    CHECK(hfx_param_annotation_at(pf, 3) == NULL);
    hfx_annotation *tint = hfx_technique_annotation(hfx_effect_technique(fx, "A"), "Tint");
    float t4[4];
    CHECK_INT(hfx_annotation_floats(tint, t4, 4), HFX_OK);
    CHECK_NEAR(t4[3], 4, 0);
    CHECK_INT(hfx_annotation_floats(tint, t4, 3), HFX_ERR_COUNT);
    CHECK(hfx_pass_annotation(hfx_technique_pass(hfx_effect_technique(fx, "A"), 0), "Tint") == NULL);
    hfx_effect_destroy(fx);
}

static void test_techniques(void) {
    hfx_effect *fx = load();
    CHECK_INT(hfx_effect_technique_count(fx), 2);
    hfx_technique *a = hfx_effect_technique(fx, "A"), *b = hfx_effect_technique(fx, "B");
    CHECK(hfx_effect_current_technique(fx) == a); /* the first, as XNA */
    hfx_effect_set_current_technique(fx, b);
    CHECK(hfx_effect_current_technique(fx) == b);
    CHECK_STR(hfx_technique_name(hfx_effect_current_technique(fx)), "B");
    CHECK_INT(hfx_technique_pass_count(a), 2);
    CHECK_INT(hfx_technique_pass_count(b), 1);
    CHECK_STR(hfx_pass_name(hfx_technique_pass(a, 1)), "P1");
    CHECK(hfx_technique_pass_by_name(a, "P1") == hfx_technique_pass(a, 1));
    CHECK(hfx_technique_pass_by_name(a, "Only") == NULL);
    CHECK(hfx_technique_pass(b, 1) == NULL);
    CHECK(hfx_effect_technique(fx, "C") == NULL);
    CHECK_STR(hfx_device_last_error(dev), "no technique named 'C'");
    CHECK(hfx_effect_technique_at(fx, 1) == b);
    hfx_effect_set_current_technique(fx, NULL); /* refused, current unchanged */
    CHECK(hfx_effect_current_technique(fx) == b);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(b, 0)), HFX_OK); /* no program: states only */
    CHECK_INT(hfx_pass_apply(NULL), HFX_ERR_NULL);
    hfx_effect_destroy(fx);
}

static void test_clone_independence(void) {
    hfx_effect *fx = load();
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "f"), 2.0f), HFX_OK);
    hfx_effect_set_current_technique(fx, hfx_effect_technique(fx, "B"));
    hfx_effect *c = hfx_effect_clone(fx);
    CHECK(c != NULL);
    float f = 0;
    CHECK_INT(hfx_param_get_float(hfx_effect_param(c, "f"), &f), HFX_OK);
    CHECK_NEAR(f, 2.0, 0); /* a clone starts with the values of its source */
    CHECK_STR(hfx_technique_name(hfx_effect_current_technique(c)), "B");
    CHECK_INT(hfx_param_set_float(hfx_effect_param(c, "f"), 7.0f), HFX_OK);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(c, "tex"), 3), HFX_OK);
    CHECK_INT(hfx_param_get_float(hfx_effect_param(fx, "f"), &f), HFX_OK);
    CHECK_NEAR(f, 2.0, 0);
    unsigned t = 1;
    CHECK_INT(hfx_param_get_texture(hfx_effect_param(fx, "tex"), &t), HFX_OK);
    CHECK_INT(t, 0);
    hfx_effect_set_current_technique(c, hfx_effect_technique(c, "A"));
    CHECK_STR(hfx_technique_name(hfx_effect_current_technique(fx)), "B");
    hfx_effect_set_current_technique(fx, hfx_effect_technique(c, "A")); /* another effect's: refused */
    CHECK_STR(hfx_technique_name(hfx_effect_current_technique(fx)), "B");
    hfx_effect_destroy(fx); /* the clone keeps the shared part alive */
    CHECK_INT(hfx_param_get_float(hfx_effect_param(c, "f"), &f), HFX_OK);
    CHECK_NEAR(f, 7.0, 0);
    hfx_effect_destroy(c);
    CHECK(hfx_effect_clone(NULL) == NULL);
}

/* Misuse beyond wrong types: counts on the way out, other effects' and devices' handles,
 * annotations of another kind, NULLs everywhere; each call fails with its code and changes
 * nothing (the output buffers included). */
static void test_misuse_changes_nothing(void) {
    hfx_effect *fx = load();
    hfx_param *v = hfx_effect_param(fx, "v"), *f = hfx_effect_param(fx, "f"), *iv = hfx_effect_param(fx, "ivec");
    float four[4] = {1, 2, 3, 4}, out[5] = {7, 7, 7, 7, 7};
    CHECK_INT(hfx_param_set_floats(v, four, 4), HFX_OK);
    uint64_t stamp = fx->stamps[P_V];
    CHECK_INT(hfx_param_get_floats(v, out, 3), HFX_ERR_COUNT);
    CHECK_INT(hfx_param_get_floats(v, out, 5), HFX_ERR_COUNT);
    CHECK_NEAR(out[0], 7, 0); /* the caller's buffer untouched */
    CHECK_INT(hfx_param_set_matrix_transpose(v, (float[16]){0}), HFX_ERR_TYPE);
    CHECK_INT(hfx_param_set_texture(v, 5), HFX_ERR_TYPE);
    CHECK_STR(hfx_device_last_error(dev), "parameter 'v': not a texture or sampler");
    unsigned tex = 9;
    CHECK_INT(hfx_param_get_texture(v, &tex), HFX_ERR_TYPE);
    CHECK_INT(tex, 9);
    int ints[4] = {5, 5, 5, 5};
    CHECK_INT(hfx_param_get_ints(v, ints, 4), HFX_ERR_TYPE);
    CHECK_INT(ints[0], 5);
    CHECK_INT(hfx_param_set_ints(iv, ints, 2), HFX_ERR_COUNT);
    CHECK_INT(hfx_param_get_ints(iv, ints, 3), HFX_OK);
    CHECK_INT(ints[0], 0);
    CHECK_INT(hfx_param_get_floats(v, out, 4), HFX_OK);
    CHECK_NEAR(out[3], 4, 0);
    CHECK(fx->stamps[P_V] == stamp);
    hfx_annotation *name = hfx_param_annotation(f, "UIName"), *min = hfx_param_annotation(f, "UIMin");
    float a = 3;
    CHECK_INT(hfx_annotation_float(name, &a), HFX_ERR_TYPE);
    CHECK_STR(hfx_device_last_error(dev), "annotation 'UIName' is not numeric");
    CHECK_INT(hfx_annotation_floats(min, out, 2), HFX_ERR_COUNT);
    CHECK_NEAR(a, 3, 0);
    CHECK(hfx_annotation_string(min) == NULL);
    CHECK(hfx_param_annotation(f, NULL) == NULL);
    CHECK(hfx_param_element(hfx_effect_param(fx, "arr"), 4) == NULL);
    CHECK(hfx_param_member_at(hfx_param_element(hfx_effect_param(fx, "spots"), 0), 2) == NULL);
    CHECK_INT(hfx_pass_attribute_location(NULL, "POSITION0"), -1);
    CHECK_INT(hfx_pass_attribute_location(hfx_technique_pass(hfx_effect_technique(fx, "A"), 0), NULL), -1);
    CHECK_INT(hfx_effect_begin(NULL), HFX_ERR_NULL);
    CHECK_INT(hfx_effect_end(NULL), HFX_ERR_NULL);
    CHECK_INT(hfx_effect_reload(NULL, "x.fx", NULL, NULL), HFX_ERR_NULL);
    CHECK(hfx_effect_technique_at(NULL, 0) == NULL);
    CHECK(hfx_technique_pass(NULL, 0) == NULL);
    CHECK_INT(hfx_technique_pass_count(NULL), 0);
    hfx_effect_destroy(fx);
}

/* Handles of another effect (loaded apart, or on another device) are refused; a clone's passes
 * apply after the effect it was cloned from is gone. */
static void test_foreign_handles(void) {
    hfx_effect *fx = load(), *other = load();
    hfx_device *dev2 = hfx_device_create_gl(test_gl_loader);
    hfx_effect *far = hfx_rt_effect_from_fx(dev2, build(), NULL, NULL);
    CHECK(far != NULL);
    hfx_technique *b = hfx_effect_technique(fx, "B");
    hfx_effect_set_current_technique(fx, b);
    hfx_effect_set_current_technique(fx, hfx_effect_technique(other, "A"));
    CHECK_STR(hfx_device_last_error(dev), "technique does not belong to this effect");
    hfx_effect_set_current_technique(fx, hfx_effect_technique(far, "A"));
    CHECK(hfx_effect_current_technique(fx) == b);
    hfx_effect *clone = hfx_effect_clone(fx);
    hfx_effect_destroy(fx);
    hfx_technique *cb = hfx_effect_current_technique(clone);
    CHECK_STR(hfx_technique_name(cb), "B");
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(cb, 0)), HFX_OK);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(clone, "A"), 1)), HFX_OK);
    CHECK(hfx_effect_device(clone) == dev);
    CHECK(hfx_effect_device(far) == dev2);
    hfx_effect_destroy(clone);
    hfx_effect_destroy(other);
    hfx_effect_destroy(far);
    hfx_device_destroy(dev2);
}

int main(void) {
    gl = test_gl_create(8, 8);
    if (!gl) test_skip("no OSMesa context");
    dev = hfx_device_create_gl(test_gl_loader);
    CHECK(dev != NULL);
    RUN(test_description);
    RUN(test_scalars_and_defaults);
    RUN(test_vectors_and_arrays);
    RUN(test_struct_arrays);
    RUN(test_matrices);
    RUN(test_textures);
    RUN(test_bad_calls_change_nothing);
    RUN(test_unchanged_value_keeps_version);
    RUN(test_annotations);
    RUN(test_techniques);
    RUN(test_clone_independence);
    RUN(test_misuse_changes_nothing);
    RUN(test_foreign_handles);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
