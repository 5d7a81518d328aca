// shading_models.fx: the Phong lighting model evaluated per vertex (Gouraud shading) or per
// pixel (Phong shading), with Phong's reflection vector or Blinn's half vector, as in the
// WebGL lecture: everything in camera space, the normal matrix is the inverse transpose of
// the model-view matrix, and a light position with w = 0 is a direction towards the light.
// Techniques: Gouraud, GouraudBlinn, Phong, BlinnPhong.

float4x4 World : World;
float4x4 View : View;
float4x4 Projection : Projection;
float4x4 WorldViewIT : WorldViewInverseTranspose; // the normal matrix

float4 LightPosition = {0.0, 1.8, 1.3, 1.0}; // world space
float3 LightAmbient = {0.2, 0.2, 0.2};
float3 LightDiffuse = {0.7, 0.7, 0.7};
float3 LightSpecular = {1.0, 1.0, 1.0};
float3 MaterialAmbient = {1.0, 0.0, 0.0};
float3 MaterialDiffuse = {1.0, 0.0, 0.0};
float3 MaterialSpecular = {1.0, 1.0, 1.0};
float Shininess < float UIMin = 1.0; float UIMax = 128.0; > = 6.0;

// Unit vector from a camera-space point towards the light.
float3 ToLight(float3 posC)
{
    float4 lightC = mul(LightPosition, View);
    if (LightPosition.w == 0.0)
        return normalize(lightC.xyz);
    return normalize(lightC.xyz - posC);
}

// I = Ia ka + Id kd max(N.L, 0) + Is ks (R.V or N.H)^shininess, the specular term only
// where the light reaches the surface.
float3 Illuminate(float3 N, float3 L, float3 V, bool blinn)
{
    float diffuse = max(dot(L, N), 0.0);
    float specular = 0.0;
    if (diffuse > 0.0)
    {
        if (blinn)
            specular = pow(max(dot(N, normalize(L + V)), 0.0), Shininess);
        else
            specular = pow(max(dot(reflect(-L, N), V), 0.0), Shininess);
    }
    return LightAmbient * MaterialAmbient + diffuse * LightDiffuse * MaterialDiffuse +
           specular * LightSpecular * MaterialSpecular;
}

struct GouraudOutput
{
    float4 Position : POSITION0;
    float4 Color : COLOR0;
};

GouraudOutput GouraudVS(float4 position : POSITION0, float3 normal : NORMAL0, uniform bool blinn)
{
    GouraudOutput output;
    float4 posC = mul(mul(position, World), View);
    float3 N = normalize(mul(float4(normal, 0.0), WorldViewIT).xyz);
    float3 V = normalize(-posC.xyz); // the camera is at the origin of its own space
    output.Color = float4(Illuminate(N, ToLight(posC.xyz), V, blinn), 1.0);
    output.Position = mul(posC, Projection);
    return output;
}

float4 GouraudPS(float4 color : COLOR0) : COLOR0
{
    return color; // interpolated across the triangle: highlights smear between vertices
}

struct PhongOutput
{
    float4 Position : POSITION0;
    float3 PosC : TEXCOORD0;
    float3 NormalC : TEXCOORD1;
};

PhongOutput PhongVS(float4 position : POSITION0, float3 normal : NORMAL0)
{
    PhongOutput output;
    float4 posC = mul(mul(position, World), View);
    output.PosC = posC.xyz;
    output.NormalC = mul(float4(normal, 0.0), WorldViewIT).xyz;
    output.Position = mul(posC, Projection);
    return output;
}

float4 PhongPS(PhongOutput input, uniform bool blinn) : COLOR0
{
    float3 N = normalize(input.NormalC); // interpolation shortens normals: renormalise
    float3 V = normalize(-input.PosC);
    return float4(Illuminate(N, ToLight(input.PosC), V, blinn), 1.0);
}

technique Gouraud
{
    pass P0
    {
        VertexShader = compile vs_3_0 GouraudVS(false);
        PixelShader = compile ps_3_0 GouraudPS();
    }
}

technique GouraudBlinn
{
    pass P0
    {
        VertexShader = compile vs_3_0 GouraudVS(true);
        PixelShader = compile ps_3_0 GouraudPS();
    }
}

technique Phong
{
    pass P0
    {
        VertexShader = compile vs_3_0 PhongVS();
        PixelShader = compile ps_3_0 PhongPS(false);
    }
}

technique BlinnPhong
{
    pass P0
    {
        VertexShader = compile vs_3_0 PhongVS();
        PixelShader = compile ps_3_0 PhongPS(true);
    }
}
