/* The GLSL 110 and GLSL ES 300 targets, run. hfxc emits them, and until now nothing drew with
 * them. The scenes of tests/runtime_only/support (five seeds, one of them two passes with
 * additive blending) are rendered from the .fx with the GLSL 330 target on an OSMesa 3.3 core
 * context, then
 *   - with the GLSL 110 target on an OSMesa compatibility-profile context (#version 110 is a
 *     compatibility-profile language: attribute / varying / gl_FragData, locations bound by the
 *     runtime with glBindAttribLocation before the link);
 *   - with the GLSL ES 300 target on the core context, which llvmpipe allows through
 *     GL_ARB_ES3_compatibility (#version 300 es on desktop GL);
 * and every pixel must be within 1/255 of the GLSL 330 picture (llvmpipe rasterises the same
 * triangles in both profiles; the shaders do the same float32 arithmetic in other words). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "hfx/hfxc.h"
#include "rto_scenes.h"
#include "test.h"

#define PIXELS (RTO_SIZE * RTO_SIZE)

static unsigned char *g_ref[16]; /* the GLSL 330 pictures, per scene */

/* Loads scene i's seed .fx for the target and renders it; the pixels in out. 0 on success. */
static int render(rto_ctx *c, int i, hfx_target target, unsigned char *out) {
    char *path = test_seed_path(rto_scene_file(i)), *errors = NULL, why[512] = "";
    hfx_load_options opt;
    memset(&opt, 0, sizeof opt);
    opt.target = target;
    hfx_effect *fx = hfx_effect_load(rto_device(c), path, &opt, &errors);
    if (!fx) fprintf(stderr, "  %s (target %d): %s\n", rto_scene_file(i), (int)target, errors ? errors : "(no message)");
    CHECK(fx != NULL);
    int drawn = fx ? rto_scene_render(c, fx, i, why, sizeof why) : 0;
    if (why[0]) fprintf(stderr, "  %s (target %d): %s\n", rto_scene_name(i), (int)target, why);
    CHECK_INT(drawn, rto_scene_passes(i));
    rto_read(c, out);
    if (fx) hfx_effect_destroy(fx);
    hfx_free(errors);
    free(path);
    return fx && drawn == rto_scene_passes(i) ? 0 : -1;
}

/* Largest channel difference from the GLSL 330 picture, and how many pixels differ at all. */
static int compare(int i, const unsigned char *px, const char *what, rto_ctx *c, int *differing) {
    int max = 0;
    *differing = 0;
    for (int p = 0; p < PIXELS; p++) {
        int d = 0;
        for (int k = 0; k < 4; k++) {
            int dk = abs(px[4 * p + k] - g_ref[i][4 * p + k]);
            if (dk > d) d = dk;
        }
        if (d) (*differing)++;
        if (d > 1 && max <= 1)
            fprintf(stderr, "  %s %s: pixel (%d, %d) is %d %d %d %d, GLSL 330 gave %d %d %d %d\n", rto_scene_name(i),
                    what, p % RTO_SIZE, p / RTO_SIZE, px[4 * p], px[4 * p + 1], px[4 * p + 2], px[4 * p + 3],
                    g_ref[i][4 * p], g_ref[i][4 * p + 1], g_ref[i][4 * p + 2], g_ref[i][4 * p + 3]);
        if (d > max) max = d;
    }
    printf("  %-22s %s: %d pixels differ from GLSL 330, max %d/255\n", rto_scene_name(i), what, *differing, max);
    if (max > 1) {
        const char *dir = getenv("HFX_BUILD_DIR");
        char png[1024];
        snprintf(png, sizeof png, "%s/%s.%s.png", dir ? dir : "/tmp", rto_scene_name(i), what);
        if (rto_write_png(c, png) == 0) fprintf(stderr, "  picture in %s\n", png);
    }
    return max;
}

/* A picture with something in it: the comparison must not pass on two empty images. */
static int covered(const unsigned char *px) {
    int n = 0;
    for (int p = 0; p < PIXELS; p++)
        if (memcmp(px + 4 * p, px, 4) != 0) n++;
    return n;
}

static void glsl330_references(void) {
    rto_ctx *c = rto_ctx_create(RTO_CORE_33);
    CHECK(c != NULL);
    if (!c) return;
    printf("  core context: GL %s\n", rto_gl_version(c));
    for (int i = 0; i < rto_scene_count(); i++) {
        g_ref[i] = calloc(PIXELS, 4);
        CHECK_INT(render(c, i, HFX_TARGET_GLSL330, g_ref[i]), 0);
        CHECK(covered(g_ref[i]) > PIXELS / 10);
    }
    rto_ctx_destroy(c);
}

/* The GLSL 110 code hfxc writes really is GLSL 110 (so the renders below ran it). */
static void glsl110_code_is_glsl110(void) {
    char *path = test_seed_path("multilights_repaired.fx");
    hfxc_options co;
    memset(&co, 0, sizeof co);
    co.targets = 1u << HFX_TARGET_GLSL110;
    hfxc_result *r = hfxc_compile_file(path, &co);
    const hfx_fx_effect *fx = r ? hfxc_result_effect(r) : NULL;
    CHECK(fx != NULL);
    if (fx) {
        CHECK_INT(fx->targets, 1u << HFX_TARGET_GLSL110);
        CHECK(fx->program_count >= 2);
        for (uint32_t p = 0; p < fx->program_count; p++) {
            const hfx_fx_code *vs = &fx->programs[p].code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL110];
            const hfx_fx_code *fs = &fx->programs[p].code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL110];
            CHECK(vs->data && strncmp(vs->data, "#version 110", 12) == 0);
            CHECK(fs->data && strncmp(fs->data, "#version 110", 12) == 0);
            CHECK_CONTAINS(vs->data, "attribute ");
            CHECK(fx->programs[p].code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data == NULL);
        }
    }
    hfxc_result_free(r);
    free(path);
}

static void glsl110_on_a_compatibility_context(void) {
    rto_ctx *c = rto_ctx_create(RTO_COMPAT);
    CHECK(c != NULL);
    if (!c) return;
    printf("  compatibility context: GL %s\n", rto_gl_version(c));
    CHECK_CONTAINS(rto_gl_version(c), "Compatibility");
    unsigned char *px = calloc(PIXELS, 4);
    for (int i = 0; i < rto_scene_count(); i++) {
        if (!g_ref[i] || render(c, i, HFX_TARGET_GLSL110, px) != 0) {
            CHECK(0);
            continue;
        }
        int differing;
        CHECK(compare(i, px, "GLSL 110", c, &differing) <= 1);
    }
    free(px);
    rto_ctx_destroy(c);
}

static void es300_on_the_core_context(void) {
    rto_ctx *c = rto_ctx_create(RTO_CORE_33);
    CHECK(c != NULL);
    if (!c) return;
    int es3 = rto_has_extension(c, "GL_ARB_ES3_compatibility");
    printf("  GL_ARB_ES3_compatibility: %s\n", es3 ? "yes" : "no");
    if (!es3) {
        printf("  this GL cannot compile #version 300 es on desktop: ES 300 not run\n");
        rto_ctx_destroy(c);
        return;
    }
    unsigned char *px = calloc(PIXELS, 4);
    for (int i = 0; i < rto_scene_count(); i++) {
        if (!g_ref[i] || render(c, i, HFX_TARGET_GLSLES300, px) != 0) {
            CHECK(0);
            continue;
        }
        int differing;
        CHECK(compare(i, px, "GLSL ES 300", c, &differing) <= 1);
    }
    free(px);
    rto_ctx_destroy(c);
}

int main(void) {
    test_require_seeds();
    RUN(glsl330_references);
    RUN(glsl110_code_is_glsl110);
    RUN(glsl110_on_a_compatibility_context);
    RUN(es300_on_the_core_context);
    for (int i = 0; i < 16; i++) free(g_ref[i]);
    return test_summary();
}
