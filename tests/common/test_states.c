/* test_states.c: the D3D9 effect state table against d3d9types.h's numbers. */
#include "states.h"
#include "test.h"

static int32_t value(const char *state, const char *name) {
    const hfx_state_info *st = hfx_state_lookup(state);
    int32_t v = -12345;
    if (!st || hfx_state_value_lookup(st, name, &v) != 0) return -12345;
    return v;
}

static void test_lookup_is_case_insensitive(void) {
    const hfx_state_info *a = hfx_state_lookup("MipFilter");
    CHECK(a != NULL);
    CHECK(hfx_state_lookup("Mipfilter") == a);
    CHECK(hfx_state_lookup("MIPFILTER") == a);
    CHECK_STR(a->name, "MipFilter");
    CHECK_INT(a->scope, HFX_SS_SAMPLER);
    CHECK_INT(a->kind, HFX_SV_ENUM);
    CHECK(hfx_state_lookup("NoSuchState") == NULL);
    CHECK(hfx_state_lookup(NULL) == NULL);
    CHECK(hfx_state_lookup("") == NULL);
}

static void test_ids_are_stable_and_round_trip(void) {
    CHECK_INT(HFX_ST_ZENABLE, 1); /* first of D3DX's table; stored in .hfxo */
    CHECK(hfx_state_by_id(0) == NULL);
    CHECK(hfx_state_by_id(hfx_state_count() + 1) == NULL);
    for (uint32_t id = 1; id <= hfx_state_count(); id++) {
        const hfx_state_info *st = hfx_state_by_id(id);
        CHECK(st != NULL);
        if (!st) continue;
        CHECK_INT(st->id, id);
        CHECK(hfx_state_lookup(st->name) == st); /* names are unique */
    }
    CHECK_INT(hfx_state_lookup("CullMode")->id, HFX_ST_CULLMODE);
    CHECK_INT(hfx_state_lookup("blendopalpha")->id, HFX_ST_BLENDOPALPHA);
}

static void test_scopes_and_kinds(void) {
    CHECK_INT(hfx_state_lookup("AlphaBlendEnable")->kind, HFX_SV_BOOL);
    CHECK_INT(hfx_state_lookup("AlphaBlendEnable")->scope, HFX_SS_RENDER);
    CHECK_INT(hfx_state_lookup("ColorWriteEnable")->kind, HFX_SV_FLAGS);
    CHECK_INT(hfx_state_lookup("BlendFactor")->kind, HFX_SV_COLOR);
    CHECK_INT(hfx_state_lookup("DepthBias")->kind, HFX_SV_FLOAT);
    CHECK_INT(hfx_state_lookup("StencilRef")->kind, HFX_SV_INT);
    CHECK_INT(hfx_state_lookup("VertexShader")->scope, HFX_SS_SHADER);
    CHECK_INT(hfx_state_lookup("PixelShader")->kind, HFX_SV_SHADER);
    CHECK_INT(hfx_state_lookup("Texture")->scope, HFX_SS_TEXTURE);
    CHECK_INT(hfx_state_lookup("Texture")->max_index, 15);
    CHECK_INT(hfx_state_lookup("ColorOp")->scope, HFX_SS_STAGE);
    CHECK_INT(hfx_state_lookup("ColorOp")->max_index, 7);
    CHECK_INT(hfx_state_lookup("WorldTransform")->kind, HFX_SV_MATRIX);
    CHECK_INT(hfx_state_lookup("LightEnable")->scope, HFX_SS_FIXED);
    CHECK_INT(hfx_state_lookup("VertexShaderConstantF")->scope, HFX_SS_FIXED);
    CHECK_INT(hfx_state_lookup("CullMode")->max_index, 0);
    CHECK_INT(hfx_state_lookup("MaxMipLevel")->kind, HFX_SV_INT);
    CHECK_INT(hfx_state_lookup("SRGBTexture")->kind, HFX_SV_BOOL);
    CHECK(hfx_state_lookup("TwoSidedStencilMode") != NULL);
    CHECK(hfx_state_lookup("CCW_StencilFunc") != NULL);
    CHECK(hfx_state_lookup("SeparateAlphaBlendEnable") != NULL);
    CHECK(hfx_state_lookup("SlopeScaleDepthBias") != NULL);
    CHECK(hfx_state_lookup("Wrap15") != NULL);
    CHECK(hfx_state_lookup("PointSize_Max") != NULL);
}

static void test_d3d9_enum_values(void) {
    CHECK_INT(value("CullMode", "None"), 1);
    CHECK_INT(value("CullMode", "CW"), 2);
    CHECK_INT(value("CullMode", "ccw"), 3);
    CHECK_INT(value("ZFunc", "Never"), 1);
    CHECK_INT(value("ZFunc", "LessEqual"), 4);
    CHECK_INT(value("ZFunc", "Always"), 8);
    CHECK_INT(value("SrcBlend", "Zero"), 1);
    CHECK_INT(value("SrcBlend", "SrcAlpha"), 5);
    CHECK_INT(value("DestBlend", "InvSrcAlpha"), 6);
    CHECK_INT(value("DestBlend", "BothInvSrcAlpha"), 13);
    CHECK_INT(value("DestBlend", "InvBlendFactor"), 15);
    CHECK_INT(value("AddressU", "Wrap"), 1);
    CHECK_INT(value("AddressV", "CLAMP"), 3);
    CHECK_INT(value("AddressW", "MirrorOnce"), 5);
    CHECK_INT(value("MinFilter", "None"), 0);
    CHECK_INT(value("MagFilter", "ANISOTROPIC"), 3);
    CHECK_INT(value("MipFilter", "GaussianQuad"), 7);
    CHECK_INT(value("StencilPass", "IncrSat"), 4);
    CHECK_INT(value("CCW_StencilFail", "Decr"), 8);
    CHECK_INT(value("FillMode", "Wireframe"), 2);
    CHECK_INT(value("BlendOp", "RevSubtract"), 3);
    CHECK_INT(value("BlendOpAlpha", "Max"), 5);
    CHECK_INT(value("ColorWriteEnable", "Alpha"), 8);
    CHECK_INT(value("ColorWriteEnable3", "Blue"), 4);
    CHECK_INT(value("ColorWriteEnable", "All"), 15); /* MonoGame's names (MonoGame's Tests/Assets/Effects/ParserTest.fx) */
    CHECK_INT(value("ColorWriteEnable", "none"), 0);
    CHECK_INT(value("ZEnable", "UseW"), 2);
    CHECK_INT(value("ZEnable", "TRUE"), 1);
    CHECK_INT(value("ZWriteEnable", "false"), 0);
    CHECK_INT(value("ZWriteEnable", "True"), 1);
    CHECK_INT(value("ShadeMode", "Gouraud"), 2);
    CHECK_INT(value("LightType", "Directional"), 3);
    CHECK_INT(value("ColorOp", "SelectArg1"), 2);
    CHECK_INT(value("ColorArg1", "Texture"), 2);
}

static void test_d3d_prefixes(void) {
    CHECK_INT(value("SrcBlend", "D3DBLEND_SRCALPHA"), 5);
    CHECK_INT(value("CullMode", "D3DCULL_CCW"), 3);
    CHECK_INT(value("ZFunc", "d3dcmp_greaterequal"), 7);
    CHECK_INT(value("AddressU", "D3DTADDRESS_BORDER"), 4);
    CHECK_INT(value("MinFilter", "D3DTEXF_LINEAR"), 2);
    CHECK_INT(value("StencilFail", "D3DSTENCILOP_INVERT"), 6);
    CHECK_INT(value("ColorWriteEnable", "D3DCOLORWRITEENABLE_GREEN"), 2);
    CHECK_INT(value("Wrap0", "D3DWRAP_V"), 2);
    /* another table's prefix is not accepted */
    CHECK_INT(value("SrcBlend", "D3DCMP_LESS"), -12345);
    CHECK_INT(value("SrcBlend", "D3DBLEND_"), -12345);
    CHECK_INT(value("SrcBlend", "Less"), -12345);
    CHECK_INT(value("AlphaRef", "True"), -12345); /* INT states have no names */
}

static void test_value_names(void) {
    CHECK_STR(hfx_state_value_name(hfx_state_lookup("CullMode"), 3), "CCW");
    CHECK_STR(hfx_state_value_name(hfx_state_lookup("SrcBlend"), 6), "InvSrcAlpha");
    CHECK_STR(hfx_state_value_name(hfx_state_lookup("ZWriteEnable"), 1), "True");
    CHECK(hfx_state_value_name(hfx_state_lookup("CullMode"), 9) == NULL);
    CHECK(hfx_state_value_name(hfx_state_lookup("AlphaRef"), 1) == NULL);
    CHECK(hfx_state_value_name(NULL, 1) == NULL);
    int32_t v;
    CHECK(hfx_state_value_lookup(NULL, "None", &v) != 0);
    CHECK(hfx_state_value_lookup(hfx_state_lookup("CullMode"), NULL, &v) != 0);
}

int main(void) {
    RUN(test_lookup_is_case_insensitive);
    RUN(test_ids_are_stable_and_round_trip);
    RUN(test_scopes_and_kinds);
    RUN(test_d3d9_enum_values);
    RUN(test_d3d_prefixes);
    RUN(test_value_names);
    return test_summary();
}
