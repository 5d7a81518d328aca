/* bench_vk_apply.c: CPU cost of setting N of 100 float4 parameters and hfx_pass_apply_vk, against
 * raw Vulkan doing the same work, in the same run on the same lavapipe device. The raw loop is
 * what a hand-written renderer pays per draw for the same shader: the changed values into its copy
 * of the uniform block, that block into a new slice of a persistently mapped ring (its one buffer
 * write), then bind the pipeline, set viewport and scissor, and bind the descriptor set with the
 * slice's dynamic offset. Both record into a command buffer that is never submitted (reset every
 * 1000 draws), so only the CPU side is measured. The pixel shader reads every parameter against
 * an interpolated value (s = s * t + p_k), so no preshader takes the parameters off the GPU.
 *
 *   ./bench_vk_apply [ITER]          N = 1, 10, 100: this thread's CPU time and user-space
 *       instructions (perf_event_open) per Apply, best of five rounds after one not kept
 *   ./bench_vk_apply ITER LOOP N     one loop alone, LOOP = hfx | raw | floor, for callgrind
 *       (valgrind --tool=callgrind --toggle-collect=run_hfx, or run_raw: instructions x ITER). */
#define _DEFAULT_SOURCE /* syscall, for bench.h's instruction counter */
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
    uint8_t *map, *image;
    uint32_t at[PARAMS]; /* byte offset of p_k in the block */
    uint32_t used, size, align;
} raw_loop;

static char *effect_source(void) {
    size_t cap = 64 * PARAMS + 512, n = 0;
    char *s = malloc(cap);
    for (int i = 0; i < PARAMS; i++) n += (size_t)snprintf(s + n, cap - n, "float4 p%d;\n", i);
    n += (size_t)snprintf(s + n, cap - n, "void VS(float4 p : POSITION, out float4 o : POSITION, out float4 t : TEXCOORD0)"
                                          " { o = p; t = p; }\n"
                                          "float4 PS(float4 t : TEXCOORD0) : COLOR { float4 s = 0;");
    for (int i = 0; i < PARAMS; i++) n += (size_t)snprintf(s + n, cap - n, " s = s * t + p%d;", i);
    snprintf(s + n, cap - n, " return s; }\ntechnique T { pass P { VertexShader = compile vs_3_0 VS(); "
                             "PixelShader = compile ps_3_0 PS(); } }\n");
    return s;
}

static void begin_cmd(VkCommandBuffer cmd, const hfx_vk_target *t) {
    (void)t;
    vkResetCommandBuffer(cmd, 0);
    VkCommandBufferBeginInfo bi = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    vkBeginCommandBuffer(cmd, &bi);
}

static void run_hfx(test_vk *v, VkCommandBuffer cmd, hfx_effect *fx, hfx_param **params, int n, int iter) {
    hfx_pass *pass = hfx_technique_pass(hfx_effect_current_technique(fx), 0);
    const hfx_vk_target *t = test_vk_target(v);
    float value[4] = {0, 0, 0, 1};
    for (int i = 0; i < iter; i++) {
        if (i % BATCH == 0) {
            hfx_device_begin_frame_vk(test_vk_device(v));
            begin_cmd(cmd, t);
        }
        value[0] = (float)i;
        for (int k = 0; k < n; k++) hfx_param_set_floats(params[k], value, 4);
        hfx_pass_apply_vk(pass, cmd, t);
    }
}

/* The floor of an API of hfx's shape (one call per parameter set, one per Apply): the raw loop
 * plus those calls into functions that do nothing. */
static __attribute__((noinline)) int empty_set(const void *p, const float *v, size_t n) {
    __asm__ volatile("" : : "r"(p), "r"(v), "r"(n) : "memory");
    return 0;
}
static __attribute__((noinline)) int empty_apply(const void *p, VkCommandBuffer cmd, const hfx_vk_target *t) {
    __asm__ volatile("" : : "r"(p), "r"(cmd), "r"(t) : "memory");
    return 0;
}

static void run_raw(test_vk *v, VkCommandBuffer cmd, raw_loop *r, int n, int iter, int floor) {
    const hfx_vk_target *t = test_vk_target(v);
    float value[4] = {0, 0, 0, 1};
    VkViewport vp = {0, 0, (float)t->width, (float)t->height, 0, 1};
    VkRect2D sc = {{0, 0}, {t->width, t->height}};
    for (int i = 0; i < iter; i++) {
        if (i % BATCH == 0) {
            r->used = 0;
            begin_cmd(cmd, t);
        }
        value[0] = (float)i;
        for (int k = 0; k < n; k++) memcpy(r->image + r->at[k], value, 16);
        for (int k = 0; floor && k < n; k++) empty_set(r->image + r->at[k], value, 4);
        if (floor) empty_apply(r, cmd, t);
        uint32_t offset = r->used;
        memcpy(r->map + offset, r->image, r->size);
        r->used += (r->size + r->align - 1) & ~(r->align - 1);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, r->pipeline);
        vkCmdSetViewport(cmd, 0, 1, &vp);
        vkCmdSetScissor(cmd, 0, 1, &sc);
        vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, r->prog->layout, 0, 1, &r->set, 1, &offset);
    }
}

/* The hand-written loop's own ring and descriptor set; program and pipeline as hfx made them. */
static int raw_setup(test_vk *v, hfx_effect *fx, raw_loop *r) {
    hfx_device *dev = test_vk_device(v);
    memset(r, 0, sizeof *r);
    r->prog = &fx->sh->vk->programs[0];
    r->pipeline = dev->vk->psos[0].pipeline;
    r->size = r->prog->block_size;
    if (r->prog->regs_at < 0 || !(r->image = calloc(1, r->size))) return 0;
    for (int k = 0; k < PARAMS; k++) r->at[k] = (uint32_t)r->prog->regs_at + 16 * r->prog->slots[k].reg;
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

/* Per Apply: this thread's CPU time (ns) and user-space instructions, best of ROUNDS after one not kept. */
enum { ROUNDS = 5 };
typedef struct figure {
    double ns, instructions;
} figure;

static figure best_of(test_vk *v, VkCommandBuffer cmd, hfx_effect *fx, hfx_param **params, raw_loop *r, int n, int iter,
                      int counter, int floor) {
    figure best = {1e30, 1e30};
    for (int round = 0; round <= ROUNDS; round++) {
        uint64_t i0 = instructions_read(counter);
        double t0 = thread_now();
        if (fx) run_hfx(v, cmd, fx, params, n, iter);
        else run_raw(v, cmd, r, n, iter, floor);
        double t = thread_now() - t0;
        uint64_t i = instructions_read(counter) - i0;
        if (round == 0) continue;
        if (1e9 * t / iter < best.ns) best.ns = 1e9 * t / iter;
        if ((double)i / iter < best.instructions) best.instructions = (double)i / iter;
    }
    return best;
}

static void measure(test_vk *v, VkCommandBuffer cmd, hfx_effect *fx, hfx_param **params, raw_loop *r, int iter) {
    static const int ns[3] = {1, 10, 100};
    int counter = instructions_open();
    printf("set + hfx_pass_apply_vk against raw Vulkan (one buffer write and the binds), per Apply, best of %d rounds "
           "of %d (floor: raw plus a call per set and per Apply into functions that do nothing)\n%-8s %10s %10s %8s "
           "%12s %12s %8s %12s %8s\n", ROUNDS, iter, "changed", "hfx ns", "raw ns", "ratio", "hfx instr", "raw instr",
           "ratio", "floor instr", "ratio");
    for (int k = 0; k < 3; k++) {
        figure h = best_of(v, cmd, fx, params, r, ns[k], iter, counter, 0);
        figure w = best_of(v, cmd, NULL, NULL, r, ns[k], iter, counter, 0);
        figure f = best_of(v, cmd, NULL, NULL, r, ns[k], iter, counter, 1);
        printf("%-8d %10.1f %10.1f %7.3fx", ns[k], h.ns, w.ns, h.ns / w.ns);
        if (counter >= 0)
            printf(" %12.1f %12.1f %7.3fx %12.1f %7.3fx\n", h.instructions, w.instructions, h.instructions / w.instructions,
                   f.instructions, f.instructions / w.instructions);
        else printf(" %12s %12s %8s\n", "-", "-", "-");
    }
    if (counter >= 0) close(counter);
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
    else if (argc > 3) run_raw(v, cmd, &r, atoi(argv[3]), iter, !strcmp(argv[2], "floor"));
    else measure(v, cmd, fx, params, &r, iter);
    printf("pipelines created: %zu\n", hfx_device_pipelines_created_vk(test_vk_device(v)));
    vkDestroyDescriptorPool(fx->dev->vk->device, r.pool, NULL);
    vkDestroyCommandPool(fx->dev->vk->device, pool, NULL);
    test_vk_buffer_free(v, &r.ring);
    free(r.image);
    hfx_effect_destroy(fx);
    hfx_vertex_layout_destroy(layout);
    test_vk_destroy(v);
    free(src);
    hfx_free(errors);
    return 0;
}
