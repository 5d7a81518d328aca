/* vulkan.c: hfxview --vulkan: the same picture on a headless Vulkan device (lavapipe), through
 * hfx_pass_apply_vk. The mesh's attributes by semantic in one vertex layout; inputs the mesh
 * lacks (COLOR0, TEXCOORD1...) read a constant white, as hfxview's GL path gives them; every
 * texture parameter gets the mipmapped checkerboard the GL path makes. */
#include "vulkan.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "vk_context.h"

enum { WHITE_BINDING = 1 };

typedef struct hv_vk {
    test_vk *v;
    hfx_vertex_layout *layout;
    test_vk_buffer vb, ib, white;
    test_vk_texture checker;
    uint32_t index_count;
} hv_vk;

static hfx_vertex_layout *mesh_layout(hfx_device *dev) {
    static const char *const white[] = {"COLOR0", "COLOR1", "TEXCOORD1", "TEXCOORD2", "TEXCOORD3", "TEXCOORD4",
                                        "TEXCOORD5", "TEXCOORD6", "TEXCOORD7", "BLENDWEIGHT0", "BLENDINDICES0"};
    hfx_vertex_element e[16] = {
        {"POSITION0", VK_FORMAT_R32G32B32_SFLOAT, offsetof(hv_vertex, pos), 0, sizeof(hv_vertex)},
        {"NORMAL0", VK_FORMAT_R32G32B32_SFLOAT, offsetof(hv_vertex, normal), 0, sizeof(hv_vertex)},
        {"TEXCOORD0", VK_FORMAT_R32G32_SFLOAT, offsetof(hv_vertex, uv), 0, sizeof(hv_vertex)},
        {"TANGENT0", VK_FORMAT_R32G32B32_SFLOAT, offsetof(hv_vertex, tangent), 0, sizeof(hv_vertex)},
        {"BINORMAL0", VK_FORMAT_R32G32B32_SFLOAT, offsetof(hv_vertex, binormal), 0, sizeof(hv_vertex)}};
    size_t n = 5;
    for (size_t i = 0; i < sizeof white / sizeof *white; i++)
        e[n++] = (hfx_vertex_element){white[i], VK_FORMAT_R32G32B32A32_SFLOAT, 0, WHITE_BINDING, 0};
    return hfx_vertex_layout_create(dev, e, n);
}

static int upload(hv_vk *g, const hv_mesh *m) {
    static const float white[4] = {1, 1, 1, 1};
    g->index_count = (uint32_t)m->icount;
    return test_vk_buffer_make(g->v, m->v, m->vcount * sizeof *m->v, &g->vb) &&
           test_vk_buffer_make(g->v, m->idx, m->icount * sizeof *m->idx, &g->ib) &&
           test_vk_buffer_make(g->v, white, sizeof white, &g->white);
}

/* Every texture parameter (or sampler, when no texture parameter feeds them) gets the checkerboard. */
static int bind_textures(hv_vk *g, hfx_effect *fx) {
    static const unsigned char light[4] = {235, 235, 235, 255}, dark[4] = {90, 90, 100, 255};
    hv_image img;
    if (hv_image_checker(&img, 256, 8, light, dark) != 0) return -1;
    int ok = test_vk_texture_make_mipmapped(g->v, img.width, img.height, img.rgba, &g->checker);
    hv_image_free(&img);
    if (!ok) return -1;
    int texture_params = 0;
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        hfx_param_type t = hfx_param_get_type(hfx_effect_param_at(fx, i));
        texture_params |= t >= HFX_TYPE_TEXTURE && t <= HFX_TYPE_TEXTURECUBE;
    }
    for (size_t i = 0; i < hfx_effect_param_count(fx); i++) {
        hfx_param *p = hfx_effect_param_at(fx, i);
        hfx_param_type t = hfx_param_get_type(p);
        int texture = t >= HFX_TYPE_TEXTURE && t <= HFX_TYPE_TEXTURE2D, sampler = t == HFX_TYPE_SAMPLER || t == HFX_TYPE_SAMPLER2D;
        if (texture || (sampler && !texture_params))
            hfx_param_set_texture_vk(p, g->checker.view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    }
    return 0;
}

/* The application's additive blending without depth writes before the second pass (--blend-passes add). */
static void additive(hfx_device *dev) {
    hfx_device_set_render_state_vk(dev, "AlphaBlendEnable", 1);
    hfx_device_set_render_state_vk(dev, "SrcBlend", 2);
    hfx_device_set_render_state_vk(dev, "DestBlend", 2);
    hfx_device_set_render_state_vk(dev, "BlendOp", 1);
    hfx_device_set_render_state_vk(dev, "ZWriteEnable", 0);
}

static int draw(hv_vk *g, hfx_effect *fx, hfx_technique *t, const hv_options *o, size_t *failed) {
    hfx_device *dev = hfx_effect_device(fx);
    VkCommandBuffer cmd = test_vk_begin(g->v, o->background);
    VkBuffer buffers[2] = {g->vb.buffer, g->white.buffer};
    VkDeviceSize offsets[2] = {0, 0};
    int rc = HFX_OK, added = 0;
    hfx_device_reset_render_states_vk(dev);
    hfx_effect_begin(fx);
    for (size_t i = 0; i < hfx_technique_pass_count(t) && rc == HFX_OK; i++) {
        if (o->pass >= 0 && (size_t)o->pass != i) continue;
        if (o->blend_add && i > 0 && !added) additive(dev), added = 1;
        rc = hfx_pass_apply_vk(hfx_technique_pass(t, i), cmd, test_vk_target(g->v));
        if (rc != HFX_OK) {
            *failed = i;
            break;
        }
        vkCmdBindVertexBuffers(cmd, 0, 2, buffers, offsets);
        vkCmdBindIndexBuffer(cmd, g->ib.buffer, 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(cmd, g->index_count, 1, 0, 0, 0);
    }
    hfx_effect_end(fx);
    if (test_vk_end(g->v) != 0 && rc == HFX_OK) rc = HFX_ERR_VULKAN;
    return rc;
}

static void release(hv_vk *g) {
    if (!g->v) return;
    test_vk_texture_free(g->v, &g->checker);
    test_vk_buffer_free(g->v, &g->vb);
    test_vk_buffer_free(g->v, &g->ib);
    test_vk_buffer_free(g->v, &g->white);
    hfx_vertex_layout_destroy(g->layout);
    int messages = test_vk_messages(g->v);
    if (messages) fprintf(stderr, "hfxview: the Vulkan validation layer sent %d messages\n", messages);
    test_vk_destroy(g->v);
}

int hv_vk_open(hv_vk **out, int width, int height, hfx_device **dev, char *err, size_t errlen) {
    const char *why = NULL;
    hv_vk *g = calloc(1, sizeof *g);
    *out = g;
    if (!g || !(g->v = test_vk_create(width, height, &why))) {
        snprintf(err, errlen, "no Vulkan device: %s", why ? why : "out of memory");
        return -1;
    }
    *dev = test_vk_device(g->v);
    g->layout = mesh_layout(*dev);
    test_vk_target(g->v)->layout = g->layout;
    return g->layout ? 0 : (snprintf(err, errlen, "%s", hfx_device_last_error(*dev)), -1);
}

int hv_vk_render(hv_vk *g, hfx_effect *fx, hfx_technique *t, const hv_options *o, const hv_mesh *m, hv_image *img,
                 size_t *failed_pass) {
    if (!upload(g, m) || bind_textures(g, fx) != 0) return HFX_ERR_MEMORY;
    int rc = draw(g, fx, t, o, failed_pass);
    if (rc != HFX_OK) return rc;
    size_t bytes = (size_t)o->width * (size_t)o->height * 4;
    memset(img, 0, sizeof *img);
    img->width = o->width, img->height = o->height;
    if (!(img->rgba = malloc(bytes))) return HFX_ERR_MEMORY;
    memcpy(img->rgba, test_vk_pixels(g->v), bytes);
    return HFX_OK;
}

void hv_vk_close(hv_vk *g) {
    if (g) release(g);
    free(g);
}

size_t hv_vk_pipelines(const hv_vk *g) { return g && g->v ? hfx_device_pipelines_created_vk(test_vk_device(g->v)) : 0; }
