/* test_apply_paths.c: Apply's same-pass path (dev->applied) and packed registers (hfx_c), on
 * effects compiled from .fx text. Every expected value is worked out here from the shaders'
 * equations; packed and separate loads of one effect must also give the same pixels. The
 * attacks: every matrix shape, the first and last registers, one and many changes between two
 * Applies, the change log's ring overflowing, clones sharing a program, technique switches,
 * an effect destroyed and another made in its place, struct / array / int / bool parameters,
 * the viewport, the alpha test, two effects and two devices, .hfxo round trips and SPIR-V;
 * and, through a loader that reuses GL names as many drivers do (Mesa does not), programs and
 * sampler objects deleted while the device's shadow still held them bound. */
#include "compile.h"
#include "gl_context.h"
#include "gl/gl_int.h"
#include "rt_support.h"
#include "test.h"

#define W 8
#define H 8

static test_gl *gl;
static tgl g;
static GLuint vao, vbo;

/* S0 takes register 0 and Last the last one of every program (parameters in declaration order). */
static const char *const shapes_fx =
    "float S0;\n"
    "float2x3 M23;\n"
    "float3x2 M32;\n"
    "float4x3 M43;\n"
    "float3x4 M34;\n"
    "float2x2 M22;\n"
    "float4x1 M41;\n"
    "float1x4 M14;\n"
    "float3x1 M31;\n"
    "float1x3 M13;\n"
    "float1x1 M11;\n"
    "float4 Last;\n"
    "float4 VS(float2 p : POSITION0) : POSITION { return float4(p, 0, 1); }\n"
    "float4 PS23() : COLOR0 { return float4(mul(float2(0.5, 0.25), M23), S0) + Last; }\n"
    "float4 PS32() : COLOR0 { return float4(mul(float3(0.5, 0.25, 0.125), M32), S0, 0) + Last; }\n"
    "float4 PS43() : COLOR0 { return float4(mul(float4(0.5, 0.25, 0.125, 0.0625), M43), S0) + Last; }\n"
    "float4 PS34() : COLOR0 { return mul(float3(0.5, 0.25, 0.125), M34) + Last; }\n"
    "float4 PS22() : COLOR0 { return float4(mul(float2(0.5, 0.25), M22), S0, 0) + Last; }\n"
    "float4 PS41() : COLOR0 { return float4(mul(float4(0.5, 0.25, 0.125, 0.0625), M41), S0, 0, 0) + Last; }\n"
    "float4 PS14() : COLOR0 { return mul(0.5, M14) + Last; }\n"
    "float4 PS31() : COLOR0 { return float4(mul(float3(0.5, 0.25, 0.125), M31), S0, 0, 0) + Last; }\n"
    "float4 PS13() : COLOR0 { return float4(mul(0.5, M13), S0) + Last; }\n"
    "float4 PS11() : COLOR0 { return float4(mul(0.5, M11), S0, 0, 0) + Last; }\n"
    "#define T(n) technique T##n { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS##n(); } }\n"
    "T(23) T(32) T(43) T(34) T(22) T(41) T(14) T(31) T(13) T(11)\n";

typedef struct shape {
    const char *tech, *param;
    uint32_t rows, cols;
} shape;

static const shape shapes[] = {{"T23", "M23", 2, 3}, {"T32", "M32", 3, 2}, {"T43", "M43", 4, 3}, {"T34", "M34", 3, 4},
                               {"T22", "M22", 2, 2}, {"T41", "M41", 4, 1}, {"T14", "M14", 1, 4}, {"T31", "M31", 3, 1},
                               {"T13", "M13", 1, 3}, {"T11", "M11", 1, 1}};
#define SHAPES (sizeof shapes / sizeof shapes[0])

/* The vector each pixel shader multiplies its matrix by (T14, T13, T11: the scalar 0.5). */
static const float in_vec[4] = {0.5f, 0.25f, 0.125f, 0.0625f};

/* The values a test sets: version v of matrix element (r, c), S0 and Last. */
static float mval(int v, uint32_t r, uint32_t c) { return v ? 0.30f - 0.05f * (float)r + 0.03f * (float)c : 0.05f + 0.1f * (float)r + 0.02f * (float)c; }
static float s0val(int v) { return v ? 0.6f : 0.35f; }
static void lastval(int v, float out[4]) {
    for (int k = 0; k < 4; k++) out[k] = v ? 0.05f * (float)(4 - k) : 0.1f * (float)(k + 1);
}

/* What a shape's pixel shader returns for version v: mul(in, M) in the first cols components,
 * S0 after them when there is room, plus Last. */
static void expected_color(const shape *s, int v, float out[4]) {
    float last[4];
    lastval(v, last);
    for (int k = 0; k < 4; k++) out[k] = 0;
    for (uint32_t c = 0; c < s->cols; c++)
        for (uint32_t r = 0; r < s->rows; r++) out[c] += in_vec[r] * mval(v, r, c);
    if (s->cols < 4) out[s->cols] = s0val(v);
    for (int k = 0; k < 4; k++) out[k] += last[k];
}

/* This file pins the parameters' registers: no preshaders (tests/runtime/test_preshaders.c). */
static hfx_effect *load_opt(hfx_device *dev, const char *src, const hfx_load_options *opt) {
    char *errors = NULL;
    hfx_load_options o = opt ? *opt : (hfx_load_options){0};
    o.no_preshaders = 1;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, strlen(src), "paths.fx", &o, &errors);
    if (!fx) fprintf(stderr, "load: %s\n", errors ? errors : "(no message)");
    CHECK(fx != NULL);
    hfx_free(errors);
    return fx;
}

static hfx_effect *load_fx(hfx_device *dev, const char *src, int separate) {
    hfx_load_options opt;
    memset(&opt, 0, sizeof opt);
    opt.separate_uniforms = separate;
    return load_opt(dev, src, &opt);
}

static hfx_pass *pass_of(hfx_effect *fx, const char *tech) {
    hfx_technique *t = hfx_effect_technique(fx, tech);
    CHECK(t != NULL);
    return hfx_technique_pass(t, 0);
}

static void set_f(hfx_effect *fx, const char *name, const float *v, size_t n) {
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, name), v, n), HFX_OK);
}

/* Sets a shape's matrix the XNA way (the top-left rows x cols of a 4x4), S0 and Last. */
static void set_shape(hfx_effect *fx, const shape *s, int v) {
    float m[16] = {0}, last[4];
    for (uint32_t r = 0; r < 4; r++)
        for (uint32_t c = 0; c < 4; c++) m[r * 4 + c] = r < s->rows && c < s->cols ? mval(v, r, c) : 99.0f;
    hfx_param *p = hfx_effect_param(fx, s->param);
    if (hfx_param_get_class(p) == HFX_CLASS_MATRIX) {
        CHECK_INT(hfx_param_set_matrix(p, m), HFX_OK);
    } else { /* float1x1 is a scalar to hfx: its one word */
        CHECK_INT(s->rows * s->cols, 1);
        CHECK_INT(hfx_param_set_floats(p, m, 1), HFX_OK);
    }
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "S0"), s0val(v)), HFX_OK);
    lastval(v, last);
    set_f(fx, "Last", last, 4);
}

static void draw(void) {
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    g.BindVertexArray(vao);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
}

static void read_px(unsigned char px[4]) { test_gl_read(gl, W / 2, H / 2, px); }

static void check_px(const float want[4], const char *what) {
    unsigned char px[4];
    read_px(px);
    for (int k = 0; k < 4; k++) {
        if (fabs(px[k] - want[k] * 255.0) > 1.01) fprintf(stderr, "  %s: channel %d\n", what, k);
        CHECK_NEAR(px[k], want[k] * 255.0, 1.01);
    }
}

/* A uniform of the bound program, by name ("hfx_c[3]", "M43"), as GL holds it. */
static void read_uniform(const char *name, float *out, int n) {
    GLint prog = 0;
    g.GetIntegerv(GL_CURRENT_PROGRAM, &prog);
    GLint loc = g.GetUniformLocation((GLuint)prog, name);
    if (loc < 0) fprintf(stderr, "  no uniform %s\n", name);
    CHECK(loc >= 0);
    float buf[16];
    for (int k = 0; k < 16; k++) buf[k] = -1000;
    if (loc >= 0) g.GetUniformfv((GLuint)prog, loc, buf);
    memcpy(out, buf, (size_t)n * sizeof *out);
}

static void check_reg(uint32_t i, int comps, const float *want) {
    char name[32];
    snprintf(name, sizeof name, "hfx_c[%u]", (unsigned)i);
    float r[4];
    read_uniform(name, r, 4);
    for (int k = 0; k < comps; k++) CHECK_NEAR(r[k], want[k], 0);
}

/* The first register of a shape's matrix: S0 takes register 0 in the programs that read it
 * (those whose result leaves room for it). */
static uint32_t shape_base(const shape *s) { return s->cols < 4 ? 1 : 0; }

/* A packed shape program's registers: S0, the matrix's row r in base + r, Last after it. */
static void check_shape_regs(const shape *s, int v) {
    float row[4], last[4];
    uint32_t base = shape_base(s);
    row[0] = s0val(v);
    if (base) check_reg(0, 1, row);
    for (uint32_t r = 0; r < s->rows; r++) {
        for (uint32_t c = 0; c < s->cols; c++) row[c] = mval(v, r, c);
        check_reg(base + r, (int)s->cols, row);
    }
    lastval(v, last);
    check_reg(base + s->rows, 4, last);
}

/* A separate shape program's matrix: GL's matRxC holds HLSL row r as column r, so the floats
 * GL reports are the row-major words. */
static void check_shape_separate(const shape *s, int v) {
    float m[16];
    read_uniform(s->param, m, (int)(s->rows * s->cols));
    for (uint32_t r = 0; r < s->rows; r++)
        for (uint32_t c = 0; c < s->cols; c++) CHECK_NEAR(m[r * s->cols + c], mval(v, r, c), 0);
}

/* Renders a shape and returns the pixel; checks it against the equations. */
static void render_shape(hfx_effect *fx, const shape *s, int v, unsigned char px[4]) {
    float want[4];
    CHECK_INT(hfx_pass_apply(pass_of(fx, s->tech)), HFX_OK);
    draw();
    expected_color(s, v, want);
    check_px(want, s->tech);
    read_px(px);
}

/* Every shape, packed and separate, two versions of the values each (the second Apply of the
 * same pass takes the short way): registers and uniforms hold the words, pixels match the
 * equations and each other. */
static void test_matrix_shapes(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *packed = load_fx(dev, shapes_fx, 0), *separate = load_fx(dev, shapes_fx, 1);
    if (!packed || !separate) goto done;
    for (size_t i = 0; i < SHAPES; i++) {
        for (int v = 0; v < 2; v++) {
            unsigned char a[4], b[4];
            set_shape(packed, &shapes[i], v);
            render_shape(packed, &shapes[i], v, a);
            check_shape_regs(&shapes[i], v);
            render_shape(packed, &shapes[i], v, a); /* same pass, nothing changed */
            set_shape(separate, &shapes[i], v);
            render_shape(separate, &shapes[i], v, b);
            check_shape_separate(&shapes[i], v);
            CHECK(memcmp(a, b, 4) == 0);
        }
    }
done:
    hfx_effect_destroy(separate);
    hfx_effect_destroy(packed);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* The same pass twice with one change between: one GL call, the right one, nothing else. */
static void one_change_packed(hfx_effect *fx, const shape *s) {
    hfx_pass *p = pass_of(fx, s->tech);
    set_shape(fx, s, 0);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    set_shape(fx, s, 1);
    CHECK_INT(hfx_pass_apply(p), HFX_OK); /* three changes: one range [0, 5] */
    check_shape_regs(s, 1);
    float last[4] = {0.9f, 0.8f, 0.7f, 0.6f};
    tc_reset();
    set_f(fx, "Last", last, 4); /* the last register alone */
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    CHECK_INT(tc_count("glUniform4fv"), 1);
    CHECK_INT(tc_calls(), 1);
    check_reg(5, 4, last);
    tc_reset();
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "S0"), 0.125f), HFX_OK); /* the first alone */
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    CHECK_INT(tc_calls(), 1);
    check_reg(0, 1, (float[1]){0.125f});
}

/* Separate: a float4 goes inline, a matrix through the log, one call each; a value set again
 * unchanged costs nothing. */
static void one_change_separate(hfx_effect *fx, const shape *s) {
    hfx_pass *p = pass_of(fx, s->tech);
    float last[4] = {0.9f, 0.8f, 0.7f, 0.6f}, m[16] = {0}, got[12];
    set_shape(fx, s, 0);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    tc_reset();
    set_f(fx, "Last", last, 4);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    CHECK_INT(tc_count("glUniform4fv"), 1);
    CHECK_INT(tc_calls(), 1);
    for (int k = 0; k < 12; k++) m[(k / 3) * 4 + k % 3] = 0.01f * (float)k;
    tc_reset();
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "M43"), m), HFX_OK);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    CHECK_INT(tc_count("glUniformMatrix4x3fv"), 1);
    CHECK_INT(tc_calls(), 1);
    read_uniform("M43", got, 12);
    for (int k = 0; k < 12; k++) CHECK_NEAR(got[k], 0.01f * (float)k, 0);
    tc_reset();
    set_f(fx, "Last", last, 4);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    CHECK_INT(tc_calls(), 0);
}

static void test_one_change_one_call(void) {
    hfx_device *dev = hfx_device_create_gl(tc_loader);
    hfx_effect *packed = load_fx(dev, shapes_fx, 0), *separate = load_fx(dev, shapes_fx, 1);
    if (packed && separate) {
        one_change_packed(packed, &shapes[2]); /* M43: S0 in register 0, rows in 1..4, Last in 5 */
        one_change_separate(separate, &shapes[2]);
    }
    hfx_effect_destroy(separate);
    hfx_effect_destroy(packed);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* Changes between two Applies of the same pass: the same parameter twice, a value set back to
 * what GL holds, and more sets than the log's ring holds (with the boundary counts). */
static void test_many_changes_and_ring(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *fx = load_fx(dev, shapes_fx, 0);
    if (!fx) goto done;
    const shape *s = &shapes[0];
    hfx_pass *p = pass_of(fx, s->tech);
    hfx_param *s0 = hfx_effect_param(fx, "S0"), *last = hfx_effect_param(fx, "Last");
    set_shape(fx, s, 0);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    /* set back: 0.35 -> 0.5 -> 0.35 between two Applies */
    CHECK_INT(hfx_param_set_float(s0, 0.5f), HFX_OK);
    CHECK_INT(hfx_param_set_float(s0, s0val(0)), HFX_OK);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    check_shape_regs(s, 0);
    uint32_t ring = fx->log_mask + 1;
    uint32_t counts[] = {ring - 1, ring, ring + 1, ring + 2, 3 * ring + 5};
    for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
        float l[4] = {0};
        for (uint32_t k = 0; k < counts[c]; k++) {
            l[0] = (float)k / 4096.0f, l[1] = (float)c / 8.0f;
            if (k % 2) CHECK_INT(hfx_param_set_floats(last, l, 4), HFX_OK);
            else CHECK_INT(hfx_param_set_float(s0, (float)(k + c) / 8192.0f), HFX_OK);
        }
        CHECK_INT(hfx_pass_apply(p), HFX_OK);
        uint32_t k_last = counts[c] - 1, k_s0 = counts[c] % 2 ? counts[c] - 1 : counts[c] - 2;
        float want_last[4] = {(float)(k_last % 2 ? k_last : k_last - 1) / 4096.0f, (float)c / 8.0f, 0, 0};
        check_reg(2 + 1, 4, want_last);
        check_reg(0, 1, (float[1]){(float)(k_s0 + c) / 8192.0f});
        /* one change after the overflow takes the inline way again */
        CHECK_INT(hfx_param_set_float(s0, 0.75f), HFX_OK);
        CHECK_INT(hfx_pass_apply(p), HFX_OK);
        check_reg(0, 1, (float[1]){0.75f});
    }
done:
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* Clones share programs and register images: alternate them with different values, change one
 * while the other was applied last, overflow a clone's ring while the other holds the program. */
static void test_clones_alternate(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *a = load_fx(dev, shapes_fx, 0);
    hfx_effect *b = a ? hfx_effect_clone(a) : NULL;
    CHECK(b != NULL);
    if (!a || !b) goto done;
    const shape *s = &shapes[2]; /* M43: S0 in register 0, rows of three in 1..4 */
    hfx_pass *pa = pass_of(a, s->tech), *pb = pass_of(b, s->tech);
    unsigned char px[4];
    set_shape(a, s, 0);
    set_shape(b, s, 1);
    for (int round = 0; round < 3; round++) {
        render_shape(a, s, 0, px);
        check_shape_regs(s, 0);
        render_shape(b, s, 1, px);
        check_shape_regs(s, 1);
    }
    /* a applied last; b changes; a again: a's values stay */
    render_shape(a, s, 0, px);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(b, "S0"), 0.9f), HFX_OK);
    CHECK_INT(hfx_pass_apply(pa), HFX_OK);
    check_shape_regs(s, 0);
    /* one change on a after b: the full comparison, not the inline one */
    CHECK_INT(hfx_pass_apply(pb), HFX_OK);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(a, "S0"), 0.2f), HFX_OK);
    CHECK_INT(hfx_pass_apply(pa), HFX_OK);
    check_reg(0, 1, (float[1]){0.2f});
    float row[3] = {mval(0, 3, 0), mval(0, 3, 1), mval(0, 3, 2)};
    check_reg(4, 3, row);
    CHECK_INT(hfx_pass_apply(pb), HFX_OK);
    check_reg(0, 1, (float[1]){0.9f});
    row[0] = mval(1, 3, 0), row[1] = mval(1, 3, 1), row[2] = mval(1, 3, 2);
    check_reg(4, 3, row);
    /* b's ring overflows while a holds the program */
    CHECK_INT(hfx_pass_apply(pa), HFX_OK);
    for (uint32_t k = 0; k < 3 * (b->log_mask + 1); k++)
        CHECK_INT(hfx_param_set_float(hfx_effect_param(b, "S0"), (float)k / 1024.0f), HFX_OK);
    CHECK_INT(hfx_pass_apply(pb), HFX_OK);
    check_reg(0, 1, (float[1]){(float)(3 * (b->log_mask + 1) - 1) / 1024.0f});
    CHECK_INT(hfx_pass_apply(pa), HFX_OK);
    check_reg(0, 1, (float[1]){0.2f});
done:
    hfx_effect_destroy(b);
    hfx_effect_destroy(a);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* Technique switches: another pass (another program) between two Applies of one pass. */
static void test_technique_switch(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *fx = load_fx(dev, shapes_fx, 0);
    if (!fx) goto done;
    unsigned char px[4];
    for (int v = 0; v < 2; v++)
        for (size_t i = 0; i < SHAPES; i++) {
            for (size_t k = 0; k < SHAPES; k++) set_shape(fx, &shapes[(i + k) % SHAPES], v);
            hfx_effect_set_current_technique(fx, hfx_effect_technique(fx, shapes[i].tech));
            render_shape(fx, &shapes[i], v, px);
            render_shape(fx, &shapes[(i + 3) % SHAPES], v, px); /* its matrix has version v too */
            render_shape(fx, &shapes[i], v, px);
        }
done:
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* An effect destroyed while its pass was the last applied, and another made (likely at the same
 * address, with its passes at the same address): its first Apply must bind and upload. Then the
 * same with a clone. */
static void test_destroy_and_reuse(void) {
    hfx_device *dev = hfx_device_create_gl(tc_loader);
    const shape *s = &shapes[1];
    unsigned char px[4];
    for (int round = 0; round < 3; round++) {
        hfx_effect *a = load_fx(dev, shapes_fx, round == 1);
        if (!a) break;
        set_shape(a, s, round % 2);
        render_shape(a, s, round % 2, px);
        hfx_effect_destroy(a);
    }
    hfx_effect *base = load_fx(dev, shapes_fx, 0);
    if (base) {
        set_shape(base, s, 0);
        for (int round = 0; round < 3; round++) {
            hfx_effect *c = hfx_effect_clone(base);
            CHECK(c != NULL);
            if (!c) break;
            set_shape(c, s, 1);
            render_shape(c, s, 1, px);
            hfx_effect_destroy(c);
            render_shape(base, s, 0, px);
            /* a clone made while base's pass is the last applied, one change: not base's log */
            c = hfx_effect_clone(base);
            CHECK_INT(hfx_param_set_float(hfx_effect_param(c, "S0"), 0.05f), HFX_OK);
            tc_reset();
            CHECK_INT(hfx_pass_apply(pass_of(c, s->tech)), HFX_OK);
            CHECK_INT(tc_count("glUniform4fv"), 1);
            check_reg(0, 1, (float[1]){0.05f});
            hfx_effect_destroy(c);
            CHECK_INT(hfx_pass_apply(pass_of(base, s->tech)), HFX_OK);
            check_reg(0, 1, (float[1]){s0val(0)});
        }
    }
    hfx_effect_destroy(base);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* The bound program's effect destroyed (GL deletes the program once it is no longer current),
 * then effects loaded: GL may hand a later program the deleted one's name, which the device
 * must not take for the program it still believes bound. */
static const char *const color_fx =
    "float4 Color;\n"
    "float4 VS(float2 p : POSITION0) : POSITION { return float4(p, 0, 1); }\n"
    "float4 PS() : COLOR0 { return Color * COLORSCALE; }\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

static hfx_effect *load_color(hfx_device *dev, const char *scale, const float *color) {
    hfx_load_options opt;
    memset(&opt, 0, sizeof opt);
    const char *defines[1] = {scale};
    opt.defines = defines;
    opt.define_count = 1;
    hfx_effect *fx = load_opt(dev, color_fx, &opt);
    if (fx) set_f(fx, "Color", color, 4);
    return fx;
}

/* A loader for a driver that hands out the lowest free program name again (as many do; Mesa
 * counts up): hfx sees virtual names, mapped to Mesa's. A program deleted while current keeps
 * its name until another is bound, as GL says; binding a freed name does nothing (GL refuses). */
#define VNAMES 64
static struct {
    GLuint real[VNAMES];
    int used[VNAMES], pending[VNAMES];
    GLuint current;
    PFNGLCREATEPROGRAMPROC CreateProgram;
    PFNGLDELETEPROGRAMPROC DeleteProgram;
    PFNGLUSEPROGRAMPROC UseProgram;
    PFNGLGETINTEGERVPROC GetIntegerv;
    PFNGLATTACHSHADERPROC AttachShader;
    PFNGLDETACHSHADERPROC DetachShader;
    PFNGLBINDATTRIBLOCATIONPROC BindAttribLocation;
    PFNGLLINKPROGRAMPROC LinkProgram;
    PFNGLGETPROGRAMIVPROC GetProgramiv;
    PFNGLGETPROGRAMINFOLOGPROC GetProgramInfoLog;
    PFNGLGETUNIFORMLOCATIONPROC GetUniformLocation;
    PFNGLGETACTIVEUNIFORMPROC GetActiveUniform;
    GLuint sreal[VNAMES];                    /* sampler objects, likewise (freed at once) */
    int sused[VNAMES];
    PFNGLGENSAMPLERSPROC GenSamplers;
    PFNGLDELETESAMPLERSPROC DeleteSamplers;
    PFNGLBINDSAMPLERPROC BindSampler;
    PFNGLSAMPLERPARAMETERIPROC SamplerParameteri;
    PFNGLSAMPLERPARAMETERFPROC SamplerParameterf;
    PFNGLSAMPLERPARAMETERFVPROC SamplerParameterfv;
} vn;

static GLuint vreal(GLuint v) { return v < VNAMES ? vn.real[v] : 0; }

static GLuint APIENTRY v_create_program(void) {
    GLuint r = vn.CreateProgram();
    for (GLuint v = 1; v < VNAMES; v++)
        if (!vn.used[v]) {
            vn.used[v] = 1, vn.pending[v] = 0, vn.real[v] = r;
            return v;
        }
    return 0;
}
static void APIENTRY v_delete_program(GLuint v) {
    if (!v || v >= VNAMES || !vn.used[v]) return;
    vn.DeleteProgram(vn.real[v]);
    if (vn.current == v) vn.pending[v] = 1;
    else vn.used[v] = 0;
}
static void APIENTRY v_use_program(GLuint v) {
    if (v && (v >= VNAMES || !vn.used[v] || (vn.pending[v] && vn.current != v))) return; /* GL_INVALID_VALUE */
    vn.UseProgram(v ? vn.real[v] : 0);
    GLuint old = vn.current;
    vn.current = v;
    if (old && old != v && vn.pending[old]) vn.pending[old] = 0, vn.used[old] = 0;
}
static void APIENTRY v_get_integerv(GLenum pname, GLint *out) {
    vn.GetIntegerv(pname, out);
    if (pname == GL_CURRENT_PROGRAM) *out = (GLint)vn.current;
    if (pname == GL_SAMPLER_BINDING && *out) {
        GLint real = *out;
        *out = 0;
        for (GLuint v = 1; v < VNAMES; v++)
            if (vn.sused[v] && vn.sreal[v] == (GLuint)real) *out = (GLint)v;
    }
}
static GLuint sreal(GLuint v) { return v < VNAMES && vn.sused[v] ? vn.sreal[v] : 0; }
static void APIENTRY v_gen_samplers(GLsizei n, GLuint *out) {
    for (GLsizei k = 0; k < n; k++) {
        out[k] = 0;
        for (GLuint v = 1; v < VNAMES && !out[k]; v++)
            if (!vn.sused[v]) {
                vn.GenSamplers(1, &vn.sreal[v]);
                vn.sused[v] = 1;
                out[k] = v;
            }
    }
}
static void APIENTRY v_delete_samplers(GLsizei n, const GLuint *names) {
    for (GLsizei k = 0; k < n; k++)
        if (names[k] && names[k] < VNAMES && vn.sused[names[k]]) {
            vn.DeleteSamplers(1, &vn.sreal[names[k]]); /* GL unbinds it from every unit */
            vn.sused[names[k]] = 0;
        }
}
static void APIENTRY v_bind_sampler(GLuint unit, GLuint v) { vn.BindSampler(unit, sreal(v)); }
static void APIENTRY v_sampler_i(GLuint v, GLenum e, GLint x) { vn.SamplerParameteri(sreal(v), e, x); }
static void APIENTRY v_sampler_f(GLuint v, GLenum e, GLfloat x) { vn.SamplerParameterf(sreal(v), e, x); }
static void APIENTRY v_sampler_fv(GLuint v, GLenum e, const GLfloat *x) { vn.SamplerParameterfv(sreal(v), e, x); }
static void APIENTRY v_attach(GLuint p, GLuint s) { vn.AttachShader(vreal(p), s); }
static void APIENTRY v_detach(GLuint p, GLuint s) { vn.DetachShader(vreal(p), s); }
static void APIENTRY v_bind_attrib(GLuint p, GLuint i, const GLchar *n) { vn.BindAttribLocation(vreal(p), i, n); }
static void APIENTRY v_link(GLuint p) { vn.LinkProgram(vreal(p)); }
static void APIENTRY v_get_programiv(GLuint p, GLenum e, GLint *o) { vn.GetProgramiv(vreal(p), e, o); }
static void APIENTRY v_get_info_log(GLuint p, GLsizei n, GLsizei *l, GLchar *o) { vn.GetProgramInfoLog(vreal(p), n, l, o); }
static GLint APIENTRY v_get_uniform_location(GLuint p, const GLchar *n) { return vn.GetUniformLocation(vreal(p), n); }
static void APIENTRY v_get_active_uniform(GLuint p, GLuint i, GLsizei n, GLsizei *l, GLint *c, GLenum *t, GLchar *o) {
    vn.GetActiveUniform(vreal(p), i, n, l, c, t, o);
}

#define VWRAP(field, wrapper) \
    if (strcmp(name, "gl" #field) == 0) { \
        *(void **)&vn.field = test_gl_loader(name); \
        return (void *)wrapper; \
    }
static void *reuse_loader(const char *name) {
    VWRAP(CreateProgram, v_create_program)
    VWRAP(DeleteProgram, v_delete_program)
    VWRAP(UseProgram, v_use_program)
    VWRAP(GetIntegerv, v_get_integerv)
    VWRAP(AttachShader, v_attach)
    VWRAP(DetachShader, v_detach)
    VWRAP(BindAttribLocation, v_bind_attrib)
    VWRAP(LinkProgram, v_link)
    VWRAP(GetProgramiv, v_get_programiv)
    VWRAP(GetProgramInfoLog, v_get_info_log)
    VWRAP(GetUniformLocation, v_get_uniform_location)
    VWRAP(GetActiveUniform, v_get_active_uniform)
    VWRAP(GenSamplers, v_gen_samplers)
    VWRAP(DeleteSamplers, v_delete_samplers)
    VWRAP(BindSampler, v_bind_sampler)
    VWRAP(SamplerParameteri, v_sampler_i)
    VWRAP(SamplerParameterf, v_sampler_f)
    VWRAP(SamplerParameterfv, v_sampler_fv)
    return test_gl_loader(name);
}
#undef VWRAP

static void vn_reset(void) {
    memset(vn.used, 0, sizeof vn.used);
    memset(vn.pending, 0, sizeof vn.pending);
    memset(vn.sused, 0, sizeof vn.sused);
    vn.current = 0;
}

static void test_deleted_program_name(void) {
    for (int reuse = 0; reuse < 2; reuse++) {
        vn_reset();
        hfx_device *dev = hfx_device_create_gl(reuse ? reuse_loader : test_gl_loader);
        const float c[4] = {0.2f, 0.4f, 0.6f, 0.8f};
        hfx_effect *a = load_color(dev, "COLORSCALE=1.0", c);
        if (!a) {
            hfx_device_destroy(dev);
            continue;
        }
        CHECK_INT(hfx_pass_apply(pass_of(a, "T")), HFX_OK);
        hfx_effect_destroy(a); /* its program stays current, deleted once another is bound */
        for (int round = 0; round < 3; round++) {
            hfx_effect *b = load_color(dev, "COLORSCALE=0.5", c), *d = load_color(dev, "COLORSCALE=0.25", c);
            if (b && d) {
                CHECK_INT(hfx_pass_apply(pass_of(d, "T")), HFX_OK);
                draw();
                check_px((float[4]){0.05f, 0.1f, 0.15f, 0.2f}, "after a deleted program");
                CHECK_INT(hfx_pass_apply(pass_of(b, "T")), HFX_OK);
                draw();
                check_px((float[4]){0.1f, 0.2f, 0.3f, 0.4f}, "after a deleted program");
            }
            hfx_effect_destroy(d); /* d's program is not current; b's is */
            hfx_effect_destroy(b);
        }
        hfx_device_destroy(dev);
        g.UseProgram(0);
    }
}

/* Packed parameters read by the vertex shader, row_major / column_major declarations, and
 * registers GL may drop (K read as K * 0 first, Tail * 0 last): the image's tail stays on the
 * CPU and a change there costs no call. */
static const char *const stage_fx =
    "float K;\n"
    "row_major float2x3 RM;\n"
    "column_major float3x2 CM;\n"
    "float4x4 WVP;\n"
    "float4 Tail;\n"
    "struct VOut { float4 pos : POSITION; float4 col : COLOR0; };\n"
    "VOut VS(float2 p : POSITION0) {\n"
    "    VOut o;\n"
    "    o.pos = mul(float4(p, 0, 1), WVP);\n"
    "    o.col = float4(mul(float2(0.5, 0.25), RM), 1);\n"
    "    return o;\n"
    "}\n"
    "float4 PS(float4 col : COLOR0) : COLOR0 {\n"
    "    return col + float4(mul(float3(0.5, 0.25, 0.125), CM), K * 0.0, 0) + Tail * 0.0;\n"
    "}\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

static void stage_set(hfx_effect *fx, int v) {
    float rm[16] = {0}, cm[16] = {0}, wvp[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1};
    for (uint32_t r = 0; r < 3; r++)
        for (uint32_t c = 0; c < 3; c++) rm[r * 4 + c] = cm[r * 4 + c] = mval(v, r, c);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "RM"), rm), HFX_OK);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "CM"), cm), HFX_OK);
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "WVP"), wvp), HFX_OK);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "K"), 0.5f), HFX_OK);
}

/* mul(float2(0.5, 0.25), RM) + mul(float3(0.5, 0.25, 0.125), CM) in .xy, RM's third column in .z. */
static void stage_check(int v) {
    float want[4] = {0, 0, 0, 1};
    for (uint32_t c = 0; c < 3; c++) want[c] = 0.5f * mval(v, 0, c) + 0.25f * mval(v, 1, c);
    for (uint32_t c = 0; c < 2; c++) want[c] += 0.5f * mval(v, 0, c) + 0.25f * mval(v, 1, c) + 0.125f * mval(v, 2, c);
    draw();
    check_px(want, "stage");
    unsigned char px[4]; /* WVP moved the quad right by a quarter of the view: column 0 is empty */
    test_gl_read(gl, 0, H / 2, px);
    CHECK_INT(px[0] + px[1] + px[2] + px[3], 0);
}

static void stages_and_trim(hfx_target target) {
    hfx_device *dev = hfx_device_create_gl(tc_loader);
    for (int separate = 0; separate < 2; separate++) {
        hfx_load_options opt;
        memset(&opt, 0, sizeof opt);
        opt.target = target;
        opt.separate_uniforms = separate;
        hfx_effect *fx = load_opt(dev, stage_fx, &opt);
        if (!fx) continue;
        hfx_pass *p = pass_of(fx, "T");
        for (int v = 0; v < 2; v++) {
            stage_set(fx, v);
            CHECK_INT(hfx_pass_apply(p), HFX_OK);
            stage_check(v);
        }
        const hfx_rt_program *prog = p->rt->prog;
        uint32_t tail = hfx_fx_param_find(fx->sh->fx, "Tail");
        const hfx_slot *ts = &prog->slots[tail];
        tc_reset();
        CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Tail"), (float[4]){1, 1, 1, 1}, 4), HFX_OK);
        CHECK_INT(hfx_pass_apply(p), HFX_OK);
        int sent = ts->mode == SLOT_REG ? ts->reg < prog->reg_active : ts->mode != SLOT_NONE;
        CHECK_INT(tc_calls(), sent);
        CHECK_INT(g.GetError(), GL_NO_ERROR);
        tc_reset();
        CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "K"), 0.25f), HFX_OK);
        CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Tail"), (float[4]){2, 2, 2, 2}, 4), HFX_OK);
        CHECK_INT(hfx_pass_apply(p), HFX_OK);
        CHECK_INT(g.GetError(), GL_NO_ERROR);
        stage_check(1);
        if (!separate) printf("  packed (target %d): %u of %u registers active, Tail in %u\n", (int)target,
                              (unsigned)prog->reg_active, (unsigned)prog->reg_size, (unsigned)ts->reg);
        hfx_effect_destroy(fx);
    }
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

static void test_stages_and_trim(void) { stages_and_trim(HFX_TARGET_GLSL330); }

/* More than 256 registers: the compiler packs up to register 255 and leaves the rest separate.
 * 70 float4x4 (280 registers): 64 packed, 6 separate; the PS sums their first rows. */
#define BIG 70

static char *big_source(void) {
    size_t cap = 64 * BIG + 1024, n = 0;
    char *src = malloc(cap);
    if (!src) return NULL;
    for (int i = 0; i < BIG; i++) n += (size_t)snprintf(src + n, cap - n, "float4x4 M%d;\n", i);
    n += (size_t)snprintf(src + n, cap - n, "float4 VS(float2 p : POSITION0) : POSITION { return float4(p, 0, 1); }\n"
                                            "float4 PS() : COLOR0 { float4 c = 0;\n");
    for (int i = 0; i < BIG; i++) n += (size_t)snprintf(src + n, cap - n, "c += M%d[0] + M%d[3];\n", i, i);
    snprintf(src + n, cap - n, "return c; }\n"
                               "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n");
    return src;
}

/* M_i's row 0 is (i, 0, 0, 0) / 8192 and row 3 (0, i, 0, 0) / 8192; rows 1, 2 are 1 (unread). */
static void big_set(hfx_effect *fx, int i, float extra) {
    char name[16];
    snprintf(name, sizeof name, "M%d", i);
    float m[16];
    for (int k = 0; k < 16; k++) m[k] = 1;
    m[0] = (float)i / 8192.0f + extra, m[1] = m[2] = m[3] = 0;
    m[12] = 0, m[13] = (float)i / 8192.0f, m[14] = 0, m[15] = extra;
    CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, name), m), HFX_OK);
}

static void big_check(float extra0, float extra3) {
    float sum = (float)(BIG * (BIG - 1) / 2) / 8192.0f;
    draw();
    check_px((float[4]){sum + extra0, sum, 0, extra3}, "big");
}

static void test_register_limit(void) {
    char *src = big_source();
    CHECK(src != NULL);
    if (!src) return;
    hfx_device *dev = hfx_device_create_gl(tc_loader);
    unsigned char px[2][4];
    for (int separate = 0; separate < 2; separate++) {
        hfx_effect *fx = load_fx(dev, src, separate);
        if (!fx) continue;
        hfx_pass *p = pass_of(fx, "T");
        for (int i = 0; i < BIG; i++) big_set(fx, i, 0);
        CHECK_INT(hfx_pass_apply(p), HFX_OK);
        big_check(0, 0);
        read_px(px[separate]);
        /* one change on the last packed register (M63's row 3 is register 255), then on the first
         * separate one, then both ends at once */
        int last_packed = 255 / 4, first_separate = 256 / 4;
        tc_reset();
        big_set(fx, last_packed, 0.25f);
        CHECK_INT(hfx_pass_apply(p), HFX_OK);
        CHECK_INT(tc_calls(), 1);
        big_check(0.25f, 0.25f);
        big_set(fx, last_packed, 0);
        big_set(fx, first_separate, 0.5f);
        CHECK_INT(hfx_pass_apply(p), HFX_OK);
        big_check(0.5f, 0.5f);
        big_set(fx, first_separate, 0);
        big_set(fx, 0, 0.125f);
        big_set(fx, BIG - 1, 0.125f);
        CHECK_INT(hfx_pass_apply(p), HFX_OK);
        big_check(0.25f, 0.25f);
        if (!separate) {
            const hfx_rt_program *prog = p->rt->prog;
            CHECK_INT(prog->reg_size, 256);
            CHECK_INT(prog->slots[first_separate].mode, SLOT_MATRIX);
        }
        hfx_effect_destroy(fx);
    }
    CHECK(memcmp(px[0], px[1], 4) == 0);
    hfx_device_destroy(dev);
    free(src);
    g.UseProgram(0);
}

/* A direct pass next to a textured one (not direct) of the same effect, the texture changed
 * between, and begin / end around: each Apply after another pass or end binds again. */
static const char *const tex_fx =
    "float4 Color;\n"
    "texture Tex;\n"
    "sampler S = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; MipFilter = None; };\n"
    "float4 VS(float2 p : POSITION0) : POSITION { return float4(p, 0, 1); }\n"
    "float4 PSColor() : COLOR0 { return Color; }\n"
    "float4 PSTex() : COLOR0 { return tex2D(S, float2(0.5, 0.5)) * Color; }\n"
    "technique T {\n"
    "  pass Plain { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PSColor(); }\n"
    "  pass Textured { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PSTex(); }\n"
    "}\n";

static GLuint texture_1x1(const unsigned char rgba[4]) {
    GLuint tex;
    g.GenTextures(1, &tex);
    g.BindTexture(GL_TEXTURE_2D, tex);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    g.BindTexture(GL_TEXTURE_2D, 0);
    return tex;
}

static void draw_check(hfx_pass *p, const float want[4], const char *what) {
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    draw();
    check_px(want, what);
}

static void test_textured_neighbour(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *fx = load_fx(dev, tex_fx, 0);
    GLuint t1 = texture_1x1((const unsigned char[4]){255, 128, 0, 255});
    GLuint t2 = texture_1x1((const unsigned char[4]){0, 255, 255, 255});
    if (!fx) goto done;
    hfx_technique *t = hfx_effect_technique(fx, "T");
    hfx_pass *plain = hfx_technique_pass(t, 0), *textured = hfx_technique_pass(t, 1);
    float c[4] = {0.5f, 0.5f, 0.5f, 1};
    set_f(fx, "Color", c, 4);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Tex"), t1), HFX_OK);
    for (int round = 0; round < 2; round++) {
        if (round) g.UseProgram(0); /* the application's program, which begin saves */
        if (round) CHECK_INT(hfx_effect_begin(fx), HFX_OK);
        draw_check(plain, c, "plain");
        draw_check(plain, c, "plain again");
        draw_check(textured, (float[4]){0.5f, 0.5f * 128 / 255.0f, 0, 1}, "textured");
        CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Tex"), t2), HFX_OK);
        c[0] = 0.25f;
        set_f(fx, "Color", c, 4);
        draw_check(plain, c, "plain after");
        draw_check(textured, (float[4]){0, 0.5f, 0.5f, 1}, "textured t2");
        CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Tex"), t1), HFX_OK);
        c[0] = 0.5f;
        set_f(fx, "Color", c, 4);
        if (round) {
            CHECK_INT(hfx_effect_end(fx), HFX_OK);
            GLint prog = -1;
            g.GetIntegerv(GL_CURRENT_PROGRAM, &prog);
            CHECK_INT(prog, 0);
            draw_check(plain, c, "plain after end"); /* without begin: binds its program again */
            g.GetIntegerv(GL_CURRENT_PROGRAM, &prog);
            CHECK_INT((GLuint)prog, plain->rt->prog->object);
        }
    }
done:
    g.DeleteTextures(1, &t1);
    g.DeleteTextures(1, &t2);
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* The same for sampler objects: destroying an effect deletes its samplers, which GL unbinds
 * from every unit; a later effect's sampler may get the name back and must still be bound.
 * A 2x1 texture (red, green) sampled at u = 0.5: Point gives green, the texture's own LINEAR
 * filter (no sampler bound) a half-and-half mix. */
static void test_deleted_sampler_name(void) {
    GLuint tex;
    g.GenTextures(1, &tex);
    g.BindTexture(GL_TEXTURE_2D, tex);
    const unsigned char texels[8] = {255, 0, 0, 255, 0, 255, 0, 255};
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    g.BindTexture(GL_TEXTURE_2D, 0);
    const float white[4] = {1, 1, 1, 1}, green[4] = {0, 1, 0, 1};
    for (int reuse = 0; reuse < 2; reuse++) {
        vn_reset();
        hfx_device *dev = hfx_device_create_gl(reuse ? reuse_loader : test_gl_loader);
        for (int round = 0; round < 3; round++) {
            hfx_effect *fx = load_fx(dev, tex_fx, 0);
            if (!fx) break;
            set_f(fx, "Color", white, 4);
            CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Tex"), tex), HFX_OK);
            draw_check(hfx_technique_pass(hfx_effect_technique(fx, "T"), 1), green, "point sampled");
            hfx_effect_destroy(fx);
        }
        hfx_device_destroy(dev);
        g.UseProgram(0);
        PFNGLBINDSAMPLERPROC bind_sampler = (PFNGLBINDSAMPLERPROC)test_gl_proc("glBindSampler");
        bind_sampler(0, 0);
    }
    g.DeleteTextures(1, &tex);
}

/* Parameters that stay separate uniforms even when packing: struct members, array elements,
 * int and bool (set_int, set_ints, set_bool), a matrix array; each changed through
 * hfx_param_member / hfx_param_element, one per Apply (the inline check) and several. */
static const char *const other_fx =
    "struct Light { float3 Dir; float Power; };\n"
    "Light L;\n"
    "float4 Arr[3];\n"
    "float2x2 Mats[2];\n"
    "int N;\n"
    "bool On;\n"
    "float K;\n"
    "float4 VS(float2 p : POSITION0) : POSITION { return float4(p, 0, 1); }\n"
    "float4 PS() : COLOR0 {\n"
    "    float4 c = float4(L.Dir * L.Power, K);\n"
    "    c += Arr[1] * (float)N;\n"
    "    c.xy += mul(float2(0.5, 0.25), Mats[1]);\n"
    "    if (On) c.z += 0.25;\n"
    "    return c;\n"
    "}\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

typedef struct other_vals {
    float dir[3], power, arr1[4], mat1[4], k;
    int n, on;
} other_vals;

static void other_expected(const other_vals *v, float out[4]) {
    for (int i = 0; i < 3; i++) out[i] = v->dir[i] * v->power;
    out[3] = v->k;
    for (int i = 0; i < 4; i++) out[i] += v->arr1[i] * (float)v->n;
    out[0] += 0.5f * v->mat1[0] + 0.25f * v->mat1[2];
    out[1] += 0.5f * v->mat1[1] + 0.25f * v->mat1[3];
    if (v->on) out[2] += 0.25f;
}

static void other_apply_check(hfx_effect *fx, const other_vals *v) {
    float want[4];
    CHECK_INT(hfx_pass_apply(pass_of(fx, "T")), HFX_OK);
    draw();
    other_expected(v, want);
    check_px(want, "other");
}

static void test_other_slots(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    for (int separate = 0; separate < 2; separate++) {
        hfx_effect *fx = load_fx(dev, other_fx, separate);
        if (!fx) continue;
        other_vals v = {{0.2f, 0.4f, 0.1f}, 0.5f, {0.1f, 0.05f, 0.2f, 0.1f}, {0.2f, 0.4f, 0.3f, 0.1f}, 0.5f, 1, 0};
        hfx_param *l = hfx_effect_param(fx, "L"), *arr = hfx_effect_param(fx, "Arr");
        hfx_param *mats = hfx_effect_param(fx, "Mats");
        CHECK_INT(hfx_param_set_floats(hfx_param_member(l, "Dir"), v.dir, 3), HFX_OK);
        CHECK_INT(hfx_param_set_float(hfx_param_member(l, "Power"), v.power), HFX_OK);
        CHECK_INT(hfx_param_set_floats(hfx_param_element(arr, 1), v.arr1, 4), HFX_OK);
        float m4[16] = {v.mat1[0], v.mat1[1], 0, 0, v.mat1[2], v.mat1[3]};
        CHECK_INT(hfx_param_set_matrix(hfx_param_element(mats, 1), m4), HFX_OK);
        CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "K"), v.k), HFX_OK);
        CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "N"), v.n), HFX_OK);
        CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "On"), v.on), HFX_OK);
        other_apply_check(fx, &v);
        /* one change per Apply, each kind */
        v.power = 1.0f;
        CHECK_INT(hfx_param_set_float(hfx_param_member(l, "Power"), v.power), HFX_OK);
        other_apply_check(fx, &v);
        v.arr1[0] = 0.3f;
        CHECK_INT(hfx_param_set_floats(hfx_param_element(arr, 1), v.arr1, 4), HFX_OK);
        other_apply_check(fx, &v);
        v.n = 2;
        CHECK_INT(hfx_param_set_ints(hfx_effect_param(fx, "N"), &v.n, 1), HFX_OK);
        other_apply_check(fx, &v);
        v.on = 1;
        CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "On"), v.on), HFX_OK);
        other_apply_check(fx, &v);
        v.mat1[3] = 0.5f;
        m4[5] = 0.5f;
        CHECK_INT(hfx_param_set_matrix(hfx_param_element(mats, 1), m4), HFX_OK);
        other_apply_check(fx, &v);
        v.k = 0.25f;
        CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "K"), v.k), HFX_OK);
        other_apply_check(fx, &v);
        /* several kinds at once */
        v.dir[0] = 0.0f, v.n = 1, v.on = 0, v.k = 0.75f;
        CHECK_INT(hfx_param_set_floats(hfx_param_member(l, "Dir"), v.dir, 3), HFX_OK);
        CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "N"), v.n), HFX_OK);
        CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "On"), v.on), HFX_OK);
        CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "K"), v.k), HFX_OK);
        other_apply_check(fx, &v);
        hfx_effect_destroy(fx);
    }
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* The viewport and the framebuffer change hfx_pos_fixup between two Applies of one pass. */
static void test_viewport_between(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *fx = load_fx(dev, shapes_fx, 0);
    if (!fx) goto done;
    hfx_pass *p = pass_of(fx, "T22");
    float f[4];
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    read_uniform("hfx_pos_fixup", f, 4);
    CHECK_NEAR(f[0], 1.0 / W, 0);
    CHECK_NEAR(f[1], -1.0 / H, 0);
    hfx_device_set_viewport(dev, 0, 0, 4, 2);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    read_uniform("hfx_pos_fixup", f, 4);
    CHECK_NEAR(f[0], 0.25, 0);
    CHECK_NEAR(f[1], -0.5, 0);
    CHECK_NEAR(f[3], 2, 0);
    /* the application binds a framebuffer object and says so */
    GLuint fbo, tex;
    g.GenTextures(1, &tex);
    g.BindTexture(GL_TEXTURE_2D, tex);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    g.GenFramebuffers(1, &fbo);
    g.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    g.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    hfx_device_sync(dev);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    read_uniform("hfx_pos_fixup", f, 4);
    CHECK_NEAR(f[1], 0.5, 0);
    CHECK_NEAR(f[2], 1, 0);
    GLint front = 0;
    g.GetIntegerv(GL_FRONT_FACE, &front);
    CHECK_INT(front, GL_CCW);
    g.BindFramebuffer(GL_FRAMEBUFFER, 0);
    g.DeleteFramebuffers(1, &fbo);
    g.DeleteTextures(1, &tex);
    hfx_device_set_viewport(dev, 0, 0, W, H);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    read_uniform("hfx_pos_fixup", f, 4);
    CHECK_NEAR(f[1], -1.0 / H, 0);
    g.GetIntegerv(GL_FRONT_FACE, &front);
    CHECK_INT(front, GL_CW);
done:
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* A direct pass's program reads the alpha test the device's render states give; another pass
 * changes those states, then the direct pass again. */
static const char *const alpha_fx =
    "float4 Color;\n"
    "float4 VS(float2 p : POSITION0) : POSITION { return float4(p, 0, 1); }\n"
    "float4 PS() : COLOR0 { return Color; }\n"
    "technique T {\n"
    "  pass Plain { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }\n"
    "  pass Tested { AlphaTestEnable = TRUE; AlphaFunc = Greater; AlphaRef = 128;\n"
    "                VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }\n"
    "}\n";

static void test_alpha_between(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *fx = load_fx(dev, alpha_fx, 0);
    if (!fx) goto done;
    hfx_technique *t = hfx_effect_technique(fx, "T");
    hfx_pass *plain = hfx_technique_pass(t, 0), *tested = hfx_technique_pass(t, 1);
    float c[4] = {0.2f, 0.4f, 0.6f, 0.25f};
    set_f(fx, "Color", c, 4);
    CHECK_INT(hfx_pass_apply(plain), HFX_OK);
    draw();
    check_px(c, "alpha always");
    CHECK_INT(hfx_pass_apply(tested), HFX_OK);
    draw(); /* 0.25 * 255 is not greater than 128: discarded */
    check_px((float[4]){0, 0, 0, 0}, "alpha greater");
    /* D3D9: the states stay set; the direct pass applied after keeps testing */
    CHECK_INT(hfx_pass_apply(plain), HFX_OK);
    draw();
    check_px((float[4]){0, 0, 0, 0}, "alpha kept");
    c[3] = 0.75f;
    set_f(fx, "Color", c, 4);
    CHECK_INT(hfx_pass_apply(plain), HFX_OK);
    draw();
    check_px(c, "alpha passes");
done:
    hfx_effect_destroy(fx);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* Two effects on one device, and two devices on one context with hfx_device_sync between. */
static void test_two_effects_two_devices(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    hfx_effect *a = load_fx(dev, shapes_fx, 0), *b = load_fx(dev, shapes_fx, 1);
    if (!a || !b) goto done;
    unsigned char px[4];
    const shape *s = &shapes[4];
    set_shape(a, s, 0);
    set_shape(b, s, 1);
    for (int round = 0; round < 2; round++) {
        render_shape(a, s, 0, px);
        render_shape(b, s, 1, px);
    }
    hfx_device *dev2 = hfx_device_create_gl(test_gl_loader);
    hfx_effect *c = load_fx(dev2, shapes_fx, 0);
    if (c) {
        set_shape(c, s, 1);
        render_shape(a, s, 0, px);
        hfx_device_sync(dev2);
        render_shape(c, s, 1, px);
        hfx_device_sync(dev);
        render_shape(a, s, 0, px);
        hfx_device_sync(dev2);
        render_shape(c, s, 1, px);
    }
    hfx_effect_destroy(c);
    hfx_device_destroy(dev2);
done:
    hfx_effect_destroy(b);
    hfx_effect_destroy(a);
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* .hfxo bytes of the compiled effect (packed and separate) render as the .fx does. */
static void test_hfxo_round_trip(void) {
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    for (int separate = 0; separate < 2; separate++) {
        hfx_load_options opt;
        memset(&opt, 0, sizeof opt);
        opt.separate_uniforms = separate;
        opt.no_preshaders = 1;
        char *diag = NULL;
        hfx_fx_effect *cfx = hfx_rt_compile_fx(NULL, shapes_fx, strlen(shapes_fx), "paths.fx", &opt, &diag);
        free(diag);
        CHECK(cfx != NULL);
        void *bytes = NULL;
        size_t size = 0;
        if (cfx) CHECK_INT(hfx_fx_write_hfxo(cfx, &bytes, &size), 0);
        hfx_fx_effect_free(cfx);
        char *errors = NULL;
        hfx_effect *fx = bytes ? hfx_effect_load_memory(dev, bytes, size, "paths.hfxo", NULL, &errors) : NULL;
        if (!fx) fprintf(stderr, "hfxo: %s\n", errors ? errors : "(none)");
        hfx_free(errors);
        free(bytes);
        CHECK(fx != NULL);
        if (!fx) continue;
        hfx_effect *clone = hfx_effect_clone(fx);
        for (size_t i = 0; i < SHAPES; i++) {
            unsigned char px[4];
            set_shape(fx, &shapes[i], 0);
            set_shape(clone, &shapes[i], 1);
            render_shape(fx, &shapes[i], 0, px);
            if (separate) check_shape_separate(&shapes[i], 0);
            else check_shape_regs(&shapes[i], 0);
            render_shape(clone, &shapes[i], 1, px);
            render_shape(fx, &shapes[i], 0, px);
        }
        hfx_effect_destroy(clone);
        hfx_effect_destroy(fx);
    }
    hfx_device_destroy(dev);
    g.UseProgram(0);
}

/* .hfxo bytes carrying SPIR-V, packed and separate, loaded with the SPIR-V target. */
static void spirv_hfxo(hfx_device *dev) {
    for (int separate = 0; separate < 2; separate++) {
        hfx_load_options opt;
        memset(&opt, 0, sizeof opt);
        opt.target = HFX_TARGET_SPIRV;
        opt.separate_uniforms = separate;
        opt.no_preshaders = 1;
        char *diag = NULL;
        hfx_fx_effect *cfx = hfx_rt_compile_fx(NULL, shapes_fx, strlen(shapes_fx), "paths.fx", &opt, &diag);
        free(diag);
        CHECK(cfx != NULL);
        void *bytes = NULL;
        size_t size = 0;
        if (cfx) CHECK_INT(hfx_fx_write_hfxo(cfx, &bytes, &size), 0);
        hfx_fx_effect_free(cfx);
        char *errors = NULL;
        hfx_effect *fx = bytes ? hfx_effect_load_memory(dev, bytes, size, "paths.hfxo", &opt, &errors) : NULL;
        if (!fx) fprintf(stderr, "spirv hfxo: %s\n", errors ? errors : "(none)");
        hfx_free(errors);
        free(bytes);
        CHECK(fx != NULL);
        for (size_t i = 0; fx && i < SHAPES; i++) {
            unsigned char px[4];
            set_shape(fx, &shapes[i], (int)(i % 2));
            render_shape(fx, &shapes[i], (int)(i % 2), px);
        }
        hfx_effect_destroy(fx);
    }
}

/* SPIR-V (a 4.5 core context): every shape packed and separate, clones alternating, one change
 * on the short way; skipped where GL cannot load SPIR-V. */
static void test_spirv(void) {
    test_gl *gl45 = test_gl_create_version(W, H, 4, 5);
    if (!gl45) {
        printf("  no 4.5 context: SPIR-V not tested\n");
        return;
    }
    test_gl *saved = gl;
    gl = gl45;
    tgl_load(&g);
    g.Viewport(0, 0, W, H);
    static const float full[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint vao45, vbo45;
    vao45 = tgl_triangles(&g, full, 6, &vbo45);
    GLuint keep = vao;
    vao = vao45;
    hfx_device *dev = hfx_device_create_gl(test_gl_loader);
    if (!dev->gl->spirv.ok) {
        printf("  no ARB_gl_spirv: SPIR-V not tested\n");
    } else {
        for (int separate = 0; separate < 2; separate++) {
            hfx_load_options opt;
            memset(&opt, 0, sizeof opt);
            opt.target = HFX_TARGET_SPIRV;
            opt.separate_uniforms = separate;
            hfx_effect *fx = load_opt(dev, shapes_fx, &opt);
            if (!fx) continue;
            hfx_effect *clone = hfx_effect_clone(fx);
            for (size_t i = 0; i < SHAPES; i++) {
                unsigned char px[4];
                float want[4];
                set_shape(fx, &shapes[i], 0);
                set_shape(clone, &shapes[i], 1);
                render_shape(fx, &shapes[i], 0, px);
                render_shape(clone, &shapes[i], 1, px);
                render_shape(fx, &shapes[i], 0, px);
                /* one change, same pass */
                float last[4] = {0.5f, 0.5f, 0.5f, 0.5f};
                set_f(fx, "Last", last, 4);
                CHECK_INT(hfx_pass_apply(pass_of(fx, shapes[i].tech)), HFX_OK);
                draw();
                expected_color(&shapes[i], 0, want);
                float l0[4];
                lastval(0, l0);
                for (int k = 0; k < 4; k++) want[k] += 0.5f - l0[k];
                check_px(want, "spirv one change");
            }
            hfx_effect_destroy(clone);
            hfx_effect_destroy(fx);
        }
        spirv_hfxo(dev);
        stages_and_trim(HFX_TARGET_SPIRV);
    }
    hfx_device_destroy(dev);
    g.UseProgram(0);
    g.DeleteBuffers(1, &vbo45);
    g.DeleteVertexArrays(1, &vao45);
    test_gl_destroy(gl45);
    vao = keep;
    gl = saved;
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    g.Viewport(0, 0, W, H);
    static const float full[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    vao = tgl_triangles(&g, full, 6, &vbo);
    RUN(test_matrix_shapes);
    RUN(test_one_change_one_call);
    RUN(test_many_changes_and_ring);
    RUN(test_clones_alternate);
    RUN(test_technique_switch);
    RUN(test_destroy_and_reuse);
    RUN(test_deleted_program_name);
    RUN(test_stages_and_trim);
    RUN(test_register_limit);
    RUN(test_textured_neighbour);
    RUN(test_deleted_sampler_name);
    RUN(test_other_slots);
    RUN(test_viewport_between);
    RUN(test_alpha_between);
    RUN(test_two_effects_two_devices);
    RUN(test_hfxo_round_trip);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
    test_gl_destroy(gl);
    gl = NULL;
    RUN(test_spirv);
    return test_summary();
}
