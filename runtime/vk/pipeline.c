/* pipeline.c: D3D9 render states as Vulkan pipeline state, and the device's pipeline cache
 * keyed by (program, render states, vertex layout, target): each pipeline is built once.
 *
 * Winding: the shaders keep D3D's clip space and flip y (hfx_pos_fixup.z = 1), so a picture
 * lands in the image with D3D9's row order, and a triangle clockwise on D3D's screen is
 * clockwise in Vulkan's framebuffer coordinates: front faces are VK_FRONT_FACE_CLOCKWISE and
 * CullMode = CCW culls the back ones. Depth is D3D's 0..1 natively. Viewport, scissor,
 * stencil reference, blend factor and depth bias are dynamic: they never make a new pipeline. */
#include <stdlib.h>
#include <string.h>

#include "vk/vk.h"

enum { DYNAMIC_COUNT = 5 };

void hfx_vk_states_of(const hfx_rs_value *rs, vk_states *st) {
    memset(st, 0, sizeof *st);
    st->cull = rs[HFX_ST_CULLMODE].i, st->fill = rs[HFX_ST_FILLMODE].i;
    st->zenable = rs[HFX_ST_ZENABLE].i != 0, st->zwrite = rs[HFX_ST_ZWRITEENABLE].i != 0, st->zfunc = rs[HFX_ST_ZFUNC].i;
    st->blend = rs[HFX_ST_ALPHABLENDENABLE].i != 0;
    if (st->blend) {
        st->src = rs[HFX_ST_SRCBLEND].i, st->dst = rs[HFX_ST_DESTBLEND].i, st->op = rs[HFX_ST_BLENDOP].i;
        st->sep_alpha = rs[HFX_ST_SEPARATEALPHABLENDENABLE].i != 0;
        st->src_a = st->sep_alpha ? rs[HFX_ST_SRCBLENDALPHA].i : st->src;
        st->dst_a = st->sep_alpha ? rs[HFX_ST_DESTBLENDALPHA].i : st->dst;
        st->op_a = st->sep_alpha ? rs[HFX_ST_BLENDOPALPHA].i : st->op;
    }
    st->write_mask[0] = rs[HFX_ST_COLORWRITEENABLE].i & 15, st->write_mask[1] = rs[HFX_ST_COLORWRITEENABLE1].i & 15;
    st->write_mask[2] = rs[HFX_ST_COLORWRITEENABLE2].i & 15, st->write_mask[3] = rs[HFX_ST_COLORWRITEENABLE3].i & 15;
    st->stencil = rs[HFX_ST_STENCILENABLE].i != 0;
    if (st->stencil) {
        st->two_sided = rs[HFX_ST_TWOSIDEDSTENCILMODE].i != 0;
        st->s_fail[0] = rs[HFX_ST_STENCILFAIL].i, st->s_zfail[0] = rs[HFX_ST_STENCILZFAIL].i;
        st->s_pass[0] = rs[HFX_ST_STENCILPASS].i, st->s_func[0] = rs[HFX_ST_STENCILFUNC].i;
        st->s_fail[1] = st->two_sided ? rs[HFX_ST_CCW_STENCILFAIL].i : st->s_fail[0];
        st->s_zfail[1] = st->two_sided ? rs[HFX_ST_CCW_STENCILZFAIL].i : st->s_zfail[0];
        st->s_pass[1] = st->two_sided ? rs[HFX_ST_CCW_STENCILPASS].i : st->s_pass[0];
        st->s_func[1] = st->two_sided ? rs[HFX_ST_CCW_STENCILFUNC].i : st->s_func[0];
        st->s_mask = rs[HFX_ST_STENCILMASK].i, st->s_write = rs[HFX_ST_STENCILWRITEMASK].i;
    }
    st->depth_bias = rs[HFX_ST_DEPTHBIAS].f[0] != 0.0f || rs[HFX_ST_SLOPESCALEDEPTHBIAS].f[0] != 0.0f;
    st->ms_mask = rs[HFX_ST_MULTISAMPLEMASK].i;
}

/* D3DCMPFUNC (1 NEVER .. 8 ALWAYS) is VkCompareOp + 1. */
static VkCompareOp compare_op(int32_t d3d) { return d3d >= 1 && d3d <= 8 ? (VkCompareOp)(d3d - 1) : VK_COMPARE_OP_ALWAYS; }
/* D3DSTENCILOP (1 KEEP .. 8 DECR) is VkStencilOp + 1. */
static VkStencilOp stencil_op(int32_t d3d) { return d3d >= 1 && d3d <= 8 ? (VkStencilOp)(d3d - 1) : VK_STENCIL_OP_KEEP; }
/* D3DBLENDOP (1 ADD .. 5 MAX) is VkBlendOp + 1. */
static VkBlendOp blend_op(int32_t d3d) { return d3d >= 1 && d3d <= 5 ? (VkBlendOp)(d3d - 1) : VK_BLEND_OP_ADD; }

/* A D3DBLEND factor; BOTHSRCALPHA / BOTHINVSRCALPHA set the destination too (D3D9 ignores the
 * destination state then). */
static VkBlendFactor blend_factor(int32_t d3d, int dst) {
    static const VkBlendFactor map[18] = {
        VK_BLEND_FACTOR_ONE, VK_BLEND_FACTOR_ZERO, VK_BLEND_FACTOR_ONE, VK_BLEND_FACTOR_SRC_COLOR,
        VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR, VK_BLEND_FACTOR_SRC_ALPHA, VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA,
        VK_BLEND_FACTOR_DST_ALPHA, VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA, VK_BLEND_FACTOR_DST_COLOR,
        VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR, VK_BLEND_FACTOR_SRC_ALPHA_SATURATE, VK_BLEND_FACTOR_SRC_ALPHA,
        VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA, VK_BLEND_FACTOR_CONSTANT_COLOR, VK_BLEND_FACTOR_ONE_MINUS_CONSTANT_COLOR,
        VK_BLEND_FACTOR_SRC1_COLOR, VK_BLEND_FACTOR_ONE_MINUS_SRC1_COLOR};
    if (d3d < 1 || d3d > 17) return dst ? VK_BLEND_FACTOR_ZERO : VK_BLEND_FACTOR_ONE;
    if (dst && d3d == 12) return VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    if (dst && d3d == 13) return VK_BLEND_FACTOR_SRC_ALPHA;
    return map[d3d];
}

static void blend_pair(int32_t src, int32_t dst, VkBlendFactor *s, VkBlendFactor *d) {
    *s = blend_factor(src, 0);
    *d = (src == 12 || src == 13) ? blend_factor(src, 1) : blend_factor(dst, 1);
}

static VkCullModeFlags cull_mode(int32_t d3d) {
    return d3d == 3 ? VK_CULL_MODE_BACK_BIT : d3d == 2 ? VK_CULL_MODE_FRONT_BIT : VK_CULL_MODE_NONE;
}

static VkStencilOpState stencil_face(const vk_states *st, int face) {
    VkStencilOpState s = {stencil_op(st->s_fail[face]), stencil_op(st->s_pass[face]), stencil_op(st->s_zfail[face]),
                          compare_op(st->s_func[face]), (uint32_t)st->s_mask, (uint32_t)st->s_write, 0};
    return s;
}

static void attachment_blend(const vk_states *st, int i, VkPipelineColorBlendAttachmentState *a) {
    memset(a, 0, sizeof *a);
    a->colorWriteMask = (VkColorComponentFlags)st->write_mask[i]; /* D3D's R1 G2 B4 A8 are Vulkan's bits */
    if (!st->blend) return;
    a->blendEnable = VK_TRUE;
    blend_pair(st->src, st->dst, &a->srcColorBlendFactor, &a->dstColorBlendFactor);
    blend_pair(st->src_a, st->dst_a, &a->srcAlphaBlendFactor, &a->dstAlphaBlendFactor);
    a->colorBlendOp = blend_op(st->op);
    a->alphaBlendOp = blend_op(st->op_a);
}

/* Attributes by semantic from the layout; one the layout lacks reads hfx's constant
 * (0, 0, 0, 1) at binding VK_ZERO_BINDING, as GL's disabled arrays read. */
typedef struct vertex_input {
    VkVertexInputBindingDescription bindings[VK_MAX_ATTRIBUTES + 1];
    VkVertexInputAttributeDescription attrs[VK_MAX_ATTRIBUTES];
    VkPipelineVertexInputStateCreateInfo info;
} vertex_input;

static void add_binding(vertex_input *v, uint32_t binding, uint32_t stride) {
    for (uint32_t i = 0; i < v->info.vertexBindingDescriptionCount; i++)
        if (v->bindings[i].binding == binding) return;
    v->bindings[v->info.vertexBindingDescriptionCount++] = (VkVertexInputBindingDescription){binding, stride,
                                                                                             VK_VERTEX_INPUT_RATE_VERTEX};
}

static int vertex_input_of(const vk_program *p, const hfx_vertex_layout *l, vertex_input *v) {
    int zero = 0;
    memset(v, 0, sizeof *v);
    v->info.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    for (uint32_t a = 0; a < p->fp->attribute_count && a < VK_MAX_ATTRIBUTES; a++) {
        const hfx_fx_attribute *at = &p->fp->attributes[a];
        const hfx_vertex_element *e = NULL;
        for (size_t i = 0; l && i < l->count && !e; i++)
            if (strcmp(l->semantics[i], at->semantic) == 0) e = &l->e[i];
        VkVertexInputAttributeDescription *d = &v->attrs[v->info.vertexAttributeDescriptionCount++];
        if (e) {
            *d = (VkVertexInputAttributeDescription){(uint32_t)at->location, e->binding, e->format, e->offset};
            add_binding(v, e->binding, e->stride);
        } else {
            *d = (VkVertexInputAttributeDescription){(uint32_t)at->location, VK_ZERO_BINDING,
                                                     VK_FORMAT_R32G32B32A32_SFLOAT, 0};
            add_binding(v, VK_ZERO_BINDING, 0);
            zero = 1;
        }
    }
    v->info.pVertexBindingDescriptions = v->bindings;
    v->info.pVertexAttributeDescriptions = v->attrs;
    return zero;
}

typedef struct pso_info {
    VkPipelineShaderStageCreateInfo stages[2];
    vertex_input vi;
    VkPipelineInputAssemblyStateCreateInfo ia;
    VkPipelineViewportStateCreateInfo vp;
    VkPipelineRasterizationStateCreateInfo rs;
    VkPipelineMultisampleStateCreateInfo ms;
    VkSampleMask sample_mask;
    VkPipelineDepthStencilStateCreateInfo ds;
    VkPipelineColorBlendAttachmentState blend[4];
    VkPipelineColorBlendStateCreateInfo cb;
    VkDynamicState dynamic[DYNAMIC_COUNT];
    VkPipelineDynamicStateCreateInfo dyn;
    VkPipelineRenderingCreateInfo rendering;
} pso_info;

static void fixed_state(struct hfx_vk_device *vk, const vk_pso_key *k, pso_info *o) {
    const vk_states *st = &k->st;
    o->ia = (VkPipelineInputAssemblyStateCreateInfo){.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
                                                     .topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
    o->vp = (VkPipelineViewportStateCreateInfo){.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                                .viewportCount = 1, .scissorCount = 1};
    VkPolygonMode fill = !vk->fill_modes || st->fill == 3 ? VK_POLYGON_MODE_FILL
                         : st->fill == 2                  ? VK_POLYGON_MODE_LINE
                                                          : VK_POLYGON_MODE_POINT;
    o->rs = (VkPipelineRasterizationStateCreateInfo){.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
                                                     .polygonMode = fill, .cullMode = cull_mode(st->cull),
                                                     .frontFace = VK_FRONT_FACE_CLOCKWISE,
                                                     .depthBiasEnable = st->depth_bias ? VK_TRUE : VK_FALSE,
                                                     .lineWidth = 1.0f};
    o->sample_mask = (VkSampleMask)st->ms_mask;
    o->ms = (VkPipelineMultisampleStateCreateInfo){.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
                                                   .rasterizationSamples = (VkSampleCountFlagBits)k->samples,
                                                   .pSampleMask = &o->sample_mask};
    int has_depth = k->depth != VK_FORMAT_UNDEFINED;
    o->ds = (VkPipelineDepthStencilStateCreateInfo){.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
                                                    .depthTestEnable = has_depth && st->zenable,
                                                    .depthWriteEnable = has_depth && st->zenable && st->zwrite,
                                                    .depthCompareOp = compare_op(st->zfunc),
                                                    .stencilTestEnable = has_depth && st->stencil,
                                                    .front = stencil_face(st, 0), .back = stencil_face(st, 1),
                                                    .maxDepthBounds = 1.0f};
}

static void blend_and_dynamic(const vk_pso_key *k, pso_info *o) {
    for (uint32_t i = 0; i < k->color_count; i++) attachment_blend(&k->st, (int)i, &o->blend[i]);
    o->cb = (VkPipelineColorBlendStateCreateInfo){.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                                  .attachmentCount = k->color_count, .pAttachments = o->blend};
    static const VkDynamicState dyn[DYNAMIC_COUNT] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR,
                                                      VK_DYNAMIC_STATE_STENCIL_REFERENCE,
                                                      VK_DYNAMIC_STATE_BLEND_CONSTANTS, VK_DYNAMIC_STATE_DEPTH_BIAS};
    memcpy(o->dynamic, dyn, sizeof dyn);
    o->dyn = (VkPipelineDynamicStateCreateInfo){.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
                                                .dynamicStateCount = DYNAMIC_COUNT, .pDynamicStates = o->dynamic};
    int stencil = k->depth == VK_FORMAT_S8_UINT || k->depth == VK_FORMAT_D16_UNORM_S8_UINT ||
                  k->depth == VK_FORMAT_D24_UNORM_S8_UINT || k->depth == VK_FORMAT_D32_SFLOAT_S8_UINT;
    o->rendering = (VkPipelineRenderingCreateInfo){.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                                   .colorAttachmentCount = k->color_count,
                                                   .pColorAttachmentFormats = k->color,
                                                   .depthAttachmentFormat = k->depth == VK_FORMAT_S8_UINT ? VK_FORMAT_UNDEFINED : k->depth,
                                                   .stencilAttachmentFormat = stencil ? k->depth : VK_FORMAT_UNDEFINED};
}

static VkResult create_pipeline(struct hfx_vk_device *vk, const vk_pso_key *k, VkPipeline *out, int *needs_zero) {
    const vk_program *p = k->program;
    pso_info *o = calloc(1, sizeof *o);
    if (!o) return VK_ERROR_OUT_OF_HOST_MEMORY;
    o->stages[0] = (VkPipelineShaderStageCreateInfo){.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                                                     .stage = VK_SHADER_STAGE_VERTEX_BIT, .module = p->vs, .pName = "main"};
    o->stages[1] = o->stages[0];
    o->stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT, o->stages[1].module = hfx_vk_fragment_module(p, k->color_count);
    *needs_zero = vertex_input_of(p, k->layout, &o->vi);
    fixed_state(vk, k, o);
    blend_and_dynamic(k, o);
    VkGraphicsPipelineCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                       .pNext = k->render_pass ? NULL : &o->rendering, .stageCount = 2,
                                       .pStages = o->stages, .pVertexInputState = &o->vi.info,
                                       .pInputAssemblyState = &o->ia, .pViewportState = &o->vp,
                                       .pRasterizationState = &o->rs, .pMultisampleState = &o->ms,
                                       .pDepthStencilState = &o->ds, .pColorBlendState = &o->cb,
                                       .pDynamicState = &o->dyn, .layout = p->layout,
                                       .renderPass = k->render_pass, .subpass = k->subpass};
    VkResult r = vk->fn.CreateGraphicsPipelines(vk->device, VK_NULL_HANDLE, 1, &ci, NULL, out);
    free(o);
    return r;
}

static uint64_t hash_key(const vk_pso_key *k) {
    const unsigned char *b = (const unsigned char *)k;
    uint64_t h = 1469598103934665603ull;
    for (size_t i = 0; i < sizeof *k; i++) h = (h ^ b[i]) * 1099511628211ull;
    return h;
}

/* The key must be zeroed before it is filled (padding takes part in the comparison). */
static const vk_pso *remember(struct hfx_vk_device *vk, const vk_pso_key *key, uint32_t i) {
    memcpy(&vk->last_key, key, sizeof *key); /* padding included: keys are compared bytewise */
    vk->last_pso = i;
    return &vk->psos[i];
}

int hfx_vk_pipeline(hfx_device *dev, const vk_pso_key *key, const vk_pso **out) {
    struct hfx_vk_device *vk = dev->vk;
    if (vk->last_pso < vk->pso_count && memcmp(&vk->last_key, key, sizeof *key) == 0) {
        *out = &vk->psos[vk->last_pso];
        return HFX_OK;
    }
    uint64_t h = hash_key(key);
    for (uint32_t i = 0; i < vk->pso_count; i++)
        if (vk->psos[i].hash == h && memcmp(&vk->psos[i].key, key, sizeof *key) == 0) {
            *out = remember(vk, key, i);
            return HFX_OK;
        }
    if (!HFX_GROW(vk->psos, vk->pso_count, vk->pso_cap, 16)) return hfx_rt_fail(dev, HFX_ERR_MEMORY, "out of memory");
    vk_pso *pso = &vk->psos[vk->pso_count];
    pso->hash = h;
    memcpy(&pso->key, key, sizeof *key);
    VkResult r = create_pipeline(vk, key, &pso->pipeline, &pso->needs_zero);
    if (r != VK_SUCCESS) return hfx_vk_fail(dev, r, "vkCreateGraphicsPipelines");
    vk->pso_count++;
    vk->psos_made++;
    *out = remember(vk, key, vk->pso_count - 1);
    return HFX_OK;
}

/* A program goes away: so do its pipelines (a later program could take its address). */
void hfx_vk_pipelines_forget(hfx_device *dev, const void *program) {
    struct hfx_vk_device *vk = dev->vk;
    uint32_t kept = 0;
    for (uint32_t i = 0; i < vk->pso_count; i++) {
        if (vk->psos[i].key.program == program) vk->fn.DestroyPipeline(vk->device, vk->psos[i].pipeline, NULL);
        else vk->psos[kept++] = vk->psos[i];
    }
    vk->pso_count = kept;
    vk->last_pso = UINT32_MAX;
    dev->applied = NULL; /* its pipeline may be gone */
}

void hfx_vk_pipelines_free(hfx_device *dev) {
    struct hfx_vk_device *vk = dev->vk;
    for (uint32_t i = 0; i < vk->pso_count; i++) vk->fn.DestroyPipeline(vk->device, vk->psos[i].pipeline, NULL);
    free(vk->psos);
    vk->psos = NULL;
    dev->applied = NULL;
    vk->pso_count = vk->pso_cap = 0;
}
