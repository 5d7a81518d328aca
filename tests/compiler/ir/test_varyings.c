/* test_varyings.c: derived varyings (compiler/ir/lower/varyings.c), read in the GLSL of small
 * effects: a vertex output that is an affine function of another output and parameters leaves
 * the varyings of both stages and the pixel shader computes it; what does not qualify (written
 * in a branch, its variable changed in between, a COLOR, a value that is not uniform-only, a
 * pixel shader that does not read the other output, a shared vertex shader whose other program
 * reads differently) keeps its varying. Every target links, in every uniform mode; SPIR-V
 * validates; each seed effect and each effect of fx/ still compiles. GL values: test_glsl_run.c
 * (derived_varying_values) and the seeds' probes of pointlights.fx. */
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

static const unsigned GLSL_ALL = (1u << HFX_TARGET_GLSL330) | (1u << HFX_TARGET_GLSLES300) | (1u << HFX_TARGET_GLSL110);

#define OUT_STRUCT "struct VOut { float4 pos : POSITION; float3 N : TEXCOORD0; float3 V : TEXCOORD1; float3 WP : TEXCOORD2; };\n"
#define PS_READS_ALL "float4 ps(VOut i) : COLOR { return float4(normalize(i.V) + i.WP + i.N, 1); }\n"
#define TECH "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n"

/* A program's two GLSL 330 stages (malloc'ed), after every GLSL target of it linked. */
typedef struct stages { char *vs, *fs; } stages;

static bool links(const hfx_fx_program *p, unsigned targets) {
    if (!p->code[0][HFX_TARGET_GLSL330].data) return true; /* a program hfx could not make (reported) */
    bool ok = true;
    for (int t = 0; t < HFX_TARGET_SPIRV; t++) {
        char *log = NULL;
        if ((targets & (1u << t)) && !test_glsl_link(p->code[0][t].data, p->code[1][t].data, &log)) {
            fprintf(stderr, "target %d does not link:\n%s\n%s\n%s\n", t, log ? log : "", p->code[0][t].data, p->code[1][t].data);
            ok = false;
        }
        free(log);
    }
    return ok;
}

static stages compile_program(const char *src, unsigned flags, uint32_t program) {
    stages s = {0};
    hfxc_options o = {0};
    o.targets = GLSL_ALL;
    o.flags = flags | HFXC_NO_WARNINGS;
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "varyings.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    if (!fx || program >= fx->program_count) {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "compile failed: %s\n%s\n", d, src);
        free(d);
    } else if (links(&fx->programs[program], GLSL_ALL)) {
        s.vs = strdup(fx->programs[program].code[0][HFX_TARGET_GLSL330].data);
        s.fs = strdup(fx->programs[program].code[1][HFX_TARGET_GLSL330].data);
    }
    hfxc_result_free(r);
    return s;
}

static stages compile(const char *src, unsigned flags) { return compile_program(src, flags, 0); }

static void release(stages *s) { free(s->vs); free(s->fs); }

/* V (TEXCOORD1) is derived: neither stage declares it, the vertex shader no longer computes it,
 * the pixel entry does, first. */
static void derived(const stages *s) {
    CHECK(s->vs && s->fs);
    if (!s->vs || !s->fs) return;
    CHECK(strstr(s->vs, "out vec4 hfx_v_TEXCOORD1;") == NULL);
    CHECK(strstr(s->fs, "in vec4 hfx_v_TEXCOORD1;") == NULL);
    CHECK(strstr(s->vs, "hfx_output.V =") == NULL);
    CHECK(strstr(s->fs, "hfx_arg0.V =") == NULL);
    CHECK_CONTAINS(s->vs, "out vec4 hfx_v_TEXCOORD2;");
    CHECK_CONTAINS(s->fs, "in vec4 hfx_v_TEXCOORD2;");
}

/* V keeps its varying in both stages. */
static void kept(const stages *s) {
    CHECK(s->vs && s->fs);
    if (!s->vs || !s->fs) return;
    CHECK_CONTAINS(s->vs, "out vec4 hfx_v_TEXCOORD1;");
    CHECK_CONTAINS(s->fs, "in vec4 hfx_v_TEXCOORD1;");
    CHECK_CONTAINS(s->fs, " = hfx_v_TEXCOORD1.xyz;");
}

static const char pointlights_like[] = "float3 Cam; float4x4 World;\n" OUT_STRUCT
    "VOut vs(float4 p : POSITION, float3 n : NORMAL) { VOut o;\n"
    "  float4 wp = mul(p, World);\n"
    "  o.pos = wp; o.N = n;\n"
    "  o.V = Cam - wp;\n"
    "  o.WP = wp;\n"
    "  return o; }\n" PS_READS_ALL TECH;

static void camera_minus_position(void) {
    stages s = compile(pointlights_like, 0);
    derived(&s);
    if (s.fs) {
        CHECK_CONTAINS(s.fs, "vec4 ps(VOut i)\n{\n    i.V = Cam - i.WP;\n");
        CHECK_CONTAINS(s.fs, "uniform vec3 Cam;\n");
    }
    if (s.vs) CHECK(strstr(s.vs, "Cam") == NULL); /* only V read it */
    release(&s);
    s = compile(pointlights_like, HFXC_NO_DERIVED_VARYINGS);
    kept(&s);
    release(&s);
}

/* Packed registers: the pixel stage reads Cam from hfx_c, which both stages declare alike. */
static void packed_and_preshaders(void) {
    const unsigned modes[] = {HFXC_PACK_UNIFORMS, HFXC_PACK_UNIFORMS | HFXC_NO_PRESHADERS};
    for (int m = 0; m < 2; m++) {
        stages s = compile(pointlights_like, modes[m]);
        derived(&s);
        if (s.fs) {
            CHECK_CONTAINS(s.fs, "vec3 Cam; // hfx_c[");
            CHECK_CONTAINS(s.fs, "    i.V = Cam - i.WP;\n");
        }
        release(&s);
    }
}

/* The other affine forms: x - U, x + U, U + x, -x + U, (U - x) * k, a plain copy, and a swizzle
 * of the whole float4. */
static void affine_forms(void) {
    static const struct { const char *stmt, *pixel; } forms[] = {
        {"o.V = wp - Cam;", "i.V = i.WP - Cam;"},
        {"o.V = wp + Cam;", "i.V = i.WP + Cam;"},
        {"o.V = Cam + wp;", "i.V = Cam + i.WP;"},
        {"o.V = -(float3)wp + Cam;", "i.V = -i.WP + Cam;"},
        {"o.V = (Cam - wp) * 0.5;", "i.V = (Cam - i.WP) * vec3(0.5);"},
        {"o.V = wp;", "i.V = i.WP;"},
    };
    for (size_t i = 0; i < sizeof forms / sizeof *forms; i++) {
        char src[1024];
        snprintf(src, sizeof src, "float3 Cam; float4x4 World;\n" OUT_STRUCT
                 "VOut vs(float4 p : POSITION, float3 n : NORMAL) { VOut o; float4 wp = mul(p, World);\n"
                 "  o.pos = wp; o.N = n; o.WP = wp; %s return o; }\n" PS_READS_ALL TECH, forms[i].stmt);
        stages s = compile(src, 0);
        derived(&s);
        if (s.fs) CHECK_CONTAINS(s.fs, forms[i].pixel);
        release(&s);
    }
}

/* Out parameters instead of a returned struct; W a float4 read through a swizzle. */
static void out_parameters(void) {
    const char *src = "float3 Cam;\n"
        "void vs(float4 p : POSITION, out float4 pos : POSITION, out float3 v : TEXCOORD1, out float4 wp : TEXCOORD2)\n"
        "{ pos = p; wp = p * 2; v = Cam - wp.xyz; }\n"
        "float4 ps(float3 v : TEXCOORD1, float4 wp : TEXCOORD2) : COLOR { return float4(v, wp.w); }\n" TECH;
    stages s = compile(src, 0);
    CHECK(s.vs && s.fs);
    if (s.vs && s.fs) {
        CHECK(strstr(s.vs, "hfx_v_TEXCOORD1") == NULL);
        CHECK(strstr(s.fs, "hfx_v_TEXCOORD1") == NULL);
        CHECK_CONTAINS(s.fs, "    v = Cam - wp.xyz;\n");
    }
    release(&s);
}

/* What must not change: each keeps V a varying. */
static void negative_cases(void) {
    static const char *const cases[] = {
        /* V written in a branch */
        "float3 Cam; float4x4 World; bool B;\n" OUT_STRUCT
        "VOut vs(float4 p : POSITION, float3 n : NORMAL) { VOut o; float4 wp = mul(p, World);\n"
        "  o.pos = wp; o.N = n; o.V = 0; if (B) o.V = Cam - wp; o.WP = wp; return o; }\n" PS_READS_ALL TECH,
        /* wp changes between the two outputs */
        "float3 Cam; float4x4 World;\n" OUT_STRUCT
        "VOut vs(float4 p : POSITION, float3 n : NORMAL) { VOut o; float4 wp = mul(p, World);\n"
        "  o.pos = wp; o.N = n; o.V = Cam - wp; wp.x += 1; o.WP = wp; return o; }\n" PS_READS_ALL TECH,
        /* V written again after */
        "float3 Cam; float4x4 World;\n" OUT_STRUCT
        "VOut vs(float4 p : POSITION, float3 n : NORMAL) { VOut o; float4 wp = mul(p, World);\n"
        "  o.pos = wp; o.N = n; o.V = Cam - wp; o.WP = wp; o.V.x *= 2; return o; }\n" PS_READS_ALL TECH,
        /* "U" reads a vertex input: not uniform-only */
        "float3 Cam; float4x4 World;\n" OUT_STRUCT
        "VOut vs(float4 p : POSITION, float3 n : NORMAL) { VOut o; float4 wp = mul(p, World);\n"
        "  o.pos = wp; o.N = n; o.V = n - wp; o.WP = wp; return o; }\n" PS_READS_ALL TECH,
        /* not affine: a product of the position with itself */
        "float3 Cam; float4x4 World;\n" OUT_STRUCT
        "VOut vs(float4 p : POSITION, float3 n : NORMAL) { VOut o; float4 wp = mul(p, World);\n"
        "  o.pos = wp; o.N = n; o.V = Cam - wp * wp; o.WP = wp; return o; }\n" PS_READS_ALL TECH,
        /* the pixel shader does not read WP */
        "float3 Cam; float4x4 World;\n" OUT_STRUCT
        "VOut vs(float4 p : POSITION, float3 n : NORMAL) { VOut o; float4 wp = mul(p, World);\n"
        "  o.pos = wp; o.N = n; o.V = Cam - wp; o.WP = wp; return o; }\n"
        "float4 ps(VOut i) : COLOR { return float4(normalize(i.V) + i.N, 1); }\n" TECH,
        /* an early return: V's statement does not always run */
        "float3 Cam; bool B;\n"
        "void vs(float4 p : POSITION, out float4 pos : POSITION, out float3 v : TEXCOORD1, out float4 wp : TEXCOORD2)\n"
        "{ pos = p; wp = p * 2; v = 0; if (B) return; v = Cam - wp.xyz; }\n"
        "float4 ps(float3 v : TEXCOORD1, float4 wp : TEXCOORD2) : COLOR { return float4(v, wp.w); }\n" TECH,
        /* different interpolation: V is centroid */
        "float3 Cam; float4x4 World;\n"
        "struct VOut { float4 pos : POSITION; float3 N : TEXCOORD0; centroid float3 V : TEXCOORD1; float3 WP : TEXCOORD2; };\n"
        "VOut vs(float4 p : POSITION, float3 n : NORMAL) { VOut o; float4 wp = mul(p, World);\n"
        "  o.pos = wp; o.N = n; o.V = Cam - wp; o.WP = wp; return o; }\n" PS_READS_ALL TECH,
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        stages s = compile(cases[i], 0);
        kept(&s);
        release(&s);
    }
}

/* D3D9 clamps interpolated colours: a COLOR output is never derived (nor derived from). */
static void colors_stay(void) {
    const char *src = "float4 Tint;\n"
        "struct VOut { float4 pos : POSITION; float4 c0 : COLOR0; float4 c1 : COLOR1; };\n"
        "VOut vs(float4 p : POSITION) { VOut o; o.pos = p; o.c0 = p; o.c1 = Tint - p; return o; }\n"
        "float4 ps(VOut i) : COLOR { return i.c0 + i.c1; }\n" TECH;
    stages s = compile(src, 0);
    CHECK(s.vs && s.fs);
    if (s.vs) CHECK_CONTAINS(s.vs, "out vec4 hfx_v_COLOR1;");
    if (s.fs) CHECK_CONTAINS(s.fs, "in vec4 hfx_v_COLOR1;");
    release(&s);
}

/* One vertex shader, two programs: one pixel shader reads WP (V is derived there), the other
 * does not (V stays); each program's text is its own, and the shared stage is not changed. */
static void shared_vertex_shader(void) {
    const char *src = "float3 Cam; float4x4 World;\n" OUT_STRUCT
        "VOut vs(float4 p : POSITION, float3 n : NORMAL) { VOut o; float4 wp = mul(p, World);\n"
        "  o.pos = wp; o.N = n; o.V = Cam - wp; o.WP = wp; return o; }\n" PS_READS_ALL
        "float4 ps2(VOut i) : COLOR { return float4(normalize(i.V) + i.N, 1); }\n"
        "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); }\n"
        "  pass Q { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps2(); }\n"
        "  pass R { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n";
    for (uint32_t program = 0; program < 2; program++) { /* R is P's program */
        stages s = compile_program(src, HFXC_PACK_UNIFORMS, program);
        if (program == 1) kept(&s);
        else derived(&s);
        release(&s);
    }
}

/* SPIR-V (OpenGL and Vulkan) of a derived varying validates: the compile's self-check runs
 * glslang on each. */
static void spirv_validates(void) {
    hfxc_options o = {0};
    o.targets = (1u << HFX_TARGET_SPIRV) | (1u << HFX_TARGET_GLSL330);
    o.flags = HFXC_PACK_UNIFORMS | HFXC_NO_WARNINGS;
    hfxc_result *r = hfxc_compile_memory(pointlights_like, strlen(pointlights_like), "varyings.fx", &o);
    CHECK(hfxc_result_ok(r));
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx && fx->programs[0].code[1][HFX_TARGET_SPIRV].size > 0);
    if (fx) CHECK(strstr(fx->programs[0].code[1][HFX_TARGET_GLSL330].data, "hfx_v_TEXCOORD1") == NULL);
    hfxc_result_free(r);
}

/* Every .fx of dir compiles and its programs link (GLSL 110 lacks what some need: the two
 * modern targets then); returns how many. */
static int folder_compiles(const char *dir, const char *skip, unsigned flags) {
    DIR *d = opendir(dir);
    int n = 0;
    for (struct dirent *e; d && (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        if (len < 4 || strcmp(e->d_name + len - 3, ".fx") != 0 || (skip && strcmp(e->d_name, skip) == 0)) continue;
        char *path = test_path_in(dir, e->d_name);
        hfxc_options o = {0};
        o.flags = flags | HFXC_NO_WARNINGS;
        unsigned targets = GLSL_ALL;
        o.targets = targets;
        hfxc_result *r = hfxc_compile_file(path, &o);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        if (!fx) {
            hfxc_result_free(r);
            o.targets = targets = 1u << HFX_TARGET_GLSL330 | 1u << HFX_TARGET_GLSLES300;
            fx = hfxc_result_effect(r = hfxc_compile_file(path, &o));
        }
        CHECK(fx != NULL);
        if (!fx) fprintf(stderr, "%s does not compile\n", path);
        for (uint32_t i = 0; fx && i < fx->program_count; i++) CHECK(links(&fx->programs[i], targets));
        hfxc_result_free(r);
        free(path);
        n++;
    }
    if (d) closedir(d);
    return n;
}

static const unsigned MODES[] = {HFXC_PACK_UNIFORMS, HFXC_PACK_UNIFORMS | HFXC_NO_PRESHADERS, 0};

static void own_effects(void) {
    for (int m = 0; m < 3; m++) CHECK(folder_compiles(HFX_SOURCE_DIR "/fx", NULL, MODES[m]) > 0);
}

static void seed_effects(void) {
    for (int m = 0; m < 3; m++) CHECK(folder_compiles(test_seed_dir(), "multilights.fx", MODES[m]) >= 10);
}

int main(void) {
    RUN(camera_minus_position);
    RUN(packed_and_preshaders);
    RUN(affine_forms);
    RUN(out_parameters);
    RUN(negative_cases);
    RUN(colors_stay);
    RUN(shared_vertex_shader);
    RUN(spirv_validates);
    RUN(own_effects);
    test_seeds_or_finish();
    RUN(seed_effects);
    return test_summary();
}
