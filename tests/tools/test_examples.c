/* Every example program run headless, its PNG read back and probed. The expected pixels are
 * worked out by hand from the example's parameters and the effect's formulas. */
#include "test.h"

#include "files.h"
#include "view_support.h"

static char *tmp;

/* Runs examples/NAME with args (OUT.png first), reads OUT.png; 1 on success. */
static int run_example(const char *name, const char *args, view_png *img) {
    char *exe_rel = view_format("examples/%s", name), *exe = view_build_path(exe_rel);
    free(exe_rel);
    if (!exe) {
        fprintf(stderr, "%s is not built\n", name);
        return 0;
    }
    char *png = view_format("%s/%s.png", tmp, name), *cmd = view_format("%s %s %s", exe, png, args), *out = NULL;
    int rc = view_run(cmd, &out);
    if (rc != 0) fprintf(stderr, "$ %s\nexit %d:\n%s\n", cmd, rc, out ? out : "");
    int ok = rc == 0 && view_png_read(img, png) == 0;
    free(out);
    free(cmd);
    free(png);
    free(exe);
    return ok;
}

/* Quad from (0,0,3.2) at 45 degrees in 256 x 256: cells of the checker are 24.1 pixels wide
 * starting at pixel 31.4; the top-left cell (texture (0,0)) is the light colour (235), its
 * right neighbour the dark one (200, 90, 40). */
static void textured_quad(void) {
    view_png img;
    CHECK(run_example("example_textured_quad", "", &img));
    if (!img.rgba) return;
    CHECK(view_pixel_near(&img, 43, 43, 235, 235, 235, 2));
    CHECK(view_pixel_near(&img, 67, 43, 200, 90, 40, 2));
    CHECK(view_pixel_near(&img, 43, 67, 200, 90, 40, 2));
    CHECK(view_pixel_near(&img, 5, 5, 100, 149, 237, 0));
    view_png_free(&img);
}

/* Sphere from (0,0,3); the centre pixel sees N = V = (0,0,1). LightDirection (-0.5,-0.8,-0.6)
 * has length 1.1180, so L = (0.4472, 0.7155, 0.5367) and N.L = 0.5367; R.V = 0.5367 too and
 * 0.5367^32 is 2e-9. colour = ambient * diffuse + diffuse * N.L:
 * r = 0.9 (0.08 + 0.5367) = 0.5550 -> 142, g = 0.72 (0.08 + 0.5367) = 0.4440 -> 113,
 * b = 0.45 (0.1 + 0.5367) = 0.2865 -> 73. */
static void phong(void) {
    view_png img;
    CHECK(run_example("example_phong", "", &img));
    if (!img.rgba) return;
    CHECK(view_pixel_near(&img, 128, 128, 142, 113, 73, 2));
    CHECK(view_pixel_near(&img, 2, 2, 0, 0, 0, 0));
    /* L points up, right and forward: near N = (0.3,0.3,0.9) (upper right on screen) N.L = 0.83,
     * near N = (-0.3,-0.3,0.9) (lower left) 0.13: red differs by about 0.9 * 0.7 * 255. */
    const unsigned char *ur = view_png_at(&img, 166, 90), *ll = view_png_at(&img, 90, 166);
    CHECK(ur[0] > ll[0] + 100);
    view_png_free(&img);
}

static int brightness(const view_png *img) {
    long sum = 0;
    for (int i = 0; i < img->width * img->height; i++) sum += img->rgba[i * 4] + img->rgba[i * 4 + 1] + img->rgba[i * 4 + 2];
    return (int)(sum / (img->width * img->height));
}

/* More lights, more light: 50 lights (each dimmer, 3/50) still outshine one. */
static void point_lights(void) {
    view_png one, many;
    CHECK(run_example("example_point_lights", "1 3", &one));
    CHECK(run_example("example_point_lights", "50 3", &many));
    if (one.rgba && many.rgba) {
        CHECK(brightness(&one) > 2); /* the background is (5, 5, 8): the one light shows */
        CHECK(brightness(&many) > brightness(&one));
    }
    view_png_free(&one);
    view_png_free(&many);
    char *out = NULL, *exe = view_build_path("examples/example_point_lights");
    if (exe) {
        char *cmd = view_format("%s %s/x.png 51", exe, tmp);
        CHECK_INT(view_run(cmd, &out), 2);
        CHECK_CONTAINS(out, "LIGHTS must be 1..50 and FRAMES at least 1");
        free(cmd);
    }
    free(out);
    free(exe);
}

/* The spot points straight down at the floor's centre: lit there (N.L = 1), only ambient
 * (0.05 of the checker) at the sides, outside the 0.25 radian cone. */
static void spot(void) {
    view_png img;
    CHECK(run_example("example_spot", "", &img));
    if (!img.rgba) return;
    const unsigned char *centre = view_png_at(&img, 128, 128);
    CHECK(centre[0] > 120);
    /* Pixel 10 of row 128 looks 20.9 degrees left of the centre ray (3.28 long): the floor at
     * x = -1.25, outside the cone's 4 tan(0.25) = 1.02 radius: ambient only, 0.05 * texel. */
    const unsigned char *side = view_png_at(&img, 10, 128), *other = view_png_at(&img, 246, 128);
    CHECK(side[0] <= 12 && side[1] <= 12 && side[2] <= 17); /* AmbientColor (0.05, 0.05, 0.07) */
    CHECK(other[0] <= 12 && other[1] <= 12 && other[2] <= 17);
    CHECK(side[0] + side[1] + side[2] > 0); /* but the floor is there, not the black clear */
    view_png_free(&img);
}

/* Material technique, sphere from (0,0,3): pass 1 gives the ambient 0.07; pass 2 adds the
 * directional light travelling along -z (N.L = 1 at the centre) times colorMaterialDifuso
 * (0.24, 0.34, 0.39); the point light at (-2,1,1) grazes the centre (N.L = 0).
 * (0.31, 0.41, 0.46) -> (79, 105, 117). */
static void multilights(void) {
    if (!test_seed_dir()) {
        printf("  (no seed corpus: example_multilights not run)\n");
        return;
    }
    view_png img;
    CHECK(run_example("example_multilights", "", &img));
    if (!img.rgba) return;
    CHECK(view_pixel_near(&img, 128, 128, 79, 105, 117, 2));
    view_png_free(&img);
}

/* Left half Textured, right half Material of fx/ambient.fx: the right teapot is exactly
 * AmbientColor (0.35, 0.35, 0.4) -> (89, 89, 102); the left one is that times the checker. */
static void techniques(void) {
    view_png img;
    CHECK(run_example("example_techniques", "", &img));
    if (!img.rgba) return;
    CHECK_INT(img.width, 512);
    CHECK(view_pixel_near(&img, 384, 140, 89, 89, 102, 1));
    const unsigned char *l = view_png_at(&img, 128, 140);
    CHECK(!(l[0] == 89 && l[1] == 89 && l[2] == 102));
    CHECK(l[0] <= 90 && l[2] <= 103); /* ambient times a texel, never more */
    CHECK(view_pixel_near(&img, 256, 5, 100, 149, 237, 0));
    view_png_free(&img);
}

/* example_window without a window: same scene as hfxview's shading_models test, 400 x 400.
 * Phong: (80, 0, 0); BlinnPhong: (131, 50, 50) (see test_hfxview_render.c). */
static void window_example_headless(void) {
    view_png img;
    CHECK(run_example("example_window", "--headless --technique Phong", &img));
    if (img.rgba) CHECK(view_pixel_near(&img, 200, 200, 80, 0, 0, 2));
    view_png_free(&img);
    CHECK(run_example("example_window", "--headless --frames 3 --technique BlinnPhong", &img));
    if (img.rgba) CHECK(view_pixel_near(&img, 200, 200, 131, 50, 50, 2));
    view_png_free(&img);
}

int main(void) {
    char *any = view_build_path("examples/example_phong");
    if (!any) test_skip("the examples are not built (they need OSMesa, libpng and stb)");
    free(any);
    tmp = test_temp_dir();
    RUN(textured_quad);
    RUN(phong);
    RUN(point_lights);
    RUN(spot);
    RUN(multilights);
    RUN(techniques);
    RUN(window_example_headless);
    char *rm = view_format("rm -rf %s", tmp);
    view_run(rm, NULL);
    free(rm);
    free(tmp);
    return test_summary();
}
