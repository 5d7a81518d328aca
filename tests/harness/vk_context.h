/* vk_context.h: a headless Vulkan device for tests and tools (lavapipe on CI): an instance with
 * the Khronos validation layer on and every message it sends counted, a device with one graphics
 * queue, an offscreen RGBA8 colour image with a depth / stencil image in one render pass, read
 * back after each frame (Vulkan 1.3's dynamic rendering too where the device has it), and an hfx
 * device on it. Frames are submitted and waited for one by one, so hfx_device_begin_frame_vk is
 * always safe. */
#ifndef HFX_TEST_VK_CONTEXT_H
#define HFX_TEST_VK_CONTEXT_H

#include <stddef.h>
#include <stdint.h>
#include <vulkan/vulkan.h>

#include "hfx/hfx_vulkan.h"

typedef struct test_vk test_vk;

typedef struct test_vk_texture {
    VkImage image;
    VkDeviceMemory memory;
    VkImageView view;
} test_vk_texture;

typedef struct test_vk_buffer {
    VkBuffer buffer;
    VkDeviceMemory memory;
} test_vk_buffer;

/* NULL when no Vulkan device can be made; *why (static text or NULL) says why. */
test_vk *test_vk_create(int width, int height, const char **why);
int test_vk_destroy(test_vk *v); /* the validation messages of the whole run, its end included */
hfx_device *test_vk_device(test_vk *v);
hfx_vk_target *test_vk_target(test_vk *v);          /* the offscreen target; set its layout before Apply */
int test_vk_width(const test_vk *v);
int test_vk_height(const test_vk *v);
/* Messages the validation layer has sent so far (each is printed as it comes). */
int test_vk_messages(const test_vk *v);
int test_vk_validation_on(const test_vk *v);
int test_vk_custom_border(const test_vk *v);           /* VK_EXT_custom_border_color enabled (and told to hfx) */

/* Starts a frame: hfx_device_begin_frame_vk, a command buffer, the render pass cleared to rgba
 * (depth 1, stencil 0), or keeping the last frame's colour, depth and stencil when clear is
 * NULL (the target's render pass follows). Returns the command buffer to record into. */
VkCommandBuffer test_vk_begin(test_vk *v, const float clear[4]);
/* The same frame begun with Vulkan 1.3's vkCmdBeginRendering instead of a render pass (the
 * target's render_pass becomes VK_NULL_HANDLE); VK_NULL_HANDLE when the device lacks it. */
VkCommandBuffer test_vk_begin_dynamic(test_vk *v, const float clear[4]);
/* Ends the render pass (or the rendering), copies the image out, submits and waits; 0 on success. */
int test_vk_end(test_vk *v);
/* Pixel (x, y) from the top left as last read back, RGBA8. */
const unsigned char *test_vk_pixel(const test_vk *v, int x, int y);
const unsigned char *test_vk_pixels(const test_vk *v); /* width * height * 4, top row first */
int test_vk_write_png(const test_vk *v, const char *path); /* 0 on success */

/* Device-local-enough (host-visible) vertex data. */
int test_vk_buffer_make(test_vk *v, const void *data, size_t size, test_vk_buffer *out);
void test_vk_buffer_free(test_vk *v, test_vk_buffer *b);
/* An RGBA8 texture (one level, row 0 first), in SHADER_READ_ONLY_OPTIMAL. */
int test_vk_texture_make(test_vk *v, int width, int height, const unsigned char *texels, test_vk_texture *out);
/* The same with every mip level, each a linear halving of the one above (glGenerateMipmap's). */
int test_vk_texture_make_mipmapped(test_vk *v, int width, int height, const unsigned char *texels, test_vk_texture *out);
/* A 2D texture, a cube (texels: the six faces +X, -X, +Y, -Y, +Z, -Z one after the other, each
 * width x height) or a volume (depth slices one after the other), mipmapped or with one level. */
typedef enum { TEST_VK_2D, TEST_VK_CUBE, TEST_VK_3D } test_vk_kind;
int test_vk_texture_make_kind(test_vk *v, test_vk_kind kind, int width, int height, int depth, int mipmapped,
                              const unsigned char *texels, test_vk_texture *out);
void test_vk_texture_free(test_vk *v, test_vk_texture *t);

#endif
