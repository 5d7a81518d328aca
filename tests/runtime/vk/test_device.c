/* The Vulkan device: creation and its errors, a first draw probed by hand, uniforms sent only
 * when changed, pipelines built once, drawing under dynamic rendering (no render pass), and the
 * validation layer silent throughout. */
#include "hfx/hfx_vulkan.h"
#include "test.h"
#include "vk_context.h"

static test_vk *V;

static const char *FLAT =
    "float4x4 WorldViewProj;\n"
    "float4 Color = float4(1, 0.5, 0.25, 1);\n"
    "float4 VS(float4 p : POSITION) : POSITION { return mul(p, WorldViewProj); }\n"
    "float4 PS() : COLOR { return Color; }\n"
    "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

/* Two triangles covering the viewport, clockwise on D3D's screen (its front faces). */
static const float QUAD[6][3] = {{-1, 1, 0.5f}, {1, 1, 0.5f}, {1, -1, 0.5f}, {-1, 1, 0.5f}, {1, -1, 0.5f}, {-1, -1, 0.5f}};
static const float IDENTITY[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

static hfx_effect *load(const char *src) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(test_vk_device(V), src, strlen(src), "flat.fx", NULL, &errors);
    if (!fx) fprintf(stderr, "load: %s\n", errors ? errors : hfx_device_last_error(test_vk_device(V)));
    hfx_free(errors);
    return fx;
}

static int draw(hfx_effect *fx, test_vk_buffer *vb, const float clear[4]) {
    VkCommandBuffer cmd = test_vk_begin(V, clear);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    int rc = hfx_pass_apply_vk(pass, cmd, test_vk_target(V));
    if (rc) fprintf(stderr, "apply: %s\n", hfx_device_last_error(test_vk_device(V)));
    VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &vb->buffer, &zero);
    if (!rc) vkCmdDraw(cmd, 6, 1, 0, 0);
    CHECK_INT(test_vk_end(V), 0);
    return rc;
}

static void check_pixel(int x, int y, int r, int g, int b, int a) {
    const unsigned char *p = test_vk_pixel(V, x, y);
    CHECK_NEAR(p[0], r, 1);
    CHECK_NEAR(p[1], g, 1);
    CHECK_NEAR(p[2], b, 1);
    CHECK_NEAR(p[3], a, 1);
}

static hfx_vertex_layout *position_layout(void) {
    hfx_vertex_element e = {"POSITION0", VK_FORMAT_R32G32B32_SFLOAT, 0, 0, 12};
    return hfx_vertex_layout_create(test_vk_device(V), &e, 1);
}

/* Color's initializer (1, 0.5, 0.25, 1) is 255, 127.5, 63.75, 255 in the image. */
static void first_draw(void) {
    hfx_effect *fx = load(FLAT);
    CHECK(fx != NULL);
    test_vk_buffer vb;
    CHECK(test_vk_buffer_make(V, QUAD, sizeof QUAD, &vb));
    hfx_vertex_layout *layout = position_layout();
    CHECK(layout != NULL);
    test_vk_target(V)->layout = layout;
    if (fx) {
        CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "WorldViewProj"), IDENTITY), HFX_OK);
        const float clear[4] = {0, 0, 1, 1};
        CHECK_INT(draw(fx, &vb, clear), HFX_OK);
        check_pixel(0, 0, 255, 128, 64, 255);
        check_pixel(31, 17, 255, 128, 64, 255);
        check_pixel(63, 63, 255, 128, 64, 255);
        const float c[4] = {0.2f, 0.4f, 0.6f, 0.8f};
        CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Color"), c, 4), HFX_OK);
        CHECK_INT(draw(fx, &vb, clear), HFX_OK);
        check_pixel(10, 50, 51, 102, 153, 204);
        CHECK_INT(hfx_device_pipelines_created_vk(test_vk_device(V)), 1);
        hfx_effect_destroy(fx);
    }
    test_vk_target(V)->layout = NULL;
    hfx_vertex_layout_destroy(layout);
    test_vk_buffer_free(V, &vb);
}

/* vertices [first, first + 3) of QUAD in a frame begun with vkCmdBeginRendering. */
static void draw_dynamic(hfx_effect *fx, test_vk_buffer *vb, const float clear[4], uint32_t first) {
    VkCommandBuffer cmd = test_vk_begin_dynamic(V, clear);
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    int rc = hfx_pass_apply_vk(pass, cmd, test_vk_target(V));
    if (rc) fprintf(stderr, "apply: %s\n", hfx_device_last_error(test_vk_device(V)));
    CHECK_INT(rc, HFX_OK);
    VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &vb->buffer, &zero);
    if (!rc) vkCmdDraw(cmd, 3, 1, first, 0);
    CHECK_INT(test_vk_end(V), 0);
}

/* A target with no render pass: hfx builds the pipeline for dynamic rendering's formats. The
 * first triangle (above the diagonal from top left to bottom right) in Color over a blue clear,
 * then the second one in another colour over what the first frame left (load, no clear). */
static void dynamic_rendering(void) {
    const float blue[4] = {0, 0, 1, 1};
    if (test_vk_begin_dynamic(V, blue) == VK_NULL_HANDLE) {
        printf("  (no dynamic rendering on this device: skipped)\n");
        return;
    }
    test_vk_end(V);
    hfx_effect *fx = load(FLAT);
    test_vk_buffer vb;
    CHECK(test_vk_buffer_make(V, QUAD, sizeof QUAD, &vb));
    hfx_vertex_layout *layout = position_layout();
    test_vk_target(V)->layout = layout;
    size_t before = hfx_device_pipelines_created_vk(test_vk_device(V));
    if (fx && layout) {
        CHECK_INT(hfx_param_set_matrix(hfx_effect_param(fx, "WorldViewProj"), IDENTITY), HFX_OK);
        draw_dynamic(fx, &vb, blue, 0);
        check_pixel(60, 3, 255, 128, 64, 255);
        check_pixel(3, 60, 0, 0, 255, 255);
        const float green[4] = {0, 1, 0, 1};
        CHECK_INT(hfx_param_set_floats(hfx_effect_param(fx, "Color"), green, 4), HFX_OK);
        draw_dynamic(fx, &vb, NULL, 3);
        check_pixel(60, 3, 255, 128, 64, 255);
        check_pixel(3, 60, 0, 255, 0, 255);
        CHECK_INT(hfx_device_pipelines_created_vk(test_vk_device(V)) - before, 1);
    }
    hfx_effect_destroy(fx);
    test_vk_target(V)->layout = NULL;
    hfx_vertex_layout_destroy(layout);
    test_vk_buffer_free(V, &vb);
}

/* Every misuse is a return code and a message. */
static void errors(void) {
    char *err = NULL;
    CHECK(hfx_device_create_vulkan(NULL, &err) == NULL);
    CHECK_CONTAINS(err, "NULL description");
    hfx_free(err);
    hfx_vulkan_desc d = {0};
    CHECK(hfx_device_create_vulkan(&d, &err) == NULL);
    CHECK_CONTAINS(err, "required");
    hfx_free(err);
    hfx_effect *fx = load(FLAT);
    CHECK(fx != NULL);
    if (fx) {
        hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
        CHECK_INT(hfx_pass_apply(pass), HFX_ERR_NOT_FOUND);
        CHECK_CONTAINS(hfx_device_last_error(test_vk_device(V)), "Vulkan");
        CHECK_INT(hfx_pass_apply_vk(pass, VK_NULL_HANDLE, test_vk_target(V)), HFX_ERR_NULL);
        CHECK_INT(hfx_param_set_texture_vk(hfx_effect_param(fx, "Color"), VK_NULL_HANDLE, 0), HFX_ERR_TYPE);
        /* begin and end in order, as on GL: a second begin or a lone end is HFX_ERR_STATE */
        CHECK_INT(hfx_effect_end(fx), HFX_ERR_STATE);
        CHECK_INT(hfx_effect_begin(fx), HFX_OK);
        CHECK_INT(hfx_effect_begin(fx), HFX_ERR_STATE);
        CHECK_STR(hfx_device_last_error(test_vk_device(V)), "hfx_effect_begin twice without hfx_effect_end (a call out of order)");
        CHECK_INT(hfx_effect_end(fx), HFX_OK);
        CHECK_INT(hfx_effect_end(fx), HFX_ERR_STATE);
        hfx_effect_destroy(fx);
    }
}

static void validation_silent(void) {
    CHECK(test_vk_validation_on(V));
    CHECK_INT(test_vk_messages(V), 0);
}

int main(void) {
    const char *why = NULL;
    V = test_vk_create(64, 64, &why);
    if (!V) test_skip(why ? why : "no Vulkan device");
    RUN(first_draw);
    RUN(dynamic_rendering);
    RUN(errors);
    RUN(validation_silent);
    test_vk_destroy(V);
    return test_summary();
}
