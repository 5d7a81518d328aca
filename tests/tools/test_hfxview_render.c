/* hfxview end to end on the project's own effects (fx/): it runs the program, reads the PNG
 * back and probes pixels whose values were worked out by hand from the effect's formulas. */
#include "test.h"

#include <unistd.h>

#include "files.h"
#include "view_support.h"

static char *hfxview, *tmp;

/* Runs hfxview with args; returns the exit status, *out gets its messages. */
static int hv(char **out, const char *args) {
    char *cmd = view_format("cd %s && %s %s", tmp, hfxview, args);
    int rc = view_run(cmd, out);
    free(cmd);
    return rc;
}

static int render(const char *args, const char *png, view_png *img) {
    char *out = NULL, *a = view_format("%s -o %s/%s", args, tmp, png), *path = view_format("%s/%s", tmp, png);
    int rc = hv(&out, a);
    if (rc != 0) fprintf(stderr, "hfxview %s exited %d:\n%s\n", a, rc, out ? out : "");
    int ok = rc == 0 && view_png_read(img, path) == 0;
    free(out);
    free(a);
    free(path);
    return ok;
}

#define FX HFX_SOURCE_DIR "/fx/"
/* D3D9 samples pixel (x, y) at integer coordinates: in a 128 x 128 image pixel 64 sits
 * exactly on the centre (the runtime reproduces D3D9's pixel centres). */
#define FRONT "--camera eye=0,0,3,at=0,0,0 --size 128x128"

/* shading_models.fx, camera at (0,0,3): the centre pixel sees (0,0,1), N = V = (0,0,1). In
 * camera space the point is (0,0,-2) and the light (0,1.8,1.3) is at (0,1.8,-1.7), so
 * L = (0,1.8,0.3)/1.8248 = (0,0.9864,0.1644) and N.L = 0.1644.
 * Phong: R.V = 0.1644, ^6 = 2e-5: red = 0.2 + 0.7*0.1644 = 0.3151 -> 80; green = blue = 0.
 * Blinn: H = (L+V)/|L+V| = (0,0.6464,0.7630), N.H^6 = 0.1973: red = 0.5124 -> 131; g = b = 50. */
static void phong_and_blinn_phong_centre_pixels(void) {
    view_png img;
    if (!render(FX "shading_models.fx --technique Phong " FRONT, "phong.png", &img)) {
        CHECK(0);
        return;
    }
    CHECK_INT(img.width, 128);
    CHECK_INT(img.height, 128);
    CHECK(view_pixel_near(&img, 64, 64, 80, 0, 0, 2));
    CHECK(view_pixel_near(&img, 1, 1, 100, 149, 237, 0)); /* CornflowerBlue */
    CHECK_INT(view_png_at(&img, 1, 1)[3], 255);
    view_png_free(&img);
    if (render(FX "shading_models.fx --technique BlinnPhong " FRONT, "blinn.png", &img))
        CHECK(view_pixel_near(&img, 64, 64, 131, 50, 50, 2));
    else
        CHECK(0);
    view_png_free(&img);
    /* Gouraud: the centre is a vertex of the sphere (u = 0, v = 1/2), so it matches Phong there. */
    if (render(FX "shading_models.fx --technique Gouraud " FRONT, "gouraud.png", &img))
        CHECK(view_pixel_near(&img, 64, 64, 80, 0, 0, 3));
    else
        CHECK(0);
    view_png_free(&img);
}

/* --light overrides the effect's own LightPosition: from (0,3,1) the light grazes the centre
 * point (0,0,1) (L = (0,1,0), N.L = 0): only the ambient 0.2 red is left -> (51, 0, 0). */
static void light_option_overrides_the_effect(void) {
    view_png img;
    if (render(FX "shading_models.fx --technique Phong --light position=0,3,1 " FRONT, "grazing.png", &img))
        CHECK(view_pixel_near(&img, 64, 64, 51, 0, 0, 1));
    else
        CHECK(0);
    view_png_free(&img);
}

/* sas_blinn.fx binds everything by semantic (WorldViewProjection, WorldInverseTranspose,
 * ViewInverse for the eye). Centre: N = L = V = H = (0,0,1) with the lamp at (0,0,10):
 * ambient 0.1 + surface (0.8,0.2,0.2) + Ks 0.4 -> (1.3, 0.7, 0.7) -> (255, 178.5, 178.5). */
static void fx_composer_semantics(void) {
    view_png img;
    if (render(FX "sas_blinn.fx " FRONT, "sas.png", &img)) {
        CHECK(view_pixel_near(&img, 64, 64, 255, 178, 178, 2));
        CHECK(view_pixel_near(&img, 0, 0, 100, 149, 237, 0));
    } else {
        CHECK(0);
    }
    view_png_free(&img);
}

/* textured.fx on the quad (2 x 2 at z = 0) from (0,0,3.2), 256 x 256, 45 degrees: the view
 * spans 3.2 tan(22.5) = 1.3255 either side, so the quad runs from pixel 31.4 to 224.6 and its
 * 8 x 8 checker cells are 24.1 pixels wide. Cell (0,0) of the default checker, at the top left
 * with texture coordinate (0,0), is light (235); its right and lower neighbours are dark. */
static void default_texture_is_a_checker_top_left_first(void) {
    view_png img;
    if (!render(FX "textured.fx --mesh quad --camera eye=0,0,3.2,at=0,0,0 --size 256x256", "quad.png", &img)) {
        CHECK(0);
        return;
    }
    CHECK(view_pixel_near(&img, 43, 43, 235, 235, 235, 2));
    CHECK(view_pixel_near(&img, 67, 43, 90, 90, 100, 2));
    CHECK(view_pixel_near(&img, 43, 67, 90, 90, 100, 2));
    CHECK(view_pixel_near(&img, 212, 212, 235, 235, 235, 2)); /* cell (7,7): light again */
    CHECK(view_pixel_near(&img, 10, 10, 100, 149, 237, 0));
    view_png_free(&img);
}

/* ambient.fx, technique Material: every pixel of the mesh is AmbientColor = (0.35,0.35,0.4). */
static void set_overrides_initializers(void) {
    view_png img;
    if (render(FX "ambient.fx --technique Material --size 64x64", "ambient.png", &img))
        CHECK(view_pixel_near(&img, 32, 32, 89, 89, 102, 1));
    else
        CHECK(0);
    view_png_free(&img);
    if (render(FX "ambient.fx --technique 1 --size 64x64 --set AmbientColor=1,0,0,1", "red.png", &img)) {
        CHECK(view_pixel_near(&img, 32, 32, 255, 0, 0, 0));
        CHECK(view_pixel_near(&img, 0, 0, 100, 149, 237, 0));
    } else {
        CHECK(0);
    }
    view_png_free(&img);
}

/* The red-on-blue image above as the texture of the quad: the quad's centre samples the
 * image's centre (red), its top-left corner the image's corner (CornflowerBlue). */
static void texture_from_a_png(void) {
    view_png img;
    char *args = view_format(FX "textured.fx --mesh quad --camera eye=0,0,3.2,at=0,0,0 --size 256x256 "
                                "--texture DiffuseTexture=%s/red.png",
                             tmp);
    if (render(args, "textured.png", &img)) {
        CHECK(view_pixel_near(&img, 128, 128, 255, 0, 0, 0));
        CHECK(view_pixel_near(&img, 34, 34, 100, 149, 237, 1));
    } else {
        CHECK(0);
    }
    view_png_free(&img);
    free(args);
}

static void obj_mesh_size_and_background(void) {
    char *obj = view_format("%s/square.obj", tmp);
    FILE *f = fopen(obj, "w");
    fputs("v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n", f);
    fclose(f);
    char *args = view_format(FX "ambient.fx --technique Material --mesh %s --size 96x64 --background 0,0,0", obj);
    view_png img;
    if (render(args, "obj.png", &img)) {
        CHECK_INT(img.width, 96);
        CHECK_INT(img.height, 64);
        CHECK(view_pixel_near(&img, 48, 32, 89, 89, 102, 1));
        CHECK(view_pixel_near(&img, 0, 0, 0, 0, 0, 0));
        CHECK_INT(view_png_at(&img, 0, 0)[3], 255);
    } else {
        CHECK(0);
    }
    view_png_free(&img);
    free(args);
    free(obj);
}

/* multipass.fx: pass 0 alone is the ambient term; both passes add the lights on top. */
static void passes(void) {
    view_png first, all;
    int ok = render(FX "multipass.fx --pass 0 " FRONT, "pass0.png", &first) &&
             render(FX "multipass.fx --pass all " FRONT, "passes.png", &all);
    CHECK(ok);
    if (ok) {
        const unsigned char *a = view_png_at(&first, 50, 50), *b = view_png_at(&all, 50, 50);
        CHECK(a[0] + a[1] + a[2] < 100);          /* ambient 0.1 of the checker */
        CHECK(b[0] + b[1] + b[2] > a[0] + a[1] + a[2] + 30);
    }
    view_png_free(&first);
    view_png_free(&all);
    char *out = NULL;
    CHECK_INT(hv(&out, FX "multipass.fx --pass 2 -o p.png"), 2);
    CHECK_CONTAINS(out, "hfxview: technique Multipass has 2 passes; no pass 2\n");
    free(out);
}

/* --mesh screen: the image's rectangle in pixels, for post-processing vertex shaders that map
 * pixels to projection space themselves, here by a ViewportSize bound by name (DigitalRise's
 * ScreenToProjection without its half-pixel step). The pixel shader shows the texture
 * coordinate: D3D9 samples pixel (x, y) at integer coordinates, so pixel (8, 56) of a 64 x 64
 * image reads uv (8/64, 56/64) = (0.125, 0.875) -> (32, 223); uv (0, 0) is the top left. */
static void screen_mesh_and_viewport_size(void) {
    char *path = view_format("%s/screen.fx", tmp);
    FILE *f = fopen(path, "w");
    fputs("float2 ViewportSize;\n"
          "void VS(float4 p : POSITION, float2 uv : TEXCOORD0, out float4 o : POSITION, out float2 t : TEXCOORD0) {\n"
          "  o = p; o.xy = p.xy / ViewportSize * float2(2, -2) - float2(1, -1); t = uv; }\n"
          "float4 PS(float2 t : TEXCOORD0) : COLOR0 { return float4(t, 0, 1); }\n"
          "technique T { pass { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n", f);
    fclose(f);
    view_png img;
    char *args = view_format("%s --mesh screen --size 64x64", path);
    if (render(args, "screen.png", &img)) {
        CHECK(view_pixel_near(&img, 8, 56, 32, 223, 0, 2));
        CHECK(view_pixel_near(&img, 1, 1, 4, 4, 0, 1)); /* covered to the corners (the edges */
        CHECK(view_pixel_near(&img, 62, 62, 247, 247, 0, 1)); /* themselves cross pixel centres) */
    } else {
        CHECK(0);
    }
    view_png_free(&img);
    free(args);
    free(path);
}

static void exit_codes_and_messages(void) {
    char *out = NULL;
    CHECK_INT(hv(&out, ""), 2);
    CHECK_CONTAINS(out, "hfxview: no effect file given\nusage: hfxview EFFECT.fx");
    free(out);
    CHECK_INT(hv(&out, "--help"), 0);
    CHECK_CONTAINS(out, "--blend-passes add|none");
    free(out);
    CHECK_INT(hv(&out, FX "ambient.fx --technique Nope"), 2);
    CHECK_CONTAINS(out, "ambient.fx has no technique 'Nope'; it has: Textured Material\n");
    free(out);
    CHECK_INT(hv(&out, FX "ambient.fx --set Nope=1"), 2);
    CHECK_CONTAINS(out, "hfxview: --set: the effect has no parameter 'Nope'\n");
    free(out);
    CHECK_INT(hv(&out, FX "ambient.fx --texture Nope=x.png"), 2);
    CHECK_CONTAINS(out, "hfxview: --texture: the effect has no texture or sampler parameter 'Nope'\n");
    free(out);
    CHECK_INT(hv(&out, FX "ambient.fx --mesh nothing.obj"), 2);
    CHECK_CONTAINS(out, "hfxview: cannot open mesh 'nothing.obj' (not a built-in mesh name either)\n");
    free(out);
    CHECK_INT(hv(&out, "no_such_file.fx -o x.png"), 1);
    CHECK_CONTAINS(out, "no_such_file.fx");
    free(out);
    CHECK_INT(hv(&out, FX "ambient.fx --list"), 0);
    CHECK_CONTAINS(out, "technique Textured\n  pass 0 P0\ntechnique Material\n  pass 0 P0\n");
    CHECK_CONTAINS(out, "parameter World : World  (SAS semantic)\n");
    CHECK_CONTAINS(out, "parameter AmbientColor  (name: white (a material or light colour))\n");
    free(out);
}

/* A compile error comes out as the compiler's located diagnostic, and exit status 1. */
static void effect_errors(void) {
    char *fx = view_format("%s/broken.fx", tmp);
    FILE *f = fopen(fx, "w");
    fputs("float4 main() : COLOR\n{\n    return undefined_thing;\n}\n"
          "technique T { pass P { PixelShader = compile ps_2_0 main(); } }\n",
          f);
    fclose(f);
    char *out = NULL, *args = view_format("%s -o %s/broken.png", fx, tmp), *where = view_format("%s(3,", fx);
    CHECK_INT(hv(&out, args), 1);
    CHECK_CONTAINS(out, where);
    CHECK_CONTAINS(out, ": error X");
    free(out);
    free(args);
    free(where);
    free(fx);
}

/* A compiled effect from hfxc renders the same as its source. */
static void renders_hfxo(void) {
    char *hfxc = view_build_path("compiler/hfxc");
    if (!hfxc) {
        printf("  (hfxc is not built: .hfxo not tried)\n");
        return;
    }
    char *out = NULL, *cmd = view_format("%s " FX "ambient.fx -o %s/ambient.hfxo", hfxc, tmp);
    CHECK_INT(view_run(cmd, &out), 0);
    char *args = view_format("%s/ambient.hfxo --technique Material --size 64x64", tmp);
    view_png img;
    if (render(args, "hfxo.png", &img)) CHECK(view_pixel_near(&img, 32, 32, 89, 89, 102, 1));
    else CHECK(0);
    view_png_free(&img);
    free(args);
    free(out);
    free(cmd);
    free(hfxc);
}

int main(void) {
    hfxview = view_build_path("tools/hfxview/hfxview");
    if (!hfxview) test_skip("hfxview is not built (it needs OSMesa, libpng and stb)");
    tmp = test_temp_dir();
    RUN(phong_and_blinn_phong_centre_pixels);
    RUN(light_option_overrides_the_effect);
    RUN(fx_composer_semantics);
    RUN(default_texture_is_a_checker_top_left_first);
    RUN(set_overrides_initializers);
    RUN(texture_from_a_png);
    RUN(obj_mesh_size_and_background);
    RUN(passes);
    RUN(screen_mesh_and_viewport_size);
    RUN(exit_codes_and_messages);
    RUN(effect_errors);
    RUN(renders_hfxo);
    test_remove_dir(tmp);
    free(tmp);
    free(hfxview);
    return test_summary();
}
