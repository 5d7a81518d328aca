// multipass.fx: lighting in two passes, the classic multi-light scheme: pass Ambient lays
// down the ambient term and the depth buffer; pass Lights adds every light on top with
// additive blending, set by the pass's own render states (no help needed from the program).

float4x4 World : World;
float4x4 View : View;
float4x4 Projection : Projection;
float3 CameraPosition : CameraPosition;

struct Light
{
    float3 Position;  // world space
    float4 Color;
    float Range;
    int Enabled;
};

#define LIGHT_COUNT 3
Light Lights[LIGHT_COUNT];

float4 AmbientColor = {0.1, 0.1, 0.12, 1.0};
float4 DiffuseColor = {0.8, 0.8, 0.8, 1.0};
float Shininess = 24.0;

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

VertexOutput MultipassVS(float3 position : POSITION0, float3 normal : NORMAL0, float2 texCoord : TEXCOORD0)
{
    VertexOutput output;
    float4 worldPosition = mul(float4(position, 1.0), World);
    output.Position = mul(mul(worldPosition, View), Projection);
    output.WorldPosition = worldPosition.xyz;
    output.WorldNormal = mul(float4(normal, 0.0), World).xyz;
    output.TexCoord = texCoord;
    return output;
}

float4 AmbientPS(VertexOutput input) : COLOR0
{
    float4 color = AmbientColor * tex2D(DiffuseSampler, input.TexCoord);
    color.a = 1.0;
    return color;
}

float4 PointLight(Light light, float3 position, float3 N, float3 V, float4 surface)
{
    float3 toLight = light.Position - position;
    float d = length(toLight);
    float3 L = toLight / d;
    float diffuse = saturate(dot(N, L));
    float specular = diffuse > 0.0 ? pow(saturate(dot(normalize(L + V), N)), Shininess) : 0.0;
    float fade = saturate(1.0 - d / light.Range);
    return fade * light.Color * (surface * diffuse + specular);
}

float4 LightsPS(VertexOutput input) : COLOR0
{
    float4 surface = DiffuseColor * tex2D(DiffuseSampler, input.TexCoord);
    float3 N = normalize(input.WorldNormal);
    float3 V = normalize(CameraPosition - input.WorldPosition);
    float4 color = 0;
    for (int i = 0; i < LIGHT_COUNT; i++)
    {
        if (Lights[i].Enabled != 0)
            color += PointLight(Lights[i], input.WorldPosition, N, V, surface);
    }
    color.a = 1.0;
    return color;
}

technique Multipass
{
    pass Ambient
    {
        ZEnable = true;
        ZWriteEnable = true;
        AlphaBlendEnable = false;
        VertexShader = compile vs_3_0 MultipassVS();
        PixelShader = compile ps_3_0 AmbientPS();
    }
    pass Lights
    {
        ZWriteEnable = false;
        ZFunc = LessEqual;
        AlphaBlendEnable = true;
        SrcBlend = One;
        DestBlend = One;
        VertexShader = compile vs_3_0 MultipassVS();
        PixelShader = compile ps_3_0 LightsPS();
    }
}
