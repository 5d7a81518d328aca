/* test_switches.c: bool parameters as switches (common/effect.h, docs/hfxo-format.md). The
 * compiler flags the first four scalar bools a program reads as they are, numbered in uniform
 * order across both stages, and wraps their declarations so a runtime can make them constants;
 * not a bool the shader writes, a bool array, an int or a float. Every combination of defines
 * is valid GLSL for every target, for a small effect, every seed and every effect of fx/; the
 * flags survive a .hfxo round trip. */
#include <dirent.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "glsl_check.h"
#include "hfx/hfxc.h"
#include "test.h"

static const unsigned GLSL_TARGETS =
    1u << HFX_TARGET_GLSL330 | 1u << HFX_TARGET_GLSLES300 | 1u << HFX_TARGET_GLSL110;

/* B0..B4 are scalar bools; Written is one a function writes; Flags an array; Count an int. */
static const char bools_fx[] =
    "bool B0 = true;\nbool B1;\nbool B2;\nbool B3;\nbool B4;\nbool Written;\nbool Flags[2];\nint Count;\n"
    "float4 Tint = float4(1, 0, 0, 1);\n"
    "float4 VS(float4 p : POSITION0) : POSITION0 { if (B2) p.x += 1; return p; }\n"
    "void Flip() { Written = !Written; }\n"
    "float4 PS() : COLOR0\n{\n    float4 c = B0 ? Tint : Tint.gbra;\n    if (B1) c *= 0.5;\n"
    "    if (B3 && B4) c.g = 1;\n    Flip();\n    if (Written || Flags[1]) c.b = 1;\n"
    "    return c * Count;\n}\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

static hfxc_result *compile_text(const char *src, const char *name) {
    hfxc_options o = {0};
    o.targets = GLSL_TARGETS;
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), name, &o);
    if (!hfxc_result_ok(r)) {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s: %s\n", name, d);
        free(d);
    }
    return r;
}

static const char *param_name(const hfx_fx_effect *fx, const hfx_fx_uniform_use *u) { return fx->params[u->param].name; }

/* The names of the program's switches in order, space-separated. */
static void switch_names(const hfx_fx_effect *fx, const hfx_fx_program *p, char *out, size_t size) {
    out[0] = 0;
    for (uint32_t k = 0; k < p->uniform_count; k++) {
        if (!(p->uniforms[k].flags & HFX_FX_USE_SWITCH)) continue;
        size_t n = strlen(out);
        snprintf(out + n, size - n, "%s%s", n ? " " : "", param_name(fx, &p->uniforms[k]));
    }
}

static void which_bools(void) {
    hfxc_result *r = compile_text(bools_fx, "bools.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx && fx->program_count == 1);
    if (fx && fx->program_count == 1) {
        char names[128];
        switch_names(fx, &fx->programs[0], names, sizeof names);
        CHECK_STR(names, "B0 B1 B2 B3"); /* B4 is the fifth; Written, Flags, Count are not switches */
    }
    hfxc_result_free(r);
}

static void declarations_as_text(void) {
    hfxc_result *r = compile_text(bools_fx, "bools.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        const char *vs = fx->programs[0].code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data;
        const char *ps = fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data;
        /* numbered in the program's uniform order, so the vertex stage's B2 is switch 2 */
        CHECK(strstr(vs, "#ifdef HFX_SWITCH_2\nconst bool B2 = HFX_SWITCH_2;\n#else\nuniform bool B2;\n#endif\n") != NULL);
        CHECK(strstr(ps, "#ifdef HFX_SWITCH_0\nconst bool B0 = HFX_SWITCH_0;\n#else\nuniform bool B0;\n#endif\n") != NULL);
        CHECK(strstr(ps, "#ifdef HFX_SWITCH_3\nconst bool B3 = HFX_SWITCH_3;\n#else\nuniform bool B3;\n#endif\n") != NULL);
        CHECK(strstr(ps, "\nuniform bool B4;\n") != NULL);
        CHECK(strstr(ps, "HFX_SWITCH_4") == NULL);
        CHECK(strstr(vs, "HFX_SWITCH_0") == NULL); /* a stage declares only what it reads */
    }
    hfxc_result_free(r);
}

/* src with `#define HFX_SWITCH_k true|false` after the #version line (what the GL runtime does). */
static char *defined(const char *src, uint32_t count, uint32_t mask) {
    const char *eol = strchr(src, '\n');
    size_t head = (size_t)(eol - src) + 1, n = strlen(src) + count * 40 + 1;
    char *out = malloc(n);
    memcpy(out, src, head);
    out[head] = 0;
    for (uint32_t k = 0; k < count; k++)
        snprintf(out + strlen(out), n - strlen(out), "#define HFX_SWITCH_%u %s\n", (unsigned)k, mask >> k & 1 ? "true" : "false");
    strcat(out, eol + 1);
    return out;
}

static uint32_t switch_count(const hfx_fx_program *p) {
    uint32_t n = 0;
    for (uint32_t k = 0; k < p->uniform_count; k++) n += (p->uniforms[k].flags & HFX_FX_USE_SWITCH) != 0;
    return n;
}

/* Every combination of the program's switches links, for every GLSL target it has; the number of
 * programs with switches. */
static int every_combination_links(const hfx_fx_effect *fx, const char *what) {
    int switched = 0;
    for (uint32_t i = 0; i < fx->program_count; i++) {
        const hfx_fx_program *p = &fx->programs[i];
        uint32_t n = switch_count(p);
        CHECK(n <= HFX_FX_MAX_SWITCHES);
        switched += n > 0;
        for (int t = HFX_TARGET_GLSL330; n && t <= HFX_TARGET_GLSL110; t++) {
            if (!p->code[HFX_STAGE_VERTEX][t].data) continue;
            for (uint32_t mask = 0; mask < 1u << n; mask++) {
                char *vs = defined(p->code[HFX_STAGE_VERTEX][t].data, n, mask);
                char *fs = defined(p->code[HFX_STAGE_FRAGMENT][t].data, n, mask);
                char *log = NULL;
                int ok = test_glsl_link(vs, fs, &log);
                if (!ok) fprintf(stderr, "%s program %u target %d switches %x:\n%s\n", what, i, t, mask, log ? log : "");
                CHECK(ok);
                free(log);
                free(vs);
                free(fs);
            }
        }
    }
    return switched;
}

static void small_effect_links(void) {
    hfxc_result *r = compile_text(bools_fx, "bools.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) CHECK_INT(every_combination_links(fx, "bools.fx"), 1);
    hfxc_result_free(r);
}

static void flags_survive_hfxo(void) {
    hfxc_result *r = compile_text(bools_fx, "bools.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    hfx_fx_effect *copy = fx ? hfx_fx_effect_copy(fx) : NULL; /* a write and a read */
    CHECK(copy != NULL);
    if (copy) {
        char names[128];
        switch_names(copy, &copy->programs[0], names, sizeof names);
        CHECK_STR(names, "B0 B1 B2 B3");
    }
    hfx_fx_effect_free(copy);
    hfxc_result_free(r);
}

/* Every .fx of dir (compiled with the seeds' own folder for includes); the programs with switches. */
static int check_dir(const char *dir, const char *skip) {
    DIR *d = opendir(dir);
    int switched = 0;
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        if (len < 4 || strcmp(e->d_name + len - 3, ".fx") != 0 || (skip && strcmp(e->d_name, skip) == 0)) continue;
        char *path = test_path_in(dir, e->d_name);
        hfxc_options o = {0};
        o.targets = GLSL_TARGETS;
        hfxc_result *r = hfxc_compile_file(path, &o);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        if (!fx) { /* GLSL 110 lacks what some need: the two modern targets then */
            hfxc_result_free(r);
            o.targets = 1u << HFX_TARGET_GLSL330 | 1u << HFX_TARGET_GLSLES300;
            fx = hfxc_result_effect(r = hfxc_compile_file(path, &o));
        }
        CHECK(fx != NULL);
        if (fx) switched += every_combination_links(fx, e->d_name);
        hfxc_result_free(r);
        free(path);
    }
    if (d) closedir(d);
    return switched;
}

static void own_effects(void) { check_dir(HFX_SOURCE_DIR "/fx", NULL); }

static void seed_effects(void) {
    int switched = check_dir(test_seed_dir(), "multilights.fx"); /* the corpus's known-bad original */
    printf("seeds: %d programs with switches\n", switched);
    CHECK(switched >= 10); /* point, spot, the speculars and multilights have bools */
}

int main(void) {
    RUN(which_bools);
    RUN(declarations_as_text);
    RUN(small_effect_links);
    RUN(flags_survive_hfxo);
    RUN(own_effects);
    test_seeds_or_finish();
    RUN(seed_effects);
    return test_summary();
}
