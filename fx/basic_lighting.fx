// basic_lighting.fx: an effect in the style of XNA's BasicEffect, written for hfx's tests and
// gallery. One technique; the int parameter ShaderIndex picks one of 14 shader pairs through
// two static const tables, as XNA's stock effects do:
//   0..3   no lighting         (+1 vertex colour, +2 texture)
//   4..7   vertex lighting     (three directional lights, Gouraud)
//   8..11  pixel lighting      (the same equations per pixel)
//   12, 13 skinned, two bones  (vertex lighting, pixel lighting)
// The lighting is XNA's: for each light, L = -direction, N.L clamped, the Blinn half vector
// H = normalize(E + L) with E towards the eye, specular (N.H)^power where N.L > 0; the
// diffuse sum is tinted by DiffuseColor plus EmissiveColor, the specular sum by
// SpecularColor. Fog mixes towards FogColor by saturate(dot(float4(position, 1), FogVector))
// (FogVector = 0: no fog).

int ShaderIndex = 0;

float4x4 World;
float3x3 WorldInverseTranspose;
float4x4 WorldViewProj;
float3 EyePosition;

float4 DiffuseColor = float4(1, 1, 1, 1);
float3 EmissiveColor = float3(0, 0, 0);
float3 SpecularColor = float3(1, 1, 1);
float SpecularPower = 16;

float3 DirLight0Direction = float3(0, 0, -1);
float3 DirLight0DiffuseColor = float3(1, 1, 1);
float3 DirLight0SpecularColor = float3(0, 0, 0);
float3 DirLight1Direction = float3(0, 0, -1);
float3 DirLight1DiffuseColor = float3(0, 0, 0);
float3 DirLight1SpecularColor = float3(0, 0, 0);
float3 DirLight2Direction = float3(0, 0, -1);
float3 DirLight2DiffuseColor = float3(0, 0, 0);
float3 DirLight2SpecularColor = float3(0, 0, 0);

float3 FogColor = float3(0, 0, 0);
float4 FogVector = float4(0, 0, 0, 0);

float4x3 Bones[2];

texture Texture;
sampler TextureSampler = sampler_state
{
    Texture = <Texture>;
    MinFilter = Point;
    MagFilter = Point;
    MipFilter = None;
};

struct VSOut
{
    float4 Position : POSITION;
    float4 Diffuse : COLOR0;
    float4 Specular : COLOR1;   // rgb: specular, a: fog factor
    float2 TexCoord : TEXCOORD0;
};

struct VSOutPixel
{
    float4 Position : POSITION;
    float4 Color : COLOR0;      // the vertex colour, its alpha times DiffuseColor's
    float2 TexCoord : TEXCOORD0;
    float4 PositionWS : TEXCOORD1; // w: fog factor
    float3 NormalWS : TEXCOORD2;
};

struct Lit { float3 Diffuse; float3 Specular; };

// One light's share, XNA's way: the specular term is zero where the light is behind.
void AddLight(inout Lit lit, float3 E, float3 N, float3 direction, float3 diffuse, float3 specular)
{
    float3 L = -direction;
    float dotL = dot(L, N);
    float dotH = dot(normalize(E + L), N);
    float zeroL = step(0, dotL);
    lit.Diffuse += zeroL * dotL * diffuse;
    lit.Specular += pow(max(dotH, 0.000001) * zeroL, SpecularPower) * specular;
}

Lit ComputeLights(float3 E, float3 N)
{
    Lit lit = (Lit)0;
    AddLight(lit, E, N, DirLight0Direction, DirLight0DiffuseColor, DirLight0SpecularColor);
    AddLight(lit, E, N, DirLight1Direction, DirLight1DiffuseColor, DirLight1SpecularColor);
    AddLight(lit, E, N, DirLight2Direction, DirLight2DiffuseColor, DirLight2SpecularColor);
    lit.Diffuse = lit.Diffuse * DiffuseColor.rgb + EmissiveColor;
    lit.Specular *= SpecularColor;
    return lit;
}

float FogFactor(float4 position)
{
    return saturate(dot(position, FogVector));
}

// ---- vertex shaders ----

VSOut Unlit(float4 position, float4 color, float2 uv)
{
    VSOut o;
    o.Position = mul(position, WorldViewProj);
    o.Diffuse = DiffuseColor * color;
    o.Specular = float4(0, 0, 0, FogFactor(position));
    o.TexCoord = uv;
    return o;
}

VSOut VertexLit(float4 position, float3 normal, float4 color, float2 uv)
{
    VSOut o;
    float3 posWS = mul(position, World).xyz;
    float3 N = normalize(mul(normal, WorldInverseTranspose));
    Lit lit = ComputeLights(normalize(EyePosition - posWS), N);
    o.Position = mul(position, WorldViewProj);
    o.Diffuse = float4(lit.Diffuse, DiffuseColor.a) * color;
    o.Specular = float4(lit.Specular, FogFactor(position));
    o.TexCoord = uv;
    return o;
}

VSOutPixel PixelLitVS(float4 position, float3 normal, float4 color, float2 uv)
{
    VSOutPixel o;
    o.Position = mul(position, WorldViewProj);
    o.Color = float4(color.rgb, color.a * DiffuseColor.a); // lit.Diffuse carries DiffuseColor.rgb
    o.TexCoord = uv;
    o.PositionWS = float4(mul(position, World).xyz, FogFactor(position));
    o.NormalWS = normalize(mul(normal, WorldInverseTranspose));
    return o;
}

VSOut VSBasic(float4 p : POSITION) { return Unlit(p, 1, 0); }
VSOut VSBasicVc(float4 p : POSITION, float4 c : COLOR) { return Unlit(p, c, 0); }
VSOut VSBasicTx(float4 p : POSITION, float2 uv : TEXCOORD0) { return Unlit(p, 1, uv); }
VSOut VSBasicTxVc(float4 p : POSITION, float4 c : COLOR, float2 uv : TEXCOORD0) { return Unlit(p, c, uv); }

VSOut VSLit(float4 p : POSITION, float3 n : NORMAL) { return VertexLit(p, n, 1, 0); }
VSOut VSLitVc(float4 p : POSITION, float3 n : NORMAL, float4 c : COLOR) { return VertexLit(p, n, c, 0); }
VSOut VSLitTx(float4 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0) { return VertexLit(p, n, 1, uv); }
VSOut VSLitTxVc(float4 p : POSITION, float3 n : NORMAL, float4 c : COLOR, float2 uv : TEXCOORD0) { return VertexLit(p, n, c, uv); }

VSOutPixel VSPixel(float4 p : POSITION, float3 n : NORMAL) { return PixelLitVS(p, n, 1, 0); }
VSOutPixel VSPixelVc(float4 p : POSITION, float3 n : NORMAL, float4 c : COLOR) { return PixelLitVS(p, n, c, 0); }
VSOutPixel VSPixelTx(float4 p : POSITION, float3 n : NORMAL, float2 uv : TEXCOORD0) { return PixelLitVS(p, n, 1, uv); }
VSOutPixel VSPixelTxVc(float4 p : POSITION, float3 n : NORMAL, float4 c : COLOR, float2 uv : TEXCOORD0) { return PixelLitVS(p, n, c, uv); }

// Two bones per vertex: the weighted sum of the bone transforms (float4x3: rotation and
// translation), applied to the position and, without the translation, to the normal.
void Skin(inout float4 position, inout float3 normal, int4 indices, float4 weights)
{
    float4x3 skin = Bones[indices.x] * weights.x + Bones[indices.y] * weights.y;
    position = float4(mul(position, skin), 1);
    normal = mul(normal, (float3x3)skin);
}

VSOut VSSkinnedLit(float4 p : POSITION, float3 n : NORMAL, int4 bi : BLENDINDICES0, float4 bw : BLENDWEIGHT0)
{
    Skin(p, n, bi, bw);
    return VertexLit(p, n, 1, 0);
}

VSOutPixel VSSkinnedPixel(float4 p : POSITION, float3 n : NORMAL, int4 bi : BLENDINDICES0, float4 bw : BLENDWEIGHT0)
{
    Skin(p, n, bi, bw);
    return PixelLitVS(p, n, 1, 0);
}

// ---- pixel shaders ----

float4 Finish(float4 color, float3 specular, float fog)
{
    color.rgb += specular * color.a;
    color.rgb = lerp(color.rgb, FogColor * color.a, fog);
    return color;
}

float4 PSBasic(VSOut i) : COLOR { return Finish(i.Diffuse, 0, i.Specular.w); }
float4 PSBasicTx(VSOut i) : COLOR { return Finish(tex2D(TextureSampler, i.TexCoord) * i.Diffuse, 0, i.Specular.w); }
float4 PSLit(VSOut i) : COLOR { return Finish(i.Diffuse, i.Specular.rgb, i.Specular.w); }
float4 PSLitTx(VSOut i) : COLOR { return Finish(tex2D(TextureSampler, i.TexCoord) * i.Diffuse, i.Specular.rgb, i.Specular.w); }

float4 PixelLit(VSOutPixel i, float4 texel)
{
    Lit lit = ComputeLights(normalize(EyePosition - i.PositionWS.xyz), normalize(i.NormalWS));
    float4 color = texel * i.Color;
    color.rgb *= lit.Diffuse;
    return Finish(color, lit.Specular, i.PositionWS.w);
}

float4 PSPixel(VSOutPixel i) : COLOR { return PixelLit(i, 1); }
float4 PSPixelTx(VSOutPixel i) : COLOR { return PixelLit(i, tex2D(TextureSampler, i.TexCoord)); }

VertexShader VSArray[14] =
{
    compile vs_2_0 VSBasic(), compile vs_2_0 VSBasicVc(), compile vs_2_0 VSBasicTx(), compile vs_2_0 VSBasicTxVc(),
    compile vs_2_0 VSLit(), compile vs_2_0 VSLitVc(), compile vs_2_0 VSLitTx(), compile vs_2_0 VSLitTxVc(),
    compile vs_2_0 VSPixel(), compile vs_2_0 VSPixelVc(), compile vs_2_0 VSPixelTx(), compile vs_2_0 VSPixelTxVc(),
    compile vs_2_0 VSSkinnedLit(), compile vs_2_0 VSSkinnedPixel(),
};

PixelShader PSArray[6] =
{
    compile ps_2_0 PSBasic(), compile ps_2_0 PSBasicTx(), compile ps_2_0 PSLit(), compile ps_2_0 PSLitTx(),
    compile ps_2_0 PSPixel(), compile ps_2_0 PSPixelTx(),
};

static const int VSIndices[14] = { 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13 };
static const int PSIndices[14] = { 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 2, 4 };

technique BasicEffect
{
    pass
    {
        VertexShader = (VSArray[VSIndices[ShaderIndex]]);
        PixelShader = (PSArray[PSIndices[ShaderIndex]]);
    }
}
