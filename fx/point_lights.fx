// point_lights.fx: up to MAX_LIGHTS point lights in one pass, handed over as parallel arrays
// (positions, colours, radii) plus a count, the way the XNA point-light tutorial fills them
// every frame. Light i fades as (1 - d / radius)^2 and is gone beyond its radius.

#define MAX_LIGHTS 50

float4x4 World : World;
float4x4 View : View;
float4x4 Projection : Projection;
float3 CameraPosition : CameraPosition;

int LightCount = 0;
float3 LightPosition[MAX_LIGHTS];
float4 LightColor[MAX_LIGHTS];
float LightRadius[MAX_LIGHTS];

float4 AmbientColor = {0.04, 0.04, 0.05, 1.0};
float4 SpecularColor = {1.0, 1.0, 1.0, 1.0};
float SpecularPower = 40.0;
float SpecularIntensity = 0.6;

texture DiffuseTexture;
sampler2D DiffuseSampler = sampler_state
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

VertexOutput PointLightsVS(float3 position : POSITION0, float3 normal : NORMAL0, float2 texCoord : TEXCOORD0)
{
    VertexOutput output;
    float4 worldPosition = mul(float4(position, 1.0), World);
    output.Position = mul(mul(worldPosition, View), Projection);
    output.WorldPosition = worldPosition.xyz;
    output.WorldNormal = mul(float4(normal, 0.0), World).xyz; // World is a rotation here
    output.TexCoord = texCoord;
    return output;
}

float4 PointLightsPS(VertexOutput input) : COLOR0
{
    float4 surface = tex2D(DiffuseSampler, input.TexCoord);
    float3 N = normalize(input.WorldNormal);
    float3 V = normalize(CameraPosition - input.WorldPosition);
    float4 color = AmbientColor * surface;
    for (int i = 0; i < LightCount; i++)
    {
        float3 toLight = LightPosition[i] - input.WorldPosition;
        float fade = 1.0 - saturate(length(toLight) / LightRadius[i]);
        float3 L = normalize(toLight);
        float diffuse = saturate(dot(N, L));
        float specular = diffuse > 0.0 ? pow(saturate(dot(reflect(-L, N), V)), SpecularPower) : 0.0;
        color += fade * fade * LightColor[i] * (surface * diffuse + SpecularIntensity * SpecularColor * specular);
    }
    color.a = 1.0;
    return color;
}

technique PointLights
{
    pass P0
    {
        VertexShader = compile vs_3_0 PointLightsVS();
        PixelShader = compile ps_3_0 PointLightsPS();
    }
}
