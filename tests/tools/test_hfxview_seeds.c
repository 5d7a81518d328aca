/* hfxview on the seed corpus: every file but multilights.fx renders lit with the automatic
 * parameter values, fxcomposer_empty.fx is a white silhouette on the background, and
 * multilights.fx fails with the compiler's located error and exit status 1. */
#include "test.h"

#include "files.h"
#include "view_support.h"

static char *hfxview, *tmp;

static int hv(char **out, const char *args) {
    char *cmd = view_format("%s %s", hfxview, args);
    int rc = view_run(cmd, out);
    free(cmd);
    return rc;
}

static int render(const char *seed, const char *args, const char *png, view_png *img) {
    char *fx = test_seed_path(seed), *path = view_format("%s/%s", tmp, png);
    char *a = view_format("%s -o %s --size 128x128 %s", fx, path, args), *out = NULL;
    int rc = hv(&out, a);
    if (rc != 0) fprintf(stderr, "hfxview %s exited %d:\n%s\n", a, rc, out ? out : "");
    int ok = rc == 0 && view_png_read(img, path) == 0;
    free(out);
    free(a);
    free(path);
    free(fx);
    return ok;
}

static void fxcomposer_empty_is_a_white_silhouette(void) {
    view_png img;
    if (!render("fxcomposer_empty.fx", "", "empty.png", &img)) {
        CHECK(0);
        return;
    }
    CHECK(view_pixel_near(&img, 64, 64, 255, 255, 255, 0));
    CHECK(view_pixel_near(&img, 0, 0, 100, 149, 237, 0));
    CHECK(view_pixel_near(&img, 127, 127, 100, 149, 237, 0));
    view_png_free(&img);
    if (render("fxcomposer_empty.fx", "--background 0.5,0,0", "empty2.png", &img)) {
        CHECK(view_pixel_near(&img, 64, 64, 255, 255, 255, 0));
        CHECK(view_pixel_near(&img, 0, 0, 128, 0, 0, 1));
    } else {
        CHECK(0);
    }
    view_png_free(&img);
}

static void multilights_fails_with_its_error(void) {
    char *fx = test_seed_path("multilights.fx"), *out = NULL;
    char *args = view_format("%s -o %s/ml.png", fx, tmp), *want = view_format("%s(204,20): error X3013: 'Phong': no matching 4 parameter function", fx);
    CHECK_INT(hv(&out, args), 1);
    CHECK_CONTAINS(out, want);
    free(out);
    free(args);
    free(want);
    free(fx);
}

/* ambient.fx: colorMaterialAmbiental = 0.05 everywhere on the mesh: 12.75 -> 13. */
static void ambient_keeps_its_initializer(void) {
    view_png img;
    if (render("ambient.fx", "", "ambient.png", &img)) CHECK(view_pixel_near(&img, 64, 64, 13, 13, 13, 1));
    else CHECK(0);
    view_png_free(&img);
}

/* ambient_textured.fx: Material is the ambient colour (0.05 -> 13); Texturizado multiplies it
 * by the checker (235 or 90/255), never brighter. */
static void ambient_textured_techniques(void) {
    view_png img;
    if (render("ambient_textured.fx", "--technique Material", "at_m.png", &img))
        CHECK(view_pixel_near(&img, 64, 64, 13, 13, 13, 1));
    else
        CHECK(0);
    view_png_free(&img);
    if (render("ambient_textured.fx", "--technique Texturizado", "at_t.png", &img)) {
        const unsigned char *p = view_png_at(&img, 64, 64);
        CHECK(p[0] >= 4 && p[0] <= 13 && p[2] <= 13);
    } else {
        CHECK(0);
    }
    view_png_free(&img);
}

/* tutorial0.fx on the quad: the default checker's light top-left cell, dark neighbours
 * (geometry as in test_hfxview_render.c, at half the size: cells 12.07 pixels from 15.7). */
static void tutorial0_checker_orientation(void) {
    view_png img;
    if (!render("tutorial0.fx", "--mesh quad --camera eye=0,0,3.2,at=0,0,0", "tut0.png", &img)) {
        CHECK(0);
        return;
    }
    CHECK(view_pixel_near(&img, 22, 22, 235, 235, 235, 3));
    CHECK(view_pixel_near(&img, 34, 22, 90, 90, 100, 3));
    CHECK(view_pixel_near(&img, 22, 34, 90, 90, 100, 3));
    view_png_free(&img);
}

/* multilights_repaired.fx, Material: pass 0 alone is colorMaterialAmbiental (0.07 -> 18);
 * adding pass 1 with --blend-passes add brings the automatic lights in. */
static void multilights_repaired_passes(void) {
    view_png first, all;
    int ok = render("multilights_repaired.fx", "--technique Material --pass 0", "mlr0.png", &first) &&
             render("multilights_repaired.fx", "--technique Material --blend-passes add --set numLuces=2", "mlr.png", &all);
    CHECK(ok);
    if (ok) {
        CHECK(view_pixel_near(&first, 64, 64, 18, 18, 18, 1));
        const unsigned char *a = view_png_at(&first, 64, 64), *b = view_png_at(&all, 64, 64);
        CHECK(b[0] + b[1] + b[2] > a[0] + a[1] + a[2] + 30);
    }
    view_png_free(&first);
    view_png_free(&all);
}

/* Every other seed, every technique, renders and lights the middle of the mesh. */
static void every_seed_renders_lit(void) {
    static const struct { const char *file, *technique, *extra; } seeds[] = {
        {"tutorial0.fx", NULL, ""}, {"phong.fx", NULL, ""}, {"pointlights.fx", NULL, ""},
        {"directional.fx", "Texturizado", ""}, {"directional.fx", "Material", ""},
        {"directional_specular.fx", "Material", "--set modIluEsp=true"},
        {"point.fx", "Material", "--set atenuado=true"}, {"point_specular.fx", "Material", ""},
        {"spot.fx", "Material", ""}, {"spot_specular.fx", "Texturizado", ""},
        {"multilights_repaired.fx", "Texturizado", "--blend-passes add"},
    };
    for (size_t i = 0; i < sizeof seeds / sizeof seeds[0]; i++) {
        char *args = view_format("%s%s %s", seeds[i].technique ? "--technique " : "",
                                 seeds[i].technique ? seeds[i].technique : "", seeds[i].extra);
        view_png img;
        if (!render(seeds[i].file, args, "seed.png", &img)) {
            fprintf(stderr, "  %s %s did not render\n", seeds[i].file, args);
            CHECK(0);
        } else {
            /* Lit: the mesh's middle is neither the background nor black. */
            const unsigned char *p = view_png_at(&img, 64, 64);
            int bg = p[0] == 100 && p[1] == 149 && p[2] == 237, lit = p[0] + p[1] + p[2] > 60;
            if (bg || !lit) fprintf(stderr, "  %s %s: centre (%d, %d, %d)\n", seeds[i].file, args, p[0], p[1], p[2]);
            CHECK(!bg && lit);
        }
        view_png_free(&img);
        free(args);
    }
}

int main(void) {
    test_require_seeds();
    hfxview = view_build_path("tools/hfxview/hfxview");
    if (!hfxview) test_skip("hfxview is not built (it needs OSMesa, libpng and stb)");
    tmp = test_temp_dir();
    RUN(fxcomposer_empty_is_a_white_silhouette);
    RUN(multilights_fails_with_its_error);
    RUN(ambient_keeps_its_initializer);
    RUN(ambient_textured_techniques);
    RUN(tutorial0_checker_orientation);
    RUN(multilights_repaired_passes);
    RUN(every_seed_renders_lit);
    test_remove_dir(tmp);
    free(tmp);
    free(hfxview);
    return test_summary();
}
