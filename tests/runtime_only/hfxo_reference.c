/* hfxo_reference: the reference pictures for runtime_only/test_hfxo_runtime. Linked with hfx
 * (runtime + compiler), it loads each scene's seed .fx directly, renders it with
 * rto_scene_render and writes the pixels as raw RGBA (RTO_SIZE x RTO_SIZE, top row first) to
 * <dir>/<scene>.rgba, plus a .png to look at. The runtime-only test, which cannot compile .fx,
 * compares its .hfxo renders with these bytes. A ctest fixture (FIXTURES_SETUP) runs it first.
 *
 * It is a test too: every scene must load, draw all its passes and show more than its clear
 * colour, so that an empty picture cannot make the comparison pass. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "files.h"
#include "rto_scenes.h"
#include "test.h"

static const char *g_dir;
static rto_ctx *g_ctx;

static char *path_in(const char *dir, const char *name, const char *ext) {
    size_t n = strlen(dir) + strlen(name) + strlen(ext) + 2;
    char *p = malloc(n);
    if (p) snprintf(p, n, "%s/%s%s", dir, name, ext);
    return p;
}

/* Pixels unlike the top-left one (which every scene leaves at its clear colour). */
static int covered(const unsigned char *px) {
    int n = 0;
    for (int i = 0; i < RTO_SIZE * RTO_SIZE; i++)
        if (memcmp(px + 4 * i, px, 4) != 0) n++;
    return n;
}

/* Distinct colours: a shaded scene has many, a flat one (fxcomposer_empty) two. */
static int distinct_colours(const unsigned char *px) {
    static unsigned char seen[1 << 15];
    memset(seen, 0, sizeof seen);
    int n = 0;
    for (int i = 0; i < RTO_SIZE * RTO_SIZE; i++) {
        unsigned key = (unsigned)(px[4 * i] >> 3) << 10 | (unsigned)(px[4 * i + 1] >> 3) << 5 | (px[4 * i + 2] >> 3);
        if (!seen[key]) seen[key] = 1, n++;
    }
    return n;
}

static void write_references(void) {
    unsigned char *px = malloc(RTO_SIZE * RTO_SIZE * 4);
    CHECK(px != NULL);
    if (!px) return;
    for (int i = 0; i < rto_scene_count(); i++) {
        char *rgba = path_in(g_dir, rto_scene_name(i), ".rgba"), *png = path_in(g_dir, rto_scene_name(i), ".png");
        remove(rgba); /* never leave a stale reference behind a failure */
        char *fx_path = test_seed_path(rto_scene_file(i)), *errors = NULL;
        hfx_effect *fx = hfx_effect_load(rto_device(g_ctx), fx_path, NULL, &errors);
        if (!fx) fprintf(stderr, "%s: %s\n", rto_scene_file(i), errors ? errors : "(no message)");
        CHECK(fx != NULL);
        char why[512] = "";
        int drawn = fx ? rto_scene_render(g_ctx, fx, i, why, sizeof why) : 0;
        if (why[0]) fprintf(stderr, "%s: %s\n", rto_scene_name(i), why);
        CHECK_INT(drawn, rto_scene_passes(i));
        rto_read(g_ctx, px);
        int cover = covered(px), colours = distinct_colours(px);
        printf("  %-22s %d passes, %d pixels drawn, %d colours\n", rto_scene_name(i), drawn, cover, colours);
        CHECK(cover > RTO_SIZE * RTO_SIZE / 10);
        CHECK(colours >= (strcmp(rto_scene_name(i), "fxcomposer_empty") == 0 ? 2 : 20));
        if (drawn == rto_scene_passes(i)) {
            FILE *f = fopen(rgba, "wb");
            CHECK(f != NULL);
            if (f) {
                CHECK_INT(fwrite(px, 1, RTO_SIZE * RTO_SIZE * 4, f), RTO_SIZE * RTO_SIZE * 4);
                CHECK_INT(fclose(f), 0);
            }
            rto_write_png(g_ctx, png);
        }
        if (fx) hfx_effect_destroy(fx);
        hfx_free(errors);
        free(fx_path);
        free(rgba);
        free(png);
    }
    free(px);
}

int main(int argc, char **argv) {
    if (argc != 2) {
        fprintf(stderr, "usage: %s OUTPUT_DIR\n", argv[0]);
        return 2;
    }
    test_require_seeds();
    g_dir = argv[1];
    if (mkdir(g_dir, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "cannot make %s\n", g_dir);
        return 1;
    }
    g_ctx = rto_ctx_create(RTO_CORE_33);
    if (!g_ctx) {
        fprintf(stderr, "no OSMesa GL 3.3 core context\n");
        return 1;
    }
    printf("GL %s; references in %s\n", rto_gl_version(g_ctx), g_dir);
    RUN(write_references);
    rto_ctx_destroy(g_ctx);
    return test_summary();
}
