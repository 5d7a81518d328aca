// ambient.fx: the ambient lighting model, I = Ia * ka, with or without a texture. The two
// techniques compile the same pixel shader with a different `uniform bool`, which is how
// D3D9 effects make shader variants without branching at run time.

float4x4 World : World;
float4x4 View : View;
float4x4 Projection : Projection;

float4 AmbientColor
<
    string UIName = "Ambient colour";
    string UIWidget = "Color";
> = {0.35, 0.35, 0.4, 1.0};

texture DiffuseTexture < string UIName = "Texture"; >;
sampler DiffuseSampler = sampler_state
{
    Texture = <DiffuseTexture>;
    MinFilter = Linear;
    MagFilter = Linear;
    MipFilter = Linear;
    AddressU = Wrap;
    AddressV = Wrap;
};

struct VertexOutput
{
    float4 Position : POSITION0;
    float2 TexCoord : TEXCOORD0;
};

VertexOutput AmbientVS(float3 position : POSITION0, float2 texCoord : TEXCOORD0)
{
    VertexOutput output;
    float4x4 worldViewProjection = mul(World, mul(View, Projection));
    output.Position = mul(float4(position, 1.0), worldViewProjection);
    output.TexCoord = texCoord;
    return output;
}

float4 AmbientPS(float2 texCoord : TEXCOORD0, uniform bool textured) : COLOR0
{
    float4 color = AmbientColor;
    if (textured)
        color *= tex2D(DiffuseSampler, texCoord);
    color.a = 1.0;
    return color;
}

technique Textured
{
    pass P0
    {
        VertexShader = compile vs_3_0 AmbientVS();
        PixelShader = compile ps_3_0 AmbientPS(true);
    }
}

technique Material
{
    pass P0
    {
        VertexShader = compile vs_3_0 AmbientVS();
        PixelShader = compile ps_3_0 AmbientPS(false);
    }
}
