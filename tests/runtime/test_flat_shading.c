/* test_flat_shading.c: values that are not interpolated take the triangle's first vertex, as
 * in Direct3D (GL's default is the last: the runtime sets the first-vertex convention).
 * `nointerpolation` on an output or input, and ShadeMode = FLAT in a pass (D3D9 flat-shades the
 * COLOR inputs then) both give every pixel of the triangle the first vertex's colour; a plain
 * pass interpolates. */
#include <string.h>

#include "gl_context.h"
#include "rt_check.h"
#include "rt_support.h"
#include "test.h"

#define W 8
#define H 8

static test_gl *gl;
static tgl g;
static hfx_device *dev;

static const char src[] =
    "struct VO { float4 p : POSITION; float4 c : COLOR0; };\n"
    "struct VOF { float4 p : POSITION; nointerpolation float4 c : COLOR0; };\n"
    "VO VS(float4 p : POSITION, float4 c : COLOR0) { VO o; o.p = p; o.c = c; return o; }\n"
    "VOF VSF(float4 p : POSITION, float4 c : COLOR0) { VOF o; o.p = p; o.c = c; return o; }\n"
    "float4 PS(float4 c : COLOR0) : COLOR { return c; }\n"
    "technique Smooth { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n"
    "technique NoInterpolation { pass P { VertexShader = compile vs_3_0 VSF(); PixelShader = compile ps_3_0 PS(); } }\n"
    "technique Flat { pass P { ShadeMode = FLAT; VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

/* One triangle over the lower-left half: red first, then green, then blue. */
static void draw(hfx_effect *fx, const char *tech) {
    static const float xyrgb[] = {-1, -1, 1, 0, 0, 1, -1, 0, 1, 0, -1, 1, 0, 0, 1};
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(fx, tech), 0);
    GLuint vao, buf;
    g.GenVertexArrays(1, &vao);
    g.BindVertexArray(vao);
    g.GenBuffers(1, &buf);
    g.BindBuffer(GL_ARRAY_BUFFER, buf);
    g.BufferData(GL_ARRAY_BUFFER, sizeof xyrgb, xyrgb, GL_STATIC_DRAW);
    int pos = hfx_pass_attribute_location(pass, "POSITION0"), col = hfx_pass_attribute_location(pass, "COLOR0");
    CHECK(pos >= 0 && col >= 0);
    g.VertexAttribPointer((GLuint)pos, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void *)0);
    g.EnableVertexAttribArray((GLuint)pos);
    g.VertexAttribPointer((GLuint)col, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void *)(2 * sizeof(float)));
    g.EnableVertexAttribArray((GLuint)col);
    g.ClearColor(0, 0, 0, 1);
    g.Clear(GL_COLOR_BUFFER_BIT);
    CHECK_INT(hfx_pass_apply(pass), HFX_OK);
    g.DrawArrays(GL_TRIANGLES, 0, 3);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    g.DeleteBuffers(1, &buf);
    g.DeleteVertexArrays(1, &vao);
}

static hfx_effect *load(void) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, src, sizeof src - 1, "flat.fx", NULL, &errors);
    if (!fx) printf("%s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    return fx;
}

/* Pixels inside the triangle (rows from the top: the triangle is GL's lower left): pure red. */
static void nointerpolation_takes_the_first_vertex(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    draw(fx, "NoInterpolation");
    rt_check_pixel(gl, 2, 5, 255, 0, 0, 255);
    rt_check_pixel(gl, 0, 1, 255, 0, 0, 255);
    hfx_effect_destroy(fx);
}

static void shade_mode_flat_takes_the_first_vertex(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    draw(fx, "Flat");
    rt_check_pixel(gl, 2, 5, 255, 0, 0, 255);
    rt_check_pixel(gl, 6, 7, 255, 0, 0, 255);
    CHECK_STR(hfx_effect_warnings(fx), "");
    hfx_effect_destroy(fx);
}

/* Smooth: D3D9 samples pixel (2, 5) (row from the top) at screen point (2, 5), its centre at
 * integers (hfx reproduces that): NDC x = 2 / 8 * 2 - 1 = -0.5, y = 1 - 5 / 8 * 2 = -0.25. With
 * v0 (-1,-1), v1 (1,-1), v2 (-1,1): green = (x + 1) / 2 = 0.25, blue = (y + 1) / 2 = 0.375,
 * red = 0.375. */
static void smooth_interpolates(void) {
    hfx_effect *fx = load();
    if (!fx) return;
    draw(fx, "Smooth");
    unsigned char px[4];
    test_gl_read(gl, 2, 5, px);
    CHECK_NEAR(px[0], 0.375 * 255, 1.5);
    CHECK_NEAR(px[1], 0.25 * 255, 1.5);
    CHECK_NEAR(px[2], 0.375 * 255, 1.5);
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    g.Viewport(0, 0, W, H);
    RUN(nointerpolation_takes_the_first_vertex);
    RUN(shade_mode_flat_takes_the_first_vertex);
    RUN(smooth_interpolates);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
