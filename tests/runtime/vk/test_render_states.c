/* D3D9 render states on Vulkan, probed against values worked out by hand: blend modes (D3D's
 * blend equations on the clear colour), depth function and write, culling with D3D's winding
 * (clockwise on screen is the front), stencil (one- and two-sided), colour write mask and
 * scissor. Every pass state picks a cached pipeline; the validation layer stays silent. */
#include "vk_draw.h"

static test_vk *V;
static hfx_effect *FX;

static const char *SRC =
    "float4 Color = float4(1, 0, 0, 1);\n"
    "int Factor = 0x80402010;\n"
    "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 PS() : COLOR { return Color; }\n"
    "float4 Red() : COLOR { return float4(1, 0, 0, 1); }\n"
    "float4 Green() : COLOR { return float4(0, 1, 0, 1); }\n"
    "#define WITH(ps) VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 ps();\n"
    "technique AlphaBlend { pass P { AlphaBlendEnable = true; SrcBlend = SrcAlpha; DestBlend = InvSrcAlpha; WITH(PS) } }\n"
    "technique Additive { pass P { AlphaBlendEnable = true; SrcBlend = One; DestBlend = One; WITH(PS) } }\n"
    "technique RevSub { pass P { AlphaBlendEnable = true; SrcBlend = One; DestBlend = One; BlendOp = RevSubtract;\n"
    "  WITH(PS) } }\n"
    "technique Factor { pass P { AlphaBlendEnable = true; SrcBlend = BlendFactor; DestBlend = Zero;\n"
    "  BlendFactor = 0x80402010; WITH(PS) } }\n"
    "technique DepthLess { pass A { WITH(Red) } pass B { ZFunc = Less; WITH(Green) } }\n"
    "technique DepthGreater { pass A { WITH(Red) } pass B { ZFunc = Greater; WITH(Green) } }\n"
    "technique NoDepthWrite { pass A { ZWriteEnable = false; WITH(Red) } pass B { WITH(Green) } }\n"
    "technique CullCW { pass P { CullMode = CW; WITH(Green) } }\n"
    "technique CullCCW { pass P { CullMode = CCW; WITH(Green) } }\n"
    "technique CullNone { pass P { CullMode = None; WITH(Green) } }\n"
    "technique Stencil { pass Mark { StencilEnable = true; StencilFunc = Always; StencilPass = Replace;\n"
    "  StencilRef = 5; ColorWriteEnable = 0; WITH(Red) }\n"
    "  pass Test { StencilFunc = Equal; StencilPass = Keep; ColorWriteEnable = Red | Green | Blue | Alpha; WITH(Green) } }\n"
    "technique TwoSided { pass Back { StencilEnable = true; TwoSidedStencilMode = true; CullMode = None;\n"
    "  StencilFunc = Always; StencilPass = Keep; Ccw_StencilFunc = Always; Ccw_StencilPass = Replace;\n"
    "  StencilRef = 7; ColorWriteEnable = 0; WITH(Red) }\n"
    "  pass Front { WITH(Red) }\n"
    "  pass Test { TwoSidedStencilMode = false; CullMode = CCW; StencilFunc = Equal; StencilPass = Keep;\n"
    "  ColorWriteEnable = 15; WITH(Green) } }\n"
    "technique FactorParam { pass P { AlphaBlendEnable = true; SrcBlend = BlendFactor; DestBlend = Zero;\n"
    "  BlendFactor = <Factor>; WITH(PS) } }\n"
    "technique Mask { pass P { ColorWriteEnable = Red | Alpha; WITH(PS) } }\n"
    "technique Scissor { pass P { ScissorTestEnable = true; WITH(Green) } }\n"
    "technique Plain { pass P { WITH(Green) } }\n";

/* The clear colour (0.2, 0.4, 0.6, 1) is 51, 102, 153, 255 in the image. */
static const float CLEAR[4] = {0.2f, 0.4f, 0.6f, 1.0f};
static const vk_quad FULL = {-1, -1, 1, 1, 0.5f, 1, 1, 0};

static int draw1(const char *technique, const float *color) {
    if (color) CHECK_INT(hfx_param_set_floats(hfx_effect_param(FX, "Color"), color, 4), HFX_OK);
    return vk_draw(V, FX, technique, &FULL, 1, CLEAR);
}

/* SrcAlpha / InvSrcAlpha: 0.25 * (1, 0, 0, 0.25) + 0.75 * (0.2, 0.4, 0.6, 1) = (0.4, 0.3, 0.45, 0.8125). */
static void blend_modes(void) {
    const float red_quarter[4] = {1, 0, 0, 0.25f}, quarter[4] = {0.25f, 0.25f, 0.25f, 0.25f};
    const float tenth[4] = {0.1f, 0.1f, 0.1f, 0.1f}, white[4] = {1, 1, 1, 1};
    CHECK_INT(draw1("AlphaBlend", red_quarter), 0);
    CHECK_PIXEL(V, 32, 32, 102, 76.5, 114.75, 207.19);
    /* One / One: (0.45, 0.65, 0.85, 1.25 -> 1). */
    CHECK_INT(draw1("Additive", quarter), 0);
    CHECK_PIXEL(V, 10, 50, 114.75, 165.75, 216.75, 255);
    /* RevSubtract: destination - source = (0.1, 0.3, 0.5, 0.9). */
    CHECK_INT(draw1("RevSub", tenth), 0);
    CHECK_PIXEL(V, 50, 10, 25.5, 76.5, 127.5, 229.5);
    /* BlendFactor 0x80402010 (A 0x80, R 0x40, G 0x20, B 0x10) times white. */
    CHECK_INT(draw1("Factor", white), 0);
    CHECK_PIXEL(V, 32, 32, 64, 32, 16, 128);
}

/* Red at depth 0.5, then green behind it at 0.7. */
static void depth(void) {
    const vk_quad q[2] = {{-1, -1, 1, 1, 0.5f, 1, 1, 0}, {-1, -1, 1, 1, 0.7f, 1, 1, 0}};
    CHECK_INT(vk_draw(V, FX, "DepthLess", q, 2, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 255, 0, 0, 255);
    CHECK_INT(vk_draw(V, FX, "DepthGreater", q, 2, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 0, 255, 0, 255);
    CHECK_INT(vk_draw(V, FX, "NoDepthWrite", q, 2, CLEAR), 0); /* red left the depth at 1: green passes */
    CHECK_PIXEL(V, 32, 32, 0, 255, 0, 255);
}

/* D3D's front faces are clockwise on screen: CullMode = CW culls them, CCW the others. */
static void culling(void) {
    const vk_quad ccw = {-1, -1, 1, 1, 0.5f, 1, 1, 1};
    CHECK_INT(vk_draw(V, FX, "CullCW", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 51, 102, 153, 255);
    CHECK_INT(vk_draw(V, FX, "CullCCW", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 0, 255, 0, 255);
    CHECK_INT(vk_draw(V, FX, "CullCCW", &ccw, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 51, 102, 153, 255);
    CHECK_INT(vk_draw(V, FX, "CullNone", &ccw, 1, CLEAR), 0);
    CHECK_PIXEL(V, 32, 32, 0, 255, 0, 255);
}

/* The left half marked with 5 (colour writes off), then green where the stencil equals 5. */
static void stencil(void) {
    const vk_quad q[2] = {{-1, -1, 0, 1, 0.5f, 1, 1, 0}, FULL};
    CHECK_INT(vk_draw(V, FX, "Stencil", q, 2, CLEAR), 0);
    CHECK_PIXEL(V, 16, 32, 0, 255, 0, 255);
    CHECK_PIXEL(V, 48, 32, 51, 102, 153, 255);
}

/* Two-sided: the back-facing (counter-clockwise) left half replaces with 7, the front-facing right
 * half keeps 0; then green where the stencil is 7: the left half only. */
static void two_sided_stencil(void) {
    const vk_quad q[3] = {{-1, -1, 0, 1, 0.5f, 1, 1, 1}, {0, -1, 1, 1, 0.5f, 1, 1, 0}, FULL};
    CHECK_INT(vk_draw(V, FX, "TwoSided", q, 3, CLEAR), 0);
    CHECK_PIXEL(V, 16, 32, 0, 255, 0, 255);
    CHECK_PIXEL(V, 48, 32, 51, 102, 153, 255);
}

/* Red | Alpha of white over the clear colour: (255, 102, 153, 255). */
static void color_write_mask(void) {
    const float white[4] = {1, 1, 1, 1};
    CHECK_INT(draw1("Mask", white), 0);
    CHECK_PIXEL(V, 32, 32, 255, 102, 153, 255);
}

/* The target's scissor (the left half) while the pass enables the test. */
static void scissor(void) {
    hfx_vk_target *t = test_vk_target(V);
    t->scissor = (VkRect2D){{0, 0}, {32, 64}};
    CHECK_INT(vk_draw(V, FX, "Scissor", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 16, 32, 0, 255, 0, 255);
    CHECK_PIXEL(V, 48, 32, 51, 102, 153, 255);
    t->scissor = (VkRect2D){{0, 0}, {64, 64}};
}

/* BlendFactor is dynamic: a new value from a parameter changes the picture, not the pipeline. */
static void dynamic_blend_factor(void) {
    const float white[4] = {1, 1, 1, 1};
    CHECK_INT(draw1("FactorParam", white), 0);
    CHECK_PIXEL(V, 32, 32, 64, 32, 16, 128);
    size_t before = hfx_device_pipelines_created_vk(test_vk_device(V));
    CHECK_INT(hfx_param_set_int(hfx_effect_param(FX, "Factor"), (int)0xFF804020u), 0);
    CHECK_INT(draw1("FactorParam", white), 0);
    CHECK_PIXEL(V, 32, 32, 128, 64, 32, 255);
    CHECK_INT(hfx_device_pipelines_created_vk(test_vk_device(V)), before);
}

/* Drawing everything again makes no pipeline: each (program, states, layout, target) was built once. */
static void pipelines_cached(void) {
    size_t before = hfx_device_pipelines_created_vk(test_vk_device(V));
    blend_modes();
    depth();
    CHECK_INT(hfx_device_pipelines_created_vk(test_vk_device(V)), before);
}

/* The pass Plain applied for one counter-clockwise quad, then, in the same command buffer
 * and with no begin / end between, again after CullMode = None (1) was set by hand: Apply's
 * short way (the same pass again keeps its pipeline) must see the hand-set state. D3D9's
 * default CullMode = CCW culls the first quad (the clear colour stays on the left half); the
 * second, on the right half, is green. Applying Plain a third time with nothing changed makes
 * no pipeline. */
static void short_way_sees_hand_states(void) {
    const vk_quad q[2] = {{-1, -1, 0, 1, 0.5f, 1, 1, 1}, {0, -1, 1, 1, 0.5f, 1, 1, 1}};
    vk_vertex verts[12];
    vk_quad_vertices(&q[0], verts), vk_quad_vertices(&q[1], verts + 6);
    test_vk_buffer vb;
    CHECK(test_vk_buffer_make(V, verts, sizeof verts, &vb));
    hfx_device *dev = test_vk_device(V);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_technique(FX, "Plain"), 0);
    CHECK_INT(hfx_device_reset_render_states_vk(dev), HFX_OK);
    VkCommandBuffer cmd = test_vk_begin(V, CLEAR);
    VkDeviceSize zero = 0;
    for (uint32_t i = 0; i < 2; i++) {
        if (i == 1) CHECK_INT(hfx_device_set_render_state_vk(dev, "CullMode", 1), HFX_OK);
        CHECK_INT(hfx_pass_apply_vk(pass, cmd, test_vk_target(V)), HFX_OK);
        vkCmdBindVertexBuffers(cmd, 0, 1, &vb.buffer, &zero);
        vkCmdDraw(cmd, 6, 1, 6 * i, 0);
    }
    size_t made = hfx_device_pipelines_created_vk(dev);
    CHECK_INT(hfx_pass_apply_vk(pass, cmd, test_vk_target(V)), HFX_OK);
    CHECK_INT(hfx_device_pipelines_created_vk(dev), made);
    CHECK_INT(test_vk_end(V), 0);
    CHECK_PIXEL(V, 16, 32, 51, 102, 153, 255);
    CHECK_PIXEL(V, 48, 32, 0, 255, 0, 255);
    test_vk_buffer_free(V, &vb);
    CHECK_INT(hfx_device_reset_render_states_vk(dev), HFX_OK);
}

int main(void) {
    hfx_vertex_layout *layout;
    V = vk_suite_begin(64, 64, &layout);
    FX = vk_load(V, SRC);
    if (!FX) return 1;
    RUN(blend_modes);
    RUN(depth);
    RUN(culling);
    RUN(stencil);
    RUN(two_sided_stencil);
    RUN(color_write_mask);
    RUN(scissor);
    RUN(dynamic_blend_factor);
    RUN(pipelines_cached);
    RUN(short_way_sees_hand_states);
    hfx_effect_destroy(FX);
    int messages = vk_suite_end(V, layout);
    return test_summary() || messages;
}
