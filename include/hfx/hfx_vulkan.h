/* hfx_vulkan.h: the hfx runtime on a Vulkan device. The same effects, parameters, techniques and
 * passes as hfx.h; the application owns its instance, device, command buffers and render passes,
 * and hfx_pass_apply_vk records what the next draw needs (pipeline, descriptor set, uniforms).
 *
 * hfx calls no Vulkan function by link: it loads every entry point through the
 * vkGetInstanceProcAddr the application hands it. Threads: like a GL context, a Vulkan hfx
 * device and everything made from it are used by one thread at a time (the application
 * synchronises); command buffers recorded by hfx_pass_apply_vk follow Vulkan's own rules.
 *
 * Frames: hfx writes uniforms into a ring of host-visible buffers, one per frame in flight.
 * Call hfx_device_begin_frame_vk once the GPU has finished the frame that last used the slot
 * (after waiting on that frame's fence), before the frame's first Apply. */
#ifndef HFX_HFX_VULKAN_H
#define HFX_HFX_VULKAN_H

#include <stdint.h>
#include <vulkan/vulkan.h>

#include "hfx/hfx.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct hfx_vertex_layout hfx_vertex_layout;

typedef struct hfx_vulkan_desc {
    VkInstance instance;
    VkPhysicalDevice physical_device;
    VkDevice device;
    uint32_t queue_family;                  /* the queue family the command buffers are recorded for */
    PFN_vkGetInstanceProcAddr get_instance_proc_addr;
    uint32_t frames_in_flight;              /* 1..8 */
    const VkPhysicalDeviceFeatures *enabled_features; /* what the device was created with; NULL: none */
    VkDeviceSize uniform_bytes_per_frame;   /* the ring's first buffer per frame; 0: 1 MiB (it grows) */
    VkBool32 sampler_mirror_clamp_to_edge;  /* enabled (Vulkan 1.2): D3D's MirrorOnce; else it mirrors */
    /* VK_EXT_custom_border_color enabled with customBorderColors and customBorderColorWithoutFormat:
     * BorderColor is any colour; else the nearest of Vulkan's three fixed ones */
    VkBool32 custom_border_colors;
    /* A queue of queue_family that hfx_device_create_vulkan submits one command buffer to (and
     * waits for) to make its default textures: 1 x 1 images of (0, 0, 0, 1), 2D, cube and
     * volume, which a sampler reads when the application set no texture for it, as D3D9
     * samples a stage with no texture and GL an unbound unit. VK_NULL_HANDLE: no defaults, and
     * such a sampler makes hfx_pass_apply_vk fail. */
    VkQueue queue;
} hfx_vulkan_desc;

/* Where the next draws go: the render pass (or, with VK_NULL_HANDLE, dynamic rendering with
 * these formats), the attachments' formats and sample count, and the viewport's size. */
typedef struct hfx_vk_target {
    VkRenderPass render_pass;
    uint32_t subpass;
    VkFormat color_formats[4];
    uint32_t color_count;
    VkFormat depth_format;                  /* VK_FORMAT_UNDEFINED: no depth / stencil attachment */
    VkSampleCountFlagBits samples;          /* 0 means VK_SAMPLE_COUNT_1_BIT */
    uint32_t width, height;                 /* the viewport hfx sets (D3D9's pixel centres follow it) */
    VkRect2D scissor;                       /* used while a pass has ScissorTestEnable = TRUE */
    const hfx_vertex_layout *layout;        /* the vertices' attributes by semantic */
} hfx_vk_target;

/* One vertex attribute, by the D3D9 semantic the shaders read ("POSITION0", "NORMAL", "TEXCOORD1"). */
typedef struct hfx_vertex_element {
    const char *semantic;
    VkFormat format;
    uint32_t offset;                        /* in the vertex */
    uint32_t binding;                       /* vertex buffer binding, 0..14 (15 is hfx's) */
    uint32_t stride;                        /* of the binding */
} hfx_vertex_element;

/* Device: the application's Vulkan objects (not owned); NULL with a message in *error when the
 * device lacks what hfx needs. error may be NULL; else free the message with hfx_free. */
HFX_API hfx_device *hfx_device_create_vulkan(const hfx_vulkan_desc *desc, char **error);
/* Starts a frame: its slot of the uniform ring and descriptor pools is reused. */
HFX_API int hfx_device_begin_frame_vk(hfx_device *dev);
HFX_API int hfx_device_end_frame_vk(hfx_device *dev);       /* the frame's Applies are all recorded */
/* Pipelines made so far (each (program, render states, vertex layout, target) once). */
HFX_API size_t hfx_device_pipelines_created_vk(const hfx_device *dev);
/* Uniform slices written to the ring and descriptor sets written so far: an Apply with nothing
 * changed adds to neither. */
HFX_API void hfx_device_writes_vk(const hfx_device *dev, size_t *uniform_slices, size_t *descriptor_sets);

/* D3D9's SetRenderState for what the application draws with (XNA's BlendState,
 * DepthStencilState, RasterizerState): "CullMode", "AlphaBlendEnable"... by their effect-file
 * names, values as D3D9 numbers them. Passes set theirs over these, and they stay set after the
 * pass, as in D3D9. Reset puts back D3D9's defaults. */
HFX_API int hfx_device_set_render_state_vk(hfx_device *dev, const char *state, int value);
HFX_API int hfx_device_reset_render_states_vk(hfx_device *dev);

/* A vertex layout described once; pipelines are cached by it. Semantics are copied. */
HFX_API hfx_vertex_layout *hfx_vertex_layout_create(hfx_device *dev, const hfx_vertex_element *elements, size_t count);
HFX_API void hfx_vertex_layout_destroy(hfx_vertex_layout *layout);         /* after the effects that drew with it */

/* A texture or sampler parameter samples this view, in this layout, from now on. */
HFX_API int hfx_param_set_texture_vk(hfx_param *p, VkImageView view, VkImageLayout layout);
/* Binds what the pass needs for the next draw into cmd (inside a render pass compatible with
 * target): the pipeline, the descriptor set, the uniforms' slice, viewport and scissor. */
HFX_API int hfx_pass_apply_vk(hfx_pass *p, VkCommandBuffer cmd, const hfx_vk_target *target);

#ifdef __cplusplus
}
#endif
#endif
