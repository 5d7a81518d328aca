/* vk_context.c: see vk_context.h. Plain Vulkan 1.1 (1.3 for dynamic rendering), linked against the loader (the test is the
 * application here; hfx itself loads its entry points through vkGetInstanceProcAddr). */
#include "vk_context.h"

#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#ifdef HFX_TEST_PNG
#include <png.h>
#endif

struct test_vk {
    VkInstance instance;
    VkDebugUtilsMessengerEXT messenger;
    VkPhysicalDevice phys;
    VkDevice device;
    VkQueue queue;
    uint32_t family;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    VkFence fence;
    VkImage color, depth;
    VkDeviceMemory color_mem, depth_mem;
    VkImageView color_view, depth_view;
    VkRenderPass pass, load_pass;   /* clearing, and keeping what the last frame drew */
    VkFramebuffer fb;
    test_vk_buffer readback;
    unsigned char *pixels;
    int width, height, messages, validation;
    int dynamic_rendering, dynamic_frame; /* the device has it; this frame uses it */
    int custom_border;                    /* VK_EXT_custom_border_color enabled (lavapipe has it) */
    VkFormat depth_format;
    hfx_device *dev;
    hfx_vk_target target;
};

static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT type,
                                                 const VkDebugUtilsMessengerCallbackDataEXT *data, void *user) {
    (void)type;
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
    ((test_vk *)user)->messages++;
    fprintf(stderr, "vulkan validation: %s\n", data && data->pMessage ? data->pMessage : "(no text)");
    return VK_FALSE;
}

static int has_layer(const char *name) {
    uint32_t n = 0;
    vkEnumerateInstanceLayerProperties(&n, NULL);
    VkLayerProperties *p = calloc(n ? n : 1, sizeof *p);
    int found = 0;
    if (p && vkEnumerateInstanceLayerProperties(&n, p) == VK_SUCCESS)
        for (uint32_t i = 0; i < n && !found; i++) found = strcmp(p[i].layerName, name) == 0;
    free(p);
    return found;
}

static VkDebugUtilsMessengerCreateInfoEXT messenger_info(test_vk *v) {
    VkDebugUtilsMessengerCreateInfoEXT m = {.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
                                            .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                                               VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
                                            .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                                           VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT,
                                            .pfnUserCallback = on_message, .pUserData = v};
    return m;
}

/* The loader unloads the driver and the layer at vkDestroyInstance, before LeakSanitizer looks:
 * their own leaks would then show as "<unknown module>" no suppression can name. Kept loaded
 * (never closed: RTLD_NODELETE), they keep their names for tests/lsan.supp. */
static void pin_driver_libraries(void) {
    static const char *const libs[] = {"libvulkan_lvp.so", "libVkLayer_khronos_validation.so"};
    for (size_t i = 0; i < sizeof libs / sizeof *libs; i++) dlopen(libs[i], RTLD_NOW | RTLD_NODELETE);
}

static int make_instance(test_vk *v) {
    pin_driver_libraries();
    static const char *layer = "VK_LAYER_KHRONOS_validation";
    static const char *ext = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    v->validation = getenv("HFX_VK_NO_VALIDATION") == NULL && has_layer(layer);
    VkApplicationInfo app = {.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO, .pApplicationName = "hfx tests",
                             .apiVersion = VK_API_VERSION_1_3};
    VkDebugUtilsMessengerCreateInfoEXT m = messenger_info(v);
    VkInstanceCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, .pNext = v->validation ? &m : NULL,
                               .pApplicationInfo = &app, .enabledLayerCount = v->validation ? 1 : 0,
                               .ppEnabledLayerNames = &layer, .enabledExtensionCount = v->validation ? 1 : 0,
                               .ppEnabledExtensionNames = &ext};
    if (vkCreateInstance(&ci, NULL, &v->instance) != VK_SUCCESS) return 0;
    if (!v->validation) return 1;
    PFN_vkCreateDebugUtilsMessengerEXT create =
        (PFN_vkCreateDebugUtilsMessengerEXT)vkGetInstanceProcAddr(v->instance, "vkCreateDebugUtilsMessengerEXT");
    return create && create(v->instance, &m, NULL, &v->messenger) == VK_SUCCESS;
}

/* The first device with a graphics queue (lavapipe is often the only one). */
static int pick_device(test_vk *v) {
    uint32_t n = 0;
    vkEnumeratePhysicalDevices(v->instance, &n, NULL);
    VkPhysicalDevice list[8];
    if (n > 8) n = 8;
    if (!n || vkEnumeratePhysicalDevices(v->instance, &n, list) < 0) return 0;
    for (uint32_t i = 0; i < n; i++) {
        uint32_t qn = 0;
        VkQueueFamilyProperties q[8];
        vkGetPhysicalDeviceQueueFamilyProperties(list[i], &qn, NULL);
        if (qn > 8) qn = 8;
        vkGetPhysicalDeviceQueueFamilyProperties(list[i], &qn, q);
        for (uint32_t f = 0; f < qn; f++)
            if (q[f].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
                v->phys = list[i];
                v->family = f;
                return 1;
            }
    }
    return 0;
}

/* Vulkan 1.3's dynamic rendering where the device has it (lavapipe does), so tests can draw
 * through hfx's render-pass-less pipelines too. */
static int has_dynamic_rendering(test_vk *v) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(v->phys, &props);
    if (props.apiVersion < VK_API_VERSION_1_3) return 0;
    VkPhysicalDeviceVulkan13Features f13 = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceFeatures2 f = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &f13};
    vkGetPhysicalDeviceFeatures2(v->phys, &f);
    return f13.dynamicRendering == VK_TRUE;
}

/* VK_EXT_custom_border_color with colours given without a format, as hfx uses it. */
static int has_custom_border(test_vk *v) {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(v->phys, NULL, &n, NULL);
    VkExtensionProperties *e = calloc(n ? n : 1, sizeof *e);
    int found = 0;
    if (e && vkEnumerateDeviceExtensionProperties(v->phys, NULL, &n, e) >= 0)
        for (uint32_t i = 0; i < n; i++) found |= strcmp(e[i].extensionName, VK_EXT_CUSTOM_BORDER_COLOR_EXTENSION_NAME) == 0;
    free(e);
    if (!found) return 0;
    VkPhysicalDeviceCustomBorderColorFeaturesEXT cb = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_CUSTOM_BORDER_COLOR_FEATURES_EXT};
    VkPhysicalDeviceFeatures2 f = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &cb};
    vkGetPhysicalDeviceFeatures2(v->phys, &f);
    return cb.customBorderColors && cb.customBorderColorWithoutFormat;
}

static int make_device(test_vk *v, VkPhysicalDeviceFeatures *enabled) {
    VkPhysicalDeviceFeatures have;
    vkGetPhysicalDeviceFeatures(v->phys, &have);
    memset(enabled, 0, sizeof *enabled);
    enabled->samplerAnisotropy = have.samplerAnisotropy;
    enabled->fillModeNonSolid = have.fillModeNonSolid;
    v->dynamic_rendering = has_dynamic_rendering(v);
    v->custom_border = has_custom_border(v);
    VkPhysicalDeviceCustomBorderColorFeaturesEXT cb = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_CUSTOM_BORDER_COLOR_FEATURES_EXT,
                                                       .customBorderColors = VK_TRUE, .customBorderColorWithoutFormat = VK_TRUE};
    VkPhysicalDeviceVulkan13Features f13 = {.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                            .pNext = v->custom_border ? &cb : NULL, .dynamicRendering = VK_TRUE};
    const char *ext = VK_EXT_CUSTOM_BORDER_COLOR_EXTENSION_NAME;
    float prio = 1.0f;
    VkDeviceQueueCreateInfo q = {.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO, .queueFamilyIndex = v->family,
                                 .queueCount = 1, .pQueuePriorities = &prio};
    VkDeviceCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                             .pNext = v->dynamic_rendering ? (void *)&f13 : v->custom_border ? (void *)&cb : NULL,
                             .queueCreateInfoCount = 1, .pQueueCreateInfos = &q,
                             .enabledExtensionCount = v->custom_border ? 1 : 0, .ppEnabledExtensionNames = &ext,
                             .pEnabledFeatures = enabled};
    if (vkCreateDevice(v->phys, &ci, NULL, &v->device) != VK_SUCCESS) return 0;
    vkGetDeviceQueue(v->device, v->family, 0, &v->queue);
    VkCommandPoolCreateInfo pi = {.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                  .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, .queueFamilyIndex = v->family};
    VkCommandBufferAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                      .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY, .commandBufferCount = 1};
    VkFenceCreateInfo fi = {.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    if (vkCreateCommandPool(v->device, &pi, NULL, &v->pool) != VK_SUCCESS) return 0;
    ai.commandPool = v->pool;
    return vkAllocateCommandBuffers(v->device, &ai, &v->cmd) == VK_SUCCESS &&
           vkCreateFence(v->device, &fi, NULL, &v->fence) == VK_SUCCESS;
}

static int memory_type(test_vk *v, uint32_t bits, VkMemoryPropertyFlags want) {
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(v->phys, &mp);
    for (uint32_t i = 0; i < mp.memoryTypeCount; i++)
        if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return (int)i;
    return -1;
}

static int bind_memory(test_vk *v, VkMemoryRequirements req, VkMemoryPropertyFlags want, VkDeviceMemory *mem) {
    int type = memory_type(v, req.memoryTypeBits, want);
    VkMemoryAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, .allocationSize = req.size,
                               .memoryTypeIndex = (uint32_t)type};
    return type >= 0 && vkAllocateMemory(v->device, &ai, NULL, mem) == VK_SUCCESS;
}

/* What an image is: a 2D image, a cube (6 layers, CUBE_COMPATIBLE) or a volume of depth slices. */
typedef struct image_shape {
    test_vk_kind kind;
    int w, h, d;               /* d: slices of a volume, 1 otherwise */
    uint32_t levels;
} image_shape;

static uint32_t shape_layers(const image_shape *s) { return s->kind == TEST_VK_CUBE ? 6 : 1; }

static int make_shaped(test_vk *v, VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect,
                       const image_shape *s, VkImage *img, VkDeviceMemory *mem, VkImageView *view) {
    static const VkImageViewType view_types[] = {VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_VIEW_TYPE_CUBE, VK_IMAGE_VIEW_TYPE_3D};
    VkImageCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                            .flags = s->kind == TEST_VK_CUBE ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0,
                            .imageType = s->kind == TEST_VK_3D ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D,
                            .format = format, .extent = {(uint32_t)s->w, (uint32_t)s->h, (uint32_t)s->d},
                            .mipLevels = s->levels, .arrayLayers = shape_layers(s), .samples = VK_SAMPLE_COUNT_1_BIT,
                            .tiling = VK_IMAGE_TILING_OPTIMAL, .usage = usage};
    if (vkCreateImage(v->device, &ci, NULL, img) != VK_SUCCESS) return 0;
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(v->device, *img, &req);
    if (!bind_memory(v, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, mem) &&
        !bind_memory(v, req, 0, mem))
        return 0;
    vkBindImageMemory(v->device, *img, *mem, 0);
    VkImageViewCreateInfo vi = {.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO, .image = *img,
                                .viewType = view_types[s->kind], .format = format,
                                .subresourceRange = {aspect, 0, s->levels, 0, shape_layers(s)}};
    return vkCreateImageView(v->device, &vi, NULL, view) == VK_SUCCESS;
}

static int make_image(test_vk *v, VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect, int w, int h,
                      VkImage *img, VkDeviceMemory *mem, VkImageView *view) {
    image_shape s = {TEST_VK_2D, w, h, 1, 1};
    return make_shaped(v, format, usage, aspect, &s, img, mem, view);
}

static VkFormat depth_format(test_vk *v) {
    static const VkFormat want[] = {VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT, VK_FORMAT_D16_UNORM_S8_UINT};
    for (size_t i = 0; i < sizeof want / sizeof *want; i++) {
        VkFormatProperties p;
        vkGetPhysicalDeviceFormatProperties(v->phys, want[i], &p);
        if (p.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT) return want[i];
    }
    return VK_FORMAT_UNDEFINED;
}

static int make_pass(test_vk *v, int load, VkRenderPass *out) {
    VkAttachmentLoadOp op = load ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
    VkAttachmentDescription a[2] = {
        {0, VK_FORMAT_R8G8B8A8_UNORM, VK_SAMPLE_COUNT_1_BIT, op, VK_ATTACHMENT_STORE_OP_STORE,
         VK_ATTACHMENT_LOAD_OP_DONT_CARE, VK_ATTACHMENT_STORE_OP_DONT_CARE,
         load ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL},
        {0, v->depth_format, VK_SAMPLE_COUNT_1_BIT, op, VK_ATTACHMENT_STORE_OP_STORE, op, VK_ATTACHMENT_STORE_OP_STORE,
         load ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL : VK_IMAGE_LAYOUT_UNDEFINED,
         VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL}};
    VkAttachmentReference cref = {0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkAttachmentReference dref = {1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription sub = {.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS, .colorAttachmentCount = 1,
                                .pColorAttachments = &cref, .pDepthStencilAttachment = &dref};
    VkSubpassDependency dep = {0, VK_SUBPASS_EXTERNAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                               VK_ACCESS_TRANSFER_READ_BIT, 0};
    VkRenderPassCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO, .attachmentCount = 2,
                                 .pAttachments = a, .subpassCount = 1, .pSubpasses = &sub, .dependencyCount = 1,
                                 .pDependencies = &dep};
    return vkCreateRenderPass(v->device, &ci, NULL, out) == VK_SUCCESS;
}

static int make_framebuffer(test_vk *v) {
    if (!make_pass(v, 0, &v->pass) || !make_pass(v, 1, &v->load_pass)) return 0;
    VkImageView views[2] = {v->color_view, v->depth_view};
    VkFramebufferCreateInfo fi = {.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO, .renderPass = v->pass,
                                  .attachmentCount = 2, .pAttachments = views, .width = (uint32_t)v->width,
                                  .height = (uint32_t)v->height, .layers = 1};
    return vkCreateFramebuffer(v->device, &fi, NULL, &v->fb) == VK_SUCCESS;
}

static int make_target(test_vk *v) {
    v->depth_format = depth_format(v);
    if (v->depth_format == VK_FORMAT_UNDEFINED) return 0;
    VkImageUsageFlags cu = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if (!make_image(v, VK_FORMAT_R8G8B8A8_UNORM, cu, VK_IMAGE_ASPECT_COLOR_BIT, v->width, v->height, &v->color,
                    &v->color_mem, &v->color_view) ||
        !make_image(v, v->depth_format, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                    VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT,
                    v->width, v->height, &v->depth, &v->depth_mem, &v->depth_view) ||
        !make_framebuffer(v))
        return 0;
    size_t bytes = (size_t)v->width * (size_t)v->height * 4;
    v->pixels = calloc(bytes, 1);
    hfx_vk_target *t = &v->target;
    t->render_pass = v->pass;
    t->color_formats[0] = VK_FORMAT_R8G8B8A8_UNORM;
    t->color_count = 1;
    t->depth_format = v->depth_format;
    t->samples = VK_SAMPLE_COUNT_1_BIT;
    t->width = (uint32_t)v->width, t->height = (uint32_t)v->height;
    t->scissor = (VkRect2D){{0, 0}, {(uint32_t)v->width, (uint32_t)v->height}};
    return v->pixels && test_vk_buffer_make(v, NULL, bytes, &v->readback);
}

static int make_hfx(test_vk *v, const VkPhysicalDeviceFeatures *features) {
    hfx_vulkan_desc d = {v->instance, v->phys, v->device, v->family, vkGetInstanceProcAddr, 2, features, 0, VK_FALSE,
                         v->custom_border ? VK_TRUE : VK_FALSE, v->queue};
    char *err = NULL;
    v->dev = hfx_device_create_vulkan(&d, &err);
    if (!v->dev) fprintf(stderr, "hfx_device_create_vulkan: %s\n", err ? err : "?");
    hfx_free(err);
    return v->dev != NULL;
}

test_vk *test_vk_create(int width, int height, const char **why) {
    test_vk *v = calloc(1, sizeof *v);
    if (!v) return NULL;
    v->width = width, v->height = height;
    VkPhysicalDeviceFeatures features;
    const char *step = !make_instance(v)                ? "no Vulkan instance (is a loader and an ICD installed?)"
                       : !pick_device(v)                ? "no Vulkan device with a graphics queue"
                       : !make_device(v, &features)     ? "vkCreateDevice failed"
                       : !make_target(v)                ? "the offscreen target could not be made"
                       : !make_hfx(v, &features)        ? "hfx_device_create_vulkan failed"
                                                        : NULL;
    if (why) *why = step;
    if (step) {
        test_vk_destroy(v);
        return NULL;
    }
    return v;
}

int test_vk_destroy(test_vk *v) {
    if (!v) return 0;
    if (v->device) vkDeviceWaitIdle(v->device);
    hfx_device_destroy(v->dev);
    if (v->device) {
        test_vk_buffer_free(v, &v->readback);
        vkDestroyFramebuffer(v->device, v->fb, NULL);
        vkDestroyRenderPass(v->device, v->pass, NULL);
        vkDestroyRenderPass(v->device, v->load_pass, NULL);
        vkDestroyImageView(v->device, v->color_view, NULL);
        vkDestroyImageView(v->device, v->depth_view, NULL);
        vkDestroyImage(v->device, v->color, NULL);
        vkDestroyImage(v->device, v->depth, NULL);
        vkFreeMemory(v->device, v->color_mem, NULL);
        vkFreeMemory(v->device, v->depth_mem, NULL);
        vkDestroyFence(v->device, v->fence, NULL);
        vkDestroyCommandPool(v->device, v->pool, NULL);
        vkDestroyDevice(v->device, NULL);
    }
    if (v->messenger) {
        PFN_vkDestroyDebugUtilsMessengerEXT destroy =
            (PFN_vkDestroyDebugUtilsMessengerEXT)vkGetInstanceProcAddr(v->instance, "vkDestroyDebugUtilsMessengerEXT");
        if (destroy) destroy(v->instance, v->messenger, NULL);
    }
    int messages = v->messages; /* the messenger is gone: nothing more can come */
    if (v->instance) vkDestroyInstance(v->instance, NULL);
    free(v->pixels);
    free(v);
    return messages;
}

hfx_device *test_vk_device(test_vk *v) { return v->dev; }
hfx_vk_target *test_vk_target(test_vk *v) { return &v->target; }
int test_vk_width(const test_vk *v) { return v->width; }
int test_vk_height(const test_vk *v) { return v->height; }
int test_vk_messages(const test_vk *v) { return v->messages; }
int test_vk_validation_on(const test_vk *v) { return v->validation; }

static void layout_barrier(VkCommandBuffer cmd, VkImage img, VkImageLayout from, VkImageLayout to,
                           VkAccessFlags src, VkAccessFlags dst, VkPipelineStageFlags s1, VkPipelineStageFlags s2);

static void begin_commands(test_vk *v) {
    if (hfx_device_begin_frame_vk(v->dev) != HFX_OK) fprintf(stderr, "begin frame: %s\n", hfx_device_last_error(v->dev));
    vkResetCommandBuffer(v->cmd, 0);
    VkCommandBufferBeginInfo bi = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                   .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    vkBeginCommandBuffer(v->cmd, &bi);
}

int test_vk_custom_border(const test_vk *v) { return v->custom_border; }

VkCommandBuffer test_vk_begin(test_vk *v, const float clear[4]) {
    v->target.render_pass = clear ? v->pass : v->load_pass;
    v->dynamic_frame = 0;
    begin_commands(v);
    VkClearValue cv[2];
    memset(cv, 0, sizeof cv);
    if (clear) memcpy(cv[0].color.float32, clear, 4 * sizeof(float));
    cv[1].depthStencil = (VkClearDepthStencilValue){1.0f, 0};
    VkRenderPassBeginInfo rp = {.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO, .renderPass = v->target.render_pass,
                                .framebuffer = v->fb, .renderArea = {{0, 0}, {(uint32_t)v->width, (uint32_t)v->height}},
                                .clearValueCount = clear ? 2 : 0, .pClearValues = clear ? cv : NULL};
    vkCmdBeginRenderPass(v->cmd, &rp, VK_SUBPASS_CONTENTS_INLINE);
    return v->cmd;
}

static int submit_and_wait(test_vk *v, VkCommandBuffer cmd) {
    VkSubmitInfo si = {.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
    if (vkQueueSubmit(v->queue, 1, &si, v->fence) != VK_SUCCESS) return -1;
    VkResult r = vkWaitForFences(v->device, 1, &v->fence, VK_TRUE, UINT64_MAX);
    vkResetFences(v->device, 1, &v->fence);
    return r == VK_SUCCESS ? 0 : -1;
}

static void depth_barrier(VkCommandBuffer cmd, VkImage img, VkImageLayout from) {
    VkImageMemoryBarrier b = {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER,
                              .srcAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                              .dstAccessMask = VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                               VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                              .oldLayout = from, .newLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                              .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                              .image = img,
                              .subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT, 0, 1, 0, 1}};
    VkPipelineStageFlags tests = VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    vkCmdPipelineBarrier(cmd, tests, tests, 0, 0, NULL, 0, NULL, 1, &b);
}

/* The same attachments as the render passes, begun with vkCmdBeginRendering: the colour image
 * comes from (and test_vk_end returns it to) TRANSFER_SRC_OPTIMAL, as after a render pass. */
static void begin_rendering(test_vk *v, const float clear[4]) {
    VkImageLayout color_from = clear ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    layout_barrier(v->cmd, v->color, color_from, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_ACCESS_TRANSFER_READ_BIT,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
    depth_barrier(v->cmd, v->depth, clear ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    VkAttachmentLoadOp op = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    VkRenderingAttachmentInfo color = {.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO, .imageView = v->color_view,
                                       .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, .loadOp = op,
                                       .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
    if (clear) memcpy(color.clearValue.color.float32, clear, 4 * sizeof(float));
    VkRenderingAttachmentInfo depth = {.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO, .imageView = v->depth_view,
                                       .imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, .loadOp = op,
                                       .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
    depth.clearValue.depthStencil = (VkClearDepthStencilValue){1.0f, 0};
    VkRenderingInfo ri = {.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                          .renderArea = {{0, 0}, {(uint32_t)v->width, (uint32_t)v->height}}, .layerCount = 1,
                          .colorAttachmentCount = 1, .pColorAttachments = &color, .pDepthAttachment = &depth,
                          .pStencilAttachment = &depth};
    vkCmdBeginRendering(v->cmd, &ri);
}

VkCommandBuffer test_vk_begin_dynamic(test_vk *v, const float clear[4]) {
    if (!v->dynamic_rendering) return VK_NULL_HANDLE;
    v->target.render_pass = VK_NULL_HANDLE;
    v->dynamic_frame = 1;
    begin_commands(v);
    begin_rendering(v, clear);
    return v->cmd;
}

static void end_rendering(test_vk *v) {
    if (!v->dynamic_frame) {
        vkCmdEndRenderPass(v->cmd);
        return;
    }
    vkCmdEndRendering(v->cmd);
    layout_barrier(v->cmd, v->color, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                   VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
}

int test_vk_end(test_vk *v) {
    end_rendering(v);
    VkBufferImageCopy copy = {.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                              .imageExtent = {(uint32_t)v->width, (uint32_t)v->height, 1}};
    vkCmdCopyImageToBuffer(v->cmd, v->color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, v->readback.buffer, 1, &copy);
    VkMemoryBarrier mb = {.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER, .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                          .dstAccessMask = VK_ACCESS_HOST_READ_BIT};
    vkCmdPipelineBarrier(v->cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &mb, 0, NULL, 0, NULL);
    if (vkEndCommandBuffer(v->cmd) != VK_SUCCESS || submit_and_wait(v, v->cmd)) return -1;
    hfx_device_end_frame_vk(v->dev);
    void *map;
    size_t bytes = (size_t)v->width * (size_t)v->height * 4;
    if (vkMapMemory(v->device, v->readback.memory, 0, bytes, 0, &map) != VK_SUCCESS) return -1;
    memcpy(v->pixels, map, bytes);
    vkUnmapMemory(v->device, v->readback.memory);
    return 0;
}

const unsigned char *test_vk_pixel(const test_vk *v, int x, int y) { return v->pixels + 4 * ((size_t)y * v->width + x); }
const unsigned char *test_vk_pixels(const test_vk *v) { return v->pixels; }

int test_vk_buffer_make(test_vk *v, const void *data, size_t size, test_vk_buffer *out) {
    memset(out, 0, sizeof *out);
    VkBufferCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, .size = size,
                             .usage = VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_INDEX_BUFFER_BIT |
                                      VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT |
                                      VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT};
    if (vkCreateBuffer(v->device, &ci, NULL, &out->buffer) != VK_SUCCESS) return 0;
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(v->device, out->buffer, &req);
    if (!bind_memory(v, req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, &out->memory))
        return 0;
    vkBindBufferMemory(v->device, out->buffer, out->memory, 0);
    void *map;
    if (data && vkMapMemory(v->device, out->memory, 0, size, 0, &map) == VK_SUCCESS) {
        memcpy(map, data, size);
        vkUnmapMemory(v->device, out->memory);
    }
    return 1;
}

void test_vk_buffer_free(test_vk *v, test_vk_buffer *b) {
    if (b->buffer) vkDestroyBuffer(v->device, b->buffer, NULL);
    if (b->memory) vkFreeMemory(v->device, b->memory, NULL);
    memset(b, 0, sizeof *b);
}

static void level_barrier(VkCommandBuffer cmd, VkImage img, uint32_t level, VkImageLayout from, VkImageLayout to,
                          VkAccessFlags src, VkAccessFlags dst, VkPipelineStageFlags s1, VkPipelineStageFlags s2) {
    VkImageMemoryBarrier b = {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER, .srcAccessMask = src,
                              .dstAccessMask = dst, .oldLayout = from, .newLayout = to,
                              .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                              .image = img, .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, level, 1, 0, VK_REMAINING_ARRAY_LAYERS}};
    vkCmdPipelineBarrier(cmd, s1, s2, 0, 0, NULL, 0, NULL, 1, &b);
}

static void layout_barrier(VkCommandBuffer cmd, VkImage img, VkImageLayout from, VkImageLayout to,
                           VkAccessFlags src, VkAccessFlags dst, VkPipelineStageFlags s1, VkPipelineStageFlags s2) {
    VkImageMemoryBarrier b = {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER, .srcAccessMask = src,
                              .dstAccessMask = dst, .oldLayout = from, .newLayout = to,
                              .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED, .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                              .image = img, .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, VK_REMAINING_MIP_LEVELS, 0,
                                                                 VK_REMAINING_ARRAY_LAYERS}};
    vkCmdPipelineBarrier(cmd, s1, s2, 0, 0, NULL, 0, NULL, 1, &b);
}

static int half(int n, uint32_t i) { return n >> i > 0 ? n >> i : 1; }

/* Level i from level i - 1, halved with a linear blit (a 2 x 2 box, 2 x 2 x 2 for a volume, as
 * glGenerateMipmap's), every layer of a cube at once. */
static void blit_level(VkCommandBuffer cmd, VkImage img, uint32_t i, const image_shape *s) {
    uint32_t layers = shape_layers(s);
    level_barrier(cmd, img, i - 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                  VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkImageBlit b = {{VK_IMAGE_ASPECT_COLOR_BIT, i - 1, 0, layers}, {{0, 0, 0}, {half(s->w, i - 1), half(s->h, i - 1), half(s->d, i - 1)}},
                     {VK_IMAGE_ASPECT_COLOR_BIT, i, 0, layers}, {{0, 0, 0}, {half(s->w, i), half(s->h, i), half(s->d, i)}}};
    vkCmdBlitImage(cmd, img, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, img, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &b,
                   VK_FILTER_LINEAR);
    level_barrier(cmd, img, i - 1, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_ACCESS_TRANSFER_READ_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
}

/* Level 0 from staging (faces or slices one after the other), the others blitted down from it;
 * every level left shader-readable. */
static int upload(test_vk *v, test_vk_texture *t, const test_vk_buffer *staging, const image_shape *s) {
    VkCommandBufferAllocateInfo ai = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, .commandPool = v->pool,
                                      .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY, .commandBufferCount = 1};
    VkCommandBuffer cmd;
    if (vkAllocateCommandBuffers(v->device, &ai, &cmd) != VK_SUCCESS) return 0;
    VkCommandBufferBeginInfo bi = {.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                   .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    vkBeginCommandBuffer(cmd, &bi);
    layout_barrier(cmd, t->image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                   VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy copy = {.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, shape_layers(s)},
                              .imageExtent = {(uint32_t)s->w, (uint32_t)s->h, (uint32_t)s->d}};
    vkCmdCopyBufferToImage(cmd, staging->buffer, t->image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    for (uint32_t i = 1; i < s->levels; i++) blit_level(cmd, t->image, i, s);
    level_barrier(cmd, t->image, s->levels - 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                  VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT);
    vkEndCommandBuffer(cmd);
    int ok = submit_and_wait(v, cmd) == 0;
    vkFreeCommandBuffers(v->device, v->pool, 1, &cmd);
    return ok;
}

int test_vk_texture_make_kind(test_vk *v, test_vk_kind kind, int width, int height, int depth, int mipmapped,
                              const unsigned char *texels, test_vk_texture *out) {
    memset(out, 0, sizeof *out);
    image_shape s = {kind, width, height, kind == TEST_VK_3D && depth > 1 ? depth : 1, 1};
    int biggest = width > height ? width : height;
    if (s.d > biggest) biggest = s.d;
    while (mipmapped && (biggest >> s.levels) > 0) s.levels++;
    test_vk_buffer staging;
    size_t bytes = (size_t)width * (size_t)height * (size_t)s.d * shape_layers(&s) * 4;
    if (!test_vk_buffer_make(v, texels, bytes, &staging)) return 0;
    VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    int ok = make_shaped(v, VK_FORMAT_R8G8B8A8_UNORM, usage, VK_IMAGE_ASPECT_COLOR_BIT, &s, &out->image, &out->memory,
                         &out->view) &&
             upload(v, out, &staging, &s);
    test_vk_buffer_free(v, &staging);
    return ok;
}

int test_vk_texture_make(test_vk *v, int width, int height, const unsigned char *texels, test_vk_texture *out) {
    return test_vk_texture_make_kind(v, TEST_VK_2D, width, height, 1, 0, texels, out);
}

int test_vk_texture_make_mipmapped(test_vk *v, int width, int height, const unsigned char *texels, test_vk_texture *out) {
    return test_vk_texture_make_kind(v, TEST_VK_2D, width, height, 1, 1, texels, out);
}

void test_vk_texture_free(test_vk *v, test_vk_texture *t) {
    vkDeviceWaitIdle(v->device);
    if (t->view) vkDestroyImageView(v->device, t->view, NULL);
    if (t->image) vkDestroyImage(v->device, t->image, NULL);
    if (t->memory) vkFreeMemory(v->device, t->memory, NULL);
    memset(t, 0, sizeof *t);
}

int test_vk_write_png(const test_vk *v, const char *path) {
#ifdef HFX_TEST_PNG
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)v->width;
    img.height = (png_uint_32)v->height;
    img.format = PNG_FORMAT_RGBA;
    return png_image_write_to_file(&img, path, 0, v->pixels, (png_int_32)(v->width * 4), NULL) ? 0 : -1;
#else
    (void)v, (void)path;
    return -1;
#endif
}

