/* mojo_side.c: an fx_2_0 effect drawn through MojoShader's effect framework and GLSL, as FNA3D
 * drives it (see mojo_side.h). */
#include "mojo_side.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "mojoshader.h"

typedef void(APIENTRYP bind_sampler_fn)(GLuint unit, GLuint sampler);
typedef void(APIENTRYP gen_samplers_fn)(GLsizei n, GLuint *samplers);
typedef void(APIENTRYP delete_samplers_fn)(GLsizei n, const GLuint *samplers);
typedef void(APIENTRYP sampler_parameteri_fn)(GLuint sampler, GLenum name, GLint value);

enum { MAX_UNITS = 32 };

struct mj_side {
    MOJOSHADER_glContext *gl_ctx;
    MOJOSHADER_effect *effect;
    MOJOSHADER_effectStateChanges changes;
    bind_sampler_fn BindSampler;
    gen_samplers_fn GenSamplers;
    delete_samplers_fn DeleteSamplers;
    sampler_parameteri_fn SamplerParameteri;
    GLuint samplers[MAX_UNITS]; /* one sampler object per unit, set from MojoShader's sampler states */
    GLuint vao;                 /* MojoShader's own: it tracks which arrays it enabled */
    PFNGLVERTEXATTRIB4FVPROC VertexAttrib4fv;
    PFNGLBINDVERTEXARRAYPROC BindVertexArray;
    int width, height;          /* the target, for VPOS (MojoShader flips it in the default framebuffer) */
    int vertex_sampler_offset;  /* MOJOSHADER_XNA4_VERTEX_TEXTURES: vertex samplers after the pixel ones */
};

/* The effect framework's backend: MojoShader's GL functions, as FNA3D wires them. */
static void *MOJOSHADERCALL compile_shader(const void *ctx, const char *mainfn, const unsigned char *tokens,
                                           const unsigned int size, const MOJOSHADER_swizzle *swiz,
                                           const unsigned int swizcount, const MOJOSHADER_samplerMap *smap,
                                           const unsigned int smapcount) {
    (void)ctx, (void)mainfn;
    return MOJOSHADER_glCompileShader(tokens, size, swiz, swizcount, smap, smapcount);
}
static void MOJOSHADERCALL add_ref(void *shader) { MOJOSHADER_glShaderAddRef(shader); }
static void MOJOSHADERCALL delete_shader(const void *ctx, void *shader) { (void)ctx, MOJOSHADER_glDeleteShader(shader); }
static MOJOSHADER_parseData *MOJOSHADERCALL parse_data(void *shader) {
    return (MOJOSHADER_parseData *)MOJOSHADER_glGetShaderParseData(shader);
}
static void MOJOSHADERCALL bind_shaders(const void *ctx, void *vs, void *ps) { (void)ctx, MOJOSHADER_glBindShaders(vs, ps); }
static void MOJOSHADERCALL bound_shaders(const void *ctx, void **vs, void **ps) {
    (void)ctx;
    MOJOSHADER_glGetBoundShaders((MOJOSHADER_glShader **)vs, (MOJOSHADER_glShader **)ps);
}
static void MOJOSHADERCALL map_uniforms(const void *ctx, float **vsf, int **vsi, unsigned char **vsb, float **psf,
                                        int **psi, unsigned char **psb) {
    (void)ctx;
    MOJOSHADER_glMapUniformBufferMemory(vsf, vsi, vsb, psf, psi, psb);
}
static void MOJOSHADERCALL unmap_uniforms(const void *ctx) { (void)ctx, MOJOSHADER_glUnmapUniformBufferMemory(); }
static const char *MOJOSHADERCALL get_error(const void *ctx) { return (void)ctx, MOJOSHADER_glGetError(); }

static void *lookup(const char *name, void *data) {
    hv_gl_loader load;
    memcpy(&load, &data, sizeof load);
    return load(name);
}

static void *entry(hv_gl_loader load, const char *name) { return load(name); }

mj_side *mj_create(const char *profile, hv_gl_loader load, int width, int height, char *err, size_t errlen) {
    mj_side *m = calloc(1, sizeof *m);
    if (m) m->width = width, m->height = height;
    void *data;
    memcpy(&data, &load, sizeof data);
    if (m) m->gl_ctx = MOJOSHADER_glCreateContext(profile, lookup, data, NULL, NULL, NULL);
    if (!m || !m->gl_ctx) {
        snprintf(err, errlen, "MojoShader: no GL context for %s: %s", profile, MOJOSHADER_glGetError());
        free(m);
        return NULL;
    }
    MOJOSHADER_glMakeContextCurrent(m->gl_ctx);
    void *p;
    if ((p = entry(load, "glBindSampler"))) memcpy(&m->BindSampler, &p, sizeof p);
    if ((p = entry(load, "glGenSamplers"))) memcpy(&m->GenSamplers, &p, sizeof p);
    if ((p = entry(load, "glDeleteSamplers"))) memcpy(&m->DeleteSamplers, &p, sizeof p);
    if ((p = entry(load, "glSamplerParameteri"))) memcpy(&m->SamplerParameteri, &p, sizeof p);
    PFNGLGETINTEGERVPROC get_integerv;
    PFNGLGENVERTEXARRAYSPROC gen_vao;
    if ((p = entry(load, "glVertexAttrib4fv"))) memcpy(&m->VertexAttrib4fv, &p, sizeof p);
    if (!m->BindSampler || !m->GenSamplers || !m->DeleteSamplers || !m->SamplerParameteri || !m->VertexAttrib4fv ||
        !(p = entry(load, "glGetIntegerv"))) {
        snprintf(err, errlen, "no sampler objects in this GL context");
        mj_destroy(m);
        return NULL;
    }
    memcpy(&get_integerv, &p, sizeof p);
    p = entry(load, "glGenVertexArrays");
    memcpy(&gen_vao, &p, sizeof p);
    p = entry(load, "glBindVertexArray");
    memcpy(&m->BindVertexArray, &p, sizeof p);
    GLint units = 0;
    get_integerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units); /* MojoShader's own rule for vertex samplers */
    if (units > 20) units = 20;
    m->vertex_sampler_offset = units > 16 ? 16 : units;
    m->GenSamplers(MAX_UNITS, m->samplers);
    gen_vao(1, &m->vao);
    return m;
}

void mj_destroy(mj_side *m) {
    if (!m) return;
    if (m->effect) MOJOSHADER_deleteEffect(m->effect);
    if (m->samplers[0]) m->DeleteSamplers(MAX_UNITS, m->samplers);
    MOJOSHADER_glMakeContextCurrent(NULL);
    MOJOSHADER_glDestroyContext(m->gl_ctx);
    free(m);
}

static unsigned char *read_all(const char *path, size_t *size) {
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *buf = n > 0 ? malloc((size_t)n) : NULL;
    if (buf && fread(buf, 1, (size_t)n, f) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    fclose(f);
    *size = (size_t)n;
    return buf;
}

int mj_load(mj_side *m, const char *path, char *err, size_t errlen) {
    size_t size = 0;
    unsigned char *buf = read_all(path, &size);
    if (!buf) return snprintf(err, errlen, "cannot read %s", path), -1;
    MOJOSHADER_effectShaderContext ctx = {compile_shader, add_ref, delete_shader, parse_data, bind_shaders,
                                          bound_shaders, map_uniforms, unmap_uniforms, get_error, m, NULL, NULL, NULL};
    m->effect = MOJOSHADER_compileEffect(buf, (unsigned int)size, NULL, 0, NULL, 0, &ctx);
    free(buf);
    if (!m->effect) return snprintf(err, errlen, "MojoShader: out of memory"), -1;
    if (m->effect->error_count > 0)
        return snprintf(err, errlen, "MojoShader: %s", m->effect->errors[0].error ? m->effect->errors[0].error : "?"), -1;
    return 0;
}

size_t mj_technique_count(const mj_side *m) { return m->effect ? (size_t)m->effect->technique_count : 0; }

size_t mj_pass_count(const mj_side *m, size_t technique) {
    return technique < mj_technique_count(m) ? m->effect->techniques[technique].pass_count : 0;
}

/* Whether the shaders' constant tables hold a matrix parameter by columns (HLSL's default):
 * the effect's own class says row-major for those in fxc's files (with the dimensions
 * transposed), so the registers' layout is read where the shaders read it. */
static int by_columns(const mj_side *m, const char *name, int fallback) {
    for (int i = 0; i < m->effect->object_count; i++) {
        const MOJOSHADER_effectObject *o = &m->effect->objects[i];
        if (o->type != MOJOSHADER_SYMTYPE_VERTEXSHADER && o->type != MOJOSHADER_SYMTYPE_PIXELSHADER) continue;
        if (o->shader.is_preshader || !o->shader.shader) continue;
        const MOJOSHADER_parseData *pd = MOJOSHADER_glGetShaderParseData(o->shader.shader);
        for (int k = 0; pd && k < pd->symbol_count; k++)
            if (!strcmp(pd->symbols[k].name, name))
                return pd->symbols[k].info.parameter_class == MOJOSHADER_SYMCLASS_MATRIX_COLUMNS;
    }
    return fallback;
}

/* One parameter's value from hfx's (row-major, elements one after another) into MojoShader's
 * registers, as FNA's EffectParameter.SetValue writes them: four components a register, a
 * column-major matrix one register per column. */
static int copy_param(const mj_side *m, MOJOSHADER_effectValue *v, hfx_param *p, char *err, size_t errlen) {
    size_t rows = hfx_param_rows(p), cols = hfx_param_columns(p), elems = hfx_param_elements(p);
    size_t n = rows * cols * (elems ? elems : 1);
    if (!n || n > 65536) return 0;
    int is_float = v->type.parameter_type == MOJOSHADER_SYMTYPE_FLOAT;
    int by_column = v->type.parameter_class >= MOJOSHADER_SYMCLASS_MATRIX_ROWS &&
                    by_columns(m, v->name, v->type.parameter_class == MOJOSHADER_SYMCLASS_MATRIX_COLUMNS);
    size_t lines = by_column ? cols : rows, width = by_column ? rows : cols;
    if (v->value_count < 4 * lines * (elems ? elems : 1)) {
        snprintf(err, errlen, "parameter %s: MojoShader holds %u values, hfx's type needs %zu registers", v->name,
                 v->value_count, lines * (elems ? elems : 1));
        return -1;
    }
    float *f = malloc(n * sizeof *f);
    int *k = malloc(n * sizeof *k);
    int rc = !f || !k ? -1 : is_float ? hfx_param_get_floats(p, f, n) : hfx_param_get_ints(p, k, n);
    for (size_t e = 0; rc == 0 && e < (elems ? elems : 1); e++)
        for (size_t l = 0; l < lines; l++)
            for (size_t c = 0; c < width && c < 4; c++) {
                size_t from = e * rows * cols + (by_column ? c * cols + l : l * cols + c), to = (e * lines + l) * 4 + c;
                if (is_float) v->valuesF[to] = f[from];
                else v->valuesI[to] = k[from];
            }
    free(f);
    free(k);
    return 0;
}

int mj_copy_params(mj_side *m, hfx_effect *fx, char *err, size_t errlen) {
    for (int i = 0; i < m->effect->param_count; i++) {
        MOJOSHADER_effectValue *v = &m->effect->params[i].value;
        if (v->type.parameter_class > MOJOSHADER_SYMCLASS_MATRIX_COLUMNS) continue; /* objects, structs */
        if (v->type.parameter_type > MOJOSHADER_SYMTYPE_FLOAT) continue;
        hfx_param *p = v->name ? hfx_effect_param(fx, v->name) : NULL;
        if (p && copy_param(m, v, p, err, errlen) != 0) return -1;
    }
    return 0;
}

static GLint gl_address(int d3d) {
    static const GLint map[] = {GL_REPEAT, GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER,
                                GL_MIRROR_CLAMP_TO_EDGE};
    return d3d >= 0 && d3d <= 5 ? map[d3d] : GL_REPEAT;
}

static GLint gl_min(int min, int mip) {
    int lin = min >= MOJOSHADER_TEXTUREFILTER_LINEAR;
    if (mip == MOJOSHADER_TEXTUREFILTER_NONE) return lin ? GL_LINEAR : GL_NEAREST;
    if (mip == MOJOSHADER_TEXTUREFILTER_POINT) return lin ? GL_LINEAR_MIPMAP_NEAREST : GL_NEAREST_MIPMAP_NEAREST;
    return lin ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_LINEAR;
}

/* A sampler register's texture (the parameter its Texture state names, else the sampler's
 * own) and states (Direct3D 9's defaults where the effect names none: wrap, point, no mips). */
static void bind_sampler(mj_side *m, const hv_gl *gl, hfx_effect *fx, const MOJOSHADER_samplerStateRegister *r,
                         int unit) {
    int address[3] = {1, 1, 1}, mag = 1, min = 1, mip = 0;
    const char *texture = r->sampler_name;
    for (unsigned i = 0; i < r->sampler_state_count; i++) {
        const MOJOSHADER_effectSamplerState *s = &r->sampler_states[i];
        int value = s->value.valuesI ? s->value.valuesI[0] : 0;
        if (s->type == MOJOSHADER_SAMP_TEXTURE && value > 0 && value < m->effect->object_count)
            texture = m->effect->objects[value].mapping.name;
        else if (s->type >= MOJOSHADER_SAMP_ADDRESSU && s->type <= MOJOSHADER_SAMP_ADDRESSW)
            address[s->type - MOJOSHADER_SAMP_ADDRESSU] = value;
        else if (s->type == MOJOSHADER_SAMP_MAGFILTER) mag = value;
        else if (s->type == MOJOSHADER_SAMP_MINFILTER) min = value;
        else if (s->type == MOJOSHADER_SAMP_MIPFILTER) mip = value;
    }
    hfx_param *p = texture ? hfx_effect_param(fx, texture) : NULL;
    unsigned int id = 0;
    if (p) hfx_param_get_texture(p, &id);
    GLenum target = p ? hfx_param_texture_target(p) : GL_TEXTURE_2D;
    if (!target) target = GL_TEXTURE_2D;
    GLuint s = m->samplers[unit];
    m->SamplerParameteri(s, GL_TEXTURE_WRAP_S, gl_address(address[0]));
    m->SamplerParameteri(s, GL_TEXTURE_WRAP_T, gl_address(address[1]));
    m->SamplerParameteri(s, GL_TEXTURE_WRAP_R, gl_address(address[2]));
    m->SamplerParameteri(s, GL_TEXTURE_MAG_FILTER, mag >= MOJOSHADER_TEXTUREFILTER_LINEAR ? GL_LINEAR : GL_NEAREST);
    m->SamplerParameteri(s, GL_TEXTURE_MIN_FILTER, gl_min(min, mip));
    gl->ActiveTexture((GLenum)(GL_TEXTURE0 + unit));
    gl->BindTexture(target, id);
    m->BindSampler((GLuint)unit, s);
}

static void bind_samplers(mj_side *m, const hv_gl *gl, hfx_effect *fx) {
    for (unsigned i = 0; i < m->changes.sampler_state_change_count; i++) {
        const MOJOSHADER_samplerStateRegister *r = &m->changes.sampler_state_changes[i];
        if (r->sampler_register < 16) bind_sampler(m, gl, fx, r, (int)r->sampler_register);
    }
    for (unsigned i = 0; i < m->changes.vertex_sampler_state_change_count; i++) {
        const MOJOSHADER_samplerStateRegister *r = &m->changes.vertex_sampler_state_changes[i];
        int unit = (int)r->sampler_register + m->vertex_sampler_offset;
        if (unit < MAX_UNITS) bind_sampler(m, gl, fx, r, unit);
    }
    gl->ActiveTexture(GL_TEXTURE0);
}

typedef struct { MOJOSHADER_usage usage; int index; size_t offset; int size; } stream;

/* The mesh's streams and the constants hfxview gives what a mesh lacks (mesh.h), as usages. */
static void set_attributes(const hv_gl *gl, const mj_side *m, const hv_gpu_mesh *g) {
    static const stream streams[] = {
        {MOJOSHADER_USAGE_POSITION, 0, offsetof(hv_vertex, pos), 3},
        {MOJOSHADER_USAGE_NORMAL, 0, offsetof(hv_vertex, normal), 3},
        {MOJOSHADER_USAGE_TANGENT, 0, offsetof(hv_vertex, tangent), 3},
        {MOJOSHADER_USAGE_BINORMAL, 0, offsetof(hv_vertex, binormal), 3},
    };
    gl->BindVertexArray(m->vao);
    gl->BindBuffer(GL_ARRAY_BUFFER, g->vbo);
    gl->BindBuffer(GL_ELEMENT_ARRAY_BUFFER, g->ibo);
    for (size_t i = 0; i < sizeof streams / sizeof streams[0]; i++)
        MOJOSHADER_glSetVertexAttribute(streams[i].usage, streams[i].index, (unsigned)streams[i].size,
                                        MOJOSHADER_ATTRIBUTE_FLOAT, 0, sizeof(hv_vertex), (void *)streams[i].offset);
    for (int set = 0; set < 8; set++) /* every texture coordinate set reuses the first (render.c) */
        MOJOSHADER_glSetVertexAttribute(MOJOSHADER_USAGE_TEXCOORD, set, 2, MOJOSHADER_ATTRIBUTE_FLOAT, 0,
                                        sizeof(hv_vertex), (void *)offsetof(hv_vertex, uv));
}

static int usage_of(const char *semantic, int *index) {
    static const char *const names[] = {"POSITION", "BLENDWEIGHT", "BLENDINDICES", "NORMAL", "PSIZE"};
    size_t n = strlen(semantic);
    *index = semantic[n - 1] - '0';
    for (int u = 0; u < 5; u++)
        if (!strncmp(semantic, names[u], n - 1) && strlen(names[u]) == n - 1) return u;
    if (!strncmp(semantic, "COLOR", n - 1) && n - 1 == 5) return MOJOSHADER_USAGE_COLOR;
    return -1;
}

/* After glProgramReady (which switches the arrays): the constant inputs, and (0, 0, 0, 1) for
 * any other input the mesh lacks, as Direct3D 9 gives an element the declaration lacks. */
static void set_constants(const mj_side *m) {
    MOJOSHADER_glShader *vs = NULL, *ps = NULL;
    MOJOSHADER_glGetBoundShaders(&vs, &ps);
    const MOJOSHADER_parseData *pd = vs ? MOJOSHADER_glGetShaderParseData(vs) : NULL;
    for (int i = 0; pd && i < pd->attribute_count; i++) {
        const MOJOSHADER_attribute *a = &pd->attributes[i];
        int loc = MOJOSHADER_glGetVertexAttribLocation(a->usage, a->index);
        if (loc < 0) continue;
        static const float none[4] = {0, 0, 0, 1};
        const float *v = none;
        for (size_t k = 0; k < hv_vertex_constant_count; k++) {
            int index, u = usage_of(hv_vertex_constants[k].semantic, &index);
            if (u == (int)a->usage && index == a->index) v = hv_vertex_constants[k].v;
        }
        m->VertexAttrib4fv((GLuint)loc, v);
    }
}

/* MojoShader switches off the arrays it enabled when its program goes, in the bound vertex
 * array object: its own, or its record of them would no longer be true. */
void mj_reset(mj_side *m) {
    m->BindVertexArray(m->vao);
    MOJOSHADER_glBindProgram(NULL);
    m->BindVertexArray(0);
    for (int u = 0; u < MAX_UNITS; u++) m->BindSampler((GLuint)u, 0);
}

/* hfx_states: hfx applies the pass first (its render states; hfx's program and units, which
 * MojoShader's replace), else the device keeps XNA's defaults and hfx is not called. */
static int draw_pass(mj_side *m, const hv_gl *gl, hfx_effect *fx, hfx_pass *p, unsigned pass, const hv_gpu_mesh *g,
                     int hfx_states, char *err, size_t errlen) {
    if (hfx_states) {
        hfx_device_sync(hfx_effect_device(fx)); /* MojoShader changed the program and the units behind hfx */
        if (hfx_pass_apply(p) != HFX_OK)
            return snprintf(err, errlen, "hfx: %s", hfx_device_last_error(hfx_effect_device(fx))), -1;
        gl->BindVertexArray(m->vao);
        MOJOSHADER_glBindProgram(NULL); /* MojoShader binds its program again (hfx's is current now) */
    }
    MOJOSHADER_effectBeginPass(m->effect, pass);
    MOJOSHADER_glShader *vs = NULL, *ps = NULL;
    MOJOSHADER_glGetBoundShaders(&vs, &ps);
    if (!vs) { /* FNA keeps the vertex shader bound before (SpriteBatch's); GL would run fixed function */
        MOJOSHADER_effectEndPass(m->effect);
        return snprintf(err, errlen, "pass %u has no vertex shader", pass), -2;
    }
    GLint program = 0;
    gl->GetIntegerv(GL_CURRENT_PROGRAM, &program);
    if (!program) {
        MOJOSHADER_effectEndPass(m->effect);
        return snprintf(err, errlen, "MojoShader: no program for pass %u: %s", pass, MOJOSHADER_glGetError()), -1;
    }
    bind_samplers(m, gl, fx);
    set_attributes(gl, m, g);
    MOJOSHADER_glProgramReady();
    /* The default framebuffer, as hfx draws in it: no flip of y (a render target would flip). */
    MOJOSHADER_glProgramViewportInfo(m->width, m->height, m->width, m->height, 0);
    set_constants(m);
    gl->DrawElements(GL_TRIANGLES, g->index_count, GL_UNSIGNED_INT, NULL);
    MOJOSHADER_effectEndPass(m->effect);
    return 0;
}

int mj_draw(mj_side *m, const hv_gl *gl, hfx_effect *fx, hfx_technique *t, size_t technique, const hv_gpu_mesh *g,
            int hfx_states, char *err, size_t errlen) {
    if (technique >= mj_technique_count(m)) return snprintf(err, errlen, "MojoShader: no technique %zu", technique), -1;
    MOJOSHADER_effectSetTechnique(m->effect, &m->effect->techniques[technique]);
    unsigned passes = 0;
    hv_set_default_states(gl);
    if (hfx_states) hfx_effect_begin(fx);
    MOJOSHADER_effectBegin(m->effect, &passes, 0, &m->changes);
    int rc = 0;
    for (unsigned i = 0; rc == 0 && i < passes && i < hfx_technique_pass_count(t); i++)
        rc = draw_pass(m, gl, fx, hfx_technique_pass(t, i), i, g, hfx_states, err, errlen);
    MOJOSHADER_effectEnd(m->effect);
    gl->BindVertexArray(0);
    if (hfx_states) {
        mj_reset(m);
        hfx_effect_end(fx);
        hfx_device_sync(hfx_effect_device(fx));
    }
    return rc;
}
