/* hfxview draws a technique's passes the way D3D9 (and XNA) would: a pass's render states stay
 * set for the next pass, which only changes what it names. Each technique below has a first
 * pass that sets a state and a second pass that names none; the pixel probed proves the second
 * pass ran under the first pass's state. --blend-passes add (the application switching to
 * additive blending between passes) still works on top of that. */
#include "test.h"

#include "files.h"
#include "view_support.h"

static char *hfxview, *tmp, *fx;

static int render(const char *args, view_png *img) {
    char *path = view_format("%s/passes.png", tmp);
    char *cmd = view_format("%s %s --mesh quad --camera eye=0,0,3.2,at=0,0,0 --size 64x64 --background 0,0,0 %s -o %s",
                            hfxview, fx, args, path),
         *out = NULL;
    int rc = view_run(cmd, &out);
    if (rc != 0) fprintf(stderr, "%s exited %d:\n%s\n", cmd, rc, out ? out : "");
    int ok = rc == 0 && view_png_read(img, path) == 0;
    free(out);
    free(cmd);
    free(path);
    return ok;
}

/* Every pass draws the quad (which fills the middle of the image) in a flat colour. */
static const char effect[] =
    "float4x4 WorldViewProjection : WORLDVIEWPROJECTION;\n"
    "float4 VS(float3 p : POSITION0) : POSITION0 { return mul(float4(p, 1), WorldViewProjection); }\n"
    "float4 Red() : COLOR0 { return float4(0.25, 0, 0, 1); }\n"
    "float4 Green() : COLOR0 { return float4(0, 0.5, 0, 1); }\n"
    "float4 Orange() : COLOR0 { return float4(1, 0.5, 0.25, 1); }\n"
    "float4 Cyan() : COLOR0 { return float4(0.5, 1, 1, 1); }\n"
    "#define SHADERS(ps) VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 ps()\n"
    /* pass 1 blends (One, One) because pass 0 switched blending on: red + green */
    "technique Blend {\n"
    "  pass A { AlphaBlendEnable = TRUE; SrcBlend = One; DestBlend = One; SHADERS(Red); }\n"
    "  pass B { SHADERS(Green); }\n"
    "}\n"
    /* pass 1 writes red only, as pass 0 asked: 0.5 red, nothing else */
    "technique Mask {\n"
    "  pass A { ColorWriteEnable = Red | Alpha; SHADERS(Orange); }\n"
    "  pass B { SHADERS(Cyan); }\n"
    "}\n"
    /* pass 0 culls the quad's (clockwise) front face; pass 1 keeps culling it: background */
    "technique Cull {\n"
    "  pass A { CullMode = CW; SHADERS(Red); }\n"
    "  pass B { SHADERS(Green); }\n"
    "}\n"
    /* no states: opaque, unless the application blends (--blend-passes add) */
    "technique Plain {\n"
    "  pass A { SHADERS(Red); }\n"
    "  pass B { SHADERS(Green); }\n"
    "}\n"
    /* pass 1 puts back what it names: opaque green over red */
    "technique Reset {\n"
    "  pass A { AlphaBlendEnable = TRUE; SrcBlend = One; DestBlend = One; SHADERS(Red); }\n"
    "  pass B { AlphaBlendEnable = FALSE; SHADERS(Green); }\n"
    "}\n";

static void blending_carries_over(void) {
    view_png img;
    if (render("--technique Blend", &img)) CHECK(view_pixel_near(&img, 32, 32, 64, 128, 0, 1));
    else CHECK(0);
    view_png_free(&img);
    /* pass 0 alone: red over black, added */
    if (render("--technique Blend --pass 0", &img)) CHECK(view_pixel_near(&img, 32, 32, 64, 0, 0, 1));
    else CHECK(0);
    view_png_free(&img);
}

static void color_write_mask_carries_over(void) {
    view_png img;
    if (render("--technique Mask", &img)) {
        CHECK(view_pixel_near(&img, 32, 32, 128, 0, 0, 1));
        CHECK(view_pixel_near(&img, 1, 1, 0, 0, 0, 0));
    } else {
        CHECK(0);
    }
    view_png_free(&img);
}

static void culling_carries_over(void) {
    view_png img;
    if (render("--technique Cull", &img)) CHECK(view_pixel_near(&img, 32, 32, 0, 0, 0, 0));
    else CHECK(0);
    view_png_free(&img);
    /* pass 1 alone starts from XNA's defaults (CullCounterClockwise): the quad shows */
    if (render("--technique Cull --pass 1", &img)) CHECK(view_pixel_near(&img, 32, 32, 0, 128, 0, 1));
    else CHECK(0);
    view_png_free(&img);
}

static void a_pass_overrides_what_it_names(void) {
    view_png img;
    if (render("--technique Reset", &img)) CHECK(view_pixel_near(&img, 32, 32, 0, 128, 0, 1));
    else CHECK(0);
    view_png_free(&img);
}

/* --blend-passes add: the application's additive blending before pass 1 is seen by the
 * runtime; a pass's own blend state still wins (Reset), and the first pass's other states
 * still carry over (Mask: red only, 1 + 0.5 saturates). */
static void blend_passes_add(void) {
    view_png img;
    if (render("--technique Plain", &img)) CHECK(view_pixel_near(&img, 32, 32, 0, 128, 0, 1));
    else CHECK(0);
    view_png_free(&img);
    if (render("--technique Plain --blend-passes add", &img)) CHECK(view_pixel_near(&img, 32, 32, 64, 128, 0, 1));
    else CHECK(0);
    view_png_free(&img);
    if (render("--technique Reset --blend-passes add", &img)) CHECK(view_pixel_near(&img, 32, 32, 0, 128, 0, 1));
    else CHECK(0);
    view_png_free(&img);
    if (render("--technique Mask --blend-passes add", &img)) CHECK(view_pixel_near(&img, 32, 32, 255, 0, 0, 1));
    else CHECK(0);
    view_png_free(&img);
}

/* Without --technique, the first technique that has a pass: the effect begins with an empty
 * one, as an effect does that includes a file whose technique is commented out. */
static void default_is_the_first_technique_that_draws(void) {
    char *saved = fx;
    fx = view_format("%s/empty_first.fx", tmp);
    FILE *f = fopen(fx, "w");
    fputs("float4x4 WorldViewProjection : WORLDVIEWPROJECTION;\n"
          "float4 VS(float3 p : POSITION0) : POSITION0 { return mul(float4(p, 1), WorldViewProjection); }\n"
          "float4 Green() : COLOR0 { return float4(0, 0.5, 0, 1); }\n"
          "technique Empty { }\n"
          "technique Draws { pass { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 Green(); } }\n", f);
    fclose(f);
    view_png img;
    if (render("", &img)) CHECK(view_pixel_near(&img, 32, 32, 0, 128, 0, 1));
    else CHECK(0);
    view_png_free(&img);
    if (render("--technique Empty", &img)) CHECK(view_pixel_near(&img, 32, 32, 0, 0, 0, 0)); /* asked for: nothing */
    else CHECK(0);
    view_png_free(&img);
    free(fx);
    fx = saved;
}

/* The same on EGL (a framebuffer object, front faces flipped by the runtime), when built. */
static void egl_too(void) {
    view_png img;
    if (!render("--technique Cull --egl", &img)) {
        printf("  (hfxview --egl does not draw here: not tried)\n");
        return;
    }
    CHECK(view_pixel_near(&img, 32, 32, 0, 0, 0, 0));
    view_png_free(&img);
    if (render("--technique Blend --egl", &img)) CHECK(view_pixel_near(&img, 32, 32, 64, 128, 0, 1));
    else CHECK(0);
    view_png_free(&img);
}

int main(void) {
    hfxview = view_build_path("tools/hfxview/hfxview");
    if (!hfxview) test_skip("hfxview is not built (it needs OSMesa, libpng and stb)");
    tmp = test_temp_dir();
    fx = view_format("%s/two_passes.fx", tmp);
    FILE *f = fopen(fx, "w");
    fputs(effect, f);
    fclose(f);
    RUN(blending_carries_over);
    RUN(color_write_mask_carries_over);
    RUN(culling_carries_over);
    RUN(a_pass_overrides_what_it_names);
    RUN(blend_passes_add);
    RUN(default_is_the_first_technique_that_draws);
    RUN(egl_too);
    test_remove_dir(tmp);
    free(fx);
    free(tmp);
    free(hfxview);
    return test_summary();
}
