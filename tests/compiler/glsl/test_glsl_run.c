/* test_glsl_run.c: HLSL semantics, checked by running hfx's GLSL on real GL (OSMesa). Each
 * case is a small effect whose pixel shader encodes results as colours; the expected values
 * are worked out by hand from HLSL's definitions (comments give the arithmetic). */
#define GL_GLEXT_PROTOTYPES 0
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "gl_context.h"
#include "gl_fns.h"
#include "hfx/hfxc.h"
#include "test.h"

enum { W = 8, H = 8 };

static test_gl *gl;

static test_gl_fns f;

static void load_gl(void) { CHECK_INT(test_gl_fns_load(&f), 0); }

/* A uniform value to set before drawing: 'f' floats (1 or 4 a piece), 'c' float3s, 'i' ints, 'm' a 3x3
 * or 4x4 matrix in XNA's row-major order (uploaded with transpose = GL_FALSE). */
typedef struct uval { const char *name; char kind; int count; float v[16]; int iv[4]; } uval;

static GLuint compile_stage(GLenum kind, const char *src) {
    GLuint s = f.CreateShader(kind);
    f.ShaderSource(s, 1, &src, NULL);
    f.CompileShader(s);
    GLint ok = 0;
    f.GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        f.GetShaderInfoLog(s, sizeof log, NULL, log);
        fprintf(stderr, "GL compile failed:\n%s\n%s\n", log, src);
    }
    return s;
}

static void set_uniforms(GLuint prog, const uval *u, int n) {
    for (int i = 0; i < n; i++) {
        GLint loc = f.GetUniformLocation(prog, u[i].name);
        if (loc < 0) { fprintf(stderr, "uniform %s not found\n", u[i].name); continue; }
        switch (u[i].kind) {
        case 'f': f.Uniform1fv(loc, u[i].count, u[i].v); break;
        case 'v': f.Uniform4fv(loc, u[i].count, u[i].v); break;
        case 'c': f.Uniform3fv(loc, u[i].count, u[i].v); break;
        case 'i': f.Uniform1iv(loc, u[i].count, u[i].iv); break;
        case '3': f.UniformMatrix3fv(loc, 1, GL_FALSE, u[i].v); break;
        case '4': f.UniformMatrix4fv(loc, 1, GL_FALSE, u[i].v); break;
        case 't': f.Uniform1iv(loc, 1, u[i].iv); break;
        }
    }
}

/* Compiles `src` with hfx (hfxc_options.flags `flags`), draws a full-screen quad with the
 * program of technique `tech` (first pass), and reads the pixel at (x, y) from the top-left as
 * floats 0..1. */
static int render_with(unsigned flags, const char *src, const char *tech, const uval *u, int nu, int x, int y, float out[4]) {
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL330;
    o.flags = flags;
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "test.fx", &o);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    if (!fx) {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "compile failed: %s\n", d);
        free(d);
        hfxc_result_free(r);
        return 0;
    }
    uint32_t prog_index = HFX_NONE;
    for (uint32_t t = 0; t < fx->technique_count; t++)
        if (!tech || strcmp(fx->techniques[t].name, tech) == 0) {
            prog_index = fx->passes[fx->techniques[t].first_pass].program;
            break;
        }
    if (prog_index >= fx->program_count) { hfxc_result_free(r); return 0; }
    const hfx_fx_program *p = &fx->programs[prog_index];
    GLuint vs = compile_stage(GL_VERTEX_SHADER, p->code[0][HFX_TARGET_GLSL330].data);
    GLuint fs = compile_stage(GL_FRAGMENT_SHADER, p->code[1][HFX_TARGET_GLSL330].data);
    GLuint prog = f.CreateProgram();
    f.AttachShader(prog, vs);
    f.AttachShader(prog, fs);
    f.LinkProgram(prog);
    GLint ok = 0;
    f.GetProgramiv(prog, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048];
        f.GetProgramInfoLog(prog, sizeof log, NULL, log);
        fprintf(stderr, "link failed: %s\n", log);
    }
    f.UseProgram(prog);
    set_uniforms(prog, u, nu);
    /* a quad covering the screen; TEXCOORD0 is (0,0) at the top left, as D3D puts it */
    static const float quad[] = {
        -1, -1, 0, 1,   0, 1,  1, -1, 0, 1,   1, 1,  -1, 1, 0, 1,   0, 0,
        -1, 1, 0, 1,    0, 0,  1, -1, 0, 1,   1, 1,   1, 1, 0, 1,   1, 0,
    };
    GLuint vao, vbo;
    f.GenVertexArrays(1, &vao);
    f.BindVertexArray(vao);
    f.GenBuffers(1, &vbo);
    f.BindBuffer(GL_ARRAY_BUFFER, vbo);
    f.BufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    f.VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void *)0);
    f.EnableVertexAttribArray(0);
    f.VertexAttribPointer(8, 2, GL_FLOAT, GL_FALSE, 6 * sizeof(float), (void *)(4 * sizeof(float)));
    f.EnableVertexAttribArray(8);
    f.Viewport(0, 0, W, H);
    f.ClearColor(0, 0, 0, 0);
    f.Clear(GL_COLOR_BUFFER_BIT);
    f.DrawArrays(GL_TRIANGLES, 0, 6);
    unsigned char px[4];
    test_gl_read(gl, x, y, px);
    for (int i = 0; i < 4; i++) out[i] = px[i] / 255.0f;
    f.DeleteBuffers(1, &vbo);
    f.DeleteVertexArrays(1, &vao);
    f.DeleteProgram(prog);
    f.DeleteShader(vs);
    f.DeleteShader(fs);
    hfxc_result_free(r);
    return ok;
}

static int render(const char *src, const char *tech, const uval *u, int nu, int x, int y, float out[4]) {
    return render_with(0, src, tech, u, nu, x, y, out);
}

#define VS_PASS \
    "struct V { float4 pos : POSITION; float2 uv : TEXCOORD0; };\n" \
    "V vs(float4 p : POSITION, float2 uv : TEXCOORD0) { V o; o.pos = p; o.uv = uv; return o; }\n"
#define TECH(ps) "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 " ps "; } }\n"

static const float TOL = 1.5f / 255.0f;

static void check_pixel(const char *src, const uval *u, int nu, float r, float g, float b, float a) {
    float px[4] = {0};
    CHECK(render(src, NULL, u, nu, W / 2, H / 2, px));
    CHECK_NEAR(px[0], r, TOL);
    CHECK_NEAR(px[1], g, TOL);
    CHECK_NEAR(px[2], b, TOL);
    CHECK_NEAR(px[3], a, TOL);
}

/* M rows: (0.1, 0.2, 0), (0, 0.05, 0.1), (0.1, 0, 0.1), uploaded row-major as XNA does. */
static const uval MAT3 = { "M", '3', 1, {0.1f, 0.2f, 0, 0, 0.05f, 0.1f, 0.1f, 0, 0.1f}, {0} };

static void mul_row_vector(void) {
    /* mul(v, M) = 1*row0 + 2*row1 + 3*row2 = (0.1+0+0.3, 0.2+0.1+0, 0+0.2+0.3) = (0.4, 0.3, 0.5) */
    const char *src = "float3x3 M;\n" VS_PASS
        "float4 ps() : COLOR { return float4(mul(float3(1, 2, 3), M), 1); }\n" TECH("ps()");
    check_pixel(src, &MAT3, 1, 0.4f, 0.3f, 0.5f, 1);
}

static void mul_column_vector(void) {
    /* mul(M, v) = (row0.v, row1.v, row2.v) = (0.1+0.4, 0.1+0.3, 0.1+0.3) = (0.5, 0.4, 0.4) */
    const char *src = "float3x3 M;\n" VS_PASS
        "float4 ps() : COLOR { return float4(mul(M, float3(1, 2, 3)), 1); }\n" TECH("ps()");
    check_pixel(src, &MAT3, 1, 0.5f, 0.4f, 0.4f, 1);
}

static void mul_translation(void) {
    /* XNA: 0.25 * identity with translation (0.25, 0.5, 0) in elements 12..14;
     * (1, 1, 0, 1) * T = (0.25 + 0.25, 0.25 + 0.5, 0, 1) */
    const uval t = { "T", '4', 1, {0.25f, 0, 0, 0, 0, 0.25f, 0, 0, 0, 0, 0.25f, 0, 0.25f, 0.5f, 0, 1}, {0} };
    const char *src = "float4x4 T;\n" VS_PASS
        "float4 ps() : COLOR { return mul(float4(1, 1, 0, 1), T); }\n" TECH("ps()");
    check_pixel(src, &t, 1, 0.5f, 0.75f, 0, 1);
}

static void mul_truncated(void) {
    /* mul(float3, float4x4) uses the upper 3 rows: no translation -> (0.25, 0.25, 0);
     * a float4 result assigned to float3 keeps xyz: (0.5, 0.75, 0); alpha: the w of the
     * full product, 1 */
    const uval t = { "T", '4', 1, {0.25f, 0, 0, 0, 0, 0.25f, 0, 0, 0, 0, 0.25f, 0, 0.25f, 0.5f, 0, 1}, {0} };
    const char *src = "float4x4 T;\n" VS_PASS
        "float4 ps() : COLOR { float3 a = mul(float3(1, 1, 0), T); float3 b = mul(float4(1, 1, 0, 1), T);\n"
        "  return float4(a.x + b.x, a.y + b.y, a.z + b.z, mul(float4(1, 1, 0, 1), T).w); }\n" TECH("ps()");
    check_pixel(src, &t, 1, 0.75f, 1.0f, 0, 1);
}

static void mul_matrix_matrix(void) {
    /* (M M)[0] = row0 * M = 0.1*row0 + 0.2*row1 + 0*row2 = (0.01, 0.03, 0.02); scaled by 10 */
    const char *src = "float3x3 M;\n" VS_PASS
        "float4 ps() : COLOR { float3x3 P = mul(M, M); return float4(P[0] * 10, 1); }\n" TECH("ps()");
    check_pixel(src, &MAT3, 1, 0.1f, 0.3f, 0.2f, 1);
}

static void matrix_swizzles(void) {
    /* M._m01 = 0.2, M._m12 = 0.1, M._21 (1-based: row 1, col 0) = 0 -> use _m20 = 0.1;
     * M[1].y = 0.05 */
    const char *src = "float3x3 M;\n" VS_PASS
        "float4 ps() : COLOR { float2 s = M._m01_m12; return float4(s, M._31 + M[1].y, 1); }\n" TECH("ps()");
    check_pixel(src, &MAT3, 1, 0.2f, 0.1f, 0.15f, 1);
}

static void matrix_constructor_rows(void) {
    /* float2x2(a, b, c, d) fills rows: m[1] = (0.3, 0.4); mul((1, 0), m) = row 0 = (0.1, 0.2) */
    const char *src = VS_PASS
        "float k;\n"
        "float4 ps() : COLOR { float2x2 m = float2x2(0.1, 0.2, 0.3, k); return float4(m[1], mul(float2(1, 0), m)); }\n"
        TECH("ps()");
    const uval u = { "k", 'f', 1, {0.4f}, {0} };
    check_pixel(src, &u, 1, 0.3f, 0.4f, 0.1f, 0.2f);
}

static void frac_fmod_round(void) {
    /* x = -0.25: frac = 0.75; fmod(-3, 2) = -1 -> (v + 2) / 4 = 0.25; round(2.5) = 3 -> 3/4;
     * (int)-1.7 = -1 -> (v + 2) / 4 = 0.25 */
    const char *src = "float x; float a; float b; float c; float d;\n" VS_PASS
        "float4 ps() : COLOR { return float4(frac(x), (fmod(a, b) + 2) / 4, round(c) / 4, ((int)d + 2) / 4.0); }\n"
        TECH("ps()");
    const uval u[] = { {"x", 'f', 1, {-0.25f}, {0}}, {"a", 'f', 1, {-3}, {0}}, {"b", 'f', 1, {2}, {0}},
                       {"c", 'f', 1, {2.5f}, {0}}, {"d", 'f', 1, {-1.7f}, {0}} };
    check_pixel(src, u, 5, 0.75f, 0.25f, 0.75f, 0.25f);
}

static void integer_division(void) {
    /* -7 / 2 = -3 (toward zero) -> (v + 4) / 8 = 0.125; -7 % 2 = -1 -> (v + 2) / 4 = 0.25;
     * 7 / 2 = 3 -> 3 / 4 = 0.75; folded constants: -7 / 2 = -3 again */
    const char *src = "int a; int b;\n" VS_PASS
        "float4 ps() : COLOR { int q = a / b; int r = a % b; int k = -7 / 2;\n"
        "  return float4((q + 4) / 8.0, (r + 2) / 4.0, (-a / b) / 4.0, (k + 4) / 8.0); }\n" TECH("ps()");
    const uval u[] = { {"a", 'i', 1, {0}, {-7}}, {"b", 'i', 1, {0}, {2}} };
    check_pixel(src, u, 2, 0.125f, 0.25f, 0.75f, 0.125f);
}

static void lerp_lit_saturate(void) {
    /* lerp(0.2, 0.6, 0.25) = 0.3; lit(0.5, 0.25, 2) = (1, 0.5, 0.0625, 1); saturate(1.5) = 1 */
    const char *src = "float t;\n" VS_PASS
        "float4 ps() : COLOR { float4 l = lit(0.5, 0.25, 2 * t * 4); return float4(lerp(0.2, 0.6, t), l.y, l.z, saturate(1.5 + t)); }\n"
        TECH("ps()");
    const uval u = { "t", 'f', 1, {0.25f}, {0} };
    check_pixel(src, &u, 1, 0.3f, 0.5f, 0.0625f, 1);
}

static void lit_negative(void) {
    /* lit(-0.5, 0.5, m): diffuse max(-0.5, 0) = 0, specular 0 since n.l < 0 */
    const char *src = "float t;\n" VS_PASS
        "float4 ps() : COLOR { return lit(-t, t, 2); }\n" TECH("ps()");
    const uval u = { "t", 'f', 1, {0.5f}, {0} };
    check_pixel(src, &u, 1, 1, 0, 0, 1);
}

static void loop_with_break(void) {
    /* adds 0.1 for i = 0..3, breaks at 4: 0.4; a while loop counting down 3 steps: 0.3 */
    const char *src = "int n;\n" VS_PASS
        "float4 ps() : COLOR { float s = 0; for (int i = 0; i < n; i++) { if (i == 4) break; s += 0.1; }\n"
        "  float w = 0; int k = 3; while (k > 0) { w += 0.1; k--; }\n"
        "  float c = 0; for (int j = 0; j < n - 4; j++) { if (j % 2 == 1) continue; c += 0.1; }\n"
        "  return float4(s, w, c, 1); }\n" TECH("ps()");
    /* the third loop skips odd j of 0..5: adds 0.1 for j = 0, 2, 4 -> 0.3 */
    const uval u = { "n", 'i', 1, {0}, {10} };
    check_pixel(src, &u, 1, 0.4f, 0.3f, 0.3f, 1);
}

/* Loop-invariant work computed once before the loop (lower/licm.c) gives the same values.
 * N.xyz = (3, 0, 4): normalize(N) = (0.6, 0, 0.8), length(N) = 5; n = 3.
 * r: three iterations of 0.6 * 0.25 -> 0.45;
 * g: v halves after each iteration, so length(v) * 0.1 is 0.5, 0.25, 0.125 -> 0.875 (v is
 *    written in the loop: nothing moves);
 * b: 2 x 2 nested iterations of 0.8 * 0.1 -> 0.32;
 * a: i * length(N) * 0.02 for i = 0, 1, 2 -> (0 + 1 + 2) * 0.1 = 0.3. */
static void loop_invariant_hoisted(void) {
    const char *src = "float4 N; int n;\n" VS_PASS
        "float4 ps() : COLOR { float4 c = 0; float3 v = N.xyz;\n"
        "  for (int i = 0; i < n; i++) { c.r += normalize(N.xyz).x * 0.25; c.g += length(v) * 0.1; v = v * 0.5;\n"
        "    c.a += i * (length(N.xyz) * 0.02); }\n"
        "  for (int j = 0; j < 2; j++) for (int k = 0; k < 2; k++) c.b += normalize(N.xyz).z * 0.1;\n"
        "  return c; }\n" TECH("ps()");
    const uval u[] = { {"N", 'v', 1, {3, 0, 4, 0}, {0}}, {"n", 'i', 1, {0}, {3}} };
    check_pixel(src, u, 2, 0.45f, 0.875f, 0.32f, 0.3f);
}

static void uniform_array_out_of_range(void) {
    /* arr = {0.1, 0.2}; the loop runs to 4: elements 2 and 3 read zero -> 0.3 */
    const char *src = "float arr[2]; int count;\n" VS_PASS
        "float4 ps() : COLOR { float s = 0; for (int i = 0; i < count; i++) s += arr[i]; return float4(s, 0, 0, 1); }\n"
        TECH("ps()");
    const uval u[] = { {"arr", 'f', 2, {0.1f, 0.2f}, {0}}, {"count", 'i', 1, {0}, {4}} };
    check_pixel(src, u, 2, 0.3f, 0, 0, 1);
    /* the same through the private copy of a written array: arr[0] doubles -> 0.2 + 0.2 */
    const char *written = "float arr[2]; int count;\n" VS_PASS
        "float4 ps() : COLOR { arr[count - 4] *= 2; float s = 0; for (int i = 0; i < count; i++) s += arr[i];\n"
        "  return float4(s, 0, 0, 1); }\n" TECH("ps()");
    check_pixel(written, u, 2, 0.4f, 0, 0, 1);
}

/* The guards ranges.c thins: arr = {0.1, 0.2}.
 * r: i from -1 (not provably >= 0: the whole guard): arr[-1] reads zero -> 0 + 0.1 + 0.2 = 0.3;
 * g: i from 0 below n = 4 (never negative: the upper end only): arr[2], arr[3] read zero -> 0.3;
 * b: i below the constant 2 (inside the array: no guard) -> 0.3;
 * a: i below the constant 4, past the end (guarded) -> 0.3, plus arr[i] after the loop, i = 4:
 *    zero -> 0.3. */
static void guarded_reads_past_either_end(void) {
    const char *src = "float arr[2]; int n;\n" VS_PASS
        "float4 ps() : COLOR { float4 c = 0;\n"
        "  for (int i = -1; i < 2; i++) c.r += arr[i];\n"
        "  for (int j = 0; j < n; j++) c.g += arr[j];\n"
        "  for (int k = 0; k < 2; k++) c.b += arr[k];\n"
        "  int m; for (m = 0; m < 4; m++) c.a += arr[m]; c.a += arr[m];\n"
        "  return c; }\n" TECH("ps()");
    const uval u[] = { {"arr", 'f', 2, {0.1f, 0.2f}, {0}}, {"n", 'i', 1, {0}, {4}} };
    check_pixel(src, u, 2, 0.3f, 0.3f, 0.3f, 0.3f);
}

static void specialisation(void) {
    const char *src = VS_PASS
        "float4 ps(uniform bool on) : COLOR { if (on) return float4(1, 0, 0, 1); return float4(0, 1, 0, 1); }\n"
        "technique On { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(true); } }\n"
        "technique Off { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(false); } }\n";
    float px[4];
    CHECK(render(src, "On", NULL, 0, 1, 1, px));
    CHECK_NEAR(px[0], 1, TOL);
    CHECK_NEAR(px[1], 0, TOL);
    CHECK(render(src, "Off", NULL, 0, 1, 1, px));
    CHECK_NEAR(px[0], 0, TOL);
    CHECK_NEAR(px[1], 1, TOL);
}

static void global_written_by_shader(void) {
    /* the shader scales its uniform copy; the uniform itself is 0.5 -> 0.25 */
    const char *src = "float4 c;\n" VS_PASS
        "float4 ps() : COLOR { c *= 0.5; return c; }\n" TECH("ps()");
    const uval u = { "c", 'v', 1, {0.5f, 0.5f, 1, 1}, {0} };
    check_pixel(src, &u, 1, 0.25f, 0.25f, 0.5f, 0.5f);
}

static void truncation_and_vector_select(void) {
    /* float3 = float4 keeps xyz; (v > 0.5) ? 1 : 0 componentwise on (0.2, 0.7, 0.9) */
    const char *src = "float4 v;\n" VS_PASS
        "float4 ps() : COLOR { float3 t = v; float3 s = (t > 0.5) ? float3(1, 1, 1) : float3(0, 0, 0); return float4(s, t.x); }\n"
        TECH("ps()");
    const uval u = { "v", 'v', 1, {0.2f, 0.7f, 0.9f, 0.4f}, {0} };
    check_pixel(src, &u, 1, 0, 1, 1, 0.2f);
}

static void d3dcolor_sincos(void) {
    /* D3DCOLORtoUBYTE4((0.2, 0.4, 0.6, 0.8)) = int4(zyxw * 255.001953) = (153, 102, 51, 204);
     * sincos(0): s = 0, c = 1 */
    const char *src = "float4 v; float z;\n" VS_PASS
        "float4 ps() : COLOR { int4 b = D3DCOLORtoUBYTE4(v); float s, c; sincos(z, s, c);\n"
        "  return float4(b.x / 255.0, b.y / 255.0, b.z / 255.0 + s, b.w / 255.0 * c); }\n" TECH("ps()");
    const uval u[] = { {"v", 'v', 1, {0.2f, 0.4f, 0.6f, 0.8f}, {0}}, {"z", 'f', 1, {0}, {0}} };
    check_pixel(src, u, 2, 0.6f, 0.4f, 0.2f, 0.8f);
}

static void orientation_and_ddy(void) {
    /* TEXCOORD0.y is 0 at NDC y = +1: the top row read top-down shows v near 0 (1/16 at the
     * first pixel centre of 8), the bottom row near 1; ddy(v) is +1/8 per pixel as in D3D */
    const char *src = VS_PASS
        "float4 ps(float2 uv : TEXCOORD0) : COLOR { return float4(uv.y, 0.5 + ddy(uv.y), 0, 1); }\n" TECH("ps()");
    float top[4], bottom[4];
    CHECK(render(src, NULL, NULL, 0, 0, 0, top));
    CHECK(render(src, NULL, NULL, 0, 0, H - 1, bottom));
    CHECK_NEAR(top[0], 1.0 / 16, TOL);
    CHECK_NEAR(bottom[0], 15.0 / 16, TOL);
    CHECK_NEAR(top[1], 0.5 + 1.0 / 8, TOL);
}

/* With hfx_pos_fixup = (1/W, -1/H, 0, H) pixel (i, j) samples D3D9's point: texture
 * coordinates i/8, j/8 instead of GL's (i + 0.5)/8, and VPOS = (i, j) counted from the top.
 * With .z = 1 (render-target flip) the picture is upside down: the top row has VPOS.y = 7. */
static void pos_fixup_gives_d3d9_centres(void) {
    const char *src = VS_PASS
        "float4 ps(float2 uv : TEXCOORD0, float2 vp : VPOS) : COLOR { return float4(uv, vp / 8); }\n" TECH("ps()");
    const uval fix = { "hfx_pos_fixup", 'v', 1, {1.0f / W, -1.0f / H, 0, H}, {0} };
    float px[4];
    CHECK(render(src, NULL, &fix, 1, 2, 3, px));
    CHECK_NEAR(px[0], 2.0 / 8, TOL);
    CHECK_NEAR(px[1], 3.0 / 8, TOL);
    CHECK_NEAR(px[2], 2.0 / 8, TOL);
    CHECK_NEAR(px[3], 3.0 / 8, TOL);
    const uval flip = { "hfx_pos_fixup", 'v', 1, {1.0f / W, 1.0f / H, 1, H}, {0} };
    CHECK(render(src, NULL, &flip, 1, 2, 0, px));
    CHECK_NEAR(px[1], 7.0 / 8, TOL); /* the last texture row is at the top of the GL image */
    CHECK_NEAR(px[3], 7.0 / 8, TOL);
}

/* D3D9's alpha test, carried by the pixel shader of an effect whose pass turns it on: GREATER
 * (5) against 0.5 keeps alpha 0.75 and discards alpha 0.25; function 0 (unset) keeps
 * everything. */
static void alpha_test_in_shader(void) {
    const char *src = "float a;\n" VS_PASS "float4 ps() : COLOR { return float4(1, 1, 1, a); }\n"
                      "technique T { pass P { AlphaTestEnable = TRUE;\n"
                      "    VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n";
    const uval keep[] = { {"a", 'f', 1, {0.75f}, {0}}, {"hfx_alpha_func", 'i', 1, {0}, {5}}, {"hfx_alpha_ref", 'f', 1, {0.5f}, {0}} };
    const uval drop[] = { {"a", 'f', 1, {0.25f}, {0}}, {"hfx_alpha_func", 'i', 1, {0}, {5}}, {"hfx_alpha_ref", 'f', 1, {0.5f}, {0}} };
    const uval off[] = { {"a", 'f', 1, {0.25f}, {0}} };
    check_pixel(src, keep, 3, 1, 1, 1, 0.75f);
    check_pixel(src, drop, 3, 0, 0, 0, 0);
    check_pixel(src, off, 1, 1, 1, 1, 0.25f);
}

static void clip_discards(void) {
    /* clip(-1) discards: the cleared (0,0,0,0) pixel stays */
    const char *src = "float k;\n" VS_PASS
        "float4 ps() : COLOR { clip(k); return float4(1, 1, 1, 1); }\n" TECH("ps()");
    const uval neg = { "k", 'f', 1, {-1}, {0} }, pos = { "k", 'f', 1, {1}, {0} };
    check_pixel(src, &neg, 1, 0, 0, 0, 0);
    check_pixel(src, &pos, 1, 1, 1, 1, 1);
}

static void struct_uniform_array(void) {
    /* spots[1].color read through a dynamic index */
    const char *src = "struct L { float4 color; int on; }; L spots[2]; int which;\n" VS_PASS
        "float4 ps() : COLOR { return spots[which].on != 0 ? spots[which].color : float4(0, 0, 1, 1); }\n" TECH("ps()");
    const uval u[] = { {"spots[1].color", 'v', 1, {0.2f, 0.4f, 0.6f, 1}, {0}}, {"spots[1].on", 'i', 1, {0}, {1}},
                       {"which", 'i', 1, {0}, {1}} };
    check_pixel(src, u, 3, 0.2f, 0.4f, 0.6f, 1);
}


/* A scalar cast to a struct fills every member (nested arrays and matrices too), to an array
 * every element: (S)0.25 gives m = all 0.25, uv[1] = (0.25, 0.25), on = (int)0.25 = 0;
 * (float[3])0.5 three 0.5s; (S)0 all zeros. Red = m._22 + uv[1].y = 0.5; green = w[2] = 0.5;
 * blue = z.m._33 + z.on + on (0) = 0; alpha 1. */
static void scalar_casts_fill_structs_and_arrays(void) {
    const char *src = "struct S { float3x3 m; float2 uv[2]; int on; };\n" VS_PASS
        "float4 ps() : COLOR { S s = (S)0.25; S z = (S)0; float w[3] = (float[3])0.5;\n"
        "  return float4(s.m._22 + s.uv[1].y, w[2], z.m._33 + z.on + s.on, 1); }\n" TECH("ps()");
    check_pixel(src, NULL, 0, 0.5f, 0.5f, 0, 1);
}

/* pow on SM2/SM3 is D3D9's pow instruction, which raises |x|: with X = -4, pow(X, 2) = 16 and
 * pow(X, 0.5) = 2 (GLSL's pow is undefined for a negative base). 16 / 32 = 0.5; 2 / 4 = 0.5. */
static void pow_of_negative_base(void) {
    const char *src = "float X;\n" VS_PASS
        "float4 ps() : COLOR { return float4(pow(X, 2) / 32, pow(X, 0.5) / 4, 0, 1); }\n" TECH("ps()");
    const uval u[] = {{"X", 'f', 1, {-4}, {0}}};
    check_pixel(src, u, 1, 0.5f, 0.5f, 0, 1);
}

/* A small constant power of an expression (not a variable) is fxc's products of it, computed
 * once: X - 0.25 = -0.75 gives -0.75, 0.5625, -0.421875, 0.31640625 (the sign kept). */
static void pow_small_of_expression(void) {
    const char *src = "float X;\n" VS_PASS
        "float4 ps() : COLOR { return float4(pow(X - 0.25, 1) + 1, pow(X - 0.25, 2), pow(X - 0.25, 3) + 1, pow(X - 0.25, 4)); }\n"
        TECH("ps()");
    const uval u[] = {{"X", 'f', 1, {-0.5f}, {0}}};
    /* fxc's products keep the sign: (-0.75 + 1, 0.5625, -0.421875 + 1, 0.31640625) */
    check_pixel(src, u, 1, 0.25f, 0.5625f, 0.578125f, 0.31640625f);
}

/* (float[4])U and (int[4])U take U's components in order; (int)-1.6 truncates to -1:
 * (w[2], -i[3] * 0.5, w[1], 1) = (0.7, 0.5, 0.2, 1). */
static void vector_cast_to_array(void) {
    const char *src = "float4 U;\n" VS_PASS
        "float4 ps() : COLOR { float w[4] = (float[4])U; int i[4] = (int[4])U; return float4(w[2], -i[3] * 0.5, w[1], 1); }\n"
        TECH("ps()");
    const uval u[] = {{"U", 'v', 1, {0.1f, 0.2f, 0.7f, -1.6f}, {0}}};
    check_pixel(src, u, 1, 0.7f, 0.5f, 0.2f, 1);
}

/* A constructor as the target: float4(s, t) = v writes v.x to s and v.yzw to t, as fxc does:
 * (s, t.x, t.z, 1) = (0.25, 0.5, 1, 1). */
static void constructor_as_lvalue(void) {
    const char *src = VS_PASS
        "float4 ps() : COLOR { float s; float3 t; float4(s, t) = float4(0.25, 0.5, 0.75, 1); return float4(s, t.x, t.z, 1); }\n"
        TECH("ps()");
    check_pixel(src, NULL, 0, 0.25f, 0.5f, 1, 1);
}

/* HLSL before SM6 evaluates both operands of ?: : f3 = c ? (f1 = 0.5) + 0.2 : (f2 = 0.6) with
 * c true leaves f1 = 0.5 and f2 = 0.6, and f3 = 0.7. Output (f1, f2, f3, 1). */
static void select_evaluates_both_operands(void) {
    const char *src = "float C;\n" VS_PASS
        "float4 ps() : COLOR { float f1 = 0, f2 = 0, f3; f3 = C > 0 ? (f1 = 0.5) + 0.2 : (f2 = 0.6); return float4(f1, f2, f3, 1); }\n"
        TECH("ps()");
    const uval u[] = {{"C", 'f', 1, {1}, {0}}};
    check_pixel(src, u, 1, 0.5f, 0.6f, 0.7f, 1);
}

static void more_intrinsics(void) {
    /* atan2(1, -1) = 3*pi/4 = 2.35619 -> / 4 = 0.589; log10(100) = 2 -> / 4; step(0.5, 0.7) = 1;
     * pow(2, 3) = 8 -> / 16; */
    const char *src = "float4 a;\n" VS_PASS
        "float4 ps() : COLOR { return float4(atan2(a.x, a.y) / 4, log10(a.z) / 4, step(0.5, a.w), pow(2, a.x * 3) / 16); }\n"
        TECH("ps()");
    const uval u = { "a", 'v', 1, {1, -1, 100, 0.7f}, {0} };
    check_pixel(src, &u, 1, 2.35619449f / 4, 0.5f, 1, 0.5f);
}

/* A 2x2 texture: first uploaded row red, green; second row blue, white. Texture coordinate
 * (0, 0) is the first row in D3D9 and in GL alike. */
static void texture_sampling(void) {
    static const unsigned char texels[] = { 255, 0, 0, 255,  0, 255, 0, 255,  0, 0, 255, 255,  255, 255, 255, 255 };
    GLuint tex;
    f.GenTextures(1, &tex);
    f.ActiveTexture(GL_TEXTURE0);
    f.BindTexture(GL_TEXTURE_2D, tex);
    f.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    const char *src = "texture t; sampler s = sampler_state { Texture = <t>; }; int which;\n" VS_PASS
        "float4 ps() : COLOR {\n"
        "  if (which == 0) return tex2D(s, float2(0.25, 0.25));\n"
        "  if (which == 1) return tex2D(s, float2(0.75, 0.25));\n"
        "  if (which == 2) return tex2Dlod(s, float4(0.25, 0.75, 0, 0));\n"
        "  return tex2Dproj(s, float4(1.5, 1.5, 0, 2)); }\n" TECH("ps()");
    static const float want[4][4] = { {1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1} };
    for (int k = 0; k < 4; k++) {
        const uval u[] = { {"s", 't', 1, {0}, {0}}, {"which", 'i', 1, {0}, {k}} };
        check_pixel(src, u, 2, want[k][0], want[k][1], want[k][2], want[k][3]);
    }
    f.DeleteTextures(1, &tex);
}

/* D3D clips z to 0..w: z = 0.5 draws, z = -0.25 and z = 1.5 do not (GL alone would draw -0.25). */
static void depth_range_remap(void) {
    const char *src = "float z;\n"
        "float4 vs(float4 p : POSITION) : POSITION { return float4(p.xy, z, 1); }\n"
        "float4 ps() : COLOR { return float4(1, 1, 1, 1); }\n" TECH("ps()");
    const uval in = { "z", 'f', 1, {0.5f}, {0} }, near = { "z", 'f', 1, {-0.25f}, {0} }, far = { "z", 'f', 1, {1.5f}, {0} };
    check_pixel(src, &in, 1, 1, 1, 1, 1);
    check_pixel(src, &near, 1, 0, 0, 0, 0);
    check_pixel(src, &far, 1, 0, 0, 0, 0);
}

/* The vertex shader transforms with mul(p, World) (World scales by 0.5 and moves right by
 * 0.5) and passes a colour through COLOR0; the quad then covers x in 0..1 of NDC only. */
static void vertex_transform_and_varying(void) {
    const char *src = "float4x4 World; float4 tint;\n"
        "struct V { float4 pos : POSITION; float4 col : COLOR0; };\n"
        "V vs(float4 p : POSITION) { V o; o.pos = mul(p, World); o.col = tint * 2; return o; }\n"
        "float4 ps(float4 c : COLOR0) : COLOR { return c; }\n" TECH("ps()");
    const uval u[] = { {"World", '4', 1, {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1}, {0}},
                       {"tint", 'v', 1, {0.1f, 0.2f, 0.3f, 0.5f}, {0}} };
    float px[4];
    CHECK(render(src, NULL, u, 2, W - 2, H / 2, px)); /* NDC x = 0.625: inside */
    CHECK_NEAR(px[0], 0.2, TOL);
    CHECK_NEAR(px[1], 0.4, TOL);
    CHECK_NEAR(px[2], 0.6, TOL);
    CHECK_NEAR(px[3], 1.0, TOL);
    CHECK(render(src, NULL, u, 2, 1, H / 2, px)); /* NDC x = -0.625: outside */
    CHECK_NEAR(px[0], 0, TOL);
}

/* Derived varyings (compiler/ir/lower/varyings.c): v = Cam - wp is computed per pixel from the
 * interpolated wp, and gives what interpolating v gives. At NDC (x, y), wp = (x, y, 0) / 2 and
 * v = (1 - x / 2, 2 - y / 2, 3), so the colour is (0.6 - x / 20, 0.7 - y / 20, 0.8, 0.5 + x / 2).
 * Pixel (6, 1) from the top left is at NDC (0.625, 0.625), pixel (1, 6) at (-0.625, -0.625). */
static void derived_varying_values(void) {
    const char *src = "float3 Cam;\n"
        "struct V { float4 pos : POSITION; float3 v : TEXCOORD0; float3 wp : TEXCOORD1; };\n"
        "V vs(float4 p : POSITION) { V o; float4 wp = p * 0.5; o.pos = p; o.v = Cam - wp; o.wp = wp; return o; }\n"
        "float4 ps(V i) : COLOR { return float4(i.v * 0.1 + 0.5, i.wp.x + 0.5); }\n" TECH("ps()");
    const uval cam = { "Cam", 'c', 1, {1, 2, 3}, {0} };
    const unsigned modes[] = { 0, HFXC_NO_DERIVED_VARYINGS };
    for (int m = 0; m < 2; m++) {
        float px[4];
        CHECK(render_with(modes[m], src, NULL, &cam, 1, 6, 1, px));
        CHECK_NEAR(px[0], 0.56875f, TOL);
        CHECK_NEAR(px[1], 0.66875f, TOL);
        CHECK_NEAR(px[2], 0.8f, TOL);
        CHECK_NEAR(px[3], 0.8125f, TOL);
        CHECK(render_with(modes[m], src, NULL, &cam, 1, 1, 6, px));
        CHECK_NEAR(px[0], 0.63125f, TOL);
        CHECK_NEAR(px[1], 0.73125f, TOL);
        CHECK_NEAR(px[2], 0.8f, TOL);
        CHECK_NEAR(px[3], 0.1875f, TOL);
    }
}

/* Statements and l-values: statics, switch, do-while, out/inout parameters, swizzle and
 * matrix element writes, increments. */
static void statements_and_lvalues(void) {
    const char *src = "int k;\n"
        "static float base = 0.05 * 2;\n"
        "void twice(inout float x, out float y) { y = x; x *= 2; }\n" VS_PASS
        "float4 ps() : COLOR {\n"
        "  float r = 0;\n"
        "  switch (k) { case 1: r = 0.25; break; case 2: r = 0.5; break; default: r = 1; }\n"
        "  int n = 0; do { n++; } while (n < 3);\n"            /* n = 3 */
        "  float a = 0.2, b; twice(a, b);\n"                    /* a = 0.4, b = 0.2 */
        "  float4 v = 0; v.zx = float2(a, b);\n"                /* v = (0.2, 0, 0.4, 0) */
        "  float2x2 m = 0; m._m10 = 0.3; m[0] = float2(0.1, base);\n" /* m = [[0.1, 0.1], [0.3, 0]] */
        "  v.y = m._21 + m[0].y + n * 0.1 - 0.3;\n"            /* 0.3 + 0.1 + 0.3 - 0.3 = 0.4 */
        "  v.w = r;\n"
        "  return v; }\n" TECH("ps()");
    const uval u = { "k", 'i', 1, {0}, {2} };
    check_pixel(src, &u, 1, 0.2f, 0.4f, 0.4f, 0.5f);
}

/* any / all, vector comparisons, bit operations and shifts on ints, vector logic. */
static void vector_logic_and_bits(void) {
    const char *src = "float4 v; int i;\n" VS_PASS
        "float4 ps() : COLOR {\n"
        "  bool4 gt = v > 0.5;\n"                               /* (F, T, T, F) */
        "  bool4 both = gt && (v < 0.8);\n"                      /* (F, T, F, F) for v = (0.2, 0.7, 0.9, 0.4) */
        "  float a = any(gt) ? 1 : 0;\n"
        "  float b = all(gt) ? 1 : 0;\n"
        "  int bits = ((i << 2) | 1) & 0xD;\n"                   /* i = 3: (12 | 1) & 13 = 13 */
        "  return float4(a, b, bits / 16.0, dot(float4(both), float4(1, 1, 1, 1)) * 0.5); }\n" TECH("ps()");
    const uval u[] = { {"v", 'v', 1, {0.2f, 0.7f, 0.9f, 0.4f}, {0}}, {"i", 'i', 1, {0}, {3}} };
    check_pixel(src, u, 2, 1, 0, 13.0f / 16, 0.5f);
}

/* User functions called in compile arguments, nested, from both stages and in several passes:
 * each comes out before the entry that now calls it. t = 0.25, m = 0.125, f = 0.5:
 * helper(t) = 0.5, fadeout = saturate(0.5 - 0.125) * 0.5 = 0.1875.
 * T: k = fadeout + helper(m) = 0.4375; fade = 0.1875; size = lerp(0.25, 0.75, 0.1875) = 0.34375.
 * U: k = helper(f) = 1; fade = helper(0.1875) = 0.375; size = lerp(0, 1, 0.1875) = 0.1875. */
static void functions_in_compile_arguments(void) {
    const char *src =
        "float t; float m; float f;\n"
        "float helper(float x) { return x * 2; }\n"
        "float fadeout(float t, float m, float f) { return saturate(helper(t) - m) * f; }\n"
        "float4 lerpsize(float t, float m, float4 a, float4 b, float f) { return lerp(a, b, fadeout(t, m, f)); }\n"
        "struct V { float4 pos : POSITION; float2 uv : TEXCOORD0; };\n"
        "V vs(float4 p : POSITION, float2 uv : TEXCOORD0, uniform float k) { V o; o.pos = p; o.uv = float2(k, uv.y); return o; }\n"
        "float4 strokePS(uniform float fade, uniform float4 size, float2 uv : TEXCOORD0) : COLOR0 {\n"
        "  return float4(fade, size.y, uv.x, 1); }\n"
        "technique T {\n"
        "  pass P0 { VertexShader = compile vs_3_0 vs(fadeout(t, m, f) + helper(m));\n"
        "            PixelShader = compile ps_3_0 strokePS(fadeout(t, m, f), lerpsize(t, m, 0.25, 0.75, f)); }\n"
        "  pass P1 { VertexShader = compile vs_3_0 vs(helper(t));\n"
        "            PixelShader = compile ps_3_0 strokePS(helper(fadeout(t, m, f)), lerpsize(t, m, 0, 1, helper(f))); } }\n"
        "technique U { pass P0 { VertexShader = compile vs_3_0 vs(helper(f));\n"
        "  PixelShader = compile ps_3_0 strokePS(helper(fadeout(t, m, f)), lerpsize(t, m, 0, 1, f)); } }\n";
    const uval u[] = { {"t", 'f', 1, {0.25f}, {0}}, {"m", 'f', 1, {0.125f}, {0}}, {"f", 'f', 1, {0.5f}, {0}} };
    float px[4] = {0};
    CHECK(render(src, "T", u, 3, W / 2, H / 2, px));
    CHECK_NEAR(px[0], 0.1875f, TOL);
    CHECK_NEAR(px[1], 0.34375f, TOL);
    CHECK_NEAR(px[2], 0.4375f, TOL);
    CHECK(render(src, "U", u, 3, W / 2, H / 2, px));
    CHECK_NEAR(px[0], 0.375f, TOL);
    CHECK_NEAR(px[1], 0.1875f, TOL);
    CHECK_NEAR(px[2], 1.0f, TOL);
}

/* Entry-point arrays with a semantic take one register each (`float4 t[2] : TEXCOORD0` is
 * TEXCOORD0 and TEXCOORD1), in both directions; an output struct member without a semantic
 * goes nowhere. uv[0] is the quad's TEXCOORD0 (u, v, 0, 1): t[1] = (0, 1, 0.75, 0), so the pixel
 * shader gives (t[0].x, t[0].y, t[1].z, t[1].y) = (0.25, 0.5, 0.75, 1) either way. */
static void entry_point_arrays(void) {
    const char *src =
        "struct VO { float4 p : POSITION; float4 t[2] : TEXCOORD0; float unused; };\n"
        "VO vs(float4 p : POSITION, float4 uv[2] : TEXCOORD0) {\n"
        "  VO o; o.p = p; o.t[0] = float4(0.25, 0.5, 0, 0); o.t[1] = float4(uv[0].zw, 0.75, 0) + uv[1] * 0;\n"
        "  o.unused = 3; return o; }\n"
        "float4 apart(float4 a : TEXCOORD0, float4 b : TEXCOORD1) : COLOR { return float4(a.xy, b.z, b.y); }\n"
        "float4 whole(float4 t[2] : TEXCOORD0) : COLOR { return float4(t[0].xy, t[1].z, t[1].y); }\n"
        "technique A { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 apart(); } }\n"
        "technique W { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 whole(); } }\n";
    for (int t = 0; t < 2; t++) {
        float px[4] = {0};
        CHECK(render(src, t ? "W" : "A", NULL, 0, W / 2, H / 2, px));
        CHECK_NEAR(px[0], 0.25f, TOL);
        CHECK_NEAR(px[1], 0.5f, TOL);
        CHECK_NEAR(px[2], 0.75f, TOL);
        CHECK_NEAR(px[3], 1.0f, TOL);
    }
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa GL 3.3 context");
    load_gl();
    RUN(mul_row_vector);
    RUN(functions_in_compile_arguments);
    RUN(entry_point_arrays);
    RUN(scalar_casts_fill_structs_and_arrays);
    RUN(pow_of_negative_base);
    RUN(pow_small_of_expression);
    RUN(vector_cast_to_array);
    RUN(constructor_as_lvalue);
    RUN(select_evaluates_both_operands);
    RUN(mul_column_vector);
    RUN(mul_translation);
    RUN(mul_truncated);
    RUN(mul_matrix_matrix);
    RUN(matrix_swizzles);
    RUN(matrix_constructor_rows);
    RUN(frac_fmod_round);
    RUN(integer_division);
    RUN(lerp_lit_saturate);
    RUN(lit_negative);
    RUN(loop_with_break);
    RUN(loop_invariant_hoisted);
    RUN(uniform_array_out_of_range);
    RUN(guarded_reads_past_either_end);
    RUN(specialisation);
    RUN(global_written_by_shader);
    RUN(truncation_and_vector_select);
    RUN(d3dcolor_sincos);
    RUN(orientation_and_ddy);
    RUN(pos_fixup_gives_d3d9_centres);
    RUN(alpha_test_in_shader);
    RUN(clip_discards);
    RUN(struct_uniform_array);
    RUN(more_intrinsics);
    RUN(texture_sampling);
    RUN(depth_range_remap);
    RUN(vertex_transform_and_varying);
    RUN(derived_varying_values);
    RUN(statements_and_lvalues);
    RUN(vector_logic_and_bits);
    test_gl_destroy(gl);
    return test_summary();
}
