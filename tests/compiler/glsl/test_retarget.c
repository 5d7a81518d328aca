/* test_retarget.c: codegen prints a stage once for GLSL 330 and makes the ES 300 text by
 * swapping the header (hfx_glsl_retarget), which is right only while the printer decides nothing
 * else on the target. This holds it: every program of the project's effects (and of the seeds,
 * when present) compiled for ES 300 alone, so printed directly, equals the GLSL 330 text of a
 * compile for 330 alone with the ES header in place of the 330 one; and the texts of a compile
 * for both are the same again. Also hfx_glsl_retarget itself on exact headers. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "glsl/glsl.h"
#include "hfx/hfxc.h"
#include "test.h"

static const char *const own[] = {
    "ambient.fx", "basic_lighting.fx", "directional.fx", "multipass.fx", "point.fx",
    "point_lights.fx", "sas_blinn.fx", "shading_models.fx", "spot.fx", "textured.fx",
};
static const char *const seeds[] = {
    "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx", "fxcomposer_empty.fx",
    "multilights_repaired.fx", "phong.fx", "point.fx", "point_specular.fx", "pointlights.fx", "spot.fx",
    "spot_specular.fx", "tutorial0.fx",
};

static hfxc_result *compile(const char *path, unsigned targets) {
    hfxc_options o = {0};
    o.targets = targets;
    o.flags = HFXC_PACK_UNIFORMS | HFXC_NO_SELF_CHECK;
    return hfxc_compile_file(path, &o);
}

static const char *code(const hfxc_result *r, uint32_t prog, int stage, int target) {
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    return fx && prog < fx->program_count ? fx->programs[prog].code[stage][target].data : NULL;
}

static void same_texts(const char *path) {
    const unsigned gl = 1u << HFX_TARGET_GLSL330, es = 1u << HFX_TARGET_GLSLES300;
    hfxc_result *a = compile(path, gl), *b = compile(path, es), *both = compile(path, gl | es);
    const hfx_fx_effect *fa = hfxc_result_effect(a), *fb = hfxc_result_effect(b);
    CHECK(fa && fb && hfxc_result_effect(both));
    if (fa && fb) CHECK_INT(fa->program_count, fb->program_count);
    for (uint32_t p = 0; fa && fb && p < fa->program_count && p < fb->program_count; p++)
        for (int s = 0; s < HFX_STAGE_COUNT; s++) {
            const char *t330 = code(a, p, s, HFX_TARGET_GLSL330), *tes = code(b, p, s, HFX_TARGET_GLSLES300);
            char *made = t330 ? hfx_glsl_retarget(t330, HFX_TARGET_GLSL330, HFX_TARGET_GLSLES300) : NULL;
            CHECK(made && tes && strcmp(made, tes) == 0);
            if (!made || !tes || strcmp(made, tes) != 0) printf("  %s: program %u stage %d differs\n", path, p, s);
            const char *both_es = code(both, p, s, HFX_TARGET_GLSLES300), *both_gl = code(both, p, s, HFX_TARGET_GLSL330);
            CHECK(both_es && tes && strcmp(both_es, tes) == 0);
            CHECK(both_gl && t330 && strcmp(both_gl, t330) == 0);
            free(made);
        }
    hfxc_result_free(a);
    hfxc_result_free(b);
    hfxc_result_free(both);
}

static void own_effects(void) {
    for (size_t i = 0; i < sizeof own / sizeof *own; i++) {
        char path[1024];
        snprintf(path, sizeof path, "%s/fx/%s", HFX_SOURCE_DIR, own[i]);
        same_texts(path);
    }
}

static void seed_effects(void) {
    for (size_t i = 0; i < sizeof seeds / sizeof *seeds; i++) {
        char *path = test_seed_path(seeds[i]);
        same_texts(path);
        free(path);
    }
}

static void headers(void) {
    char *t = hfx_glsl_retarget("#version 330 core\nvoid main() {}\n", HFX_TARGET_GLSL330, HFX_TARGET_GLSLES300);
    CHECK_STR(t, "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n"
                 "precision highp sampler3D;\nprecision highp samplerCube;\nvoid main() {}\n");
    char *back = t ? hfx_glsl_retarget(t, HFX_TARGET_GLSLES300, HFX_TARGET_GLSL330) : NULL;
    CHECK_STR(back, "#version 330 core\nvoid main() {}\n");
    CHECK(hfx_glsl_retarget("#version 110\nvoid main() {}\n", HFX_TARGET_GLSL330, HFX_TARGET_GLSLES300) == NULL);
    free(t);
    free(back);
}

int main(void) {
    RUN(headers);
    RUN(own_effects);
    test_seeds_or_finish();
    RUN(seed_effects);
    return test_summary();
}
