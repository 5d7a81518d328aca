/* scene_vk.c: the seed scene drawn with Vulkan on lavapipe (see scene_gpu.h). seed_clear opens
 * a frame (a cleared render pass); draws record into it; the first read closes it (submit, wait,
 * read back). A draw after a read opens a frame that keeps the picture. The application state
 * the GL scene sets with GL calls (XNA's defaults, culling, additive blending) is set here with
 * hfx_device_set_render_state_vk, D3D9-style. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hfx/hfx_vulkan.h"
#include "scene_gpu.h"
#include "test.h"
#include "vk_context.h"

typedef struct vk_part {
    test_vk *v;
    hfx_vertex_layout *layout;
    VkCommandBuffer cmd;  /* the open frame's, or NULL */
} vk_part;

static vk_part *part(seed_scene *s) { return s->gpu; }

static hfx_vertex_layout *seed_layout(hfx_device *dev) {
    const hfx_vertex_element e[3] = {
        {"POSITION0", VK_FORMAT_R32G32B32_SFLOAT, offsetof(seed_vertex, pos), 0, sizeof(seed_vertex)},
        {"NORMAL0", VK_FORMAT_R32G32B32_SFLOAT, offsetof(seed_vertex, normal), 0, sizeof(seed_vertex)},
        {"TEXCOORD0", VK_FORMAT_R32G32_SFLOAT, offsetof(seed_vertex, uv), 0, sizeof(seed_vertex)},
    };
    return hfx_vertex_layout_create(dev, e, 3);
}

int seed_gpu_open(seed_scene *s, int major, int minor) {
    (void)major, (void)minor;
    const char *why = NULL;
    vk_part *p = calloc(1, sizeof *p);
    if (!p) return 0;
    s->gpu = p;
    p->v = test_vk_create(s->width, s->height, &why);
    if (!p->v) test_skip(why ? why : "no Vulkan device");
    s->dev = test_vk_device(p->v);
    s->target = HFX_TARGET_SPIRV_VK;
    p->layout = seed_layout(s->dev);
    test_vk_target(p->v)->layout = p->layout;
    return p->layout != NULL;
}

/* Submits the open frame and reads the picture back. */
static void close_frame(seed_scene *s) {
    vk_part *p = part(s);
    if (!p->cmd) return;
    p->cmd = NULL;
    if (test_vk_end(p->v) != 0) seed_note(s, "submitting the frame failed");
}

void seed_gpu_close(seed_scene *s) {
    vk_part *p = part(s);
    if (!p) return;
    if (p->v) {
        close_frame(s);
        int messages = test_vk_messages(p->v);
        if (messages) fprintf(stderr, "FAIL: the validation layer sent %d messages\n", messages);
        if (messages) test_failed_++;
    }
    hfx_vertex_layout_destroy(p->layout);
    test_vk_destroy(p->v); /* destroys s->dev */
    s->dev = NULL;
    free(p);
}

void seed_set_culling(seed_scene *s, int on) {
    if (hfx_device_set_render_state_vk(s->dev, "CullMode", on ? 3 : 1) != HFX_OK) seed_note(s, "CullMode: %s", hfx_device_last_error(s->dev));
}

void seed_clear(seed_scene *s, rgba c) {
    close_frame(s);
    hfx_device_reset_render_states_vk(s->dev); /* XNA's defaults are D3D9's: LessEqual, cull CCW, opaque */
    const float clear[4] = {(float)c.r, (float)c.g, (float)c.b, (float)c.a};
    part(s)->cmd = test_vk_begin(part(s)->v, clear);
}

void seed_gpu_mesh_upload(seed_scene *s, seed_mesh *m) {
    test_vk_buffer *b = calloc(1, sizeof *b);
    if (!b || !test_vk_buffer_make(part(s)->v, m->v, (size_t)m->count * sizeof *m->v, b)) seed_note(s, "no vertex buffer");
    m->gpu = b;
}

void seed_gpu_mesh_free(seed_scene *s, seed_mesh *m) {
    close_frame(s);
    if (m->gpu) test_vk_buffer_free(part(s)->v, m->gpu);
    free(m->gpu);
    m->gpu = NULL;
}

int seed_gpu_set_texture(seed_scene *s, hfx_param *p, const seed_texture *t) {
    (void)s;
    const test_vk_texture *tex = t->gpu;
    return hfx_param_set_texture_vk(p, tex ? tex->view : VK_NULL_HANDLE, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void seed_gpu_read(seed_scene *s, int x, int y, unsigned char rgba[4]) {
    close_frame(s);
    memcpy(rgba, test_vk_pixel(part(s)->v, x, y), 4);
}

int seed_gpu_write_png(seed_scene *s, const char *path) {
    close_frame(s);
    return test_vk_write_png(part(s)->v, path);
}

/* XNA's BlendState.Additive, set before the second pass's Apply as a game does. */
static void additive(seed_scene *s) {
    hfx_device_set_render_state_vk(s->dev, "AlphaBlendEnable", 1);
    hfx_device_set_render_state_vk(s->dev, "SrcBlend", 2);
    hfx_device_set_render_state_vk(s->dev, "DestBlend", 2);
    hfx_device_set_render_state_vk(s->dev, "BlendOp", 1);
}

static int draw_pass(seed_scene *s, hfx_pass *pass, const seed_mesh *m) {
    vk_part *p = part(s);
    if (hfx_pass_apply_vk(pass, p->cmd, test_vk_target(p->v)) != HFX_OK) {
        seed_note(s, "applying pass '%s': %s", hfx_pass_name(pass), hfx_device_last_error(s->dev));
        return 0;
    }
    VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(p->cmd, 0, 1, &((test_vk_buffer *)m->gpu)->buffer, &zero);
    vkCmdDraw(p->cmd, (uint32_t)m->count, 1, 0, 0);
    return 1;
}

int seed_draw(seed_scene *s, hfx_effect *fx, const char *technique, const seed_mesh *m, seed_blend blend) {
    if (!fx || !m || !m->gpu) return 0;
    hfx_technique *t = technique ? hfx_effect_technique(fx, technique) : hfx_effect_current_technique(fx);
    if (!t) {
        seed_note(s, "no technique '%s'", technique ? technique : "(current)");
        return 0;
    }
    hfx_effect_set_current_technique(fx, t);
    if (!part(s)->cmd) part(s)->cmd = test_vk_begin(part(s)->v, NULL);
    if (hfx_effect_begin(fx) != HFX_OK) seed_note(s, "hfx_effect_begin: %s", hfx_device_last_error(s->dev));
    int drawn = 0;
    for (size_t i = 0; i < hfx_technique_pass_count(t); i++) {
        if (blend == SEED_BLEND_ADD_AFTER_FIRST && i == 1) additive(s);
        drawn += draw_pass(s, hfx_technique_pass(t, i), m);
    }
    if (hfx_effect_end(fx) != HFX_OK) seed_note(s, "hfx_effect_end: %s", hfx_device_last_error(s->dev));
    return drawn;
}

seed_texture seed_texture_make(seed_scene *s, int width, int height, const unsigned char *texels) {
    seed_texture t = {width, height, texels, 0, NULL};
    test_vk_texture *tex = calloc(1, sizeof *tex);
    if (!tex || !test_vk_texture_make(part(s)->v, width, height, texels, tex)) seed_note(s, "no texture");
    t.gpu = tex;
    return t;
}

void seed_texture_free(seed_scene *s, seed_texture *t) {
    close_frame(s);
    if (t->gpu) test_vk_texture_free(part(s)->v, t->gpu);
    free(t->gpu);
    t->gpu = NULL;
}
