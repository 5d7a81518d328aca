/* vk.h: the Vulkan back end's objects. The device keeps a table of entry points loaded through
 * the application's vkGetInstanceProcAddr (no link to a loader), a uniform ring and descriptor
 * pools per frame in flight, and caches of pipelines and samplers. An effect's shared part holds
 * one vk_program per compiled program (shader modules, layouts, the map of its uniform block);
 * each instance holds, per program, the block's bytes as its values make them. */
#ifndef HFX_RUNTIME_VK_H
#define HFX_RUNTIME_VK_H

#define VK_NO_PROTOTYPES
#include "hfx/hfx_vulkan.h"
#include "internal.h"

#define HFX_VK_INSTANCE_FUNCS(X) \
    X(GetDeviceProcAddr) X(GetPhysicalDeviceProperties) X(GetPhysicalDeviceMemoryProperties) \
    X(GetPhysicalDeviceFormatProperties)

#define HFX_VK_DEVICE_FUNCS(X) \
    X(CreateBuffer) X(DestroyBuffer) X(GetBufferMemoryRequirements) X(AllocateMemory) X(FreeMemory) \
    X(BindBufferMemory) X(MapMemory) X(UnmapMemory) X(CreateShaderModule) X(DestroyShaderModule) \
    X(CreateDescriptorSetLayout) X(DestroyDescriptorSetLayout) X(CreatePipelineLayout) \
    X(DestroyPipelineLayout) X(CreateGraphicsPipelines) X(DestroyPipeline) X(CreateSampler) \
    X(DestroySampler) X(CreateDescriptorPool) X(DestroyDescriptorPool) X(ResetDescriptorPool) \
    X(AllocateDescriptorSets) X(UpdateDescriptorSets) X(CmdBindPipeline) X(CmdBindDescriptorSets) \
    X(CmdBindVertexBuffers) X(CmdSetViewport) X(CmdSetScissor) X(CmdSetStencilReference) \
    X(CmdSetBlendConstants) X(CmdSetDepthBias) X(CreateImage) X(DestroyImage) X(GetImageMemoryRequirements) \
    X(BindImageMemory) X(CreateImageView) X(DestroyImageView) X(CreateCommandPool) X(DestroyCommandPool) \
    X(AllocateCommandBuffers) X(BeginCommandBuffer) X(EndCommandBuffer) X(CmdPipelineBarrier) \
    X(CmdClearColorImage) X(QueueSubmit) X(QueueWaitIdle)

typedef struct hfx_vk_fns {
    PFN_vkGetInstanceProcAddr GetInstanceProcAddr;
#define HFX_VK_FN_(name) PFN_vk##name name;
    HFX_VK_INSTANCE_FUNCS(HFX_VK_FN_)
    HFX_VK_DEVICE_FUNCS(HFX_VK_FN_)
#undef HFX_VK_FN_
} hfx_vk_fns;

/* A program reads at most 16 attributes (Vulkan's least maxVertexInputAttributes); a layout may
 * describe more, for the programs that read different ones. */
enum { VK_ZERO_BINDING = 15, VK_MAX_FRAMES = 8, VK_MAX_ATTRIBUTES = 16, VK_MAX_LAYOUT_ELEMENTS = 32 };

/* A host-visible, coherent buffer, mapped for its lifetime. */
typedef struct vk_chunk {
    VkBuffer buffer;
    VkDeviceMemory memory;
    uint8_t *map;
    VkDeviceSize size;
} vk_chunk;

/* One frame in flight: uniform chunks (the last one is being filled) and descriptor pools. */
typedef struct vk_frame {
    vk_chunk *chunks;
    uint32_t chunk_count, chunk;    /* chunk: the one being filled */
    VkDeviceSize used;              /* bytes of chunks[chunk] handed out */
    VkDescriptorPool *pools;
    uint32_t pool_count, pool;      /* pool: the one allocated from */
} vk_frame;

/* A render state block as pipeline state: the D3D values a pipeline depends on. */
typedef struct vk_states {
    int32_t cull, fill, zenable, zwrite, zfunc;
    int32_t blend, sep_alpha, src, dst, op, src_a, dst_a, op_a;
    int32_t write_mask[4];
    int32_t stencil, two_sided, s_fail[2], s_zfail[2], s_pass[2], s_func[2], s_mask, s_write;
    int32_t depth_bias, ms_mask;
} vk_states;

typedef struct vk_pso_key {
    const void *program;
    const hfx_vertex_layout *layout;
    VkRenderPass render_pass;
    uint32_t subpass, color_count, samples;
    VkFormat color[4], depth;
    vk_states st;
} vk_pso_key;

typedef struct vk_pso {
    uint64_t hash;
    vk_pso_key key;
    VkPipeline pipeline;
    int needs_zero;                 /* reads an attribute the layout lacks: bind VK_ZERO_BINDING */
} vk_pso;

/* A 1x1 image of (0, 0, 0, 1) per sampler dimension (HFX_FX_DIM_*), as D3D9 samples a stage
 * with no texture: what a sampler the application gave no texture reads (defaults.c). */
typedef struct vk_default_image {
    VkImage image;
    VkDeviceMemory memory;
    VkImageView view;
} vk_default_image;

typedef struct vk_sampler_entry {
    hfx_sampler_desc desc;
    VkSampler sampler;
} vk_sampler_entry;

struct hfx_vk_device {
    hfx_vk_fns fn;
    VkInstance instance;
    VkPhysicalDevice phys;
    VkDevice device;
    VkPhysicalDeviceMemoryProperties memory;
    VkDeviceSize ubo_align, first_chunk;
    uint32_t max_attributes, max_varyings, max_colors; /* vertex inputs, locations between the stages, pixel outputs */
    float max_anisotropy;           /* 0 unless the device was created with samplerAnisotropy */
    int fill_modes;                 /* fillModeNonSolid */
    uint32_t frame_count, frame;    /* frames in flight, the current one */
    uint64_t serial;                /* frames begun; 0: none yet */
    vk_frame frames[VK_MAX_FRAMES];
    vk_chunk zero;                  /* zeros for attributes the layout lacks */
    vk_pso *psos;
    uint32_t pso_count, pso_cap;
    size_t psos_made;               /* pipelines created, for hfx_device_pipelines_created_vk */
    size_t slices_written, sets_written; /* hfx_device_writes_vk */
    vk_pso_key last_key;            /* the last Apply's key and pipeline: most Applies repeat it */
    uint32_t last_pso;              /* index in psos, UINT32_MAX: none */
    /* Apply's short way (apply.c): while hfx_device.applied is set, that pass's render states are
     * what the device holds and last_pso is its pipeline for this program and target. */
    hfx_vk_target quick_target;     /* the target it was applied for */
    uint32_t quick_program;         /* and the program it chose */
    vk_sampler_entry *samplers;
    uint32_t sampler_count, sampler_cap;
    int mirror_once;                /* samplerMirrorClampToEdge */
    int custom_border;              /* VK_EXT_custom_border_color (without format) */
    struct spv_context_t *spirv;    /* SPIRV-Tools' validator for Vulkan 1.0 (program.c): every module passes it */
    vk_default_image defaults[4];   /* per hfx_fx_dim; none without hfx_vulkan_desc.queue */
};

struct hfx_vertex_layout {
    hfx_device *dev;
    size_t count;
    char semantics[VK_MAX_LAYOUT_ELEMENTS][24];
    hfx_vertex_element e[VK_MAX_LAYOUT_ELEMENTS];
};

/* How one leaf of the uniform block is filled from the effect's values. */
typedef struct vk_upload {
    uint32_t dst, src;              /* byte offset in the block; word offset in the values */
    uint32_t count, stride;         /* elements, and their stride in the block */
    uint16_t comps, cols;           /* components per column, columns (1 unless a matrix) */
    uint16_t col_stride, kind;      /* bytes between columns; VK_UP_* */
} vk_upload;

enum { VK_UP_SAME, VK_UP_TO_INT, VK_UP_TO_FLOAT, VK_UP_TO_BOOL };

enum { VK_SLOT_NONE, VK_SLOT_REG, VK_SLOT_OTHER }; /* vk_slot.mode */

/* What a program reads of one top-level parameter: a packed register run, or uploads. */
typedef struct vk_slot {
    uint32_t mode;                  /* VK_SLOT_NONE, VK_SLOT_REG, VK_SLOT_OTHER */
    uint32_t reg, first, count;
    uint16_t reg_rows, reg_cols;
    uint32_t offset;                /* VK_SLOT_REG: the parameter's words */
} vk_slot;

typedef struct vk_program {
    VkShaderModule vs, fs;
    VkShaderModule fs_fewer[4];     /* fs_fewer[n]: fs for n colour attachments, when it writes more (outputs.c) */
    uint32_t colors_written;        /* the pixel shader's highest colour Location + 1 */
    VkDescriptorSetLayout set_layout;
    VkPipelineLayout layout;
    uint32_t block_size;            /* 0: no uniforms */
    int32_t regs_at, fixup_at, alpha_func_at, alpha_ref_at; /* byte offsets, -1 when absent */
    uint32_t reg_count;
    vk_slot *slots;                 /* per top-level parameter + 1 */
    vk_upload *uploads;
    uint32_t upload_count;
    uint32_t sampler_count;         /* bindings HFX_VK_BINDING_SAMPLER0.. */
    uint8_t sampler_dims[32];       /* per binding: the hfx_fx_dim the modules sample it with (reflect.c) */
    const hfx_fx_program *fp;
} vk_program;

/* An effect sampler: its sampler_state's constant part and the states read at Apply. */
typedef struct vk_fx_sampler {
    hfx_sampler_desc base;
    const hfx_fx_state *dynamic[32];
    uint32_t dynamic_count;
} vk_fx_sampler;

struct hfx_vk_shared {
    vk_program *programs;
    uint32_t program_count;
    vk_fx_sampler *samplers;
    int8_t *texture_dims;           /* per parameter: hfx_rt_texture_dim (2D when none), what the application was told */
};

/* Per instance, per program: the uniform block as this instance's values make it, and the
 * slice and descriptor set that hold it now. */
typedef struct vk_bound {
    uint8_t *image;
    uint64_t *held;                 /* per top-level parameter + 1: the version in image */
    uint64_t seen;                  /* the change log's length when last looked */
    int dirty;                      /* image differs from the slice */
    uint64_t frame;                 /* serial of the frame the slice and set belong to */
    VkBuffer buffer;
    uint32_t offset;
    VkDescriptorSet set;
    VkImageView *views;             /* per sampler binding: what set holds */
    VkImageLayout *layouts;
    VkSampler *vk_samplers;
    hfx_preshaders pre;             /* the program's preshaders, run into this image's hfx_c */
} vk_bound;

struct hfx_vk_instance {
    vk_bound **bound;               /* per program, made at its first Apply */
    uint32_t bound_count;           /* programs (the shared part may be gone when this is freed) */
    uint32_t last_program;          /* the last Apply's program + 1 (0: none): a pass that sets no
                                     * shaders keeps it, as D3D9 keeps the device's shaders */
    hfx_rs_value saved[HFX_ST_COUNT_];
};

/* backend.c */
extern const hfx_backend hfx_vk_backend;

/* apply.c: the table's pass_apply, which refuses (Apply records into hfx_pass_apply_vk's
 * command buffer). */
int hfx_vk_pass_apply(hfx_pass *p);

/* device.c */
void hfx_vk_device_destroy(hfx_device *dev);
int hfx_vk_fail(hfx_device *dev, VkResult r, const char *what);
int hfx_vk_chunk_make(hfx_device *dev, VkDeviceSize size, VkBufferUsageFlags usage, vk_chunk *c);
void hfx_vk_chunk_free(hfx_device *dev, vk_chunk *c);
/* A slice of size bytes of the current frame's ring: its buffer, offset and memory. */
int hfx_vk_slice(hfx_device *dev, uint32_t size, VkBuffer *buffer, uint32_t *offset, uint8_t **map);
int hfx_vk_descriptor_set(hfx_device *dev, VkDescriptorSetLayout layout, VkDescriptorSet *set);
int hfx_vk_memory_type(const struct hfx_vk_device *vk, uint32_t bits, VkMemoryPropertyFlags want); /* -1: none */

/* defaults.c */
int hfx_vk_defaults_make(hfx_device *dev, VkQueue queue, uint32_t family);
void hfx_vk_defaults_free(hfx_device *dev);

/* reflect.c: the members of a module's uniform block (set 0, binding HFX_VK_BINDING_BLOCK). */
typedef struct vk_leaf {
    char path[160];                 /* "name", "s.member", "a[2].member" */
    uint32_t offset, count, stride; /* count 0: not an array */
    uint16_t base, comps, cols, col_stride; /* base: VK_BASE_* */
} vk_leaf;
enum { VK_BASE_FLOAT, VK_BASE_INT, VK_BASE_UINT, VK_BASE_BOOL };
typedef struct vk_block {
    vk_leaf *leaves;
    uint32_t count, size;           /* size: bytes up to the end of the last member */
} vk_block;
int hfx_vk_reflect_block(const uint32_t *words, size_t count, vk_block *out); /* 0, or -1 (bad or no memory) */
void hfx_vk_block_free(vk_block *b);
/* NULL when every descriptor a module declares is a slot of the program's layout (set 0: the block,
 * samplers below sampler_count; *block set when it declares the block), else why not. */
/* Sets dims[k] to the hfx_fx_dim of sampler binding HFX_VK_BINDING_SAMPLER0 + k (k < count) that
 * the module declares; leaves the others. 0, or -1 when the module cannot be read. */
int hfx_vk_sampler_dims(const uint32_t *words, size_t count, uint8_t *dims, uint32_t dim_count);
const char *hfx_vk_check_slots(const uint32_t *words, size_t count, uint32_t sampler_count, bool *block);

/* program.c */
int hfx_vk_program_build(hfx_shared *sh, uint32_t index);
int hfx_vk_validator_make(struct hfx_vk_device *vk); /* 0, or HFX_ERR_MEMORY */
void hfx_vk_validator_free(struct hfx_vk_device *vk);
int hfx_vk_spirv_valid(const struct hfx_vk_device *vk, const uint32_t *words, size_t count, char reason[256]);
void hfx_vk_program_free(hfx_device *dev, vk_program *p);

/* outputs.c */
int hfx_vk_outputs_make(hfx_device *dev, const hfx_fx_code *code, vk_program *p);
VkShaderModule hfx_vk_fragment_module(const vk_program *p, uint32_t color_count);

/* pipeline.c */
void hfx_vk_states_of(const hfx_rs_value *rs, vk_states *st);
int hfx_vk_pipeline(hfx_device *dev, const vk_pso_key *key, const vk_pso **out);
void hfx_vk_pipelines_forget(hfx_device *dev, const void *program);
void hfx_vk_pipelines_free(hfx_device *dev);

/* sampler.c */
int hfx_vk_sampler(hfx_device *dev, const hfx_sampler_desc *d, VkSampler *out);
void hfx_vk_samplers_free(hfx_device *dev);
void hfx_vk_fx_samplers_make(hfx_shared *sh);

/* uniforms.c */
int hfx_vk_bound_make(hfx_effect *fx, const vk_program *p, vk_bound **out);
void hfx_vk_bound_free(vk_bound *b);
void hfx_vk_uniforms_update(hfx_effect *fx, const vk_program *p, vk_bound *b, const hfx_vk_target *t);

#endif
