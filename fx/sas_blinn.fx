/*
% A Blinn-Phong material written the way FX Composer's material templates are: every input
% is bound by its semantic (SAS), so a viewer fills the matrices and the eye position itself.

keywords: material classic
*/

float4x4 WorldITXf : WorldInverseTranspose < string UIWidget = "None"; >;
float4x4 WvpXf : WorldViewProjection < string UIWidget = "None"; >;
float4x4 WorldXf : World < string UIWidget = "None"; >;
float4x4 ViewIXf : ViewInverse < string UIWidget = "None"; >;

float3 Lamp0Pos : Position
<
    string Object = "PointLight0";
    string UIName = "Lamp 0 Position";
    string Space = "World";
> = {0.0, 0.0, 10.0};

float3 Lamp0Color : Specular < string UIName = "Lamp 0"; string UIWidget = "Color"; > = {1.0, 1.0, 1.0};
float3 AmbiColor : Ambient < string UIName = "Ambient Light"; string UIWidget = "Color"; > = {0.1, 0.1, 0.1};
float3 SurfaceColor : Diffuse < string UIName = "Surface"; string UIWidget = "Color"; > = {0.8, 0.2, 0.2};
float Ks < string UIWidget = "slider"; float UIMin = 0.0; float UIMax = 1.0; float UIStep = 0.05; > = 0.4;
float SpecExpon : SpecularPower < string UIWidget = "slider"; float UIMin = 1.0; float UIMax = 128.0; > = 30.0;

struct AppData
{
    float3 Position : POSITION;
    float3 Normal : NORMAL;
};

struct VertexOutput
{
    float4 HPosition : POSITION;
    float3 WorldNormal : TEXCOORD0;
    float3 LightVec : TEXCOORD1;
    float3 WorldView : TEXCOORD2;
};

VertexOutput std_VS(AppData IN)
{
    VertexOutput OUT;
    float4 Po = float4(IN.Position.xyz, 1.0);
    float3 Pw = mul(Po, WorldXf).xyz;
    OUT.WorldNormal = mul(float4(IN.Normal, 0.0), WorldITXf).xyz;
    OUT.LightVec = Lamp0Pos - Pw;
    OUT.WorldView = ViewIXf[3].xyz - Pw; // the camera sits in the inverse view's last row
    OUT.HPosition = mul(Po, WvpXf);
    return OUT;
}

float4 blinn_PS(VertexOutput IN) : COLOR
{
    float3 N = normalize(IN.WorldNormal);
    float3 L = normalize(IN.LightVec);
    float3 V = normalize(IN.WorldView);
    float3 H = normalize(L + V);
    float diffuse = saturate(dot(N, L));
    float specular = diffuse > 0.0 ? Ks * pow(saturate(dot(N, H)), SpecExpon) : 0.0;
    float3 color = AmbiColor + SurfaceColor * diffuse * Lamp0Color + specular * Lamp0Color;
    return float4(color, 1.0);
}

technique Main
{
    pass p0
    {
        VertexShader = compile vs_3_0 std_VS();
        ZEnable = true;
        ZWriteEnable = true;
        CullMode = None;
        PixelShader = compile ps_3_0 blinn_PS();
    }
}
