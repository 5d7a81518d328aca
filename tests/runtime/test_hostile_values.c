/* test_hostile_values.c: values from hostile or extreme input that C cannot convert to an
 * integer (NaN, infinities, 1e30: C11 6.3.1.4 leaves the cast undefined) give what Direct3D's
 * rule gives (common/eval.h: truncate, NaN 0, out of range clamps), at the four places the
 * runtime converts them: a float state at load, an int read of a float annotation, states bound
 * to parameters at Apply, and the shader-array selector of a hostile .hfxo. Under the sanitizer
 * build (-fsanitize=float-cast-overflow, fatal) each of these stopped the test before the fix. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "eval_code.h"
#include "gl_context.h"
#include "hfx/hfxc.h"
#include "internal.h"
#include "rt_support.h"
#include "test.h"

#define W 4
#define H 4

static test_gl *gl;
static tgl g;
static hfx_device *dev;

#define PROGRAM \
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n" \
    "float4 PS() : COLOR { return float4(1, 1, 1, 1); }\n"
#define SHADERS "VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS();"

static hfx_effect *load(const char *src, const char *name) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, strlen(src), name, NULL, &errors);
    if (!fx) printf("  %s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    return fx;
}

static int apply(hfx_effect *fx) {
    return hfx_pass_apply(hfx_technique_pass(hfx_effect_technique_at(fx, 0), 0));
}

/* `DepthBias = 1e30;` (valid: a float state) is looked at once at load, where its int view is
 * 2147483647 by the rule; at Apply the bias itself stays 1e30. */
static void float_state_at_load(void) {
    hfx_effect *fx = load(PROGRAM "technique T { pass P { DepthBias = 1e30; " SHADERS " } }", "bias.fx");
    if (!fx) return;
    CHECK_STR(hfx_effect_warnings(fx), "");
    CHECK_INT(apply(fx), HFX_OK);
    CHECK(dev->rs[HFX_ST_DEPTHBIAS].f[0] == 1e30f);
    CHECK_INT(dev->rs[HFX_ST_DEPTHBIAS].i, INT32_MAX);
    hfx_effect_destroy(fx);
}

/* hfx_annotation_int on float annotations: 1e10 and 1e39 (+inf as a float) clamp to INT_MAX,
 * -1e10 to INT_MIN, 0/0 (NaN) gives 0, -2.9 truncates to -2. */
static void float_annotations_as_int(void) {
    hfx_effect *fx = load("float X < float UIMax = 1e10; float UIMin = -1e10; float Inf = 1e39; float Bad = 0.0 / 0.0;"
                          " float Step = -2.9; > = 0;\n" PROGRAM "technique T { pass P { " SHADERS " } }",
                          "annotations.fx");
    if (!fx) return;
    static const struct { const char *name; int want; } rows[] = {
        {"UIMax", INT32_MAX}, {"UIMin", INT32_MIN}, {"Inf", INT32_MAX}, {"Bad", 0}, {"Step", -2}};
    hfx_param *x = hfx_effect_param(fx, "X");
    for (size_t k = 0; k < sizeof rows / sizeof *rows; k++) {
        int v = 12345;
        CHECK_INT(hfx_annotation_int(hfx_param_annotation(x, rows[k].name), &v), HFX_OK);
        CHECK_INT(v, rows[k].want);
    }
    float f = 0;
    CHECK(hfx_annotation_float(hfx_param_annotation(x, "Inf"), &f) == HFX_OK && isinf(f) && f > 0);
    hfx_effect_destroy(fx);
}

/* States bound to parameters take the parameters' values at Apply: a float state keeps the
 * float and its int view follows the rule; an int state (AlphaRef) is the rule's int, and the
 * shader's reference is (AlphaRef & 255) / 255. */
static void bound_states_at_apply(void) {
    hfx_effect *fx = load("float Bias; float4 Blend; float Ref;\n" PROGRAM
                          "technique T { pass P { DepthBias = Bias; BlendFactor = Blend; AlphaRef = Ref; AlphaTestEnable = true;"
                          " AlphaFunc = Greater; " SHADERS " } }", "bound.fx");
    if (!fx) return;
    static const struct { float v; int32_t i; float ref; } rows[] = {
        {NAN, 0, 0.0f}, {INFINITY, INT32_MAX, 1.0f}, {-INFINITY, INT32_MIN, 0.0f}, {1e10f, INT32_MAX, 1.0f},
        {-1e10f, INT32_MIN, 0.0f}, {128.7f, 128, 128.0f / 255.0f}, {FLT_TRUE_MIN, 0, 0.0f}, {-FLT_MAX, INT32_MIN, 0.0f}};
    for (size_t k = 0; k < sizeof rows / sizeof *rows; k++) {
        float v = rows[k].v, blend[4] = {v, NAN, -v, 0.5f};
        CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Bias"), v), HFX_OK);
        CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Blend"), blend, 4), HFX_OK);
        CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Ref"), v), HFX_OK);
        CHECK_INT(apply(fx), HFX_OK);
        const hfx_rs_value *rs = dev->rs;
        CHECK(memcmp(&rs[HFX_ST_DEPTHBIAS].f[0], &v, sizeof v) == 0); /* NaN too: the same bits */
        CHECK_INT(rs[HFX_ST_DEPTHBIAS].i, rows[k].i);
        CHECK(memcmp(rs[HFX_ST_BLENDFACTOR].f, blend, sizeof blend) == 0);
        CHECK_INT(rs[HFX_ST_BLENDFACTOR].i, rows[k].i);
        CHECK_INT(rs[HFX_ST_ALPHAREF].i, rows[k].i);
        CHECK(rs[HFX_ST_ALPHAREF].f[0] == (float)rows[k].i);
        GLint program = 0;
        g.GetIntegerv(GL_CURRENT_PROGRAM, &program);
        float ref = -1;
        g.GetUniformfv((GLuint)program, g.GetUniformLocation((GLuint)program, "hfx_alpha_ref"), &ref);
        CHECK(ref == rows[k].ref);
    }
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
}

/* ---- the shader-array selector of a hostile .hfxo ---- */

static const char arrays[] =
    "int ShaderIndex = 0;\n"
    "float Sel = 0;\n"
    "static const int PSIndices[4] = {2, 0, 1, 1};\n"
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 PSRed() : COLOR { return float4(1, 0, 0, 1); }\n"
    "float4 PSGreen() : COLOR { return float4(0, 1, 0, 1); }\n"
    "float4 PSBlue() : COLOR { return float4(0, 0, 1, 1); }\n"
    "PixelShader PSArray[3] = { compile ps_2_0 PSRed(), compile ps_2_0 PSGreen(), compile ps_2_0 PSBlue() };\n"
    "technique ByTable { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = (PSArray[PSIndices[ShaderIndex]]); } }\n";

/* The .hfxo of `arrays` with the PixelShader selector's program replaced by code[0 .. n). */
static void *patched_hfxo(const uint32_t *code, uint32_t n, size_t *size) {
    hfxc_result *r = hfxc_compile_memory(arrays, sizeof arrays - 1, "arrays.fx", NULL);
    const hfx_fx_effect *e = hfxc_result_effect(r);
    void *bytes = NULL, *out = NULL;
    CHECK(e && hfx_fx_write_hfxo(e, &bytes, size) == 0);
    char err[256] = "";
    hfx_fx_effect *fx = bytes ? hfx_fx_read_hfxo(bytes, *size, err, sizeof err) : NULL;
    CHECK(fx != NULL);
    uint32_t *exprs = fx ? realloc(fx->exprs, (fx->expr_words + n) * sizeof *exprs) : NULL;
    int patched = 0;
    if (exprs) {
        fx->exprs = exprs;
        for (uint32_t i = 0; i < fx->state_count; i++) {
            hfx_fx_state *st = &fx->states[i];
            if (st->id != HFX_ST_PIXELSHADER || st->kind != HFX_FX_VALUE_EXPR) continue;
            memcpy(exprs + fx->expr_words, code, n * sizeof *code);
            st->ref = fx->expr_words;
            st->count = n;
            patched++;
        }
        fx->expr_words += n;
    }
    CHECK_INT(patched, 1);
    CHECK(fx && hfx_fx_write_hfxo(fx, &out, size) == 0);
    hfx_fx_effect_free(fx);
    free(bytes);
    hfxc_result_free(r);
    return out;
}

static uint32_t fbits(float f) {
    uint32_t w;
    memcpy(&w, &f, sizeof w);
    return w;
}

/* A program of constants that can only give 1e30 (or a vector) is refused at load, with why. */
static void selector_refused_at_load(void) {
    const uint32_t huge[] = {hfx_evc_word(HFX_EVC_CONST, HFX_EV_FLOAT, 1), fbits(1e30f)};
    const uint32_t pair[] = {hfx_evc_word(HFX_EVC_CONST, HFX_EV_INT, 2), 0, 1};
    const struct { const uint32_t *code; uint32_t n; const char *why; } rows[] = {
        {huge, 2, "a shader array selector always gives 1e+30, no array index"},
        {pair, 3, "a shader array selector gives 2 values, not one index"}};
    for (size_t k = 0; k < 2; k++) {
        size_t size = 0;
        void *bytes = patched_hfxo(rows[k].code, rows[k].n, &size);
        char *errors = NULL;
        hfx_effect *fx = bytes ? hfx_effect_load_memory(dev, bytes, size, "hostile.hfxo", NULL, &errors) : NULL;
        CHECK(fx == NULL);
        CHECK_CONTAINS(errors ? errors : "", rows[k].why);
        hfx_free(errors);
        hfx_effect_destroy(fx);
        free(bytes);
    }
}

/* The centre pixel after drawing the pass: 4 red + 2 green + 1 blue (0/1 each). */
static int draw(hfx_effect *fx) {
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
    g.ClearColor(0, 0, 0, 1);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(apply(fx), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    unsigned char px[4];
    test_gl_read(gl, W / 2, H / 2, px);
    g.DeleteBuffers(1, &buffer);
    g.DeleteVertexArrays(1, &vao);
    return (px[0] > 128) * 4 + (px[1] > 128) * 2 + (px[2] > 128);
}

/* A selector reading the float Sel directly (no table to clamp it) loads; at Apply its value is
 * truncated by the rule and clamped into the entries the pass has (0..2), as D3D9 clamps
 * PSArray[i]: 1e30 and +inf give the last (blue), NaN, -inf and -5 the first (red), 1.9 green. */
static void selector_clamped_at_apply(void) {
    hfxc_result *r = hfxc_compile_memory(arrays, sizeof arrays - 1, "arrays.fx", NULL);
    const hfx_fx_effect *e = hfxc_result_effect(r);
    uint32_t sel = HFX_NONE;
    for (uint32_t i = 0; e && i < e->param_count; i++)
        if (!strcmp(e->params[i].name, "Sel")) sel = e->params[i].offset;
    CHECK(sel != HFX_NONE);
    hfxc_result_free(r);
    const uint32_t code[] = {hfx_evc_word(HFX_EVC_PARAM, HFX_EV_FLOAT, 1), sel};
    size_t size = 0;
    void *bytes = patched_hfxo(code, 2, &size);
    char *errors = NULL;
    hfx_effect *fx = bytes ? hfx_effect_load_memory(dev, bytes, size, "hostile.hfxo", NULL, &errors) : NULL;
    if (!fx) printf("  %s\n", errors ? errors : "");
    hfx_free(errors);
    free(bytes);
    CHECK(fx != NULL);
    if (!fx) return;
    enum { RED = 4, GREEN = 2, BLUE = 1 };
    static const struct { float sel; int colour; } rows[] = {
        {0, RED}, {1e30f, BLUE}, {NAN, RED}, {INFINITY, BLUE}, {-INFINITY, RED}, {-5, RED}, {1.9f, GREEN}, {2, BLUE}};
    for (size_t k = 0; k < sizeof rows / sizeof *rows; k++) {
        CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Sel"), rows[k].sel), HFX_OK);
        CHECK_INT(draw(fx), rows[k].colour);
    }
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    RUN(float_state_at_load);
    RUN(float_annotations_as_int);
    RUN(bound_states_at_apply);
    RUN(selector_refused_at_load);
    RUN(selector_clamped_at_apply);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
