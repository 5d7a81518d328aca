/* hfxview --watch, headless: hfxview runs in the background, the test rewrites the effect's
 * include under it, and hfxview writes the PNG again after each reload ("wrote ... (N)" on
 * stderr when a PNG is complete). The colour comes from the include and is checked by hand; a
 * broken edit prints its located error, "did not reload", and leaves the last good PNG alone.
 * The vertex shader scales the sphere a hundredfold so it covers every pixel whatever the
 * camera, and the pass culls nothing: the whole image is the pixel shader's colour. */
#include <signal.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <time.h>
#include <unistd.h>

#include "files.h"
#include "test.h"
#include "view_support.h"

static char *exe, *tmp;

static const char main_fx[] =
    "#include \"color.fxh\"\n"
    "float4 VS(float3 p : POSITION0) : POSITION0 { return float4(p.xy * 100, 0.5, 1); }\n"
    "float4 PS() : COLOR0 { return float4(BASE, 1); }\n"
    "technique T { pass P { CullMode = None; ZEnable = false;\n"
    "    VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

/* Written beside and renamed over, as editors save, so hfxview never reads half a file. */
static void write_file(const char *name, const char *text) {
    char *p = view_format("%s/%s", tmp, name), *part = view_format("%s/%s.part", tmp, name);
    FILE *f = fopen(part, "w");
    CHECK(f != NULL);
    if (f) fputs(text, f), fclose(f);
    CHECK_INT(rename(part, p), 0);
    free(p), free(part);
}

/* Waits (up to 30 s) for `needle` in hfxview's log; 1 when it came. */
static int wait_for(const char *needle) {
    char *log = view_format("%s/log.txt", tmp);
    int found = 0;
    for (int i = 0; i < 600 && !found; i++) {
        char *text = test_read_file(log, NULL);
        found = text && strstr(text, needle);
        free(text);
        if (!found) nanosleep(&(struct timespec){0, 50 * 1000 * 1000}, NULL);
    }
    if (!found) fprintf(stderr, "hfxview never printed \"%s\"\n", needle);
    free(log);
    return found;
}

static void check_png(int r, int g, int b) {
    char *png = view_format("%s/out.png", tmp);
    view_png img;
    CHECK_INT(view_png_read(&img, png), 0);
    if (img.rgba) {
        CHECK(view_pixel_near(&img, 8, 8, r, g, b, 1));
        CHECK(view_pixel_near(&img, 0, 15, r, g, b, 1));
    }
    view_png_free(&img);
    free(png);
}

/* The edits follow each other faster than a coarse file clock may tick: each version differs
 * in size from the one before, which the check also compares. */
static void reloads_on_edits(void) {
    write_file("main.fx", main_fx);
    write_file("color.fxh", "#define BASE float3(0.2, 0.4, 0.8)\n");
    char *cmd = view_format("cd %s && exec %s main.fx -o out.png --size 16x16 --mesh sphere --watch 2>log.txt "
                            ">/dev/null & echo $!", tmp, exe);
    char *out = NULL;
    CHECK_INT(view_run(cmd, &out), 0);
    pid_t pid = out ? (pid_t)atoi(out) : 0;
    CHECK(pid > 0);
    if (pid > 0 && wait_for("wrote out.png (1)")) check_png(51, 102, 204); /* (0.2, 0.4, 0.8) * 255 */

    write_file("color.fxh", "#define BASE float3(0.6, 0.2, 0)\n");
    if (pid > 0 && wait_for("wrote out.png (2)")) check_png(153, 51, 0); /* (0.6, 0.2, 0) * 255 */

    write_file("color.fxh", "#define BASE float3(1, 1, \n"); /* the macro's ')' is gone */
    if (pid > 0 && wait_for("did not reload")) {
        char *log = view_format("%s/log.txt", tmp), *text = test_read_file(log, NULL);
        CHECK_CONTAINS(text, "main.fx(3,");   /* where BASE is used */
        CHECK_CONTAINS(text, ": error X");
        free(text), free(log);
        check_png(153, 51, 0); /* the last good picture */
    }
    write_file("color.fxh", "#define BASE float3(0.2, 1.0, 0.4)\n");
    if (pid > 0 && wait_for("wrote out.png (3)")) check_png(51, 255, 102);
    if (pid > 0) kill(pid, SIGTERM);
    free(out), free(cmd);
}

int main(void) {
    exe = view_build_path("tools/hfxview/hfxview");
    if (!exe) test_skip("hfxview is not built (it needs OSMesa, libpng and stb)");
    tmp = test_temp_dir();
    RUN(reloads_on_edits);
    test_remove_dir(tmp);
    free(tmp), free(exe);
    return test_summary();
}
