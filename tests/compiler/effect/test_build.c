/* The effect builder on the seed corpus: parameters (order, class, type, shape, semantics,
 * defaults, annotations), samplers, techniques, passes and their states. Expected values are
 * read off the seed sources by hand. */
#include <stdlib.h>
#include <string.h>

#include "effect.h"
#include "files.h"
#include "hfx/hfxc.h"
#include "states.h"
#include "test.h"

static hfxc_result *compile_seed(const char *name) {
    char *path = test_seed_path(name);
    hfxc_result *r = hfxc_compile_file(path, NULL);
    if (!hfxc_result_ok(r) || !hfxc_result_effect(r)) {
        char *text = hfxc_diagnostics_text(r);
        fprintf(stderr, "%s did not build:\n%s", name, text);
        free(text);
    }
    free(path);
    return r;
}

static const hfx_fx_param *param(const hfx_fx_effect *fx, const char *name) {
    uint32_t i = hfx_fx_param_find(fx, name);
    if (i == HFX_NONE) fprintf(stderr, "no parameter '%s'\n", name);
    return i == HFX_NONE ? NULL : &fx->params[i];
}

static float value_f(const hfx_fx_effect *fx, const hfx_fx_param *p, uint32_t k) {
    float f;
    memcpy(&f, &fx->values[p->offset + k], sizeof f);
    return f;
}

static const hfx_fx_annotation *annotation(const hfx_fx_effect *fx, const hfx_fx_param *p, const char *name) {
    for (uint32_t i = 0; i < p->annotation_count; i++)
        if (strcmp(fx->annotations[p->first_annotation + i].name, name) == 0)
            return &fx->annotations[p->first_annotation + i];
    fprintf(stderr, "no annotation '%s' on '%s'\n", name, p->name);
    return NULL;
}

static float annotation_f(const hfx_fx_annotation *a) {
    float f = -999;
    if (a && a->count) memcpy(&f, &a->data[0], sizeof f);
    return f;
}

static uint32_t state_id(const char *name) {
    const hfx_state_info *info = hfx_state_lookup(name);
    return info ? info->id : 0xdeadu;
}

static void all_good_seeds_build(void) {
    static const char *const good[] = {"tutorial0.fx", "phong.fx", "pointlights.fx", "ambient.fx",
                                       "ambient_textured.fx", "directional.fx", "point.fx", "spot.fx",
                                       "directional_specular.fx", "point_specular.fx", "spot_specular.fx",
                                       "multilights_repaired.fx", "fxcomposer_empty.fx"};
    for (size_t i = 0; i < sizeof good / sizeof *good; i++) {
        hfxc_result *r = compile_seed(good[i]);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        CHECK(fx != NULL);
        if (fx) {
            CHECK(fx->technique_count >= 1);
            for (uint32_t p = 0; p < fx->pass_count; p++) CHECK(fx->passes[p].program != HFX_NONE);
            /* The layout rules of effect.h: values tile the buffer, children follow parents. */
            uint32_t words = 0;
            for (uint32_t p = 0; p < fx->top_param_count; p++) {
                CHECK_INT(fx->params[p].offset, words);
                CHECK_INT(fx->params[p].parent, HFX_NONE);
                words += fx->params[p].words;
            }
            CHECK_INT(fx->value_words, words);
            for (uint32_t p = fx->top_param_count; p < fx->param_count; p++) CHECK(fx->params[p].parent < p);
        }
        hfxc_result_free(r);
    }
}

static void ambient_params(void) {
    hfxc_result *r = compile_seed("ambient.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    CHECK_INT(fx->top_param_count, 4);
    CHECK_INT(fx->param_count, 4);
    CHECK_STR(fx->params[0].name, "world");
    CHECK_STR(fx->params[1].name, "view");
    CHECK_STR(fx->params[2].name, "projection");
    CHECK_STR(fx->params[3].name, "colorMaterialAmbiental");
    const hfx_fx_param *w = &fx->params[0];
    CHECK_INT(w->klass, HFX_CLASS_MATRIX);
    CHECK_INT(w->type, HFX_TYPE_FLOAT);
    CHECK_INT(w->rows, 4);
    CHECK_INT(w->cols, 4);
    CHECK_INT(w->elements, 0);
    CHECK_INT(w->words, 16);
    CHECK_STR(w->semantic, "World");
    CHECK_STR(w->glsl_name, "world");
    CHECK_STR(fx->params[2].semantic, "Projection");
    const hfx_fx_param *c = &fx->params[3];
    CHECK_INT(c->klass, HFX_CLASS_VECTOR);
    CHECK_INT(c->type, HFX_TYPE_FLOAT);
    CHECK_INT(c->rows, 1);
    CHECK_INT(c->cols, 4);
    CHECK(c->semantic == NULL);
    CHECK_INT(c->offset, 48);
    CHECK_NEAR(value_f(fx, c, 0), 0.05, 1e-7);
    CHECK_NEAR(value_f(fx, c, 1), 0.05, 1e-7);
    CHECK_NEAR(value_f(fx, c, 2), 0.05, 1e-7);
    CHECK_NEAR(value_f(fx, c, 3), 1.0, 0);
    CHECK_INT(c->annotation_count, 2);
    const hfx_fx_annotation *a = annotation(fx, c, "UIName");
    CHECK(a && a->type == HFX_TYPE_STRING && a->klass == HFX_CLASS_OBJECT);
    if (a) CHECK_STR(a->string, "Color Ambiental");
    a = annotation(fx, c, "UIWidget");
    if (a) CHECK_STR(a->string, "Color");
    /* No initializer: zero. */
    for (uint32_t k = 0; k < 16; k++) CHECK_INT(fx->values[k], 0);
    CHECK_INT(fx->technique_count, 1);
    CHECK_STR(fx->techniques[0].name, "ModeloAmbiental");
    CHECK_INT(fx->techniques[0].pass_count, 1);
    CHECK_STR(fx->passes[0].name, "p0");
    CHECK_INT(fx->passes[0].state_count, 2);
    CHECK_INT(fx->program_count, 1);
    for (uint32_t s = 0; s < 2; s++) {
        const hfx_fx_state *st = &fx->states[fx->passes[0].first_state + s];
        CHECK_INT(st->kind, HFX_FX_VALUE_PROGRAM);
        CHECK_INT(st->ref, 0);
        CHECK_INT(st->id, state_id(s == 0 ? "VertexShader" : "PixelShader"));
    }
    CHECK_INT(fx->states[0].line, 32);
    CHECK_INT(fx->states[0].col, 9);
done:
    hfxc_result_free(r);
}

static void spot_specular_sliders(void) {
    hfxc_result *r = compile_seed("spot_specular.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    /* world view projection anguloInterno blancoLuz falloff anguloExterno posicionLuz
     * colorMaterialAmbiental colorMaterialDifuso c1 c2 c3 rango texturaModelo
     * modeloTexturaMuestra atenuado ks n colorMaterialEspecular posicionCamara modIluEsp */
    CHECK_INT(fx->top_param_count, 22);
    CHECK_STR(fx->params[10].name, "c1");
    CHECK_STR(fx->params[12].name, "c3");
    const hfx_fx_param *ks = param(fx, "ks");
    CHECK(ks != NULL);
    if (!ks) goto done;
    CHECK_INT(ks - fx->params, 17);
    CHECK_INT(ks->klass, HFX_CLASS_SCALAR);
    CHECK_INT(ks->rows, 1);
    CHECK_INT(ks->cols, 1);
    CHECK_NEAR(value_f(fx, ks, 0), 0.05, 1e-7); /* `= {0.05F}` on a scalar */
    CHECK_INT(ks->annotation_count, 5);
    const hfx_fx_annotation *a = annotation(fx, ks, "UIWidget");
    if (a) CHECK_STR(a->string, "slider");
    a = annotation(fx, ks, "UIMin");
    CHECK(a && a->type == HFX_TYPE_FLOAT && a->klass == HFX_CLASS_SCALAR && a->count == 1);
    CHECK_NEAR(annotation_f(a), 0.0, 0);
    CHECK_NEAR(annotation_f(annotation(fx, ks, "UIMax")), 10.0, 0);
    CHECK_NEAR(annotation_f(annotation(fx, ks, "UIStep")), 0.05, 1e-7);
    /* The annotation order is the source order. */
    CHECK_STR(fx->annotations[ks->first_annotation].name, "UIWidget");
    CHECK_STR(fx->annotations[ks->first_annotation + 4].name, "UIName");
    const hfx_fx_param *n = param(fx, "n");
    if (n) CHECK_NEAR(value_f(fx, n, 0), 5.0, 0);
    const hfx_fx_param *at = param(fx, "atenuado");
    if (at) {
        CHECK_INT(at->type, HFX_TYPE_BOOL);
        CHECK_INT(fx->values[at->offset], 0);
    }
    const hfx_fx_param *tex = param(fx, "texturaModelo");
    if (tex) {
        CHECK_INT(tex->klass, HFX_CLASS_OBJECT);
        CHECK_INT(tex->type, HFX_TYPE_TEXTURE2D);
        CHECK_INT(tex->words, 0);
        CHECK(tex->glsl_name == NULL);
    }
    const hfx_fx_param *smp = param(fx, "modeloTexturaMuestra");
    if (smp && tex) {
        CHECK_INT(smp->type, HFX_TYPE_SAMPLER);
        CHECK(smp->sampler != HFX_NONE);
        if (smp->sampler != HFX_NONE) {
            const hfx_fx_sampler *s = &fx->samplers[smp->sampler];
            CHECK_INT(s->texture_param, tex - fx->params);
            CHECK_INT(s->state_count, 5);
            CHECK_INT(fx->states[s->first_state].id, state_id("MinFilter"));
            CHECK_INT(fx->states[s->first_state + 3].id, state_id("AddressU"));
            CHECK_INT(fx->states[s->first_state + 3].i, 1); /* Wrap = D3DTADDRESS_WRAP = 1 */
        }
    }
    CHECK_INT(fx->technique_count, 2);
    CHECK_STR(fx->techniques[0].name, "Texturizado");
    CHECK_STR(fx->techniques[1].name, "Material");
    CHECK_STR(fx->passes[1].name, "P0");
    /* MainPS(true) and MainPS(false) are different programs. */
    CHECK_INT(fx->program_count, 2);
done:
    hfxc_result_free(r);
}

static void pointlights_arrays(void) {
    hfxc_result *r = compile_seed("pointlights.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    const hfx_fx_param *lp = param(fx, "LightPosition");
    if (!lp) goto done;
    CHECK_INT(lp->klass, HFX_CLASS_VECTOR);
    CHECK_INT(lp->cols, 3);
    CHECK_INT(lp->elements, 50);
    CHECK_INT(lp->child_count, 50);
    CHECK_INT(lp->words, 150);
    const hfx_fx_param *e7 = &fx->params[lp->first_child + 7];
    CHECK_INT(e7->parent, lp - fx->params);
    CHECK_INT(e7->elements, 0);
    CHECK_INT(e7->cols, 3);
    CHECK_INT(e7->offset, lp->offset + 21);
    const hfx_fx_param *lc = param(fx, "LightColor");
    if (lc) CHECK_INT(lc->offset, lp->offset + 150);
    const hfx_fx_param *al = param(fx, "activeLights");
    if (al) {
        CHECK_INT(al->type, HFX_TYPE_INT);
        CHECK_INT(al->klass, HFX_CLASS_SCALAR);
    }
    const hfx_fx_param *ds = param(fx, "DiffuseSampler");
    if (ds && ds->sampler != HFX_NONE) {
        CHECK_INT(ds->type, HFX_TYPE_SAMPLER2D);
        const hfx_fx_sampler *s = &fx->samplers[ds->sampler];
        CHECK_INT(s->state_count, 5);
        CHECK_INT(fx->states[s->first_state + 2].id, state_id("MagFilter"));
        CHECK_INT(fx->states[s->first_state + 2].i, 3); /* ANISOTROPIC = D3DTEXF_ANISOTROPIC = 3 */
        CHECK_INT(s->texture_param, hfx_fx_param_find(fx, "DiffuseTexture"));
    }
done:
    hfxc_result_free(r);
}

static void multilights_structs(void) {
    hfxc_result *r = compile_seed("multilights_repaired.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    const hfx_fx_param *spots = param(fx, "spots");
    if (!spots) goto done;
    CHECK_INT(spots->klass, HFX_CLASS_STRUCT);
    CHECK_INT(spots->elements, 2);
    CHECK_INT(spots->child_count, 2);
    /* LuzSpot: 3 + 3 + 4 + 7 floats + 2 ints = 19 words, twice. */
    CHECK_INT(spots->words, 38);
    const hfx_fx_param *e1 = &fx->params[spots->first_child + 1];
    CHECK_INT(e1->klass, HFX_CLASS_STRUCT);
    CHECK_INT(e1->offset, spots->offset + 19);
    static const char *const members[] = {"Posicion", "Blanco", "Color", "AnguloInterno", "AnguloExterno", "Falloff",
                                          "Rango", "C1", "C2", "C3", "Atenuar", "Encender"};
    CHECK_INT(e1->child_count, 12);
    for (uint32_t m = 0; m < 12 && m < e1->child_count; m++) {
        const hfx_fx_param *mp = &fx->params[e1->first_child + m];
        CHECK_STR(mp->name, members[m]);
        CHECK_STR(mp->glsl_name, members[m]);
        CHECK_INT(mp->parent, e1 - fx->params);
    }
    const hfx_fx_param *encender = &fx->params[e1->first_child + 11];
    CHECK_INT(encender->type, HFX_TYPE_INT);
    CHECK_INT(encender->offset, spots->offset + 19 + 18);
    const hfx_fx_param *color = &fx->params[e1->first_child + 2];
    CHECK_INT(color->klass, HFX_CLASS_VECTOR);
    CHECK_INT(color->cols, 4);
    CHECK_INT(color->offset, spots->offset + 19 + 6);
    const hfx_fx_param *num = param(fx, "numLuces");
    if (num) CHECK_INT((int32_t)fx->values[num->offset], 4);
    CHECK_INT(fx->technique_count, 2);
    CHECK_INT(fx->pass_count, 4);
    CHECK_STR(fx->passes[0].name, "Ambiental");
    CHECK_STR(fx->passes[3].name, "MultiLuces");
    CHECK_INT(fx->techniques[1].first_pass, 2);
    CHECK_INT(fx->program_count, 4); /* two pixel shaders, each with true and false */
done:
    hfxc_result_free(r);
}

static void tutorial0_sampler(void) {
    hfxc_result *r = compile_seed("tutorial0.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    CHECK_INT(fx->sampler_count, 1);
    const hfx_fx_sampler *s = &fx->samplers[0];
    CHECK_INT(s->param, hfx_fx_param_find(fx, "diffuseSampler"));
    CHECK_INT(s->texture_param, hfx_fx_param_find(fx, "diffuseTexture")); /* Texture = (diffuseTexture) */
    CHECK_INT(s->dim, HFX_FX_DIM_2D);
    CHECK_INT(s->state_count, 5);
    static const char *const names[] = {"AddressU", "AddressV", "MagFilter", "MinFilter", "MipFilter"};
    static const int32_t values[] = {3, 3, 2, 2, 2}; /* CLAMP = 3, LINEAR = 2 */
    for (uint32_t i = 0; i < 5 && i < s->state_count; i++) {
        const hfx_fx_state *st = &fx->states[s->first_state + i];
        CHECK_INT(st->id, state_id(names[i]));
        CHECK_INT(st->kind, HFX_FX_VALUE_INT);
        CHECK_INT(st->i, values[i]);
        CHECK_INT(st->line, 9 + i);
    }
    CHECK_STR(fx->techniques[0].name, "Tut0");
    CHECK_STR(fx->passes[0].name, "Pass1");
done:
    hfxc_result_free(r);
}

static void fxcomposer_cull_none(void) {
    hfxc_result *r = compile_seed("fxcomposer_empty.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    CHECK_STR(fx->params[0].semantic, "WorldViewProjection");
    CHECK_STR(fx->techniques[0].name, "technique0");
    const hfx_fx_pass *p = &fx->passes[0];
    CHECK_INT(p->state_count, 3);
    const hfx_fx_state *cull = &fx->states[p->first_state];
    CHECK_INT(cull->id, state_id("CullMode"));
    CHECK_INT(cull->kind, HFX_FX_VALUE_INT);
    CHECK_INT(cull->i, 1); /* D3DCULL_NONE */
    CHECK_INT(cull->line, 24);
done:
    hfxc_result_free(r);
}

static void point_bool_and_multi_declarators(void) {
    hfxc_result *r = compile_seed("point.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    uint32_t c1 = hfx_fx_param_find(fx, "c1"), c2 = hfx_fx_param_find(fx, "c2"), c3 = hfx_fx_param_find(fx, "c3");
    CHECK(c1 != HFX_NONE && c2 == c1 + 1 && c3 == c1 + 2);
done:
    hfxc_result_free(r);
}

static void multilights_is_refused(void) {
    char *path = test_seed_path("multilights.fx");
    hfxc_result *r = hfxc_compile_file(path, NULL);
    CHECK(!hfxc_result_ok(r));
    CHECK(hfxc_result_effect(r) == NULL);
    char *text = hfxc_diagnostics_text(r);
    CHECK_CONTAINS(text, "multilights.fx(204,20): error X3013: 'Phong': no matching 4 parameter function");
    free(text);
    hfxc_result_free(r);
    free(path);
}

static void ambient_textured_programs(void) {
    hfxc_result *r = compile_seed("ambient_textured.fx");
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx) goto done;
    CHECK_INT(fx->technique_count, 2);
    CHECK_INT(fx->program_count, 2);
    CHECK_INT(fx->passes[0].program, 0);
    CHECK_INT(fx->passes[1].program, 1);
    const hfx_fx_param *t = param(fx, "texturaModelo");
    if (t) CHECK_INT(t->annotation_count, 1);
done:
    hfxc_result_free(r);
}

/* Every seed's effect survives .hfxo: the bytes written from the read copy are the same. */
static void seeds_round_trip_through_hfxo(void) {
    static const char *const seeds[] = {"ambient.fx", "pointlights.fx", "multilights_repaired.fx", "tutorial0.fx"};
    for (size_t i = 0; i < sizeof seeds / sizeof *seeds; i++) {
        hfxc_result *r = compile_seed(seeds[i]);
        const hfx_fx_effect *fx = hfxc_result_effect(r);
        CHECK(fx != NULL);
        void *a = NULL, *b = NULL;
        size_t na = 0, nb = 0;
        CHECK(fx && hfx_fx_write_hfxo(fx, &a, &na) == 0);
        char err[256];
        hfx_fx_effect *back = a ? hfx_fx_read_hfxo(a, na, err, sizeof err) : NULL;
        CHECK(back != NULL);
        if (back) {
            CHECK_INT(back->param_count, fx->param_count);
            CHECK_INT(back->program_count, fx->program_count);
            CHECK_STR(back->programs[0].code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data,
                      fx->programs[0].code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data);
            CHECK(hfx_fx_write_hfxo(back, &b, &nb) == 0);
            CHECK(na == nb && memcmp(a, b, na) == 0);
        }
        hfx_fx_effect_free(back);
        free(a);
        free(b);
        hfxc_result_free(r);
    }
}

/* A pass that names no vertex (pixel) shader keeps the previous pass's, as a D3D9 device holds
 * it between passes; `= NULL` sets none (the fixed-function stand-in); a new technique starts
 * with none. */
static void passes_keep_the_previous_shaders(void) {
    static const char src[] =
        "float4x4 W;\n"
        "float4 vs(float4 p : POSITION) : POSITION { return mul(p, W); }\n"
        "float4 red() : COLOR { return float4(1, 0, 0, 1); }\n"
        "float4 green() : COLOR { return float4(0, 1, 0, 1); }\n"
        "technique t {\n"
        "  pass p0 { VertexShader = compile vs_2_0 vs(); PixelShader = compile ps_2_0 red(); }\n"
        "  pass p1 { PixelShader = compile ps_2_0 green(); }\n"
        "  pass p2 { AlphaBlendEnable = true; }\n"
        "  pass p3 { VertexShader = NULL; }\n"
        "}\n"
        "technique u { pass q0 { PixelShader = compile ps_2_0 red(); } }\n";
    hfxc_result *r = hfxc_compile_memory(src, strlen(src), "held.fx", NULL);
    const hfx_fx_effect *fx = hfxc_result_effect(r);
    CHECK(fx != NULL);
    if (!fx || fx->pass_count != 5) goto done;
    const char *code[5][2];
    for (int p = 0; p < 5; p++) {
        uint32_t prog = fx->passes[p].program;
        CHECK(prog != HFX_NONE);
        if (prog == HFX_NONE) goto done;
        for (int s = 0; s < 2; s++) code[p][s] = (const char *)fx->programs[prog].code[s][HFX_TARGET_GLSL330].data;
    }
    CHECK_CONTAINS(code[1][HFX_STAGE_VERTEX], "vertex shader generated by hfx from vs"); /* p0's */
    CHECK_STR(code[1][HFX_STAGE_VERTEX], code[0][HFX_STAGE_VERTEX]);
    CHECK_CONTAINS(code[1][HFX_STAGE_FRAGMENT], "from green");
    CHECK_INT(fx->passes[2].program, fx->passes[1].program); /* both shaders held */
    CHECK(strstr(code[3][HFX_STAGE_VERTEX], "from vs") == NULL); /* NULL: the stand-in */
    CHECK_CONTAINS(code[3][HFX_STAGE_FRAGMENT], "from green");
    CHECK(strstr(code[4][HFX_STAGE_VERTEX], "from vs") == NULL); /* technique u holds nothing of t */
done:
    hfxc_result_free(r);
}

int main(void) {
    test_require_seeds();
    RUN(all_good_seeds_build);
    RUN(ambient_params);
    RUN(spot_specular_sliders);
    RUN(pointlights_arrays);
    RUN(multilights_structs);
    RUN(tutorial0_sampler);
    RUN(fxcomposer_cull_none);
    RUN(point_bool_and_multi_declarators);
    RUN(multilights_is_refused);
    RUN(ambient_textured_programs);
    RUN(seeds_round_trip_through_hfxo);
    RUN(passes_keep_the_previous_shaders);
    return test_summary();
}
