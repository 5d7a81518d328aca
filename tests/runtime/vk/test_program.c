/* test_program.c (Vulkan): a .hfxo whose SPIR-V for Vulkan is corrupted is refused at load with
 * the validator's reason, naming the effect, pass and stage, before the driver sees the module
 * (runtime/vk/program.c), as is valid SPIR-V naming descriptors the pipeline layout lacks, or
 * whose stages' interfaces disagree with each other, the attributes or the device; the
 * same file uncorrupted loads and draws. The .hfxo is written by
 * the compiler's own writer, so its CRC is right and only the module is wrong. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "hfx/hfxc.h"
#include "vk_draw.h"

static test_vk *V;
static const float CLEAR[4] = {0, 0, 0, 1};
static const vk_quad FULL = {-1, -1, 1, 1, 0.5f, 1, 1, 0};

static const char red[] = "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                          "float4 PS() : COLOR { return float4(1, 0, 0, 1); }\n"
                          "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

/* src compiled for Vulkan alone, owned by the caller; NULL (and a failed check) otherwise. */
static hfx_fx_effect *compiled(const char *src, size_t len, const char *name) {
    hfxc_options opt = {0};
    opt.targets = 1u << HFX_TARGET_SPIRV_VK;
    hfxc_result *r = hfxc_compile_memory(src, len, name, &opt);
    hfx_fx_effect *fx = hfxc_result_take_effect(r);
    hfxc_result_free(r);
    CHECK(fx != NULL && fx->program_count == 1);
    if (fx && fx->program_count == 1) return fx;
    hfx_fx_effect_free(fx);
    return NULL;
}

/* fx written as .hfxo (malloc'ed, *size bytes) and freed. */
static void *as_hfxo(hfx_fx_effect *fx, size_t *size) {
    void *out = NULL;
    CHECK(hfx_fx_write_hfxo(fx, &out, size) == 0);
    hfx_fx_effect_free(fx);
    return out;
}

/* The .hfxo of `red` with word `word` of pass P's pixel shader module set to `value`
 * (word UINT32_MAX: unchanged). */
static void *hfxo_with(uint32_t word, uint32_t value, size_t *size) {
    hfx_fx_effect *fx = compiled(red, sizeof red - 1, "red.fx");
    if (!fx) return NULL;
    hfx_fx_code *ps = &fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV_VK];
    CHECK(ps->size >= 20 && ps->size % 4 == 0);
    if (word != UINT32_MAX && word < ps->size / 4) memcpy(ps->data + 4 * word, &value, 4);
    return as_hfxo(fx, size);
}

/* Loads the .hfxo; NULL with *errors set when refused. */
static hfx_effect *load(void *bytes, size_t size, char **errors) {
    *errors = NULL;
    hfx_effect *fx = bytes ? hfx_effect_load_memory(test_vk_device(V), bytes, size, "red.hfxo", NULL, errors) : NULL;
    free(bytes);
    return fx;
}

/* bytes (freed) refused at load with `expected`, which the device's last error repeats. */
static void refused_as(void *bytes, size_t size, const char *expected) {
    char *errors = NULL;
    hfx_effect *fx = load(bytes, size, &errors);
    CHECK(fx == NULL);
    CHECK_STR(errors ? errors : "", expected);
    CHECK_STR(hfx_device_last_error(test_vk_device(V)), expected);
    hfx_free(errors);
    hfx_effect_destroy(fx);
}

static void check_refused(uint32_t word, uint32_t value, const char *expected) {
    size_t size = 0;
    void *bytes = hfxo_with(word, value, &size);
    refused_as(bytes, size, expected);
}

/* Word 0 is the magic number 0x07230203: anything else is not SPIR-V, refused before the
 * validator runs. */
static void no_magic_refused(void) {
    check_refused(0, 0x03022307u, "red.fx: technique 'T', pass 'P': the pixel shader's code is not SPIR-V (no "
                                  "magic number)");
}

/* Word 3 is the ID bound, one more than the largest ID: 1 leaves no ID valid, and SPIRV-Tools
 * reports the first instruction defining one (spirv-val says the same of the file). */
static void bad_bound_refused(void) {
    check_refused(3, 1, "red.fx: technique 'T', pass 'P': the pixel shader's SPIR-V is not valid for Vulkan "
                        "1.0: Result <id> '1' must be less than the ID bound '1'.");
}

/* Words 7.. are `OpExtInstImport %1 "GLSL.std.450"`; word 9 is "GLSL": with byte 0xC0 for its first 'L'
 * the import names no instruction set. The validator quotes the name; the byte that is not
 * printable ASCII shows as '?' (spirv-val prints it raw). */
static void bad_import_refused(void) {
    check_refused(9, 0x4C53C047u, "red.fx: technique 'T', pass 'P': the pixel shader's SPIR-V is not valid for Vulkan "
                                  "1.0: Invalid extended instruction import 'G?SL.std.450'");
}

static const char tinted[] = "float4 Tint; texture Tex; sampler S = sampler_state { Texture = <Tex>; };\n"
                             "float4 VS(float4 p : POSITION) : POSITION { return p; }\n"
                             "float4 PS(float2 t : TEXCOORD0) : COLOR { return tex2D(S, t) * Tint; }\n"
                             "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

/* The .hfxo of `tinted` with the pixel shader's first `OpDecorate %v <decoration> <from>` made to
 * say `to`: valid SPIR-V still, but naming a descriptor the program's pipeline layout lacks. */
static void *hfxo_decorated(uint32_t decoration, uint32_t from, uint32_t to, size_t *size) {
    hfx_fx_effect *fx = compiled(tinted, sizeof tinted - 1, "tinted.fx");
    if (!fx) return NULL;
    hfx_fx_code *ps = &fx->programs[0].code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV_VK];
    uint32_t *w = (uint32_t *)(void *)ps->data, n = (uint32_t)(ps->size / 4), found = 0;
    for (uint32_t i = 5; i < n && !found && (w[i] >> 16);) {
        if (w[i] == (4u << 16 | 71u) && w[i + 2] == decoration && w[i + 3] == from) w[i + 3] = to, found = 1;
        i += w[i] >> 16;
    }
    CHECK(found);
    return as_hfxo(fx, size);
}

static void check_decoration_refused(uint32_t decoration, uint32_t from, uint32_t to, const char *expected) {
    size_t size = 0;
    void *bytes = hfxo_decorated(decoration, from, to, &size);
    refused_as(bytes, size, expected);
}

/* SPIR-V's validator takes any DescriptorSet and Binding; a pipeline layout without them is
 * undefined behaviour, and lavapipe crashed on set 880045673 (found by fuzz_runtime_vk). The
 * layout has set 0: the block at binding 0 (decoration 33, Binding) and one sampler at 1. */
static void foreign_descriptors_refused(void) {
    check_decoration_refused(34, 0, 880045673u, "tinted.fx: technique 'T', pass 'P': the pixel shader's SPIR-V "
                                                "declares a descriptor set other than 0");
    check_decoration_refused(33, 1, 5, "tinted.fx: technique 'T', pass 'P': the pixel shader's SPIR-V declares a "
                                       "sampler binding the program does not have");
    check_decoration_refused(33, 0, 2, "tinted.fx: technique 'T', pass 'P': the pixel shader's SPIR-V declares a "
                                       "uniform block at another binding than the effect's");
    size_t size = 0;
    char *errors = NULL;
    void *bytes = hfxo_decorated(33, 1, 1, &size); /* unchanged: loads */
    hfx_effect *fx = load(bytes, size, &errors);
    CHECK(fx != NULL);
    hfx_free(errors);
    hfx_effect_destroy(fx);
}

static const char passed[] = "void VS(float4 p : POSITION, float2 t : TEXCOORD0, out float4 op : POSITION,\n"
                             "        out float2 ot : TEXCOORD0) { op = p; ot = t; }\n"
                             "float4 PS(float2 t : TEXCOORD0) : COLOR { return float4(t, 0, 1); }\n"
                             "technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n";

/* `passed` with the nth `OpDecorate %v Location <from>` (decoration 30) of the stage's module made
 * to say `to`, or (stage -1) its program's attribute at location `from` moved to `to`. */
static void *hfxo_located(int stage, uint32_t nth, uint32_t from, uint32_t to, size_t *size) {
    hfx_fx_effect *fx = compiled(passed, sizeof passed - 1, "passed.fx");
    if (!fx) return NULL;
    uint32_t found = 0;
    hfx_fx_program *prog = &fx->programs[0];
    for (uint32_t a = 0; stage < 0 && a < prog->attribute_count; a++)
        if (prog->attributes[a].location == (int32_t)from && !found++) prog->attributes[a].location = (int32_t)to;
    hfx_fx_code *code = stage < 0 ? NULL : &prog->code[stage][HFX_TARGET_SPIRV_VK];
    uint32_t *w = code ? (uint32_t *)(void *)code->data : NULL, n = code ? (uint32_t)(code->size / 4) : 0;
    for (uint32_t i = 5; i < n && found <= nth && (w[i] >> 16);) {
        if (w[i] == (4u << 16 | 71u) && w[i + 2] == 30 && w[i + 3] == from && found++ == nth) w[i + 3] = to;
        i += w[i] >> 16;
    }
    CHECK(found > (stage < 0 ? 0 : nth));
    return as_hfxo(fx, size);
}

static void check_located_refused(int stage, uint32_t nth, uint32_t from, uint32_t to, const char *why) {
    size_t size = 0;
    void *bytes = hfxo_located(stage, nth, from, to, &size);
    char expected[256];
    snprintf(expected, sizeof expected, "passed.fx: technique 'T', pass 'P': the shaders' interface has %s", why);
    refused_as(bytes, size, expected);
}

/* Each module is valid alone; the pipeline joining them is not. lavapipe wrote out of bounds on
 * a vertex output at Location 0x40000001 (found by fuzz_runtime_vk); the validation layer
 * reports a pixel input nothing writes (InputNotProduced) and a vertex input no attribute feeds.
 * In `passed`'s vertex shader, Location 0 is POSITION0's input, then TEXCOORD0's output; the
 * pixel shader reads TEXCOORD0 at Location 0; the program's attributes are POSITION0 at 0 and
 * TEXCOORD0 at 8 (D3D9's usage order). */
static void interface_refused(void) {
    check_located_refused(HFX_STAGE_VERTEX, 1, 0, 0x40000001u, "an interface location past the last one a device has");
    check_located_refused(HFX_STAGE_FRAGMENT, 0, 0, 1, "a pixel shader input no vertex shader output writes");
    check_located_refused(HFX_STAGE_VERTEX, 0, 0, 3, "a vertex shader input no attribute provides");
    check_located_refused(-1, 0, 0, 8, "two attributes on one location");
    check_located_refused(-1, 0, 8, 4000, "an attribute location past the device's");
    size_t size = 0;
    char *errors = NULL;
    hfx_effect *fx = load(hfxo_located(HFX_STAGE_FRAGMENT, 0, 0, 0, &size), size, &errors); /* unchanged: loads */
    CHECK(fx != NULL);
    hfx_free(errors);
    hfx_effect_destroy(fx);
}

/* The device still works after the refusals, and the uncorrupted file draws its red. */
static void valid_draws(void) {
    size_t size = 0;
    char *errors = NULL;
    void *bytes = hfxo_with(UINT32_MAX, 0, &size);
    hfx_effect *fx = load(bytes, size, &errors);
    if (!fx) fprintf(stderr, "load: %s\n", errors ? errors : "");
    hfx_free(errors);
    CHECK(fx != NULL);
    if (!fx) return;
    CHECK_INT(vk_draw(V, fx, "T", &FULL, 1, CLEAR), 0);
    CHECK_PIXEL(V, 8, 8, 255, 0, 0, 255);
    hfx_effect_destroy(fx);
}

int main(void) {
    hfx_vertex_layout *layout;
    V = vk_suite_begin(16, 16, &layout);
    RUN(no_magic_refused);
    RUN(bad_bound_refused);
    RUN(bad_import_refused);
    RUN(foreign_descriptors_refused);
    RUN(interface_refused);
    RUN(valid_draws);
    vk_suite_end(V, layout); /* the validation layer saw no invalid module */
    return test_summary();
}
