/* test_switches.c: bool parameters as switches (common/effect.h). Apply draws with the program
 * variant for the bools' values now, linked the first time a combination is needed and kept:
 * probed after each change (on Apply's full and short paths), a float set while another
 * variant was bound reaches the one bound next, and a combination seen before reuses its GL
 * program. PS returns Lit (red) or Dark (blue) by UseLit, halved when Half: 255 or 128 (0.5 *
 * 255 = 127.5, which GL's conversion to 8 bits rounds to 127 or 128: within 1). Lit and Dark
 * are multiplied by a varying (1) so that the branch stays in the shader: on parameters alone
 * it would be a preshader, and a bool only preshaders read is no switch. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl_context.h"
#include "rt_support.h"
#include "test.h"

#define W 8
#define H 8

static test_gl *gl;
static tgl g;
static hfx_device *dev;

static const char switches_fx[] =
    "float4 Lit = float4(1, 0, 0, 1);\nfloat4 Dark = float4(0, 0, 1, 1);\nbool UseLit = true;\nbool Half = false;\n"
    "void VS(float4 p : POSITION0, out float4 o : POSITION0, out float4 w : TEXCOORD0) { o = p; w = 1; }\n"
    "float4 PS(float4 w : TEXCOORD0) : COLOR0\n{\n    float4 c;\n    if (UseLit) c = Lit * w;\n    else c = Dark * w;\n"
    "    if (Half) c.rgb *= 0.5;\n    return c;\n}\n"
    "technique T { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

static hfx_effect *load(const char *src) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, strlen(src), "switches.fx", NULL, &errors);
    if (!fx) fprintf(stderr, "%s\n", errors ? errors : "");
    hfx_free(errors);
    return fx;
}

static void draw_quad(void) {
    static const float xy[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    GLuint vbo, vao = tgl_triangles(&g, xy, 6, &vbo);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
}

/* The centre pixel as 0xRRGGBB. */
static unsigned centre(void) {
    unsigned char px[4];
    test_gl_read(gl, W / 2, H / 2, px);
    return (unsigned)px[0] << 16 | (unsigned)px[1] << 8 | px[2];
}

/* One channel within 1 of want (shift: 16 red, 8 green, 0 blue), the others 0. */
static void expect(unsigned got, int shift, int want) {
    int c = (int)(got >> shift & 255);
    if (c < want - 1 || c > want + 1 || (got & ~(255u << shift)) != 0) fprintf(stderr, "got %06x\n", got);
    CHECK(c >= want - 1 && c <= want + 1);
    CHECK_INT(got & ~(255u << shift), 0);
}

/* Apply, draw, read; *program gets the GL program Apply bound. */
static unsigned draw(hfx_effect *fx, GLint *program) {
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    hfx_effect_begin(fx);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(fx, "T"), 0)), HFX_OK);
    g.GetIntegerv(GL_CURRENT_PROGRAM, program);
    draw_quad();
    hfx_effect_end(fx);
    return centre();
}

static void each_combination_draws_its_colour(void) {
    hfx_effect *fx = load(switches_fx);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_param *use_lit = hfx_effect_param(fx, "UseLit"), *half = hfx_effect_param(fx, "Half");
    GLint lit_full, lit_half, dark_half, again;
    expect(draw(fx, &lit_full), 16, 255);
    CHECK_INT(hfx_param_set_bool(half, 1), HFX_OK);
    expect(draw(fx, &lit_half), 16, 128);
    CHECK(lit_half != lit_full); /* another variant */
    CHECK_INT(hfx_param_set_bool(use_lit, 0), HFX_OK);
    expect(draw(fx, &dark_half), 0, 128);
    /* Lit changes while the Dark variant is bound: the Lit one gets it when it is bound again */
    const float green[4] = {0, 1, 0, 1};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Lit"), green, 4), HFX_OK);
    expect(draw(fx, &again), 0, 128);
    CHECK_INT(hfx_param_set_bool(use_lit, 1), HFX_OK);
    CHECK_INT(hfx_param_set_bool(half, 0), HFX_OK);
    expect(draw(fx, &again), 8, 255);
    CHECK_INT(again, lit_full); /* linked once, kept */
    hfx_effect_destroy(fx);
}

/* The same pass applied again with nothing else set takes Apply's short path: a bool changed in
 * between still picks the other variant there. */
static void the_short_path_follows_the_switches(void) {
    hfx_effect *fx = load(switches_fx);
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, "T"), 0);
    g.ClearColor(0, 0, 0, 0);
    g.Clear(GL_COLOR_BUFFER_BIT);
    hfx_effect_begin(fx);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "UseLit"), 0), HFX_OK);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    draw_quad();
    expect(centre(), 0, 255);
    CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "Half"), 1), HFX_OK);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    draw_quad();
    expect(centre(), 0, 128);
    /* a float alone: the short path keeps the variant and uploads the value */
    const float grey[4] = {0, 0, 0.5f, 1};
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Dark"), grey, 4), HFX_OK);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    draw_quad();
    expect(centre(), 0, 64); /* 0.25 * 255 = 63.75 */
    hfx_effect_end(fx);
    hfx_effect_destroy(fx);
}

/* Two instances of one effect share programs and variants, each drawing its own bools. */
static void clones_keep_their_own_values(void) {
    hfx_effect *a = load(switches_fx);
    hfx_effect *b = a ? hfx_effect_clone(a) : NULL;
    CHECK(a && b);
    if (a && b) {
        GLint pa, pb;
        CHECK_INT(hfx_param_set_bool(hfx_effect_param(b, "UseLit"), 0), HFX_OK);
        expect(draw(a, &pa), 16, 255);
        expect(draw(b, &pb), 0, 255);
        CHECK(pa != pb);
        expect(draw(a, &pb), 16, 255);
        CHECK_INT(pb, pa);
    }
    hfx_effect_destroy(b);
    hfx_effect_destroy(a);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    g.Viewport(0, 0, W, H);
    dev = hfx_device_create_gl(test_gl_loader);
    RUN(each_combination_draws_its_colour);
    RUN(the_short_path_follows_the_switches);
    RUN(clones_keep_their_own_values);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
