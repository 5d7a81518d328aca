// textured.fx: a textured mesh, the first effect of the XNA shader tutorial: each vertex goes
// from object to world to camera to projection space, and each pixel samples one texture.

float4x4 World;
float4x4 View;
float4x4 Projection;

texture DiffuseTexture;
sampler DiffuseSampler = sampler_state
{
    Texture = <DiffuseTexture>;
    MinFilter = Linear;
    MagFilter = Linear;
    MipFilter = Linear;
    AddressU = Wrap;
    AddressV = Wrap;
};

struct VertexInput
{
    float4 Position : POSITION0;
    float2 TexCoord : TEXCOORD0;
};

struct VertexOutput
{
    float4 Position : POSITION0;
    float2 TexCoord : TEXCOORD0;
};

VertexOutput TexturedVS(VertexInput input)
{
    VertexOutput output;
    float4 worldPosition = mul(input.Position, World);
    float4 viewPosition = mul(worldPosition, View);
    output.Position = mul(viewPosition, Projection);
    output.TexCoord = input.TexCoord;
    return output;
}

float4 TexturedPS(VertexOutput input) : COLOR0
{
    return tex2D(DiffuseSampler, input.TexCoord);
}

technique Textured
{
    pass P0
    {
        VertexShader = compile vs_2_0 TexturedVS();
        PixelShader = compile ps_2_0 TexturedPS();
    }
}
