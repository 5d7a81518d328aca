// spot.fx: a spot light: full strength inside InnerAngle of the axis from LightPosition to
// LightTarget, nothing outside OuterAngle, and in between ((cos a - cos outer) /
// (cos inner - cos outer)) ^ Falloff. Angles are half-angles in radians.

float4x4 World : World;
float4x4 View : View;
float4x4 Projection : Projection;
float4x4 WorldInverseTranspose : WorldInverseTranspose;
float3 CameraPosition : CameraPosition;

float3 LightPosition = {0.0, 4.0, 1.0};
float3 LightTarget = {0.0, 0.0, 0.0};
float4 LightColor = {1.0, 1.0, 0.9, 1.0};
float InnerAngle = 0.12;
float OuterAngle = 0.22;
float Falloff = 1.0;

float4 AmbientColor = {0.05, 0.05, 0.07, 1.0};
float4 DiffuseColor = {0.85, 0.85, 0.85, 1.0};
float4 SpecularColor = {0.6, 0.6, 0.6, 1.0};
float SpecularPower = 32.0;

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

VertexOutput SpotVS(float3 position : POSITION0, float3 normal : NORMAL0, float2 texCoord : TEXCOORD0)
{
    VertexOutput output;
    float4 worldPosition = mul(float4(position, 1.0), World);
    output.Position = mul(mul(worldPosition, View), Projection);
    output.WorldPosition = worldPosition.xyz;
    output.WorldNormal = mul(float4(normal, 0.0), WorldInverseTranspose).xyz;
    output.TexCoord = texCoord;
    return output;
}

float ConeAttenuation(float3 L)
{
    float3 axis = normalize(LightPosition - LightTarget); // from the target back to the light
    float cosAlpha = dot(axis, L);
    float cosInner = cos(InnerAngle);
    float cosOuter = cos(OuterAngle);
    if (cosAlpha >= cosInner)
        return 1.0;
    if (cosAlpha <= cosOuter)
        return 0.0;
    return pow((cosAlpha - cosOuter) / (cosInner - cosOuter), Falloff);
}

float4 SpotPS(VertexOutput input, uniform bool textured) : COLOR0
{
    float3 N = normalize(input.WorldNormal);
    float3 L = normalize(LightPosition - input.WorldPosition);
    float3 V = normalize(CameraPosition - input.WorldPosition);
    float diffuse = saturate(dot(N, L));
    float specular = diffuse > 0.0 ? pow(saturate(dot(reflect(-L, N), V)), SpecularPower) : 0.0;

    float4 surface = DiffuseColor;
    if (textured)
        surface *= tex2D(DiffuseSampler, input.TexCoord);
    float cone = ConeAttenuation(L);
    float4 color = AmbientColor * surface + cone * LightColor * (surface * diffuse + SpecularColor * specular);
    color.a = 1.0;
    return color;
}

technique Textured
{
    pass P0
    {
        VertexShader = compile vs_3_0 SpotVS();
        PixelShader = compile ps_3_0 SpotPS(true);
    }
}

technique Material
{
    pass P0
    {
        VertexShader = compile vs_3_0 SpotVS();
        PixelShader = compile ps_3_0 SpotPS(false);
    }
}
