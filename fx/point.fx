// point.fx: a point light that fades with distance, att = 1 / (c + l d + q d^2), and reaches
// nothing beyond Range. Diffuse and specular per pixel, in world space.

float4x4 World : World;
float4x4 View : View;
float4x4 Projection : Projection;
float4x4 WorldInverseTranspose : WorldInverseTranspose;
float3 CameraPosition : CameraPosition;

float3 LightPosition = {1.5, 2.0, 2.0};
float4 LightColor = {1.0, 0.95, 0.85, 1.0};
float AttenuationConstant = 1.0;
float AttenuationLinear = 0.1;
float AttenuationQuadratic = 0.05;
float Range = 20.0;

float4 AmbientColor = {0.06, 0.06, 0.08, 1.0};
float4 DiffuseColor = {0.35, 0.55, 0.85, 1.0};
float4 SpecularColor = {1.0, 1.0, 1.0, 1.0};
float SpecularPower = 48.0;

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

struct VertexOutput
{
    float4 Position : POSITION0;
    float2 TexCoord : TEXCOORD0;
    float3 WorldNormal : TEXCOORD1;
    float3 WorldPosition : TEXCOORD2;
};

VertexOutput PointVS(float3 position : POSITION0, float3 normal : NORMAL0, float2 texCoord : TEXCOORD0)
{
    VertexOutput output;
    float4 worldPosition = mul(float4(position, 1.0), World);
    output.Position = mul(mul(worldPosition, View), Projection);
    output.WorldPosition = worldPosition.xyz;
    output.WorldNormal = mul(float4(normal, 0.0), WorldInverseTranspose).xyz;
    output.TexCoord = texCoord;
    return output;
}

float Attenuation(float d)
{
    if (d > Range)
        return 0.0;
    return min(1.0 / (AttenuationConstant + AttenuationLinear * d + AttenuationQuadratic * d * d), 1.0);
}

float4 PointPS(VertexOutput input, uniform bool textured) : COLOR0
{
    float3 toLight = LightPosition - input.WorldPosition;
    float3 N = normalize(input.WorldNormal);
    float3 L = normalize(toLight);
    float3 V = normalize(CameraPosition - input.WorldPosition);
    float diffuse = saturate(dot(N, L));
    float specular = diffuse > 0.0 ? pow(saturate(dot(reflect(-L, N), V)), SpecularPower) : 0.0;

    float4 surface = DiffuseColor;
    if (textured)
        surface *= tex2D(DiffuseSampler, input.TexCoord);
    float att = Attenuation(length(toLight));
    float4 color = AmbientColor * surface + att * LightColor * (surface * diffuse + SpecularColor * specular);
    color.a = 1.0;
    return color;
}

technique Textured
{
    pass P0
    {
        VertexShader = compile vs_3_0 PointVS();
        PixelShader = compile ps_3_0 PointPS(true);
    }
}

technique Material
{
    pass P0
    {
        VertexShader = compile vs_3_0 PointVS();
        PixelShader = compile ps_3_0 PointPS(false);
    }
}
