/* test_glsl_seeds.c: every pass of every good seed effect gives GLSL 330 and ES 300 sources
 * that glslang compiles and links; specialisation gives the two techniques of
 * ambient_textured.fx different pixel shaders. */
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "glsl_check.h"
#include "hfx/hfxc.h"
#include "test.h"

static const char *const good_seeds[] = {
    "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx", "fxcomposer_empty.fx",
    "multilights_repaired.fx", "phong.fx", "point.fx", "point_specular.fx", "pointlights.fx", "spot.fx",
    "spot_specular.fx", "tutorial0.fx",
};

static hfxc_result *compile_seed(const char *name, unsigned targets) {
    char *path = test_seed_path(name);
    hfxc_options o = {0};
    o.targets = targets;
    hfxc_result *r = hfxc_compile_file(path, &o);
    free(path);
    if (!hfxc_result_ok(r)) {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s: %s\n", name, d);
        free(d);
    }
    return r;
}

static int link_program(const hfx_fx_program *p, int target, const char *what) {
    char *log = NULL;
    const char *vs = p->code[HFX_STAGE_VERTEX][target].data, *fs = p->code[HFX_STAGE_FRAGMENT][target].data;
    if (!vs || !fs) { fprintf(stderr, "%s: no code\n", what); return 0; }
    int ok = test_glsl_link(vs, fs, &log);
    if (!ok) fprintf(stderr, "%s:\n%s\n--- vertex\n%s\n--- fragment\n%s\n", what, log ? log : "", vs, fs);
    free(log);
    return ok;
}

static void every_seed_links(void) {
    unsigned targets = (1u << HFX_TARGET_GLSL330) | (1u << HFX_TARGET_GLSLES300);
    for (size_t i = 0; i < sizeof good_seeds / sizeof *good_seeds; i++) {
        hfxc_result *r = compile_seed(good_seeds[i], targets);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        CHECK(fx != NULL);
        if (fx) {
            CHECK(fx->program_count > 0);
            for (uint32_t p = 0; p < fx->program_count; p++) {
                char what[128];
                snprintf(what, sizeof what, "%s program %u (330)", good_seeds[i], p);
                CHECK(link_program(&fx->programs[p], HFX_TARGET_GLSL330, what));
                snprintf(what, sizeof what, "%s program %u (ES 300)", good_seeds[i], p);
                CHECK(link_program(&fx->programs[p], HFX_TARGET_GLSLES300, what));
            }
        }
        hfxc_result_free(r);
    }
}

/* GLSL 110 (attribute / varying / gl_FragData) for the same passes. */
static void every_seed_links_glsl110(void) {
    for (size_t i = 0; i < sizeof good_seeds / sizeof *good_seeds; i++) {
        hfxc_result *r = compile_seed(good_seeds[i], 1u << HFX_TARGET_GLSL110);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        CHECK(fx != NULL);
        for (uint32_t p = 0; fx && p < fx->program_count; p++) {
            char what[128];
            snprintf(what, sizeof what, "%s program %u (110)", good_seeds[i], p);
            CHECK(link_program(&fx->programs[p], HFX_TARGET_GLSL110, what));
        }
        hfxc_result_free(r);
    }
}

static const hfx_fx_program *pass_program(const hfx_fx_effect *fx, const char *tech, uint32_t pass) {
    for (uint32_t t = 0; t < fx->technique_count; t++)
        if (strcmp(fx->techniques[t].name, tech) == 0) {
            uint32_t prog = fx->passes[fx->techniques[t].first_pass + pass].program;
            return prog < fx->program_count ? &fx->programs[prog] : NULL;
        }
    return NULL;
}

static void specialisation_differs(void) {
    hfxc_result *r = compile_seed("ambient_textured.fx", 1u << HFX_TARGET_GLSL330);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        const hfx_fx_program *tex = pass_program(fx, "Texturizado", 0), *mat = pass_program(fx, "Material", 0);
        CHECK(tex && mat);
        if (tex && mat) {
            const char *ft = tex->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data;
            const char *fm = mat->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data;
            CHECK(ft && fm && strcmp(ft, fm) != 0);
            CHECK_CONTAINS(ft, "texture(modeloTexturaMuestra, ");
            CHECK(fm && !strstr(fm, "texture("));
            CHECK(fm && !strstr(fm, "sampler2D"));
            /* no pass of the effect turns the alpha test on: no flag, and no code for it */
            CHECK(!(tex->flags & HFX_FX_PROGRAM_ALPHA_TEST));
            CHECK(ft && !strstr(ft, "alpha"));
            CHECK_INT(tex->sampler_count, 1);
            CHECK_INT(mat->sampler_count, 0);
            if (tex->sampler_count) {
                CHECK_STR(tex->samplers[0].glsl_name, "modeloTexturaMuestra");
                CHECK_INT(tex->samplers[0].unit, 0);
            }
            /* the textured pass writes the global: a private copy, set from the uniform */
            CHECK_CONTAINS(ft, "hfx_priv_colorMaterialAmbiental = colorMaterialAmbiental;");
            CHECK(fm && !strstr(fm, "hfx_priv_"));
            CHECK_INT(tex->attribute_count, 2);
            if (tex->attribute_count == 2) {
                CHECK_STR(tex->attributes[0].semantic, "POSITION0");
                CHECK_INT(tex->attributes[0].location, 0);
                CHECK_STR(tex->attributes[1].semantic, "TEXCOORD0");
                CHECK_INT(tex->attributes[1].location, 8);
            }
        }
    }
    hfxc_result_free(r);
}

/* Same input, same bytes. */
static void output_is_deterministic(void) {
    hfxc_result *a = compile_seed("multilights_repaired.fx", 1u << HFX_TARGET_GLSL330);
    hfxc_result *b = compile_seed("multilights_repaired.fx", 1u << HFX_TARGET_GLSL330);
    const hfx_fx_effect *fa = hfxc_result_effect(a), *fb = hfxc_result_effect(b);
    CHECK(fa && fb);
    if (fa && fb) {
        CHECK_INT(fa->program_count, fb->program_count);
        for (uint32_t p = 0; p < fa->program_count && p < fb->program_count; p++)
            for (int s = 0; s < 2; s++)
                CHECK_STR(fa->programs[p].code[s][HFX_TARGET_GLSL330].data, fb->programs[p].code[s][HFX_TARGET_GLSL330].data);
    }
    hfxc_result_free(a);
    hfxc_result_free(b);
}

int main(void) {
    test_require_seeds();
    RUN(every_seed_links);
    RUN(every_seed_links_glsl110);
    RUN(specialisation_differs);
    RUN(output_is_deterministic);
    return test_summary();
}
