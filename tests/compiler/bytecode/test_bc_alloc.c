/* test_bc_alloc.c: the bytecode back end's temporaries (compiler/bytecode/bc_alloc.c) and the
 * folds that keep values out of them. Shaders compiled through the fxc path (/T, /E) and their
 * code compared as exact text, each instruction and register worked out by hand in a comment;
 * the liveness over flow control checked on a hand-made instruction list (the writer flattens
 * every if and unrolls every loop, so only such a list has a loop to check). */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bytecode/bc_int.h"
#include "hfx/hfxc.h"
#include "test.h"

/* The listing's code, from the version line on (the CTAB comment is test_bytecode.c's). */
static char *code_of(const char *src, const char *profile) {
    hfxc_options o = {.entry = "main", .profile = profile};
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "t.fx", &o);
    size_t size = 0;
    const void *code = hfxc_result_bytecode(r, &size);
    char *text = NULL;
    if (hfxc_result_ok(r) && code) {
        char *diags = NULL;
        text = hfxc_disassemble(code, size, "t.vso", &diags);
        free(diags);
    } else text = hfxc_diagnostics_text(r);
    hfxc_result_free(r);
    char *at = text ? strstr(text, "\n    ") : NULL;
    char *out = strdup(at ? at + 1 : text ? text : "");
    free(text);
    return out;
}

static void code_is(const char *src, const char *profile, const char *want) {
    char *text = code_of(src, profile);
    CHECK_STR(text, want);
    free(text);
}

/* Four scalars live at once share one register, one component each (one register per value
 * would take four). 5 slots: four dp4 and the four products as one mul straight to oPos. */
static void scalars_share_a_register(void) {
    code_is("float4 A, B, C, D;\n"
            "float4 main(float4 p : POSITION) : POSITION {\n"
            "    float a = dot(p, A);\n    float b = dot(p, B);\n    float c = dot(p, C);\n    float d = dot(p, D);\n"
            "    return float4(a * b, b * c, c * d, d * a);\n}\n",
            "vs_2_0",
            "    vs_2_0\n"
            "    dcl_position v0\n"
            "    dp4 r0.x, v0, c0\n"
            "    dp4 r0.y, v0, c1\n"         /* b: r0.x is still live, b takes the next free component */
            "    dp4 r0.z, v0, c2\n"
            "    dp4 r0.w, v0, c3\n"
            /* the four products, once the scalars share r0, are one mul (bc_vec.c after the
             * allocation): lane x r0.x * r0.y, y r0.y * r0.z, z r0.z * r0.w, w r0.w * r0.x */
            "    mul oPos, r0, r0.yzwx\n"
            "\n// approximately 5 instruction slots used\n");
}

/* c.rgb *= t.rgb on a copy of an input: the copy takes only the component the product does not
 * write (mov r0.w, v0.w, not a mov of all four), and the product writes the texel's register,
 * which dies there. 4 slots: texld, mul, mov, and ps_2_0's mov to oC0 (oC0 takes only a mov). */
static void copy_on_write_takes_only_what_is_kept(void) {
    code_is("sampler S;\n"
            "float4 main(float2 uv : TEXCOORD0, float4 col : COLOR0) : COLOR0 {\n"
            "    float4 c = col;\n    c.rgb *= tex2D(S, uv).rgb;\n    return c;\n}\n",
            "ps_2_0",
            "    ps_2_0\n"
            "    dcl t0.xy\n"
            "    dcl v0\n"
            "    dcl_2d s0\n"
            "    texld r0, t0, s0\n"
            "    mul r0.xyz, v0, r0\n"
            "    mov r0.w, v0.w\n"
            "    mov oC0, r0\n"
            "\n// approximately 4 instruction slots used (1 texture, 3 arithmetic)\n");
}

/* Two-bone skinning as XNA's SkinnedEffect writes it: the float4x3 bones are column_major, three
 * registers of four (one per column); skin += Bones[i] * w adds them up by columns, a mul for
 * the first bone (0 + x * w: the zero folds) and a mad for the second, and mul(p, skin) is one
 * dp4 per column. 16 slots: both indices times 3 and one mova a0.xy (2), per bone three columns (3): 8;
 * the position's three dp4 and its w of 1: 4; WorldViewProj's four dp4: 4. Three temporaries:
 * the three columns (r0.xy, the indices, is a column's once a0 holds them). */
static void skinning_by_columns(void) {
    code_is("float4x3 Bones[4];\nfloat4x4 WorldViewProj;\n"
            "void main(float4 p : POSITION, int4 i : BLENDINDICES, float4 w : BLENDWEIGHT, out float4 o : POSITION) {\n"
            "    float4x3 skin = 0;\n"
            "    skin += Bones[i.x] * w.x;\n"
            "    skin += Bones[i.y] * w.y;\n"
            "    o = mul(float4(mul(p, skin), 1), WorldViewProj);\n}\n",
            "vs_2_0",
            "    vs_2_0\n"
            "    def c16, 0, 3, 1, 0\n"
            "    dcl_position v0\n"
            "    dcl_blendindices v1\n"
            "    dcl_blendweight v2\n"
            "    mul r0.xy, v1, c16.y\n"   /* three registers a bone, both indices at once */
            "    mova a0.xy, r0\n"
            "    mul r0, c0[a0.x], v2.x\n"  /* column 0 of Bones[i.x] * w.x */
            "    mul r1, c1[a0.x], v2.x\n"
            "    mul r2, c2[a0.x], v2.x\n"
            "    mad r0, c0[a0.y], v2.y, r0\n"
            "    mad r1, c1[a0.y], v2.y, r1\n"
            "    mad r2, c2[a0.y], v2.y, r2\n"
            "    dp4 r0.x, v0, r0\n"        /* mul(p, skin).x: p . column 0 */
            "    dp4 r0.y, v0, r1\n"
            "    dp4 r0.z, v0, r2\n"
            "    mov r0.w, c16.z\n"
            "    dp4 oPos.x, r0, c12\n"
            "    dp4 oPos.y, r0, c13\n"
            "    dp4 oPos.z, r0, c14\n"
            "    dp4 oPos.w, r0, c15\n"
            "\n// approximately 16 instruction slots used\n");
}

/* lit += x * y starting from (Lit)0 is one mul, not a mov of zero and a mad; x * 1 is x. 2 slots. */
static void compound_assignment_folds(void) {
    code_is("float4 K;\n"
            "float4 main(float4 col : COLOR0) : COLOR0 {\n"
            "    float4 s = 0;\n    s += col * K;\n    return s * 1;\n}\n",
            "ps_2_0",
            "    ps_2_0\n"
            "    dcl v0\n"
            "    mul r0, v0, c0\n"
            "    mov oC0, r0\n"
            "\n// approximately 2 instruction slots used (0 texture, 2 arithmetic)\n");
}

/* forty variables, each the previous times A[i]: the generator holds a virtual temporary for each
 * until the end of main (40 at once, more than the 32 it once numbered), but only one value is
 * live at a time, so all of it runs in r0: mul r0, v0, c0, then r0 *= c1..c38, and the last
 * product written straight to oPos. 40 slots. */
static void forty_virtual_temporaries_in_one_register(void) {
    static char src[4096], want[4096];
    size_t n = (size_t)sprintf(src, "float4 A[40];\nfloat4 main(float4 p : POSITION) : POSITION {\n    float4 x0 = p * A[0];\n");
    for (int i = 1; i < 40; i++) n += (size_t)sprintf(src + n, "    float4 x%d = x%d * A[%d];\n", i, i - 1, i);
    sprintf(src + n, "    return x39;\n}\n");
    n = (size_t)sprintf(want, "    vs_2_0\n    dcl_position v0\n    mul r0, v0, c0\n");
    for (int i = 1; i < 39; i++) n += (size_t)sprintf(want + n, "    mul r0, r0, c%d\n", i);
    sprintf(want + n, "    mul oPos, r0, c39\n\n// approximately 40 instruction slots used\n");
    code_is(src, "vs_2_0", want);
}

/* thirteen products, then their maximum: computed in order they hold thirteen registers before
 * the first max (vs_2_0 has 12); reordered, each product is computed just before the max that
 * reads it: r0 = s1, r1 = s0, r0 = max(s0, s1), then r1 = sK, r0 = max(r0, r1) for K = 2..12,
 * the last written to oPos. 2 registers, 25 slots. */
static void products_computed_where_read(void) {
    static char src[2048], want[2048];
    size_t n = (size_t)sprintf(src, "float4 A[13];\nfloat4 main(float4 p : POSITION) : POSITION {\n");
    for (int i = 0; i < 13; i++) n += (size_t)sprintf(src + n, "    float4 s%d = p * A[%d];\n", i, i);
    n += (size_t)sprintf(src + n, "    return ");
    for (int i = 1; i < 13; i++) n += (size_t)sprintf(src + n, "max(");
    n += (size_t)sprintf(src + n, "s0");
    for (int i = 1; i < 13; i++) n += (size_t)sprintf(src + n, ", s%d)", i);
    sprintf(src + n, ";\n}\n");
    n = (size_t)sprintf(want, "    vs_2_0\n    dcl_position v0\n    mul r0, v0, c1\n    mul r1, v0, c0\n    max r0, r1, r0\n");
    for (int i = 2; i < 12; i++) n += (size_t)sprintf(want + n, "    mul r1, v0, c%d\n    max r0, r0, r1\n", i);
    sprintf(want + n, "    mul r1, v0, c12\n    max oPos, r0, r1\n\n// approximately 25 instruction slots used\n");
    code_is(src, "vs_2_0", want);
}

/* The same products summed: each product but s1 goes into the add that reads it, a mad
 * (bc_mad.c): r0 = s1, then r0 = v0 * cK + r0 for K = 0, 2..12. 1 register, 13 slots. */
static void products_added_as_mads(void) {
    static char src[2048], want[2048];
    size_t n = (size_t)sprintf(src, "float4 A[13];\nfloat4 main(float4 p : POSITION) : POSITION {\n");
    for (int i = 0; i < 13; i++) n += (size_t)sprintf(src + n, "    float4 s%d = p * A[%d];\n", i, i);
    n += (size_t)sprintf(src + n, "    return s0");
    for (int i = 1; i < 13; i++) n += (size_t)sprintf(src + n, " + s%d", i);
    sprintf(src + n, ";\n}\n");
    n = (size_t)sprintf(want, "    vs_2_0\n    dcl_position v0\n    mul r0, v0, c1\n    mad r0, v0, c0, r0\n");
    for (int i = 2; i < 12; i++) n += (size_t)sprintf(want + n, "    mad r0, v0, c%d, r0\n", i);
    sprintf(want + n, "    mad oPos, v0, c12, r0\n\n// approximately 13 instruction slots used\n");
    code_is(src, "vs_2_0", want);
}

/* c / 16 reads the literal 1/16 = 0.0625 (no rcp); c / (float4)x is one rcp of c0.x written to
 * all four components (x replicated), then its mul; c * 0.0625 goes into the add as a mad: 4
 * arithmetic slots with the mov to oC0. The def keeps 16 beside 0.0625 (read in .y). */
static void reciprocals_of_literals_and_scalars(void) {
    code_is("float x;\nfloat4 main(float4 c : COLOR0) : COLOR0 { return c / 16 + c / (float4)x; }\n", "ps_2_0",
            "    ps_2_0\n"
            "    def c1, 16, 0.0625, 0, 0\n"
            "    dcl v0\n"
            "    rcp r0, c0.x\n"
            "    mul r0, v0, r0\n"
            "    mad r0, v0, c1.y, r0\n"
            "    mov oC0, r0\n"
            "\n// approximately 4 instruction slots used (0 texture, 4 arithmetic)\n");
}

/* --- liveness over flow, on a hand-made list --- */

static d3d9_inst inst(uint16_t op, int dst, unsigned mask, int s0, uint8_t sw0, int s1, uint8_t sw1) {
    d3d9_inst in;
    memset(&in, 0, sizeof in);
    in.op = op;
    if (dst >= 0) { in.has_dst = true; in.dst = (d3d9_dst){.type = D3D9_REG_TEMP, .num = (uint16_t)dst, .mask = (uint8_t)mask}; }
    int s[2] = {s0, s1};
    uint8_t sw[2] = {sw0, sw1};
    for (int k = 0; k < 2; k++) {
        if (s[k] == -1) continue;
        in.src[in.src_count++] = s[k] >= 100 ? (d3d9_src){.type = D3D9_REG_CONST, .num = (uint16_t)(s[k] - 100), .swizzle = sw[k]}
                                             : (d3d9_src){.type = D3D9_REG_TEMP, .num = (uint16_t)s[k], .swizzle = sw[k]};
    }
    return in;
}

/* x = 0; rep { y = x + 1; x = y; } out = y: the copy x = y is read only by the next iteration
 * (a walk in order sees no later read and would drop it), and x must keep its register through
 * the loop while y lives beside it: both fit one register, x in .x and y in .y. */
static void loop_carried_value(void) {
    hfx_arena arena;
    hfx_arena_init(&arena);
    ir_ctx c;
    memset(&c, 0, sizeof c);
    c.arena = &arena;
    bc_gen g;
    memset(&g, 0, sizeof g);
    g.c = &c;
    enum { X = 0x00, Y = 0x55 }; /* .xxxx, .yyyy */
    d3d9_inst code[] = {
        inst(D3D9_MOV, 5, 1, 100, X, -1, 0),  /* r5.x = c0.x (0) */
        inst(D3D9_REP, -1, 0, -1, 0, -1, 0),
        inst(D3D9_ADD, 7, 1, 5, X, 100, Y),   /* r7.x = r5.x + c0.y (1) */
        inst(D3D9_MOV, 5, 1, 7, X, -1, 0),    /* r5.x = r7.x: read at the loop's top only */
        inst(D3D9_ENDREP, -1, 0, -1, 0, -1, 0),
        inst(D3D9_MOV, 9, 0xf, 7, X, -1, 0),  /* a read after the loop keeps r7 */
        inst(D3D9_MOV, 8, 1, 100, X, -1, 0),  /* dead: nothing reads r8 */
    };
    code[1].src[code[1].src_count++] = (d3d9_src){.type = D3D9_REG_CONSTINT, .num = 0};
    code[5].has_dst = true;
    code[5].dst = (d3d9_dst){.type = D3D9_REG_RASTOUT, .num = 0, .mask = 0xf};
    g.insts = code;
    g.inst_count = g.inst_cap = sizeof code / sizeof *code;
    hfx_bc_dead_code(&g);
    CHECK_INT(g.inst_count, 6);               /* only the write to r8 goes */
    CHECK_INT(g.insts[3].op, D3D9_MOV);
    CHECK_INT(hfx_bc_renumber(&g), 1);        /* one register: x and y packed */
    CHECK_INT(g.insts[0].dst.num, 0);
    CHECK_INT(g.insts[0].dst.mask, 1);        /* x in r0.x */
    CHECK_INT(g.insts[2].dst.mask, 2);        /* y in r0.y (x is live through the loop) */
    CHECK_INT(g.insts[2].src[0].swizzle, X);  /* reads x */
    CHECK_INT(g.insts[3].dst.mask, 1);        /* the copy: r0.x = r0.y */
    CHECK_INT(g.insts[3].src[0].swizzle, Y);
    CHECK_INT(g.insts[5].src[0].swizzle, Y);
    hfx_arena_free(&arena);
}

/* A scalar copied into three components of an output (`float4(s, s, s, 1)`): the mul computing
 * s writes oD0.xyz itself, each lane reading the component it read for s (c1.x), not a
 * temporary and a `mov oD0.xyz, r0.x`. 4 slots. */
static void scalar_splat_written_in_place(void) {
    code_is("float4 A, B;\n"
            "float4 main(float4 p : POSITION, out float4 d : COLOR0) : POSITION {\n"
            "    float s = dot(p, A) * B.x;\n    d = float4(s, s, s, 1);\n    return p;\n}\n",
            "vs_2_0",
            "    vs_2_0\n"
            "    def c2, 0, 1, 0, 0\n"
            "    dcl_position v0\n"
            "    dp4 r0.x, v0, c0\n"         /* dot(p, A) */
            "    mul oD0.xyz, r0.x, c1.x\n"  /* times B.x, into the three lanes */
            "    mov oD0.w, c2.y\n"          /* the 1 */
            "    mov oPos, v0\n"
            "\n// approximately 4 instruction slots used\n");
}

/* A skinned position (`p.xyz = mul(p, s)`, s a float4x3 variable, row_major rows c0..c3 times
 * w.x) is a mul / mad chain accumulating into one temporary; the copy into p.xyz (whose w is
 * v0.w) is folded into the whole chain, each mad reading the running sum where p is: 13 slots,
 * no `mov r1.xyz, r0`. */
static void accumulation_written_in_place(void) {
    code_is("row_major float4x3 B[2];\nfloat4x4 W;\n"
            "float4 main(float4 p : POSITION, float4 w : BLENDWEIGHT) : POSITION {\n"
            "    float4x3 s = B[0] * w.x;\n    p.xyz = mul(p, s);\n    return mul(p, W);\n}\n",
            "vs_2_0",
            "    vs_2_0\n"
            "    dcl_position v0\n"
            "    dcl_blendweight v1\n"
            "    mul r0.xyz, c0, v1.x\n"     /* s's rows: B[0] times w.x */
            "    mul r1.xyz, c1, v1.x\n"
            "    mul r2.xyz, c2, v1.x\n"
            "    mul r3.xyz, c3, v1.x\n"
            "    mul r0.xyz, v0.x, r0\n"     /* p.x s[0] + p.y s[1] + p.z s[2] + p.w s[3], into p.xyz */
            "    mad r0.xyz, v0.y, r1, r0\n"
            "    mad r0.xyz, v0.z, r2, r0\n"
            "    mad r0.xyz, v0.w, r3, r0\n"
            "    mov r0.w, v0.w\n"
            "    dp4 oPos.x, r0, c8\n"       /* W: c8..c11 (B takes c0..c7) */
            "    dp4 oPos.y, r0, c9\n"
            "    dp4 oPos.z, r0, c10\n"
            "    dp4 oPos.w, r0, c11\n"
            "\n// approximately 13 instruction slots used\n");
}

/* hfx_bc_tidy, the unread positions of a swizzle once registers are renumbered: a source of
 * which one position is read (rsq, rcp, exp, log, pow, dp2add's addend) is the replicate of
 * it, in the dot products' mode too (D3D9 wants `rsq r1.x, r1.x`; an x read was left as the
 * identity, `rsq r1.x, r1`, in 18 scalar instructions of 6 corpus effects); a dot product's
 * three positions keep the identity (`dp3 r0.x, r1, r2`) or repeat their last. Swizzles as
 * bytes, two bits a position from x up: .xyzw 0xe4, .xxxx 0x00, .yyyy 0x55, .yzxx 0x09. */
static void one_read_position_replicated(void) {
    CHECK(hfx_bc_tidy(0xe4, 0x1, true) == 0x00);
    CHECK(hfx_bc_tidy(0xe4, 0x1, false) == 0x00);
    CHECK(hfx_bc_tidy(0xe5, 0x1, true) == 0x55); /* .yxzw reading y in position 0 */
    CHECK(hfx_bc_tidy(0xe4, 0x7, true) == 0xe4);
    CHECK(hfx_bc_tidy(0x24, 0x7, true) == 0xe4); /* .xyzx reading xyz: the identity */
    CHECK(hfx_bc_tidy(0xc9, 0x7, true) == 0x09); /* .yzxw reading yzx: w repeats the last, .yzxx */
}

int main(void) {
    RUN(scalars_share_a_register);
    RUN(copy_on_write_takes_only_what_is_kept);
    RUN(skinning_by_columns);
    RUN(compound_assignment_folds);
    RUN(loop_carried_value);
    RUN(forty_virtual_temporaries_in_one_register);
    RUN(products_computed_where_read);
    RUN(products_added_as_mads);
    RUN(reciprocals_of_literals_and_scalars);
    RUN(scalar_splat_written_in_place);
    RUN(accumulation_written_in_place);
    RUN(one_read_position_replicated);
    return test_summary();
}
