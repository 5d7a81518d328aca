/* test_render_states.c: D3D9 render and sampler states on GL, read back with glGet and
 * checked on rendered pixels (culling by winding, blending with computed results). */
#include "gl_context.h"
#include "internal.h"
#include "rt_check.h"
#include "rt_support.h"
#include "test.h"

#define W 16
#define H 16

static test_gl *gl;
static tgl g;
static hfx_device *dev;

static void clear(float r, float gg, float b, float a) {
    g.ClearColor(r, gg, b, a);
    g.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

static GLint geti(GLenum e) {
    GLint v[4] = {0};
    g.GetIntegerv(e, v);
    return v[0];
}

static float getf(GLenum e) {
    float v[4] = {0};
    g.GetFloatv(e, v);
    return v[0];
}

/* A colour effect whose one pass holds the states added by add(fx). */
static hfx_effect *effect_with(void (*add)(hfx_fx_effect *), int alpha_test, char **warnings_out) {
    hfx_fx_effect *cfx = tb_new();
    uint32_t c = tb_param(cfx, "Color", "Color", HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 0, 4);
    uint32_t prog;
    if (alpha_test) {
        prog = tb_program(cfx, tb_vs_pos,
                          "#version 330\n"
                          "uniform vec4 Color;\n"
                          "uniform int hfx_alpha_func;\n"
                          "uniform float hfx_alpha_ref;\n"
                          "out vec4 hfx_out0;\n"
                          "void main() {\n"
                          "    float a = Color.a;\n"
                          "    bool pass = hfx_alpha_func == 8 || (hfx_alpha_func == 5 && a > hfx_alpha_ref)\n"
                          "        || (hfx_alpha_func == 2 && a < hfx_alpha_ref);\n"
                          "    if (!pass) discard;\n"
                          "    hfx_out0 = Color;\n"
                          "}\n");
        cfx->programs[prog].flags |= HFX_FX_PROGRAM_ALPHA_TEST;
    } else {
        prog = tb_program(cfx, tb_vs_pos, tb_fs_color);
    }
    tb_uses(cfx, prog, c);
    tb_technique(cfx, "T");
    uint32_t first = cfx->state_count;
    if (add) add(cfx);
    tb_pass(cfx, "P", prog, first, cfx->state_count - first);
    char *errors = NULL;
    hfx_effect *fx = hfx_rt_effect_from_fx(dev, cfx, NULL, &errors);
    if (!fx) fprintf(stderr, "load: %s\n", errors ? errors : "");
    CHECK(fx != NULL);
    hfx_free(errors);
    if (warnings_out) *warnings_out = fx ? strdup(hfx_effect_warnings(fx)) : NULL;
    return fx;
}

/* Each test starts from GL's defaults with a new device (whose D3D states are D3D9's
 * defaults), since render states stay set after a pass, as in D3D9. */
static void fresh(void) {
    hfx_device_destroy(dev);
    static const GLenum off[] = {GL_DEPTH_TEST, GL_STENCIL_TEST, GL_BLEND, GL_CULL_FACE, GL_SCISSOR_TEST,
                                 GL_FRAMEBUFFER_SRGB, GL_SAMPLE_MASK, GL_LINE_SMOOTH, GL_POLYGON_OFFSET_FILL};
    for (size_t i = 0; i < sizeof off / sizeof *off; i++) g.Disable(off[i]);
    g.UseProgram(0);
    dev = hfx_device_create_gl(test_gl_loader);
    CHECK(dev != NULL);
}

static int apply(hfx_effect *fx) { return hfx_pass_apply(hfx_technique_pass(hfx_effect_current_technique(fx), 0)); }

static void set_color(hfx_effect *fx, float r, float gg, float b, float a) {
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Color"), (float[4]){r, gg, b, a}, 4), HFX_OK);
}

/* Triangles in NDC: the first is clockwise on screen (D3D's front face), the second the same
 * corners in the other order. Both cover the lower-left half of the target. */
static const float cw[6] = {-1, -1, -1, 1, 1, -1};
static const float ccw[6] = {-1, -1, 1, -1, -1, 1};

static void draw(const float *xy, int n) {
    GLuint vbo, vao = tgl_triangles(&g, xy, n, &vbo);
    g.DrawArrays(GL_TRIANGLES, 0, n);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
}

static const float full[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};

static void add_cull_ccw(hfx_fx_effect *fx) { tb_state_e(fx, "CullMode", 0, "CCW"); }
static void add_cull_cw(hfx_fx_effect *fx) { tb_state_e(fx, "CullMode", 0, "CW"); }
static void add_cull_none(hfx_fx_effect *fx) { tb_state_e(fx, "CullMode", 0, "None"); }

/* Is the lower-left pixel lit after drawing xy with a CullMode? */
static int lit(void (*add)(hfx_fx_effect *), const float *xy) {
    hfx_effect *fx = effect_with(add, 0, NULL);
    set_color(fx, 1, 1, 1, 1);
    clear(0, 0, 0, 1);
    apply(fx);
    draw(xy, 3);
    unsigned char px[4];
    test_gl_read(gl, 1, H - 2, px);
    hfx_effect_destroy(fx);
    return px[0] == 255;
}

static void test_cull_by_winding(void) {
    fresh();
    CHECK_INT(lit(add_cull_ccw, cw), 1);  /* D3D's default: counter-clockwise faces culled */
    CHECK_INT(lit(add_cull_ccw, ccw), 0);
    CHECK_INT(lit(add_cull_cw, cw), 0);
    CHECK_INT(lit(add_cull_cw, ccw), 1);
    CHECK_INT(lit(add_cull_none, cw), 1);
    CHECK_INT(lit(add_cull_none, ccw), 1);
    CHECK_INT(geti(GL_FRONT_FACE), GL_CW);
    CHECK_INT(g.IsEnabled(GL_CULL_FACE), GL_FALSE);
}

static void add_alpha_blend(hfx_fx_effect *fx) {
    tb_state_e(fx, "AlphaBlendEnable", 0, "TRUE");
    tb_state_e(fx, "SrcBlend", 0, "SrcAlpha");
    tb_state_e(fx, "DestBlend", 0, "InvSrcAlpha");
}

static void add_separate_alpha(hfx_fx_effect *fx) {
    add_alpha_blend(fx);
    tb_state_e(fx, "SeparateAlphaBlendEnable", 0, "TRUE");
    tb_state_e(fx, "SrcBlendAlpha", 0, "Zero");
    tb_state_e(fx, "DestBlendAlpha", 0, "One");
}

static void add_blend_factor(hfx_fx_effect *fx) {
    tb_state_e(fx, "AlphaBlendEnable", 0, "TRUE");
    tb_state_e(fx, "SrcBlend", 0, "BlendFactor");
    tb_state_e(fx, "DestBlend", 0, "One");
    tb_state_e(fx, "BlendOp", 0, "RevSubtract");
    tb_state_i(fx, "BlendFactor", 0, (int32_t)0x80402000); /* D3DCOLOR ARGB: a=128 r=64 g=32 b=0 */
}

static void add_both_src_alpha(hfx_fx_effect *fx) {
    tb_state_e(fx, "AlphaBlendEnable", 0, "TRUE");
    tb_state_e(fx, "SrcBlend", 0, "BothSrcAlpha");
    tb_state_e(fx, "DestBlend", 0, "Zero"); /* overruled by BothSrcAlpha */
}

static void test_blending(void) {
    /* dest (0, 0.4, 0.8, 1), src (1, 0, 0, 0.25): src * 0.25 + dest * 0.75 */
    fresh();
    hfx_effect *fx = effect_with(add_alpha_blend, 0, NULL);
    set_color(fx, 1, 0, 0, 0.25f);
    clear(0, 0.4f, 0.8f, 1);
    apply(fx);
    draw(full, 6);
    rt_check_pixel(gl, 4, 4, 64, 77, 153, 207); /* 63.75, 76.5, 153, 0.0625 + 0.75 = 207.2 */
    hfx_effect_destroy(fx);
    fresh();
    /* alpha apart: Zero * src + One * dest keeps the cleared alpha */
    fx = effect_with(add_separate_alpha, 0, NULL);
    set_color(fx, 1, 0, 0, 0.25f);
    clear(0, 0.4f, 0.8f, 0.5f);
    apply(fx);
    draw(full, 6);
    rt_check_pixel(gl, 4, 4, 64, 77, 153, 128);
    hfx_effect_destroy(fx);
    fresh();
    /* RevSubtract: dest - src * factor; factor (64, 32, 0, 128) / 255 */
    fx = effect_with(add_blend_factor, 0, NULL);
    set_color(fx, 1, 1, 1, 1);
    clear(0.5f, 0.5f, 0.5f, 1);
    apply(fx);
    draw(full, 6);
    rt_check_pixel(gl, 4, 4, 64, 96, 128, 127); /* 127.5 - 64, 127.5 - 32, 127.5 - 0, 255 - 128 */
    float bc[4];
    g.GetFloatv(GL_BLEND_COLOR, bc);
    CHECK_NEAR(bc[0], 64 / 255.0, 1e-6);
    CHECK_NEAR(bc[3], 128 / 255.0, 1e-6);
    CHECK_INT(geti(GL_BLEND_EQUATION_RGB), GL_FUNC_REVERSE_SUBTRACT);
    hfx_effect_destroy(fx);
    fresh();
    /* BothSrcAlpha: source SrcAlpha, destination InvSrcAlpha whatever DestBlend says */
    fx = effect_with(add_both_src_alpha, 0, NULL);
    set_color(fx, 1, 0, 0, 0.25f);
    clear(0, 0.4f, 0.8f, 1);
    apply(fx);
    draw(full, 6);
    rt_check_pixel(gl, 4, 4, 64, 77, 153, 207);
    CHECK_INT(geti(GL_BLEND_DST_RGB), GL_ONE_MINUS_SRC_ALPHA);
    hfx_effect_destroy(fx);
}

static void add_many(hfx_fx_effect *fx) {
    tb_state_e(fx, "ZEnable", 0, "TRUE");
    tb_state_e(fx, "ZWriteEnable", 0, "FALSE");
    tb_state_e(fx, "ZFunc", 0, "Greater");
    tb_state_e(fx, "FillMode", 0, "Wireframe");
    tb_state_e(fx, "StencilEnable", 0, "TRUE");
    tb_state_e(fx, "StencilFunc", 0, "Equal");
    tb_state_i(fx, "StencilRef", 0, 5);
    tb_state_i(fx, "StencilMask", 0, 0xf0);
    tb_state_i(fx, "StencilWriteMask", 0, 0x0f);
    tb_state_e(fx, "StencilFail", 0, "IncrSat");
    tb_state_e(fx, "StencilZFail", 0, "Decr");
    tb_state_e(fx, "StencilPass", 0, "Replace");
    tb_state_e(fx, "TwoSidedStencilMode", 0, "TRUE");
    tb_state_e(fx, "CCW_StencilFunc", 0, "NotEqual");
    tb_state_e(fx, "CCW_StencilPass", 0, "Invert");
    tb_state_e(fx, "ScissorTestEnable", 0, "TRUE");
    tb_state_i(fx, "ColorWriteEnable", 0, 1 | 8);
    tb_state_i(fx, "ColorWriteEnable1", 0, 2);
    tb_state_f(fx, "DepthBias", 0, (float[1]){0.001f}, 1);
    tb_state_f(fx, "SlopeScaleDepthBias", 0, (float[1]){2.0f}, 1);
    tb_state_e(fx, "MultiSampleAntiAlias", 0, "FALSE");
    tb_state_e(fx, "SRGBWriteEnable", 0, "TRUE");
    tb_state_e(fx, "BlendOp", 0, "Max");
    tb_state_e(fx, "DitherEnable", 0, "FALSE");
    tb_state_e(fx, "AntiAliasedLineEnable", 0, "TRUE");
    tb_state_i(fx, "MultiSampleMask", 0, 3);
}

static void test_render_states_read_back(void) {
    fresh();
    hfx_effect *fx = effect_with(add_many, 0, NULL);
    CHECK_STR(hfx_effect_warnings(fx), "");
    CHECK_INT(hfx_effect_begin(fx), HFX_OK);
    CHECK_INT(apply(fx), HFX_OK);
    CHECK_INT(g.IsEnabled(GL_DEPTH_TEST), GL_TRUE);
    CHECK_INT(geti(GL_DEPTH_WRITEMASK), GL_FALSE);
    CHECK_INT(geti(GL_DEPTH_FUNC), GL_GREATER);
    CHECK_INT(geti(GL_POLYGON_MODE), GL_LINE);
    CHECK_INT(g.IsEnabled(GL_STENCIL_TEST), GL_TRUE);
    CHECK_INT(geti(GL_STENCIL_FUNC), GL_EQUAL);
    CHECK_INT(geti(GL_STENCIL_REF), 5);
    CHECK_INT(geti(GL_STENCIL_VALUE_MASK), 0xf0);
    CHECK_INT(geti(GL_STENCIL_WRITEMASK), 0x0f);
    CHECK_INT(geti(GL_STENCIL_FAIL), GL_INCR);
    CHECK_INT(geti(GL_STENCIL_PASS_DEPTH_FAIL), GL_DECR_WRAP);
    CHECK_INT(geti(GL_STENCIL_PASS_DEPTH_PASS), GL_REPLACE);
    CHECK_INT(geti(GL_STENCIL_BACK_FUNC), GL_NOTEQUAL);   /* CCW faces are GL's back faces */
    CHECK_INT(geti(GL_STENCIL_BACK_PASS_DEPTH_PASS), GL_INVERT);
    CHECK_INT(geti(GL_STENCIL_BACK_FAIL), GL_KEEP);
    CHECK_INT(geti(GL_STENCIL_BACK_REF), 5);
    CHECK_INT(geti(GL_STENCIL_BACK_WRITEMASK), 0x0f);
    CHECK_INT(g.IsEnabled(GL_SCISSOR_TEST), GL_TRUE);
    GLboolean m[4];
    g.GetBooleani_v(GL_COLOR_WRITEMASK, 0, m);
    CHECK(m[0] && !m[1] && !m[2] && m[3]);
    g.GetBooleani_v(GL_COLOR_WRITEMASK, 1, m);
    CHECK(!m[0] && m[1] && !m[2] && !m[3]);
    g.GetBooleani_v(GL_COLOR_WRITEMASK, 2, m);
    CHECK(m[0] && m[1] && m[2] && m[3]);
    CHECK_INT(g.IsEnabled(GL_POLYGON_OFFSET_FILL), GL_TRUE);
    CHECK_NEAR(getf(GL_POLYGON_OFFSET_FACTOR), 2.0, 0);
    CHECK_NEAR(getf(GL_POLYGON_OFFSET_UNITS), 0.001 * 16777215.0, 0.01); /* one 24-bit depth step per 2^-24 */
    CHECK_INT(g.IsEnabled(GL_MULTISAMPLE), GL_FALSE);
    CHECK_INT(g.IsEnabled(GL_FRAMEBUFFER_SRGB), GL_TRUE);
    CHECK_INT(geti(GL_BLEND_EQUATION_RGB), GL_MAX);
    CHECK_INT(geti(GL_BLEND_EQUATION_ALPHA), GL_MAX);
    CHECK_INT(g.IsEnabled(GL_DITHER), GL_FALSE);
    CHECK_INT(g.IsEnabled(GL_LINE_SMOOTH), GL_TRUE);
    CHECK_INT(g.IsEnabled(GL_SAMPLE_MASK), GL_TRUE);
    GLint mask = 0;
    g.GetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &mask);
    CHECK_INT(mask, 3);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    /* end puts back what begin found */
    CHECK_INT(hfx_effect_end(fx), HFX_OK);
    CHECK_INT(g.IsEnabled(GL_STENCIL_TEST), GL_FALSE);
    CHECK_INT(geti(GL_DEPTH_WRITEMASK), GL_TRUE);
    CHECK_INT(geti(GL_DEPTH_FUNC), GL_LESS);
    CHECK_INT(geti(GL_POLYGON_MODE), GL_FILL);
    CHECK_INT(geti(GL_STENCIL_BACK_FUNC), GL_ALWAYS);
    CHECK_INT(geti(GL_BLEND_EQUATION_RGB), GL_FUNC_ADD);
    g.GetBooleani_v(GL_COLOR_WRITEMASK, 0, m);
    CHECK(m[0] && m[1] && m[2] && m[3]);
    CHECK_INT(g.IsEnabled(GL_MULTISAMPLE), GL_TRUE);
    CHECK_INT(g.IsEnabled(GL_DITHER), GL_TRUE);
    CHECK_NEAR(getf(GL_POLYGON_OFFSET_UNITS), 0, 0);
    CHECK_INT(g.IsEnabled(GL_POLYGON_OFFSET_FILL), GL_FALSE);
    hfx_effect_destroy(fx);
}

static void add_nothing(hfx_fx_effect *fx) { (void)fx; }

static void test_states_persist_and_begin_end_restores(void) {
    /* a pass's states stay set after it (D3D9): the next pass without CullMode keeps None */
    fresh();
    hfx_effect *a = effect_with(add_cull_none, 0, NULL), *b = effect_with(add_nothing, 0, NULL);
    g.Enable(GL_CULL_FACE);
    g.CullFace(GL_FRONT);
    CHECK_INT(hfx_effect_begin(a), HFX_OK);
    apply(a);
    CHECK_INT(g.IsEnabled(GL_CULL_FACE), GL_FALSE);
    apply(b);
    CHECK_INT(g.IsEnabled(GL_CULL_FACE), GL_FALSE);
    GLint prog = geti(GL_CURRENT_PROGRAM);
    CHECK(prog != 0);
    CHECK_INT(hfx_effect_end(a), HFX_OK);
    CHECK_INT(g.IsEnabled(GL_CULL_FACE), GL_TRUE);
    CHECK_INT(geti(GL_CULL_FACE_MODE), GL_FRONT);
    CHECK_INT(geti(GL_CURRENT_PROGRAM), 0);
    CHECK_INT(hfx_effect_end(a), HFX_ERR_STATE); /* no begin */
    /* after end the shadow matches GL again, so the next apply really disables culling */
    apply(a);
    CHECK_INT(g.IsEnabled(GL_CULL_FACE), GL_FALSE);
    hfx_effect_destroy(a);
    hfx_effect_destroy(b);
}

static void add_param_states(hfx_fx_effect *fx) {
    uint32_t z = tb_param(fx, "zOn", NULL, HFX_CLASS_SCALAR, HFX_TYPE_BOOL, 1, 1, 0, HFX_NONE, 4, 1);
    uint32_t c = tb_param(fx, "cull", NULL, HFX_CLASS_SCALAR, HFX_TYPE_INT, 1, 1, 0, HFX_NONE, 5, 1);
    uint32_t f = tb_param(fx, "factor", NULL, HFX_CLASS_VECTOR, HFX_TYPE_FLOAT, 1, 4, 0, HFX_NONE, 6, 4);
    tb_state_p(fx, "ZEnable", 0, z);
    tb_state_p(fx, "CullMode", 0, c);
    tb_state_p(fx, "BlendFactor", 0, f);
}

static void test_param_valued_states(void) {
    fresh();
    hfx_effect *fx = effect_with(add_param_states, 0, NULL);
    CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "zOn"), 0), HFX_OK);
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "cull"), 2), HFX_OK);
    CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "factor"), (float[4]){0.25f, 0.5f, 0.75f, 1}, 4), HFX_OK);
    apply(fx);
    CHECK_INT(g.IsEnabled(GL_DEPTH_TEST), GL_FALSE);
    CHECK_INT(g.IsEnabled(GL_CULL_FACE), GL_TRUE);
    CHECK_INT(geti(GL_CULL_FACE_MODE), GL_FRONT); /* CW culls GL's front (clockwise) faces */
    float bc[4];
    g.GetFloatv(GL_BLEND_COLOR, bc);
    CHECK_NEAR(bc[2], 0.75, 0);
    CHECK_INT(hfx_param_set_bool(hfx_effect_param(fx, "zOn"), 1), HFX_OK);
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "cull"), 1), HFX_OK);
    apply(fx);
    CHECK_INT(g.IsEnabled(GL_DEPTH_TEST), GL_TRUE);
    CHECK_INT(g.IsEnabled(GL_CULL_FACE), GL_FALSE);
    hfx_effect_destroy(fx);
}

static void add_alpha_test(hfx_fx_effect *fx) {
    tb_state_e(fx, "AlphaTestEnable", 0, "TRUE");
    tb_state_e(fx, "AlphaFunc", 0, "Greater");
    tb_state_i(fx, "AlphaRef", 0, 128);
}

static void test_alpha_test_emulation(void) {
    fresh();
    hfx_effect *fx = effect_with(add_alpha_test, 1, NULL);
    CHECK_STR(hfx_effect_warnings(fx), "");
    set_color(fx, 1, 1, 1, 0.4f); /* 0.4 < 128 / 255: discarded */
    clear(0, 0, 0, 1);
    apply(fx);
    draw(full, 6);
    rt_check_pixel(gl, 3, 3, 0, 0, 0, 255);
    set_color(fx, 1, 1, 1, 0.6f);
    apply(fx);
    draw(full, 6);
    rt_check_pixel(gl, 3, 3, 255, 255, 255, 153);
    GLint prog = geti(GL_CURRENT_PROGRAM), func = 0;
    float ref = 0;
    g.GetUniformiv((GLuint)prog, g.GetUniformLocation((GLuint)prog, "hfx_alpha_func"), &func);
    g.GetUniformfv((GLuint)prog, g.GetUniformLocation((GLuint)prog, "hfx_alpha_ref"), &ref);
    CHECK_INT(func, 5);
    CHECK_NEAR(ref, 128 / 255.0, 1e-6);
    hfx_effect_destroy(fx);
}

static void add_unsupported(hfx_fx_effect *fx) {
    tb_state_e(fx, "Lighting", 0, "TRUE");           /* line 11 */
    tb_state_e(fx, "Wrap0", 0, "U");                 /* 12 */
    tb_state_e(fx, "FogEnable", 0, "TRUE");          /* 13 */
    tb_state_e(fx, "ColorOp", 0, "Modulate");        /* 14 */
    tb_state_e(fx, "ZEnable", 0, "UseW");            /* 15 */
    tb_state_e(fx, "AlphaTestEnable", 0, "TRUE");    /* 16 */
    tb_state_e(fx, "CullMode", 0, "None");           /* 17: fine */
    tb_state_e(fx, "MinFilter", 1, "GaussianQuad");  /* 18 */
    uint32_t vs = tb_state_i(fx, "VertexShader", 0, 0); /* 19: say, an asm shader */
    fx->states[vs].kind = HFX_FX_VALUE_UNSUPPORTED;
}

static void test_unsupported_states_reported_once(void) {
    fresh();
    char *w = NULL;
    hfx_effect *fx = effect_with(add_unsupported, 0, &w);
    CHECK(fx != NULL); /* never a failed load because of one state */
    CHECK_STR(w,
              "test.fx(11,5): warning: 'Lighting': fixed-function state; shaders do this work, so it has no effect (as in D3D9 with shaders)\n"
              "test.fx(12,5): warning: 'Wrap0': cylindrical texture wrapping (Wrap0..15) is not available in GL; ignored\n"
              "test.fx(13,5): warning: 'FogEnable': fixed-function fog is not available in GL core; ignored\n"
              "test.fx(14,5): warning: 'ColorOp': texture-stage state is fixed-function; it has no effect with shaders\n"
              "test.fx(15,5): warning: 'ZEnable': ZEnable = UseW (w-buffering) is not available in GL; using a z-buffer\n"
              "test.fx(16,5): warning: 'AlphaTestEnable': alpha test needs the pass's pixel shader to carry it (no hfx_alpha_func uniform); ignored\n"
              "test.fx(18,5): warning: 'MinFilter': GaussianQuad filtering is not available in GL; filtering linearly\n"
              "test.fx(19,5): warning: 'VertexShader': this value cannot be expressed in GL; ignored\n");
    apply(fx);
    apply(fx);
    CHECK_STR(hfx_effect_warnings(fx), w); /* Apply adds nothing */
    CHECK_INT(g.IsEnabled(GL_DEPTH_TEST), GL_TRUE);
    free(w);
    hfx_effect_destroy(fx);
}

/* Sampler states, read back from the sampler object bound on the unit. */
static hfx_effect *sampler_effect(void) {
    hfx_fx_effect *cfx = tb_new();
    uint32_t tex = tb_param(cfx, "tex", NULL, HFX_CLASS_OBJECT, HFX_TYPE_TEXTURE2D, 0, 0, 0, HFX_NONE, 0, 0);
    uint32_t s0 = tb_param(cfx, "s0", "s0", HFX_CLASS_OBJECT, HFX_TYPE_SAMPLER2D, 0, 0, 0, HFX_NONE, 0, 0);
    uint32_t s1 = tb_param(cfx, "s1", "s1", HFX_CLASS_OBJECT, HFX_TYPE_SAMPLER2D, 0, 0, 0, HFX_NONE, 0, 0);
    uint32_t a = tb_sampler(cfx, s0, tex, HFX_FX_DIM_2D), b = tb_sampler(cfx, s1, tex, HFX_FX_DIM_2D);
    uint32_t first = cfx->state_count;
    tb_state_e(cfx, "MinFilter", 0, "Linear");
    tb_state_e(cfx, "MagFilter", 0, "Point");
    tb_state_e(cfx, "MipFilter", 0, "Linear");
    tb_state_e(cfx, "AddressU", 0, "Mirror");
    tb_state_e(cfx, "AddressV", 0, "Border");
    tb_state_e(cfx, "AddressW", 0, "MirrorOnce");
    tb_state_i(cfx, "BorderColor", 0, (int32_t)0xff00ff00); /* D3DCOLOR: opaque green */
    tb_state_f(cfx, "MipMapLodBias", 0, (float[1]){-1.5f}, 1);
    tb_state_i(cfx, "MaxMipLevel", 0, 2);
    tb_sampler_states(cfx, a, first, cfx->state_count - first);
    first = cfx->state_count;
    tb_state_e(cfx, "MinFilter", 0, "Anisotropic");
    tb_state_e(cfx, "MagFilter", 0, "Anisotropic");
    tb_state_e(cfx, "MipFilter", 0, "None");
    tb_state_i(cfx, "MaxAnisotropy", 0, 4);
    tb_state_e(cfx, "AddressU", 0, "Clamp");
    tb_sampler_states(cfx, b, first, cfx->state_count - first);
    uint32_t prog = tb_program(cfx, tb_vs_pos,
                               "#version 330\nuniform sampler2D s0;\nuniform sampler2D s1;\nout vec4 hfx_out0;\n"
                               "void main() { hfx_out0 = texture(s0, vec2(0.25, 0.25)) + texture(s1, vec2(0.75)) * 0.0; }\n");
    tb_sampler_use(cfx, prog, "s0", a, 0);
    tb_sampler_use(cfx, prog, "s1", b, 1);
    tb_technique(cfx, "T");
    tb_pass(cfx, "Plain", prog, 0, 0);
    first = cfx->state_count;
    tb_state_e(cfx, "MinFilter", 0, "Point"); /* pass-level: sampler stage 0 */
    tb_pass(cfx, "Override", prog, first, 1);
    char *errors = NULL;
    hfx_effect *fx = hfx_rt_effect_from_fx(dev, cfx, NULL, &errors);
    CHECK(fx != NULL);
    hfx_free(errors);
    return fx;
}

static GLuint sampler_on(int unit) {
    GLint s = 0;
    g.ActiveTexture(GL_TEXTURE0 + (GLenum)unit);
    g.GetIntegerv(GL_SAMPLER_BINDING, &s);
    return (GLuint)s;
}

static GLint sampler_i(GLuint s, GLenum e) {
    GLint v[4] = {0};
    g.GetSamplerParameteriv(s, e, v);
    return v[0];
}

static void test_sampler_states(void) {
    fresh();
    hfx_effect *fx = sampler_effect();
    GLuint tex = 0;
    g.GenTextures(1, &tex);
    g.BindTexture(GL_TEXTURE_2D, tex);
    /* 2x2: red, green / blue, white (rows bottom-up as GL stores them) */
    const unsigned char texels[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 255};
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    /* one level: GL needs to be told, or a mip filter makes the texture incomplete (D3D knows) */
    g.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    g.BindTexture(GL_TEXTURE_2D, 0);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "tex"), tex), HFX_OK);
    hfx_technique *t = hfx_effect_current_technique(fx);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(t, 0)), HFX_OK);
    GLuint s = sampler_on(0);
    CHECK(s != 0);
    CHECK_INT(sampler_i(s, GL_TEXTURE_MIN_FILTER), GL_LINEAR_MIPMAP_LINEAR);
    CHECK_INT(sampler_i(s, GL_TEXTURE_MAG_FILTER), GL_NEAREST);
    CHECK_INT(sampler_i(s, GL_TEXTURE_WRAP_S), GL_MIRRORED_REPEAT);
    CHECK_INT(sampler_i(s, GL_TEXTURE_WRAP_T), GL_CLAMP_TO_BORDER);
    CHECK_INT(sampler_i(s, GL_TEXTURE_WRAP_R), GL_MIRROR_CLAMP_TO_EDGE);
    float f[4] = {0};
    g.GetSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, f);
    CHECK_NEAR(f[0], 0, 0);
    CHECK_NEAR(f[1], 1, 0);
    CHECK_NEAR(f[3], 1, 0);
    g.GetSamplerParameterfv(s, GL_TEXTURE_LOD_BIAS, f);
    CHECK_NEAR(f[0], -1.5, 0);
    g.GetSamplerParameterfv(s, GL_TEXTURE_MIN_LOD, f); /* MaxMipLevel 2: mip 2 is the largest used */
    CHECK_NEAR(f[0], 2, 0);
    GLint bound = 0;
    g.GetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    CHECK_INT(bound, tex);
    GLuint s1 = sampler_on(1);
    CHECK_INT(sampler_i(s1, GL_TEXTURE_MIN_FILTER), GL_LINEAR);
    CHECK_INT(sampler_i(s1, GL_TEXTURE_MAG_FILTER), GL_LINEAR);
    CHECK_INT(sampler_i(s1, GL_TEXTURE_WRAP_S), GL_CLAMP_TO_EDGE);
    CHECK_INT(sampler_i(s1, GL_TEXTURE_WRAP_T), GL_REPEAT); /* D3D's default Wrap */
    if (dev->max_anisotropy > 0) {
        g.GetSamplerParameterfv(s1, GL_TEXTURE_MAX_ANISOTROPY, f);
        CHECK_NEAR(f[0], dev->max_anisotropy < 4 ? dev->max_anisotropy : 4, 0);
    }
    /* the pass's MinFilter[0] = Point overrides stage 0 only, keeping the sampler's MipFilter */
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(t, 1)), HFX_OK);
    GLuint so = sampler_on(0);
    CHECK(so != s);
    CHECK_INT(sampler_i(so, GL_TEXTURE_MIN_FILTER), GL_NEAREST_MIPMAP_LINEAR);
    CHECK_INT(sampler_i(so, GL_TEXTURE_WRAP_S), GL_MIRRORED_REPEAT);
    CHECK_INT(sampler_on(1), s1);
    /* the texture is sampled: (0.25, 0.25) is the bottom-left texel, red */
    GLuint vbo, vao = tgl_triangles(&g, full, 6, &vbo);
    clear(0, 0, 0, 0);
    g.DrawArrays(GL_TRIANGLES, 0, 6);
    rt_check_pixel(gl, 8, 8, 255, 0, 0, 255);
    g.DeleteBuffers(1, &vbo);
    g.DeleteVertexArrays(1, &vao);
    CHECK_INT(g.GetError(), GL_NO_ERROR);
    hfx_effect_destroy(fx);
    g.DeleteTextures(1, &tex);
}

static uint32_t stage_tex_param;

static void add_stage_states(hfx_fx_effect *fx) {
    stage_tex_param = tb_param(fx, "other", NULL, HFX_CLASS_OBJECT, HFX_TYPE_TEXTURE2D, 0, 0, 0, HFX_NONE, 0, 0);
    tb_state_e(fx, "MinFilter", 3, "Linear");
    tb_state_e(fx, "AddressU", 3, "Clamp");
    tb_state_p(fx, "Texture", 2, stage_tex_param);
}

/* Pass-level Texture[n] binds on stage n; sampler states alone leave stage n's texture. */
static void test_pass_stage_states(void) {
    fresh();
    GLuint tex[2];
    g.GenTextures(2, tex);
    g.ActiveTexture(GL_TEXTURE3);
    g.BindTexture(GL_TEXTURE_2D, tex[0]);
    g.ActiveTexture(GL_TEXTURE0);
    hfx_effect *fx = effect_with(add_stage_states, 0, NULL);
    CHECK_STR(hfx_effect_warnings(fx), "");
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "other"), tex[1]), HFX_OK);
    CHECK_INT(apply(fx), HFX_OK);
    GLuint s3 = sampler_on(3);
    CHECK(s3 != 0);
    CHECK_INT(sampler_i(s3, GL_TEXTURE_MIN_FILTER), GL_LINEAR);
    CHECK_INT(sampler_i(s3, GL_TEXTURE_WRAP_S), GL_CLAMP_TO_EDGE);
    CHECK_INT(geti(GL_TEXTURE_BINDING_2D), tex[0]); /* unit 3, active since sampler_on */
    g.ActiveTexture(GL_TEXTURE2);
    CHECK_INT(geti(GL_TEXTURE_BINDING_2D), tex[1]);
    g.ActiveTexture(GL_TEXTURE0);
    hfx_effect_destroy(fx);
    g.DeleteTextures(2, tex);
    fresh();
}

/* A 1D texture is a 2D texture of height 1 (the GLSL samples it with a sampler2D). */
static void test_1d_textures_bind_as_2d(void) {
    fresh();
    hfx_fx_effect *cfx = tb_new();
    uint32_t tex = tb_param(cfx, "ramp", NULL, HFX_CLASS_OBJECT, HFX_TYPE_TEXTURE1D, 0, 0, 0, HFX_NONE, 0, 0);
    uint32_t sp = tb_param(cfx, "s", "s", HFX_CLASS_OBJECT, HFX_TYPE_SAMPLER1D, 0, 0, 0, HFX_NONE, 0, 0);
    uint32_t sm = tb_sampler(cfx, sp, tex, HFX_FX_DIM_1D);
    uint32_t prog = tb_program(cfx, tb_vs_pos,
                               "#version 330\nuniform sampler2D s;\nout vec4 o;\n"
                               "void main() { o = texture(s, vec2(0.9, 0.5)); }\n");
    tb_sampler_use(cfx, prog, "s", sm, 0);
    tb_technique(cfx, "T");
    tb_pass(cfx, "P", prog, 0, 0);
    hfx_effect *fx = hfx_rt_effect_from_fx(dev, cfx, NULL, NULL);
    CHECK(fx != NULL);
    GLuint t;
    g.GenTextures(1, &t);
    g.BindTexture(GL_TEXTURE_2D, t);
    const unsigned char texels[8] = {0, 0, 0, 255, 255, 128, 0, 255};
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    g.BindTexture(GL_TEXTURE_2D, 0);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "ramp"), t), HFX_OK);
    CHECK_INT(apply(fx), HFX_OK);
    g.ActiveTexture(GL_TEXTURE0);
    CHECK_INT(geti(GL_TEXTURE_BINDING_2D), t);
    clear(0, 0, 0, 0);
    draw(full, 6);
    rt_check_pixel(gl, 8, 8, 255, 128, 0, 255); /* u = 0.9: the second texel (Point filtering by default) */
    hfx_effect_destroy(fx);
    g.DeleteTextures(1, &t);
    fresh();
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    CHECK(dev != NULL);
    g.Viewport(0, 0, W, H);
    RUN(test_cull_by_winding);
    RUN(test_blending);
    RUN(test_render_states_read_back);
    RUN(test_states_persist_and_begin_end_restores);
    RUN(test_param_valued_states);
    RUN(test_alpha_test_emulation);
    RUN(test_unsupported_states_reported_once);
    RUN(test_sampler_states);
    RUN(test_pass_stage_states);
    RUN(test_1d_textures_bind_as_2d);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
