/* The issue: "A .hfxo written by hfxc loads in the runtime with the compiler library not
 * linked, and renders the same pixels as loading the .fx."
 *
 * This program links hfx_runtime (runtime + compile_none.c), not hfx and not hfx_compiler
 * (tests/extra.cmake asserts its link libraries, and runtime_only/no_compiler_symbols checks the
 * executable with nm). It
 *   1. shows the compiler is absent: loading a .fx fails with compile_none.c's message, and no
 *      hfxc_* function is linked in (weak references stay NULL);
 *   2. runs the hfxc program ($HFX_BUILD_DIR/compiler/hfxc) to write the seeds' .hfxo files into
 *      a temporary folder;
 *   3. loads each .hfxo with hfx_effect_load, renders the scene of tests/runtime_only/support
 *      and compares every pixel with the picture runtime_only/hfxo_reference rendered from the
 *      .fx in a program linked with hfx (argv[1] is its folder; a ctest fixture runs it first).
 * Both programs hand the same GLSL 330 to the same GL (llvmpipe), so the pixels must be equal
 * byte for byte: no tolerance. */
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "files.h"
#include "rto_scenes.h"
#include "test.h"

extern char **environ;

/* hfx/hfxc.h's entry points, declared weak and without their header: in a program linked with
 * hfx they are defined (compile_fx.c calls them); here nothing may pull them in. */
struct hfxc_result;
extern struct hfxc_result *hfxc_compile_file(const char *path, const void *opt) __attribute__((weak));
extern struct hfxc_result *hfxc_compile_memory(const char *src, size_t size, const char *name, const void *opt)
    __attribute__((weak));

static const char *g_refs;
static char *g_tmp;
static rto_ctx *g_ctx;
static int g_compiled; /* hfxc wrote every .hfxo */

static char *join(const char *dir, const char *name, const char *ext) {
    size_t n = strlen(dir) + strlen(name) + strlen(ext) + 2;
    char *p = malloc(n);
    if (p) snprintf(p, n, "%s/%s%s", dir, name, ext);
    return p;
}

static char *base_name(const char *file) { /* "phong.fx" -> "phong" */
    char *b = strdup(file), *dot = strrchr(b, '.');
    if (dot) *dot = '\0';
    return b;
}

static void compiler_is_absent(void) {
    CHECK(hfxc_compile_file == NULL);
    CHECK(hfxc_compile_memory == NULL);
    char *path = test_seed_path("phong.fx"), *errors = NULL;
    hfx_effect *fx = hfx_effect_load(rto_device(g_ctx), path, NULL, &errors);
    CHECK(fx == NULL);
    CHECK_CONTAINS(errors, "phong.fx: this program links hfx_runtime, which loads compiled effects (.hfxo) only; "
                           "compile the .fx with hfxc or link hfx");
    CHECK_CONTAINS(errors, "or link hfx\n"); /* one message a line */
    CHECK_CONTAINS(hfx_device_last_error(rto_device(g_ctx)), "links hfx_runtime");
    printf("  loading phong.fx:\n%s", errors ? errors : "(null)\n");
    if (fx) hfx_effect_destroy(fx);
    hfx_free(errors);
    free(path);
    /* The same from memory: source text is not an .hfxo, and nothing here can compile it. */
    static const char src[] = "float4 main() : COLOR { return 1; } technique T { pass P { "
                              "PixelShader = compile ps_2_0 main(); } }";
    fx = hfx_effect_load_memory(rto_device(g_ctx), src, sizeof src - 1, "inline.fx", NULL, &errors);
    CHECK(fx == NULL);
    CHECK_CONTAINS(errors, "inline.fx: this program links hfx_runtime");
    if (fx) hfx_effect_destroy(fx);
    hfx_free(errors);
    /* An effect fxc compiled (fx_2_0's magic, then nothing that matters): the message names it. */
    static const unsigned char fxb[12] = {0x01, 0x09, 0xff, 0xfe, 4, 0, 0, 0, 0, 0, 0, 0};
    fx = hfx_effect_load_memory(rto_device(g_ctx), fxb, sizeof fxb, "stock.fxb", NULL, &errors);
    CHECK(fx == NULL);
    CHECK_CONTAINS(errors, "stock.fxb: an effect compiled by fxc (fx_2_0); this program links hfx_runtime, which loads "
                           ".hfxo files only: convert it with `hfxc -o X.hfxo X.fxb` or link hfx");
    if (fx) hfx_effect_destroy(fx);
    hfx_free(errors);
}

/* hfxc --quiet --no-warnings --target glsl330,glsles300 -o TMP/hfxo/ seeds... */
static void hfxc_writes_the_hfxo_files(void) {
    const char *build = getenv("HFX_BUILD_DIR");
    CHECK(build != NULL);
    if (!build) return;
    char *hfxc = join(build, "compiler", "/hfxc");
    CHECK(access(hfxc, X_OK) == 0);
    char *out = join(g_tmp, "hfxo", "/");
    int n = rto_scene_count();
    char **argv = calloc((size_t)n + 8, sizeof *argv);
    char **paths = calloc((size_t)n, sizeof *paths);
    int a = 0;
    argv[a++] = hfxc;
    argv[a++] = "--quiet";
    argv[a++] = "--no-warnings";
    argv[a++] = "--target";
    argv[a++] = "glsl330,glsles300";
    argv[a++] = "-o";
    argv[a++] = out;
    for (int i = 0; i < n; i++) argv[a++] = paths[i] = test_seed_path(rto_scene_file(i));
    argv[a] = NULL;
    pid_t pid;
    int status = -1;
    CHECK_INT(posix_spawn(&pid, hfxc, NULL, NULL, argv, environ), 0);
    CHECK(waitpid(pid, &status, 0) == pid);
    CHECK(WIFEXITED(status));
    CHECK_INT(WEXITSTATUS(status), 0);
    int all = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    for (int i = 0; i < n; i++) {
        char *name = base_name(rto_scene_file(i)), *dir = join(g_tmp, "hfxo", "");
        char *file = join(dir, name, ".hfxo");
        struct stat st;
        int ok = stat(file, &st) == 0 && st.st_size > 64;
        if (!ok) fprintf(stderr, "  %s was not written\n", file);
        CHECK(ok);
        all &= ok;
        free(name), free(dir), free(file);
    }
    g_compiled = all;
    for (int i = 0; i < n; i++) free(paths[i]);
    free(paths), free(argv), free(out), free(hfxc);
}

static unsigned char *read_reference(const char *scene) {
    char *path = join(g_refs, scene, ".rgba");
    size_t size = 0;
    unsigned char *px = (unsigned char *)test_read_file(path, &size);
    if (!px) fprintf(stderr, "  no reference %s (runtime_only/hfxo_reference writes it)\n", path);
    else if (size != (size_t)RTO_SIZE * RTO_SIZE * 4) {
        fprintf(stderr, "  %s has %zu bytes, expected %d\n", path, size, RTO_SIZE * RTO_SIZE * 4);
        free(px);
        px = NULL;
    }
    free(path);
    return px;
}

/* Renders scene i from its .hfxo with the target and compares with the .fx reference: the
 * number of pixels that differ, the largest channel difference in *max_diff. -1 on failure. */
static int render_and_compare(int i, hfx_target target, int *max_diff) {
    *max_diff = 0;
    char *name = base_name(rto_scene_file(i)), *dir = join(g_tmp, "hfxo", ""), *hfxo = join(dir, name, ".hfxo");
    hfx_load_options opt;
    memset(&opt, 0, sizeof opt);
    opt.target = target;
    char *errors = NULL, why[512] = "";
    hfx_effect *fx = hfx_effect_load(rto_device(g_ctx), hfxo, &opt, &errors);
    if (!fx) fprintf(stderr, "  %s: %s\n", hfxo, errors ? errors : "(no message)");
    CHECK(fx != NULL);
    int differing = -1;
    unsigned char *ref = read_reference(rto_scene_name(i)), *px = malloc(RTO_SIZE * RTO_SIZE * 4);
    CHECK(ref != NULL);
    if (fx && ref && px) {
        int drawn = rto_scene_render(g_ctx, fx, i, why, sizeof why);
        if (why[0]) fprintf(stderr, "  %s: %s\n", rto_scene_name(i), why);
        CHECK_INT(drawn, rto_scene_passes(i));
        rto_read(g_ctx, px);
        differing = 0;
        for (int p = 0; p < RTO_SIZE * RTO_SIZE; p++) {
            int d = 0;
            for (int k = 0; k < 4; k++) {
                int dk = abs(px[4 * p + k] - ref[4 * p + k]);
                if (dk > d) d = dk;
            }
            if (d) {
                if (differing < 3)
                    fprintf(stderr, "  %s: pixel (%d, %d) is %d %d %d %d, the .fx gave %d %d %d %d\n",
                            rto_scene_name(i), p % RTO_SIZE, p / RTO_SIZE, px[4 * p], px[4 * p + 1], px[4 * p + 2],
                            px[4 * p + 3], ref[4 * p], ref[4 * p + 1], ref[4 * p + 2], ref[4 * p + 3]);
                differing++;
                if (d > *max_diff) *max_diff = d;
            }
        }
        if (differing) {
            char *png = join(g_refs, rto_scene_name(i), target == HFX_TARGET_GLSL330 ? ".hfxo.png" : ".es300.png");
            rto_write_png(g_ctx, png);
            fprintf(stderr, "  %s: %d pixels differ (max %d/255); picture in %s\n", rto_scene_name(i), differing,
                    *max_diff, png);
            free(png);
        }
    }
    if (fx) hfx_effect_destroy(fx);
    hfx_free(errors);
    free(ref), free(px), free(name), free(dir), free(hfxo);
    return differing;
}

/* GLSL 330 from the .hfxo against GLSL 330 from the .fx: the same bytes. */
static void hfxo_renders_the_pixels_of_the_fx(void) {
    CHECK(g_compiled);
    if (!g_compiled) return;
    for (int i = 0; i < rto_scene_count(); i++) {
        int max_diff, differing = render_and_compare(i, HFX_TARGET_GLSL330, &max_diff);
        printf("  %-22s .hfxo vs .fx: %d of %d pixels differ\n", rto_scene_name(i), differing, RTO_SIZE * RTO_SIZE);
        CHECK_INT(differing, 0);
    }
}

/* The GLSL ES 300 code of the same .hfxo, on the desktop context (GL_ARB_ES3_compatibility):
 * a different shader text with the same arithmetic (highp is float32), so within 1/255. */
static void hfxo_es300_code_renders_the_same(void) {
    CHECK(g_compiled);
    if (!g_compiled) return;
    if (!rto_has_extension(g_ctx, "GL_ARB_ES3_compatibility")) {
        printf("  GL_ARB_ES3_compatibility absent: ES 300 not run\n");
        return;
    }
    for (int i = 0; i < rto_scene_count(); i++) {
        int max_diff, differing = render_and_compare(i, HFX_TARGET_GLSLES300, &max_diff);
        printf("  %-22s ES 300 .hfxo vs .fx (330): %d pixels differ, max %d/255\n", rto_scene_name(i), differing,
               max_diff);
        CHECK(differing >= 0);
        CHECK(max_diff <= 1);
    }
}

/* A .hfxo compiled without GLSL 110 asked for GLSL 110: refused with the reader's reason. */
static void missing_target_is_refused(void) {
    CHECK(g_compiled);
    if (!g_compiled) return;
    char *hfxo = join(g_tmp, "hfxo/phong", ".hfxo"), *errors = NULL;
    hfx_load_options opt;
    memset(&opt, 0, sizeof opt);
    opt.target = HFX_TARGET_GLSL110;
    hfx_effect *fx = hfx_effect_load(rto_device(g_ctx), hfxo, &opt, &errors);
    CHECK(fx == NULL);
    CHECK_CONTAINS(errors, "the effect carries no code for the requested shader target");
    if (fx) hfx_effect_destroy(fx);
    hfx_free(errors);
    free(hfxo);
}

static void remove_tree(const char *tmp) {
    for (int i = 0; i < rto_scene_count(); i++) {
        char *name = base_name(rto_scene_file(i)), *dir = join(tmp, "hfxo", ""), *f = join(dir, name, ".hfxo");
        remove(f);
        free(name), free(dir), free(f);
    }
    char *dir = join(tmp, "hfxo", "");
    rmdir(dir);
    free(dir);
    rmdir(tmp);
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s REFERENCE_DIR\n", argv[0]);
        return 2;
    }
    test_require_seeds();
    g_refs = argv[1];
    g_tmp = test_temp_dir();
    if (!g_tmp) {
        fprintf(stderr, "no temporary folder\n");
        return 1;
    }
    g_ctx = rto_ctx_create(RTO_CORE_33);
    if (!g_ctx) {
        fprintf(stderr, "no OSMesa GL 3.3 core context\n");
        return 1;
    }
    printf("GL %s\n", rto_gl_version(g_ctx));
    RUN(compiler_is_absent);
    RUN(hfxc_writes_the_hfxo_files);
    RUN(hfxo_renders_the_pixels_of_the_fx);
    RUN(hfxo_es300_code_renders_the_same);
    RUN(missing_target_is_refused);
    rto_ctx_destroy(g_ctx);
    remove_tree(g_tmp);
    free(g_tmp);
    return test_summary();
}
