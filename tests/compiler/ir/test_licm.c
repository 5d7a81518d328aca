/* test_licm.c: loop-invariant code motion (compiler/ir/lower/licm.c), read in the GLSL of small
 * pixel shaders: what no iteration changes is computed once into an hfx_invN local before the
 * loop; what a loop writes (directly, through an out argument, a struct member, or a global a
 * called function assigns), texture sampling and derivatives stay inside. Every target's GLSL
 * must still link. */
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "glsl_check.h"
#include "hfx/hfxc.h"
#include "test.h"

#define VS "float4 vs(float4 p : POSITION) : POSITION { return p; }\n"
#define TECH "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n"

static const unsigned ALL = (1u << HFX_TARGET_GLSL330) | (1u << HFX_TARGET_GLSLES300) | (1u << HFX_TARGET_GLSL110);

/* The GLSL 330 pixel shader of VS + body + TECH (malloc'ed), after checking each of targets
 * links; NULL when something fails. */
static char *pixel_glsl_for(const char *body, unsigned flags, unsigned targets) {
    size_t n = strlen(body) + 512;
    char *src = malloc(n), *fs = NULL;
    snprintf(src, n, "%s%s%s", VS, body, TECH);
    hfxc_options o = {0};
    o.targets = targets;
    o.flags = flags;
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "licm.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    bool ok = fx && fx->program_count == 1;
    for (int t = 0; ok && t < HFX_TARGET_COUNT; t++) {
        char *log = NULL;
        if ((targets & (1u << t)) && !test_glsl_link(fx->programs[0].code[0][t].data, fx->programs[0].code[1][t].data, &log)) {
            fprintf(stderr, "target %d rejected:\n%s\n%s\n", t, log ? log : "", fx->programs[0].code[1][t].data);
            ok = false;
        }
        free(log);
    }
    if (ok) fs = strdup(fx->programs[0].code[1][HFX_TARGET_GLSL330].data);
    else fprintf(stderr, "compile failed:\n%s\n", src);
    hfxc_result_free(r);
    free(src);
    return fs;
}

static char *pixel_glsl(const char *body, unsigned flags) { return pixel_glsl_for(body, flags, ALL); }

/* The text from the first "for (" on: what the loops evaluate (or NULL). */
static const char *loop_part(const char *fs) { return fs ? strstr(fs, "for (") : NULL; }

/* The text before the first "for (": what runs once. */
static bool before_loop(const char *fs, const char *what) {
    const char *at = fs ? strstr(fs, what) : NULL, *loop = loop_part(fs);
    return at && loop && at < loop;
}

static void invariant_normalize_moves_out(void) {
    char *fs = pixel_glsl("int count;\n"
                          "float4 ps(float3 N : TEXCOORD0) : COLOR { float s = 0;\n"
                          "  for (int i = 0; i < count; i++) s += dot(normalize(N), float3(i, 1, 0));\n"
                          "  return s; }\n", 0);
    CHECK(fs != NULL);
    CHECK(before_loop(fs, "vec3 hfx_inv0 = normalize(N);"));
    CHECK_CONTAINS(loop_part(fs), "dot(hfx_inv0, vec3(float(i), 1.0, 0.0))");
    CHECK(loop_part(fs) && !strstr(loop_part(fs), "normalize"));
    free(fs);
}

/* N written in the loop, directly or as an inout argument: normalize(N) changes. */
static void written_operand_stays(void) {
    char *fs = pixel_glsl("int count;\n"
                          "float4 ps(float3 N : TEXCOORD0) : COLOR { float s = 0;\n"
                          "  for (int i = 0; i < count; i++) { s += length(normalize(N)); N = N * 0.5; }\n"
                          "  return s; }\n", 0);
    CHECK(fs && !strstr(fs, "hfx_inv"));
    CHECK_CONTAINS(loop_part(fs), "normalize(N)");
    free(fs);
    fs = pixel_glsl("int count;\nvoid halve(inout float3 v) { v *= 0.5; }\n"
                    "float4 ps(float3 N : TEXCOORD0) : COLOR { float s = 0;\n"
                    "  for (int i = 0; i < count; i++) { s += length(normalize(N)); halve(N); }\n"
                    "  return s; }\n", 0);
    CHECK(fs && !strstr(fs, "hfx_inv"));
    CHECK_CONTAINS(loop_part(fs), "normalize(N)");
    free(fs);
}

/* A struct member or a swizzle written, and a global a called function assigns. */
static void members_and_globals_written_stay(void) {
    char *fs = pixel_glsl("int count;\nstruct In { float3 N : TEXCOORD0; };\n"
                          "float4 ps(In v) : COLOR { float s = 0;\n"
                          "  for (int i = 0; i < count; i++) { s += length(normalize(v.N)); v.N.x += 1; }\n"
                          "  return s; }\n", 0);
    CHECK(fs && !strstr(fs, "hfx_inv"));
    free(fs);
    fs = pixel_glsl("int count;\nstatic float3 g = float3(1, 2, 3);\nvoid bump() { g.y += 1; }\n"
                    "float4 ps() : COLOR { float s = 0;\n"
                    "  for (int i = 0; i < count; i++) { s += length(g * 2); bump(); }\n"
                    "  return s; }\n", 0);
    CHECK(fs && !strstr(fs, "hfx_inv"));
    CHECK_CONTAINS(loop_part(fs), "length(");
    free(fs);
}

/* Sampling and derivatives stay where they are; the coordinate's arithmetic moves out. */
static void sampling_and_derivatives_stay(void) {
    char *fs = pixel_glsl("int count; sampler2D S;\n"
                          "float4 ps(float2 uv : TEXCOORD0) : COLOR { float4 s = 0;\n"
                          "  for (int i = 0; i < count; i++) s += tex2D(S, uv * 2) + ddx(uv.x);\n"
                          "  return s; }\n", 0);
    CHECK(fs != NULL);
    CHECK(before_loop(fs, "vec2 hfx_inv0 = uv * vec2(2.0);"));
    CHECK_CONTAINS(loop_part(fs), "texture(S, hfx_inv0)");
    CHECK_CONTAINS(loop_part(fs), "dFdx(uv.x)");
    CHECK(!before_loop(fs, "texture("));
    free(fs);
}

/* The inner loop's invariant, length(N) * sqrt(i), stops between the loops (i changes in the
 * outer one); its length(N) part leaves the outer loop too. */
static void nested_loops(void) {
    char *fs = pixel_glsl("int count;\n"
                          "float4 ps(float3 N : TEXCOORD0) : COLOR { float s = 0;\n"
                          "  for (int i = 0; i < count; i++) for (int j = 0; j < count; j++)\n"
                          "    s += length(N) * sqrt((float)i) + j;\n"
                          "  return s; }\n", 0);
    CHECK(fs != NULL);
    CHECK(before_loop(fs, "float hfx_inv1 = length(N);"));
    const char *outer = loop_part(fs), *inner = outer ? strstr(outer + 1, "for (") : NULL;
    const char *between = outer ? strstr(outer, "float hfx_inv0 = hfx_inv1 * sqrt(abs(float(i)));") : NULL;
    CHECK(between && inner && between < inner);
    CHECK_CONTAINS(inner, "s += hfx_inv0 + float(j);");
    free(fs);
}

/* A loop as an if's whole branch or among a switch's cases: its locals get a block. */
static void loops_outside_blocks(void) {
    char *fs = pixel_glsl_for("int count;\n"
                              "float4 ps(float3 N : TEXCOORD0) : COLOR { float s = 0;\n"
                              "  if (count > 1) for (int i = 0; i < count; i++) s += length(N) * i;\n"
                              "  switch (count) { case 2: for (int j = 0; j < 2; j++) s += length(N) * j; break;\n"
                              "    default: s += 1; }\n" /* GLSL 110 has no switch */
                              "  return s; }\n", 0, ALL & ~(1u << HFX_TARGET_GLSL110));
    CHECK(fs != NULL);
    CHECK_CONTAINS(fs, "    {\n        float hfx_inv0 = length(N);\n        for (int i = 0;");
    CHECK_CONTAINS(fs, "    {\n            float hfx_inv1 = length(N);\n            for (int j = 0;");
    free(fs);
}

/* Parameter-only work in a loop still becomes a preshader (computed on the CPU); a term added
 * as it is would go before the loop whole (lower/sums.c), so this one is multiplied. */
static void preshaders_still_taken(void) {
    char *fs = pixel_glsl("int count; float4 A; float k;\n"
                          "float4 ps(float3 N : TEXCOORD0) : COLOR { float4 s = 0;\n"
                          "  for (int i = 0; i < count; i++) s += A * k * i;\n"
                          "  return s; }\n", HFXC_PACK_UNIFORMS);
    CHECK(fs != NULL);
    CHECK_CONTAINS(fs, "vec4 hfx_pre0; // hfx_c[0] = (A * (float4)k), computed on the CPU");
    CHECK(before_loop(fs, "vec4 hfx_inv0 = hfx_pre0;"));
    free(fs);
}

int main(void) {
    RUN(invariant_normalize_moves_out);
    RUN(written_operand_stays);
    RUN(members_and_globals_written_stay);
    RUN(sampling_and_derivatives_stay);
    RUN(nested_loops);
    RUN(loops_outside_blocks);
    RUN(preshaders_still_taken);
    return test_summary();
}
