/* The effect builder on small sources: default values folded from initializers, annotations,
 * pass and sampler states with D3D9's numbers, shader variables and arrays, and the located
 * errors for what cannot be built. Expected numbers are worked out by hand in the comments. */
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "hfx/hfxc.h"
#include "states.h"
#include "test.h"

static hfxc_result *compile(const char *src) {
    return hfxc_compile_memory(src, strlen(src), "t.fx", NULL);
}

static const hfx_fx_effect *effect_of(hfxc_result *r) {
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    if (!fx) {
        char *text = hfxc_diagnostics_text(r);
        fprintf(stderr, "did not build:\n%s", text);
        free(text);
    }
    return fx;
}

static float fword(uint32_t w) {
    float f;
    memcpy(&f, &w, sizeof f);
    return f;
}

static const hfx_fx_param *param(const hfx_fx_effect *fx, const char *name) {
    uint32_t i = hfx_fx_param_find(fx, name);
    if (i == HFX_NONE) fprintf(stderr, "no parameter '%s'\n", name);
    return i == HFX_NONE ? &fx->params[0] : &fx->params[i];
}

static float pf(const hfx_fx_effect *fx, const char *name, uint32_t k) { return fword(fx->values[param(fx, name)->offset + k]); }
static int32_t pi(const hfx_fx_effect *fx, const char *name, uint32_t k) { return (int32_t)fx->values[param(fx, name)->offset + k]; }

static uint32_t state_id(const char *name) {
    const hfx_state_info *info = hfx_state_lookup(name);
    return info ? info->id : 0xdeadu;
}

static void defaults_are_folded(void) {
    hfxc_result *r = compile(
        "float a = -2.5;\n"
        "float4 v = float4(1, 2, 3, 4) * 2;\n"
        "int i = 7 / 2;\n"
        "int j = -(3 + 4);\n"
        "bool b = true;\n"
        "float2 h = 0.5;\n"
        "float3x2 m = {1, 2, 3, 4, 5, 6};\n"
        "static const float K = 3;\n"
        "float k2 = K * 2;\n"
        "int2 iv = {1, -1};\n"
        "float arr[3] = {1, 2, 3};\n"
        "struct S { float x; int y; float2 z; };\n"
        "S st = {1.5, 2, 3, 4};\n"
        "float none;\n"
        "float ks = {0.05F};\n"
        "float4 hexmix = {0x10, 1e1, .5, 2.};\n"
        "float folded = sqrt(16) + pow(2, 3) + max(1, -4) + radians(180) + saturate(1.5);\n"
        "float3 mins = min(float3(1, 5, -2), 2);\n");
    const hfx_fx_effect *fx = effect_of(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    CHECK_INT(fx->top_param_count, 16); /* K is static: not a parameter */
    CHECK_INT(hfx_fx_param_find(fx, "K"), HFX_NONE);
    CHECK_NEAR(pf(fx, "a", 0), -2.5, 0);
    for (int k = 0; k < 4; k++) CHECK_NEAR(pf(fx, "v", (uint32_t)k), 2.0 * (k + 1), 0);
    CHECK_INT(pi(fx, "i", 0), 3);  /* integer division */
    CHECK_INT(pi(fx, "j", 0), -7);
    CHECK_INT(pi(fx, "b", 0), 1);
    CHECK_NEAR(pf(fx, "h", 0), 0.5, 0);
    CHECK_NEAR(pf(fx, "h", 1), 0.5, 0);
    const hfx_fx_param *m = param(fx, "m");
    CHECK_INT(m->rows, 3);
    CHECK_INT(m->cols, 2);
    for (int k = 0; k < 6; k++) CHECK_NEAR(pf(fx, "m", (uint32_t)k), k + 1, 0); /* row-major: _11 _12 _21 ... */
    CHECK_NEAR(pf(fx, "k2", 0), 6.0, 0);
    CHECK_INT(pi(fx, "iv", 0), 1);
    CHECK_INT(pi(fx, "iv", 1), -1);
    CHECK_INT(param(fx, "arr")->elements, 3);
    for (int k = 0; k < 3; k++) CHECK_NEAR(pf(fx, "arr", (uint32_t)k), k + 1, 0);
    const hfx_fx_param *st = param(fx, "st");
    CHECK_INT(st->klass, HFX_CLASS_STRUCT);
    CHECK_INT(st->words, 4);
    CHECK_NEAR(pf(fx, "st", 0), 1.5, 0);
    CHECK_INT(pi(fx, "st", 1), 2); /* the int member is stored as int32 */
    CHECK_NEAR(pf(fx, "st", 2), 3.0, 0);
    CHECK_NEAR(pf(fx, "st", 3), 4.0, 0);
    CHECK_INT(st->child_count, 3);
    CHECK_STR(fx->params[st->first_child + 2].name, "z");
    CHECK_INT(fx->params[st->first_child + 2].offset, st->offset + 2);
    CHECK_INT(pi(fx, "none", 0), 0);
    CHECK_NEAR(pf(fx, "ks", 0), 0.05, 1e-7);
    CHECK_NEAR(pf(fx, "hexmix", 0), 16, 0);
    CHECK_NEAR(pf(fx, "hexmix", 1), 10, 0);
    CHECK_NEAR(pf(fx, "hexmix", 2), 0.5, 0);
    CHECK_NEAR(pf(fx, "hexmix", 3), 2, 0);
    CHECK_NEAR(pf(fx, "folded", 0), 4 + 8 + 1 + 3.14159265 + 1, 1e-5); /* folded like fxc does */
    CHECK_NEAR(pf(fx, "mins", 0), 1, 0);
    CHECK_NEAR(pf(fx, "mins", 1), 2, 0);
    CHECK_NEAR(pf(fx, "mins", 2), -2, 0);
done:
    hfxc_result_free(r);
}

/* Initializers fold with common/eval, Direct3D's rules: vector intrinsics, 32-bit int wrap,
 * int -> uint keeping the bits, shifts by the low 5 bits, round as floor(x + 0.5), pow on |x|. */
static void intrinsics_and_d3d_rules_fold(void) {
    hfxc_result *r = compile(
        "float3 L = normalize(float3(1, 1, -1));\n"
        "static const float3 Dir = float3(0, 3, 4);\n"
        "float3 L2 = normalize(Dir) * 2;\n"
        "float d = dot(float3(1, 2, 3), float3(4, 5, 6));\n"
        "float len = length(float2(3, 4)) + distance(float2(1, 1), float2(4, 5));\n"
        "float3 c = cross(float3(1, 0, 0), float3(0, 1, 0));\n"
        "uint u = -1;\n"
        "int big = 4294967295;\n"
        "int wrap = 2147483647 + 1;\n"
        "int sh = 1 << 33;\n"
        "float rnd = round(-2.5);\n"
        "float p = pow(-2, 2);\n"
        "float lerped = lerp(2, 4, 0.25) + smoothstep(0, 1, 0.5) + step(0.5, 0.25);\n");
    const hfx_fx_effect *fx = effect_of(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    float k = (float)(1.0 / 1.7320508075688772); /* 1 / sqrt(3), in single precision */
    CHECK_NEAR(pf(fx, "L", 0), k, 0);
    CHECK_NEAR(pf(fx, "L", 1), k, 0);
    CHECK_NEAR(pf(fx, "L", 2), -k, 0);
    CHECK_NEAR(pf(fx, "L2", 0), 0, 0);
    CHECK_NEAR(pf(fx, "L2", 1), (float)0.6 * 2, 0); /* (0, 3, 4) / 5 */
    CHECK_NEAR(pf(fx, "L2", 2), (float)0.8 * 2, 0);
    CHECK_NEAR(pf(fx, "d", 0), 32, 0); /* 4 + 10 + 18 */
    CHECK_NEAR(pf(fx, "len", 0), 10, 0); /* 5 + 5 */
    CHECK_NEAR(pf(fx, "c", 2), 1, 0);
    CHECK_INT(fx->values[param(fx, "u")->offset], 4294967295u);
    CHECK_INT(pi(fx, "big", 0), -1);
    CHECK_INT(pi(fx, "wrap", 0), INT32_MIN);
    CHECK_INT(pi(fx, "sh", 0), 2);
    CHECK_NEAR(pf(fx, "rnd", 0), -2, 0);
    CHECK_NEAR(pf(fx, "p", 0), 4, 0);
    CHECK_NEAR(pf(fx, "lerped", 0), 2.5 + 0.5 + 0, 0);
done:
    hfxc_result_free(r);
}

/* Fixed-function states bound to array elements, as DirectX 9 effects write them:
 * `LightPosition[1] = <g_vLightPos[1]>;` reads element 1 of the parameter array. */
static void indexed_states_bound_to_elements(void) {
    hfxc_result *r = compile(
        "float4 g_vLightPos[2];\n"
        "float4 ps() : COLOR { return 1; }\n"
        "technique T { pass P { LightPosition[0] = <g_vLightPos[0]>; LightPosition[1] = <g_vLightPos[1]>;\n"
        "  PixelShader = compile ps_2_0 ps(); } }\n");
    const hfx_fx_effect *fx = effect_of(r);
    CHECK(fx != NULL);
    if (fx) {
        const hfx_fx_param *arr = param(fx, "g_vLightPos");
        const hfx_fx_state *st = &fx->states[fx->passes[0].first_state];
        CHECK_INT(st[0].kind, HFX_FX_VALUE_PARAM);
        CHECK_INT(st[0].index, 0);
        CHECK_INT(st[0].ref, arr->first_child);
        CHECK_INT(st[1].index, 1);
        CHECK_INT(st[1].ref, arr->first_child + 1);
    }
    hfxc_result_free(r);
}

static void check_error(const char *src, const char *expected);

/* fxc checks that every path returns after `compile ps_3_0 PS(1)` has fixed the uniform
 * parameters: PS(1) returns on every path, PS(2) falls off the end (X3507 at PS). */
static void returns_checked_per_pass(void) {
    const char *ok_src = "float4 PS(uniform int mode) : COLOR { if (mode == 0) return 1; else if (mode == 1) return 0.5; }\n"
                         "technique A { pass P { PixelShader = compile ps_3_0 PS(1); } }\n";
    hfxc_result *r = compile(ok_src);
    CHECK(effect_of(r) != NULL);
    hfxc_result_free(r);
    check_error("float4 PS(uniform int mode) : COLOR { if (mode == 0) return 1; else if (mode == 1) return 0.5; }\n"
                "technique B { pass P { PixelShader = compile ps_3_0 PS(2); } }\n",
                "t.fx(1,8): error X3507: 'PS': Not all control paths return a value");
}

static void objects_and_strings(void) {
    hfxc_result *r = compile(
        "string Description = \"two \" \"parts\";\n"
        "texture t;\n"
        "textureCUBE env;\n"
        "sampler3D vol;\n"
        "shared float4 tint : DIFFUSE;\n"
        "row_major float4x4 rm;\n"
        "float gl_thing;\n");
    const hfx_fx_effect *fx = effect_of(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    const hfx_fx_param *d = param(fx, "Description");
    CHECK_INT(d->klass, HFX_CLASS_OBJECT);
    CHECK_INT(d->type, HFX_TYPE_STRING);
    CHECK_STR(d->string, "two parts");
    CHECK(d->glsl_name == NULL);
    CHECK_INT(param(fx, "t")->type, HFX_TYPE_TEXTURE);
    CHECK_INT(param(fx, "env")->type, HFX_TYPE_TEXTURECUBE);
    const hfx_fx_param *vol = param(fx, "vol");
    CHECK_INT(vol->type, HFX_TYPE_SAMPLER3D);
    CHECK(vol->sampler != HFX_NONE);
    if (vol->sampler != HFX_NONE) {
        CHECK_INT(fx->samplers[vol->sampler].dim, HFX_FX_DIM_3D);
        CHECK_INT(fx->samplers[vol->sampler].texture_param, HFX_NONE);
        CHECK_INT(fx->samplers[vol->sampler].state_count, 0);
    }
    CHECK_INT(param(fx, "tint")->flags, HFX_FX_PARAM_SHARED);
    CHECK_STR(param(fx, "tint")->semantic, "DIFFUSE");
    CHECK_INT(param(fx, "rm")->flags, HFX_FX_PARAM_ROW_MAJOR);
    CHECK_STR(param(fx, "gl_thing")->glsl_name, "hfx_gl_thing"); /* GLSL reserves gl_ */
    CHECK_INT(fx->technique_count, 0);
done:
    hfxc_result_free(r);
}

static void annotations_of_every_kind(void) {
    hfxc_result *r = compile(
        "float x <\n"
        "    string UIName = \"Joined \" \"name\";\n"
        "    int Count = -3;\n"
        "    float3 Dir = {1, 2, 3};\n"
        "    bool Hidden = true;\n"
        "    float4 C = float4(0.1, 0.2, 0.3, 0.4);\n"
        "    float Half = 1.0 / 2;\n"
        "> = 1;\n");
    const hfx_fx_effect *fx = effect_of(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    const hfx_fx_param *x = param(fx, "x");
    CHECK_INT(x->annotation_count, 6);
    const hfx_fx_annotation *a = &fx->annotations[x->first_annotation];
    CHECK_STR(a[0].name, "UIName");
    CHECK_STR(a[0].string, "Joined name");
    CHECK_INT(a[1].type, HFX_TYPE_INT);
    CHECK_INT(a[1].klass, HFX_CLASS_SCALAR);
    CHECK_INT((int32_t)a[1].data[0], -3);
    CHECK_INT(a[2].klass, HFX_CLASS_VECTOR);
    CHECK_INT(a[2].cols, 3);
    CHECK_INT(a[2].count, 3);
    CHECK_NEAR(fword(a[2].data[2]), 3.0, 0);
    CHECK_INT(a[3].type, HFX_TYPE_BOOL);
    CHECK_INT(a[3].data[0], 1);
    CHECK_NEAR(fword(a[4].data[1]), 0.2, 1e-7);
    CHECK_NEAR(fword(a[5].data[0]), 0.5, 0);
done:
    hfxc_result_free(r);
}

static void pass_states_resolve(void) {
    hfxc_result *r = compile(
        "bool blend = true;\n"
        "texture t;\n"
        "float4 fog = {1, 0, 0, 1};\n"
        "technique T < string Purpose = \"test\"; >\n"
        "{\n"
        "    pass P < int Order = 2; >\n"
        "    {\n"
        "        CullMode = CW;\n"
        "        ZEnable = true;\n"
        "        AlphaRef = 0x80;\n"
        "        srcblend = SRCALPHA;\n"
        "        ColorWriteEnable = Red | Green;\n"
        "        AlphaBlendEnable = <blend>;\n"
        "        Texture[1] = <t>;\n"
        "        MinFilter[2] = Point;\n"
        "        BlendFactor = float4(0.25, 0.5, 0.75, 1);\n"
        "        FogStart = 0.5;\n"
        "        ZWriteEnable = FALSE;\n"
        "        DestBlend = D3DBLEND_INVSRCALPHA;\n"
        "    }\n"
        "    pass { FogColor = (fog); }\n"
        "}\n");
    const hfx_fx_effect *fx = effect_of(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    CHECK_INT(fx->technique_count, 1);
    CHECK_INT(fx->techniques[0].annotation_count, 1);
    CHECK_STR(fx->annotations[fx->techniques[0].first_annotation].string, "test");
    CHECK_INT(fx->pass_count, 2);
    const hfx_fx_pass *p = &fx->passes[0];
    CHECK_STR(p->name, "P");
    CHECK_INT(p->annotation_count, 1);
    CHECK_INT((int32_t)fx->annotations[p->first_annotation].data[0], 2);
    CHECK_INT(p->program, HFX_NONE);
    CHECK_INT(p->state_count, 12);
    const hfx_fx_state *s = &fx->states[p->first_state];
    static const char *const names[] = {"CullMode", "ZEnable", "AlphaRef", "SrcBlend", "ColorWriteEnable",
                                        "AlphaBlendEnable", "Texture", "MinFilter", "BlendFactor", "FogStart",
                                        "ZWriteEnable", "DestBlend"};
    for (int i = 0; i < 12; i++) CHECK_INT(s[i].id, state_id(names[i]));
    CHECK_INT(s[0].kind, HFX_FX_VALUE_INT);
    CHECK_INT(s[0].i, 2);   /* D3DCULL_CW */
    CHECK_INT(s[0].line, 8);
    CHECK_INT(s[0].col, 9);
    CHECK_INT(s[1].i, 1);
    CHECK_INT(s[2].i, 128);
    CHECK_INT(s[3].i, 5);   /* D3DBLEND_SRCALPHA */
    CHECK_INT(s[4].i, 3);   /* RED 1 | GREEN 2 */
    CHECK_INT(s[5].kind, HFX_FX_VALUE_PARAM);
    CHECK_INT(s[5].ref, hfx_fx_param_find(fx, "blend"));
    CHECK_INT(s[6].kind, HFX_FX_VALUE_PARAM);
    CHECK_INT(s[6].ref, hfx_fx_param_find(fx, "t"));
    CHECK_INT(s[6].index, 1);
    CHECK_INT(s[7].index, 2);
    CHECK_INT(s[7].i, 1);   /* D3DTEXF_POINT */
    CHECK_INT(s[8].kind, HFX_FX_VALUE_FLOAT);
    CHECK_INT(s[8].count, 4);
    CHECK_NEAR(s[8].f[1], 0.5, 0);
    CHECK_INT(s[9].kind, HFX_FX_VALUE_FLOAT);
    CHECK_INT(s[9].count, 1);
    CHECK_NEAR(s[9].f[0], 0.5, 0);
    CHECK_INT(s[10].i, 0);
    CHECK_INT(s[11].i, 6);  /* D3DBLEND_INVSRCALPHA */
    const hfx_fx_pass *anon = &fx->passes[1];
    CHECK_STR(anon->name, "");
    CHECK_INT(anon->state_count, 1);
    CHECK_INT(fx->states[anon->first_state].kind, HFX_FX_VALUE_PARAM);
    CHECK_INT(fx->states[anon->first_state].ref, hfx_fx_param_find(fx, "fog"));
done:
    hfxc_result_free(r);
}

static void sampler_arrays(void) {
    hfxc_result *r = compile(
        "texture a; texture b;\n"
        "sampler s[2] = { sampler_state { Texture = <a>; AddressU = Mirror; },\n"
        "                 sampler_state { Texture = <b>; MaxAnisotropy = 8; } };\n");
    const hfx_fx_effect *fx = effect_of(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    const hfx_fx_param *s = param(fx, "s");
    CHECK_INT(s->elements, 2);
    CHECK_INT(s->sampler, HFX_NONE);
    CHECK_INT(fx->sampler_count, 2);
    for (uint32_t e = 0; e < 2 && e < s->child_count; e++) {
        const hfx_fx_param *el = &fx->params[s->first_child + e];
        CHECK_INT(el->sampler, e);
        CHECK_INT(fx->samplers[e].param, s->first_child + e);
        CHECK_INT(fx->samplers[e].texture_param, hfx_fx_param_find(fx, e ? "b" : "a"));
        CHECK_INT(fx->samplers[e].state_count, 1);
    }
    CHECK_INT(fx->states[fx->samplers[0].first_state].i, 2); /* D3DTADDRESS_MIRROR */
    CHECK_INT(fx->states[fx->samplers[1].first_state].i, 8);
done:
    hfxc_result_free(r);
}

static const char shaders[] =
    "float4 vs(float4 p : POSITION) : POSITION { return p; }\n"
    "float4 red() : COLOR { return float4(1, 0, 0, 1); }\n"
    "float4 green() : COLOR { return float4(0, 1, 0, 1); }\n";

static void shader_variables_and_arrays(void) {
    char src[2048];
    snprintf(src, sizeof src,
             "%s"
             "VertexShader VS = compile vs_2_0 vs();\n"
             "PixelShader PS[2] = { compile ps_2_0 red(), compile ps_2_0 green() };\n"
             "technique T {\n"
             "    pass A { VertexShader = (VS); PixelShader = (PS[1]); }\n"
             "    pass B { VertexShader = <VS>; PixelShader = compile ps_2_0 green(); }\n"
             "    pass C { VertexShader = VS; PixelShader = (PS[0]); }\n"
             "    pass D { VertexShader = NULL; PixelShader = NULL; CullMode = None; }\n"
             "}\n",
             shaders);
    hfxc_result *r = compile(src);
    const hfx_fx_effect *fx = effect_of(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    CHECK_INT(param(fx, "VS")->type, HFX_TYPE_VERTEXSHADER);
    CHECK_INT(param(fx, "PS")->type, HFX_TYPE_PIXELSHADER);
    CHECK_INT(param(fx, "PS")->elements, 2);
    CHECK_INT(fx->pass_count, 4);
    /* A and B compile the same pair: one program; C another; D none. */
    CHECK_INT(fx->program_count, 2);
    CHECK_INT(fx->passes[0].program, 0);
    CHECK_INT(fx->passes[1].program, 0);
    CHECK_INT(fx->passes[2].program, 1);
    CHECK_INT(fx->passes[3].program, HFX_NONE);
    const hfx_fx_state *d = &fx->states[fx->passes[3].first_state];
    CHECK_INT(d[0].kind, HFX_FX_VALUE_PROGRAM);
    CHECK_INT(d[0].ref, HFX_NONE);
    CHECK_INT(d[2].i, 1);
done:
    hfxc_result_free(r);
}

static void check_error(const char *src, const char *expected) {
    hfxc_result *r = compile(src);
    CHECK(!hfxc_result_ok(r));
    CHECK(hfxc_result_effect(r) == NULL);
    char *text = hfxc_diagnostics_text(r);
    CHECK_CONTAINS(text, expected);
    free(text);
    hfxc_result_free(r);
}

static void located_errors(void) {
    check_error("technique T { pass P { CullModes = None; } }\n",
                "t.fx(1,24): error X3000: unrecognized state 'CullModes'");
    check_error("technique T { pass P {\n  CullMode = Sideways;\n} }\n",
                "t.fx(2,14): error X3004: undeclared identifier 'Sideways'");
    check_error("float4 c; sampler s = sampler_state { Texture = <c>; };\n",
                "t.fx(1,50): error X3017: Texture expects a texture, 'c' is float4");
    check_error("sampler s = sampler_state { CullMode = None; };\n",
                "t.fx(1,29): error X3000: 'CullMode' is not a sampler state");
    check_error("technique T { pass P { MinFilter[16] = Point; } }\n",
                "t.fx(1,34): error X3018: 'MinFilter': state index must be a constant from 0 to 15");
    /* 300 elements of 1 member of 300 elements: 90600 params, over the 65536 limit. */
    check_error("struct S { float a[300]; };\nS s[300];\n",
                "t.fx(2,3): error X3094: 's': parameter too large (90000 values, 90600 elements and members)");
    check_error("texture t;\ntechnique T { pass P { CullMode = <t>; } }\n",
                "t.fx(2,36): error X3017: CullMode cannot take 't', which is texture");
    char src[2048];
    snprintf(src, sizeof src,
             "%s"
             "PixelShader PS[2] = { compile ps_2_0 red(), compile ps_2_0 green() };\n"
             "int which, other;\n"
             "technique T { pass P { VertexShader = compile vs_2_0 vs(); PixelShader = (PS[which + other]); } }\n",
             shaders);
    /* PS[which] is chosen at Apply now (test_shader_arrays.c); two driving parameters are not */
    check_error(src, "t.fx(6,20): error X3094: shader arrays chosen by more than one int parameter are not supported");
}

/* An effect written for Direct3D 9 and 10 (issue 30): the D3D10 state objects, technique10 and
 * fxgroup are dropped with a warning each, D3D10's Filter becomes D3D9's three filter states
 * (D3DTEXF_POINT 1, LINEAR 2, ANISOTROPIC 3), an unknown sampler state is skipped, nested
 * braces in a pass hold more states, and the Direct3D 9 technique loads. */
static void d3d10_syntax_beside_d3d9(void) {
    hfxc_result *r = compile(
        "float4 c;\n"
        "RasterizerState rs { CullMode = None; FillMode = Solid; };\n"
        "BlendState bs { BlendEnable[0] = TRUE; SrcBlend = ONE; };\n"
        "DepthStencilState ds { DepthEnable = FALSE; };\n"
        "SamplerState lin { Filter = MIN_LINEAR_MAG_MIP_POINT; AddressU = Wrap; };\n"
        "sampler an = sampler_state { Filter = ANISOTROPIC; ComparisonFunc = LESS; };\n"
        "float4 ps() : COLOR0 { return c; }\n"
        "technique10 T10 { pass P { SetPixelShader(CompileShader(ps_4_0, ps())); SetRasterizerState(rs);\n"
        "  SetBlendState(bs, float4(0, 0, 0, 0), 0xFFFFFFFF); SetDepthStencilState(ds, 0); } }\n"
        "fxgroup G { technique11 T11 { pass P { SetPixelShader(CompileShader(ps_5_0, ps())); } } }\n"
        "technique T { pass P { PixelShader = compile ps_2_0 ps(); { CullMode = CW; } ZEnable = false; } }\n");
    const hfx_fx_effect *fx = effect_of(r);
    CHECK(fx != NULL);
    char *text = hfxc_diagnostics_text(r);
    CHECK_CONTAINS(text, "t.fx(2,17): warning X3094: 'rs': RasterizerState is Direct3D 10 effect syntax, ignored in fx_2_0");
    CHECK_CONTAINS(text, "t.fx(3,12): warning X3094: 'bs': BlendState is Direct3D 10 effect syntax, ignored in fx_2_0");
    CHECK_CONTAINS(text, "t.fx(4,19): warning X3094: 'ds': DepthStencilState is Direct3D 10 effect syntax, ignored in fx_2_0");
    CHECK_CONTAINS(text, "t.fx(6,52): warning X3000: unrecognized sampler state 'ComparisonFunc' ignored");
    CHECK_CONTAINS(text, "t.fx(8,13): warning X3094: 'T10': technique10 is Direct3D 10 effect syntax, ignored in fx_2_0");
    CHECK_CONTAINS(text, "t.fx(10,1): warning X3094: 'G': fxgroup is Direct3D 10 effect syntax, ignored in fx_2_0");
    free(text);
    if (!fx) goto done;
    CHECK_INT(fx->technique_count, 1);
    CHECK_STR(fx->techniques[0].name, "T");
    CHECK_INT(fx->sampler_count, 2);
    static const char *const filters[] = {"MinFilter", "MagFilter", "MipFilter"};
    static const int32_t lin[] = {2, 1, 1, 3}, an[] = {3, 3, 2}; /* lin's fourth: D3DTADDRESS_WRAP 1 */
    for (uint32_t k = 0; k < 3; k++) {
        const hfx_fx_state *a = &fx->states[fx->samplers[0].first_state + k], *b = &fx->states[fx->samplers[1].first_state + k];
        CHECK_INT(a->id, state_id(filters[k]));
        CHECK_INT(a->i, lin[k]);
        CHECK_INT(b->id, state_id(filters[k]));
        CHECK_INT(b->i, an[k]);
    }
    CHECK_INT(fx->samplers[0].state_count, 4);
    CHECK_INT(fx->states[fx->samplers[0].first_state + 3].i, 1);
    CHECK_INT(fx->samplers[1].state_count, 3);
    const hfx_fx_pass *p = &fx->passes[fx->techniques[0].first_pass];
    CHECK_INT(p->state_count, 3); /* PixelShader, CullMode (nested), ZEnable */
    CHECK_INT(fx->states[p->first_state + 1].id, state_id("CullMode"));
    CHECK_INT(fx->states[p->first_state + 1].i, 2); /* D3DCULL_CW */
    CHECK_INT(fx->states[p->first_state + 2].id, state_id("ZEnable"));
done:
    hfxc_result_free(r);
}

int main(void) {
    RUN(defaults_are_folded);
    RUN(intrinsics_and_d3d_rules_fold);
    RUN(indexed_states_bound_to_elements);
    RUN(returns_checked_per_pass);
    RUN(objects_and_strings);
    RUN(annotations_of_every_kind);
    RUN(pass_states_resolve);
    RUN(sampler_arrays);
    RUN(shader_variables_and_arrays);
    RUN(located_errors);
    RUN(d3d10_syntax_beside_d3d9);
    return test_summary();
}
