/* The GLFW example in a real window, on a virtual X server (xvfb-run): 5 frames of the
 * BlinnPhong technique, the last one saved from the window's back buffer before the swap.
 * The centre pixel is the hand-computed (131, 50, 50) of test_examples.c. Skipped where
 * Xvfb or GLFW is missing. */
#include "test.h"

#include "files.h"
#include "view_support.h"

static char *exe;

static void window_screenshot(void) {
    char *tmp = test_temp_dir(), *png = view_format("%s/window.png", tmp), *out = NULL;
    /* The X server's GL driver (swrast via GLX) leaks on unload, in frames LeakSanitizer
     * cannot even name; the headless run in test_examples checks this program's own leaks. */
    char *cmd = view_format("ASAN_OPTIONS=\"$ASAN_OPTIONS:detect_leaks=0\" xvfb-run -a -s '-screen 0 640x480x24' "
                            "%s %s --frames 5 --technique BlinnPhong", exe, png);
    int rc = view_run(cmd, &out);
    if (rc != 0) fprintf(stderr, "$ %s\nexit %d:\n%s\n", cmd, rc, out ? out : "");
    CHECK_INT(rc, 0);
    if (out && strstr(out, "headless")) test_skip("GLFW could not open a window on Xvfb; example_window fell back to headless");
    CHECK_CONTAINS(out, "window, technique BlinnPhong");
    view_png img;
    CHECK_INT(view_png_read(&img, png), 0);
    if (img.rgba) {
        CHECK_INT(img.width, 400);
        CHECK(view_pixel_near(&img, 200, 200, 131, 50, 50, 2));
        CHECK(view_pixel_near(&img, 3, 3, 26, 26, 31, 1)); /* the clear colour (0.1, 0.1, 0.12) */
    }
    view_png_free(&img);
    char *rm = view_format("rm -rf %s", tmp);
    view_run(rm, NULL);
    free(rm);
    free(out);
    free(cmd);
    free(png);
    free(tmp);
}

int main(void) {
    exe = view_build_path("examples/example_window");
    if (!exe) test_skip("example_window is not built (it needs OSMesa, libpng and stb)");
    if (view_run("command -v xvfb-run && command -v Xvfb", NULL) != 0)
        test_skip("xvfb-run / Xvfb is not installed (Debian: apt-get install xvfb)");
    RUN(window_screenshot);
    free(exe);
    return test_summary();
}
