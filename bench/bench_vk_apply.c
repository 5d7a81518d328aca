/* bench_vk_apply.c: CPU cost of setting N of 100 float4 parameters and hfx_pass_apply_vk, against
 * a hand-written Vulkan loop doing the same work, in the same run on the same lavapipe device:
 * write the changed values into the program's uniform block, copy the block into a new slice
 * of a persistently mapped ring, bind the pipeline, set viewport and scissor, and bind the same
 * descriptor set with the slice's dynamic offset. Both record into a command buffer that is
 * never submitted (reset every 1000 draws), so only the CPU side is timed.
 *
 *   ./bench_vk_apply [ITER]          best of five rounds of ITER applies for N = 1, 10, 100 (wall
 *                                    clock: noisy on a shared machine)
 *   ./bench_vk_apply ITER LOOP N     one loop alone, LOOP = hfx | raw, for instruction counts, which
 *       are stable: valgrind --tool=callgrind with ITER 200 and 1200; the difference of the two
 *       totals / 1000 is the per-Apply count (setup cancels out). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "vk_context.h" /* first: the loader's prototypes for the hand-written loop */
#include "vk/vk.h"      /* hfx's internals, to borrow its program and pipeline */

#define PARAMS 100
#define BATCH 1000

typedef struct raw_loop {
    const vk_program *prog;
    VkPipeline pipeline;
    VkDescriptorPool pool;
    VkDescriptorSet set;
    test_vk_buffer ring;
    uint8_t *map, image[PARAMS * 16];
    uint32_t used, size, align;
} raw_loop;

static char *effect_source(void) {
    size_t cap = 64 * PARAMS + 512, n = 0;
    char *s = malloc(cap);
    for (int i = 0; i < PARAMS; i++) n += (size_t)snprintf(s + n, cap - n, "float4 p%d;\n", i);
    n += (size_t)snprintf(s + n, cap - n, "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                                          "float4 PS() : COLOR { return 0");
    for (int i = 0; i < PARAMS; i++) n += (size_t)snprintf(s + n, cap - n, " + p%d", i);
    snprintf(s + n, cap - n, "; }\ntechnique T { pass P { VertexShader = compile vs_3_0 VS(); "
                             "PixelShader = compile ps_3_0 PS(); } }\n");
    return s;
}

static void begin_cmd(VkCommandBuffer cmd, const hfx_vk_target *t) {
    (void)t;
    vkResetCommandBuffer(cmd, 0);
    VkCommandBufferBeginInfo bi = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    vkBeginCommandBuffer(cmd, &bi);
}

static double run_hfx(test_vk *v, VkCommandBuffer cmd, hfx_effect *fx, hfx_param **params, int n, int iter) {
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    const hfx_vk_target *t = test_vk_target(v);
    float value[4] = {0, 0, 0, 1};
    double start = now();
    for (int i = 0; i < iter; i++) {
        if (i % BATCH == 0) {
            hfx_device_begin_frame_vk(test_vk_device(v));
            begin_cmd(cmd, t);
        }
        value[0] = (float)i;
        for (int k = 0; k < n; k++) hfx_param_set_floats(params[k], value, 4);
        hfx_pass_apply_vk(pass, cmd, t);
    }
    return now() - start;
}

static double run_raw(test_vk *v, VkCommandBuffer cmd, raw_loop *r, int n, int iter) {
    const hfx_vk_target *t = test_vk_target(v);
    float value[4] = {0, 0, 0, 1};
    VkViewport vp = {0, 0, (float)t->width, (float)t->height, 0, 1};
    VkRect2D sc = {{0, 0}, {t->width, t->height}};
    double start = now();
    for (int i = 0; i < iter; i++) {
        if (i % BATCH == 0) {
            r->used = 0;
            begin_cmd(cmd, t);
        }
        value[0] = (float)i;
        for (int k = 0; k < n; k++) memcpy(r->image + r->prog->regs_at + 16 * k, value, 16);
        uint32_t offset = r->used;
        memcpy(r->map + offset, r->image, r->size);
        r->used += (r->size + r->align - 1) & ~(r->align - 1);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, r->pipeline);
        vkCmdSetViewport(cmd, 0, 1, &vp);
        vkCmdSetScissor(cmd, 0, 1, &sc);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, r->prog->layout, 0, 1, &r->set, 1, &offset);
    }
    return now() - start;
}

/* The hand-written loop's own ring and descriptor set; program and pipeline as hfx made them. */
static int raw_setup(test_vk *v, hfx_effect *fx, raw_loop *r) {
    hfx_device *dev = test_vk_device(v);
    memset(r, 0, sizeof *r);
    r->prog = &fx->sh->vk->programs[0];
    r->pipeline = dev->vk->psos[0].pipeline;
    r->size = r->prog->block_size;
    r->align = (uint32_t)dev->vk->ubo_align;
    VkDevice d = dev->vk->device;
    size_t ring = (size_t)BATCH * ((r->size + r->align - 1) & ~(r->align - 1));
    if (!test_vk_buffer_make(v, NULL, ring, &r->ring)) return 0;
    if (vkMapMemory(d, r->ring.memory, 0, ring, 0, (void **)&r->map) != VK_SUCCESS) return 0;
    VkDescriptorPoolSize ps = {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1};
    VkDescriptorPoolCreateInfo pi = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, .maxSets = 1,
                                     .poolSizeCount = 1, .pPoolSizes = &ps};
    if (vkCreateDescriptorPool(d, &pi, NULL, &r->pool) != VK_SUCCESS) return 0;
    VkDescriptorSetAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO, .descriptorPool = r->pool,
                                      .descriptorSetCount = 1, .pSetLayouts = &r->prog->set_layout};
    if (vkAllocateDescriptorSets(d, &ai, &r->set) != VK_SUCCESS) return 0;
    VkDescriptorBufferInfo bi = {r->ring.buffer, 0, r->size};
    VkWriteDescriptorSet w = {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, .dstSet = r->set, .dstBinding = 0,
                              .descriptorCount = 1, .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                              .pBufferInfo = &bi};
    vkUpdateDescriptorSets(d, 1, &w, 0, NULL);
    return 1;
}

static VkCommandBuffer command_buffer(test_vk *v, VkCommandPool *pool) {
    hfx_device *dev = test_vk_device(v);
    VkCommandPoolCreateInfo pi = {.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                  .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT};
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    if (vkCreateCommandPool(dev->vk->device, &pi, NULL, pool) != VK_SUCCESS) return cmd;
    VkCommandBufferAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, .commandPool = *pool,
                                      .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY, .commandBufferCount = 1};
    vkAllocateCommandBuffers(dev->vk->device, &ai, &cmd);
    return cmd;
}

static void measure(test_vk *v, VkCommandBuffer cmd, hfx_effect *fx, hfx_param **params, raw_loop *r, int iter) {
    static const int ns[3] = {1, 10, 100};
    for (int k = 0; k < 3; k++) {
        double best_hfx = 1e30, best_raw = 1e30;
        for (int round = 0; round < 5; round++) {
            double h = run_hfx(v, cmd, fx, params, ns[k], iter), w = run_raw(v, cmd, r, ns[k], iter);
            if (h < best_hfx) best_hfx = h;
            if (w < best_raw) best_raw = w;
        }
        printf("N = %3d: hfx %7.1f ns/apply, hand-written %7.1f ns/apply, ratio %.2f\n", ns[k], 1e9 * best_hfx / iter,
               1e9 * best_raw / iter, best_hfx / best_raw);
    }
}

int main(int argc, char **argv) {
    int iter = argc > 1 ? atoi(argv[1]) : 20000;
    setenv("HFX_VK_NO_VALIDATION", "1", 1); /* the layer would time itself */
    const char *why = NULL;
    test_vk *v = test_vk_create(64, 64, &why);
    if (!v) return printf("no Vulkan device: %s\n", why ? why : "?"), 0;
    hfx_vertex_element e = {"POSITION0", VK_FORMAT_R32G32B32_SFLOAT, 0, 0, 12};
    hfx_vertex_layout *layout = hfx_vertex_layout_create(test_vk_device(v), &e, 1);
    test_vk_target(v)->layout = layout;
    char *src = effect_source(), *errors = NULL;
    hfx_effect *fx = hfx_effect_load_memory(test_vk_device(v), src, strlen(src), "bench.fx", NULL, &errors);
    if (!fx) return printf("load: %s\n", errors ? errors : "?"), 1;
    hfx_param *params[PARAMS];
    for (int i = 0; i < PARAMS; i++) {
        char name[16];
        snprintf(name, sizeof name, "p%d", i);
        params[i] = hfx_effect_param(fx, name);
    }
    VkCommandPool pool;
    VkCommandBuffer cmd = command_buffer(v, &pool);
    raw_loop r;
    run_hfx(v, cmd, fx, params, 1, 1); /* makes the pipeline the raw loop borrows */
    if (!raw_setup(v, fx, &r)) return printf("raw setup failed\n"), 1;
    if (argc > 3 && !strcmp(argv[2], "hfx")) run_hfx(v, cmd, fx, params, atoi(argv[3]), iter);
    else if (argc > 3) run_raw(v, cmd, &r, atoi(argv[3]), iter);
    else measure(v, cmd, fx, params, &r, iter);
    printf("pipelines created: %zu\n", hfx_device_pipelines_created_vk(test_vk_device(v)));
    vkDestroyDescriptorPool(fx->dev->vk->device, r.pool, NULL);
    vkDestroyCommandPool(fx->dev->vk->device, pool, NULL);
    test_vk_buffer_free(v, &r.ring);
    hfx_effect_destroy(fx);
    hfx_vertex_layout_destroy(layout);
    test_vk_destroy(v);
    free(src);
    hfx_free(errors);
    return 0;
}
