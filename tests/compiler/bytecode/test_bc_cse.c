/* test_bc_cse.c: the passes that make hfx's ps_2_0 code as short as fxc's (compiler/bytecode/
 * bc_cse.c: values computed twice, read once; bc_vec.c: per-component operations on one register
 * as one; bc_ports.c: literals one instruction reads gathered into one def). Shaders compiled
 * through the fxc path (/T ps_2_0 /E main) and their code compared as exact text, each line
 * worked out by hand in a comment; the literal gathering on a hand-made instruction list. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bytecode/bc_int.h"
#include "hfx/hfxc.h"
#include "test.h"

/* The listing's code, from the version line on. */
static char *code_of(const char *src) {
    hfxc_options o = {.entry = "main", .profile = "ps_2_0"};
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "t.fx", &o);
    size_t size = 0;
    const void *code = hfxc_result_bytecode(r, &size);
    char *text = NULL;
    if (hfxc_result_ok(r) && code) {
        char *diags = NULL;
        text = hfxc_disassemble(code, size, "t.pso", &diags);
        free(diags);
    } else text = hfxc_diagnostics_text(r);
    hfxc_result_free(r);
    char *at = text ? strstr(text, "\n    ") : NULL;
    char *out = strdup(at ? at + 1 : text ? text : "");
    free(text);
    return out;
}

static void code_is(const char *src, const char *want) {
    char *text = code_of(src);
    CHECK_STR(text, want);
    free(text);
}

/* float2(-o.x, -o.y) and float2(-o.x, o.y) are built by the generator as copies, one component
 * each. The first is o under a negation: the add reads -r0 itself (the copy goes). The second's
 * two copies become one mul of o by (-1, 1) (x * -1 is -x, x * 1 is x, to the bit), which the
 * add after it takes as a mad: 6 arithmetic slots, where the copies took 9. */
static void negated_copies_read_in_place(void) {
    code_is("float2 Size;\nsampler S;\n"
            "float4 main(float2 uv : TEXCOORD0) : COLOR0 {\n    float2 o = 1 / Size;\n"
            "    return tex2D(S, uv + float2(-o.x, -o.y)) + tex2D(S, uv + float2(-o.x, o.y));\n}\n",
            "    ps_2_0\n"
            "    def c1, 0, 1, -1, 0\n"
            "    dcl t0.xy\n"
            "    dcl_2d s0\n"
            "    rcp r0.x, c0.x\n"            /* o = 1 / Size, one component at a time (rcp is scalar) */
            "    rcp r0.y, c0.y\n"
            "    add r1.xy, t0, -r0\n"        /* uv + (-o.x, -o.y) */
            "    texld r2, r1, s0\n"
            "    mad r0.xy, r0, c1.zyzw, t0\n" /* o * (-1, 1) + uv: c1.z = -1 in x, c1.y = 1 in y */
            "    texld r1, r0, s0\n"
            "    add r0, r2, r1\n"
            "    mov oC0, r0\n"
            "\n// approximately 8 instruction slots used (2 texture, 6 arithmetic)\n");
}

/* A blur tap's offset float2(Pos, 0) is written twice (for + and -): the second pair of movs
 * holds what r0 holds already, so the second mad reads r0: 6 arithmetic slots, not 8. (The mov
 * of Pos is ps_2_0's one constant read port: the mad reads Blur.) */
static void offset_built_once(void) {
    code_is("float Pos;\nfloat Blur;\nsampler S;\n"
            "float4 main(float2 uv : TEXCOORD0) : COLOR0 {\n"
            "    return tex2D(S, uv + float2(Pos, 0) * Blur) + tex2D(S, uv - float2(Pos, 0) * Blur);\n}\n",
            "    ps_2_0\n"
            "    def c2, 0, 0, 0, 0\n"
            "    dcl t0.xy\n"
            "    dcl_2d s0\n"
            "    mov r0.x, c0.x\n"             /* float2(Pos, 0) */
            "    mov r0.y, c2.x\n"
            "    mad r1.xy, r0, c1.x, t0\n"    /* uv + (Pos, 0) * Blur */
            "    texld r2, r1, s0\n"
            "    mad r0.xy, -r0, c1.x, t0\n"   /* uv - (Pos, 0) * Blur, from the same r0 */
            "    texld r1, r0, s0\n"
            "    add r0, r2, r1\n"
            "    mov oC0, r0\n"
            "\n// approximately 8 instruction slots used (2 texture, 6 arithmetic)\n");
}

/* sin(Time * 3 + uv.x) twice: one range reduction and one sincos (8 slots in ps_2_0): 17
 * arithmetic slots where the two took 30. */
static void sine_computed_once(void) {
    char *text = code_of("float Time;\n"
                         "float4 main(float2 uv : TEXCOORD0) : COLOR0 {\n    float a = sin(Time * 3 + uv.x);\n"
                         "    float b = sin(Time * 3 + uv.x) * 0.5;\n    return float4(a, b, 0, 1);\n}\n");
    const char *first = strstr(text, "sincos");
    CHECK(first != NULL);
    CHECK(first && strstr(first + 1, "sincos") == NULL);
    CHECK(strstr(text, "    mov r0.x, r1.y\n    mul r0.y, r0.x, c1.z\n") != NULL); /* a, and b = the same sine * 0.5 (c1.z) */
    CHECK(strstr(text, "(0 texture, 17 arithmetic)") != NULL);
    free(text);
}

/* Both sides of the if compute x * y + 1: the second is the first (one mad), and the select
 * between two equal values is that value (no cmp; B leaves the table). The mov is ps_2_0's one
 * t read port (the mad reads t0 and t1). */
static void equal_sides_selected_once(void) {
    code_is("bool B;\n"
            "float4 main(float4 x : TEXCOORD0, float4 y : TEXCOORD1) : COLOR0 {\n"
            "    float4 c;\n    if (B) c = x * y + 1; else c = x * y + 1;\n    return c;\n}\n",
            "    ps_2_0\n"
            "    def c1, 0, 1, 0, 0\n"
            "    dcl t0\n"
            "    dcl t1\n"
            "    mov r0, t0\n"
            "    mad r0, r0, t1, c1.y\n"
            "    mov oC0, r0\n"
            "\n// approximately 3 instruction slots used (0 texture, 3 arithmetic)\n");
}

/* --- literals gathered, on a hand-made list --- */

/* `cmp r0.x, r1.x, c3.z, c2.w` reads 1 and 0 from two def registers (ps_2_0: one constant read
 * port): they are read from one def holding both instead of a copy into a temporary. c2 is
 * full, so the pair takes the next free register, c4 = (1, 0, ...). */
static void literals_from_one_def(void) {
    hfx_arena arena;
    hfx_arena_init(&arena);
    ir_ctx c;
    memset(&c, 0, sizeof c);
    c.arena = &arena;
    bc_gen g;
    memset(&g, 0, sizeof g);
    g.c = &c;
    g.stage = D3D9_PS;
    g.model = D3D9_SM(2, 0);
    g.max_consts = 32;
    bc_def defs[2] = {{{0.2f, 0.7f, 0.1f, 0}, 4, 2}, {{0.5f, 2, 1, 3}, 4, 3}};
    g.defs = defs;
    g.def_count = g.def_cap = 2;
    g.cused[2] = g.cused[3] = 1;
    d3d9_inst cmp;
    memset(&cmp, 0, sizeof cmp);
    cmp.op = D3D9_CMP;
    cmp.has_dst = true;
    cmp.dst = (d3d9_dst){.type = D3D9_REG_TEMP, .num = 0, .mask = 1};
    cmp.src[0] = (d3d9_src){.type = D3D9_REG_TEMP, .num = 1, .swizzle = 0x00};
    cmp.src[1] = (d3d9_src){.type = D3D9_REG_CONST, .num = 3, .swizzle = 0xaa}; /* c3.z = 1 */
    cmp.src[2] = (d3d9_src){.type = D3D9_REG_CONST, .num = 2, .swizzle = 0xff}; /* c2.w = 0 */
    cmp.src_count = 3;
    g.insts = &cmp;
    g.inst_count = g.inst_cap = 1;
    hfx_bc_gather_literals(&g);
    CHECK(!g.failed);
    CHECK_INT(g.def_count, 3);
    CHECK_INT(g.defs[2].num, 0);             /* the first free c register */
    CHECK(g.defs[2].used == 2 && g.defs[2].v[0] == 1 && g.defs[2].v[1] == 0);
    CHECK_INT(cmp.src[1].num, 0);
    CHECK_INT(cmp.src[1].swizzle, 0x00);     /* .x: 1 */
    CHECK_INT(cmp.src[2].num, 0);
    CHECK_INT(cmp.src[2].swizzle, 0x55);     /* .y: 0 */
    CHECK_INT(hfx_d3d9_port_excess(g.stage, g.model, &cmp, &(unsigned){0}), -1);
    hfx_arena_free(&arena);
}

/* pow of a float3 (fxc's three lights' specular): pow is a three-slot macro per component (9
 * slots); a log per component, one mul by the exponents and an exp per component are 7. */
static void vector_pow_by_log_and_exp(void) {
    code_is("float3 E;\n"
            "float4 main(float3 b : TEXCOORD0) : COLOR0 { return float4(pow(b, E), 1); }\n",
            "    ps_2_0\n"
            "    def c1, 1, 0, 0, 0\n"
            "    dcl t0.xyz\n"
            "    log r0.x, t0.x\n"          /* log2 |b| per component */
            "    log r0.y, t0.y\n"
            "    log r0.z, t0.z\n"
            "    mul r0.xyz, r0, c0\n"      /* times E (c0) */
            "    exp r1.x, r0.x\n"          /* 2^(E log2 |b|) = |b|^E */
            "    exp r1.y, r0.y\n"
            "    exp r1.z, r0.z\n"
            "    mov r1.w, c1.x\n"          /* the 1 */
            "    mov oC0, r1\n"
            "\n// approximately 9 instruction slots used (0 texture, 9 arithmetic)\n");
}

/* A normalized vector only adds read (v = normalize(E - p), then v - L0, v - L1: half vectors):
 * nrm's mul by rsq(dot(x, x)) goes into the adds as mads, as fxc writes it: dp3 / rsq, then
 * mad r1 = (E - p) * rsq - L0 (c1) and the same - L1 (c2). 15 slots (the nrm and two adds were
 * 5 of 16). */
static void normalize_folded_into_adds(void) {
    code_is("float3 E, L0, L1;\n"
            "float4 main(float3 p : TEXCOORD0, float3 n : TEXCOORD1) : COLOR0 {\n"
            "    float3 v = normalize(E - p);\n"
            "    float3 h0 = normalize(v - L0);\n"
            "    float3 h1 = normalize(v - L1);\n"
            "    return float4(dot(h0, n), dot(h1, n), 0, 1);\n}\n",
            "    ps_2_0\n"
            "    def c3, 0, 1, 0, 0\n"
            "    dcl t0.xyz\n"
            "    dcl t1.xyz\n"
            "    add r0.xyz, c0, -t0\n"     /* E - p */
            "    dp3 r0.w, r0, r0\n"        /* |E - p|^2 */
            "    rsq r0.w, r0.w\n"
            "    mad r1.xyz, r0, r0.w, -c1\n" /* v - L0 */
            "    nrm r2.xyz, r1\n"          /* h0: read by a dp3, kept as nrm */
            "    mad r0.xyz, r0, r0.w, -c2\n" /* v - L1 */
            "    nrm r1.xyz, r0\n"
            "    dp3 r0.x, r2, t1\n"
            "    dp3 r0.y, r1, t1\n"
            "    mov r0.zw, c3.xyxy\n"      /* (0, 1) */
            "    mov oC0, r0\n"
            "\n// approximately 15 instruction slots used (0 texture, 15 arithmetic)\n");
}

int main(void) {
    RUN(negated_copies_read_in_place);
    RUN(offset_built_once);
    RUN(sine_computed_once);
    RUN(equal_sides_selected_once);
    RUN(literals_from_one_def);
    RUN(vector_pow_by_log_and_exp);
    RUN(normalize_folded_into_adds);
    return test_summary();
}
