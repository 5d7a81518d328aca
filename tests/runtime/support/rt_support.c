/* rt_support.c: see rt_support.h. Test code: plain globals are fine here. */
#include "rt_support.h"

#include <stdlib.h>
#include <string.h>

#include "gl/gl.h"
#include "gl_context.h"

static char *dup(const char *s) {
    if (!s) return NULL;
    char *d = malloc(strlen(s) + 1);
    strcpy(d, s);
    return d;
}

#define GROW(arr, count) ((arr) = realloc((arr), ((count) + 1) * sizeof *(arr)), memset(&(arr)[count], 0, sizeof *(arr)), &(arr)[(count)++])

hfx_fx_effect *tb_new(void) {
    hfx_fx_effect *fx = calloc(1, sizeof *fx);
    fx->source_name = dup("test.fx");
    fx->targets = 1u << HFX_TARGET_GLSL330;
    return fx;
}

uint32_t tb_param(hfx_fx_effect *fx, const char *name, const char *glsl, hfx_param_class k, hfx_param_type t,
                  uint32_t rows, uint32_t cols, uint32_t elements, uint32_t parent, uint32_t offset, uint32_t words) {
    hfx_fx_param *p = GROW(fx->params, fx->param_count);
    p->name = dup(name);
    p->glsl_name = dup(glsl);
    p->klass = k;
    p->type = t;
    p->rows = rows;
    p->cols = cols;
    p->elements = elements;
    p->parent = parent;
    p->first_child = 0;
    p->offset = offset;
    p->words = words;
    p->sampler = HFX_NONE;
    if (parent == HFX_NONE) fx->top_param_count = fx->param_count;
    if (offset + words > fx->value_words) {
        fx->values = realloc(fx->values, (offset + words) * sizeof *fx->values);
        memset(fx->values + fx->value_words, 0, (offset + words - fx->value_words) * sizeof *fx->values);
        fx->value_words = offset + words;
    }
    return fx->param_count - 1;
}

void tb_children(hfx_fx_effect *fx, uint32_t parent, uint32_t first, uint32_t count) {
    fx->params[parent].first_child = first;
    fx->params[parent].child_count = count;
}

void tb_top_count(hfx_fx_effect *fx, uint32_t n) { fx->top_param_count = n; }

void tb_set_float(hfx_fx_effect *fx, uint32_t word, float v) { memcpy(&fx->values[word], &v, 4); }

static hfx_fx_annotation *add_annotation(hfx_fx_effect *fx, const char *name) {
    hfx_fx_annotation *a = GROW(fx->annotations, fx->annotation_count);
    a->name = dup(name);
    return a;
}

uint32_t tb_annotation_f(hfx_fx_effect *fx, const char *name, const float *v, uint32_t n) {
    hfx_fx_annotation *a = add_annotation(fx, name);
    a->type = HFX_TYPE_FLOAT;
    a->klass = n == 1 ? HFX_CLASS_SCALAR : HFX_CLASS_VECTOR;
    a->rows = 1;
    a->cols = n;
    a->count = n;
    a->data = malloc(n * 4);
    memcpy(a->data, v, n * 4);
    return fx->annotation_count - 1;
}

uint32_t tb_annotation_i(hfx_fx_effect *fx, const char *name, hfx_param_type t, int32_t v) {
    hfx_fx_annotation *a = add_annotation(fx, name);
    a->type = t;
    a->klass = HFX_CLASS_SCALAR;
    a->rows = a->cols = a->count = 1;
    a->data = malloc(4);
    memcpy(a->data, &v, 4);
    return fx->annotation_count - 1;
}

uint32_t tb_annotation_s(hfx_fx_effect *fx, const char *name, const char *s) {
    hfx_fx_annotation *a = add_annotation(fx, name);
    a->type = HFX_TYPE_STRING;
    a->klass = HFX_CLASS_OBJECT;
    a->string = dup(s);
    return fx->annotation_count - 1;
}

uint32_t tb_program(hfx_fx_effect *fx, const char *vs, const char *fs) {
    hfx_fx_program *p = GROW(fx->programs, fx->program_count);
    p->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].data = dup(vs);
    p->code[HFX_STAGE_VERTEX][HFX_TARGET_GLSL330].size = strlen(vs);
    p->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].data = dup(fs);
    p->code[HFX_STAGE_FRAGMENT][HFX_TARGET_GLSL330].size = strlen(fs);
    return fx->program_count - 1;
}

void tb_attribute(hfx_fx_effect *fx, uint32_t prog, const char *semantic, const char *glsl, int32_t location) {
    hfx_fx_program *p = &fx->programs[prog];
    hfx_fx_attribute *a = GROW(p->attributes, p->attribute_count);
    a->semantic = dup(semantic);
    a->glsl_name = dup(glsl);
    a->location = location;
}

void tb_uses(hfx_fx_effect *fx, uint32_t prog, uint32_t param) {
    hfx_fx_program *p = &fx->programs[prog];
    hfx_fx_uniform_use *u = GROW(p->uniforms, p->uniform_count);
    u->param = param;
    u->reg = HFX_NONE;
}

void tb_sampler_use(hfx_fx_effect *fx, uint32_t prog, const char *glsl, uint32_t sampler, int32_t unit) {
    hfx_fx_program *p = &fx->programs[prog];
    hfx_fx_sampler_use *s = GROW(p->samplers, p->sampler_count);
    s->glsl_name = dup(glsl);
    s->sampler = sampler;
    s->unit = unit;
}

uint32_t tb_sampler(hfx_fx_effect *fx, uint32_t param, uint32_t texture_param, hfx_fx_dim dim) {
    hfx_fx_sampler *s = GROW(fx->samplers, fx->sampler_count);
    s->param = param;
    s->texture_param = texture_param;
    s->dim = dim;
    fx->params[param].sampler = fx->sampler_count - 1;
    return fx->sampler_count - 1;
}

static hfx_fx_state *add_state(hfx_fx_effect *fx, const char *name, uint32_t index) {
    const hfx_state_info *info = hfx_state_lookup(name);
    hfx_fx_state *s = GROW(fx->states, fx->state_count);
    s->id = info ? info->id : 0;
    s->index = index;
    s->line = 10 + fx->state_count;
    s->col = 5;
    s->count = 1;
    return s;
}

uint32_t tb_state_i(hfx_fx_effect *fx, const char *name, uint32_t index, int32_t v) {
    hfx_fx_state *s = add_state(fx, name, index);
    s->kind = HFX_FX_VALUE_INT;
    s->i = v;
    return fx->state_count - 1;
}

uint32_t tb_state_e(hfx_fx_effect *fx, const char *name, uint32_t index, const char *value) {
    int32_t v = -999;
    hfx_state_value_lookup(hfx_state_lookup(name), value, &v);
    return tb_state_i(fx, name, index, v);
}

uint32_t tb_state_f(hfx_fx_effect *fx, const char *name, uint32_t index, const float *f, uint32_t n) {
    hfx_fx_state *s = add_state(fx, name, index);
    s->kind = HFX_FX_VALUE_FLOAT;
    s->count = n;
    memcpy(s->f, f, n * sizeof *f);
    return fx->state_count - 1;
}

uint32_t tb_state_p(hfx_fx_effect *fx, const char *name, uint32_t index, uint32_t param) {
    hfx_fx_state *s = add_state(fx, name, index);
    s->kind = HFX_FX_VALUE_PARAM;
    s->ref = param;
    return fx->state_count - 1;
}

void tb_sampler_states(hfx_fx_effect *fx, uint32_t sampler, uint32_t first, uint32_t count) {
    fx->samplers[sampler].first_state = first;
    fx->samplers[sampler].state_count = count;
}

uint32_t tb_technique(hfx_fx_effect *fx, const char *name) {
    hfx_fx_technique *t = GROW(fx->techniques, fx->technique_count);
    t->name = dup(name);
    t->first_pass = fx->pass_count;
    return fx->technique_count - 1;
}

uint32_t tb_pass(hfx_fx_effect *fx, const char *name, uint32_t program, uint32_t first_state, uint32_t state_count) {
    hfx_fx_pass *p = GROW(fx->passes, fx->pass_count);
    p->name = dup(name);
    p->program = program;
    p->first_state = first_state;
    p->state_count = state_count;
    fx->techniques[fx->technique_count - 1].pass_count++;
    return fx->pass_count - 1;
}

/* Counting wrappers. */
static unsigned long total_calls;
#define HFX_GL_V_(name, params, args) \
    static unsigned long n_##name; \
    static void(APIENTRYP real_##name) params; \
    static void APIENTRY count_##name params { total_calls++; n_##name++; real_##name args; }
#define HFX_GL_R_(ret, name, params, args) \
    static unsigned long n_##name; \
    static ret(APIENTRYP real_##name) params; \
    static ret APIENTRY count_##name params { total_calls++; n_##name++; return real_##name args; }
HFX_GL_FUNCS(HFX_GL_V_, HFX_GL_R_)
#undef HFX_GL_V_
#undef HFX_GL_R_

void *tc_loader(const char *name) {
#define HFX_GL_V_(fn, params, args) \
    if (strcmp(name, "gl" #fn) == 0) { \
        *(void **)&real_##fn = test_gl_loader(name); \
        return real_##fn ? (void *)count_##fn : NULL; \
    }
#define HFX_GL_R_(ret, fn, params, args) HFX_GL_V_(fn, params, args)
    HFX_GL_FUNCS(HFX_GL_V_, HFX_GL_R_)
#undef HFX_GL_V_
#undef HFX_GL_R_
    return test_gl_loader(name);
}

unsigned long tc_calls(void) { return total_calls; }

unsigned long tc_count(const char *name) {
#define HFX_GL_V_(fn, params, args) if (strcmp(name, "gl" #fn) == 0) return n_##fn;
#define HFX_GL_R_(ret, fn, params, args) HFX_GL_V_(fn, params, args)
    HFX_GL_FUNCS(HFX_GL_V_, HFX_GL_R_)
#undef HFX_GL_V_
#undef HFX_GL_R_
    return 0;
}

void tc_reset(void) {
    total_calls = 0;
#define HFX_GL_V_(fn, params, args) n_##fn = 0;
#define HFX_GL_R_(ret, fn, params, args) HFX_GL_V_(fn, params, args)
    HFX_GL_FUNCS(HFX_GL_V_, HFX_GL_R_)
#undef HFX_GL_V_
#undef HFX_GL_R_
}

void tgl_load(tgl *g) { test_gl_fns_load(g); }

GLuint tgl_triangles(tgl *g, const float *xy, int vertices, GLuint *buffer) {
    GLuint vao = 0;
    g->GenVertexArrays(1, &vao);
    g->BindVertexArray(vao);
    g->GenBuffers(1, buffer);
    g->BindBuffer(GL_ARRAY_BUFFER, *buffer);
    g->BufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(vertices * 2 * sizeof(float)), xy, GL_STATIC_DRAW);
    g->VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, NULL);
    g->EnableVertexAttribArray(0);
    return vao;
}

const char *const tb_vs_pos =
    "#version 330\n"
    "layout(location = 0) in vec2 POSITION0;\n"
    "void main() { gl_Position = vec4(POSITION0, 0.5, 1.0); }\n";

const char *const tb_fs_color =
    "#version 330\n"
    "uniform vec4 Color;\n"
    "out vec4 hfx_out0;\n"
    "void main() { hfx_out0 = Color; }\n";
