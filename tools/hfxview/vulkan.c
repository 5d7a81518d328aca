/* vulkan.c: hfxview --vulkan: the same picture on a headless Vulkan device (lavapipe), through
 * hfx_pass_apply_vk. The mesh's attributes by semantic in one vertex layout, the inputs a mesh
 * lacks as the GL path gives them (mesh.h); the textures the GL path would bind (textures.c:
 * --texture, annotated files, the checkerboards), as 2D, cube or volume images and views. */
#include "vulkan.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "textures.h"
#include "vk_context.h"

enum { CONSTANT_BINDING = 1 };

typedef struct hv_vk {
    test_vk *v;
    hfx_vertex_layout *layout;
    test_vk_buffer vb, ib, constants;  /* constants: hv_vertex_constants, one vec4 each */
    test_vk_texture textures[64];
    size_t texture_count;
    hv_textures made;
    uint32_t index_count;
} hv_vk;

/* The mesh's attributes by semantic, TEXCOORD1..7 reading the first set and the inputs a mesh
 * never has reading hv_vertex_constants from a constant buffer (stride 0), as the GL path
 * gives them (render.c). */
static hfx_vertex_layout *mesh_layout(hfx_device *dev) {
    static const char *const sets[] = {"TEXCOORD1", "TEXCOORD2", "TEXCOORD3", "TEXCOORD4", "TEXCOORD5", "TEXCOORD6", "TEXCOORD7"};
    hfx_vertex_element e[32] = {
        {"POSITION0", VK_FORMAT_R32G32B32_SFLOAT, offsetof(hv_vertex, pos), 0, sizeof(hv_vertex)},
        {"NORMAL0", VK_FORMAT_R32G32B32_SFLOAT, offsetof(hv_vertex, normal), 0, sizeof(hv_vertex)},
        {"TEXCOORD0", VK_FORMAT_R32G32_SFLOAT, offsetof(hv_vertex, uv), 0, sizeof(hv_vertex)},
        {"TANGENT0", VK_FORMAT_R32G32B32_SFLOAT, offsetof(hv_vertex, tangent), 0, sizeof(hv_vertex)},
        {"BINORMAL0", VK_FORMAT_R32G32B32_SFLOAT, offsetof(hv_vertex, binormal), 0, sizeof(hv_vertex)}};
    size_t n = 5;
    for (size_t i = 0; i < sizeof sets / sizeof *sets; i++)
        e[n++] = (hfx_vertex_element){sets[i], VK_FORMAT_R32G32_SFLOAT, offsetof(hv_vertex, uv), 0, sizeof(hv_vertex)};
    for (size_t i = 0; i < hv_vertex_constant_count; i++)
        e[n++] = (hfx_vertex_element){hv_vertex_constants[i].semantic, VK_FORMAT_R32G32B32A32_SFLOAT,
                                      (uint32_t)(i * sizeof hv_vertex_constants[i].v), CONSTANT_BINDING, 0};
    return hfx_vertex_layout_create(dev, e, n);
}

static int upload(hv_vk *g, const hv_mesh *m) {
    float constants[16][4];
    for (size_t i = 0; i < hv_vertex_constant_count && i < 16; i++)
        memcpy(constants[i], hv_vertex_constants[i].v, sizeof constants[i]);
    g->index_count = (uint32_t)m->icount;
    return test_vk_buffer_make(g->v, m->v, m->vcount * sizeof *m->v, &g->vb) &&
           test_vk_buffer_make(g->v, m->idx, m->icount * sizeof *m->idx, &g->ib) &&
           test_vk_buffer_make(g->v, constants, hv_vertex_constant_count * sizeof constants[0], &g->constants);
}

/* A texture for hv_bind_textures_with: the image's first face as a 2D texture, its six faces
 * (or the one image on every face) as a cube, its slices as a volume; mipmapped as GL's. */
static uint64_t vk_make(void *ctx, const hv_image *img, hv_tex_kind kind) {
    hv_vk *g = ctx;
    if (g->texture_count == sizeof g->textures / sizeof *g->textures) return 0;
    size_t face = (size_t)img->width * (size_t)img->height * 4;
    unsigned char *six = NULL;
    const unsigned char *texels = img->rgba;
    if (kind == HV_TEX_CUBE && hv_image_face_count(img) != 6) {
        if (!(six = malloc(face * 6))) return 0;
        for (int f = 0; f < 6; f++) memcpy(six + face * (size_t)f, img->rgba, face);
        texels = six;
    }
    static const test_vk_kind kinds[] = {TEST_VK_2D, TEST_VK_CUBE, TEST_VK_3D};
    test_vk_texture *t = &g->textures[g->texture_count];
    int ok = test_vk_texture_make_kind(g->v, kinds[kind], img->width, img->height, kind == HV_TEX_3D ? img->depth : 1, 1,
                                       texels, t);
    free(six);
    if (!ok) return test_vk_texture_free(g->v, t), 0;
    g->texture_count++;
    return (uint64_t)(uintptr_t)t->view;
}

static int vk_set(hfx_param *p, uint64_t view) {
    return hfx_param_set_texture_vk(p, (VkImageView)(uintptr_t)view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
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
    VkBuffer buffers[2] = {g->vb.buffer, g->constants.buffer};
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

/* Frees everything; the validation layer's messages over the whole run (0 without the layer). */
static int release(hv_vk *g) {
    if (!g->v) return 0;
    for (size_t i = 0; i < g->texture_count; i++) test_vk_texture_free(g->v, &g->textures[i]);
    test_vk_buffer_free(g->v, &g->vb);
    test_vk_buffer_free(g->v, &g->ib);
    test_vk_buffer_free(g->v, &g->constants);
    hfx_vertex_layout_destroy(g->layout);
    int messages = test_vk_destroy(g->v); /* with the device's own at its destruction (objects left alive) */
    if (messages) fprintf(stderr, "hfxview: error: the Vulkan validation layer sent %d messages\n", messages);
    return messages;
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
    const hv_texture_maker maker = {g, vk_make, vk_set};
    char err[512];
    if (!upload(g, m)) return HFX_ERR_MEMORY;
    if (hv_bind_textures_with(&g->made, &maker, fx, o, err, sizeof err) != 0) {
        fprintf(stderr, "hfxview: %s\n", err);
        return HFX_ERR_NOT_FOUND;
    }
    int rc = draw(g, fx, t, o, failed_pass);
    if (rc != HFX_OK) return rc;
    size_t bytes = (size_t)o->width * (size_t)o->height * 4;
    memset(img, 0, sizeof *img);
    img->width = o->width, img->height = o->height;
    if (!(img->rgba = malloc(bytes))) return HFX_ERR_MEMORY;
    memcpy(img->rgba, test_vk_pixels(g->v), bytes);
    return HFX_OK;
}

int hv_vk_close(hv_vk *g) {
    int messages = g ? release(g) : 0;
    free(g);
    return messages;
}

size_t hv_vk_pipelines(const hv_vk *g) { return g && g->v ? hfx_device_pipelines_created_vk(test_vk_device(g->v)) : 0; }
