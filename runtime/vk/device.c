/* device.c: the Vulkan device: its entry points (loaded through the application's
 * vkGetInstanceProcAddr), the frames in flight with their uniform rings and descriptor pools,
 * vertex layouts, and destruction. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "vk/vk.h"

enum { POOL_SETS = 256 };

int hfx_vk_fail(hfx_device *dev, VkResult r, const char *what) {
    if (r == VK_ERROR_OUT_OF_HOST_MEMORY || r == VK_ERROR_OUT_OF_DEVICE_MEMORY)
        return hfx_rt_fail(dev, HFX_ERR_MEMORY, "%s: out of memory (VkResult %d)", what, (int)r);
    return hfx_rt_fail(dev, HFX_ERR_VULKAN, "%s failed (VkResult %d)", what, (int)r);
}

/* Every entry point, or the name of the first one missing. */
static const char *load_functions(hfx_vk_fns *f, VkInstance inst, VkDevice device) {
#define HFX_VK_INST_(name) \
    if (!(f->name = (PFN_vk##name)f->GetInstanceProcAddr(inst, "vk" #name))) return "vk" #name;
    HFX_VK_INSTANCE_FUNCS(HFX_VK_INST_)
#undef HFX_VK_INST_
#define HFX_VK_DEV_(name) \
    if (!(f->name = (PFN_vk##name)f->GetDeviceProcAddr(device, "vk" #name))) return "vk" #name;
    HFX_VK_DEVICE_FUNCS(HFX_VK_DEV_)
#undef HFX_VK_DEV_
    return NULL;
}

int hfx_vk_memory_type(const struct hfx_vk_device *vk, uint32_t bits, VkMemoryPropertyFlags want) {
    for (uint32_t i = 0; i < vk->memory.memoryTypeCount; i++)
        if ((bits & (1u << i)) && (vk->memory.memoryTypes[i].propertyFlags & want) == want) return (int)i;
    return -1;
}

int hfx_vk_chunk_make(hfx_device *dev, VkDeviceSize size, VkBufferUsageFlags usage, vk_chunk *c) {
    struct hfx_vk_device *vk = dev->vk;
    memset(c, 0, sizeof *c);
    VkBufferCreateInfo bi = {.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, .size = size, .usage = usage};
    VkResult r = vk->fn.CreateBuffer(vk->device, &bi, NULL, &c->buffer);
    if (r != VK_SUCCESS) return hfx_vk_fail(dev, r, "vkCreateBuffer");
    VkMemoryRequirements req;
    vk->fn.GetBufferMemoryRequirements(vk->device, c->buffer, &req);
    int type = hfx_vk_memory_type(vk, req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    if (type < 0) {
        hfx_vk_chunk_free(dev, c);
        return hfx_rt_fail(dev, HFX_ERR_VULKAN, "the device has no host-visible, coherent memory for uniform buffers");
    }
    VkMemoryAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, .allocationSize = req.size,
                               .memoryTypeIndex = (uint32_t)type};
    void *map = NULL;
    if ((r = vk->fn.AllocateMemory(vk->device, &ai, NULL, &c->memory)) != VK_SUCCESS ||
        (r = vk->fn.BindBufferMemory(vk->device, c->buffer, c->memory, 0)) != VK_SUCCESS ||
        (r = vk->fn.MapMemory(vk->device, c->memory, 0, VK_WHOLE_SIZE, 0, &map)) != VK_SUCCESS) {
        hfx_vk_chunk_free(dev, c);
        return hfx_vk_fail(dev, r, "allocating a uniform buffer");
    }
    c->map = map;
    c->size = size;
    return HFX_OK;
}

void hfx_vk_chunk_free(hfx_device *dev, vk_chunk *c) {
    struct hfx_vk_device *vk = dev->vk;
    if (c->map) vk->fn.UnmapMemory(vk->device, c->memory);
    if (c->buffer) vk->fn.DestroyBuffer(vk->device, c->buffer, NULL);
    if (c->memory) vk->fn.FreeMemory(vk->device, c->memory, NULL);
    memset(c, 0, sizeof *c);
}

/* The next chunk of the frame's ring, made (twice as large as the last) when it has none. */
static int next_chunk(hfx_device *dev, vk_frame *f, VkDeviceSize need) {
    if (f->used && f->chunk + 1 < f->chunk_count && f->chunks[f->chunk + 1].size >= need) {
        f->chunk++, f->used = 0;
        return HFX_OK;
    }
    VkDeviceSize size = f->chunk_count ? 2 * f->chunks[f->chunk_count - 1].size : dev->vk->first_chunk;
    while (size < need) size *= 2;
    vk_chunk *grown = realloc(f->chunks, (f->chunk_count + 1) * sizeof *grown);
    if (!grown) return hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
    f->chunks = grown;
    int rc = hfx_vk_chunk_make(dev, size, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, &f->chunks[f->chunk_count]);
    if (rc) return rc;
    f->chunk = f->chunk_count++;
    f->used = 0;
    return HFX_OK;
}

int hfx_vk_slice(hfx_device *dev, uint32_t size, VkBuffer *buffer, uint32_t *offset, uint8_t **map) {
    struct hfx_vk_device *vk = dev->vk;
    vk_frame *f = &vk->frames[vk->frame];
    VkDeviceSize at = (f->used + vk->ubo_align - 1) & ~(vk->ubo_align - 1);
    if (!f->chunk_count || at + size > f->chunks[f->chunk].size) {
        int rc = next_chunk(dev, f, size);
        if (rc) return rc;
        at = 0;
    }
    vk_chunk *c = &f->chunks[f->chunk];
    f->used = at + size;
    *buffer = c->buffer;
    *offset = (uint32_t)at;
    *map = c->map + at;
    return HFX_OK;
}

static int new_pool(hfx_device *dev, vk_frame *f) {
    struct hfx_vk_device *vk = dev->vk;
    VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, POOL_SETS},
                                     {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4 * POOL_SETS}};
    VkDescriptorPoolCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, .maxSets = POOL_SETS,
                                     .poolSizeCount = 2, .pPoolSizes = sizes};
    VkDescriptorPool *grown = realloc(f->pools, (f->pool_count + 1) * sizeof *grown);
    if (!grown) return hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
    f->pools = grown;
    VkResult r = vk->fn.CreateDescriptorPool(vk->device, &ci, NULL, &f->pools[f->pool_count]);
    if (r != VK_SUCCESS) return hfx_vk_fail(dev, r, "vkCreateDescriptorPool");
    f->pool = f->pool_count++;
    return HFX_OK;
}

/* From the frame's pool; a full pool moves on to the next one (made when there is none). */
int hfx_vk_descriptor_set(hfx_device *dev, VkDescriptorSetLayout layout, VkDescriptorSet *set) {
    struct hfx_vk_device *vk = dev->vk;
    vk_frame *f = &vk->frames[vk->frame];
    for (int tries = 0; tries < 3; tries++) {
        if (f->pool_count) {
            VkDescriptorSetAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                              .descriptorPool = f->pools[f->pool], .descriptorSetCount = 1,
                                              .pSetLayouts = &layout};
            VkResult r = vk->fn.AllocateDescriptorSets(vk->device, &ai, set);
            if (r == VK_SUCCESS) return HFX_OK;
            if (r != VK_ERROR_OUT_OF_POOL_MEMORY && r != VK_ERROR_FRAGMENTED_POOL)
                return hfx_vk_fail(dev, r, "vkAllocateDescriptorSets");
        }
        int rc = f->pool + 1 < f->pool_count ? (f->pool++, HFX_OK) : new_pool(dev, f);
        if (rc) return rc;
    }
    return hfx_rt_fail(dev, HFX_ERR_VULKAN, "vkAllocateDescriptorSets: no pool could hold the set");
}

int hfx_device_begin_frame_vk(hfx_device *dev) {
    if (!dev) return HFX_ERR_NULL;
    struct hfx_vk_device *vk = dev->vk;
    if (!vk) return hfx_rt_fail(dev, HFX_ERR_NOT_FOUND, "hfx_device_begin_frame_vk: not a Vulkan device");
    vk->frame = (uint32_t)(vk->serial % vk->frame_count);
    vk->serial++;
    vk_frame *f = &vk->frames[vk->frame];
    for (uint32_t i = 0; i < f->pool_count; i++) {
        VkResult r = vk->fn.ResetDescriptorPool(vk->device, f->pools[i], 0);
        if (r != VK_SUCCESS) return hfx_vk_fail(dev, r, "vkResetDescriptorPool");
    }
    f->pool = 0;
    f->chunk = 0;
    f->used = 0;
    return HFX_OK;
}

int hfx_device_end_frame_vk(hfx_device *dev) {
    if (!dev) return HFX_ERR_NULL;
    if (!dev->vk) return hfx_rt_fail(dev, HFX_ERR_NOT_FOUND, "hfx_device_end_frame_vk: not a Vulkan device");
    return HFX_OK; /* coherent memory: nothing to flush */
}

void hfx_device_writes_vk(const hfx_device *dev, size_t *uniform_slices, size_t *descriptor_sets) {
    if (uniform_slices) *uniform_slices = dev && dev->vk ? dev->vk->slices_written : 0;
    if (descriptor_sets) *descriptor_sets = dev && dev->vk ? dev->vk->sets_written : 0;
}

size_t hfx_device_pipelines_created_vk(const hfx_device *dev) { return dev && dev->vk ? dev->vk->psos_made : 0; }

static void frames_free(hfx_device *dev) {
    struct hfx_vk_device *vk = dev->vk;
    for (uint32_t i = 0; i < VK_MAX_FRAMES; i++) {
        vk_frame *f = &vk->frames[i];
        for (uint32_t c = 0; c < f->chunk_count; c++) hfx_vk_chunk_free(dev, &f->chunks[c]);
        for (uint32_t p = 0; p < f->pool_count; p++) vk->fn.DestroyDescriptorPool(vk->device, f->pools[p], NULL);
        free(f->chunks);
        free(f->pools);
    }
}

void hfx_vk_device_destroy(hfx_device *dev) {
    if (dev->vk) {
        hfx_vk_pipelines_free(dev);
        hfx_vk_samplers_free(dev);
        frames_free(dev);
        hfx_vk_chunk_free(dev, &dev->vk->zero);
        hfx_vk_validator_free(dev->vk);
        hfx_vk_defaults_free(dev);
        free(dev->vk);
    }
    free(dev);
}

static void read_limits(struct hfx_vk_device *vk, const hfx_vulkan_desc *d) {
    VkPhysicalDeviceProperties props;
    vk->fn.GetPhysicalDeviceProperties(vk->phys, &props);
    vk->fn.GetPhysicalDeviceMemoryProperties(vk->phys, &vk->memory);
    vk->ubo_align = props.limits.minUniformBufferOffsetAlignment ? props.limits.minUniformBufferOffsetAlignment : 256;
    const VkPhysicalDeviceLimits *lim = &props.limits;
    vk->max_attributes = lim->maxVertexInputAttributes;
    uint32_t comps = lim->maxVertexOutputComponents < lim->maxFragmentInputComponents ? lim->maxVertexOutputComponents
                                                                                       : lim->maxFragmentInputComponents;
    vk->max_varyings = comps / 4;
    vk->max_colors = lim->maxFragmentOutputAttachments < lim->maxColorAttachments ? lim->maxFragmentOutputAttachments
                                                                                  : lim->maxColorAttachments;
    const VkPhysicalDeviceFeatures *feat = d->enabled_features;
    vk->max_anisotropy = feat && feat->samplerAnisotropy ? props.limits.maxSamplerAnisotropy : 0.0f;
    vk->fill_modes = feat && feat->fillModeNonSolid;
    vk->mirror_once = d->sampler_mirror_clamp_to_edge != VK_FALSE;
    vk->custom_border = d->custom_border_colors != VK_FALSE;
    vk->frame_count = d->frames_in_flight;
    vk->first_chunk = d->uniform_bytes_per_frame ? d->uniform_bytes_per_frame : (VkDeviceSize)1 << 20;
}

static const char *check_desc(const hfx_vulkan_desc *d) {
    if (!d) return "hfx_device_create_vulkan: NULL description";
    if (!d->instance || !d->physical_device || !d->device || !d->get_instance_proc_addr)
        return "hfx_device_create_vulkan: the instance, physical device, device and vkGetInstanceProcAddr are required";
    if (d->frames_in_flight < 1 || d->frames_in_flight > VK_MAX_FRAMES)
        return "hfx_device_create_vulkan: frames_in_flight must be 1..8";
    return NULL;
}

static hfx_device *create_failed(hfx_device *dev, const char *msg, char **error) {
    if (error) *error = hfx_rt_strdup(msg ? msg : dev->error);
    if (dev) hfx_vk_device_destroy(dev);
    return NULL;
}

hfx_device *hfx_device_create_vulkan(const hfx_vulkan_desc *d, char **error) {
    if (error) *error = NULL;
    const char *bad = check_desc(d);
    if (bad) return create_failed(NULL, bad, error);
    hfx_device *dev = calloc(1, sizeof *dev);
    if (!dev || !(dev->vk = calloc(1, sizeof *dev->vk))) {
        free(dev);
        return create_failed(NULL, "out of memory", error);
    }
    dev->be = &hfx_vk_backend;
    struct hfx_vk_device *vk = dev->vk;
    vk->instance = d->instance, vk->phys = d->physical_device, vk->device = d->device;
    vk->fn.GetInstanceProcAddr = d->get_instance_proc_addr;
    const char *missing = load_functions(&vk->fn, d->instance, d->device);
    if (missing) {
        hfx_rt_fail(dev, HFX_ERR_VULKAN, "Vulkan entry point %s is missing", missing);
        return create_failed(dev, NULL, error);
    }
    read_limits(vk, d);
    if (hfx_vk_validator_make(vk)) return create_failed(dev, "out of memory", error);
    vk->last_pso = UINT32_MAX;
    hfx_rs_defaults(dev->rs);
    if (hfx_vk_chunk_make(dev, 64, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, &vk->zero)) return create_failed(dev, NULL, error);
    static const float zero_one[4] = {0, 0, 0, 1}; /* what GL's disabled attribute arrays read */
    memcpy(vk->zero.map, zero_one, sizeof zero_one);
    if (d->queue && hfx_vk_defaults_make(dev, d->queue, d->queue_family)) return create_failed(dev, NULL, error);
    return dev;
}

/* "POSITION" and "position0" are both POSITION0, as the compiler spells attribute semantics. */
static int canonical_semantic(const char *s, char out[24]) {
    size_t n = strlen(s);
    if (n == 0 || n > 20) return 0;
    for (size_t i = 0; i < n; i++) out[i] = (char)((s[i] >= 'a' && s[i] <= 'z') ? s[i] - 32 : s[i]);
    out[n] = 0;
    if (out[n - 1] < '0' || out[n - 1] > '9') out[n] = '0', out[n + 1] = 0;
    return 1;
}

hfx_vertex_layout *hfx_vertex_layout_create(hfx_device *dev, const hfx_vertex_element *e, size_t count) {
    if (!dev || !dev->vk || (!e && count)) return NULL;
    if (count > VK_MAX_LAYOUT_ELEMENTS) {
        hfx_rt_fail(dev, HFX_ERR_COUNT, "hfx_vertex_layout_create: at most %d elements", VK_MAX_LAYOUT_ELEMENTS);
        return NULL;
    }
    hfx_vertex_layout *l = calloc(1, sizeof *l);
    if (!l) return NULL;
    l->dev = dev;
    l->count = count;
    for (size_t i = 0; i < count; i++) {
        l->e[i] = e[i];
        if (!e[i].semantic || !canonical_semantic(e[i].semantic, l->semantics[i]) || e[i].binding >= VK_ZERO_BINDING) {
            hfx_rt_fail(dev, HFX_ERR_TYPE, "hfx_vertex_layout_create: element %zu needs a semantic and a binding below %d",
                        i, VK_ZERO_BINDING);
            free(l);
            return NULL;
        }
        l->e[i].semantic = l->semantics[i];
    }
    return l;
}

void hfx_vertex_layout_destroy(hfx_vertex_layout *l) { free(l); }

int hfx_device_set_render_state_vk(hfx_device *dev, const char *state, int value) {
    if (!dev || !state) return HFX_ERR_NULL;
    const hfx_state_info *info = hfx_state_lookup(state);
    if (!dev->vk) return hfx_rt_fail(dev, HFX_ERR_NOT_FOUND, "hfx_device_set_render_state_vk: not a Vulkan device");
    if (!info || info->scope != HFX_SS_RENDER || info->id >= HFX_ST_COUNT_)
        return hfx_rt_fail(dev, HFX_ERR_NOT_FOUND, "'%s' is not a render state", state);
    hfx_fx_state st;
    memset(&st, 0, sizeof st);
    st.id = info->id, st.kind = HFX_FX_VALUE_INT, st.i = value, st.count = 1;
    hfx_rs_resolve(NULL, &st, &dev->rs[info->id]);
    return HFX_OK;
}

int hfx_device_reset_render_states_vk(hfx_device *dev) {
    if (!dev) return HFX_ERR_NULL;
    if (!dev->vk) return hfx_rt_fail(dev, HFX_ERR_NOT_FOUND, "hfx_device_reset_render_states_vk: not a Vulkan device");
    hfx_rs_defaults(dev->rs);
    return HFX_OK;
}
