/* An effect fxc compiled (fx_2_0), loaded by hfx_effect_load_memory as a .fx would be: the
 * hand-built test effect of tests/compiler/support/fx2_builder.h through the public
 * reflection API (types, semantics, annotations, defaults), a pass's render states applied on
 * GL and read back, a parameter-valued state and a computed one following their parameters,
 * the texture a pass binds, and clones keeping their own values. The effect has no shaders
 * (its pass draws nothing): what it checks is everything around them. */
#include <stdlib.h>
#include <string.h>

#include "../compiler/support/fx2_builder.h"
#include "gl_context.h"
#include "internal.h"
#include "rt_check.h"
#include "rt_support.h"
#include "test.h"

#define W 4
#define H 4

static test_gl *gl;
static tgl g;
static hfx_device *dev;

static hfx_effect *load_sample(void) {
    size_t size;
    uint8_t *file = fxb_sample_file(&size, NULL, 0);
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, file, size, "t.fxb", NULL, &errors);
    if (!fx) fprintf(stderr, "did not load:\n%s\n", errors ? errors : "(no message)");
    hfx_free(errors);
    free(file);
    return fx;
}

static GLint geti(GLenum e) {
    GLint v[4] = {0};
    g.GetIntegerv(e, v);
    return v[0];
}

static void reflection(void) {
    hfx_effect *fx = load_sample();
    CHECK(fx != NULL);
    if (!fx) return;
    CHECK_INT(hfx_effect_param_count(fx), 12);
    hfx_param *color = hfx_effect_param_by_semantic(fx, "diffuse");
    CHECK(color == hfx_effect_param(fx, "Color"));
    CHECK_INT(hfx_param_get_class(color), HFX_CLASS_VECTOR);
    CHECK_INT(hfx_param_columns(color), 4);
    float c[4] = {0};
    CHECK_INT(hfx_param_get_floats(color, c, 4), HFX_OK);
    CHECK_NEAR(c[0], 0.25, 0);
    CHECK_NEAR(c[3], 1, 0);
    CHECK_STR(hfx_annotation_string(hfx_param_annotation(color, "UIName")), "Tint");
    float ui_min = 0;
    CHECK_INT(hfx_annotation_float(hfx_param_annotation(color, "UIMin"), &ui_min), HFX_OK);
    CHECK_NEAR(ui_min, 0.5, 0);
    float m[16] = {0};
    CHECK_INT(hfx_param_get_matrix(hfx_effect_param(fx, "World"), m), HFX_OK);
    CHECK_NEAR(m[12], 13, 0); /* row 3, column 0: XNA's translation x */
    hfx_param *weights = hfx_effect_param(fx, "Weights");
    CHECK_INT(hfx_param_elements(weights), 3);
    float w1 = 0;
    CHECK_INT(hfx_param_get_float(hfx_param_element(weights, 1), &w1), HFX_OK);
    CHECK_NEAR(w1, 2, 0);
    hfx_param *b = hfx_param_member(hfx_effect_param(fx, "St"), "b");
    float bv[2] = {0};
    CHECK_INT(hfx_param_columns(b), 2);
    CHECK_INT(hfx_param_get_floats(b, bv, 2), HFX_OK);
    CHECK_NEAR(bv[1], 9, 0);
    CHECK_INT(hfx_param_get_type(hfx_effect_param(fx, "Samp")), HFX_TYPE_SAMPLER2D);
    hfx_technique *t = hfx_effect_technique(fx, "T");
    int order = 0;
    CHECK_INT(hfx_annotation_int(hfx_technique_annotation(t, "Order"), &order), HFX_OK);
    CHECK_INT(order, 3);
    CHECK_STR(hfx_annotation_string(hfx_pass_annotation(hfx_technique_pass(t, 0), "Mode")), "x");
    hfx_effect_destroy(fx);
}

/* CullMode = None, ZEnable = false, BlendFactor = (0.5, 0.25, 1, 0), StencilRef = <Index>. */
static void states_on_gl(void) {
    hfx_effect *fx = load_sample();
    CHECK(fx != NULL);
    if (!fx) return;
    hfx_pass *p = hfx_technique_pass(hfx_effect_technique(fx, "T"), 0);
    g.Enable(GL_CULL_FACE);
    g.Enable(GL_DEPTH_TEST);
    hfx_device_sync(dev);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    CHECK_INT(g.IsEnabled(GL_CULL_FACE), GL_FALSE);
    CHECK_INT(g.IsEnabled(GL_DEPTH_TEST), GL_FALSE);
    float bc[4] = {0};
    g.GetFloatv(GL_BLEND_COLOR, bc);
    CHECK_NEAR(bc[0], 0.5, 0);
    CHECK_NEAR(bc[1], 0.25, 0);
    CHECK_NEAR(bc[2], 1, 0);
    CHECK_INT(geti(GL_STENCIL_REF), 2);
    CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "Index"), 5), HFX_OK);
    CHECK_INT(hfx_pass_apply(p), HFX_OK);
    CHECK_INT(geti(GL_STENCIL_REF), 5);
    /* a clone keeps its own values */
    hfx_effect *copy = hfx_effect_clone(fx);
    CHECK(copy != NULL);
    if (copy) {
        CHECK_INT(hfx_param_set_int(hfx_effect_param(copy, "Index"), 7), HFX_OK);
        CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(copy, "T"), 0)), HFX_OK);
        CHECK_INT(geti(GL_STENCIL_REF), 7);
        CHECK_INT(hfx_pass_apply(p), HFX_OK);
        CHECK_INT(geti(GL_STENCIL_REF), 5);
        hfx_effect_destroy(copy);
    }
    hfx_effect_destroy(fx);
}

/* AlphaRef = (Ref * 255): 0.5 gives 127 (127.5 truncated), 0.2 gives 51. */
static void computed_state_follows_its_parameter(void) {
    hfx_effect *fx = load_sample();
    CHECK(fx != NULL);
    if (!fx) return;
    const hfx_fx_effect *e = fx->sh->fx;
    const hfx_fx_state *alpha_ref = &e->states[e->passes[0].first_state + 3];
    CHECK_INT(alpha_ref->id, HFX_ST_ALPHAREF);
    hfx_rs_value v;
    hfx_rs_resolve(fx, alpha_ref, &v);
    CHECK_INT(v.i, 127);
    CHECK_INT(hfx_param_set_float(hfx_effect_param(fx, "Ref"), 0.2f), HFX_OK);
    hfx_rs_resolve(fx, alpha_ref, &v);
    CHECK_INT(v.i, 51);
    hfx_effect_destroy(fx);
}

/* Texture[0] = <Tex>: the texture set on Tex is bound on unit 0 by Apply. */
static void pass_binds_the_texture(void) {
    hfx_effect *fx = load_sample();
    CHECK(fx != NULL);
    if (!fx) return;
    GLuint tex;
    g.GenTextures(1, &tex);
    g.BindTexture(GL_TEXTURE_2D, tex);
    static const unsigned char px[4] = {255, 0, 0, 255};
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    g.BindTexture(GL_TEXTURE_2D, 0);
    hfx_device_sync(dev);
    CHECK_INT(hfx_param_set_texture(hfx_effect_param(fx, "Tex"), tex), HFX_OK);
    CHECK_INT(hfx_pass_apply(hfx_technique_pass(hfx_effect_technique(fx, "T"), 0)), HFX_OK);
    g.ActiveTexture(GL_TEXTURE0);
    CHECK_INT(geti(GL_TEXTURE_BINDING_2D), (GLint)tex);
    hfx_effect_destroy(fx);
    g.DeleteTextures(1, &tex);
    hfx_device_sync(dev);
}

/* Real bytecode: a pass-through vs_2_0 and a ps_2_0 array (red, green) picked by ShaderIndex,
 * drawn over a blue clear: the centre pixel is the picked shader's colour. */
static void shaders_draw(void) {
    size_t size;
    uint8_t *file = fxb_shader_file(&size);
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(dev, file, size, "s.fxb", NULL, &errors);
    if (!fx) fprintf(stderr, "did not load:\n%s\n", errors ? errors : "(no message)");
    CHECK(fx != NULL);
    hfx_free(errors);
    free(file);
    if (!fx) return;
    static const float quad[12] = {-1, -1, 1, -1, 1, 1, -1, -1, 1, 1, -1, 1};
    hfx_pass *p = hfx_technique_pass(hfx_effect_technique(fx, "T"), 0);
    CHECK_INT(hfx_pass_attribute_location(p, "POSITION0"), 0);
    for (int k = 0; k < 2; k++) {
        CHECK_INT(hfx_param_set_int(hfx_effect_param(fx, "ShaderIndex"), k), HFX_OK);
        GLuint buffer, vao = tgl_triangles(&g, quad, 6, &buffer);
        g.ClearColor(0, 0, 1, 1);
        g.Clear(GL_COLOR_BUFFER_BIT);
        hfx_effect_begin(fx);
        CHECK_INT(hfx_pass_apply(p), HFX_OK);
        g.DrawArrays(GL_TRIANGLES, 0, 6);
        hfx_effect_end(fx);
        unsigned char px[4];
        test_gl_read(gl, W / 2, H / 2, px);
        CHECK_INT(px[0], k ? 0 : 255);
        CHECK_INT(px[1], k ? 255 : 0);
        CHECK_INT(px[2], 0);
        g.DeleteBuffers(1, &buffer);
        g.DeleteVertexArrays(1, &vao);
    }
    hfx_effect_destroy(fx);
}

int main(void) {
    gl = test_gl_create(W, H);
    if (!gl) test_skip("no OSMesa context");
    tgl_load(&g);
    dev = hfx_device_create_gl(test_gl_loader);
    CHECK(dev != NULL);
    g.Viewport(0, 0, W, H);
    RUN(reflection);
    RUN(states_on_gl);
    RUN(computed_state_follows_its_parameter);
    RUN(pass_binds_the_texture);
    RUN(shaders_draw);
    hfx_device_destroy(dev);
    test_gl_destroy(gl);
    return test_summary();
}
