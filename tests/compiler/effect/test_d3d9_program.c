/* test_d3d9_program.c: a pass's program from fxc bytecode (hfx_codegen_d3d9_program): vs_2_0 and
 * ps_2_0 assembled by hand, their constants named by a CTAB as the effect's parameters, turned
 * into GLSL, checked by glslang, drawn on GL (OSMesa) and probed against the values worked out
 * from the D3D9 instruction definitions. Models the translator does not handle yet are refused
 * with a located X5006. */
#define GL_GLEXT_PROTOTYPES 0
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdlib.h>
#include <string.h>

#include "../d3d9/d3d9_asm.h"
#include "d3d9/d3d9.h"
#include "effect/codegen.h"
#include "gl_context.h"
#include "gl_fns.h"
#include "glsl/glslang.h"
#include "hfx/hfxc.h"
#include "test.h"

enum { W = 8, H = 8 };
static test_gl *gl;
static test_gl_fns f;

/* The effect whose parameters the CTABs name (its own passes are not used). */
static const char params_fx[] =
    "float4x4 M; float4 Tint; float Scale; float4 Colors[2]; float4 Offset; int Count; float4x4 Mats[2];\n"
    "texture Tex; sampler TexSampler = sampler_state { Texture = <Tex>; MinFilter = Point; MagFilter = Point; };\n"
    "technique T { pass P { } }\n";

typedef struct fixture {
    hfx_arena arena;
    hfx_diags diags;
    hfxc_result *r;
    hfx_fx_effect *fx;
    hfx_codegen *cg;
    uint32_t file;
} fixture;

static void open_fixture(fixture *x, bool pack) {
    hfx_arena_init(&x->arena);
    hfx_diags_init(&x->diags, &x->arena, 0);
    x->file = hfx_diags_add_file(&x->diags, "t.fxb", NULL, "", 0);
    hfxc_options o = {0};
    o.targets = 1u << HFX_TARGET_GLSL330;
    x->r = hfxc_compile_memory(params_fx, strlen(params_fx), "params.fx", &o);
    x->fx = (hfx_fx_effect *)hfxc_result_effect(x->r);
    CHECK(x->fx != NULL);
    x->cg = hfx_codegen_new(&x->arena, &x->diags, hfx_types_new(&x->arena), NULL, x->fx, 1u << HFX_TARGET_GLSL330,
                            pack, NULL, NULL);
}

static void close_fixture(fixture *x) {
    hfxc_result_free(x->r);
    hfx_arena_free(&x->arena);
}

static d3d9_shader *decode(fixture *x, const uint32_t *w, size_t n, uint32_t base) {
    d3d9_input in = {w, (uint32_t)(n * 4), x->file, base};
    d3d9_shader *s = hfx_d3d9_decode(&x->arena, &x->diags, &in);
    CHECK(s != NULL);
    return s;
}

/* vs_2_0: m4x4 oPos, v0, c0 (M, column-major); mov oT0.xy, v1; mov r0.x, c5.x; mul oD0, c4, r0.x
 * (Tint * Scale: one c register an instruction, vs_2_0's read port);
 * mova a0.x, c8.x (def 1); mov oD1, c6[a0.x] (Colors[1]); mov oT1, c4[a0.x] (c5: Scale, through the
 * register file, Tint being no array). */
static size_t vs_tokens(uint32_t *w) {
    static const ctab_const k[] = {{"M", 2, 0, 4, 3, 3, 4, 4, 1}, {"Tint", 2, 4, 1, 1, 3, 1, 4, 1},
                                   {"Scale", 2, 5, 1, 0, 3, 1, 1, 1}, {"Colors", 2, 6, 2, 1, 3, 1, 4, 2}};
    size_t n = 0;
    w[n++] = VS(2, 0);
    n += put_ctab(w + n, "hand", k, 4);
    const uint32_t code[] = {
        OP(0x51, 5), DST(R_CONST, 8, 0xf), fbits(1), 0, 0, 0,
        OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 0, 0xf),
        OP(0x1f, 2), 0x80000005u, DST(R_INPUT, 1, 0xf),
        OP(0x14, 3), DST(R_RASTOUT, 0, 0xf), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 0, XYZW),
        OP(0x01, 2), DST(R_OUTPUT, 0, 0x3), SRC(R_INPUT, 1, XYZW),
        OP(0x01, 2), DST(R_TEMP, 0, 0x1), SRC(R_CONST, 5, 0),
        OP(0x05, 3), DST(R_ATTROUT, 0, 0xf), SRC(R_CONST, 4, XYZW), SRC(R_TEMP, 0, 0),
        OP(0x2e, 2), DST(R_ADDR, 0, 0x1), SRC(R_CONST, 8, 0),
        OP(0x01, 3), DST(R_ATTROUT, 1, 0xf), SRC(R_CONST, 6, XYZW) | REL, SRC(R_ADDR, 0, 0),
        OP(0x01, 3), DST(R_OUTPUT, 1, 0xf), SRC(R_CONST, 4, XYZW) | REL, SRC(R_ADDR, 0, 0),
        END_TOKEN};
    memcpy(w + n, code, sizeof code);
    return n + sizeof code / 4;
}

/* ps_2_0: def c1, 0.5, 0.25, 2, -1; mov r2, c0 (Offset: one c register an instruction, ps_2_0's
 * read port); mad r0, v0, c1.x, r2; add r0.z, r0.z, v1.z;
 * rsq r1.x, c1.w; mul r0.w, r0.w, r1.x; cmp r0.y, c1.w, c1.x, c1.y; dcl t1; add r0.x, r0.x, t1.x;
 * mov oC0, r0. */
static size_t ps_tokens(uint32_t *w) {
    static const ctab_const k[] = {{"Offset", 2, 0, 1, 1, 3, 1, 4, 1}};
    size_t n = 0;
    w[n++] = PS(2, 0);
    n += put_ctab(w + n, "hand", k, 1);
    const uint32_t code[] = {
        OP(0x51, 5), DST(R_CONST, 1, 0xf), fbits(0.5f), fbits(0.25f), fbits(2), fbits(-1),
        OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 0, 0xf),
        OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 1, 0xf),
        OP(0x01, 2), DST(R_TEMP, 2, 0xf), SRC(R_CONST, 0, XYZW),
        OP(0x04, 4), DST(R_TEMP, 0, 0xf), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 1, 0), SRC(R_TEMP, 2, XYZW),
        OP(0x02, 3), DST(R_TEMP, 0, 0x4), SRC(R_TEMP, 0, 0xaa), SRC(R_INPUT, 1, 0xaa),
        OP(0x07, 2), DST(R_TEMP, 1, 0x1), SRC(R_CONST, 1, 0xff),
        OP(0x05, 3), DST(R_TEMP, 0, 0x8), SRC(R_TEMP, 0, 0xff), SRC(R_TEMP, 1, 0),
        OP(0x58, 4), DST(R_TEMP, 0, 0x2), SRC(R_CONST, 1, 0xff), SRC(R_CONST, 1, 0), SRC(R_CONST, 1, 0x55),
        OP(0x1f, 2), 0x80000000u, DST(R_ADDR, 1, 0xf),
        OP(0x02, 3), DST(R_TEMP, 0, 0x1), SRC(R_TEMP, 0, 0), SRC(R_ADDR, 1, 0),
        OP(0x01, 2), DST(R_COLOROUT, 0, 0xf), SRC(R_TEMP, 0, XYZW),
        END_TOKEN};
    memcpy(w + n, code, sizeof code);
    return n + sizeof code / 4;
}

static GLuint stage(GLenum kind, const char *src) {
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

static void set4(GLuint prog, const char *name, const float *v, int count) {
    GLint loc = f.GetUniformLocation(prog, name);
    if (loc >= 0) f.Uniform4fv(loc, count, v);
}

/* Draws the program over the 8x8 target with XNA's parameter values; reads pixels (0, 4), (5, 4). */
/* The value draw puts in every preshader's registers, as the runtime would have computed it. */
static float pre_value[4] = {0.1f, 0.2f, 0.3f, 0.4f};

static void draw(const hfx_fx_program *p, const hfx_fx_effect *fx, unsigned char left[4], unsigned char right[4]) {
    GLuint vs = stage(GL_VERTEX_SHADER, p->code[0][HFX_TARGET_GLSL330].data);
    GLuint fs = stage(GL_FRAGMENT_SHADER, p->code[1][HFX_TARGET_GLSL330].data);
    GLuint prog = f.CreateProgram();
    f.AttachShader(prog, vs);
    f.AttachShader(prog, fs);
    f.LinkProgram(prog);
    f.UseProgram(prog);
    /* M: XNA's row-major translation by (0.5, 0, 0); the runtime uploads it untransposed */
    static const float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1};
    static const float tint[4] = {0.2f, 0.4f, 0.6f, 0.8f}, scale = 0.5f, offset[4] = {0.3f, 0.1f, 0.05f, 0.6f};
    static const float colors[8] = {0, 0, 0.9f, 0, 0, 0, 0.3f, 0};
    /* Mats: the identity, then M's translation */
    static const float mats[32] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1,
                                   1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5f, 0, 0, 1};
    for (uint32_t i = 0; i < fx->top_param_count; i++) {
        const char *g = fx->params[i].glsl_name, *n = fx->params[i].name;
        if (!g) continue;
        GLint loc = f.GetUniformLocation(prog, g);
        if (strcmp(n, "M") == 0 && loc >= 0) f.UniformMatrix4fv(loc, 1, GL_FALSE, m);
        else if (strcmp(n, "Tint") == 0) set4(prog, g, tint, 1);
        else if (strcmp(n, "Offset") == 0) set4(prog, g, offset, 1);
        else if (strcmp(n, "Colors") == 0) set4(prog, g, colors, 2);
        else if (strcmp(n, "Scale") == 0 && loc >= 0) f.Uniform1fv(loc, 1, &scale);
        else if (strcmp(n, "Count") == 0 && loc >= 0) f.Uniform1i(loc, 2);
        else if (strcmp(n, "Mats") == 0 && loc >= 0) f.UniformMatrix4fv(loc, 2, GL_FALSE, mats);
    }
    /* what the runtime's preshaders would put in their registers (pre_value) */
    for (uint32_t i = 0; i < p->preshader_count; i++) {
        char name[32];
        snprintf(name, sizeof name, "hfx_c[%u]", p->preshaders[i].reg);
        set4(prog, name, pre_value, 1);
    }
    /* a 1x1 texture of (51, 102, 153, 204) / 255 = (0.2, 0.4, 0.6, 0.8) on unit 0 for every sampler */
    static const unsigned char texel[4] = {51, 102, 153, 204};
    GLuint tex;
    f.GenTextures(1, &tex);
    f.ActiveTexture(GL_TEXTURE0);
    f.BindTexture(GL_TEXTURE_2D, tex);
    f.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    f.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    for (uint32_t i = 0; i < p->sampler_count; i++) {
        GLint loc = f.GetUniformLocation(prog, p->samplers[i].glsl_name);
        if (loc >= 0) f.Uniform1i(loc, 0);
    }
    static const float quad[] = {-1, -1, 0, 1, 0, 1, 1, -1, 0, 1, 1, 1, -1, 1, 0, 1, 0, 0,
                                 -1, 1, 0, 1, 0, 0, 1, -1, 0, 1, 1, 1, 1, 1, 0, 1, 1, 0};
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
    test_gl_read(gl, 0, 4, left);
    test_gl_read(gl, 5, 4, right);
    f.DeleteBuffers(1, &vbo);
    f.DeleteVertexArrays(1, &vao);
    f.DeleteTextures(1, &tex);
    f.DeleteProgram(prog);
    f.DeleteShader(vs);
    f.DeleteShader(fs);
}

static void near(const unsigned char px[4], float r, float g, float b, float a) {
    CHECK_NEAR(px[0] / 255.0, r, 1.5 / 255);
    CHECK_NEAR(px[1] / 255.0, g, 1.5 / 255);
    CHECK_NEAR(px[2] / 255.0, b, 1.5 / 255);
    CHECK_NEAR(px[3] / 255.0, a, 1.5 / 255);
}

static void vs_ps_2_0_drawn(void) {
    fixture x;
    open_fixture(&x, false);
    uint32_t vw[256], pw[256];
    d3d9_shader *vs = decode(&x, vw, vs_tokens(vw), 0), *ps = decode(&x, pw, ps_tokens(pw), 1024);
    hfx_fx_program prog;
    int rc = hfx_codegen_d3d9_program(x.cg, vs, ps, false, &prog);
    CHECK_INT(rc, 0);
    if (rc != 0) {
        char *d = hfx_diags_format(&x.diags, 0);
        fprintf(stderr, "%s", d);
        free(d);
    } else {
        bool glslang = hfx_glslang_available() && hfx_glslang_begin();
        for (int s = 0; s < 2 && glslang; s++) {
            char *log = NULL;
            CHECK_INT(hfx_glslang_check(prog.code[s][HFX_TARGET_GLSL330].data, s, HFX_TARGET_GLSL330, &log), 0);
            if (log) fprintf(stderr, "%s\n%s\n", log, prog.code[s][HFX_TARGET_GLSL330].data);
            free(log);
        }
        if (glslang) hfx_glslang_end();
        if (getenv("HFX_D3D9_SHOW")) printf("%s\n%s\n", prog.code[0][HFX_TARGET_GLSL330].data, prog.code[1][HFX_TARGET_GLSL330].data);
        CHECK_INT(prog.attribute_count, 2); /* POSITION0 at 0, TEXCOORD0 at 8 */
        if (prog.attribute_count == 2) CHECK_INT(prog.attributes[1].location, 8);
        if (gl) {
            unsigned char left[4], right[4];
            draw(&prog, x.fx, left, right);
            /* M moves the quad right by 0.5 in NDC (2 of 8 pixels): column 0 stays clear */
            near(left, 0, 0, 0, 0);
            /* r0 = oD0 * 0.5 + Offset = (0.1, 0.2, 0.3, 0.4) * 0.5 + (0.3, 0.1, 0.05, 0.6) = (0.35, 0.2, 0.2, 0.8);
             * .z += Colors[a0.x = 1].z = 0.3 -> 0.5; .w *= rsq(|-1|) = 1; .y = cmp(-1 >= 0) -> 0.25;
             * .x += TEXCOORD1.x = c5.x = Scale = 0.5 -> 0.85 */
            near(right, 0.85f, 0.25f, 0.5f, 0.8f);
        }
    }
    hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

/* vs_3_0: dcl_position v0; dcl_texcoord v1; dcl_position o0; dcl_texcoord o1; mov o0, v0; mov o1, v1. */
static const uint32_t vs30[] = {
    VS(3, 0),
    OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 0, 0xf), OP(0x1f, 2), 0x80000005u, DST(R_INPUT, 1, 0xf),
    OP(0x1f, 2), 0x80000000u, DST(R_OUTPUT, 0, 0xf), OP(0x1f, 2), 0x80000005u, DST(R_OUTPUT, 1, 0xf),
    OP(0x01, 2), DST(R_OUTPUT, 0, 0xf), SRC(R_INPUT, 0, XYZW),
    OP(0x01, 2), DST(R_OUTPUT, 1, 0xf), SRC(R_INPUT, 1, XYZW),
    END_TOKEN};

/* ps_3_0 with flow control, predication and a texture read (values in the comments). */
static size_t ps30_tokens(uint32_t *w) {
    static const ctab_const k[] = {{"TexSampler", 3, 0, 1, 4, 12, 1, 1, 1}};
    size_t n = 0;
    w[n++] = PS(3, 0);
    n += put_ctab(w + n, "hand", k, 1);
    const uint32_t code[] = {
        OP(0x30, 5), DST(R_CONSTINT, 0, 0xf), 3, 0, 0, 0,                  /* defi i0, 3, 0, 0, 0 */
        OP(0x30, 5), DST(R_CONSTINT, 1, 0xf), 4, 1, 2, 0,                  /* defi i1, 4, 1, 2, 0: aL = 1, 3, 5, 7 */
        OP(0x2f, 2), DST(R_CONSTBOOL, 0, 0xf), 1,                           /* defb b0, true */
        OP(0x51, 5), DST(R_CONST, 0, 0xf), fbits(0), fbits(1), fbits(0.125f), fbits(-0.5f),
        OP(0x51, 5), DST(R_CONST, 1, 0xf), fbits(0.25f), fbits(0.5f), fbits(0.75f), fbits(1),
        OP(0x51, 5), DST(R_CONST, 2, 0xf), fbits(0.0625f), 0, 0, 0,
        OP(0x51, 5), DST(R_CONST, 4, 0xf), fbits(0.125f), 0, 0, 0,
        OP(0x51, 5), DST(R_CONST, 6, 0xf), fbits(0.25f), 0, 0, 0,
        OP(0x51, 5), DST(R_CONST, 8, 0xf), fbits(0.5f), 0, 0, 0,
        OP(0x1f, 2), 0x80000005u, DST(R_INPUT, 0, 0x3),                    /* dcl_texcoord v0.xy */
        OP(0x1f, 2), 0x90000000u, DST(R_SAMPLER, 0, 0xf),                  /* dcl_2d s0 */
        OP(0x01, 2), DST(R_TEMP, 0, 0xf), SRC(R_CONST, 0, 0),              /* mov r0, c0.x: 0 */
        OP(0x26, 1), SRC(R_CONSTINT, 0, XYZW),                              /* rep i0 (3 times) */
        OP(0x02, 3), DST(R_TEMP, 0, 0x1), SRC(R_TEMP, 0, 0), SRC(R_CONST, 0, 0xaa), /* r0.x += 0.125 */
        OP(0x27, 0),                                                        /* endrep: r0.x = 0.375 */
        OP(0x1b, 2), SRC(R_LOOP, 0, XYZW), SRC(R_CONSTINT, 1, XYZW),        /* loop aL, i1 */
        OP(0x02, 4), DST(R_TEMP, 0, 0x2), SRC(R_TEMP, 0, 0x55), SRC(R_CONST, 1, 0) | REL, SRC(R_LOOP, 0, 0),
        OPC(0x2d, 2, 3), SRC(R_TEMP, 0, 0x55), SRC(R_CONST, 1, 0),          /* break_ge r0.y, c1.x (0.25) */
        OP(0x1d, 0),                                  /* endloop: 0.0625 + 0.125 + 0.25 = 0.4375, then break */
        OP(0x28, 1), SRC(R_CONSTBOOL, 0, XYZW),                             /* if b0 */
        OP(0x01, 2), DST(R_TEMP, 0, 0x4), SRC(R_CONST, 1, 0xaa),           /*   mov r0.z, c1.z: 0.75 */
        OP(0x2a, 0),                                                        /* else */
        OP(0x01, 2), DST(R_TEMP, 0, 0x4), SRC(R_CONST, 1, 0),              /*   mov r0.z, c1.x */
        OP(0x2b, 0),                                                        /* endif */
        OPC(0x5e, 3, 1), DST(R_PRED, 0, 0xf), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 1, 0x55), /* setp_gt p0, r0, 0.5 */
        OP(0x01, 3) | PRED_BIT, DST(R_TEMP, 0, 0xf), SRC(R_PRED, 0, XYZW), SRC(R_CONST, 0, 0x55), /* (p0) mov r0, 1 */
        OP(0x42, 3), DST(R_TEMP, 1, 0xf), SRC(R_INPUT, 0, XYZW), SRC(R_SAMPLER, 0, XYZW), /* texld r1, v0, s0 */
        OP(0x01, 2), DST(R_TEMP, 0, 0x8), SRC(R_TEMP, 1, 0x55),            /* mov r0.w, r1.y: 0.4 */
        OP(0x01, 2), DST(R_COLOROUT, 0, 0xf), SRC(R_TEMP, 0, XYZW),
        END_TOKEN};
    memcpy(w + n, code, sizeof code);
    return n + sizeof code / 4;
}

static void vs_ps_3_0_flow_drawn(void) {
    fixture x;
    open_fixture(&x, true);
    uint32_t pw[256];
    d3d9_shader *vs = decode(&x, vs30, sizeof vs30 / 4, 0), *ps = decode(&x, pw, ps30_tokens(pw), 512);
    hfx_fx_program prog;
    int rc = vs && ps ? hfx_codegen_d3d9_program(x.cg, vs, ps, false, &prog) : -1;
    CHECK_INT(rc, 0);
    if (rc != 0) {
        char *d = hfx_diags_format(&x.diags, 0);
        fprintf(stderr, "%s", d);
        free(d);
    } else {
        if (getenv("HFX_D3D9_SHOW")) printf("%s\n", prog.code[1][HFX_TARGET_GLSL330].data);
        CHECK_INT(prog.sampler_count, 1);
        if (gl) {
            unsigned char left[4], right[4];
            draw(&prog, x.fx, left, right);
            /* r0 = (0.375, 0.4375, 0.75, 0); p0 = r0 > 0.5 = (F, F, T, F) sets .z to 1; .w = texel.y = 0.4 */
            near(left, 0.375f, 0.4375f, 1, 0.4f);
            near(right, 0.375f, 0.4375f, 1, 0.4f);
        }
    }
    hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

/* One entry compiled from HLSL by hfx's bytecode writer (hfxc /T profile /E main), decoded. */
static d3d9_shader *compiled(fixture *x, const char *src, const char *profile, uint32_t base) {
    hfxc_options o = {.entry = "main", .profile = profile};
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "loop.fx", &o);
    size_t size = 0;
    const void *code = hfxc_result_bytecode(r, &size);
    CHECK(code != NULL);
    d3d9_shader *s = NULL;
    if (code) {
        uint32_t *w = hfx_arena_alloc_raw(&x->arena, size);
        memcpy(w, code, size);
        s = decode(x, w, size / 4, base);
    } else {
        char *d = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s", d);
        free(d);
    }
    hfxc_result_free(r);
    return s;
}

static void draw_pair(fixture *x, d3d9_shader *vs, d3d9_shader *ps, const float want[4]) {
    hfx_fx_program prog;
    int rc = vs && ps ? hfx_codegen_d3d9_program(x->cg, vs, ps, false, &prog) : -1;
    CHECK_INT(rc, 0);
    if (rc != 0) {
        char *d = hfx_diags_format(&x->diags, 0);
        fprintf(stderr, "%s", d);
        free(d);
        return;
    }
    if (getenv("HFX_D3D9_SHOW")) printf("%s\n%s\n", prog.code[0][HFX_TARGET_GLSL330].data, prog.code[1][HFX_TARGET_GLSL330].data);
    if (gl) {
        unsigned char left[4], right[4];
        draw(&prog, x->fx, left, right);
        near(right, want[0], want[1], want[2], want[3]);
    }
    hfx_fx_program_clear(&prog);
}

/* Loops bounded by a parameter, as hfx's writer writes them, read back and drawn (Count = 2):
 * ps_3_0's `loop aL` / `break_ge` with Colors[i] read as c[aL + n], vs_2_0's `rep` over Count's
 * i register. */
static void parameter_bound_loops_drawn(void) {
    fixture x;
    open_fixture(&x, true);
    /* c = (0.1, 0.2, 0.3, 0.4) + (Colors[0] + Colors[1]) * 0.5 = (0.1, 0.2, 0.3 + (0.9 + 0.3) * 0.5, 0.4) */
    d3d9_shader *ps = compiled(&x, "int Count; float4 Colors[2];\n"
                                   "float4 main(float2 uv : TEXCOORD0) : COLOR0 {\n"
                                   "    float4 c = float4(0.1, 0.2, 0.3, 0.4);\n"
                                   "    for (int i = 0; i < Count; i++) c += Colors[i] * 0.5;\n"
                                   "    return c;\n}\n", "ps_3_0", 512);
    draw_pair(&x, decode(&x, vs30, sizeof vs30 / 4, 0), ps, (const float[4]){0.1f, 0.2f, 0.9f, 0.4f});
    close_fixture(&x);
    open_fixture(&x, false); /* parameters as uniforms of their own, which draw() sets by name */
    /* col = Offset * 0.5 twice = Offset = (0.3, 0.1, 0.05, 0.6); M moves the quad right by 0.5 */
    d3d9_shader *vs = compiled(&x, "int Count; float4 Offset; float4x4 M;\n"
                                   "void main(float4 p : POSITION, out float4 o : POSITION, out float4 col : COLOR0) {\n"
                                   "    o = mul(p, M);\n    col = 0;\n"
                                   "    for (int i = 0; i < Count; i++) col += Offset * 0.5;\n}\n", "vs_2_0", 0);
    d3d9_shader *ps2 = compiled(&x, "float4 main(float4 c : COLOR0) : COLOR0 { return c; }\n", "ps_2_0", 1024);
    draw_pair(&x, vs, ps2, (const float[4]){0.3f, 0.1f, 0.05f, 0.6f});
    close_fixture(&x);
}

/* Matrices and arrays with semantics between hfx's vs_2_0 and ps_2_0 (a register per column of
 * m, oT0..3 / t0..3; one per element of w, oT4..5 / t4..5) and a computed index in the pixel
 * shader (selects over Colors' registers), read back and drawn. m's rows: Offset, Offset * 2,
 * (0.1, 0.2, 0.3, 0.4), (0, 0, 0, 1); w = {Offset, 0.5}; Offset = (0.3, 0.1, 0.05, 0.6):
 * x = m[2].x + m[1].w / 4 = 0.1 + 1.2 / 4 = 0.4, y = m[2].y + w[1].y / 10 = 0.25,
 * z = m[2].z + Colors[(int)(w[1].x * 2)].z = 0.3 + Colors[1].z = 0.6, w = m[0].x + m[3].w / 10 = 0.4. */
static void semantic_matrices_and_indexes_drawn(void) {
    fixture x;
    open_fixture(&x, false);
    d3d9_shader *vs = compiled(&x, "float4x4 M; float4 Offset;\n"
                                   "void main(float4 p : POSITION, out float4 o : POSITION, out float4x4 m : TEXCOORD0,\n"
                                   "          out float4 w[2] : TEXCOORD4) {\n"
                                   "    o = mul(p, M);\n"
                                   "    m = float4x4(Offset, Offset * 2, float4(0.1, 0.2, 0.3, 0.4), float4(0, 0, 0, 1));\n"
                                   "    w[0] = Offset;\n    w[1] = 0.5;\n}\n", "vs_2_0", 0);
    d3d9_shader *ps = compiled(&x, "float4 Colors[2];\n"
                                   "float4 main(float4x4 m : TEXCOORD0, float4 w[2] : TEXCOORD4) : COLOR0 {\n"
                                   "    return float4(m[2].x + m[1].w * 0.25, m[2].y + w[1].y * 0.1,\n"
                                   "                  m[2].z + Colors[(int)(w[1].x * 2)].z, m[0].x + m[3].w * 0.1);\n}\n",
                               "ps_2_0", 1024);
    draw_pair(&x, vs, ps, (const float[4]){0.4f, 0.25f, 0.6f, 0.4f});
    close_fixture(&x);
}

/* A register the shader's PRES block computes (d3d9_shader.pres, filled by the effect reader): the
 * program gets a preshader entry with the code, the GLSL reads it from hfx_c. */
static void preshader_registers(void) {
    fixture x;
    open_fixture(&x, true);
    static const uint32_t vs[] = {VS(2, 0), OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 0, 0xf),
                                  OP(0x01, 2), DST(R_RASTOUT, 0, 0xf), SRC(R_INPUT, 0, XYZW), END_TOKEN};
    static const uint32_t ps[] = {PS(2, 0), OP(0x01, 2), DST(R_COLOROUT, 0, 0xf), SRC(R_CONST, 5, XYZW), END_TOKEN};
    static const uint32_t code[3] = {7, 8, 9}; /* carried, not run here */
    static const d3d9_preshader_out out = {5, 1, code, 3, "Tint * 2", D3D9_PRE_C};
    d3d9_shader *v = decode(&x, vs, sizeof vs / 4, 0), *p = decode(&x, ps, sizeof ps / 4, 64);
    p->pres = &out;
    p->pre_count = 1;
    hfx_fx_program prog;
    int rc = hfx_codegen_d3d9_program(x.cg, v, p, false, &prog);
    CHECK_INT(rc, 0);
    if (rc == 0) {
        CHECK_INT(prog.preshader_count, 1);
        CHECK_INT(prog.pre_words, 3);
        if (prog.preshader_count == 1) {
            CHECK_INT(prog.preshaders[0].rows, 1);
            CHECK_INT(prog.preshaders[0].cols, 4);
            CHECK_INT(prog.pre_code[prog.preshaders[0].first + 2], 9);
            char want[96];
            snprintf(want, sizeof want, "vec4 hfx_pre_c5; // hfx_c[%u] = Tint * 2, computed on the CPU (a preshader)",
                     prog.preshaders[0].reg);
            CHECK_CONTAINS(prog.code[1][HFX_TARGET_GLSL330].data, want);
        }
        if (gl) {
            unsigned char left[4], right[4];
            draw(&prog, x.fx, left, right);
            near(right, 0.1f, 0.2f, 0.3f, 0.4f);
        }
    }
    hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

/* ps_1_1 (no length fields): tex, result shift, _bx2, complement, co-issue, constants clamped to
 * [-1, 1], cnd on r0.a; the pixel is r0. Drawn with the texel (0.2, 0.4, 0.6, 0.8). */
static size_t ps11_tokens(uint32_t *w) {
    static const ctab_const k[] = {{"TexSampler", 3, 0, 1, 4, 12, 1, 1, 1}};
    size_t n = 0;
    w[n++] = PS(1, 1);
    n += put_ctab(w + n, "hand", k, 1);
    const uint32_t code[] = {
        0x51, DST(R_CONST, 0, 0xf), fbits(0.5f), fbits(0.25f), fbits(1), fbits(-1),
        0x51, DST(R_CONST, 1, 0xf), fbits(2), 0, 0, 0,                           /* read as 1: clamped */
        0x42, DST(R_ADDR, 0, 0xf),                                                /* tex t0 */
        0x05, DST(R_TEMP, 0, 0xf) | 1u << 24, SRC(R_ADDR, 0, XYZW), SRC(R_CONST, 0, 0), /* mul_x2 r0, t0, c0.x: t0 */
        0x02, DST(R_TEMP, 0, 0x7), SRC(R_TEMP, 0, XYZW), SRCM(R_ADDR, 0, XYZW, 4), /* add r0.rgb, r0, t0_bx2: (-0.4, 0.2, 0.8) */
        0x01 | COISSUE_BIT, DST(R_TEMP, 0, 0x8), SRCM(R_ADDR, 0, XYZW, 6),         /* +mov r0.a, 1 - t0: 0.2 */
        0x04, DST(R_TEMP, 0, 0x7), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 1, 0), SRC(R_CONST, 0, 0x55), /* (-0.15, 0.45, 1) */
        0x50, DST(R_TEMP, 1, 0xf), SRC(R_TEMP, 0, 0xff), SRC(R_CONST, 0, 0), SRC(R_CONST, 0, 0x55), /* 0.2 > 0.5? : 0.25 */
        0x02, DST(R_TEMP, 0, 0x1), SRC(R_TEMP, 0, XYZW), SRC(R_TEMP, 1, XYZW),     /* r0.r = -0.15 + 0.25 = 0.1 */
        END_TOKEN};
    memcpy(w + n, code, sizeof code);
    return n + sizeof code / 4;
}

static void ps_1_1_drawn(void) {
    fixture x;
    open_fixture(&x, true);
    uint32_t pw[256];
    d3d9_shader *vs = decode(&x, vs30, sizeof vs30 / 4, 0), *ps = decode(&x, pw, ps11_tokens(pw), 512);
    hfx_fx_program prog;
    int rc = vs && ps ? hfx_codegen_d3d9_program(x.cg, vs, ps, false, &prog) : -1;
    CHECK_INT(rc, 0);
    if (rc != 0) {
        char *d = hfx_diags_format(&x.diags, 0);
        fprintf(stderr, "%s", d);
        free(d);
    } else {
        if (getenv("HFX_D3D9_SHOW")) printf("%s\n", prog.code[1][HFX_TARGET_GLSL330].data);
        if (gl) {
            unsigned char left[4], right[4];
            draw(&prog, x.fx, left, right);
            near(right, 0.1f, 0.45f, 1, 0.2f);
        }
    }
    hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

/* ps_1_4: texld r0, t0 (sampler 0); phase; add r0, r0_bx2, c0 = (-0.1, 0.3, 0.7, 1.1), inside ps_1_4's
 * [-8, 8]; mad r0, r0, c0, c0 = (0.45, 0.65, 0.85, 1.05), which the target stores as 1. */
static void ps_1_4_drawn(void) {
    fixture x;
    open_fixture(&x, true);
    static const ctab_const k[] = {{"TexSampler", 3, 0, 1, 4, 12, 1, 1, 1}};
    uint32_t pw[256];
    size_t n = 0;
    pw[n++] = PS(1, 4);
    n += put_ctab(pw + n, "hand", k, 1);
    const uint32_t code[] = {
        0x51, DST(R_CONST, 0, 0xf), fbits(0.5f), fbits(0.5f), fbits(0.5f), fbits(0.5f),
        0x42, DST(R_TEMP, 0, 0xf), SRC(R_ADDR, 0, XYZW),
        0xfffd,
        0x02, DST(R_TEMP, 0, 0xf), SRCM(R_TEMP, 0, XYZW, 4), SRC(R_CONST, 0, XYZW),
        0x04, DST(R_TEMP, 0, 0xf), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 0, XYZW), SRC(R_CONST, 0, XYZW),
        END_TOKEN};
    memcpy(pw + n, code, sizeof code);
    n += sizeof code / 4;
    d3d9_shader *vs = decode(&x, vs30, sizeof vs30 / 4, 0), *ps = decode(&x, pw, n, 512);
    hfx_fx_program prog;
    int rc = vs && ps ? hfx_codegen_d3d9_program(x.cg, vs, ps, false, &prog) : -1;
    CHECK_INT(rc, 0);
    if (rc == 0 && gl) {
        unsigned char left[4], right[4];
        draw(&prog, x.fx, left, right);
        near(right, 0.45f, 0.65f, 0.85f, 1);
    }
    hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

/* The program of a vertex shader's n tokens and a ps_2_0 passing its COLOR0 (v0) on; rc as
 * hfx_codegen_d3d9_program, -1 when either does not decode. */
static int with_colour_ps(fixture *x, const uint32_t *vw, size_t n, hfx_fx_program *prog) {
    static const uint32_t ps[] = {PS(2, 0), OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 0, 0xf),
                                  OP(0x01, 2), DST(R_COLOROUT, 0, 0xf), SRC(R_INPUT, 0, XYZW), END_TOKEN};
    d3d9_shader *v = decode(x, vw, n, 0), *p = decode(x, ps, sizeof ps / 4, 1024);
    return v && p ? hfx_codegen_d3d9_program(x->cg, v, p, false, prog) : -1;
}

/* vs_1_1 (no length fields; relative sources carry no address token): mov a0.x, c8.x rounds 0.6 to
 * 1 (the reference's "rounding to nearest"; truncation would give 0); mov oD0, c6[a0.x] is
 * Colors[1] = (0, 0, 0.3, 0), which ps_2_0's mov oC0, v0 shows. */
static void vs_1_1_drawn(void) {
    fixture x;
    open_fixture(&x, false);
    static const ctab_const k[] = {{"Colors", 2, 6, 2, 1, 3, 1, 4, 2}};
    uint32_t vw[256];
    size_t n = 0;
    vw[n++] = VS(1, 1);
    n += put_ctab(vw + n, "hand", k, 1);
    const uint32_t code[] = {
        0x1f, 0x80000000u, DST(R_INPUT, 0, 0xf),
        0x51, DST(R_CONST, 8, 0xf), fbits(0.6f), 0, 0, 0,
        0x01, DST(R_ADDR, 0, 0x1), SRC(R_CONST, 8, 0),
        0x01, DST(R_RASTOUT, 0, 0xf), SRC(R_INPUT, 0, XYZW),
        0x01, DST(R_ATTROUT, 0, 0xf), SRC(R_CONST, 6, XYZW) | REL,
        END_TOKEN};
    memcpy(vw + n, code, sizeof code);
    n += sizeof code / 4;
    hfx_fx_program prog;
    int rc = with_colour_ps(&x, vw, n, &prog);
    CHECK_INT(rc, 0);
    if (rc == 0 && gl) {
        unsigned char left[4], right[4];
        draw(&prog, x.fx, left, right);
        near(right, 0, 0, 0.3f, 0);
    }
    hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

static void old_forms_refused_with_location(void) {
    fixture x;
    open_fixture(&x, true);
    static const uint32_t ps11[] = {PS(1, 1), 0x40, DST(R_ADDR, 0, 0xf), 0x43, DST(R_ADDR, 1, 0xf), SRC(R_ADDR, 0, XYZW), END_TOKEN};
    d3d9_shader *ps = decode(&x, ps11, sizeof ps11 / 4, 96);
    hfx_fx_program prog;
    CHECK_INT(hfx_codegen_d3d9_program(x.cg, NULL, ps, false, &prog), -1);
    char *text = hfx_diags_format(&x.diags, 0);
    CHECK_STR(text, "t.fxb(0,108): error X5006: texbem is not supported yet\n");
    free(text);
    hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

static void subroutines_refused_at_instruction(void) {
    fixture x;
    open_fixture(&x, true);
    static const uint32_t vs[] = {VS(2, 0), OP(0x19, 1), SRC(R_LABEL, 0, XYZW), OP(0x1c, 0),
                                  OP(0x1e, 1), SRC(R_LABEL, 0, XYZW), OP(0x1c, 0), END_TOKEN};
    d3d9_shader *s = decode(&x, vs, sizeof vs / 4, 200);
    hfx_fx_program prog;
    CHECK_INT(hfx_codegen_d3d9_program(x.cg, s, NULL, false, &prog), -1);
    char *text = hfx_diags_format(&x.diags, 0);
    CHECK_STR(text, "t.fxb(0,204): error X5006: subroutines (call) are not supported yet\n");
    free(text);
    hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

/* A source the translator cannot read (here v0 with the `!` modifier, 13, which only a predicate
 * register takes) is refused at that instruction: crs once built its cross product on the missing
 * value (found by fuzz_d3d9). Words: version 0, dcl 1-3, crs at word 4 (byte 300 + 16). */
static void unreadable_source_refused(void) {
    fixture x;
    open_fixture(&x, true);
    static const uint32_t vs[] = {VS(3, 0), OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 0, 0xf),
                                  OP(0x21, 3), DST(R_TEMP, 0, 0x7), SRC(R_INPUT, 0, XYZW), SRCM(R_INPUT, 0, XYZW, 13),
                                  END_TOKEN};
    d3d9_shader *s = decode(&x, vs, sizeof vs / 4, 300);
    hfx_fx_program prog;
    CHECK_INT(hfx_codegen_d3d9_program(x.cg, s, NULL, false, &prog), -1);
    char *text = hfx_diags_format(&x.diags, 0);
    CHECK_STR(text, "t.fxb(0,316): error X5006: source modifier 13 is not supported here\n");
    free(text);
    hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

/* ps_1_1's `texcoord tN` past the model's t registers (fuzz_d3d9 in CI: the texcoord read a
 * register the translator has no variable for and crossed a null one): refused with an error. */
static void texcoord_past_the_registers_refused(void) {
    fixture x;
    open_fixture(&x, true);
    static const uint32_t ps[] = {0xffff0101u, 0x00000040u, 0x88e4001cu, 0x40000001u, 0xb00f0000u, 0xb2ff0000u, END_TOKEN};
    d3d9_shader *s = decode(&x, ps, sizeof ps / 4, 300);
    CHECK(s != NULL);
    hfx_fx_program prog;
    memset(&prog, 0, sizeof prog);
    if (s) CHECK_INT(hfx_codegen_d3d9_program(x.cg, NULL, s, false, &prog), -1);
    char *text = hfx_diags_format(&x.diags, 0);
    CHECK_STR(text, "t.fxb(0,304): error X5006: t28 is no texture coordinate register of this model\n");
    free(text);
    hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

/* fxc's ob# / oi# preshader outputs (d3d9_preshader_out.file B and I) drive `if b0` and
 * `rep i3`: the b register is the preshader's x != 0, the i register its components truncated.
 *     def c0, 0.25, 0.5, 0.75, 1;  def c1, 0.125, 0, 0, 0
 *     mov r0, c1.y;  rep i3 { add r0.x, r0.x, c1.x };  if b0 { mov r0.y, c0.w } else { mov r0.y, c0.x }
 *     mov r0.z, c0.y;  mov r0.w, c0.w;  mov oC0, r0
 * Preshaders giving (2.75, 1, 0, 0): i3.x = 2 (truncated; rounding would give 3 passes, 0.375),
 * b0 true: (0.25, 1, 0.5, 1). Giving zeros: no pass, b0 false: (0, 0.25, 0.5, 1). */
static void preshader_bool_and_int_registers(void) {
    fixture x;
    open_fixture(&x, true);
    const uint32_t ps[] = {
        PS(3, 0),
        OP(0x51, 5), DST(R_CONST, 0, 0xf), fbits(0.25f), fbits(0.5f), fbits(0.75f), fbits(1),
        OP(0x51, 5), DST(R_CONST, 1, 0xf), fbits(0.125f), 0, 0, 0,
        OP(0x01, 2), DST(R_TEMP, 0, 0xf), SRC(R_CONST, 1, 0x55),
        OP(0x26, 1), SRC(R_CONSTINT, 3, XYZW),
        OP(0x02, 3), DST(R_TEMP, 0, 0x1), SRC(R_TEMP, 0, 0), SRC(R_CONST, 1, 0),
        OP(0x27, 0),
        OP(0x28, 1), SRC(R_CONSTBOOL, 0, XYZW),
        OP(0x01, 2), DST(R_TEMP, 0, 0x2), SRC(R_CONST, 0, 0xff),
        OP(0x2a, 0),
        OP(0x01, 2), DST(R_TEMP, 0, 0x2), SRC(R_CONST, 0, 0),
        OP(0x2b, 0),
        OP(0x01, 2), DST(R_TEMP, 0, 0x4), SRC(R_CONST, 0, 0x55),
        OP(0x01, 2), DST(R_TEMP, 0, 0x8), SRC(R_CONST, 0, 0xff),
        OP(0x01, 2), DST(R_COLOROUT, 0, 0xf), SRC(R_TEMP, 0, XYZW),
        END_TOKEN};
    static const uint32_t code[3] = {7, 8, 9}; /* carried, not run here */
    static const d3d9_preshader_out outs[2] = {{3, 1, code, 3, NULL, D3D9_PRE_I}, {0, 1, code, 3, NULL, D3D9_PRE_B}};
    d3d9_shader *v = decode(&x, vs30, sizeof vs30 / 4, 0), *p = decode(&x, ps, sizeof ps / 4, 256);
    if (p) p->pres = outs, p->pre_count = 2;
    hfx_fx_program prog;
    int rc = v && p ? hfx_codegen_d3d9_program(x.cg, v, p, false, &prog) : -1;
    CHECK_INT(rc, 0);
    if (rc == 0) {
        CHECK_INT(prog.preshader_count, 2);
        CHECK_CONTAINS(prog.code[1][HFX_TARGET_GLSL330].data, "vec4 hfx_pre_i3;");
        CHECK_CONTAINS(prog.code[1][HFX_TARGET_GLSL330].data, "vec4 hfx_pre_b0;");
        if (gl) {
            unsigned char left[4], right[4];
            memcpy(pre_value, (const float[4]){2.75f, 1, 0, 0}, sizeof pre_value);
            draw(&prog, x.fx, left, right);
            near(right, 0.25f, 1, 0.5f, 1);
            memset(pre_value, 0, sizeof pre_value);
            draw(&prog, x.fx, left, right);
            near(right, 0, 0.25f, 0.5f, 1);
            memcpy(pre_value, (const float[4]){0.1f, 0.2f, 0.3f, 0.4f}, sizeof pre_value);
        }
    }
    if (rc == 0) hfx_fx_program_clear(&prog);
    close_fixture(&x);
}

/* fxc's mul(v, M) as a dp4 per register (vs_2_0: dp4 oPos.x, v0, c0 ... dp4 oPos.w, v0, c3, M
 * column-major) is read as one product of the parameter; dp4 r0.x, r0, c0; dp4 r0.y, r0, c1
 * is not (the second reads the r0.x the first wrote) and keeps D3D9's order. */
static size_t columns_vs_tokens(uint32_t *w) {
    static const ctab_const k[] = {{"M", 2, 0, 4, 3, 3, 4, 4, 1}, {"Tint", 2, 4, 1, 1, 3, 1, 4, 1}};
    size_t n = 0;
    w[n++] = VS(2, 0);
    n += put_ctab(w + n, "hand", k, 2);
    const uint32_t code[] = {
        OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 0, 0xf),
        OP(0x09, 3), DST(R_RASTOUT, 0, 0x1), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 0, XYZW),
        OP(0x09, 3), DST(R_RASTOUT, 0, 0x2), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 1, XYZW),
        OP(0x09, 3), DST(R_RASTOUT, 0, 0x4), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 2, XYZW),
        OP(0x09, 3), DST(R_RASTOUT, 0, 0x8), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 3, XYZW),
        OP(0x01, 2), DST(R_TEMP, 0, 0xf), SRC(R_CONST, 4, XYZW),
        OP(0x09, 3), DST(R_TEMP, 0, 0x1), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 0, XYZW),
        OP(0x09, 3), DST(R_TEMP, 0, 0x2), SRC(R_TEMP, 0, 0x00), SRC(R_CONST, 3, XYZW),
        OP(0x01, 2), DST(R_ATTROUT, 0, 0xf), SRC(R_TEMP, 0, XYZW),
        END_TOKEN};
    memcpy(w + n, code, sizeof code);
    return n + sizeof code / 4;
}

static void matrix_columns_drawn(void) {
    fixture x;
    open_fixture(&x, false);
    uint32_t vw[256];
    hfx_fx_program prog;
    int rc = with_colour_ps(&x, vw, columns_vs_tokens(vw), &prog);
    CHECK_INT(rc, 0);
    if (rc == 0) {
        const char *vs = prog.code[0][HFX_TARGET_GLSL330].data;
        CHECK(strstr(vs, "hfx_out_POSITION0 = M * hfx_in_POSITION0;") != NULL); /* one product */
        const char *d = strstr(vs, "dot("); /* the r0 pair stays two dot products */
        CHECK(d && (d = strstr(d + 1, "dot(")) && !strstr(d + 1, "dot("));
        if (gl) {
            unsigned char left[4], right[4];
            draw(&prog, x.fx, left, right);
            /* M moves the quad right by 0.5 (2 of 8 pixels): column 0 stays clear */
            near(left, 0, 0, 0, 0);
            /* c0 = M's column 0 = (1, 0, 0, 0.5), c3 = (0, 0, 0, 1); r0 = Tint = (0.2, 0.4, 0.6, 0.8);
             * r0.x = dot(r0, c0) = 0.2 + 0.4 = 0.6; r0.y = dot(r0.xxxx, c3) = the new r0.x = 0.6 */
            near(right, 0.6f, 0.6f, 0.6f, 0.8f);
        }
        hfx_fx_program_clear(&prog);
    }
    close_fixture(&x);
}

/* How many times needle occurs in text. */
static int occurrences(const char *text, const char *needle) {
    int n = 0;
    for (const char *p = text; (p = strstr(p, needle)) != NULL; p++) n++;
    return n;
}

/* fxc's dp4 runs over one element of a matrix array (CascadedShadowMask's ShadowMatrices[i]) are
 * one product of that element too, whichever components they write: Mats (c0..c7, column-major)
 * is the identity then M's translation; dp4 oPos.x..w, v0, c4..c7 is Mats[1] * v0;
 * dp4 r1.y/z/w, r0, c0/c1/c2 (three of Mats[0]'s registers) is (Mats[0] * r0).xyz; a lone
 * dp4 r1.x, r0, c4 is (Mats[1] * r0).x. */
static size_t array_matrix_vs_tokens(uint32_t *w) {
    static const ctab_const k[] = {{"Mats", 2, 0, 8, 3, 3, 4, 4, 2}, {"Tint", 2, 8, 1, 1, 3, 1, 4, 1}};
    size_t n = 0;
    w[n++] = VS(2, 0);
    n += put_ctab(w + n, "hand", k, 2);
    const uint32_t code[] = {
        OP(0x1f, 2), 0x80000000u, DST(R_INPUT, 0, 0xf),
        OP(0x01, 2), DST(R_TEMP, 0, 0xf), SRC(R_CONST, 8, XYZW),
        OP(0x09, 3), DST(R_RASTOUT, 0, 0x1), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 4, XYZW),
        OP(0x09, 3), DST(R_RASTOUT, 0, 0x2), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 5, XYZW),
        OP(0x09, 3), DST(R_RASTOUT, 0, 0x4), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 6, XYZW),
        OP(0x09, 3), DST(R_RASTOUT, 0, 0x8), SRC(R_INPUT, 0, XYZW), SRC(R_CONST, 7, XYZW),
        OP(0x09, 3), DST(R_TEMP, 1, 0x2), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 0, XYZW),
        OP(0x09, 3), DST(R_TEMP, 1, 0x4), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 1, XYZW),
        OP(0x09, 3), DST(R_TEMP, 1, 0x8), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 2, XYZW),
        OP(0x09, 3), DST(R_TEMP, 1, 0x1), SRC(R_TEMP, 0, XYZW), SRC(R_CONST, 4, XYZW),
        OP(0x01, 2), DST(R_ATTROUT, 0, 0xf), SRC(R_TEMP, 1, XYZW),
        END_TOKEN};
    memcpy(w + n, code, sizeof code);
    return n + sizeof code / 4;
}

static void array_matrix_rows_drawn(void) {
    fixture x;
    open_fixture(&x, false);
    uint32_t vw[256];
    hfx_fx_program prog;
    int rc = with_colour_ps(&x, vw, array_matrix_vs_tokens(vw), &prog);
    CHECK_INT(rc, 0);
    if (rc == 0) {
        const char *vs = prog.code[0][HFX_TARGET_GLSL330].data;
        CHECK(strstr(vs, "hfx_out_POSITION0 = Mats[1] * hfx_in_POSITION0;") != NULL);
        CHECK(strstr(vs, "Mats[0] * hfx_r0") != NULL);
        CHECK(strstr(vs, "Mats[1] * hfx_r0") != NULL);
        CHECK(occurrences(vs, "dot(") == 0);
        if (gl) {
            unsigned char left[4], right[4];
            draw(&prog, x.fx, left, right);
            near(left, 0, 0, 0, 0); /* Mats[1] moved the quad right by 0.5 */
            /* r1.yzw = the identity's product with Tint (0.2, 0.4, 0.6, 0.8): (0.2, 0.4, 0.6);
             * r1.x = Mats[1]'s register 0 (its column (1, 0, 0, 0.5)) . Tint = 0.2 + 0.4 */
            near(right, 0.6f, 0.2f, 0.4f, 0.6f);
        }
        hfx_fx_program_clear(&prog);
    }
    close_fixture(&x);
}

/* fxc's one-component exp / log / rcp / rsq over a register's components are one vector
 * operation; a pair where the second reads what the first wrote stays two. def c1 = (4, 2, 1,
 * 0.25):
 *   rcp r0.x, c1.x; rcp r0.y, c1.y; rcp r0.z, c1.z; rcp r0.w, c1.x   r0 = (0.25, 0.5, 1, 0.25)
 *   mov r1, c1; rsq r1.w, r1.x (0.5); rsq r1.z, r1.w (rsq 0.5 = 1.41421; together: rsq 0.25 = 2)
 *   mul r1.z, r1.z, c1.w                                              r1.z = 0.353553 (not 0.5)
 *   log r2.x, c1.y; log r2.y, c1.x                                    r2.xy = (1, 2)
 *   exp r3.x, -r2.x; exp r3.y, -r2.y                                  r3.xy = (0.5, 0.25)
 *   mul r4.x, r0.y, r0.w; mov r4.y, r1.z; mov r4.z, r3.x; mov r4.w, r3.y; mov oC0, r4
 * The pixel: (0.125, 0.353553, 0.5, 0.25). */
static size_t scalar_runs_ps_tokens(uint32_t *w) {
    enum { NEG = 1 };
    static const uint32_t code[] = {
        PS(2, 0),
        OP(0x51, 5), DST(R_CONST, 1, 0xf), 0x40800000u /* 4 */, 0x40000000u /* 2 */, 0x3f800000u /* 1 */,
        0x3e800000u /* 0.25 */,
        OP(0x06, 2), DST(R_TEMP, 0, 0x1), SRC(R_CONST, 1, 0x00),
        OP(0x06, 2), DST(R_TEMP, 0, 0x2), SRC(R_CONST, 1, 0x55),
        OP(0x06, 2), DST(R_TEMP, 0, 0x4), SRC(R_CONST, 1, 0xaa),
        OP(0x06, 2), DST(R_TEMP, 0, 0x8), SRC(R_CONST, 1, 0x00),
        OP(0x01, 2), DST(R_TEMP, 1, 0xf), SRC(R_CONST, 1, XYZW),
        OP(0x07, 2), DST(R_TEMP, 1, 0x8), SRC(R_TEMP, 1, 0x00),
        OP(0x07, 2), DST(R_TEMP, 1, 0x4), SRC(R_TEMP, 1, 0xff),
        OP(0x05, 3), DST(R_TEMP, 1, 0x4), SRC(R_TEMP, 1, 0xaa), SRC(R_CONST, 1, 0xff),
        OP(0x0f, 2), DST(R_TEMP, 2, 0x1), SRC(R_CONST, 1, 0x55),
        OP(0x0f, 2), DST(R_TEMP, 2, 0x2), SRC(R_CONST, 1, 0x00),
        OP(0x0e, 2), DST(R_TEMP, 3, 0x1), SRCM(R_TEMP, 2, 0x00, NEG),
        OP(0x0e, 2), DST(R_TEMP, 3, 0x2), SRCM(R_TEMP, 2, 0x55, NEG),
        OP(0x05, 3), DST(R_TEMP, 4, 0x1), SRC(R_TEMP, 0, 0x55), SRC(R_TEMP, 0, 0xff),
        OP(0x01, 2), DST(R_TEMP, 4, 0x2), SRC(R_TEMP, 1, 0xaa),
        OP(0x01, 2), DST(R_TEMP, 4, 0x4), SRC(R_TEMP, 3, 0x00),
        OP(0x01, 2), DST(R_TEMP, 4, 0x8), SRC(R_TEMP, 3, 0x55),
        OP(0x01, 2), DST(R_COLOROUT, 0, 0xf), SRC(R_TEMP, 4, XYZW),
        END_TOKEN};
    memcpy(w, code, sizeof code);
    return sizeof code / 4;
}

static void scalar_runs_drawn(void) {
    fixture x;
    open_fixture(&x, false);
    uint32_t vw[256], pw[256];
    hfx_fx_program prog;
    int rc = hfx_codegen_d3d9_program(x.cg, decode(&x, vw, vs_tokens(vw), 0),
                                      decode(&x, pw, scalar_runs_ps_tokens(pw), 1024), false, &prog);
    CHECK_INT(rc, 0);
    if (rc == 0) {
        const char *ps = prog.code[1][HFX_TARGET_GLSL330].data;
        CHECK_INT(occurrences(ps, "exp2("), 1);
        CHECK_INT(occurrences(ps, "log2("), 1);
        CHECK_INT(occurrences(ps, "inversesqrt("), 2);
        /* a scalar result written to one component is written as it is, not splat and picked */
        CHECK(strstr(ps, "hfx_r1.w = min(inversesqrt(") != NULL);
        /* a write mask narrows the operation: mul r4.x, r0.y, r0.w multiplies one component */
        CHECK(strstr(ps, "hfx_r4.x = hfx_r0.y * hfx_r0.w;") != NULL);
        CHECK(strstr(ps, "hfx_r1.z = hfx_r1.z * 0.25;") != NULL);
        if (gl) {
            unsigned char left[4], right[4];
            draw(&prog, x.fx, left, right);
            near(right, 0.125f, 0.353553f, 0.5f, 0.25f);
        }
        hfx_fx_program_clear(&prog);
    }
    close_fixture(&x);
}

/* _sat takes NaN to 0, as D3D10 and later hardware saturates (GLSL's clamp leaves it undefined;
 * llvmpipe's happens to give 0 too, so the GLSL is checked for the explicit test as well):
 * Colors[0].x (c2.x) is 0, so rcp r0.x, c2.x = +inf and mul r0.x, r0.x, c2.x = NaN, at run time.
 *   def c0, 0, 2, -1, 0.5; def c1, 1, 0.25, 0, 0
 *   mov r2, c0; mov r2.x, r0.x; mov_sat r3, r2        r3 = (0, 1, 0, 0.5) (NaN kept: r3.x NaN)
 *   cmp r3.x, -r3.x, c1.x, c1.y                        -0 >= 0: 1 (NaN >= 0 is false: 0.25)
 *   mov oC0, r3                                        the pixel: (1, 1, 0, 0.5) */
static void saturate_nan_drawn(void) {
    static const ctab_const k[] = {{"Colors", 2, 2, 2, 1, 3, 1, 4, 2}};
    enum { SAT = 1, NEG = 1 };
    uint32_t pw[256];
    size_t n = 0;
    pw[n++] = PS(2, 0);
    n += put_ctab(pw + n, "hand", k, 1);
    const uint32_t code[] = {
        OP(0x51, 5), DST(R_CONST, 0, 0xf), 0, 0x40000000u /* 2 */, 0xbf800000u /* -1 */, 0x3f000000u /* 0.5 */,
        OP(0x51, 5), DST(R_CONST, 1, 0xf), 0x3f800000u /* 1 */, 0x3e800000u /* 0.25 */, 0, 0,
        OP(0x06, 2), DST(R_TEMP, 0, 0x1), SRC(R_CONST, 2, 0x00),
        OP(0x05, 3), DST(R_TEMP, 0, 0x1), SRC(R_TEMP, 0, 0x00), SRC(R_CONST, 2, 0x00),
        OP(0x01, 2), DST(R_TEMP, 2, 0xf), SRC(R_CONST, 0, XYZW),
        OP(0x01, 2), DST(R_TEMP, 2, 0x1), SRC(R_TEMP, 0, 0x00),
        OP(0x01, 2), DSTM(R_TEMP, 3, 0xf, SAT), SRC(R_TEMP, 2, XYZW),
        OP(0x58, 4), DST(R_TEMP, 3, 0x1), SRCM(R_TEMP, 3, 0x00, NEG), SRC(R_CONST, 1, 0x00), SRC(R_CONST, 1, 0x55),
        OP(0x01, 2), DST(R_COLOROUT, 0, 0xf), SRC(R_TEMP, 3, XYZW),
        END_TOKEN};
    memcpy(pw + n, code, sizeof code);
    n += sizeof code / 4;
    fixture x;
    open_fixture(&x, false);
    uint32_t vw[256];
    hfx_fx_program prog;
    int rc = hfx_codegen_d3d9_program(x.cg, decode(&x, vw, columns_vs_tokens(vw), 0), decode(&x, pw, n, 1024), false, &prog);
    CHECK_INT(rc, 0);
    if (rc == 0) {
        CHECK(strstr(prog.code[1][HFX_TARGET_GLSL330].data, "hfx_r3 = mix(clamp(hfx_r3, 0.0, 1.0), vec4(0.0), isnan(hfx_r3));") != NULL);
        if (gl) {
            unsigned char left[4], right[4];
            draw(&prog, x.fx, left, right);
            near(right, 1, 1, 0, 0.5f);
        }
        hfx_fx_program_clear(&prog);
    }
    close_fixture(&x);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (gl) CHECK_INT(test_gl_fns_load(&f), 0);
    else printf("no OSMesa GL 3.3 context: programs are built and checked, not drawn\n");
    RUN(vs_ps_2_0_drawn);
    RUN(ps_1_1_drawn);
    RUN(ps_1_4_drawn);
    RUN(vs_1_1_drawn);
    RUN(old_forms_refused_with_location);
    RUN(vs_ps_3_0_flow_drawn);
    RUN(subroutines_refused_at_instruction);
    RUN(unreadable_source_refused);
    RUN(texcoord_past_the_registers_refused);
    RUN(preshader_registers);
    RUN(preshader_bool_and_int_registers);
    RUN(parameter_bound_loops_drawn);
    RUN(semantic_matrices_and_indexes_drawn);
    RUN(matrix_columns_drawn);
    RUN(array_matrix_rows_drawn);
    RUN(scalar_runs_drawn);
    RUN(saturate_nan_drawn);
    if (gl) test_gl_destroy(gl);
    return test_summary();
}
