// directional.fx: one directional light (the sun), Lambert diffuse plus Phong specular,
// computed per pixel in world space. Techniques: Textured and Material (no texture).

float4x4 World : World;
float4x4 View : View;
float4x4 Projection : Projection;
float4x4 WorldInverseTranspose : WorldInverseTranspose; // turns normals into world space
float3 CameraPosition : CameraPosition;

float3 LightDirection = {-0.5, -0.8, -0.6}; // where the light travels, in world space
float4 LightColor = {1.0, 1.0, 1.0, 1.0};
float4 AmbientColor = {0.08, 0.08, 0.1, 1.0};
float4 DiffuseColor = {0.9, 0.72, 0.45, 1.0};
float4 SpecularColor = {1.0, 1.0, 1.0, 1.0};
float SpecularPower < float UIMin = 1.0; float UIMax = 128.0; > = 32.0;

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

VertexOutput DirectionalVS(float3 position : POSITION0, float3 normal : NORMAL0, float2 texCoord : TEXCOORD0)
{
    VertexOutput output;
    float4 worldPosition = mul(float4(position, 1.0), World);
    output.Position = mul(mul(worldPosition, View), Projection);
    output.WorldPosition = worldPosition.xyz;
    output.WorldNormal = mul(float4(normal, 0.0), WorldInverseTranspose).xyz;
    output.TexCoord = texCoord;
    return output;
}

float4 DirectionalPS(VertexOutput input, uniform bool textured) : COLOR0
{
    float3 N = normalize(input.WorldNormal);
    float3 L = -normalize(LightDirection);
    float3 V = normalize(CameraPosition - input.WorldPosition);
    float diffuse = saturate(dot(N, L));
    float3 R = reflect(-L, N);
    float specular = diffuse > 0.0 ? pow(saturate(dot(R, V)), SpecularPower) : 0.0;

    float4 surface = DiffuseColor;
    if (textured)
        surface *= tex2D(DiffuseSampler, input.TexCoord);
    float4 color = AmbientColor * surface + LightColor * (surface * diffuse + SpecularColor * specular);
    color.a = 1.0;
    return color;
}

technique Textured
{
    pass P0
    {
        VertexShader = compile vs_3_0 DirectionalVS();
        PixelShader = compile ps_3_0 DirectionalPS(true);
    }
}

technique Material
{
    pass P0
    {
        VertexShader = compile vs_3_0 DirectionalVS();
        PixelShader = compile ps_3_0 DirectionalPS(false);
    }
}
