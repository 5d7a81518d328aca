/* The parser over the seed corpus: every file parses without a diagnostic, and the trees
 * hold what seed-fx/README.md and the files themselves say (values read off the sources). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "files.h"
#include "hfx/hfxc.h"
#include "parse_util.h"
#include "test.h"

static const char *const seeds[] = {
    "ambient.fx", "ambient_textured.fx", "directional.fx", "directional_specular.fx",
    "fxcomposer_empty.fx", "multilights.fx", "multilights_repaired.fx", "phong.fx", "point.fx",
    "point_specular.fx", "pointlights.fx", "spot.fx", "spot_specular.fx", "tutorial0.fx",
};

static tp_result *parse_seed(const char *file) {
    char *path = test_seed_path(file);
    tp_result *r = tp_run(path, NULL);
    free(path);
    return r;
}

static void all_seeds_parse_without_diagnostics(void) {
    for (size_t i = 0; i < sizeof seeds / sizeof *seeds; i++) {
        char *path = test_seed_path(seeds[i]);
        hfxc_options opt = {0};
        opt.flags = HFXC_PARSE_ONLY;
        hfxc_result *res = hfxc_compile_file(path, &opt);
        char *text = hfxc_diagnostics_text(res);
        if (hfxc_diag_count(res) != 0) fprintf(stderr, "%s:\n%s", seeds[i], text);
        CHECK_INT(hfxc_diag_count(res), 0);
        CHECK(hfxc_result_ok(res));
        char *dump = hfxc_result_ast_dump(res);
        CHECK(dump && strstr(dump, "technique "));
        free(dump);
        free(text);
        hfxc_result_free(res);
        free(path);
    }
}

/* The number of globals of each kind a file declares, counted by hand from the listing. */
static void seed_global_counts(void) {
    tp_result *r = parse_seed("tutorial0.fx");
    /* World View Projection diffuseTexture diffuseSampler, 2 structs, 2 functions, Tut0 */
    CHECK_INT(r->ast->decl_count, 10);
    tp_free(r);
    r = parse_seed("fxcomposer_empty.fx");
    CHECK_INT(r->ast->decl_count, 4); /* WorldViewProj, mainVS, mainPS, technique0 */
    tp_free(r);
    r = parse_seed("ambient.fx");
    CHECK_INT(r->ast->decl_count, 7); /* world view projection colorMaterialAmbiental mainVS mainPS technique */
    tp_free(r);
}

static void ambient_textured_techniques(void) {
    tp_result *r = parse_seed("ambient_textured.fx");
    const char *names[2] = {"Texturizado", "Material"};
    for (int i = 0; i < 2; i++) {
        hfx_decl *t = tp_find(r, names[i]);
        CHECK(t && t->kind == DECL_TECHNIQUE);
        if (!t || t->kind != DECL_TECHNIQUE) continue;
        CHECK_STR(t->technique->keyword, "technique");
        CHECK_INT(t->technique->pass_count, 1);
        hfx_pass_ast *p = &t->technique->passes[0];
        CHECK_STR(p->name, "p0");
        CHECK_INT(p->state_count, 2);
        hfx_state_assign *vs = tp_state(p->states, p->state_count, "VertexShader");
        hfx_state_assign *ps = tp_state(p->states, p->state_count, "PixelShader");
        CHECK(vs && vs->value->kind == EX_COMPILE);
        CHECK(ps && ps->value->kind == EX_COMPILE);
        if (!vs || !ps) continue;
        CHECK_STR(vs->value->profile, "vs_3_0");
        CHECK_STR(vs->value->name, "mainVS");
        CHECK_INT(vs->value->arg_count, 0);
        CHECK_STR(ps->value->profile, "ps_3_0");
        CHECK_STR(ps->value->name, "mainPS");
        CHECK_INT(ps->value->arg_count, 1);
        CHECK_INT(ps->value->args[0]->kind, EX_BOOL);
        CHECK_INT(ps->value->args[0]->ival, i == 0); /* mainPS(true) in Texturizado, (false) in Material */
    }
    CHECK_CONTAINS(r->dump, "technique Texturizado\n  pass p0\n    state VertexShader = compile vs_3_0 mainVS()\n"
                            "    state PixelShader = compile ps_3_0 mainPS(true)\n");
    tp_free(r);
}

static void ambient_annotations_and_initializer(void) {
    tp_result *r = parse_seed("ambient.fx");
    hfx_decl *c = tp_find(r, "colorMaterialAmbiental");
    CHECK(c && c->kind == DECL_VAR);
    if (!c) { tp_free(r); return; }
    CHECK(c->is_global);
    CHECK_INT(c->type->kind, TY_VECTOR);
    CHECK_INT(c->type->cols, 4);
    CHECK_INT(c->annotation_count, 2);
    if (c->annotation_count == 2) {
        CHECK_STR(c->annotations[0].name, "UIName");
        CHECK_INT(c->annotations[0].type->kind, TY_STRING);
        CHECK_STR(c->annotations[0].value->sval, "Color Ambiental");
        CHECK_STR(c->annotations[1].name, "UIWidget");
        CHECK_STR(c->annotations[1].value->sval, "Color");
    }
    CHECK(c->init && c->init->kind == EX_INIT_LIST);
    if (c->init && c->init->arg_count == 4) {
        const double want[4] = {0.05, 0.05, 0.05, 1.0};
        for (int i = 0; i < 4; i++) {
            CHECK_INT(c->init->args[i]->kind, EX_FLOAT);
            CHECK_NEAR(c->init->args[i]->fval, want[i], 1e-12);
        }
    }
    hfx_decl *w = tp_find(r, "world");
    CHECK(w && w->semantic && strcmp(w->semantic, "World") == 0);
    CHECK(w && w->type->kind == TY_MATRIX && w->type->rows == 4 && w->type->cols == 4);
    /* float4 mainVS(float3 posicion : POSITION) : POSITION */
    hfx_decl *vs = tp_find(r, "mainVS");
    CHECK(vs && vs->kind == DECL_FUNC);
    if (vs && vs->kind == DECL_FUNC) {
        CHECK_STR(vs->func->ret_semantic, "POSITION");
        CHECK_INT(vs->func->param_count, 1);
        CHECK_STR(vs->func->params[0]->name, "posicion");
        CHECK_STR(vs->func->params[0]->semantic, "POSITION");
        CHECK_INT(vs->loc.line, 17);
        CHECK_INT(vs->loc.col, 8);
    }
    tp_free(r);
}

static void tutorial0_sampler_state(void) {
    tp_result *r = parse_seed("tutorial0.fx");
    hfx_decl *s = tp_find(r, "diffuseSampler");
    CHECK(s && s->init && s->init->kind == EX_SAMPLER_STATE);
    if (!s || !s->init || s->init->kind != EX_SAMPLER_STATE) { tp_free(r); return; }
    CHECK_INT(s->type->kind, TY_SAMPLER);
    CHECK_INT(s->type->dim, DIM_GENERIC);
    CHECK_INT(s->init->state_count, 6);
    hfx_state_assign *st = s->init->states;
    CHECK_STR(st[0].name, "Texture");
    CHECK_INT(st[0].value->kind, EX_IDENT);
    CHECK_STR(st[0].value->name, "diffuseTexture");
    CHECK(st[0].value->parenthesized);
    CHECK_INT(st[0].loc.line, 8);
    CHECK_INT(st[0].loc.col, 5);
    hfx_state_assign *au = tp_state(st, 6, "AddressU");
    CHECK(au && au->value->kind == EX_IDENT && strcmp(au->value->name, "CLAMP") == 0 && !au->value->parenthesized);
    hfx_state_assign *mip = tp_state(st, 6, "Mipfilter");
    CHECK(mip && mip->value->kind == EX_IDENT && strcmp(mip->value->name, "LINEAR") == 0);
    CHECK_CONTAINS(r->dump, "var sampler diffuseSampler = sampler_state { Texture = (diffuseTexture); "
                            "AddressU = CLAMP; AddressV = CLAMP; MagFilter = LINEAR; MinFilter = LINEAR; "
                            "Mipfilter = LINEAR; }\n");
    tp_free(r);
}

static void pointlights_arrays(void) {
    tp_result *r = parse_seed("pointlights.fx");
    const char *names[3] = {"LightPosition", "LightColor", "LightRadius"};
    const int cols[3] = {3, 4, 1};
    for (int i = 0; i < 3; i++) {
        hfx_decl *d = tp_find(r, names[i]);
        CHECK(d && d->type->kind == TY_ARRAY);
        if (!d || d->type->kind != TY_ARRAY) continue;
        CHECK_INT(d->type->array_len, 50); /* #define MaxLights 50 */
        CHECK(d->type->array_len_expr == NULL);
        CHECK_INT(d->type->elem->cols, cols[i]);
        CHECK_INT(d->type->elem->base, B_FLOAT);
    }
    hfx_decl *s = tp_find(r, "DiffuseSampler");
    CHECK(s && s->type->kind == TY_SAMPLER && s->type->dim == DIM_2D);
    if (s && s->init && s->init->kind == EX_SAMPLER_STATE) {
        CHECK_INT(s->init->states[0].value->kind, EX_STATE_REF);
        CHECK_STR(s->init->states[0].value->name, "DiffuseTexture");
        CHECK_STR(s->init->states[1].name, "ADDRESSU");
    }
    hfx_decl *a = tp_find(r, "activeLights");
    CHECK(a && a->type->kind == TY_SCALAR && a->type->base == B_INT);
    tp_free(r);
}

static void point_multi_declarator(void) {
    tp_result *r = parse_seed("point.fx");
    const char *names[3] = {"c1", "c2", "c3"};
    for (int i = 0; i < 3; i++) {
        hfx_decl *d = tp_find(r, names[i]);
        CHECK(d && d->kind == DECL_VAR && d->type->kind == TY_SCALAR && d->type->base == B_FLOAT);
        if (!d) continue;
        CHECK_INT(d->loc.line, 32); /* float c1, c2, c3; */
        CHECK_INT(d->loc.col, 7 + 4 * i);
        CHECK(tp_find_nth(r, names[i], 1) == NULL);
    }
    /* three separate decls, adjacent in source order */
    uint32_t at = 0;
    while (at < r->ast->decl_count && r->ast->decls[at] != tp_find(r, "c1")) at++;
    CHECK(at + 2 < r->ast->decl_count && r->ast->decls[at + 1] == tp_find(r, "c2") &&
          r->ast->decls[at + 2] == tp_find(r, "c3"));
    tp_free(r);
}

static void fxcomposer_render_state(void) {
    tp_result *r = parse_seed("fxcomposer_empty.fx");
    hfx_decl *t = tp_find(r, "technique0");
    CHECK(t && t->kind == DECL_TECHNIQUE && t->technique->pass_count == 1);
    if (t && t->kind == DECL_TECHNIQUE && t->technique->pass_count == 1) {
        hfx_pass_ast *p = &t->technique->passes[0];
        CHECK_STR(p->name, "p0");
        CHECK_INT(p->state_count, 3);
        CHECK_STR(p->states[0].name, "CullMode");
        CHECK_INT(p->states[0].value->kind, EX_IDENT);
        CHECK_STR(p->states[0].value->name, "None");
        CHECK_INT(p->states[0].loc.line, 24);
        CHECK_INT(p->states[0].loc.col, 9);
    }
    hfx_decl *w = tp_find(r, "WorldViewProj");
    CHECK(w && w->semantic && strcmp(w->semantic, "WorldViewProjection") == 0);
    CHECK_STR(r->dump,
              "var float4x4 WorldViewProj : WorldViewProjection\n"
              "function float4 mainVS : POSITION\n"
              "  param float3 pos : POSITION\n"
              "  block\n"
              "    return mul(float4(pos.xyz, 1.0), WorldViewProj)\n"
              "function float4 mainPS : COLOR\n"
              "  block\n"
              "    return float4(1.0, 1.0, 1.0, 1.0)\n"
              "technique technique0\n"
              "  pass p0\n"
              "    state CullMode = None\n"
              "    state VertexShader = compile vs_3_0 mainVS()\n"
              "    state PixelShader = compile ps_3_0 mainPS()\n");
    tp_free(r);
}

static void multilights_structs_and_call_location(void) {
    tp_result *r = parse_seed("multilights_repaired.fx");
    hfx_decl *s = tp_find(r, "LuzSpot");
    CHECK(s && s->kind == DECL_STRUCT);
    if (!s || s->kind != DECL_STRUCT) { tp_free(r); return; }
    const hfx_struct *st = s->type->st;
    static const char *const fields[] = {"Posicion", "Blanco", "Color", "AnguloInterno", "AnguloExterno",
                                         "Falloff", "Rango", "C1", "C2", "C3", "Atenuar", "Encender"};
    CHECK_INT(st->field_count, 12);
    for (uint32_t i = 0; i < st->field_count && i < 12; i++) CHECK_STR(st->fields[i].name, fields[i]);
    CHECK_INT(st->fields[1].type->cols, 3);      /* float3 Blanco */
    CHECK_INT(st->fields[2].type->cols, 4);      /* float4 Color */
    CHECK_INT(st->fields[11].type->base, B_INT); /* int Encender */
    hfx_decl *spots = tp_find(r, "spots");
    CHECK(spots && spots->type->kind == TY_ARRAY && spots->type->array_len == 2);
    CHECK(spots && spots->type->elem->kind == TY_STRUCT && spots->type->elem->st == st);
    hfx_decl *ml = tp_find(r, "MultiLuces");
    CHECK(ml == NULL); /* a pass name, not a global */
    hfx_decl *tex = tp_find(r, "Texturizado");
    CHECK(tex && tex->kind == DECL_TECHNIQUE && tex->technique->pass_count == 2);
    if (tex && tex->kind == DECL_TECHNIQUE && tex->technique->pass_count == 2) {
        CHECK_STR(tex->technique->passes[0].name, "Ambiental");
        CHECK_STR(tex->technique->passes[1].name, "MultiLuces");
    }
    tp_free(r);

    /* multilights.fx line 204: `float4 color = Phong(` with the call at column 20 */
    r = parse_seed("multilights.fx");
    hfx_decl *f = tp_find(r, "FuentePuntual");
    CHECK(f && f->kind == DECL_FUNC && f->func->body);
    if (f && f->kind == DECL_FUNC && f->func->body && f->func->body->body_count) {
        hfx_stmt *decl = f->func->body->body[0];
        CHECK_INT(decl->kind, ST_DECL);
        hfx_expr *call = decl->decls[0]->init;
        CHECK(call && call->kind == EX_CALL);
        CHECK_STR(call->name, "Phong");
        CHECK_INT(call->arg_count, 4);
        CHECK_INT(call->loc.line, 204);
        CHECK_INT(call->loc.col, 20);
    }
    tp_free(r);
}

int main(void) {
    test_require_seeds();
    RUN(all_seeds_parse_without_diagnostics);
    RUN(seed_global_counts);
    RUN(ambient_textured_techniques);
    RUN(ambient_annotations_and_initializer);
    RUN(tutorial0_sampler_state);
    RUN(pointlights_arrays);
    RUN(point_multi_declarator);
    RUN(fxcomposer_render_state);
    RUN(multilights_structs_and_call_location);
    return test_summary();
}
