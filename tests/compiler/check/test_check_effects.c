/* Effects in the styles XNA, MonoGame and FX Composer users write (sprite, skinning, normal
 * mapping, post-processing, fixed-size loops, shader arrays): each must check without a
 * diagnostic and leave a tree that satisfies ast.h's invariants. */
#include <stdlib.h>

#include "check_util.h"
#include "test.h"

static void expect_clean(const char *name, const char *src) {
    ckt_result *r = ckt_run(src);
    char *t = ckt_text(r);
    if (*t) fprintf(stderr, "%s:\n%s", name, t);
    CHECK(r->ok);
    CHECK_STR(t, "");
    free(t);
    char why[256];
    int bad = ckt_invariants(r, why, sizeof why);
    if (bad) fprintf(stderr, "%s: %s\n", name, why);
    CHECK_INT(bad, 0);
    ckt_free(r);
}

static void sprite_effect(void) {
    expect_clean("sprite",
        "sampler TextureSampler : register(s0);\n"
        "float Amount = 0.5;\n"
        "float4 main(float4 color : COLOR0, float2 texCoord : TEXCOORD0) : COLOR0\n"
        "{\n"
        "    float4 tex = tex2D(TextureSampler, texCoord);\n"
        "    float gray = dot(tex.rgb, float3(0.3, 0.59, 0.11));\n"
        "    tex.rgb = lerp(tex.rgb, gray, Amount);\n"
        "    return tex * color;\n"
        "}\n"
        "technique Desaturate { pass { PixelShader = compile ps_2_0 main(); } }\n");
}

static void skinned_effect(void) {
    expect_clean("skinned",
        "#define MaxBones 59\n"
        "float4x3 Bones[MaxBones];\n"
        "float4x4 WorldViewProj;\n"
        "float3 LightDir = normalize(float3(1, -1, 0));\n"
        "struct VSIn { float4 Position : POSITION0; float3 Normal : NORMAL0; float4 Indices : BLENDINDICES0;\n"
        "              float4 Weights : BLENDWEIGHT0; float2 Tex : TEXCOORD0; };\n"
        "struct VSOut { float4 Position : POSITION0; float2 Tex : TEXCOORD0; float Light : TEXCOORD1; };\n"
        "void Skin(inout VSIn v, uniform int boneCount)\n"
        "{\n"
        "    float4x3 skinning = 0;\n"
        "    [unroll]\n"
        "    for (int i = 0; i < boneCount; i++)\n"
        "        skinning += Bones[v.Indices[i]] * v.Weights[i];\n"
        "    v.Position.xyz = mul(v.Position, skinning);\n"
        "    v.Normal = mul(v.Normal, (float3x3)skinning);\n"
        "}\n"
        "VSOut VS(VSIn vin, uniform int boneCount)\n"
        "{\n"
        "    VSOut o = (VSOut)0;\n"
        "    Skin(vin, boneCount);\n"
        "    o.Position = mul(vin.Position, WorldViewProj);\n"
        "    o.Tex = vin.Tex;\n"
        "    o.Light = saturate(dot(normalize(vin.Normal), -LightDir));\n"
        "    return o;\n"
        "}\n"
        "VertexShader VSArray[4] = { compile vs_2_0 VS(1), compile vs_2_0 VS(2), compile vs_2_0 VS(3),\n"
        "                            compile vs_2_0 VS(4) };\n"
        "int ShaderIndex = 0;\n"
        "technique Skinned { pass { VertexShader = (VSArray[ShaderIndex]); } }\n");
}

static void normal_map_effect(void) {
    expect_clean("normalmap",
        "float4x4 World; float4x4 View; float4x4 Projection;\n"
        "float3 LightPosition; float3 EyePosition; float SpecularPower = 16;\n"
        "texture ColorMap; texture NormalMap;\n"
        "sampler2D ColorSampler = sampler_state { Texture = <ColorMap>; MinFilter = Linear; MagFilter = Linear;\n"
        "    MipFilter = Linear; AddressU = Wrap; AddressV = Wrap; };\n"
        "sampler2D NormalSampler = sampler_state { Texture = <NormalMap>; };\n"
        "struct VSOutput { float4 Pos : POSITION; float2 UV : TEXCOORD0; float3 L : TEXCOORD1; float3 V : TEXCOORD2; };\n"
        "VSOutput VS(float4 pos : POSITION, float3 n : NORMAL, float3 t : TANGENT, float3 b : BINORMAL, float2 uv : TEXCOORD0)\n"
        "{\n"
        "    VSOutput o;\n"
        "    float4 world = mul(pos, World);\n"
        "    o.Pos = mul(mul(world, View), Projection);\n"
        "    float3x3 toTangent = transpose(float3x3(mul(t, (float3x3)World), mul(b, (float3x3)World),\n"
        "                                            mul(n, (float3x3)World)));\n"
        "    o.L = mul(LightPosition - world.xyz, toTangent);\n"
        "    o.V = mul(toTangent, EyePosition - world.xyz);\n"
        "    o.UV = uv;\n"
        "    return o;\n"
        "}\n"
        "float4 PS(VSOutput i) : COLOR0\n"
        "{\n"
        "    float3 n = normalize(tex2D(NormalSampler, i.UV).xyz * 2 - 1);\n"
        "    float3 l = normalize(i.L), v = normalize(i.V);\n"
        "    float3 h = normalize(l + v);\n"
        "    float4 lighting = lit(dot(n, l), dot(n, h), SpecularPower);\n"
        "    float4 c = tex2D(ColorSampler, i.UV);\n"
        "    c.rgb = c.rgb * lighting.y + lighting.z;\n"
        "    return c;\n"
        "}\n"
        "technique NormalMapping { pass P0 { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }\n");
}

static void blur_effect(void) {
    expect_clean("blur",
        "sampler s0;\n"
        "static const int SampleCount = 5;\n"
        "float2 Offsets[SampleCount];\n"
        "static const float Weights[SampleCount] = { 0.06, 0.24, 0.4, 0.24, 0.06 };\n"
        "float4 Blur(float2 uv : TEXCOORD0) : COLOR0\n"
        "{\n"
        "    float4 sum = 0;\n"
        "    for (int i = 0; i < SampleCount; i++)\n"
        "        sum += tex2D(s0, uv + Offsets[i]) * Weights[i];\n"
        "    sum.a = 1;\n"
        "    return i > 3 ? sum : sum * 0.5;\n"
        "}\n"
        "float4 Threshold(float2 uv : TEXCOORD0, uniform float t) : COLOR0\n"
        "{\n"
        "    float4 c = tex2Dlod(s0, float4(uv, 0, 0));\n"
        "    clip(dot(c.rgb, 1.0 / 3) - t);\n"
        "    return saturate((c - t) / (1 - t));\n"
        "}\n"
        "technique T {\n"
        "    pass Blur { PixelShader = compile ps_3_0 Blur(); AlphaBlendEnable = false; }\n"
        "    pass Bright { PixelShader = compile ps_3_0 Threshold(0.25); ZEnable = false; CullMode = CCW; }\n"
        "}\n");
}

static void intrinsic_zoo(void) {
    expect_clean("intrinsics",
        "samplerCUBE env; sampler3D vol; sampler1D ramp;\n"
        "float4 f(float3 p : TEXCOORD0, float3 n : TEXCOORD1, float4 q : TEXCOORD2) : COLOR\n"
        "{\n"
        "    float s, c;\n"
        "    sincos(p.x, s, c);\n"
        "    float ip;\n"
        "    float fr = modf(p.y, ip);\n"
        "    float3 r = reflect(-p, n) + refract(p, n, 1.33) + faceforward(n, p, n) + cross(p, n);\n"
        "    float4 e = texCUBE(env, r) + texCUBEbias(env, float4(r, 1)) + tex3D(vol, p) + tex1D(ramp, s);\n"
        "    float4x4 m = float4x4(q, q.yzwx, q.zwxy, q.wxyz);\n"
        "    float d = determinant(m) + length(p) + distance(p, n) + atan2(s, c) + fmod(p.z, 2);\n"
        "    bool ok = all(isfinite(p)) && !any(isnan(q)) && !isinf(d);\n"
        "    float3 sm = smoothstep(0, 1, p) * step(0.5, n) + exp2(p) + log2(abs(p) + 1) + pow(abs(n), 2);\n"
        "    float g = fwidth(s) + ddx(c) + ddy(c) + frac(d) + floor(d) + ceil(d) + round(d) + trunc(d) + sign(d);\n"
        "    int4 col = D3DCOLORtoUBYTE4(q);\n"
        "    float4 mm = mul(m, q) + mul(q, transpose(m)) + noise(p) + radians(degrees(q)) + rsqrt(q * q + 1);\n"
        "    return ok ? e * d + float4(sm, g) + mm + col : max(min(q, 1), -1);\n"
        "}\n");
}

static void globals_written_by_shaders(void) {
    /* the seeds' FX Composer style: a pixel shader normalizes and scales uniform globals */
    ckt_result *r = ckt_run(
        "float3 dir;\nfloat4 tint = {1, 1, 1, 1};\n"
        "float4 ps(uniform bool useTint) : COLOR { dir = normalize(dir); if (useTint) tint *= 0.5; return float4(dir, 1) * tint; }\n"
        "technique T { pass { PixelShader = compile ps_2_0 ps(true); } }\n");
    CHECK(r->ok);
    CHECK(ckt_find(r, "dir")->assigned);
    CHECK(ckt_find(r, "tint")->assigned);
    ckt_free(r);
}

int main(void) {
    RUN(sprite_effect);
    RUN(skinned_effect);
    RUN(normal_map_effect);
    RUN(blur_effect);
    RUN(intrinsic_zoo);
    RUN(globals_written_by_shaders);
    return test_summary();
}
