/* test_bc_aggregate.c: what bc_aggregate.c writes, as fxc's listing of hand-written shaders (exact
 * text, each instruction worked out by hand from the D3D9 instruction definitions): indexes the
 * compiler cannot fold (selects over the elements; a0 for a vertex shader's parameter array),
 * structs as values, matrices and arrays with a semantic (a register per column / element), and
 * sincos's out arguments (once written into the def register a new variable names: X5999). The
 * values are checked by the semantics tables' rows run through fx_2_0 (tests/runtime/semantics). */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bc_listing.h"
#include "hfx/hfxc.h"
#include "test.h"


/* The listing of src for profile is BC_LISTING_HEAD followed by rest. */
static void expect(const char *src, const char *profile, const char *rest) {
    bool ok;
    char *text = bc_listing(src, profile, &ok), *want = malloc(strlen(BC_LISTING_HEAD) + strlen(rest) + 1);
    CHECK(ok);
    strcpy(want, BC_LISTING_HEAD);
    strcat(want, rest);
    CHECK_STR(text, want);
    free(want);
    free(text);
}

/* v[K] for a parameter K: a chain of selects, element k taken where K - (k - 0.5) >= 0, the last
 * that holds winning: add r0.y = K - 0.5, cmp picks v.y over v.x, then v.z, v.w (2 slots each);
 * the float result is returned splatted. K (c0) and the def (c1) are two c registers, one more
 * than ps_2_0's read port: K is copied into r0.x once, and the three adds read it there. Once
 * registers are given, the first two adds (K - 0.5 into r0.y, K - 1.5 into r0.z, nothing between
 * reading r0.z) are one add: `add r0.yz, r0.x, c1.xxyw`. */
static void ps_2_0_vector_read(void) {
    expect(
        "int K;\n"
        "float4 main(float4 v : TEXCOORD0) : COLOR0 { return v[K]; }\n",
        "ps_2_0",
        "// Parameters:\n"
        "//\n"
        "//   int K;\n"
        "//\n"
        "//\n"
        "// Registers:\n"
        "//\n"
        "//   Name         Reg   Size\n"
        "//   ------------ ----- ----\n"
        "//   K            c0       1\n"
        "//\n"
        "\n"
        "    ps_2_0\n"
        "    def c1, -0.5, -1.5, -2.5, 0\n"
        "    dcl t0\n"
        "    mov r0.x, c0.x\n"
        "    add r0.yz, r0.x, c1.xxyw\n"
        "    cmp r0.y, r0.y, t0.y, t0.x\n"
        "    cmp r0.y, r0.z, t0.z, r0.y\n"
        "    add r0.z, r0.x, c1.z\n"
        "    cmp r0.y, r0.z, t0.w, r0.y\n"
        "    mov oC0, r0.y\n"
        "\n"
        "// approximately 7 instruction slots used (0 texture, 7 arithmetic)\n");
}

/* a[K] = 0.5 on a copy of an input: each component written under K == k, tested as
 * -(K - k)^2 >= 0 by the cmp that writes it (add, mul, cmp per component; k = 0 needs no add);
 * the copy itself is gone, each cmp reading the input's component in place (bc_fold.c). K - k
 * reads K's c0 and the def's c1 / c2, two c registers (ps_2_0 reads one an instruction): K is
 * copied into r1.x once (K * K reads c0 alone). */
static void ps_2_0_vector_write(void) {
    expect(
        "int K;\n"
        "float4 main(float4 v : TEXCOORD0) : COLOR0 { float4 a = v; a[K] = 0.5; return a; }\n",
        "ps_2_0",
        "// Parameters:\n"
        "//\n"
        "//   int K;\n"
        "//\n"
        "//\n"
        "// Registers:\n"
        "//\n"
        "//   Name         Reg   Size\n"
        "//   ------------ ----- ----\n"
        "//   K            c0       1\n"
        "//\n"
        "\n"
        "    ps_2_0\n"
        "    def c1, 0, 0.5, -1, -2\n"
        "    def c2, -3, 0, 0, 0\n"
        "    dcl t0\n"
        "    mul r0.x, c0.x, c0.x\n"
        "    cmp r0.x, -r0.x, c1.y, t0.x\n"
        "    mov r1.x, c0.x\n"
        "    add r1.y, r1.x, c1.z\n"
        "    mul r1.y, r1.y, r1.y\n"
        "    cmp r0.y, -r1.y, c1.y, t0.y\n"
        "    add r1.y, r1.x, c1.w\n"
        "    mul r1.y, r1.y, r1.y\n"
        "    cmp r0.z, -r1.y, c1.y, t0.z\n"
        "    add r1.x, r1.x, c2.x\n"
        "    mul r1.x, r1.x, r1.x\n"
        "    cmp r0.w, -r1.x, c1.y, t0.w\n"
        "    mov oC0, r0\n"
        "\n"
        "// approximately 13 instruction slots used (0 texture, 13 arithmetic)\n");
}

/* A struct built from an initialiser list, copied and updated: its slots are views of the
 * input (no mov until the return gathers them), t.a += 1 the only arithmetic; the gathering
 * copies join it as adds of -0 (exact: x + -0 is x for every x, -0 included). */
static void ps_2_0_struct_copy(void) {
    expect(
        "struct S { float a; float2 b; };\n"
        "float4 main(float4 v : TEXCOORD0) : COLOR0 { S s = {v.x, v.yz}; S t = s; t.a += 1; return float4(t.b, t.a, s.a); }\n",
        "ps_2_0",
        "\n"
        "    ps_2_0\n"
        "    def c0, 0, 1, -0, 0\n"
        "    dcl t0\n"
        "    add r0, t0.yzxx, c0.zzyz\n" /* (v.y + -0, v.z + -0, v.x + 1, v.x + -0): the copies joined to the add */
        "    mov oC0, r0\n"
        "\n"
        "// approximately 2 instruction slots used (0 texture, 2 arithmetic)\n");
}

/* Colors[K] in a pixel shader (no a0 in ps_2_0): selects over the array's registers. ps_2_0
 * reads one c register an instruction: K (c3) is copied once for K - 0.5 and K - 1.5 (the def
 * c4), and Colors[1] (c1) for the cmp that also reads Colors[0] (c0; the first of two alike). */
static void ps_2_0_parameter_array_read(void) {
    expect(
        "float4 Colors[3];\n"
        "int K;\n"
        "float4 main(float4 v : TEXCOORD0) : COLOR0 { return Colors[K] * v; }\n",
        "ps_2_0",
        "// Parameters:\n"
        "//\n"
        "//   float4 Colors[3];\n"
        "//   int K;\n"
        "//\n"
        "//\n"
        "// Registers:\n"
        "//\n"
        "//   Name         Reg   Size\n"
        "//   ------------ ----- ----\n"
        "//   Colors       c0       3\n"
        "//   K            c3       1\n"
        "//\n"
        "\n"
        "    ps_2_0\n"
        "    def c4, -0.5, -1.5, 0, 0\n"
        "    dcl t0\n"
        "    mov r0.x, c3.x\n"
        "    add r1.x, r0.x, c4.x\n"
        "    mov r2, c1\n"
        "    cmp r1, r1.x, r2, c0\n"
        "    add r0.x, r0.x, c4.y\n"
        "    cmp r1, r0.x, c2, r1\n"
        "    mul r1, r1, t0\n"
        "    mov oC0, r1\n"
        "\n"
        "// approximately 8 instruction slots used (0 texture, 8 arithmetic)\n");
}

/* Colors[K] in a vertex shader: mova then c[a0.x + 0]. */
static void vs_2_0_parameter_array_read(void) {
    expect(
        "float4 Colors[3];\n"
        "int K;\n"
        "float4 main(float4 v : TEXCOORD0) : COLOR0 { return Colors[K] * v; }\n",
        "vs_2_0",
        "// Parameters:\n"
        "//\n"
        "//   float4 Colors[3];\n"
        "//   int K;\n"
        "//\n"
        "//\n"
        "// Registers:\n"
        "//\n"
        "//   Name         Reg   Size\n"
        "//   ------------ ----- ----\n"
        "//   Colors       c0       3\n"
        "//   K            c3       1\n"
        "//\n"
        "\n"
        "    vs_2_0\n"
        "    dcl_texcoord v0\n"
        "    mova a0.x, c3.x\n"
        "    mul oD0, c0[a0.x], v0\n"
        "\n"
        "// approximately 2 instruction slots used\n");
}

/* float4x4 world : TEXCOORD1 takes TEXCOORD1..4, its columns (D3D9's column_major packing, as
 * instancing streams it): mul(p, world) is a dp4 per column register, world[1] the .y of each.
 * vs_2_0 reads one v register an instruction: p is copied into r0 once for the four dp4. */
static void vs_2_0_matrix_input(void) {
    expect(
        "float4x4 ViewProj;\n"
        "float4 main(float4 p : POSITION0, float4x4 world : TEXCOORD1, out float4 row : TEXCOORD0) : POSITION0 {\n"
        "    row = world[1];\n"
        "    return mul(mul(p, world), ViewProj);\n"
        "}\n",
        "vs_2_0",
        "// Parameters:\n"
        "//\n"
        "//   float4x4 ViewProj;\n"
        "//\n"
        "//\n"
        "// Registers:\n"
        "//\n"
        "//   Name         Reg   Size\n"
        "//   ------------ ----- ----\n"
        "//   ViewProj     c0       4\n"
        "//\n"
        "\n"
        "    vs_2_0\n"
        "    dcl_position v0\n"
        "    dcl_texcoord1 v1\n"
        "    dcl_texcoord2 v2\n"
        "    dcl_texcoord3 v3\n"
        "    dcl_texcoord4 v4\n"
        "    mov oT0.x, v1.y\n"
        "    mov oT0.y, v2.y\n"
        "    mov oT0.z, v3.y\n"
        "    mov oT0.w, v4.y\n"
        "    mov r0, v0\n"
        "    dp4 r1.x, r0, v1\n"
        "    dp4 r1.y, r0, v2\n"
        "    dp4 r1.z, r0, v3\n"
        "    dp4 r1.w, r0, v4\n"
        "    dp4 oPos.x, r1, c0\n"
        "    dp4 oPos.y, r1, c1\n"
        "    dp4 oPos.z, r1, c2\n"
        "    dp4 oPos.w, r1, c3\n"
        "\n"
        "// approximately 13 instruction slots used\n");
}

/* float4 w[2] : TEXCOORD1 is t1, t2; float4x4 m : TEXCOORD3 is t3..t6 by columns, so row 2 of m
 * is gathered from their .z. ps_2_0 reads one t register an instruction: v.x (t0, one component
 * against t2's four) is copied for the mad. */
static void ps_2_0_array_and_matrix_inputs(void) {
    expect(
        "float4 main(float4 v : TEXCOORD0, float4 w[2] : TEXCOORD1, float4x4 m : TEXCOORD3) : COLOR0 { return w[1] + m[2] * v.x; }\n",
        "ps_2_0",
        "\n"
        "    ps_2_0\n"
        "    dcl t0\n"
        "    dcl t1\n"
        "    dcl t2\n"
        "    dcl t3\n"
        "    dcl t4\n"
        "    dcl t5\n"
        "    dcl t6\n"
        "    mov r0.x, t3.z\n"
        "    mov r0.y, t4.z\n"
        "    mov r0.z, t5.z\n"
        "    mov r0.w, t6.z\n"
        "    mov r1.x, t0.x\n"
        "    mad r0, r0, r1.x, t2\n"
        "    mov oC0, r0\n"
        "\n"
        "// approximately 7 instruction slots used (0 texture, 7 arithmetic)\n");
}

/* sincos into new variables: they name a def register's zero until written, and the results
 * must go to temporaries of their own (once stored into the c register: X5999 in ps_3_0). */
static void ps_3_0_sincos_out_arguments(void) {
    bool ok;
    char *text = bc_listing("float4 main(float4 v : TEXCOORD0) : COLOR0 { float s, c; sincos(v.x, s, c); return float4(s, c, 0, 1); }\n",
                         "ps_3_0", &ok);
    CHECK(ok);
    CHECK(text && strstr(text, "sincos r") != NULL);
    free(text);
}

int main(void) {
    RUN(ps_2_0_vector_read);
    RUN(ps_2_0_vector_write);
    RUN(ps_2_0_struct_copy);
    RUN(ps_2_0_parameter_array_read);
    RUN(vs_2_0_parameter_array_read);
    RUN(vs_2_0_matrix_input);
    RUN(ps_2_0_array_and_matrix_inputs);
    RUN(ps_3_0_sincos_out_arguments);
    return test_summary();
}
