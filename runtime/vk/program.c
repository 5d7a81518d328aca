/* program.c: a compiled program on Vulkan: its two shader modules (HFX_TARGET_SPIRV_VK), the
 * descriptor set layout (the uniform block as a dynamic uniform buffer, then one combined image
 * sampler per sampler the program reads) and pipeline layout, and the map from the effect's
 * parameters to the block: packed ones into hfx_c (the D3D9 register file, laid out as GL's
 * hfx_c[]), the others leaf by leaf at the offsets the module declares (reflect.c). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* libspirv.h defines (not declares) a const with external linkage; renamed here so that a
 * program including it too (the compiler's tests) links with this file. */
#define kDefaultMaxIdBound hfx_vk_spv_max_id_bound
#include <spirv-tools/libspirv.h>
#undef kDefaultMaxIdBound

#include "spirv_iface.h"
#include "spirv_loc.h"
#include "vk/vk.h"

typedef struct build {
    hfx_shared *sh;
    vk_program *p;
    vk_block block;
    uint32_t cap;
} build;

static const char *name_of(const hfx_shared *sh) { return sh->fx->source_name ? sh->fx->source_name : "effect"; }

/* Once per device, not per module: the context holds the grammar tables the validator reads. */
int hfx_vk_validator_make(struct hfx_vk_device *vk) {
    vk->spirv = spvContextCreate(SPV_ENV_VULKAN_1_0);
    return vk->spirv ? HFX_OK : HFX_ERR_MEMORY;
}

void hfx_vk_validator_free(struct hfx_vk_device *vk) {
    if (vk->spirv) spvContextDestroy(vk->spirv);
    vk->spirv = NULL;
}

/* "technique 'T', pass 'P'" of the first pass (or shader-array variant) that uses program index,
 * for messages: programs are per pass, so that names the code the user wrote. */
static void program_user(const hfx_fx_effect *fx, uint32_t index, char *out, size_t n) {
    uint32_t pass = HFX_NONE;
    for (uint32_t i = 0; i < fx->pass_count && pass == HFX_NONE; i++)
        if (fx->passes[i].program == index) pass = i;
    for (uint32_t i = 0; i < fx->variant_count && pass == HFX_NONE; i++)
        if (fx->variants[i].program == index && fx->variants[i].pass < fx->pass_count) pass = fx->variants[i].pass;
    const char *tech = "";
    for (uint32_t t = 0; t < fx->technique_count && pass != HFX_NONE; t++)
        if (pass - fx->techniques[t].first_pass < fx->techniques[t].pass_count) tech = fx->techniques[t].name;
    if (pass == HFX_NONE) snprintf(out, n, "program %u", index);
    else snprintf(out, n, "technique '%s', pass '%s'", tech ? tech : "", fx->passes[pass].name ? fx->passes[pass].name : "");
}

/* Whether SPIRV-Tools accepts words[0..count) for Vulkan 1.0; if not, its reason's first line
 * (the disassembled instruction follows it) in reason[256]. The reason can quote the module's
 * own bytes, so what is not printable ASCII shows as '?'. */
int hfx_vk_spirv_valid(const struct hfx_vk_device *vk, const uint32_t *words, size_t count, char reason[256]) {
    spv_diagnostic diag = NULL;
    spv_result_t r = spvValidateBinary(vk->spirv, words, count, &diag);
    if (r != SPV_SUCCESS) {
        const char *text = diag && diag->error ? diag->error : "no reason given";
        size_t n = 0;
        for (; text[n] && text[n] != '\n' && n + 1 < 256; n++)
            reason[n] = (unsigned char)text[n] < 0x20 || (unsigned char)text[n] > 0x7e ? '?' : text[n];
        reason[n] = '\0';
    }
    spvDiagnosticDestroy(diag);
    return r == SPV_SUCCESS;
}

/* Vulkan leaves invalid SPIR-V undefined (a driver may crash or hang on it), so a module the
 * validator refuses is the effect's load error and never reaches vkCreateShaderModule. Size and
 * magic first: the cheap refusal of what is not SPIR-V at all. */
static int check_module(hfx_shared *sh, uint32_t index, const hfx_fx_code *code, const char *what, bool *block) {
    const uint32_t *words = (const uint32_t *)(const void *)code->data;
    char user[160], reason[256];
    if (!code->data || code->size < 20 || code->size % 4)
        return hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "%s: the %s shader has no SPIR-V for Vulkan (compile with the "
                           "spirv-vk target)", name_of(sh), what);
    program_user(sh->fx, index, user, sizeof user);
    if (words[0] != 0x07230203u)
        return hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "%s: %s: the %s shader's code is not SPIR-V (no magic number)",
                           name_of(sh), user, what);
    if (!hfx_vk_spirv_valid(sh->dev->vk, words, code->size / 4, reason))
        return hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "%s: %s: the %s shader's SPIR-V is not valid for Vulkan 1.0: %s",
                           name_of(sh), user, what, reason);
    /* valid SPIR-V may still name descriptors the pipeline layout lacks, which a driver need not survive */
    const char *slot = hfx_vk_check_slots(words, code->size / 4, sh->fx->programs[index].sampler_count, block);
    if (slot)
        return hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "%s: %s: the %s shader's SPIR-V declares %s", name_of(sh), user, what,
                           slot);
    return HFX_OK;
}

static int make_module(hfx_shared *sh, uint32_t index, const hfx_fx_code *code, const char *what, bool *block,
                       VkShaderModule *out) {
    struct hfx_vk_device *vk = sh->dev->vk;
    int rc = check_module(sh, index, code, what, block);
    if (rc) return rc;
    VkShaderModuleCreateInfo ci = {.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO, .codeSize = code->size,
                                   .pCode = (const uint32_t *)(const void *)code->data};
    VkResult r = vk->fn.CreateShaderModule(vk->device, &ci, NULL, out);
    return r == VK_SUCCESS ? HFX_OK : hfx_vk_fail(sh->dev, r, "vkCreateShaderModule");
}

/* Whether the attributes the pipeline binds (vertex_input_of: the first VK_MAX_ATTRIBUTES, at
 * their own locations) feed every input the vertex shader reads, on locations the device has. */
static const char *attributes_feed(const hfx_fx_program *fp, const hfx_spirv_iface *in, uint32_t max) {
    uint8_t given[HFX_SPIRV_MAX_LOCATIONS] = {0};
    for (uint32_t a = 0; a < fp->attribute_count && a < VK_MAX_ATTRIBUTES; a++) {
        int32_t l = fp->attributes[a].location;
        if (l < 0 || (uint32_t)l >= max || (uint32_t)l >= HFX_SPIRV_MAX_LOCATIONS) return "an attribute location past the device's";
        if (given[l]++) return "two attributes on one location";
    }
    for (uint32_t l = 0; l < in->end; l++)
        if (in->kind[l] && !given[l]) return "a vertex shader input no attribute provides";
    return NULL;
}

/* SPIRV-Tools checks each module alone; the two stages must also agree with each other, with the
 * program's attributes and with the device's limits, or pipeline creation is undefined (lavapipe
 * writes out of bounds on a location past its tables). Checked once, when the program is built. */
static int check_interface(hfx_shared *sh, uint32_t index, const hfx_fx_program *fp) {
    const struct hfx_vk_device *vk = sh->dev->vk;
    const hfx_fx_code *vs = &fp->code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV_VK], *fs = &fp->code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV_VK];
    const uint32_t *vw = (const uint32_t *)(const void *)vs->data, *fw = (const uint32_t *)(const void *)fs->data;
    hfx_spirv_iface vin, vout, fin, fout;
    const char *why = hfx_spirv_interface(vw, vs->size / 4, 0, &vin);
    if (!why) why = hfx_spirv_interface(vw, vs->size / 4, 1, &vout);
    if (!why) why = hfx_spirv_interface(fw, fs->size / 4, 0, &fin);
    if (!why) why = hfx_spirv_interface(fw, fs->size / 4, 1, &fout);
    if (!why && (vout.end > vk->max_varyings || fin.end > vk->max_varyings)) why = "more varyings than the device has";
    if (!why && fout.end > vk->max_colors) why = "more colour outputs than the device has";
    if (!why) why = hfx_spirv_interface_fed(&vout, &fin);
    if (!why) why = attributes_feed(fp, &vin, vk->max_attributes);
    if (!why) return HFX_OK;
    char user[160];
    program_user(sh->fx, index, user, sizeof user);
    return hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "%s: %s: the shaders' interface has %s", name_of(sh), user, why);
}

/* Each sampler binding's dimension: the effect sampler's, unless a module samples it as another. */
static int read_sampler_dims(hfx_shared *sh, const hfx_fx_program *fp, vk_program *p) {
    for (uint32_t k = 0; k < p->sampler_count; k++) {
        uint32_t s = fp->samplers[k].sampler;
        p->sampler_dims[k] = (uint8_t)(s < sh->fx->sampler_count ? sh->fx->samplers[s].dim : HFX_FX_DIM_2D);
    }
    for (int st = 0; st < HFX_STAGE_COUNT; st++) {
        const hfx_fx_code *c = &fp->code[st][HFX_TARGET_SPIRV_VK];
        if (hfx_vk_sampler_dims((const uint32_t *)(const void *)c->data, c->size / 4, p->sampler_dims, p->sampler_count))
            return hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "%s: a shader's SPIR-V could not be read", name_of(sh));
    }
    return HFX_OK;
}

static const vk_leaf *find_leaf(const vk_block *b, const char *path) {
    for (uint32_t i = 0; i < b->count; i++)
        if (strcmp(b->leaves[i].path, path) == 0) return &b->leaves[i];
    return NULL;
}

static int32_t offset_of(const vk_block *b, const char *path) {
    const vk_leaf *l = find_leaf(b, path);
    return l ? (int32_t)l->offset : -1;
}

static uint16_t upload_kind(const hfx_fx_param *p, const vk_leaf *l) {
    int data_float = p->type == HFX_TYPE_FLOAT, leaf_float = l->base == VK_BASE_FLOAT;
    if (data_float == leaf_float) return VK_UP_SAME;
    return leaf_float ? VK_UP_TO_FLOAT : VK_UP_TO_INT;
}

/* One leaf of the block from parameter p's words (an array: count elements); a hfx_param_leaves
 * callback, by the same paths as GL's uniform names. */
static int add_upload(void *ctx, const char *path, const hfx_fx_param *p) {
    build *b = ctx;
    const vk_leaf *l = find_leaf(&b->block, path);
    if (!l) return HFX_OK; /* not in the block: the program does not read it */
    uint32_t elems = p->elements ? p->elements : 1, per = p->words / elems;
    if (per != (uint32_t)l->comps * l->cols) {
        hfx_shared_warn(b->sh, NULL, "uniform '%s': its type does not match parameter '%s'; not uploaded", path,
                        p->name ? p->name : "");
        return HFX_OK;
    }
    if (!HFX_GROW(b->p->uploads, b->p->upload_count, b->cap, 8)) return HFX_ERR_MEMORY;
    vk_upload *u = &b->p->uploads[b->p->upload_count++];
    u->dst = l->offset, u->src = p->offset;
    u->count = l->count ? (l->count < elems ? l->count : elems) : 1;
    u->stride = l->stride, u->comps = l->comps, u->cols = l->cols, u->col_stride = l->col_stride;
    u->kind = upload_kind(p, l);
    return HFX_OK;
}

static void pack_slot(vk_slot *slot, const hfx_fx_effect *fx, const hfx_fx_uniform_use *u) {
    slot->mode = VK_SLOT_REG;
    slot->reg = u->reg;
    slot->reg_rows = (uint16_t)hfx_fx_param_packable(fx, u->param);
    slot->reg_cols = (uint16_t)fx->params[u->param].cols;
    slot->offset = fx->params[u->param].offset;
}

static int map_uniforms(build *b, const hfx_fx_program *fp) {
    vk_program *p = b->p;
    const hfx_fx_effect *fx = b->sh->fx;
    p->slots = calloc((size_t)fx->top_param_count + 1, sizeof *p->slots);
    if (!p->slots) return HFX_ERR_MEMORY;
    for (uint32_t i = 0; i < fp->uniform_count; i++) {
        uint32_t param = fp->uniforms[i].param;
        if (param >= fx->top_param_count || !fx->params[param].glsl_name || p->slots[param].mode) continue;
        vk_slot *slot = &p->slots[param];
        if (hfx_fx_use_packed(fp, &fp->uniforms[i])) {
            if (p->regs_at >= 0) pack_slot(slot, fx, &fp->uniforms[i]);
            continue;
        }
        slot->first = p->upload_count;
        int rc = hfx_param_leaves(fx, param, fx->params[param].glsl_name, add_upload, b);
        if (rc) return rc;
        slot->count = p->upload_count - slot->first;
        if (slot->count) slot->mode = VK_SLOT_OTHER;
    }
    return HFX_OK;
}

/* The block's layout from whichever stage declares it (both declare the same one). */
static int read_block(build *b, const hfx_fx_program *fp) {
    for (int s = 0; s < HFX_STAGE_COUNT; s++) {
        const hfx_fx_code *c = &fp->code[s][HFX_TARGET_SPIRV_VK];
        if (hfx_vk_reflect_block((const uint32_t *)(const void *)c->data, c->size / 4, &b->block))
            return hfx_rt_fail(b->sh->dev, HFX_ERR_LOAD, "%s: a shader's SPIR-V could not be read", name_of(b->sh));
        if (b->block.count) break;
    }
    vk_program *p = b->p;
    p->block_size = (b->block.size + 15u) & ~15u;
    p->regs_at = offset_of(&b->block, "hfx_c");
    p->fixup_at = offset_of(&b->block, "hfx_pos_fixup");
    p->alpha_func_at = offset_of(&b->block, "hfx_alpha_func");
    p->alpha_ref_at = offset_of(&b->block, "hfx_alpha_ref");
    p->reg_count = fp->reg_count;
    return HFX_OK;
}

static int make_layouts(hfx_shared *sh, vk_program *p) {
    struct hfx_vk_device *vk = sh->dev->vk;
    VkDescriptorSetLayoutBinding bind[1 + 32];
    uint32_t n = 0;
    VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    if (p->block_size)
        bind[n++] = (VkDescriptorSetLayoutBinding){HFX_VK_BINDING_BLOCK, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1, stages, NULL};
    for (uint32_t k = 0; k < p->sampler_count; k++)
        bind[n++] = (VkDescriptorSetLayoutBinding){HFX_VK_BINDING_SAMPLER0 + k, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1,
                                                   stages, NULL};
    VkDescriptorSetLayoutCreateInfo si = {.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO, .bindingCount = n,
                                          .pBindings = bind};
    VkResult r = vk->fn.CreateDescriptorSetLayout(vk->device, &si, NULL, &p->set_layout);
    if (r != VK_SUCCESS) return hfx_vk_fail(sh->dev, r, "vkCreateDescriptorSetLayout");
    VkPipelineLayoutCreateInfo li = {.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO, .setLayoutCount = 1,
                                     .pSetLayouts = &p->set_layout};
    r = vk->fn.CreatePipelineLayout(vk->device, &li, NULL, &p->layout);
    return r == VK_SUCCESS ? HFX_OK : hfx_vk_fail(sh->dev, r, "vkCreatePipelineLayout");
}

int hfx_vk_program_build(hfx_shared *sh, uint32_t index) {
    const hfx_fx_program *fp = &sh->fx->programs[index];
    build b = {sh, &sh->vk->programs[index], {NULL, 0, 0}, 0};
    vk_program *p = b.p;
    p->fp = fp;
    p->regs_at = p->fixup_at = p->alpha_func_at = p->alpha_ref_at = -1;
    if (fp->sampler_count > 32)
        return hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "%s: a program samples more than 32 samplers", name_of(sh));
    p->sampler_count = fp->sampler_count;
    bool block = false;
    int rc = make_module(sh, index, &fp->code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV_VK], "vertex", &block, &p->vs);
    if (!rc) rc = make_module(sh, index, &fp->code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV_VK], "pixel", &block, &p->fs);
    if (!rc) rc = check_interface(sh, index, fp);
    if (!rc) rc = read_sampler_dims(sh, fp, p);
    if (!rc) rc = hfx_vk_outputs_make(sh->dev, &fp->code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV_VK], p);
    if (!rc) rc = read_block(&b, fp);
    if (!rc && block && !p->block_size)
        rc = hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "%s: a shader's uniform block has no members", name_of(sh));
    if (!rc) rc = map_uniforms(&b, fp);
    if (!rc) rc = make_layouts(sh, p);
    hfx_vk_block_free(&b.block);
    if (rc == HFX_ERR_MEMORY) hfx_rt_fail(sh->dev, rc, "out of memory");
    return rc;
}

void hfx_vk_program_free(hfx_device *dev, vk_program *p) {
    struct hfx_vk_device *vk = dev->vk;
    if (p->layout) vk->fn.DestroyPipelineLayout(vk->device, p->layout, NULL);
    if (p->set_layout) vk->fn.DestroyDescriptorSetLayout(vk->device, p->set_layout, NULL);
    if (p->vs) vk->fn.DestroyShaderModule(vk->device, p->vs, NULL);
    if (p->fs) vk->fn.DestroyShaderModule(vk->device, p->fs, NULL);
    for (int n = 0; n < 4; n++)
        if (p->fs_fewer[n]) vk->fn.DestroyShaderModule(vk->device, p->fs_fewer[n], NULL);
    free(p->slots);
    free(p->uploads);
    memset(p, 0, sizeof *p);
}
