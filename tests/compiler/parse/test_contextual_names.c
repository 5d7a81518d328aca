/* test_contextual_names.c: names fxc accepts although they spell a builtin type or a keyword
 * elsewhere, as real effects use them: XNA's DECLARE_TEXTURE(Texture, 0) declares `texture2D
 * Texture;` and a sampler reading `Texture = (Texture);`; `sampler Sampler`, `sampler
 * samplerState`, `Texture = <Texture>;`; `VertexShader = null;` in lower case. Each must compile
 * with no diagnostic and reflect the parameters by those names. */
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "hfx/hfxc.h"
#include "test.h"

static void compiles_clean(const char *src, const char *const *names, int n) {
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "t.fx", NULL);
    char *d = hfxc_diagnostics_text(r);
    CHECK_STR(d, "");
    free(d);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    for (int i = 0; fx && i < n; i++) {
        if (hfx_fx_param_find(fx, names[i]) == HFX_NONE) printf("  no parameter '%s'\n", names[i]);
        CHECK(hfx_fx_param_find(fx, names[i]) != HFX_NONE);
    }
    hfxc_result_free(r);
}

static void xna_declare_texture(void) {
    const char *src =
        "#define DECLARE_TEXTURE(Name, index) texture2D Name; "
        "sampler Name##Sampler : register(s##index) = sampler_state { Texture = (Name); };\n"
        "#define SAMPLE_TEXTURE(Name, texCoord) tex2D(Name##Sampler, texCoord)\n"
        "DECLARE_TEXTURE(Texture, 0);\n"
        "float4 ps(float2 uv : TEXCOORD0) : COLOR0 { return SAMPLE_TEXTURE(Texture, uv); }\n"
        "technique T { pass P { PixelShader = compile ps_2_0 ps(); } }\n";
    const char *const names[] = {"Texture", "TextureSampler"};
    compiles_clean(src, names, 2);
}

/* XNA tutorials name their entry points after the types (petriw's XNA-Shader-Programming,
 * Biophage's GaussianBlur.fx): `float4 PixelShader(...)`, compiled by `compile ps_2_0
 * PixelShader()`, and the pass still sets the PixelShader state; VertexShader stays a type
 * where a name follows it. */
static void functions_named_like_shader_types(void) {
    const char *src =
        "float4x4 WVP;\n"
        "struct OUT { float4 Pos : POSITION; };\n"
        "OUT VertexShader(float4 Pos : POSITION) { OUT o; o.Pos = mul(Pos, WVP); return o; }\n"
        "float4 PixelShader(float2 uv : TEXCOORD0) : COLOR0 { return float4(uv, 0, 1); }\n"
        "VertexShader Shaders[1] = { compile vs_2_0 VertexShader() };\n"
        "technique T { pass P { VertexShader = compile vs_2_0 VertexShader(); PixelShader = compile ps_2_0 PixelShader(); } }\n";
    const char *const names[] = {"WVP", "Shaders"};
    compiles_clean(src, names, 2);
}

/* MonoGame's DECLARE_TEXTURE for SM4 spells `Texture2D<float4> Texture : register(t0);` (the
 * id Software RTCW port's SkeletalEffect.fx). */
static void name_after_a_template_type(void) {
    const char *src =
        "Texture2D<float4> Texture : register(t0);\n"
        "sampler TextureSampler : register(s0) = sampler_state { Texture = (Texture); };\n"
        "float4 ps(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(TextureSampler, uv); }\n"
        "technique T { pass P { PixelShader = compile ps_2_0 ps(); } }\n";
    const char *const names[] = {"Texture", "TextureSampler"};
    compiles_clean(src, names, 2);
}

static void sampler_and_texture_names(void) {
    const char *src =
        "texture Texture;\n"
        "sampler Sampler = sampler_state { Texture = <Texture>; MinFilter = Linear; };\n"
        "sampler samplerState;\n"
        "float4 ps(float2 uv : TEXCOORD0) : COLOR { return tex2D(Sampler, uv) + tex2D(samplerState, uv); }\n"
        "Texture t2;\n" /* the spelling still declares with the type where a name follows */
        "Texture xTexture : TEXTURE;\n" /* a semantic spelled like a type */
        "technique T { pass P { VertexShader = null; PixelShader = compile ps_2_0 ps(); } }\n";
    const char *const names[] = {"Texture", "Sampler", "samplerState", "t2", "xTexture"};
    compiles_clean(src, names, 5);
}

int main(void) {
    RUN(xna_declare_texture);
    RUN(functions_named_like_shader_types);
    RUN(name_after_a_template_type);
    RUN(sampler_and_texture_names);
    return test_summary();
}
