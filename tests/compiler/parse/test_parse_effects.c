/* The parser on the effect layer: techniques (any keyword spelling, anonymous, annotated),
 * passes, state assignments with every kind of value, sampler_state blocks. */
#include "parse_util.h"
#include "test.h"

static void technique_spellings(void) {
    tp_result *r = tp_parse("technique A { pass p0 { } }\n"
                            "Technique B { Pass P1 { } pass { } };\n"
                            "technique10 C { pass { SetVertexShader(CompileShader(vs_4_0, VS())); } }\n"
                            "technique11 D { }\n"
                            "technique { pass { } }\n"
                            "TECHNIQUE E < string Group = \"g\"; > { PASS x < int order = 2; > { } }\n"
                            "technique Technique { pass Pass { } }\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "technique A\n"
                       "  pass p0\n"
                       "technique B (Technique)\n"
                       "  pass P1\n"
                       "  pass <anonymous>\n"
                       "technique C (technique10)\n"
                       "  pass <anonymous>\n"
                       "    state SetVertexShader = SetVertexShader(CompileShader(vs_4_0, VS()))\n"
                       "technique D (technique11)\n"
                       "technique <anonymous>\n"
                       "  pass <anonymous>\n"
                       "technique E (TECHNIQUE)\n"
                       "  annotation string Group = \"g\"\n"
                       "  pass x\n"
                       "    annotation int order = 2\n"
                       "technique Technique\n"
                       "  pass Pass\n");
    CHECK_INT(r->ast->decl_count, 7);
    hfx_decl *anon = r->ast->decls[4];
    CHECK_INT(anon->kind, DECL_TECHNIQUE);
    CHECK(anon->name == NULL && anon->technique->name == NULL);
    CHECK_INT(anon->loc.line, 5); /* the keyword, for want of a name */
    CHECK_INT(anon->loc.col, 1);
    CHECK_INT(anon->technique->passes[0].loc.col, 13);
    hfx_decl *b = tp_find(r, "B");
    CHECK(b && b->loc.line == 2 && b->loc.col == 11);
    CHECK(b && b->technique->passes[0].loc.col == 20);
    tp_free(r);
}

static void state_values(void) {
    tp_result *r = tp_parse("#define VSP vs_3_0\n"
                            "technique T {\n"
                            "  pass P {\n"
                            "    Texture[0] = <tex>;\n"
                            "    CullMode = None;\n"
                            "    ZFunc = LessEqual;\n"
                            "    VertexShader = (vsArr[1]);\n"
                            "    PixelShader = NULL;\n"
                            "    ColorWriteEnable = Red | Green;\n"
                            "    ZEnable = true;\n"
                            "    SrcBlend = (srcBlendParam);\n"
                            "    VertexShader = compile vs_3_0 F(true, 2.0, float2(1,0));\n"
                            "    PixelShader = compile VSP G;\n"
                            "    MinFilter[1] = linear;\n"
                            "    BlendFactor = float4(1, 1, 1, 1);\n"
                            "    sampler[2] = (s);\n"
                            "  }\n"
                            "}\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "technique T\n"
                       "  pass P\n"
                       "    state Texture[0] = <tex>\n"
                       "    state CullMode = None\n"
                       "    state ZFunc = LessEqual\n"
                       "    state VertexShader = (vsArr[1])\n"
                       "    state PixelShader = NULL\n"
                       "    state ColorWriteEnable = (Red | Green)\n"
                       "    state ZEnable = true\n"
                       "    state SrcBlend = (srcBlendParam)\n"
                       "    state VertexShader = compile vs_3_0 F(true, 2.0, float2(1, 0))\n"
                       "    state PixelShader = compile vs_3_0 G()\n"
                       "    state MinFilter[1] = linear\n"
                       "    state BlendFactor = float4(1, 1, 1, 1)\n"
                       "    state sampler[2] = (s)\n");
    hfx_decl *t = tp_find(r, "T");
    if (t && t->technique->pass_count == 1 && t->technique->passes[0].state_count == 13) {
        hfx_state_assign *s = t->technique->passes[0].states;
        CHECK_INT(s[0].value->kind, EX_STATE_REF);
        CHECK_INT(s[0].index->ival, 0);
        CHECK_INT(s[0].loc.line, 4);
        CHECK_INT(s[0].loc.col, 5);
        CHECK_INT(s[3].value->kind, EX_INDEX);
        CHECK(s[3].value->parenthesized);
        CHECK_INT(s[4].value->kind, EX_NULL);
        CHECK_INT(s[8].value->kind, EX_COMPILE);
        CHECK_INT(s[8].value->arg_count, 3);
        CHECK_INT(s[8].value->loc.col, 35); /* the entry name, like a call */
    } else {
        CHECK(0);
    }
    tp_free(r);
}

static void sampler_state_forms(void) {
    tp_result *r = tp_parse("texture t;\n"
                            "sampler a = sampler_state { Texture = <t>; MipFilter = LINEAR; };\n"
                            "sampler2D b = sampler_state { texture = (t); AddressU[0] = Clamp; BorderColor = 0xFF00FF; };\n"
                            "samplerCUBE c { Texture = <t>; };\n"
                            "sampler2D f < string n = \"x\"; > { Texture = <t>; BorderColor = Texture; };\n"
                            "sampler d[2] = { sampler_state { Texture = <t>; }, sampler_state { } };\n"
                            "sampler e = sampler_state { };\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "var texture t\n"
                       "var sampler a = sampler_state { Texture = <t>; MipFilter = LINEAR; }\n"
                       "var sampler2D b = sampler_state { texture = (t); AddressU[0] = Clamp; BorderColor = 16711935; }\n"
                       "var samplerCUBE c = sampler_state { Texture = <t>; }\n"
                       "var sampler2D f = sampler_state { Texture = <t>; BorderColor = Texture; }\n"
                       "  annotation string n = \"x\"\n"
                       "var sampler[2] d = {sampler_state { Texture = <t>; }, sampler_state { }}\n"
                       "var sampler e = sampler_state { }\n");
    hfx_decl *a = tp_find(r, "a");
    CHECK(a && a->init->kind == EX_SAMPLER_STATE && a->init->state_count == 2);
    CHECK(a && a->init->loc.line == 2 && a->init->loc.col == 13);
    tp_free(r);
}

/* XNA/MonoGame accept the effect keywords in any case; elsewhere the words stay names. */
static void effect_keywords_in_any_case(void) {
    tp_result *r = tp_parse("texture t;\n"
                            "sampler s = SAMPLER_STATE { Texture = <t>; };\n"
                            "VertexShader asmVS = asm { vs_1_1\n mov oPos, v0 };\n"
                            "DWORD mask = 0xF;\n"
                            "float Compile = 1, Pass = 2;\n"
                            "TECHNIQUE T { PASS { VertexShader = Compile vs_2_0 F(); PixelShader = COMPILE ps_2_0 G(Pass); } }\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "var texture t\n"
                       "var sampler s = sampler_state { Texture = <t>; }\n"
                       "var vertexshader asmVS = asm { vs_1_1\nmov oPos , v0 }\n"
                       "var uint mask = 15\n"
                       "var float Compile = 1\n"
                       "var float Pass = 2\n"
                       "technique T (TECHNIQUE)\n"
                       "  pass <anonymous>\n"
                       "    state VertexShader = compile vs_2_0 F()\n"
                       "    state PixelShader = compile ps_2_0 G(Pass)\n");
    tp_free(r);
}

/* Fixed-function D3D9 passes: type spellings as state names and values (D3DTA_TEXTURE is
 * `Texture`), while `float4(...)` stays a constructor. */
static void fixed_function_states(void) {
    tp_result *r = tp_parse("float4x4 mWorld; texture tex;\n"
                            "technique FF { pass P0 < float3 v = {1, 2, 3}; > {\n"
                            "  Lighting = false; LightEnable[0] = true; LightType[0] = Directional;\n"
                            "  ColorOp[0] = Modulate; ColorArg1[0] = Texture; ColorArg2[0] = Diffuse;\n"
                            "  AlphaArg1[0] = Texture | AlphaReplicate; Texture[0] = <tex>;\n"
                            "  Sampler[0] = sampler_state { Texture = <tex>; }; WorldTransform[0] = <mWorld>;\n"
                            "  ColorArg1[1] = Texture;\n"
                            "  LightDiffuse[0] = float4(1, 1, 1, 1); FVF = XYZ | Normal | Tex1;\n"
                            "  VertexShader = NULL; PixelShader = NULL;\n"
                            "} }\n");
    CHECK_STR(r->errors, "");
    CHECK_STR(r->dump, "var float4x4 mWorld\n"
                       "var texture tex\n"
                       "technique FF\n"
                       "  pass P0\n"
                       "    annotation float3 v = {1, 2, 3}\n"
                       "    state Lighting = false\n"
                       "    state LightEnable[0] = true\n"
                       "    state LightType[0] = Directional\n"
                       "    state ColorOp[0] = Modulate\n"
                       "    state ColorArg1[0] = Texture\n"
                       "    state ColorArg2[0] = Diffuse\n"
                       "    state AlphaArg1[0] = (Texture | AlphaReplicate)\n"
                       "    state Texture[0] = <tex>\n"
                       "    state Sampler[0] = sampler_state { Texture = <tex>; }\n"
                       "    state WorldTransform[0] = <mWorld>\n"
                       "    state ColorArg1[1] = Texture\n"
                       "    state LightDiffuse[0] = float4(1, 1, 1, 1)\n"
                       "    state FVF = ((XYZ | Normal) | Tex1)\n"
                       "    state VertexShader = NULL\n"
                       "    state PixelShader = NULL\n");
    tp_free(r);
}

/* Shapes from FX Composer's templates and the DirectX SDK samples (written from memory of
 * their style): SAS annotations, semantics with annotations and initializers, uniform
 * parameters bound by compile, loops over light arrays. */
static void sdk_and_composer_styles(void) {
    tp_result *r = tp_parse(
        "float Script : STANDARDSGLOBAL < string UIWidget = \"none\"; string ScriptClass = \"object\";\n"
        "  string Script = \"Technique=Main;\"; > = 0.8;\n"
        "float4x4 WorldITXf : WorldInverseTranspose < string UIWidget = \"None\"; >;\n"
        "float3 Lamp0Pos : Position < string Object = \"PointLight0\"; string Space = \"World\"; > = {-0.5f,2.0f,1.25f};\n"
        "texture ColorTexture : DIFFUSE < string ResourceName = \"default_color.dds\"; string ResourceType = \"2D\"; >;\n"
        "sampler2D ColorSampler = sampler_state { Texture = <ColorTexture>; FILTER = MIN_MAG_MIP_LINEAR;\n"
        "  AddressU = Wrap; AddressV = Wrap; };\n"
        "float3 g_LightDir[3]; float4 g_LightDiffuse[3];\n"
        "struct VS_OUTPUT { float4 Position : POSITION; float4 Diffuse : COLOR0; float2 TextureUV : TEXCOORD0; };\n"
        "VS_OUTPUT RenderSceneVS(float4 vPos : POSITION, float3 vNormal : NORMAL, float2 vTexCoord0 : TEXCOORD0,\n"
        "                        uniform int nNumLights, uniform bool bTexture, uniform bool bAnimate) {\n"
        "  VS_OUTPUT Output; float3 vTotalLightDiffuse = float3(0,0,0);\n"
        "  for(int i=0; i<nNumLights; i++ )\n"
        "    vTotalLightDiffuse += g_LightDiffuse[i] * max(0,dot(vNormal, g_LightDir[i]));\n"
        "  Output.Position = vPos; Output.Diffuse.rgb = vTotalLightDiffuse; Output.Diffuse.a = 1.0f;\n"
        "  if( bTexture ) Output.TextureUV = vTexCoord0; else Output.TextureUV = 0;\n"
        "  return Output; }\n"
        "float4 RenderScenePS(VS_OUTPUT In, uniform bool bTexture) : COLOR0 {\n"
        "  return bTexture ? tex2D(ColorSampler, In.TextureUV) * In.Diffuse : In.Diffuse; }\n"
        "technique Main < string Script = \"Pass=p0;\"; > {\n"
        "  pass p0 < string Script = \"Draw=geometry;\"; > {\n"
        "    VertexShader = compile vs_2_0 RenderSceneVS(1, true, true);\n"
        "    ZEnable = true; ZWriteEnable = true; ZFunc = LessEqual; AlphaBlendEnable = false; CullMode = None;\n"
        "    PixelShader = compile ps_2_0 RenderScenePS(true);\n"
        "  }\n"
        "}\n");
    CHECK_STR(r->errors, "");
    hfx_decl *lamp = tp_find(r, "Lamp0Pos");
    CHECK(lamp && lamp->semantic && strcmp(lamp->semantic, "Position") == 0);
    CHECK(lamp && lamp->annotation_count == 2 && lamp->init && lamp->init->arg_count == 3);
    if (lamp && lamp->init && lamp->init->arg_count == 3) {
        CHECK_INT(lamp->init->args[0]->kind, EX_UNARY); /* -0.5f */
        CHECK_NEAR(lamp->init->args[2]->fval, 1.25, 1e-12);
    }
    hfx_decl *vs = tp_find(r, "RenderSceneVS");
    CHECK(vs && vs->func->param_count == 6 && vs->func->params[5]->mods == MOD_UNIFORM);
    hfx_decl *t = tp_find(r, "Main");
    CHECK(t && t->technique->annotation_count == 1 && t->technique->pass_count == 1);
    if (t && t->technique->pass_count == 1) {
        hfx_pass_ast *p = &t->technique->passes[0];
        CHECK_INT(p->annotation_count, 1);
        CHECK_STR(p->annotations[0].value->sval, "Draw=geometry;");
        CHECK_INT(p->state_count, 7);
        CHECK_INT(p->states[0].value->arg_count, 3);
    }
    tp_free(r);
}

int main(void) {
    RUN(technique_spellings);
    RUN(state_values);
    RUN(sampler_state_forms);
    RUN(effect_keywords_in_any_case);
    RUN(fixed_function_states);
    RUN(sdk_and_composer_styles);
    return test_summary();
}
