/* Robustness, deterministic: (1) effects with random state assignments and values (valid
 * syntax, often wrong meaning) go through the whole compiler: each either builds or fails with
 * located errors, never crashes; (2) .hfxo files of real seeds with random words changed and
 * the checksum recomputed (so the structural checks, not the CRC, must catch them): the reader
 * refuses them or returns an effect every index of which is safe to follow. Meant to run
 * under ASan/UBSan, which turn any bad read into a failure. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "hfx/hfxc.h"
#include "test.h"

static uint32_t rng_next(uint64_t *s) {
    *s = *s * 6364136223846793005ull + 1442695040888963407ull;
    return (uint32_t)(*s >> 33);
}

static const char base[] =
    "float4 q < string a = \"x\" \"y\"; float2 b = {1, 2}; > = {1, 2, 3, 4};\n"
    "texture tx;\n"
    "struct S { float a; float3 b; };\n"
    "S tt[2];\n"
    "int big = 3;\n"
    "bool flag = true;\n"
    "sampler ss[2] = { sampler_state { Texture = <tx>; }, sampler_state { AddressU = Clamp; } };\n"
    "sampler one = sampler_state { %s };\n"
    "float4 vs(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 ps() : COLOR { return q; }\n"
    "PixelShader PS[2] = { compile ps_2_0 ps(), compile ps_3_0 ps() };\n"
    "VertexShader VS = compile vs_2_0 vs();\n"
    "technique Tech { pass P { %s } pass { %s } }\n";

static const char *const state_names[] = {
    "ZEnable", "ColorWriteEnable", "AlphaRef", "BlendFactor", "VertexShader", "PixelShader", "Texture[3]",
    "Texture", "Sampler[1]", "FogColor", "CullMode", "MinFilter[2]", "MinFilter[99]", "FogStart", "AddressU",
    "TextureTransform[0]", "LightEnable[0]", "SrcBlend", "Wrap0", "BogusState", "MaxAnisotropy[1]", "Sampler",
    "StencilRef", "AlphaBlendEnable", "BorderColor", "MipMapLodBias", "VertexShaderConstant[0]"};
static const char *const values[] = {
    "<q>", "<tx>", "<VS>", "(PS[1])", "(PS[0])", "(PS[2])", "(PS[big])", "NULL", "None", "Red | Green", "7",
    "-1", "0x80000000", "1e39", "-1e39", "float4(1,2,3,4)", "true", "FALSE", "(ss[1])", "<ss>", "q", "big",
    "compile vs_2_0 vs()", "compile ps_2_0 ps()", "Linear", "Point", "D3DBLEND_ONE", "1.0/0.0", "(big)",
    "<tt>", "VS", "PS", "flag", "<flag>", "(tx)", "2 * 3 + 1", "Wrap", "CCW"};

static void append_states(uint64_t *seed, char *buf, size_t size, int max) {
    size_t n = 0;
    buf[0] = 0;
    int count = (int)(rng_next(seed) % (uint32_t)(max + 1));
    for (int i = 0; i < count && n < size; i++)
        n += (size_t)snprintf(buf + n, size - n, "%s = %s; ",
                              state_names[rng_next(seed) % (sizeof state_names / sizeof *state_names)],
                              values[rng_next(seed) % (sizeof values / sizeof *values)]);
}

static void random_states_never_crash(void) {
    uint64_t seed = 12345;
    int built = 0, refused = 0;
    for (int i = 0; i < 300; i++) {
        char s1[1024], p1[1024], p2[1024], src[4096];
        append_states(&seed, s1, sizeof s1, 3);
        append_states(&seed, p1, sizeof p1, 6);
        append_states(&seed, p2, sizeof p2, 3);
        snprintf(src, sizeof src, base, s1, p1, p2);
        hfxc_result *r = hfxc_compile_memory(src, strlen(src), "fuzz.fx", NULL);
        if (hfxc_result_ok(r) && hfxc_result_effect(r)) {
            built++;
        } else {
            refused++;
            /* Every refusal says where. */
            CHECK(hfxc_diag_count(r) > 0);
            for (size_t k = 0; k < hfxc_diag_count(r); k++) {
                const hfxc_diag *d = hfxc_diag_at(r, k);
                if (d->severity == HFXC_ERROR) CHECK(d->line > 0 && d->code > 0);
            }
        }
        hfxc_result_free(r);
    }
    printf("  %d built, %d refused\n", built, refused);
    CHECK(built > 0 && refused > 0); /* both paths exercised */
}

/* Follows every index of an accepted effect, as a runtime would. */
static unsigned long walk(const hfx_fx_effect *fx) {
    unsigned long sum = strlen(fx->source_name);
    for (uint32_t i = 0; i < fx->param_count; i++) {
        const hfx_fx_param *p = &fx->params[i];
        sum += strlen(p->name) + (p->semantic ? strlen(p->semantic) : 0) + (p->string ? strlen(p->string) : 0);
        for (uint32_t w = 0; w < p->words; w++) sum += fx->values[p->offset + w];
        for (uint32_t c = 0; c < p->child_count; c++) sum += fx->params[p->first_child + c].words;
        for (uint32_t a = 0; a < p->annotation_count; a++) sum += strlen(fx->annotations[p->first_annotation + a].name);
        if (p->sampler != HFX_NONE) sum += fx->samplers[p->sampler].state_count;
        if (p->parent != HFX_NONE) sum += fx->params[p->parent].words;
    }
    for (uint32_t i = 0; i < fx->annotation_count; i++)
        for (uint32_t k = 0; k < fx->annotations[i].count; k++) sum += fx->annotations[i].data[k];
    for (uint32_t i = 0; i < fx->state_count; i++) {
        const hfx_fx_state *s = &fx->states[i];
        if (s->kind == HFX_FX_VALUE_PARAM && s->ref != HFX_NONE) sum += fx->params[s->ref].words;
        if (s->kind == HFX_FX_VALUE_PROGRAM && s->ref != HFX_NONE) sum += fx->programs[s->ref].flags;
    }
    for (uint32_t i = 0; i < fx->sampler_count; i++) {
        const hfx_fx_sampler *s = &fx->samplers[i];
        sum += fx->params[s->param].words + (s->texture_param != HFX_NONE ? fx->params[s->texture_param].words : 0);
        for (uint32_t k = 0; k < s->state_count; k++) sum += fx->states[s->first_state + k].id;
    }
    for (uint32_t i = 0; i < fx->program_count; i++) {
        const hfx_fx_program *p = &fx->programs[i];
        for (int s = 0; s < HFX_STAGE_COUNT; s++)
            for (int t = 0; t < HFX_TARGET_COUNT; t++)
                if (p->code[s][t].data) sum += strlen(p->code[s][t].data) + (unsigned char)p->code[s][t].data[p->code[s][t].size];
        for (uint32_t k = 0; k < p->attribute_count; k++) sum += strlen(p->attributes[k].semantic);
        for (uint32_t k = 0; k < p->sampler_count; k++) sum += fx->samplers[p->samplers[k].sampler].param;
        for (uint32_t k = 0; k < p->uniform_count; k++) sum += fx->params[p->uniforms[k].param].words;
    }
    for (uint32_t i = 0; i < fx->pass_count; i++) {
        const hfx_fx_pass *p = &fx->passes[i];
        for (uint32_t k = 0; k < p->state_count; k++) sum += fx->states[p->first_state + k].id;
        for (uint32_t k = 0; k < p->annotation_count; k++) sum += fx->annotations[p->first_annotation + k].count;
        if (p->program != HFX_NONE) sum += fx->programs[p->program].attribute_count;
    }
    for (uint32_t i = 0; i < fx->technique_count; i++)
        for (uint32_t k = 0; k < fx->techniques[i].pass_count; k++) sum += strlen(fx->passes[fx->techniques[i].first_pass + k].name);
    return sum;
}

static uint32_t crc32_bitwise(const uint8_t *p, size_t n) {
    uint32_t crc = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        crc ^= p[i];
        for (int k = 0; k < 8; k++) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1)));
    }
    return ~crc;
}

static void hostile_hfxo_never_reads_out_of_bounds(void) {
    test_require_seeds();
    static const char *const seeds[] = {"tutorial0.fx", "multilights_repaired.fx"};
    uint64_t seed = 777;
    int accepted = 0, refused = 0;
    for (size_t f = 0; f < sizeof seeds / sizeof *seeds; f++) {
        char *path = test_seed_path(seeds[f]);
        hfxc_result *r = hfxc_compile_file(path, NULL);
        free(path);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        CHECK(fx != NULL);
        void *data = NULL;
        size_t size = 0;
        if (!fx || hfx_fx_write_hfxo(fx, &data, &size) != 0) {
            hfxc_result_free(r);
            continue;
        }
        CHECK(walk(fx) > 0);
        uint8_t *copy = malloc(size);
        for (int i = 0; i < 1500; i++) {
            memcpy(copy, data, size);
            int changes = 1 + (int)(rng_next(&seed) % 3);
            for (int c = 0; c < changes; c++) {
                /* A word somewhere after the header, set to a small number, a huge one, or NONE. */
                size_t at = 24 + 4 * (rng_next(&seed) % (uint32_t)((size - 24) / 4));
                uint32_t kind = rng_next(&seed) % 4;
                uint32_t v = kind == 0 ? rng_next(&seed) % 64 : kind == 1 ? rng_next(&seed) : kind == 2 ? 0xffffffffu : 0;
                memcpy(copy + at, &v, 4);
            }
            uint32_t crc = crc32_bitwise(copy + 16, size - 16);
            memcpy(copy + 12, &crc, 4);
            char err[256] = "";
            hfx_fx_effect *back = hfx_fx_read_hfxo(copy, size, err, sizeof err);
            if (back) {
                accepted++;
                walk(back);
                hfx_fx_effect_free(back);
            } else {
                refused++;
                CHECK(strncmp(err, "hfxo: ", 6) == 0);
            }
        }
        free(copy);
        free(data);
        hfxc_result_free(r);
    }
    printf("  %d accepted (and walked), %d refused\n", accepted, refused);
    CHECK(refused > 0);
}

int main(void) {
    RUN(random_states_never_crash);
    RUN(hostile_hfxo_never_reads_out_of_bounds);
    return test_summary();
}
