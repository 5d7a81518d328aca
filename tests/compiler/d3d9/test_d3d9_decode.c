/* test_d3d9_decode.c: hand-assembled D3D9 shaders decoded and printed as fxc's listing (exact
 * text), and malformed ones refused with exact, located diagnostics. The expected listings follow
 * fxc's published format (four-space indent, two more per block, swizzles as .x / .xyzw rules,
 * `_sat_pp` order, nine-digit floats with three-digit exponents, the CTAB header). */
#include <stdlib.h>
#include <string.h>

#include "d3d9/d3d9.h"
#include "d3d9_asm.h"
#include "test.h"

/* Decodes words; returns the listing, or the diagnostics when decoding failed (malloc'ed). */
static char *run(const uint32_t *w, size_t n, int *ok) {
    hfx_arena arena;
    hfx_diags diags;
    hfx_arena_init(&arena);
    hfx_diags_init(&diags, &arena, 0);
    d3d9_input in = {w, (uint32_t)(n * 4), hfx_diags_add_file(&diags, "t.vso", NULL, "", 0), 0};
    d3d9_shader *s = hfx_d3d9_decode(&arena, &diags, &in);
    char *out;
    if (s) {
        sbuf b = {0};
        hfx_d3d9_disassemble(s, &b);
        out = hfx_sb_take(&b);
    } else out = hfx_diags_format(&diags, 0);
    *ok = s != NULL;
    hfx_arena_free(&arena);
    return out;
}

#define RUN_OK(words, expected) do { int ok_; char *t_ = run(words, sizeof words / 4, &ok_); \
    CHECK(ok_); CHECK_STR(t_, expected); free(t_); } while (0)
#define RUN_ERR(words, expected) do { int ok_; char *t_ = run(words, sizeof words / 4, &ok_); \
    CHECK(!ok_); CHECK_STR(t_, expected); free(t_); } while (0)

static void ps_2_0_texture(void) {
    const uint32_t w[] = {
        PS(2, 0),
        OP(0x1f, 2), 0x80000000u, DST(R_ADDR, 0, 0x3),                 /* dcl t0.xy */
        OP(0x1f, 2), 0x90000000u, DST(R_SAMPLER, 0, 0xf),              /* dcl_2d s0 */
        OP(0x51, 5), DST(R_CONST, 1, 0xf), fbits(1), fbits(0.5f), fbits(-0.0f), fbits(1e-5f),
        OP(0x42, 3), DST(R_TEMP, 0, 0xf), SRC(R_ADDR, 0, XYZW), SRC(R_SAMPLER, 0, XYZW),
        OP(0x05, 3), DSTM(R_TEMP, 0, 0x7, 3), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 0, 0),
        OP(0x58, 4), DST(R_TEMP, 1, 0xf), SRCM(R_TEMP, 0, SW(1, 0, 2, 2), 1), SRCM(R_CONST, 1, 0x55, 11),
        SRCM(R_CONST, 1, 0xaa, 12),
        OP(0x01, 2), DST(R_COLOROUT, 0, 0xf), SRC(R_TEMP, 0, XYZW),
        END_TOKEN};
    RUN_OK(w,
           "    ps_2_0\n"
           "    dcl t0.xy\n"
           "    dcl_2d s0\n"
           "    def c1, 1, 0.5, -0, 9.99999975e-006\n"
           "    texld r0, t0, s0\n"
           "    mul_sat_pp r0.xyz, r0, c0.x\n"
           "    cmp r1, -r0.yxzz, c1_abs.y, -c1_abs.z\n"
           "    mov oC0, r0\n"
           "\n"
           "// approximately 4 instruction slots used (1 texture, 3 arithmetic)\n");
}

static void vs_3_0_listing(void) {
    static const ctab_const k[] = {
        {"Flag", 0, 0, 1, 0, 1, 1, 1, 1},
        {"Count", 1, 0, 1, 0, 2, 1, 1, 1},
        {"WorldViewProj", 2, 0, 4, 3, 3, 4, 4, 1},
        {"Scale", 2, 5, 1, 0, 3, 1, 1, 1},
        {"Offsets", 2, 6, 2, 1, 3, 1, 4, 2},
        {"Tex", 3, 0, 1, 4, 12, 1, 1, 1}};
    const uint32_t code[] = {
        OP(0x51, 5), DST(R_CONST, 4, 0xf), fbits(1), fbits(0), fbits(0), fbits(0),
        OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 0, 0xf),                        /* dcl_position v0 */
        OP(0x1f, 2), 0x80010005u, DST(R_INPUT, 1, 0xf),                        /* dcl_texcoord1 v1 */
        OP(0x1f, 2), 0x80000000u, DST(R_OUTPUT, 0, 0xf),                       /* dcl_position o0 */
        OP(0x1f, 2), 0x80000005u, DST(R_OUTPUT, 1, 0x3),                       /* dcl_texcoord o1.xy */
        OP(0x14, 3), DST(R_OUTPUT, 0, 0xf), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 0, XYZW),
        OP(0x04, 4), DST(R_OUTPUT, 1, 0x3), SRC(R_INPUT, 1, XYZW), SRC(R_CONST, 5, 0),
        SRCM(R_CONST, 5, SW(1, 2, 2, 3), 1),   /* one c register: vs_3_0's read port */
        OP(0x26, 1), SRC(R_CONSTINT, 0, XYZW),                                 /* rep i0 */
        OP(0x02, 3), DST(R_TEMP, 0, 0xf), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 4, 0),
        OPC(0x29, 2, 4), SRC(R_TEMP, 0, 0), SRC(R_CONST, 4, 0x55),             /* if_lt */
        OP(0x2c, 0),                                                           /* break */
        OP(0x2b, 0),                                                           /* endif */
        OP(0x27, 0),                                                           /* endrep */
        OP(0x2e, 2), DST(R_ADDR, 0, 0x1), SRC(R_INPUT, 1, 0),                  /* mova a0.x, v1.x */
        OP(0x01, 3), DST(R_TEMP, 1, 0xf), SRC(R_CONST, 7, XYZW) | REL, SRC(R_ADDR, 0, 0),
        OPC(0x5e, 3, 1), DST(R_PRED, 0, 0x1), SRC(R_TEMP, 1, 0), SRC(R_CONST, 4, 0x55),
        OP(0x01, 3) | PRED_BIT, DST(R_OUTPUT, 0, 0x4), SRCM(R_PRED, 0, 0, 13), SRC(R_TEMP, 1, XYZW),
        OP(0x28, 1), SRCM(R_CONSTBOOL, 0, 0, 0),                              /* if b0 */
        OP(0x2a, 0),                                                          /* else */
        OP(0x5f, 3), DST(R_TEMP, 2, 0xf), SRC(R_INPUT, 1, XYZW), SRC(R_SAMPLER, 0, XYZW),
        OP(0x2b, 0),
        END_TOKEN};
    uint32_t w[512];
    w[0] = VS(3, 0);
    size_t n = 1 + put_ctab(w + 1, "hfx test compiler", k, 6);
    memcpy(w + n, code, sizeof code);
    n += sizeof code / 4;
    int ok;
    char *t = run(w, n, &ok);
    CHECK(ok);
    CHECK_STR(t,
              "//\n"
              "// Generated by hfx test compiler\n"
              "//\n"
              "// Parameters:\n"
              "//\n"
              "//   int Count;\n"
              "//   bool Flag;\n"
              "//   float4 Offsets[2];\n"
              "//   float Scale;\n"
              "//   sampler2D Tex;\n"
              "//   float4x4 WorldViewProj;\n"
              "//\n"
              "//\n"
              "// Registers:\n"
              "//\n"
              "//   Name          Reg   Size\n"
              "//   ------------- ----- ----\n"
              "//   Flag          b0       1\n"
              "//   Count         i0       1\n"
              "//   WorldViewProj c0       4\n"
              "//   Scale         c5       1\n"
              "//   Offsets       c6       2\n"
              "//   Tex           s0       1\n"
              "//\n"
              "\n"
              "    vs_3_0\n"
              "    def c4, 1, 0, 0, 0\n"
              "    dcl_position v0\n"
              "    dcl_texcoord1 v1\n"
              "    dcl_position o0\n"
              "    dcl_texcoord o1.xy\n"
              "    m4x4 o0, v0, c0\n"
              "    mad o1.xy, v1, c5.x, -c5.yzzw\n"
              "    rep i0\n"
              "      add r0, r0, c4.x\n"
              "      if_lt r0.x, c4.y\n"
              "        break\n"
              "      endif\n"
              "    endrep\n"
              "    mova a0.x, v1.x\n"
              "    mov r1, c7[a0.x]\n"
              "    setp_gt p0.x, r1.x, c4.y\n"
              "    (!p0.x) mov o0.z, r1\n"
              "    if b0\n"
              "    else\n"
              "      texldl r2, v1, s0\n"
              "    endif\n"
              "\n"
              "// approximately 27 instruction slots used\n");
    free(t);
}

/* ps_1_x: coissue, source modifiers of the fixed-function era, result shifts, tex / texcoord. */
static void ps_1_x_listing(void) {
    /* ps_1_x has no length field: operand tokens are the following ones with bit 31 set. */
    static const uint32_t w[] = {
        PS(1, 1),
        0x42, DST(R_ADDR, 0, 0xf),                                                      /* tex t0 */
        0x05, DST(R_TEMP, 0, 0x7) | 1u << 24, SRCM(R_ADDR, 0, XYZW, 4), SRCM(R_INPUT, 0, XYZW, 6),
        0x01 | COISSUE_BIT, DSTM(R_TEMP, 0, 0x8, 1), SRCM(R_ADDR, 0, 0xff, 2),
        0x50, DST(R_TEMP, 0, 0xf), SRC(R_TEMP, 0, 0xff), SRCM(R_INPUT, 1, XYZW, 7), SRCM(R_CONST, 0, XYZW, 3),
        0x05, DST(R_TEMP, 0, 0xf) | 0xfu << 24, SRC(R_TEMP, 0, XYZW), SRC(R_TEMP, 0, XYZW),
        END_TOKEN};
    RUN_OK(w,
           "    ps_1_1\n"
           "    tex t0\n"
           "    mul_x2 r0.xyz, t0_bx2, 1 - v0\n"
           "    +mov_sat r0.w, t0_bias.w\n"
           "    cnd r0, r0.w, v1_x2, -c0_bias\n"
           "    mul_d2 r0, r0, r0\n"
           "\n"
           "// approximately 5 instruction slots used (1 texture, 4 arithmetic)\n");
}

static void errors_located(void) {
    static const uint32_t bad_version[] = {0x12345678u, END_TOKEN};
    RUN_ERR(bad_version, "t.vso(0,0): error X5001: not a D3D9 shader: version token 0x12345678\n");
    static const uint32_t old_model[] = {VS(1, 0), END_TOKEN};
    RUN_ERR(old_model, "t.vso(0,0): error X5001: unsupported shader model vs_1_0\n");
    static const uint32_t truncated[] = {PS(2, 0), OP(0x01, 2), DST(R_COLOROUT, 0, 0xf)};
    RUN_ERR(truncated, "t.vso(0,4): error X5000: instruction runs past the end of the shader (2 words, 1 left)\n");
    static const uint32_t no_end[] = {PS(2, 0), OP(0x01, 2), DST(R_COLOROUT, 0, 0xf), SRC(R_TEMP, 0, XYZW)};
    RUN_ERR(no_end, "t.vso(0,16): error X5000: no END token\n");
    /* Every error of the stream, each at its token: two opcodes ps_2_0 lacks, a register it
     * cannot write, a bad operand count. */
    static const uint32_t many[] = {
        PS(2, 0),
        OP(0x28, 1), SRC(R_CONSTBOOL, 0, XYZW),
        OP(0x0c, 3), DST(R_TEMP, 0, 0xf), SRC(R_TEMP, 0, XYZW), SRC(R_TEMP, 0, XYZW),
        OP(0x01, 2), DST(R_RASTOUT, 0, 0xf), SRC(R_TEMP, 0, XYZW),
        OP(0x02, 2), DST(R_TEMP, 0, 0xf), SRC(R_TEMP, 0, XYZW),
        OP(0x01, 2), DST(R_TEMP, 40, 0xf), SRC(R_CONSTBOOL, 0, XYZW),
        END_TOKEN};
    RUN_ERR(many,
            "t.vso(0,4): error X5002: if is not allowed in ps_2_0\n"
            "t.vso(0,12): error X5002: slt is not allowed in ps_2_0\n"
            "t.vso(0,32): error X5003: register type 4 (oPos/oFog/oPts) cannot be written in ps_2_0\n"
            "t.vso(0,40): error X5003: add needs 3 operand tokens, has 2\n"
            "t.vso(0,56): error X5003: register r40 out of range in ps_2_0 (32)\n"
            "t.vso(0,60): error X5003: register type 14 (b) cannot be read in ps_2_0\n");
    static const uint32_t flow[] = {
        VS(2, 0),
        OP(0x2b, 0),                                 /* endif */
        OP(0x28, 1), SRC(R_CONSTBOOL, 0, XYZW),      /* if b0, never closed */
        OP(0x27, 0),                                 /* endrep inside the if */
        END_TOKEN};
    RUN_ERR(flow,
            "t.vso(0,4): error X5004: endif without a matching if\n"
            "t.vso(0,16): error X5004: endrep without a matching rep\n"
            "t.vso(0,20): error X5004: 1 flow-control block not closed at END\n");
    static const uint32_t comment[] = {PS(2, 0), COMMENT(3), 0x42415443u, 0};
    RUN_ERR(comment, "t.vso(0,4): error X5000: comment of 3 words runs past the end of the shader\n");
    static const uint32_t ctab[] = {PS(2, 0), COMMENT(8), 0x42415443u, 28, 0, 0, 5, 28, 0, 0, END_TOKEN};
    RUN_ERR(ctab, "t.vso(0,4): error X5005: constant table: 5 constants do not fit in the table\n");
    static const uint32_t unknown[] = {PS(2, 0), OP(0x3f, 0), OP(0x2c, 0), END_TOKEN};
    RUN_ERR(unknown,
            "t.vso(0,4): error X5002: unknown opcode 0x003f\n"
            "t.vso(0,8): error X5002: break is not allowed in ps_2_0\n");
}

/* Read ports (Microsoft's "Registers" tables): SM2 / SM3 read one c, one v, one t register an
 * instruction (the same one any number of times), SM2's sincos its two macro constants beside;
 * ps_1_x two c and two v. Each refused instruction is located at its token and names what it
 * reads. */
static void read_ports(void) {
    static const uint32_t vs[] = {
        VS(2, 0),
        OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 0, 0xf),
        OP(0x1f, 2), 0x80000003u, DST(R_INPUT, 1, 0xf),
        OP(0x04, 4), DST(R_TEMP, 0, 0xf), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 0, XYZW), SRC(R_CONST, 1, XYZW),
        OP(0x04, 4), DST(R_TEMP, 0, 0xf), SRC(R_CONST, 2, 0), SRC(R_CONST, 2, XYZW), SRC(R_INPUT, 0, XYZW),
        OP(0x08, 3), DST(R_TEMP, 1, 0x1), SRC(R_INPUT, 0, XYZW), SRC(R_INPUT, 1, XYZW),
        OP(0x25, 4), DST(R_TEMP, 2, 0x3), SRC(R_TEMP, 0, 0), SRC(R_CONST, 3, XYZW), SRC(R_CONST, 4, XYZW),
        OP(0x2e, 2), DST(R_ADDR, 0, 0x1), SRC(R_INPUT, 1, 0),
        OP(0x05, 4), DST(R_TEMP, 3, 0xf), SRC(R_CONST, 5, XYZW) | REL, SRC(R_ADDR, 0, 0), SRC(R_CONST, 5, XYZW),
        END_TOKEN};
    RUN_ERR(vs,
            "t.vso(0,28): error X5003: mad reads 2 different registers (c0, c1); vs_2_0 has 1 read port for them\n"
            "t.vso(0,68): error X5003: dp3 reads 2 different registers (v0, v1); vs_2_0 has 1 read port for them\n"
            "t.vso(0,116): error X5003: mul reads 2 different registers (c5[a0.x], c5); vs_2_0 has 1 read port for them\n");
    static const uint32_t ps[] = {
        PS(2, 0),
        OP(0x1f, 2), 0x80000000u, DST(R_ADDR, 0, 0xf),
        OP(0x1f, 2), 0x80000000u, DST(R_ADDR, 1, 0xf),
        OP(0x02, 3), DST(R_TEMP, 0, 0xf), SRC(R_ADDR, 0, XYZW), SRC(R_ADDR, 1, XYZW),
        OP(0x05, 3), DST(R_TEMP, 0, 0xf), SRC(R_ADDR, 1, XYZW), SRC(R_ADDR, 1, 0xff),
        OP(0x12, 4), DST(R_TEMP, 0, 0xf), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 0, XYZW), SRC(R_CONST, 1, XYZW),
        END_TOKEN};
    RUN_ERR(ps,
            "t.vso(0,28): error X5003: add reads 2 different registers (t0, t1); ps_2_0 has 1 read port for them\n"
            "t.vso(0,60): error X5003: lrp reads 2 different registers (c0, c1); ps_2_0 has 1 read port for them\n");
    static const uint32_t ps11[] = {
        PS(1, 1),
        0x04, DST(R_TEMP, 0, 0xf), SRC(R_INPUT, 1, XYZW), SRC(R_CONST, 2, XYZW), SRC(R_INPUT, 0, XYZW),
        0x04, DST(R_TEMP, 0, 0xf), SRC(R_CONST, 0, XYZW), SRC(R_CONST, 1, XYZW), SRC(R_CONST, 2, XYZW),
        END_TOKEN};
    RUN_ERR(ps11, "t.vso(0,24): error X5003: mad reads 3 different registers (c0, c1, c2); ps_1_1 has 2 read ports for them\n");
}

/* From SM2 on, rcp / rsq / exp / log / pow / sincos name their one component by a replicate
 * swizzle (Microsoft's instruction pages); any other swizzle is refused at the instruction. */
static void scalar_sources(void) {
    static const uint32_t ps[] = {
        PS(2, 0),
        OP(0x07, 2), DST(R_TEMP, 0, 0x1), SRC(R_TEMP, 1, XYZW),
        OP(0x07, 2), DST(R_TEMP, 0, 0x2), SRC(R_TEMP, 1, 0x55),
        OP(0x20, 3), DST(R_TEMP, 0, 0x1), SRC(R_TEMP, 1, 0), SRC(R_TEMP, 2, 0x1b),
        END_TOKEN};
    RUN_ERR(ps,
            "t.vso(0,4): error X5003: rsq reads r1 without a replicate swizzle (.x, .y, .z or .w)\n"
            "t.vso(0,28): error X5003: pow reads r2 without a replicate swizzle (.x, .y, .z or .w)\n");
}

static void shader_detection(void) {
    static const uint32_t ps[] = {PS(2, 0), END_TOKEN}, vs11[] = {VS(1, 1), END_TOKEN}, vs10[] = {VS(1, 0), END_TOKEN};
    static const uint32_t fx[] = {0xfeff0901u, 0}; /* an fx_2_0 effect's version word */
    CHECK(hfx_d3d9_is_shader(ps, sizeof ps));
    CHECK(hfx_d3d9_is_shader(vs11, sizeof vs11));
    CHECK(!hfx_d3d9_is_shader(vs10, sizeof vs10));
    CHECK(!hfx_d3d9_is_shader(fx, sizeof fx));
    CHECK(!hfx_d3d9_is_shader(ps, 4));
}

int main(void) {
    RUN(shader_detection);
    RUN(ps_2_0_texture);
    RUN(vs_3_0_listing);
    RUN(ps_1_x_listing);
    RUN(errors_located);
    RUN(read_ports);
    RUN(scalar_sources);
    return test_summary();
}
