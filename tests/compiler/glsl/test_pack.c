/* test_pack.c: HFXC_PACK_UNIFORMS. Registers follow the rule of docs/hfxc.md ("Packed
 * uniforms"), checked by hand on a small effect; the GLSL of one stage is checked as text; every
 * stage of that effect, of every seed and of every effect in fx/ compiled with the flag is
 * valid GLSL (330, ES 300, and 110 wherever the unpacked output is) and valid SPIR-V whose
 * locations agree with common/spirv_loc.c; .hfxo keeps the registers; without the flag nothing
 * is packed. */
#define GL_GLEXT_PROTOTYPES 0
#include <GL/gl.h>
#include <GL/glext.h>
#include <dirent.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "gl_context.h"
#include "gl_fns.h"
#include "glsl_check.h"
#include "hfx/hfxc.h"
#include "glsl/spirv.h"
#include "spirv_loc.h"
#include "test.h"

#if defined(__has_include)
#if __has_include(<spirv-tools/libspirv.h>)
#include <spirv-tools/libspirv.h>
#define HAVE_SPIRV_TOOLS 1
#endif
#endif

static const unsigned GLSL330 = 1u << HFX_TARGET_GLSL330, ES300 = 1u << HFX_TARGET_GLSLES300,
                      GLSL110 = 1u << HFX_TARGET_GLSL110, SPIRV = 1u << HFX_TARGET_SPIRV;

/* Every kind of parameter: the floats are packed, the rest are not. */
static const char mixed_fx[] =
    "float Scale;\nfloat2 Offset;\nfloat3 LightDir;\nfloat4 Tint;\nfloat4x4 World;\n"
    "#ifndef SQUARE\nfloat3x4 Bones;\nfloat4x3 Shape;\n#endif\n"
    "int Count;\nbool Enabled;\nfloat4 Palette[2];\nstruct Light { float3 Dir; float4 Color; };\nLight Sun;\n"
    "static float3 Twice = LightDir * 2;\n" /* a static's initialiser reads a packed parameter */
    "struct VSOut { float4 Pos : POSITION; float4 Color : COLOR0; };\n"
    "VSOut VS(float4 p : POSITION)\n{\n    VSOut o;\n"
    "#ifndef SQUARE\n    float3 q = mul(Bones, p) + mul(p, Shape);\n#else\n    float3 q = p.xyz;\n#endif\n"
    "    o.Pos = mul(float4(q * Scale, 1), World) + float4(Offset, 0, 0);\n"
    "    o.Color = Palette[Count] + Sun.Color;\n    return o;\n}\n"
    "float4 PS(float4 c : COLOR0) : COLOR0\n{\n    Tint.a = 1;\n" /* written: a private copy of the packed value */
    "    float4 r = c * Tint + float4(Twice, 0);\n    if (Enabled) r *= Scale;\n    return r;\n}\n"
    "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";

/* The registers by hand, and uploads without preshaders: this file pins the parameters' layout
 * (preshaders take the registers after it: tests/runtime/test_preshaders.c). */
static hfxc_result *compile_text(const char *src, const char *name, unsigned targets, unsigned flags,
                                 const char *define) {
    hfxc_options o = {0};
    o.targets = targets;
    o.flags = flags | HFXC_NO_PRESHADERS;
    o.defines = &define;
    o.define_count = define ? 1 : 0;
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), name, &o);
    if (!hfxc_result_ok(r)) {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s: %s\n", name, d);
        free(d);
    }
    return r;
}

static hfxc_result *compile_path(const char *path, unsigned targets, unsigned flags) {
    hfxc_options o = {0};
    o.targets = targets;
    o.flags = flags | HFXC_NO_PRESHADERS;
    return hfxc_compile_file(path, &o);
}

static const hfx_fx_uniform_use *use_of(const hfx_fx_effect *fx, const hfx_fx_program *p, const char *name) {
    for (uint32_t k = 0; k < p->uniform_count; k++)
        if (strcmp(fx->params[p->uniforms[k].param].name, name) == 0) return &p->uniforms[k];
    return NULL;
}

static uint32_t reg_of(const hfx_fx_effect *fx, const hfx_fx_program *p, const char *name) {
    const hfx_fx_uniform_use *u = use_of(fx, p, name);
    CHECK(u != NULL);
    return u ? u->reg : 0xdeadu;
}

static int link_program(const hfx_fx_program *p, int target, const char *what) {
    char *log = NULL;
    const char *vs = p->code[HFX_STAGE_VERTEX][target].data, *fs = p->code[HFX_STAGE_FRAGMENT][target].data;
    if (!vs || !fs) {
        fprintf(stderr, "%s: no code\n", what);
        return 0;
    }
    int ok = test_glsl_link(vs, fs, &log);
    if (!ok) fprintf(stderr, "%s:\n%s\n--- vertex\n%s\n--- fragment\n%s\n", what, log ? log : "", vs, fs);
    free(log);
    return ok;
}

static void registers_by_hand(void) {
    hfxc_result *r = compile_text(mixed_fx, "mixed.fx", GLSL330 | ES300, HFXC_PACK_UNIFORMS, NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx && fx->program_count == 1);
    if (fx && fx->program_count == 1) {
        const hfx_fx_program *p = &fx->programs[0];
        /* The pixel stage's first, in parameter order: Scale and LightDir (Twice's initialiser)
         * as they are, then Tint (copied: the shader writes it); then the vertex stage's. A
         * float, float2, float3, float4 take one each; float4x4 four rows; float3x4 three rows;
         * float4x3 four rows. */
        CHECK_INT(reg_of(fx, p, "Scale"), 0);
        CHECK_INT(reg_of(fx, p, "LightDir"), 1);
        CHECK_INT(reg_of(fx, p, "Tint"), 2);
        CHECK_INT(reg_of(fx, p, "Offset"), 3);
        CHECK_INT(reg_of(fx, p, "World"), 4);
        CHECK_INT(reg_of(fx, p, "Bones"), 8);
        CHECK_INT(reg_of(fx, p, "Shape"), 11);
        CHECK_INT(p->reg_count, 15);
        CHECK_INT(reg_of(fx, p, "Count"), HFX_NONE);
        CHECK_INT(reg_of(fx, p, "Enabled"), HFX_NONE);
        CHECK_INT(reg_of(fx, p, "Palette"), HFX_NONE);
        CHECK_INT(reg_of(fx, p, "Sun"), HFX_NONE);
        for (int t = HFX_TARGET_GLSL330; t <= HFX_TARGET_GLSLES300; t++) {
            const char *vs = p->code[HFX_STAGE_VERTEX][t].data, *fs = p->code[HFX_STAGE_FRAGMENT][t].data;
            CHECK_CONTAINS(vs, "uniform vec4 hfx_c[15];\n");
            CHECK_CONTAINS(fs, "uniform vec4 hfx_c[15];\n"); /* the same size in both stages */
            CHECK_CONTAINS(vs, "    Bones = mat3x4(hfx_c[8], hfx_c[9], hfx_c[10]);\n");
            CHECK_CONTAINS(vs, "    Shape = mat4x3(hfx_c[11].xyz, hfx_c[12].xyz, hfx_c[13].xyz, hfx_c[14].xyz);\n");
            CHECK_CONTAINS(vs, "    World = mat4(hfx_c[4], hfx_c[5], hfx_c[6], hfx_c[7]);\n");
            CHECK_CONTAINS(vs, "    Offset = hfx_c[3].xy;\n");
            CHECK_CONTAINS(vs, "uniform int Count;\n");
            /* read at Count, which nothing bounds: one zero element past its end (glsl_expr.c) */
            CHECK_CONTAINS(vs, "uniform vec4 Palette[3];\n");
            CHECK_CONTAINS(vs, "o.Color = Palette[min(uint(Count), 2u)] + Sun.Color;\n");
            CHECK_CONTAINS(vs, "uniform Light Sun;\n");
            CHECK_CONTAINS(fs, "uniform bool Enabled;\n");
            /* packed values first: the static and the written copy are made from them */
            CHECK_CONTAINS(fs, "{\n    Tint = hfx_c[2];\n    LightDir = hfx_c[1].xyz;\n    Scale = hfx_c[0].x;\n"
                               "    hfx_priv_Tint = Tint;\n    hfx_static_Twice = LightDir * vec3(2.0);\n");
            CHECK(vs && !strstr(vs, "uniform float Scale"));
            CHECK(fs && !strstr(fs, "uniform vec4 Tint"));
            CHECK(link_program(p, t, t == HFX_TARGET_GLSL330 ? "mixed.fx (330)" : "mixed.fx (ES 300)"));
        }
    }
    hfxc_result_free(r);

    /* GLSL 110 has no non-square matrices and says so, as without the flag. */
    r = compile_text(mixed_fx, "mixed.fx", GLSL110, HFXC_PACK_UNIFORMS, NULL);
    CHECK(!hfxc_result_ok(r));
    char *d = hfxc_diagnostics_text(r);
    CHECK_CONTAINS(d, "non-square matrices are not available in GLSL 110");
    free(d);
    hfxc_result_free(r);
    r = compile_text(mixed_fx, "mixed.fx", GLSL110 | GLSL330, HFXC_PACK_UNIFORMS, "SQUARE");
    fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        const hfx_fx_program *p = &fx->programs[0];
        CHECK_INT(reg_of(fx, p, "World"), 4);
        CHECK_INT(p->reg_count, 8);
        CHECK_CONTAINS(p->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL110].data, "uniform vec4 hfx_c[8];\n");
        CHECK(link_program(p, HFX_TARGET_GLSL110, "mixed.fx SQUARE (110)"));
        CHECK(link_program(p, HFX_TARGET_GLSL330, "mixed.fx SQUARE (330)"));
    }
    hfxc_result_free(r);
}

/* Without the flag: no register anywhere, and the text of the default build. */
static void off_by_default(void) {
    hfxc_result *r = compile_text(mixed_fx, "mixed.fx", GLSL330 | ES300, 0, NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    for (uint32_t i = 0; fx && i < fx->program_count; i++) {
        const hfx_fx_program *p = &fx->programs[i];
        CHECK_INT(p->reg_count, 0);
        for (uint32_t k = 0; k < p->uniform_count; k++) CHECK_INT(p->uniforms[k].reg, HFX_NONE);
        for (int s = 0; s < HFX_STAGE_COUNT; s++) {
            CHECK(!strstr(p->code[s][HFX_TARGET_GLSL330].data, "hfx_c"));
            CHECK(!strstr(p->code[s][HFX_TARGET_GLSLES300].data, "hfx_c"));
        }
    }
    hfxc_result_free(r);
}

/* No pass turns the alpha test on: the pixel shader carries none of its code. */
static const char small_fx[] =
    "float4 Tint;\nfloat Gain;\nfloat3x3 M;\nint N;\n"
    "float4 PS(float4 c : COLOR0) : COLOR0 { return float4(mul(c.rgb, M), 1) * Tint * Gain + N; }\n"
    "technique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n";

static const char small_frag[] =
    "#version 330 core\n"
    "// pixel shader generated by hfx from PS\n"
    "\n"
    "uniform vec4 hfx_c[5];\n"
    "mat3 M; // hfx_c[2..4]\n"
    "vec4 Tint; // hfx_c[0]\n"
    "float Gain; // hfx_c[1]\n"
    "uniform int N;\n"
    "in vec4 hfx_v_COLOR0;\n"
    "layout(location = 0) out vec4 hfx_o_COLOR0;\n"
    "\n"
    "// PS (entry point)\n"
    "vec4 PS(vec4 c)\n"
    "{\n"
    "    return vec4(M * c.xyz, 1.0) * Tint * Gain + vec4(N);\n"
    "}\n"
    "\n"
    "void main()\n"
    "{\n"
    "    M = mat3(hfx_c[2].xyz, hfx_c[3].xyz, hfx_c[4].xyz);\n"
    "    Tint = hfx_c[0];\n"
    "    Gain = hfx_c[1].x;\n"
    "    vec4 hfx_arg0 = vec4(0.0);\n"
    "    hfx_arg0 = hfx_v_COLOR0;\n"
    "    vec4 hfx_ret = PS(hfx_arg0);\n"
    "    hfx_o_COLOR0 = hfx_ret;\n"
    "}\n";

static void exact_small_stage(void) {
    hfxc_result *r = compile_text(small_fx, "small.fx", GLSL330, HFXC_PACK_UNIFORMS, NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        const hfx_fx_program *p = &fx->programs[0];
        CHECK_STR(p->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data, small_frag);
        /* The fixed-function vertex stand-in reads no parameter: no hfx_c. */
        CHECK(!strstr(p->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data, "hfx_c"));
        CHECK_INT(p->reg_count, 5);
        CHECK(link_program(p, HFX_TARGET_GLSL330, "small.fx"));
    }
    hfxc_result_free(r);
}

/* More than 256 registers: packing stops at the parameter that does not fit. */
static void cap_at_256_registers(void) {
    size_t cap = 1 << 16;
    char *src = malloc(cap);
    size_t n = 0;
    for (int i = 0; i < 70; i++) n += (size_t)snprintf(src + n, cap - n, "float4x4 m%d;\n", i);
    n += (size_t)snprintf(src + n, cap - n, "float last;\nfloat4 PS() : COLOR0 { float4 s = last;\n");
    for (int i = 0; i < 70; i++) n += (size_t)snprintf(src + n, cap - n, "s += m%d[1];\n", i);
    snprintf(src + n, cap - n, "return s; }\ntechnique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n");
    hfxc_result *r = compile_text(src, "many.fx", GLSL330, HFXC_PACK_UNIFORMS, NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        const hfx_fx_program *p = &fx->programs[0];
        CHECK_INT(p->reg_count, 256);
        CHECK_INT(reg_of(fx, p, "m63"), 252);
        CHECK_INT(reg_of(fx, p, "m64"), HFX_NONE);
        CHECK_INT(reg_of(fx, p, "last"), HFX_NONE); /* it would fit, but packing has stopped */
        CHECK_CONTAINS(p->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data, "uniform mat4 m64;\n");
        char *log = NULL;
        CHECK(test_glsl_compile(p->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data, 1, &log));
        free(log);
    }
    hfxc_result_free(r);
    free(src);
}

/* ---- on GL: the packed program shows the same values as the unpacked one ---- */

/* Each parameter's words are (base + k) / 255, so every component reads back as its own byte. */
static const struct { const char *name; unsigned rows, cols, base; } gl_params[] = {
    {"W4", 4, 4, 1}, {"B34", 3, 4, 20}, {"S43", 4, 3, 40}, {"Q", 2, 2, 60}, {"R13", 1, 3, 70}, {"C31", 3, 1, 80},
    {"Scale", 1, 1, 90}, {"Off", 1, 2, 100}, {"Dir", 1, 3, 110}, {"Tint", 1, 4, 120},
};
enum { GL_PARAMS = sizeof gl_params / sizeof *gl_params, PICKS = 8 };

static const char gl_fx[] =
    "float4x4 W4;\nfloat3x4 B34;\nfloat4x3 S43;\nfloat2x2 Q;\nfloat1x3 R13;\nfloat3x1 C31;\n"
    "float Scale;\nfloat2 Off;\nfloat3 Dir;\nfloat4 Tint;\nint Pick;\n"
    "float4 vs(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 ps() : COLOR\n{\n"
    "    if (Pick == 0) return W4[0];\n"
    "    if (Pick == 1) return mul(W4, float4(0, 1, 0, 0));\n"      /* column 1 */
    "    if (Pick == 2) return B34[2];\n"
    "    if (Pick == 3) return float4(mul(B34, float4(0, 0, 0, 1)), 1);\n" /* column 3 */
    "    if (Pick == 4) return float4(S43[3], S43._m12);\n"
    "    if (Pick == 5) return float4(Q[1], Q._m01, R13._m02);\n"
    "    if (Pick == 6) return float4(C31._m20, C31._m10, Scale, Off.y);\n"
    "    return float4(Dir, Tint.z);\n}\n"
    "technique T { pass P { VertexShader = compile vs_3_0 vs(); PixelShader = compile ps_3_0 ps(); } }\n";

/* The bytes each Pick shows, from HLSL's definitions and the words above. */
static const unsigned char gl_expected[PICKS][4] = {
    {1, 2, 3, 4}, {2, 6, 10, 14}, {28, 29, 30, 31}, {23, 27, 31, 255},
    {49, 50, 51, 45}, {62, 63, 61, 72}, {82, 81, 90, 101}, {110, 111, 112, 122},
};

typedef test_gl_fns glf;

static void load_glf(glf *f) { CHECK_INT(test_gl_fns_load(f), 0); }

static void param_words(unsigned i, float *w) {
    for (unsigned k = 0; k < gl_params[i].rows * gl_params[i].cols; k++) w[k] = (float)(gl_params[i].base + k) / 255.0f;
}

/* As today's runtime: the row-major words into the uniform's own GLSL type, transpose = GL_FALSE. */
static void upload_unpacked(const glf *f, GLuint prog, unsigned i) {
    float w[16];
    param_words(i, w);
    GLint loc = f->GetUniformLocation(prog, gl_params[i].name);
    if (loc < 0) return;
    unsigned r = gl_params[i].rows, c = gl_params[i].cols;
    if (r == 4 && c == 4) f->UniformMatrix4fv(loc, 1, GL_FALSE, w);
    else if (r == 3 && c == 4) f->UniformMatrix3x4fv(loc, 1, GL_FALSE, w);
    else if (r == 4 && c == 3) f->UniformMatrix4x3fv(loc, 1, GL_FALSE, w);
    else if (r == 2 && c == 2) f->UniformMatrix2fv(loc, 1, GL_FALSE, w);
    else if (r * c == 1) f->Uniform1fv(loc, 1, w);
    else if (r * c == 2) f->Uniform2fv(loc, 1, w);
    else if (r * c == 3) f->Uniform3fv(loc, 1, w);
    else f->Uniform4fv(loc, 1, w);
}

/* As a packing runtime: each row into its register, padded to four; one call for all. */
static void upload_packed(const glf *f, GLuint prog, const hfx_fx_effect *fx, const hfx_fx_program *p) {
    float regs[4 * 64] = {0};
    CHECK(p->reg_count > 0 && p->reg_count <= 64);
    for (uint32_t k = 0; k < p->uniform_count; k++) {
        const hfx_fx_uniform_use *u = &p->uniforms[k];
        const char *name = fx->params[u->param].name;
        for (unsigned i = 0; i < GL_PARAMS; i++) {
            if (strcmp(gl_params[i].name, name) != 0) continue;
            if (!hfx_fx_use_packed(p, u)) {
                upload_unpacked(f, prog, i);
                continue;
            }
            float w[16];
            param_words(i, w);
            for (unsigned row = 0; row < gl_params[i].rows && u->reg + row < 64; row++)
                memcpy(&regs[4 * (u->reg + row)], &w[row * gl_params[i].cols], sizeof *w * gl_params[i].cols);
        }
    }
    GLint loc = f->GetUniformLocation(prog, "hfx_c[0]");
    CHECK(loc >= 0);
    f->Uniform4fv(loc, (GLsizei)p->reg_count, regs);
}

static GLuint gl_program(const glf *f, const hfx_fx_program *p) {
    GLuint sh[2], prog = f->CreateProgram();
    for (int s = 0; s < 2; s++) {
        const char *src = p->code[s][HFX_TARGET_GLSL330].data;
        sh[s] = f->CreateShader(s ? GL_FRAGMENT_SHADER : GL_VERTEX_SHADER);
        f->ShaderSource(sh[s], 1, &src, NULL);
        f->CompileShader(sh[s]);
        f->AttachShader(prog, sh[s]);
    }
    f->LinkProgram(prog);
    f->DeleteShader(sh[0]);
    f->DeleteShader(sh[1]);
    GLint ok = 0;
    f->GetProgramiv(prog, GL_LINK_STATUS, &ok);
    CHECK(ok);
    return prog;
}

/* Draws every Pick with the effect compiled with `flags`; got[pick] are the centre pixels. */
static void gl_run(const glf *f, test_gl *gl, unsigned flags, unsigned char got[PICKS][4]) {
    hfxc_result *r = compile_text(gl_fx, "gl.fx", GLSL330, flags, NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) { hfxc_result_free(r); return; }
    const hfx_fx_program *p = &fx->programs[0];
    GLuint prog = gl_program(f, p);
    f->UseProgram(prog);
    if (flags & HFXC_PACK_UNIFORMS) upload_packed(f, prog, fx, p);
    else
        for (unsigned i = 0; i < GL_PARAMS; i++) upload_unpacked(f, prog, i);
    static const float quad[] = {-1, -1, 0, 1, 1, -1, 0, 1, -1, 1, 0, 1, -1, 1, 0, 1, 1, -1, 0, 1, 1, 1, 0, 1};
    GLuint vao, vbo;
    f->GenVertexArrays(1, &vao);
    f->BindVertexArray(vao);
    f->GenBuffers(1, &vbo);
    f->BindBuffer(GL_ARRAY_BUFFER, vbo);
    f->BufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
    f->VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), (void *)0);
    f->EnableVertexAttribArray(0);
    f->Viewport(0, 0, 4, 4);
    for (int pick = 0; pick < PICKS; pick++) {
        f->Uniform1i(f->GetUniformLocation(prog, "Pick"), pick);
        f->Clear(GL_COLOR_BUFFER_BIT);
        f->DrawArrays(GL_TRIANGLES, 0, 6);
        test_gl_read(gl, 2, 2, got[pick]);
    }
    f->DeleteBuffers(1, &vbo);
    f->DeleteVertexArrays(1, &vao);
    f->DeleteProgram(prog);
    hfxc_result_free(r);
}

static void same_values_on_gl(void) {
    test_gl *gl = test_gl_create(4, 4);
    if (!gl) {
        printf("note: no OSMesa GL 3.3 context: values not checked on GL\n");
        return;
    }
    glf f;
    load_glf(&f);
    unsigned char plain[PICKS][4] = {{0}}, packed[PICKS][4] = {{0}};
    gl_run(&f, gl, 0, plain);
    gl_run(&f, gl, HFXC_PACK_UNIFORMS, packed);
    for (int pick = 0; pick < PICKS; pick++)
        for (int c = 0; c < 4; c++) {
            if (plain[pick][c] != gl_expected[pick][c] || packed[pick][c] != gl_expected[pick][c])
                fprintf(stderr, "Pick %d component %d: expected %u, unpacked %u, packed %u\n", pick, c,
                        gl_expected[pick][c], plain[pick][c], packed[pick][c]);
            CHECK_INT(plain[pick][c], gl_expected[pick][c]);
            CHECK_INT(packed[pick][c], gl_expected[pick][c]);
        }
    test_gl_destroy(gl);
}

/* ---- SPIR-V ---- */

static int validate(const hfx_fx_code *c, const char *what) {
    if (!c->data || c->size < 20 || c->size % 4) {
        fprintf(stderr, "%s: no SPIR-V\n", what);
        return 0;
    }
#ifdef HAVE_SPIRV_TOOLS
    spv_context ctx = spvContextCreate(SPV_ENV_OPENGL_4_5);
    spv_const_binary_t bin = {(const uint32_t *)(const void *)c->data, c->size / 4};
    spv_diagnostic diag = NULL;
    spv_result_t rc = spvValidate(ctx, &bin, &diag);
    if (rc != SPV_SUCCESS) fprintf(stderr, "%s: %s\n", what, diag && diag->error ? diag->error : "invalid");
    spvDiagnosticDestroy(diag);
    spvContextDestroy(ctx);
    return rc == SPV_SUCCESS;
#else
    (void)what;
    return ((const uint32_t *)(const void *)c->data)[0] == 0x07230203u;
#endif
}

/* Locations in the modules are the ones common/spirv_loc.c computes: unpacked uniforms,
 * then hfx_c, then samplers. Returns the number of hfx_c declarations found. */
static int check_spirv_locations(const hfx_fx_effect *fx, const hfx_fx_program *p, const char *what) {
    int regs = 0;
    for (int s = 0; s < HFX_STAGE_COUNT; s++) {
        const hfx_fx_code *c = &p->code[s][HFX_TARGET_SPIRV];
        const uint32_t *w = (const uint32_t *)(const void *)c->data;
        size_t n = c->size / 4;
        int32_t loc, binding;
        if (hfx_spirv_find(w, n, HFX_FX_REGS_NAME, &loc, &binding) == 1) {
            regs++;
            CHECK(p->reg_count > 0);
            CHECK_INT(loc, (int32_t)hfx_fx_spirv_regs_location(fx, p));
            CHECK_INT(loc, hfx_spirv_location(fx, p, HFX_FX_REGS_NAME));
        }
        for (uint32_t k = 0; k < p->uniform_count; k++) {
            const char *name = fx->params[p->uniforms[k].param].glsl_name;
            if (!name) continue;
            if (hfx_fx_use_packed(p, &p->uniforms[k])) {
                CHECK_INT(hfx_spirv_location(fx, p, name), -1); /* a private global, no location */
                if (hfx_spirv_find(w, n, name, &loc, &binding) == 1) CHECK_INT(loc, -1);
            } else if (hfx_spirv_find(w, n, name, &loc, &binding) == 1) {
                CHECK_INT(loc, hfx_spirv_location(fx, p, name));
                CHECK(loc >= 0 && (uint64_t)loc < hfx_fx_spirv_regs_location(fx, p));
            }
        }
        for (uint32_t k = 0; k < p->sampler_count; k++)
            if (hfx_spirv_find(w, n, p->samplers[k].glsl_name, &loc, &binding) == 1) {
                CHECK_INT(loc, hfx_spirv_location(fx, p, p->samplers[k].glsl_name));
                CHECK(loc >= 0 && (uint64_t)loc >= hfx_fx_spirv_regs_location(fx, p) + p->reg_count);
                CHECK_INT(binding, p->samplers[k].unit);
            }
    }
    if (p->reg_count && !regs) fprintf(stderr, "%s: packs %u registers but no module declares hfx_c\n", what, p->reg_count);
    return regs;
}

static void mixed_spirv(void) {
    hfxc_result *r = compile_text(mixed_fx, "mixed.fx", SPIRV | GLSL330, HFXC_PACK_UNIFORMS, NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx && (fx->targets & SPIRV)) {
        const hfx_fx_program *p = &fx->programs[0];
        /* Palette (2), Count, Enabled, Sun (2 members), by parameter order; then hfx_c. */
        CHECK_INT(hfx_spirv_location(fx, p, "Count"), 0);
        CHECK_INT(hfx_spirv_location(fx, p, "Enabled"), 1);
        CHECK_INT(hfx_spirv_location(fx, p, "Palette"), 2);
        CHECK_INT(hfx_spirv_location(fx, p, "Sun"), 4);
        CHECK_INT(hfx_fx_spirv_regs_location(fx, p), 6);
        CHECK_INT(hfx_spirv_location(fx, p, "hfx_c"), 6);
        CHECK_INT(hfx_spirv_location(fx, p, "World"), -1);
        CHECK_INT(hfx_spirv_location(fx, p, "hfx_pos_fixup"), 6 + 15);
        const hfx_fx_code *vc = &p->code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV];
        int32_t regs_loc = -1;
        CHECK_INT(hfx_spirv_find((const uint32_t *)(const void *)vc->data, vc->size / 4, "hfx_c", &regs_loc, NULL), 1);
        CHECK_INT(regs_loc, 6);
        for (int s = 0; s < HFX_STAGE_COUNT; s++) CHECK(validate(&p->code[s][HFX_TARGET_SPIRV], "mixed.fx"));
        CHECK_INT(check_spirv_locations(fx, p, "mixed.fx"), 2);
    } else if (fx) {
        printf("note: no SPIR-V (built without glslang)\n");
    }
    hfxc_result_free(r);
}

/* ---- every seed and every effect of fx/ ---- */

typedef struct corpus_stats { int effects, programs, packed, glsl110, spirv; } corpus_stats;

static void check_glsl(const char *path, const char *name, corpus_stats *st) {
    hfxc_result *r = compile_path(path, GLSL330 | ES300, HFXC_PACK_UNIFORMS);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    if (!fx) {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s: %s\n", name, d);
        free(d);
    }
    CHECK(fx != NULL);
    for (uint32_t i = 0; fx && i < fx->program_count; i++) {
        const hfx_fx_program *p = &fx->programs[i];
        char what[512];
        snprintf(what, sizeof what, "%s program %u (330)", name, i);
        CHECK(link_program(p, HFX_TARGET_GLSL330, what));
        snprintf(what, sizeof what, "%s program %u (ES 300)", name, i);
        CHECK(link_program(p, HFX_TARGET_GLSLES300, what));
        st->programs++;
        st->packed += p->reg_count > 0;
    }
    st->effects += fx != NULL;
    hfxc_result_free(r);
}

/* GLSL 110 wherever the unpacked output compiles (non-square matrices do not). */
static void check_glsl110(const char *path, const char *name, corpus_stats *st) {
    hfxc_result *plain = compile_path(path, GLSL110, 0);
    if (hfxc_result_effect(plain)) {
        hfxc_result *r = compile_path(path, GLSL110, HFXC_PACK_UNIFORMS);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        CHECK(fx != NULL);
        for (uint32_t i = 0; fx && i < fx->program_count; i++) {
            char what[512];
            snprintf(what, sizeof what, "%s program %u (110)", name, i);
            CHECK(link_program(&fx->programs[i], HFX_TARGET_GLSL110, what));
            st->glsl110++;
        }
        hfxc_result_free(r);
    }
    hfxc_result_free(plain);
}

static void check_spirv(const char *path, const char *name, corpus_stats *st) {
    hfxc_result *r = compile_path(path, SPIRV, HFXC_PACK_UNIFORMS);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    if (!fx) {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s (SPIR-V): %s\n", name, d);
        free(d);
    }
    CHECK(fx != NULL);
    for (uint32_t i = 0; fx && (fx->targets & SPIRV) && i < fx->program_count; i++) {
        const hfx_fx_program *p = &fx->programs[i];
        char what[512];
        snprintf(what, sizeof what, "%s program %u (SPIR-V)", name, i);
        for (int s = 0; s < HFX_STAGE_COUNT; s++) CHECK(validate(&p->code[s][HFX_TARGET_SPIRV], what));
        int regs = check_spirv_locations(fx, p, what);
        CHECK(regs > 0 || p->reg_count == 0);
        st->spirv++;
    }
    hfxc_result_free(r);
}

/* The effect survives .hfxo with its registers. */
static void check_hfxo(const char *path, const char *name) {
    hfxc_result *r = compile_path(path, GLSL330, HFXC_PACK_UNIFORMS);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    void *data = NULL;
    size_t size = 0;
    if (fx) CHECK_INT(hfx_fx_write_hfxo(fx, &data, &size), 0);
    char err[256] = "";
    hfx_fx_effect *back = data ? hfx_fx_read_hfxo(data, size, err, sizeof err) : NULL;
    if (fx && !back) fprintf(stderr, "%s: %s\n", name, err);
    CHECK(!fx || back);
    for (uint32_t i = 0; back && i < fx->program_count && i < back->program_count; i++) {
        const hfx_fx_program *a = &fx->programs[i], *b = &back->programs[i];
        CHECK_INT(a->reg_count, b->reg_count);
        CHECK_INT(a->uniform_count, b->uniform_count);
        for (uint32_t k = 0; k < a->uniform_count && k < b->uniform_count; k++) {
            CHECK_INT(a->uniforms[k].param, b->uniforms[k].param);
            CHECK_INT(a->uniforms[k].reg, b->uniforms[k].reg);
        }
    }
    hfx_fx_effect_free(back);
    free(data);
    hfxc_result_free(r);
}

static void check_effect_file(const char *path, const char *name, corpus_stats *st) {
    check_glsl(path, name, st);
    check_glsl110(path, name, st);
    check_spirv(path, name, st);
    check_hfxo(path, name);
}

static int cmp_names(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* The .fx files of dir, sorted; skip names the corpus keeps as known-bad. */
static int list_fx(const char *dir, char ***out) {
    DIR *d = opendir(dir);
    int n = 0, cap = 0;
    *out = NULL;
    if (!d) return 0;
    for (struct dirent *e; (e = readdir(d));) {
        size_t len = strlen(e->d_name);
        if (len < 4 || strcmp(e->d_name + len - 3, ".fx") != 0) continue;
        if (n == cap) {
            cap = cap ? cap * 2 : 16;
            *out = realloc(*out, sizeof **out * (size_t)cap);
        }
        (*out)[n++] = strdup(e->d_name);
    }
    closedir(d);
    if (n) qsort(*out, (size_t)n, sizeof **out, cmp_names);
    return n;
}

static void check_dir(const char *dir, const char *const *skip, corpus_stats *st) {
    char **names;
    int n = list_fx(dir, &names);
    for (int i = 0; i < n; i++) {
        bool skipped = false;
        for (const char *const *s = skip; s && *s; s++) skipped |= strcmp(*s, names[i]) == 0;
        if (!skipped) {
            size_t len = strlen(dir) + strlen(names[i]) + 2;
            char *path = malloc(len);
            snprintf(path, len, "%s/%s", dir, names[i]);
            check_effect_file(path, names[i], st);
            free(path);
        }
        free(names[i]);
    }
    free(names);
}

static void own_effects(void) {
    corpus_stats st = {0};
    check_dir(HFX_SOURCE_DIR "/fx", NULL, &st);
    printf("fx/: %d effects, %d programs (%d packing), %d GLSL 110, %d SPIR-V\n", st.effects, st.programs, st.packed,
           st.glsl110, st.spirv);
    CHECK(st.effects >= 5);
    CHECK(st.packed > 0);
}

static void seed_effects(void) {
    /* multilights.fx is the corpus's known-bad original (multilights_repaired.fx is the fix). */
    static const char *const bad[] = {"multilights.fx", NULL};
    corpus_stats st = {0};
    check_dir(test_seed_dir(), bad, &st);
    printf("seeds: %d effects, %d programs (%d packing), %d GLSL 110, %d SPIR-V\n", st.effects, st.programs,
           st.packed, st.glsl110, st.spirv);
    CHECK(st.effects >= 13);
    CHECK(st.packed > 0);
}

static void mixed_hfxo(void) {
    hfxc_result *r = compile_text(mixed_fx, "mixed.fx", GLSL330, HFXC_PACK_UNIFORMS, NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (fx) {
        hfx_fx_effect *copy = hfx_fx_effect_copy(fx); /* a write and a read */
        CHECK(copy != NULL);
        if (copy) {
            CHECK_INT(copy->programs[0].reg_count, 15);
            CHECK_INT(reg_of(copy, &copy->programs[0], "Shape"), 11);
            CHECK_INT(reg_of(copy, &copy->programs[0], "Sun"), HFX_NONE);
        }
        hfx_fx_effect_free(copy);
    }
    hfxc_result_free(r);
}

int main(void) {
    RUN(registers_by_hand);
    RUN(off_by_default);
    RUN(exact_small_stage);
    RUN(cap_at_256_registers);
    RUN(same_values_on_gl);
    RUN(mixed_spirv);
    RUN(mixed_hfxo);
    RUN(own_effects);
    test_seeds_or_finish();
    RUN(seed_effects);
    return test_summary();
}
