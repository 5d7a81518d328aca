/* sampler.c: D3D9 sampler states as VkSamplers, cached per device by their description (an
 * effect's sampler_state blocks, with states that read parameters resolved at Apply).
 *
 * - MinFilter / MagFilter Point (or None) sample the nearest texel, anything else linearly;
 *   Anisotropic turns on anisotropy (MaxAnisotropy, clamped to the device's) when the device
 *   was created with samplerAnisotropy. MipFilter None samples level 0 only, Point / Linear
 *   pick mipmapMode.
 * - AddressU/V/W: Wrap, Mirror, Clamp, Border, MirrorOnce (mirror-clamp-to-edge when enabled,
 *   else mirrored repeat). BorderColor: the colour itself where the application enabled
 *   VK_EXT_custom_border_color (hfx_vulkan_desc.custom_border_colors), else the nearest of
 *   Vulkan's three fixed border colours.
 * - MaxMipLevel (D3D's most detailed level used) is minLod; MipMapLodBias is mipLodBias. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "vk/vk.h"

static VkSamplerAddressMode address_mode(const struct hfx_vk_device *vk, int32_t d3d) {
    switch (d3d) {
    case 2: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case 3: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case 4: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    case 5: return vk->mirror_once ? VK_SAMPLER_ADDRESS_MODE_MIRROR_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    default: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    }
}

static VkFilter filter(int32_t d3d) { return d3d <= 1 ? VK_FILTER_NEAREST : VK_FILTER_LINEAR; }

/* Vulkan's fixed border colours, in the order that breaks ties toward transparent black. */
static const struct { VkBorderColor id; float rgba[4]; } FIXED_BORDERS[3] = {
    {VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK, {0, 0, 0, 0}},
    {VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK, {0, 0, 0, 1}},
    {VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE, {1, 1, 1, 1}},
};

/* The fixed colour nearest c; *off: how far from it (0: exact). */
static VkBorderColor nearest_border(const float c[4], float *off) {
    int best = 0;
    for (int k = 0; k < 3; k++) {
        float d = 0;
        for (int i = 0; i < 4; i++) d += fabsf(c[i] - FIXED_BORDERS[k].rgba[i]);
        if (k == 0 || d < *off) best = k, *off = d;
    }
    return FIXED_BORDERS[best].id;
}

static bool uses_border(const hfx_sampler_desc *d) { return d->address[0] == 4 || d->address[1] == 4 || d->address[2] == 4; }

/* D3D9's BorderColor: the nearest fixed colour, or, where the application enabled custom ones
 * and it is not exact, the colour itself (only where a border is sampled: such samplers count
 * against maxCustomBorderColorSamplers). */
static void border(const struct hfx_vk_device *vk, const hfx_sampler_desc *d, VkSamplerCreateInfo *ci,
                   VkSamplerCustomBorderColorCreateInfoEXT *custom) {
    float off = 0;
    ci->borderColor = nearest_border(d->border, &off);
    if (!vk->custom_border || !uses_border(d) || off == 0) return;
    memset(custom, 0, sizeof *custom);
    custom->sType = VK_STRUCTURE_TYPE_SAMPLER_CUSTOM_BORDER_COLOR_CREATE_INFO_EXT;
    memcpy(custom->customBorderColor.float32, d->border, sizeof custom->customBorderColor.float32);
    custom->format = VK_FORMAT_UNDEFINED; /* customBorderColorWithoutFormat */
    ci->pNext = custom;
    ci->borderColor = VK_BORDER_COLOR_FLOAT_CUSTOM_EXT;
}

static void sampler_info(const struct hfx_vk_device *vk, const hfx_sampler_desc *d, VkSamplerCreateInfo *ci,
                         VkSamplerCustomBorderColorCreateInfoEXT *custom) {
    memset(ci, 0, sizeof *ci);
    ci->sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    ci->magFilter = filter(d->mag);
    ci->minFilter = filter(d->min);
    ci->mipmapMode = d->mip == 2 || d->mip == 3 ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    ci->addressModeU = address_mode(vk, d->address[0]);
    ci->addressModeV = address_mode(vk, d->address[1]);
    ci->addressModeW = address_mode(vk, d->address[2]);
    ci->mipLodBias = d->lod_bias;
    int aniso = vk->max_anisotropy > 0 && (d->min == 3 || d->mag == 3);
    ci->anisotropyEnable = aniso ? VK_TRUE : VK_FALSE;
    float a = d->max_anisotropy < 1 ? 1.0f : (float)d->max_anisotropy;
    ci->maxAnisotropy = aniso ? (a > vk->max_anisotropy ? vk->max_anisotropy : a) : 1.0f;
    ci->minLod = d->mip ? (float)d->max_mip_level : 0.0f;
    ci->maxLod = d->mip ? VK_LOD_CLAMP_NONE : 0.0f;
    border(vk, d, ci, custom);
}

int hfx_vk_sampler(hfx_device *dev, const hfx_sampler_desc *d, VkSampler *out) {
    struct hfx_vk_device *vk = dev->vk;
    for (uint32_t i = 0; i < vk->sampler_count; i++)
        if (memcmp(&vk->samplers[i].desc, d, sizeof *d) == 0) {
            *out = vk->samplers[i].sampler;
            return HFX_OK;
        }
    if (!HFX_GROW(vk->samplers, vk->sampler_count, vk->sampler_cap, 8))
        return hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
    VkSamplerCreateInfo ci;
    VkSamplerCustomBorderColorCreateInfoEXT custom;
    sampler_info(vk, d, &ci, &custom);
    VkResult r = vk->fn.CreateSampler(vk->device, &ci, NULL, out);
    if (r != VK_SUCCESS) return hfx_vk_fail(dev, r, "vkCreateSampler");
    vk->samplers[vk->sampler_count++] = (vk_sampler_entry){*d, *out};
    return HFX_OK;
}

void hfx_vk_samplers_free(hfx_device *dev) {
    struct hfx_vk_device *vk = dev->vk;
    for (uint32_t i = 0; i < vk->sampler_count; i++) vk->fn.DestroySampler(vk->device, vk->samplers[i].sampler, NULL);
    free(vk->samplers);
    vk->samplers = NULL;
    vk->sampler_count = vk->sampler_cap = 0;
}

/* Each sampler_state block: constant states into base, parameter-reading ones kept for Apply. */
void hfx_vk_fx_samplers_make(hfx_shared *sh) {
    for (uint32_t i = 0; i < sh->fx->sampler_count; i++) {
        vk_fx_sampler *s = &sh->vk->samplers[i];
        hfx_sampler_desc_of(sh->fx, i, &s->base, s->dynamic, &s->dynamic_count);
    }
}
