/* hfxview --vulkan against hfxview on GL: every seed effect (but multilights.fx, which does not
 * compile) and every fx/ effect, rendered at 128 x 128 on both back ends, must agree within
 * 2/255 on at least 99% of the pixels; the share is printed for each. Each picture takes one
 * pipeline per pass, and the validation layer says nothing (hfxview prints what it says); a
 * message it does send makes hfxview exit 1. */
#include <dirent.h>

#include "files.h"
#include "test.h"
#include "view_support.h"

static char *hfxview, *tmp;
static int pipelines, pictures; /* made while the gallery renders on Vulkan */

static int render(const char *fx, const char *flags, const char *png, view_png *img) {
    char *path = view_format("%s/%s", tmp, png), *out = NULL;
    char *cmd = view_format("HFXVIEW_PIPELINES=1 %s %s -o %s --size 128x128 %s", hfxview, fx, path, flags);
    int rc = view_run(cmd, &out);
    if (rc != 0) fprintf(stderr, "%s exited %d:\n%s\n", cmd, rc, out ? out : "");
    if (out && strstr(out, "validation")) fprintf(stderr, "%s:\n%s\n", cmd, out);
    const char *made = out ? strstr(out, "hfxview: ") : NULL;
    int n = 0;
    if (made && sscanf(made, "hfxview: %d pipelines", &n) == 1) pipelines += n, pictures++;
    int ok = rc == 0 && view_png_read(img, path) == 0;
    if (ok && out && strstr(out, "validation")) view_png_free(img), ok = 0;
    free(out);
    free(cmd);
    free(path);
    return ok;
}

/* The share of pixels whose every channel is within 2/255. */
static double share_within_2(const view_png *a, const view_png *b) {
    if (a->width != b->width || a->height != b->height) return 0;
    size_t n = (size_t)a->width * (size_t)a->height, close = 0;
    for (size_t i = 0; i < n; i++) {
        int worst = 0;
        for (int c = 0; c < 4; c++) {
            int d = abs(a->rgba[4 * i + c] - b->rgba[4 * i + c]);
            if (d > worst) worst = d;
        }
        close += worst <= 2;
    }
    return 100.0 * (double)close / (double)n;
}

static void compare(const char *fx, const char *name) {
    view_png gl, vk;
    char *gl_png = view_format("%s.gl.png", name), *vk_png = view_format("%s.vk.png", name);
    int have_gl = render(fx, "", gl_png, &gl), ok = have_gl && render(fx, "--vulkan", vk_png, &vk);
    CHECK(ok);
    if (have_gl && !ok) view_png_free(&gl);
    if (ok) {
        double share = share_within_2(&gl, &vk);
        printf("gl-vs-vulkan: %-28s %6.2f%% of pixels within 2/255\n", name, share);
        CHECK(share >= 99.0);
        view_png_free(&vk);
    }
    if (ok) view_png_free(&gl);
    free(gl_png);
    free(vk_png);
}

static void seeds_match(void) {
    static const char *const seeds[] = {"ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx",
                                        "fxcomposer_empty.fx", "multilights_repaired.fx", "phong.fx", "point.fx",
                                        "point_specular.fx", "pointlights.fx", "spot.fx", "spot_specular.fx",
                                        "tutorial0.fx"};
    for (size_t i = 0; i < sizeof seeds / sizeof *seeds; i++) {
        char *path = test_seed_path(seeds[i]);
        if (path) compare(path, seeds[i]);
        free(path);
    }
}

static void fx_folder_matches(void) {
    char *dir = view_format("%s/fx", HFX_SOURCE_DIR);
    DIR *d = opendir(dir);
    CHECK(d != NULL);
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n < 4 || strcmp(e->d_name + n - 3, ".fx") != 0) continue;
        char *path = view_format("%s/%s", dir, e->d_name);
        compare(path, e->d_name);
        free(path);
    }
    if (d) closedir(d);
    free(dir);
}

/* A validation-layer message fails hfxview (exit status 1, as a failed effect), not only the
 * tests: the layer's best-practices checks, switched on from the environment as vkconfig does
 * (VK_LAYER_ENABLES), warn on every run (VK_EXT_debug_utils is a debugging extension), so
 * hfxview itself is unchanged. The same run without them exits 0. Without the layer installed
 * the variable does nothing and there is nothing to check. */
static void validation_message_fails(void) {
    char *png = view_format("%s/layer.png", tmp), *out = NULL, *clean = NULL;
    char *args = view_format("--vulkan %s/fx/ambient.fx -o %s --size 32x32", HFX_SOURCE_DIR, png);
    char *warned = view_format("VK_LAYER_ENABLES=VK_VALIDATION_FEATURE_ENABLE_BEST_PRACTICES_EXT %s %s", hfxview, args);
    char *plain = view_format("%s %s", hfxview, args);
    int rc = view_run(warned, &out), clean_rc = view_run(plain, &clean);
    CHECK(clean_rc == 0 && clean && !strstr(clean, "vulkan validation:"));
    if (out && strstr(out, "vulkan validation:")) {
        CHECK(rc == 1);
        CHECK(strstr(out, "hfxview: error: the Vulkan validation layer sent ") != NULL);
        printf("validation: a layer message makes hfxview exit %d\n", rc);
    } else {
        printf("validation: not checked (no validation layer: hfxview exited %d without a message)\n", rc);
    }
    free(out), free(clean), free(warned), free(plain), free(args), free(png);
}

int main(void) {
    test_require_seeds();
    hfxview = view_build_path("tools/hfxview/hfxview");
    if (!hfxview) test_skip("hfxview is not built (it needs OSMesa, libpng and stb)");
    char *out = NULL, *probe = view_format("%s --vulkan --list %s/fx/ambient.fx", hfxview, HFX_SOURCE_DIR);
    int rc = view_run(probe, &out);
    free(probe);
    if (rc != 0 && out && strstr(out, "without Vulkan")) test_skip("hfxview was built without Vulkan");
    if (rc != 0 && out && strstr(out, "no Vulkan device")) test_skip(out);
    free(out);
    tmp = test_temp_dir();
    RUN(validation_message_fails);
    RUN(seeds_match);
    RUN(fx_folder_matches);
    printf("gl-vs-vulkan: %d pipelines made for %d Vulkan pictures\n", pipelines, pictures);
    test_remove_dir(tmp);
    free(tmp);
    free(hfxview);
    return test_summary();
}
