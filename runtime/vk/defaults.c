/* defaults.c: the textures a sampler reads when the application set none. D3D9 samples a stage
 * with no texture as (0, 0, 0, 1), and GL's unbound unit (texture object 0, incomplete) reads
 * the same, so each back end gives a sampler without a texture that colour: on Vulkan one 1 x 1
 * image per dimension (2D, 1D as 2D, volume, cube with six layers), cleared once at device
 * creation on the application's queue and kept in SHADER_READ_ONLY_OPTIMAL. */
#include <string.h>

#include "vk/vk.h"

static int make_image(hfx_device *dev, hfx_fx_dim dim, vk_default_image *out) {
    struct hfx_vk_device *vk = dev->vk;
    int cube = dim == HFX_FX_DIM_CUBE, vol = dim == HFX_FX_DIM_3D;
    VkImageCreateInfo ii = {.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                            .flags = cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0,
                            .imageType = vol ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D,
                            .format = VK_FORMAT_R8G8B8A8_UNORM, .extent = {1, 1, 1}, .mipLevels = 1,
                            .arrayLayers = cube ? 6 : 1, .samples = VK_SAMPLE_COUNT_1_BIT,
                            .tiling = VK_IMAGE_TILING_OPTIMAL,
                            .usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                            .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
    VkResult r = vk->fn.CreateImage(vk->device, &ii, NULL, &out->image);
    if (r != VK_SUCCESS) return hfx_vk_fail(dev, r, "vkCreateImage (default texture)");
    VkMemoryRequirements req;
    vk->fn.GetImageMemoryRequirements(vk->device, out->image, &req);
    int type = hfx_vk_memory_type(vk, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (type < 0) type = hfx_vk_memory_type(vk, req.memoryTypeBits, 0);
    VkMemoryAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, .allocationSize = req.size,
                               .memoryTypeIndex = (uint32_t)type};
    if (type < 0) return hfx_rt_fail(dev, HFX_ERR_VULKAN, "no memory type for a default texture");
    if ((r = vk->fn.AllocateMemory(vk->device, &ai, NULL, &out->memory)) != VK_SUCCESS ||
        (r = vk->fn.BindImageMemory(vk->device, out->image, out->memory, 0)) != VK_SUCCESS)
        return hfx_vk_fail(dev, r, "allocating a default texture");
    VkImageViewCreateInfo vi = {.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO, .image = out->image,
                                .viewType = cube ? VK_IMAGE_VIEW_TYPE_CUBE : vol ? VK_IMAGE_VIEW_TYPE_3D : VK_IMAGE_VIEW_TYPE_2D,
                                .format = VK_FORMAT_R8G8B8A8_UNORM,
                                .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, cube ? 6 : 1}};
    if ((r = vk->fn.CreateImageView(vk->device, &vi, NULL, &out->view)) != VK_SUCCESS)
        return hfx_vk_fail(dev, r, "vkCreateImageView (default texture)");
    return HFX_OK;
}

static void barrier(const hfx_vk_fns *fn, VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                    VkAccessFlags src, VkAccessFlags dst, VkPipelineStageFlags src_stage, VkPipelineStageFlags dst_stage) {
    VkImageMemoryBarrier b = {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER, .srcAccessMask = src, .dstAccessMask = dst,
                              .oldLayout = from, .newLayout = to, .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                              .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .image = image,
                              .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, VK_REMAINING_ARRAY_LAYERS}};
    fn->CmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 0, NULL, 0, NULL, 1, &b);
}

/* Clears every default image to (0, 0, 0, 1) and leaves it ready for sampling. */
static void record_clears(const struct hfx_vk_device *vk, VkCommandBuffer cmd) {
    static const VkClearColorValue black = {.float32 = {0, 0, 0, 1}};
    VkImageSubresourceRange all = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, VK_REMAINING_ARRAY_LAYERS};
    for (int d = 0; d < 4; d++) {
        VkImage im = vk->defaults[d].image;
        barrier(&vk->fn, cmd, im, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
        vk->fn.CmdClearColorImage(cmd, im, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &all);
        barrier(&vk->fn, cmd, im, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
    }
}

static int submit_clears(hfx_device *dev, VkQueue queue, uint32_t family) {
    struct hfx_vk_device *vk = dev->vk;
    VkCommandPoolCreateInfo pi = {.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                  .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT, .queueFamilyIndex = family};
    VkCommandPool pool;
    VkResult r = vk->fn.CreateCommandPool(vk->device, &pi, NULL, &pool);
    if (r != VK_SUCCESS) return hfx_vk_fail(dev, r, "vkCreateCommandPool (default textures)");
    VkCommandBufferAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, .commandPool = pool,
                                      .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY, .commandBufferCount = 1};
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VkCommandBufferBeginInfo bi = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                   .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    if ((r = vk->fn.AllocateCommandBuffers(vk->device, &ai, &cmd)) == VK_SUCCESS &&
        (r = vk->fn.BeginCommandBuffer(cmd, &bi)) == VK_SUCCESS) {
        record_clears(vk, cmd);
        VkSubmitInfo si = {.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
        if ((r = vk->fn.EndCommandBuffer(cmd)) == VK_SUCCESS && (r = vk->fn.QueueSubmit(queue, 1, &si, VK_NULL_HANDLE)) == VK_SUCCESS)
            r = vk->fn.QueueWaitIdle(queue);
    }
    vk->fn.DestroyCommandPool(vk->device, pool, NULL); /* frees cmd */
    return r == VK_SUCCESS ? HFX_OK : hfx_vk_fail(dev, r, "making the default textures");
}

int hfx_vk_defaults_make(hfx_device *dev, VkQueue queue, uint32_t family) {
    for (int d = 0; d < 4; d++) {
        int rc = make_image(dev, (hfx_fx_dim)d, &dev->vk->defaults[d]);
        if (rc) return rc;
    }
    return submit_clears(dev, queue, family);
}

void hfx_vk_defaults_free(hfx_device *dev) {
    struct hfx_vk_device *vk = dev->vk;
    for (int d = 0; d < 4; d++) {
        vk_default_image *im = &vk->defaults[d];
        if (im->view) vk->fn.DestroyImageView(vk->device, im->view, NULL);
        if (im->image) vk->fn.DestroyImage(vk->device, im->image, NULL);
        if (im->memory) vk->fn.FreeMemory(vk->device, im->memory, NULL);
    }
    memset(vk->defaults, 0, sizeof vk->defaults);
}
