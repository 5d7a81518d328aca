/* vk_draw.h: what the Vulkan runtime tests share: loading an effect from text on the test
 * device, quads given in D3D's clip space (x right, y up, z depth), drawn one pass each, and
 * pixel checks against hand-computed values. Static inline so the CHECKs count in the test's
 * own file (test.h's counters are per translation unit). */
#ifndef HFX_TEST_VK_DRAW_H
#define HFX_TEST_VK_DRAW_H

#include "hfx/hfx_vulkan.h"
#include "test.h"
#include "vk_context.h"

/* A vertex: D3D clip-space position and a texture coordinate. */
typedef struct vk_vertex { float pos[3], uv[2]; } vk_vertex;

/* A quad from (x0, y0) to (x1, y1) at depth z, clockwise on screen (D3D's front face) unless
 * ccw; uv runs (0, 0) at the top left to (u1, v1) at the bottom right. */
typedef struct vk_quad { float x0, y0, x1, y1, z, u1, v1; int ccw; } vk_quad;

static inline void vk_quad_vertices(const vk_quad *q, vk_vertex out[6]) {
    const vk_vertex tl = {{q->x0, q->y1, q->z}, {0, 0}}, tr = {{q->x1, q->y1, q->z}, {q->u1, 0}};
    const vk_vertex br = {{q->x1, q->y0, q->z}, {q->u1, q->v1}}, bl = {{q->x0, q->y0, q->z}, {0, q->v1}};
    const vk_vertex cw[6] = {tl, tr, br, tl, br, bl}, ccw[6] = {tl, br, tr, tl, bl, br};
    memcpy(out, q->ccw ? ccw : cw, sizeof cw);
}

/* Every effect a test loads is one that must load: a failure is a failed CHECK here, so a test
 * that returns early on NULL still fails (it would otherwise print "ok"). */
static inline hfx_effect *vk_load(test_vk *v, const char *src) {
    char *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(test_vk_device(v), src, strlen(src), "test.fx", NULL, &errors);
    if (!fx) fprintf(stderr, "load: %s\n", errors ? errors : hfx_device_last_error(test_vk_device(v)));
    hfx_free(errors);
    CHECK(fx != NULL);
    return fx;
}

static inline hfx_vertex_layout *vk_layout(test_vk *v) {
    const hfx_vertex_element e[2] = {{"POSITION", VK_FORMAT_R32G32B32_SFLOAT, 0, 0, sizeof(vk_vertex)},
                                     {"TEXCOORD0", VK_FORMAT_R32G32_SFLOAT, 12, 0, sizeof(vk_vertex)}};
    return hfx_vertex_layout_create(test_vk_device(v), e, 2);
}

/* Clears to `clear`, then draws quad i with pass i of the technique (each pass once per quad
 * when there are more quads than passes: pass i % passes). Returns the Apply failures. */
static inline int vk_draw(test_vk *v, hfx_effect *fx, const char *technique, const vk_quad *quads, int n,
                          const float clear[4]) {
    vk_vertex verts[6 * 8];
    for (int i = 0; i < n && i < 8; i++) vk_quad_vertices(&quads[i], &verts[6 * i]);
    test_vk_buffer vb;
    if (!test_vk_buffer_make(v, verts, sizeof verts, &vb)) return n;
    hfx_technique *t = technique ? hfx_effect_technique(fx, technique) : hfx_effect_current_technique(fx);
    if (t) hfx_effect_set_current_technique(fx, t);
    VkCommandBuffer cmd = test_vk_begin(v, clear);
    int failed = t ? 0 : n;
    hfx_effect_begin(fx);
    for (int i = 0; t && i < n; i++) {
        hfx_pass *pass = hfx_technique_pass(t, (size_t)i % hfx_technique_pass_count(t));
        if (hfx_pass_apply_vk(pass, cmd, test_vk_target(v)) != HFX_OK) {
            fprintf(stderr, "apply: %s\n", hfx_device_last_error(test_vk_device(v)));
            failed++;
            continue;
        }
        VkDeviceSize zero = 0;
        vkCmdBindVertexBuffers(cmd, 0, 1, &vb.buffer, &zero);
        vkCmdDraw(cmd, 6, 1, (uint32_t)(6 * i), 0);
    }
    hfx_effect_end(fx);
    if (test_vk_end(v) != 0) failed++;
    test_vk_buffer_free(v, &vb);
    return failed;
}

/* A test program's device, w x h, with vk_layout on its target (test_skip without Vulkan);
 * vk_suite_end frees both and checks that the validation layer reported nothing. */
static inline test_vk *vk_suite_begin(int w, int h, hfx_vertex_layout **layout) {
    const char *why = NULL;
    test_vk *v = test_vk_create(w, h, &why);
    if (!v) test_skip(why ? why : "no Vulkan device");
    *layout = vk_layout(v);
    test_vk_target(v)->layout = *layout;
    return v;
}

/* The validation layer's message count (checked to be 0). */
static inline int vk_suite_end(test_vk *v, hfx_vertex_layout *layout) {
    hfx_vertex_layout_destroy(layout);
    int messages = test_vk_messages(v);
    test_vk_destroy(v);
    CHECK_INT(messages, 0);
    return messages;
}

#define CHECK_PIXEL(v, x, y, r, g, b, a) do { const unsigned char *p_ = test_vk_pixel((v), (x), (y)); \
    CHECK_NEAR(p_[0], (r), 1.01); CHECK_NEAR(p_[1], (g), 1.01); CHECK_NEAR(p_[2], (b), 1.01); \
    CHECK_NEAR(p_[3], (a), 1.01); } while (0)

#endif
