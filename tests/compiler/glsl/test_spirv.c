/* test_spirv.c: the SPIR-V target. Every pass of the 13 good seeds becomes a vertex and a
 * fragment module with a valid header (magic, version 1.0), a `main` entry point of the right
 * execution model, that SPIRV-Tools' validator accepts for OpenGL 4.5 (the library spirv-val
 * is built on); uniforms sit at the documented locations, samplers at their units, varyings
 * match between the stages; the printer's SPIR-V mode and bad inputs behave. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "hfx/hfxc.h"
#include "glsl/spirv.h"
#include "test.h"

#if defined(__has_include)
#if __has_include(<spirv-tools/libspirv.h>)
#include <spirv-tools/libspirv.h>
#define HAVE_SPIRV_TOOLS 1
#endif
#endif

static const char *const good_seeds[] = {
    "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx", "fxcomposer_empty.fx",
    "multilights_repaired.fx", "phong.fx", "point.fx", "point_specular.fx", "pointlights.fx", "spot.fx",
    "spot_specular.fx", "tutorial0.fx",
};
enum { SEEDS = sizeof good_seeds / sizeof *good_seeds };

static const unsigned SPIRV = 1u << HFX_TARGET_SPIRV, GLSL330 = 1u << HFX_TARGET_GLSL330;

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

/* src compiled as `name` for targets; its diagnostics printed when it fails. */
static hfxc_result *compile_source(const char *src, const char *name, unsigned targets) {
    hfxc_options o = {0};
    o.targets = targets;
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), name, &o);
    if (!hfxc_result_ok(r)) {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s: %s\n", name, d);
        free(d);
    }
    return r;
}

static const uint32_t *words_of(const hfx_fx_code *c, size_t *count) {
    *count = c->size / 4;
    return (const uint32_t *)(const void *)c->data;
}

/* The OpEntryPoint's execution model and name (-1 when there is none). */
static int entry_point(const uint32_t *w, size_t n, char *name, size_t name_size) {
    for (size_t i = 5; i < n;) {
        uint32_t len = w[i] >> 16, op = w[i] & 0xffffu;
        if (!len || i + len > n) return -1;
        if (op == 15 && len >= 4) { /* OpEntryPoint model id "name" interface... */
            snprintf(name, name_size, "%s", (const char *)&w[i + 3]);
            return (int)w[i + 1];
        }
        i += len;
    }
    return -1;
}

static int validate(const uint32_t *w, size_t n, const char *what) {
#ifdef HAVE_SPIRV_TOOLS
    spv_context ctx = spvContextCreate(SPV_ENV_OPENGL_4_5);
    spv_const_binary_t bin = {w, n};
    spv_diagnostic diag = NULL;
    spv_result_t rc = spvValidate(ctx, &bin, &diag);
    if (rc != SPV_SUCCESS) fprintf(stderr, "%s: %s\n", what, diag && diag->error ? diag->error : "invalid");
    spvDiagnosticDestroy(diag);
    spvContextDestroy(ctx);
    return rc == SPV_SUCCESS;
#else
    (void)w, (void)n, (void)what;
    return 1;
#endif
}

static void check_module(const hfx_fx_code *c, int stage, const char *what) {
    size_t n;
    const uint32_t *w = words_of(c, &n);
    CHECK(c->data != NULL);
    if (!c->data) return;
    CHECK_INT(c->size % 4, 0);
    CHECK(n > 5);
    CHECK_INT(w[0], 0x07230203);
    CHECK_INT(w[1], 0x00010000); /* SPIR-V 1.0 */
    CHECK(w[3] > 1);             /* id bound */
    CHECK_INT(w[4], 0);          /* schema */
    char name[64] = "";
    CHECK_INT(entry_point(w, n, name, sizeof name), stage == HFX_STAGE_VERTEX ? 0 : 4); /* Vertex, Fragment */
    CHECK_STR(name, "main");
    CHECK(validate(w, n, what));
}

static void every_seed_pass_validates(void) {
#ifndef HAVE_SPIRV_TOOLS
    printf("note: SPIRV-Tools headers absent: modules are checked by header and entry point only\n");
#endif
    uint32_t modules = 0;
    for (size_t i = 0; i < SEEDS; i++) {
        hfxc_result *r = compile_seed(good_seeds[i], SPIRV);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        CHECK(fx != NULL);
        if (fx) {
            CHECK(fx->program_count > 0);
            CHECK_INT(fx->targets, SPIRV); /* the GLSL 330 it came from is not kept */
            for (uint32_t t = 0; t < fx->technique_count; t++)
                for (uint32_t k = 0; k < fx->techniques[t].pass_count; k++) {
                    const hfx_fx_pass *pass = &fx->passes[fx->techniques[t].first_pass + k];
                    CHECK(pass->program < fx->program_count);
                    if (pass->program >= fx->program_count) continue;
                    const hfx_fx_program *p = &fx->programs[pass->program];
                    for (int s = 0; s < HFX_STAGE_COUNT; s++) {
                        char what[256];
                        snprintf(what, sizeof what, "%s %s.%s stage %d", good_seeds[i], fx->techniques[t].name,
                                 pass->name, s);
                        check_module(&p->code[s][HFX_TARGET_SPIRV], s, what);
                        size_t nw;
                        const uint32_t *w = words_of(&p->code[s][HFX_TARGET_SPIRV], &nw);
                        CHECK_INT(hfx_spirv_bool_uniform(w, nw, NULL, 0), 0);
                        CHECK(p->code[s][HFX_TARGET_GLSL330].data == NULL);
                        modules++;
                    }
                }
        }
        hfxc_result_free(r);
    }
    CHECK(modules >= 2 * SEEDS);
}

/* Names of OpName'd ids starting with prefix, with their Location (the test's own walk). */
static int names_with_prefix(const uint32_t *w, size_t n, const char *prefix, char names[][64], int max) {
    int count = 0;
    for (size_t i = 5; i < n && count < max;) {
        uint32_t len = w[i] >> 16, op = w[i] & 0xffffu;
        if (!len || i + len > n) break;
        if (op == 5 && len >= 3) {
            const char *s = (const char *)&w[i + 2];
            if (strncmp(s, prefix, strlen(prefix)) == 0) snprintf(names[count++], 64, "%s", s);
        }
        i += len;
    }
    return count;
}

static void locations_follow_the_rules(void) {
    uint32_t uniforms = 0, samplers = 0, varyings = 0;
    for (size_t i = 0; i < SEEDS; i++) {
        hfxc_result *r = compile_seed(good_seeds[i], SPIRV);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        for (uint32_t pi = 0; fx && pi < fx->program_count; pi++) {
            const hfx_fx_program *p = &fx->programs[pi];
            size_t n[2];
            const uint32_t *w[2] = {words_of(&p->code[0][HFX_TARGET_SPIRV], &n[0]),
                                    words_of(&p->code[1][HFX_TARGET_SPIRV], &n[1])};
            for (uint32_t u = 0; u < p->uniform_count; u++) {
                uint32_t param = p->uniforms[u].param;
                const char *name = fx->params[param].glsl_name;
                int found = 0;
                for (int s = 0; s < 2 && name; s++) {
                    int32_t loc, binding;
                    if (hfx_spirv_find(w[s], n[s], name, &loc, &binding) != 1) continue;
                    found = 1;
                    CHECK_INT(loc, hfx_spirv_location(fx, p, name));
                    CHECK(loc >= 0);
                    uniforms++;
                }
                CHECK(found);
            }
            for (uint32_t k = 0; k < p->sampler_count; k++) {
                int found = 0;
                for (int s = 0; s < 2; s++) {
                    int32_t loc, binding;
                    if (hfx_spirv_find(w[s], n[s], p->samplers[k].glsl_name, &loc, &binding) != 1) continue;
                    found = 1;
                    CHECK_INT(binding, p->samplers[k].unit);
                    CHECK_INT(loc, hfx_spirv_location(fx, p, p->samplers[k].glsl_name));
                    CHECK(loc >= 0);
                    samplers++;
                }
                CHECK(found);
            }
            /* Varyings: every vertex output the fragment shader reads has one location in both. */
            char names[32][64];
            int count = names_with_prefix(w[1], n[1], "hfx_v_", names, 32);
            for (int v = 0; v < count; v++) {
                int32_t lv, lf;
                CHECK_INT(hfx_spirv_find(w[0], n[0], names[v], &lv, NULL), 1);
                CHECK_INT(hfx_spirv_find(w[1], n[1], names[v], &lf, NULL), 1);
                CHECK(lf >= 0);
                CHECK_INT(lv, lf);
                varyings++;
            }
        }
        hfxc_result_free(r);
    }
    CHECK(uniforms > 20);
    CHECK(samplers > 0);
    CHECK(varyings > 10);
}

/* Known values from multilights_repaired.fx: world, view, projection are its first three
 * parameters (locations 0, 1, 2 in the vertex shader); hfx_pos_fixup follows the program's
 * uniforms and samplers. */
static void multilights_locations(void) {
    hfxc_result *r = compile_seed("multilights_repaired.fx", SPIRV);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        const hfx_fx_program *p = &fx->programs[0];
        CHECK_INT(hfx_spirv_location(fx, p, "world"), 0);
        CHECK_INT(hfx_spirv_location(fx, p, "view"), 1);
        CHECK_INT(hfx_spirv_location(fx, p, "projection"), 2);
        CHECK_INT(hfx_spirv_location(fx, p, "no_such_name"), -1);
        CHECK_INT(hfx_spirv_location(fx, NULL, "world"), -1);
        size_t n;
        const uint32_t *w = words_of(&p->code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV], &n);
        int32_t loc, world;
        CHECK_INT(hfx_spirv_find(w, n, "world", &world, NULL), 1);
        CHECK_INT(world, 0);
        CHECK_INT(hfx_spirv_find(w, n, "hfx_pos_fixup", &loc, NULL), 1);
        CHECK_INT(loc, hfx_spirv_location(fx, p, "hfx_pos_fixup"));
        int32_t after = 0;
        for (uint32_t u = 0; u < p->uniform_count; u++) {
            int32_t l = hfx_spirv_location(fx, p, fx->params[p->uniforms[u].param].glsl_name);
            if (l >= after) after = l + 1;
        }
        CHECK_INT(loc, after + (int32_t)p->sampler_count);
        CHECK_INT(hfx_spirv_find(w, n, "no_such_name", &loc, NULL), 0);
        CHECK_INT(loc, -1);
    }
    hfxc_result_free(r);
}

/* A large parameter another program reads does not push this program's locations up. */
static void locations_are_per_program(void) {
    const char *src = "float4 big1[3000];\nfloat4 big2[3000];\nfloat4 x;\n"
                      "float4 VS(float4 p : POSITION) : POSITION { return p * x; }\n"
                      "float4 VS1(float4 p : POSITION) : POSITION { return p * big1[3]; }\n"
                      "float4 VS2(float4 p : POSITION) : POSITION { return p * big2[3]; }\n"
                      "float4 PS() : COLOR { return x; }\n"
                      "technique t { pass a { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }\n"
                      "  pass b { VertexShader = compile vs_3_0 VS1(); PixelShader = compile ps_3_0 PS(); }\n"
                      "  pass c { VertexShader = compile vs_3_0 VS2(); PixelShader = compile ps_3_0 PS(); } }\n";
    hfxc_result *r = compile_source(src, "big.fx", SPIRV);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        CHECK_INT(fx->program_count, 3);
        CHECK_INT(hfx_spirv_location(fx, &fx->programs[0], "x"), 0);
        CHECK_INT(hfx_spirv_location(fx, &fx->programs[2], "big2"), 0);
        CHECK_INT(hfx_spirv_location(fx, &fx->programs[2], "x"), 3000);
        size_t n;
        const uint32_t *w = words_of(&fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV], &n);
        int32_t loc;
        CHECK_INT(hfx_spirv_find(w, n, "x", &loc, NULL), 1);
        CHECK_INT(loc, 0);
    }
    hfxc_result_free(r);
}

/* Asking for GLSL 330 and SPIR-V keeps the GLSL 330 exactly as a GLSL-only compile gives it. */
static void glsl330_kept_when_asked(void) {
    hfxc_result *a = compile_seed("ambient_textured.fx", SPIRV | GLSL330);
    hfxc_result *b = compile_seed("ambient_textured.fx", GLSL330);
    const hfx_fx_effect *fa = hfxc_result_effect(a), *fb = hfxc_result_effect(b);
    CHECK(fa && fb);
    if (fa && fb) {
        CHECK_INT(fa->targets, SPIRV | GLSL330);
        CHECK_INT(fb->targets, GLSL330);
        CHECK_INT(fa->program_count, fb->program_count);
        for (uint32_t p = 0; p < fa->program_count && p < fb->program_count; p++)
            for (int s = 0; s < HFX_STAGE_COUNT; s++) {
                CHECK_STR(fa->programs[p].code[s][HFX_TARGET_GLSL330].data, fb->programs[p].code[s][HFX_TARGET_GLSL330].data);
                CHECK(fa->programs[p].code[s][HFX_TARGET_SPIRV].size > 20);
                CHECK(fb->programs[p].code[s][HFX_TARGET_SPIRV].data == NULL);
            }
    }
    hfxc_result_free(a);
    hfxc_result_free(b);
}

/* The printer's SPIR-V mode, read back from the module: locations by the rules (parameters in
 * order, samplers after them at their unit's binding, the known internal ones after those),
 * bools as int. */
static void printer_spirv_mode(void) {
    const char *src = "float4x4 m[3];\nbool on;\ntexture T;\nsampler2D s = sampler_state { Texture = <T>; };\n"
                      "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                      "float4 PS(float2 uv : TEXCOORD0) : COLOR { return on ? tex2D(s, uv) * m[2][0] : 0; }\n"
                      "technique t { pass p { AlphaTestEnable = true;\n"
                      "  VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";
    hfxc_result *r = compile_source(src, "mode.fx", SPIRV);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        const hfx_fx_code *c = &fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV];
        check_module(c, HFX_STAGE_FRAGMENT, "mode.fx");
        size_t n;
        const uint32_t *w = words_of(c, &n);
        int32_t loc, binding;
        CHECK_INT(hfx_spirv_find(w, n, "m", &loc, &binding), 1);
        CHECK_INT(loc, 0);
        CHECK_INT(hfx_spirv_find(w, n, "on", &loc, &binding), 1);
        CHECK_INT(loc, 3); /* after m's 3 matrices */
        CHECK_INT(binding, -1);
        CHECK_INT(hfx_spirv_find(w, n, "s", &loc, &binding), 1);
        CHECK_INT(loc, 4);
        CHECK_INT(binding, 0); /* its texture unit */
        CHECK_INT(hfx_spirv_find(w, n, "hfx_alpha_ref", &loc, &binding), 1);
        CHECK_INT(loc, 7); /* 4 + 1 sampler + hfx_pos_fixup, hfx_alpha_func */
        CHECK_INT(hfx_spirv_bool_uniform(w, n, NULL, 0), 0); /* `on` is an int */
        c = &fx->programs[0].code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV];
        w = words_of(c, &n);
        CHECK_INT(hfx_spirv_find(w, n, "hfx_pos_fixup", &loc, &binding), 1);
        CHECK_INT(loc, 5);
    }
    hfxc_result_free(r);
}

/* A bool uniform named like a struct field or a parameter is read converted all the same (the
 * text rewrite once kept it bool there: a #define would have broken the field and the parameter). */
static void bool_named_like_a_field(void) {
    const char *srcs[2] = {
        "struct S { bool on; };\nbool on;\n"
        "float4 PS() : COLOR { S x; x.on = on; return x.on ? 1 : 0; }\n",
        "bool on;\nbool f(bool on) { return on; }\n"
        "float4 PS() : COLOR { return f(!on) || on ? 1 : 0; }\n",
    };
    for (int i = 0; i < 2; i++) {
        char src[512];
        snprintf(src, sizeof src, "%s%s", srcs[i], "technique t { pass p { PixelShader = compile ps_3_0 PS(); } }\n");
        hfxc_result *r = compile_source(src, "bools.fx", SPIRV);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        CHECK(fx != NULL);
        if (fx) {
            const hfx_fx_code *c = &fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV];
            check_module(c, HFX_STAGE_FRAGMENT, "bool named like a field");
            size_t n;
            const uint32_t *w = words_of(c, &n);
            int32_t loc;
            CHECK_INT(hfx_spirv_bool_uniform(w, n, NULL, 0), 0);
            CHECK_INT(hfx_spirv_find(w, n, "on", &loc, NULL), 1);
            CHECK_INT(loc, i == 0 ? 0 : -1); /* the second: OpName "on" is f's parameter first */
        }
        hfxc_result_free(r);
    }
}

static uint32_t count_warnings(const hfxc_result *r, const char *needle) {
    uint32_t n = 0;
    for (size_t i = 0; i < hfxc_diag_count(r); i++) {
        const hfxc_diag *d = hfxc_diag_at(r, i);
        if (d->severity == HFXC_WARNING && strstr(d->message, needle)) n++;
    }
    return n;
}

/* bool, bool2 and bool arrays become int in the SPIR-V (valid); a struct with a bool member
 * cannot, and says so in a warning. */
static void bool_uniforms(void) {
    const char *common = "bool flags[3];\nbool2 bb;\nbool one;\nsampler2D samp;\n"
                         "float4 VS(float4 p : POSITION) : POSITION { return p; }\n";
    const char *tail = "technique t { pass p { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";
    char src[2048];
    snprintf(src, sizeof src, "%sfloat4 PS(float2 uv : TEXCOORD0) : COLOR {\n"
                              "  float4 c = tex2D(samp, uv);\n"
                              "  if (flags[2] && bb.y && one) c *= 2;\n  return c;\n}\n%s", common, tail);
    hfxc_result *r = compile_source(src, "bools.fx", SPIRV);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    CHECK_INT(count_warnings(r, "bool"), 0);
    if (fx) {
        const hfx_fx_code *c = &fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV];
        check_module(c, HFX_STAGE_FRAGMENT, "bool uniforms");
        size_t n;
        const uint32_t *w = words_of(c, &n);
        CHECK_INT(hfx_spirv_bool_uniform(w, n, NULL, 0), 0);
        int32_t loc;
        const hfx_fx_program *p = &fx->programs[0];
        CHECK_INT(hfx_spirv_find(w, n, "flags", &loc, NULL), 1);
        CHECK_INT(loc, 0);
        CHECK_INT(hfx_spirv_location(fx, p, "bb"), 3); /* after flags[3] */
        CHECK_INT(hfx_spirv_location(fx, p, "one"), 4);
        CHECK_INT(hfx_spirv_location(fx, p, "samp"), 5);
        CHECK_INT(hfx_spirv_find(w, n, "one", &loc, NULL), 1);
        CHECK_INT(loc, 4);
    }
    hfxc_result_free(r);

    snprintf(src, sizeof src, "%sstruct L { bool on; float3 c; };\nL lights[2];\n"
                              "float4 PS(float2 uv : TEXCOORD0) : COLOR {\n"
                              "  float4 c = tex2D(samp, uv);\n"
                              "  if (lights[1].on) c *= 2;\n  return c;\n}\n%s", common, tail);
    r = compile_source(src, "bools.fx", SPIRV);
    fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    CHECK_INT(count_warnings(r, "'lights': a uniform with bool members stays bool in SPIR-V"), 1);
    if (fx) {
        const hfx_fx_code *c = &fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV];
        size_t n;
        const uint32_t *w = words_of(c, &n);
        char name[64] = "";
        CHECK_INT(hfx_spirv_bool_uniform(w, n, name, sizeof name), 1);
        CHECK_STR(name, "lights");
    }
    hfxc_result_free(r);
    uint32_t junk[6] = {1, 2, 3, 4, 5, 6};
    CHECK_INT(hfx_spirv_bool_uniform(junk, 6, NULL, 0), -1);
}

/* Broken GLSL gives -1, a log naming the problem, and no code; garbage is not SPIR-V. */
static void bad_inputs(void) {
    hfx_fx_effect fx;
    memset(&fx, 0, sizeof fx);
    hfx_fx_program p;
    memset(&p, 0, sizeof p);
    CHECK(hfx_spirv_begin());
    char *log = NULL;
    CHECK_INT(hfx_spirv_program(&fx, &p, &log), -1); /* no GLSL at all */
    CHECK_CONTAINS(log, "no GLSL");
    free(log);
    /* the printer's text is malloc'ed: failures free it */
    p.code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV].data =
        strdup("#version 450 core\nout vec4 hfx_v_X;\nvoid main() { gl_Position = vec4(0.0); hfx_v_X = vec4(1.0); }\n");
    p.code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV].data = strdup("#version 450 core\nvoid main() { undeclared_thing = 1.0; }\n");
    log = NULL;
    CHECK_INT(hfx_spirv_program(&fx, &p, &log), -1);
    CHECK_CONTAINS(log, "undeclared_thing");
    CHECK_CONTAINS(log, "fragment shader");
    CHECK(p.code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV].data == NULL);
    CHECK(p.code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV].data == NULL);
    free(log);
    p.code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV].data = strdup("#version 450 core\nvoid main() { undeclared_thing = 1.0; }\n");
    CHECK_INT(hfx_spirv_program(&fx, &p, NULL), -1); /* no log wanted */
    CHECK(p.code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV].data == NULL);
    p.code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV].data = strdup("");
    CHECK_INT(hfx_spirv_program(&fx, &p, NULL), -1);
    hfx_spirv_end();

    uint32_t junk[8] = {0x12345678, 1, 2, 3, 4, 5, 6, 7};
    int32_t loc = 5, binding = 5;
    CHECK_INT(hfx_spirv_find(junk, 8, "x", &loc, &binding), -1);
    CHECK_INT(loc, -1);
    CHECK_INT(binding, -1);
    uint32_t truncated[7] = {0x07230203, 0x00010000, 0, 10, 0, (9u << 16) | 5, 1}; /* OpName past the end */
    CHECK_INT(hfx_spirv_find(truncated, 7, "x", &loc, &binding), -1);
    uint32_t zero_len[6] = {0x07230203, 0x00010000, 0, 10, 0, 0};
    CHECK_INT(hfx_spirv_find(zero_len, 6, "x", &loc, &binding), -1);
    CHECK_INT(hfx_spirv_find(NULL, 0, "x", NULL, NULL), -1);
}

int main(void) {
    if (!hfx_spirv_available()) test_skip("built without glslang: no SPIR-V target");
    RUN(printer_spirv_mode);
    RUN(bool_named_like_a_field);
    RUN(bad_inputs);
    RUN(bool_uniforms);
    test_require_seeds();
    RUN(every_seed_pass_validates);
    RUN(locations_follow_the_rules);
    RUN(multilights_locations);
    RUN(locations_are_per_program);
    RUN(glsl330_kept_when_asked);
    return test_summary();
}
