/* test_bytecode.c: hfx's D3D9 bytecode back end through the library's fxc path (/T, /E): fxc's
 * listing of hand-written shaders as exact text (each instruction worked out by hand from the
 * D3D9 instruction definitions: column_major matrices in column registers, mul(v, M) as one dp4
 * per column, a product plus a constant as one mad, saturate folded into the instruction, clip as
 * texkill of a register, comparisons as cmp), and the model's limits refused with their errors. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bc_listing.h"
#include "hfx/hfxc.h"
#include "test.h"


static const char header[] = BC_LISTING_HEAD "// Parameters:\n//\n";

static void listing(const char *src, const char *profile, const char *params, const char *body) {
    bool ok;
    char *text = bc_listing(src, profile, &ok);
    CHECK(ok);
    char *want = malloc(strlen(header) + strlen(params) + strlen(body) + 1);
    strcpy(want, header);
    strcat(want, params);
    strcat(want, body);
    CHECK_STR(text, want);
    free(want);
    free(text);
}

static void vs_2_0_transform_and_mad(void) {
    listing("float4x4 WorldViewProj;\nfloat4 Tint;\n"
            "void main(float4 p : POSITION, float2 uv : TEXCOORD0, out float4 oPos : POSITION, out float2 oUv : TEXCOORD0,\n"
            "          out float4 oCol : COLOR0) {\n"
            "    oPos = mul(p, WorldViewProj);\n    oUv = uv;\n    oCol = Tint * 0.5 + 0.25;\n}\n",
            "vs_2_0",
            "//   float4 Tint;\n//   float4x4 WorldViewProj;\n//\n//\n// Registers:\n//\n"
            "//   Name          Reg   Size\n//   ------------- ----- ----\n"
            "//   WorldViewProj c0       4\n//   Tint          c4       1\n//\n\n",
            "    vs_2_0\n"
            "    def c5, 0.5, 0.25, 0, 0\n"
            "    dcl_position v0\n"
            "    dcl_texcoord v1\n"
            "    dp4 oPos.x, v0, c0\n"      /* column 0 of the column_major matrix */
            "    dp4 oPos.y, v0, c1\n"
            "    dp4 oPos.z, v0, c2\n"
            "    dp4 oPos.w, v0, c3\n"
            "    mov r0.xy, c5\n"           /* vs_2_0 reads one c register an instruction: of Tint (c4) */
            "    mad oD0, c4, r0.x, r0.y\n" /* and the def (c5) the cheaper copied, its .xy read */
            "    mov oT0.xy, v1\n"          /* Tint * 0.5 + 0.25 */
            "\n// approximately 7 instruction slots used\n");
}

static void ps_2_0_clip_and_saturate(void) {
    listing("sampler S;\nfloat4 Cut;\n"
            "float4 main(float2 uv : TEXCOORD0, float4 c : COLOR0) : COLOR0 {\n"
            "    float4 t = tex2D(S, uv);\n    clip(t.a - 0.5);\n    return saturate(t * c + Cut);\n}\n",
            "ps_2_0",
            "//   float4 Cut;\n//   sampler2D S;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   S            s0       1\n//   Cut          c0       1\n//\n\n",
            "    ps_2_0\n"
            "    def c1, 0, 0.5, 0, 0\n"
            "    dcl t0.xy\n"
            "    dcl v0\n"
            "    dcl_2d s0\n"
            "    texld r0, t0, s0\n"
            "    add r1, r0.w, -c1.y\n"     /* t.a - 0.5 into all of r1: texkill tests its x, y and z */
            "    texkill r1\n"
            "    mad_sat r0, r0, v0, c0\n"  /* reads t, then writes its register */
            "    mov oC0, r0\n"
            "\n// approximately 5 instruction slots used (2 texture, 3 arithmetic)\n");
}

static void ps_3_0_reflect_pow_select(void) {
    listing("float3 L;\nfloat Power;\n"
            "float4 main(float3 n : TEXCOORD0, float3 v : TEXCOORD1) : COLOR0 {\n"
            "    float3 N = normalize(n);\n    float d = dot(N, L);\n"
            "    float s = pow(saturate(dot(reflect(-L, N), v)), Power);\n"
            "    return float4(d > 0 ? s : 0, d, 0, 1);\n}\n",
            "ps_3_0",
            "//   float3 L;\n//   float Power;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   L            c0       1\n//   Power        c1       1\n//\n\n",
            "    ps_3_0\n"
            "    def c2, 0, 1, 0, 0\n"
            "    dcl_texcoord v0.xyz\n"
            "    dcl_texcoord1 v1.xyz\n"
            "    nrm r0.xyz, v0\n"
            "    dp3 r0.w, r0, c0\n"               /* d, packed beside N (r0.w is free) */
            "    dp3 r1.x, r0, -c0\n"              /* reflect(i = -L, N): dot(N, i) */
            "    add r1.x, r1.x, r1.x\n"           /* 2 dot(N, i) */
            "    mad r0.xyz, r0, -r1.x, -c0\n"     /* i - 2 dot(N, i) N, over N (read first), d kept in .w */
            "    dp3_sat r0.x, r0, v1\n"
            "    pow r0.x, r0.x, c1.x\n"
            "    cmp oC0.x, -r0.w, c2.x, r0.x\n"   /* d > 0 ? s : 0 is 0 - d < 0 (0 - d folded to -d): (-d >= 0) ? 0 : s */
            "    mov oC0.y, r0.w\n"
            "    mov oC0.zw, c2.xyxy\n"
            "\n// approximately 14 instruction slots used (0 texture, 14 arithmetic)\n");
}

/* A loop bounded by a parameter in ps_3_0, as fxc writes it: the counter i in a temporary tested
 * against N by break_ge at the top of each pass; aL runs 0, 1, 2... (defi: 255 passes at most,
 * start 0, step 1) so Col[i] is c[aL + 1]; slots: loop 3, break_comp 3, endloop 2, the rest 1. */
static void ps_3_0_parameter_loop(void) {
    listing("int N;\nfloat4 Col[8];\n"
            "float4 main(float2 uv : TEXCOORD0) : COLOR0 {\n    float4 c = 0;\n"
            "    for (int i = 0; i < N; i++) c += Col[i] * uv.x;\n    return c;\n}\n",
            "ps_3_0",
            "//   float4 Col[8];\n//   int N;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   N            c0       1\n//   Col          c1       8\n//\n\n",
            "    ps_3_0\n"
            "    def c9, 0, 1, 0, 0\n"
            "    defi i0, 255, 0, 1, 0\n"
            "    dcl_texcoord v0.xy\n"
            "    mov r0.x, c9.x\n"              /* i = 0 */
            "    mov r1, c9.x\n"                /* c = 0 */
            "    loop aL, i0\n"
            "      break_ge r0.x, c0.x\n"       /* leaves when !(i < N) */
            "      mad r1, c1[aL], v0.x, r1\n"  /* c += Col[i] * uv.x */
            "      add r0.x, r0.x, c9.y\n"      /* i++ */
            "    endloop\n"
            "    mov oC0, r1\n"
            "\n// approximately 13 instruction slots used (0 texture, 13 arithmetic)\n");
}

/* A while loop with a break in ps_3_0: `rep` over defi's 255 passes (no counter for aL to
 * follow), the condition as break_ge at the top (x.x < Limit negated), `if (x.y > 2) break;` as
 * one break_gt; slots: rep 3, break_comp 3 each, endrep 2. x lives in r0 across the loop: its
 * new value (r1) goes back to r0 before the break and at the pass's end, two movs fxc would
 * not need (the copies' sinking stops at the break; left for later), 16 slots in all. */
static void ps_3_0_while_break(void) {
    listing("float4 K;\nfloat Limit;\n"
            "float4 main(float4 c : COLOR0) : COLOR0 {\n    float4 x = c;\n"
            "    while (x.x < Limit) {\n        x += K;\n        if (x.y > 2) break;\n    }\n    return x;\n}\n",
            "ps_3_0",
            "//   float4 K;\n//   float Limit;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   Limit        c0       1\n//   K            c1       1\n//\n\n",
            "    ps_3_0\n"
            "    def c2, 0, 2, 0, 0\n"
            "    defi i0, 255, 0, 0, 0\n"
            "    dcl_color v0\n"
            "    mov r0, v0\n"
            "    rep i0\n"
            "      break_ge r0.x, c0.x\n"
            "      add r1, r0, c1\n"
            "      mov r0, r1\n"
            "      break_gt r1.y, c2.y\n"
            "      mov r0, r1\n"
            "    endrep\n"
            "    mov oC0, r0\n"
            "\n// approximately 16 instruction slots used (0 texture, 16 arithmetic)\n");
}

/* vs_2_0's static loop: `rep i0` runs Count's i register (INT4 in the CTAB) times; the counter,
 * which nothing reads, is not kept. Slots: rep 3, endrep 2. */
static void vs_2_0_static_loop(void) {
    listing("int Count;\nfloat4 Offset;\n"
            "float4 main(float4 p : POSITION) : POSITION {\n    float4 x = p;\n"
            "    for (int i = 0; i < Count; i++) x += Offset;\n    return x;\n}\n",
            "vs_2_0",
            "//   int Count;\n//   float4 Offset;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   Offset       c1       1\n//   Count        i0       1\n//\n\n",
            "    vs_2_0\n"
            "    dcl_position v0\n"
            "    mov r0, v0\n"
            "    rep i0\n"
            "      add r0, r0, c1\n"
            "    endrep\n"
            "    mov oPos, r0\n"
            "\n// approximately 8 instruction slots used\n");
}

/* `register(vs, c3) : register(ps, c1)` (FNA's stock effects write every parameter so): each
 * stage takes its own reservation; a parameter without one takes the first register no
 * parameter reserves for that stage (c0 here, though A and B come first). Before, the last
 * reservation written served both stages: A at c1 in the vertex shader, on top of B. */
static void per_stage_registers(void) {
    static const char src[] = "float4 A : register(vs, c3) : register(ps, c1);\nfloat4 B : register(vs, c1);\nfloat4 C;\n"
                              "float4 main(float4 p : POSITION) : POSITION { return p * A + B + C; }\n";
    static const char ps_src[] = "float4 A : register(vs, c3) : register(ps, c1);\nfloat4 C;\n"
                                 "float4 main(float4 c : COLOR0) : COLOR0 { return c * A + C; }\n";
    listing(ps_src, "ps_2_0",
            "//   float4 A;\n//   float4 C;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   A            c1       1\n//   C            c0       1\n//\n\n",
            "    ps_2_0\n"
            "    dcl v0\n"
            "    mov r0, c1\n"           /* ps_2_0 reads one c register an instruction: A first of two alike */
            "    mad r0, v0, r0, c0\n"   /* c * A + C */
            "    mov oC0, r0\n"
            "\n// approximately 3 instruction slots used (0 texture, 3 arithmetic)\n");
    listing(src, "vs_2_0",
            "//   float4 A;\n//   float4 B;\n//   float4 C;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   A            c3       1\n//   B            c1       1\n//   C            c0       1\n//\n\n",
            "    vs_2_0\n"
            "    dcl_position v0\n"
            "    mov r0, c3\n"         /* vs_2_0's one c register an instruction: A copied */
            "    mad r0, v0, r0, c1\n" /* p * A + B */
            "    add oPos, r0, c0\n"   /* + C */
            "\n// approximately 3 instruction slots used\n");
}

/* A select on a comparison in a pixel shader is one cmp on the difference, as fxc writes it:
 * a < K.x ? K.z : K.w is (a - K.x >= 0) ? K.w : K.z, and clip's scalar is computed into the
 * whole register texkill tests (its sources' .x / .w / .z replicated), no mov between; x >= A.x
 * ? c : B is (x - A.x >= 0) ? c : B. Before: the comparison's 0 / 1 (add, cmp), a cmp on it, and
 * clip's mov r1, r1.x (2 more slots each). */
static void ps_2_0_compare_select(void) {
    listing("sampler S;\nfloat4 K;\nfloat4 main(float2 uv : TEXCOORD0) : COLOR0 {\n"
            "    float4 c = tex2D(S, uv);\n    clip(c.a < K.x ? K.z : K.w);\n    return c;\n}\n",
            "ps_2_0",
            "//   float4 K;\n//   sampler2D S;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   S            s0       1\n//   K            c0       1\n//\n\n",
            "    ps_2_0\n"
            "    dcl t0.xy\n"
            "    dcl_2d s0\n"
            "    texld r0, t0, s0\n"
            "    add r1.x, r0.w, -c0.x\n"    /* c.a - K.x */
            "    cmp r1, r1.x, c0.w, c0.z\n" /* >= 0: K.w, else K.z; all four components */
            "    texkill r1\n"
            "    mov oC0, r0\n"
            "\n// approximately 5 instruction slots used (2 texture, 3 arithmetic)\n");
    listing("float4 A;\nfloat4 B;\nfloat4 main(float4 c : COLOR0) : COLOR0 {\n    return c.x >= A.x ? c : B;\n}\n",
            "ps_2_0",
            "//   float4 A;\n//   float4 B;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   A            c0       1\n//   B            c1       1\n//\n\n",
            "    ps_2_0\n"
            "    dcl v0\n"
            "    add r0.x, v0.x, -c0.x\n" /* c.x - A.x */
            "    cmp r0, r0.x, v0, c1\n"  /* >= 0: c, else B */
            "    mov oC0, r0\n"
            "\n// approximately 3 instruction slots used (0 texture, 3 arithmetic)\n");
}

/* normalize into an output: nrm's macro written out, dp3 / rsq / mul, the mul writing oT0 (3
 * slots, where nrm is 3 and a mov into oT0 a fourth); the length's square and its rsq take r0.w
 * beside the vector, as fxc's `dp3 r0.w, r0, r0` / `rsq r0.w, r0.w` / `mul oT1.xyz, r0.w, r0`. */
static void vs_2_0_normalize_output(void) {
    listing("float3x3 W;\nvoid main(float4 p : POSITION, float3 n : NORMAL, out float4 oPos : POSITION,\n"
            "          out float3 oN : TEXCOORD0) {\n    oPos = p;\n    oN = normalize(mul(n, W));\n}\n",
            "vs_2_0",
            "//   float3x3 W;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   W            c0       3\n//\n\n",
            "    vs_2_0\n"
            "    dcl_position v0\n"
            "    dcl_normal v1\n"
            "    dp3 r0.x, v1, c0\n" /* mul(n, W): a dp3 per column register */
            "    dp3 r0.y, v1, c1\n"
            "    dp3 r0.z, v1, c2\n"
            "    dp3 r0.w, r0, r0\n" /* |v|^2 */
            "    rsq r0.w, r0.w\n"
            "    mul oT0.xyz, r0.w, r0\n"
            "    mov oPos, v0\n"
            "\n// approximately 7 instruction slots used\n");
}

/* A product kept in a variable and added afterwards is one mad (the mul and the add of a plain
 * walk: 4 slots; EnvironmentMapEffect's envmap * alpha - color, fxc's `mad r0.xyz, r0, r1.w, -r1`). */
static void ps_2_0_product_then_add(void) {
    listing("sampler S;\nfloat4 K;\nfloat4 main(float2 uv : TEXCOORD0, float4 c : COLOR0) : COLOR0 {\n"
            "    float4 e = tex2D(S, uv) * c.a;\n    return e - K;\n}\n",
            "ps_2_0",
            "//   float4 K;\n//   sampler2D S;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   S            s0       1\n//   K            c0       1\n//\n\n",
            "    ps_2_0\n"
            "    dcl t0.xy\n"
            "    dcl v0\n"
            "    dcl_2d s0\n"
            "    texld r0, t0, s0\n"
            "    mad r0, r0, v0.w, -c0\n" /* tex * c.a - K */
            "    mov oC0, r0\n"
            "\n// approximately 3 instruction slots used (1 texture, 2 arithmetic)\n");
}

/* tex1D: D3D9 has no 1D textures (the sampler is declared 2D, texld reads .xy), so the
 * coordinate is (x, 0.5), the middle row of the 2D texture standing for the 1D one, as the GLSL
 * back end samples it; .y must be written (MojoShader's GLSL read it uninitialised). */
static void ps_2_0_tex1d(void) {
    listing("sampler1D S;\nfloat4 main(float x : TEXCOORD0) : COLOR0 { return tex1D(S, x); }\n", "ps_2_0",
            "//   sampler1D S;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   S            s0       1\n//\n\n",
            "    ps_2_0\n"
            "    def c0, 0.5, 0, 0, 0\n"
            "    dcl t0.x\n"
            "    dcl_2d s0\n"             /* D3D9's sampler types: 2D, cube, volume */
            "    mov r0.x, t0.x\n"        /* ps_2_0 samples at a temporary with no swizzle */
            "    mov r0.y, c0.x\n"        /* the row: 0.5 */
            "    texld r1, r0, s0\n"
            "    mov oC0, r1\n"
            "\n// approximately 4 instruction slots used (1 texture, 3 arithmetic)\n");
}

/* A sampler array is one run of s registers named once in the CTAB: element k at the first + k,
 * up to the last element read (D3DX binds element k of the parameter to register first + k). S[2]
 * read first opens the run s0..s2; A, read next, takes s3. */
static void ps_2_0_sampler_array(void) {
    listing("sampler2D A;\nsampler2D S[4];\n"
            "float4 main(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(S[2], uv) + tex2D(A, uv); }\n", "ps_2_0",
            "//   sampler2D A;\n//   sampler2D S[4];\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   S            s0       3\n//   A            s3       1\n//\n\n",
            "    ps_2_0\n"
            "    dcl t0.xy\n"
            "    dcl_2d s2\n"
            "    dcl_2d s3\n"
            "    texld r0, t0, s2\n"
            "    texld r1, t0, s3\n"
            "    add r0, r0, r1\n"
            "    mov oC0, r0\n"
            "\n// approximately 4 instruction slots used (2 texture, 2 arithmetic)\n");
}

/* `int i; for (i = 0; ...)`: a counter declared before the loop is unrolled as one declared in it
 * (ps_2_0 has no loops), and the code after the loop reads its last value: s = 4 * 0.25 = 1,
 * i = 4, i / 4.0 = 1, so the pixel is K * (1, 1, 4, 1). */
static void ps_2_0_counter_after_loop(void) {
    listing("float4 K;\nfloat4 main() : COLOR0 { int i; float s = 0; for (i = 0; i < 4; i++) s += 0.25; "
            "return K * float4(s, i / 4.0, i, 1); }\n",
            "ps_2_0",
            "//   float4 K;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   K            c0       1\n//\n\n",
            "    ps_2_0\n"
            "    def c1, 0, 0.25, 4, 1\n"
            "    mov r0, c1.wwzw\n"   /* (1, 1, 4, 1) */
            "    mul r0, c0, r0\n"
            "    mov oC0, r0\n"
            "\n// approximately 3 instruction slots used (0 texture, 3 arithmetic)\n");
}

/* Registers given by hand may overlap, as FNA's stock effects place WorldInverseTranspose at c19
 * inside a float4x4 World at c16: each table entry ends at the last register its own code
 * reads (World's columns 0..2 for a position's xyz: c0..c2, Size 3), never inside the next
 * parameter's, or a loader would upload World's fourth column over WIT's first row. */
static void vs_2_0_overlapping_registers(void) {
    listing("float4x4 World : register(c0);\nfloat3x3 WIT : register(c3);\n"
            "void main(float4 p : POSITION, float3 n : NORMAL, out float4 oPos : POSITION, out float3 oN : TEXCOORD0) {\n"
            "    oPos = float4(mul(p, World).xyz, 1);\n    oN = mul(n, WIT);\n}\n",
            "vs_2_0",
            "//   float3x3 WIT;\n//   float4x4 World;\n//\n//\n// Registers:\n//\n"
            "//   Name         Reg   Size\n//   ------------ ----- ----\n"
            "//   World        c0       3\n//   WIT          c3       3\n//\n\n",
            "    vs_2_0\n"
            "    def c6, 1, 0, 0, 0\n"
            "    dcl_position v0\n"
            "    dcl_normal v1\n"
            "    dp4 oPos.x, v0, c0\n"
            "    dp4 oPos.y, v0, c1\n"
            "    dp4 oPos.z, v0, c2\n"
            "    mov oPos.w, c6.x\n"
            "    dp3 oT0.x, v1, c3\n"
            "    dp3 oT0.y, v1, c4\n"
            "    dp3 oT0.z, v1, c5\n"
            "\n// approximately 7 instruction slots used\n");
}

static void refused(const char *src, const char *profile, const char *message) {
    bool ok;
    char *text = bc_listing(src, profile, &ok);
    CHECK(!ok);
    CHECK_STR(text, message);
    free(text);
}

static void limits(void) {
    /* 70 unrolled mads and the mov to oC0: 71 arithmetic slots, ps_2_0 has 64 */
    refused("float4 K;\nfloat4 main(float4 c : COLOR0) : COLOR0 {\n    float4 x = c;\n"
            "    for (int i = 0; i < 70; i++) x = x * x + K;\n    return x;\n}\n",
            "ps_2_0",
            "t.fx(2,8): error X5608: Compiled shader code uses too many arithmetic instruction slots (71). Max. allowed "
            "by the target (ps_2_0) is 64.\n");
    /* the same fits ps_2_a's 512 */
    bool ok;
    char *text = bc_listing("float4 K;\nfloat4 main(float4 c : COLOR0) : COLOR0 {\n    float4 x = c;\n"
                         "    for (int i = 0; i < 70; i++) x = x * x + K;\n    return x;\n}\n", "ps_2_a", &ok);
    CHECK(ok);
    CHECK_CONTAINS(text, "// approximately 71 instruction slots used (0 texture, 71 arithmetic)\n");
    free(text);
    /* thirteen products summed, then multiplied by the sum one by one: each is computed before
     * the add that first reads it, but all thirteen stay live until their mul; after the last
     * add: the sum and s0..s12, 14 registers (vs_2_0 has 12) */
    static char src[2048];
    size_t n = (size_t)sprintf(src, "float4 A[13];\nfloat4 main(float4 p : POSITION) : POSITION {\n");
    for (int i = 0; i < 13; i++) n += (size_t)sprintf(src + n, "    float4 s%d = p * A[%d];\n", i, i);
    n += (size_t)sprintf(src + n, "    float4 t = s0");
    for (int i = 1; i < 13; i++) n += (size_t)sprintf(src + n, " + s%d", i);
    n += (size_t)sprintf(src + n, ";\n    return t");
    for (int i = 0; i < 13; i++) n += (size_t)sprintf(src + n, " * s%d", i);
    sprintf(src + n, ";\n}\n");
    refused(src, "vs_2_0", "t.fx(2,8): error X4505: this shader needs 14 temporary registers; vs_2_0 has 12\n");
    /* ps_2_0 has no loops: one bounded by a parameter cannot be unrolled (fxc: X3511) */
    refused("int N;\nfloat4 K;\nfloat4 main(float4 c : COLOR0) : COLOR0 {\n    float4 x = c;\n"
            "    for (int i = 0; i < N; i++) x += K;\n    return x;\n}\n",
            "ps_2_0",
            "t.fx(5,5): error X3511: unable to unroll loop, loop does not appear to terminate in a timely manner (1024 iterations)\n");
    /* SM3 nests loops 4 deep: the fifth is refused where it starts */
    refused("int N;\nfloat4 main(float4 c : COLOR0) : COLOR0 {\n    float4 x = c;\n"
            "    for (int a = 0; a < N; a++)\n        for (int b = 0; b < N; b++)\n"
            "            for (int d = 0; d < N; d++)\n                for (int e = 0; e < N; e++)\n"
            "                    for (int f = 0; f < N; f++) x += c;\n    return x;\n}\n",
            "ps_3_0", "t.fx(8,21): error X5301: loop nesting exceeds the limit of ps_3_0 (4)\n");
    /* vs_2_0 nests loops 1 deep */
    refused("int N;\nfloat4 main(float4 c : POSITION) : POSITION {\n    float4 x = c;\n"
            "    for (int a = 0; a < N; a++)\n        for (int b = 0; b < N; b++) x += c;\n    return x;\n}\n",
            "vs_2_0", "t.fx(5,9): error X5301: loop nesting exceeds the limit of vs_2_0 (1)\n");
    /* tex2Dlod needs SM3 */
    refused("sampler S;\nfloat4 main(float4 uv : TEXCOORD0) : COLOR0 { return tex2Dlod(S, uv); }\n", "ps_2_0",
            "t.fx(2,54): error X4121: tex2Dlod needs a higher shader model than ps_2_0\n");
}

/* A pixel shader writing its input (t.y--): ps_2_0's t registers cannot be written, so the
 * input goes to a temporary where it is written: x copied, y decremented from the input itself
 * (t0.y - 1: the copy's reader reads what it copied, bc_fold.c), the two one add (the copy as
 * t0.x + -0, bc_vec.c), and returned as t.xyxy: 2 arithmetic slots. The copy was once missed
 * for ++ / -- and the shader failed its own validation (X5999). */
static void ps_2_0_written_input(void) {
    bool ok;
    char *text = bc_listing("float4 main(float2 t : TEXCOORD0) : COLOR0 { t.y--; return t.xyxy; }\n", "ps_2_0", &ok);
    CHECK(ok);
    CHECK_STR(text, "//\n// Generated by hfxc 0.1.0 (D3D9 bytecode)\n//\n\n"
            "    ps_2_0\n"
            "    def c0, -1, -0, 0, 0\n"
            "    dcl t0.xy\n"
            "    add r0.xy, t0, c0.yxzw\n"  /* the copy of t.x and t.y - 1 as one add: t.x + -0 is t.x, -0 and NaN too (bc_vec.c) */
            "    mov oC0, r0.xyxy\n"
            "\n// approximately 2 instruction slots used (0 texture, 2 arithmetic)\n");
    free(text);
}

int main(void) {
    RUN(ps_2_0_compare_select);
    RUN(vs_2_0_normalize_output);
    RUN(ps_2_0_product_then_add);
    RUN(vs_2_0_transform_and_mad);
    RUN(ps_2_0_clip_and_saturate);
    RUN(ps_3_0_parameter_loop);
    RUN(vs_2_0_static_loop);
    RUN(ps_3_0_while_break);
    RUN(ps_3_0_reflect_pow_select);
    RUN(per_stage_registers);
    RUN(limits);
    RUN(ps_2_0_written_input);
    RUN(ps_2_0_tex1d);
    RUN(ps_2_0_sampler_array);
    RUN(ps_2_0_counter_after_loop);
    RUN(vs_2_0_overlapping_registers);
    return test_summary();
}
