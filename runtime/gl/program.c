/* program.c: one GL program per compiled pass program: compile, link, bind attribute
 * locations, point sampler uniforms at their units, and resolve every parameter the program
 * reads into glUniform* calls (struct members and array elements by their GLSL names). The
 * call for each uniform follows the GLSL type GL reports, so the upload always matches the
 * declaration; matrices go up row-major with transpose = GL_FALSE, which is the layout the
 * generated GLSL is written for (a HLSL RxC matrix is a GLSL matRxC holding its transpose). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "eval.h"
#include "gl/gl_int.h"

typedef struct active_uniform {
    char name[256];
    GLenum type;
    GLint size;
} active_uniform;

typedef struct build {
    hfx_shared *sh;
    hfx_rt_program *p;
    active_uniform *active;
    GLint active_count;
    uint32_t upload_cap;
} build;

static GLuint compile_stage(hfx_shared *sh, GLenum type, const char *src, const char *what) {
    hfx_gl *gl = &sh->dev->gl->fn;
    GLuint s = gl->CreateShader(type);
    if (!s) return 0;
    gl->ShaderSource(s, 1, &src, NULL);
    gl->CompileShader(s);
    GLint ok = 0, len = 0;
    gl->GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (ok) return s;
    gl->GetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    char log[768] = "";
    gl->GetShaderInfoLog(s, sizeof log, NULL, log);
    hfx_rt_fail(sh->dev, HFX_ERR_GL, "%s: GL refused the %s shader: %s", sh->fx->source_name ? sh->fx->source_name : "effect",
                what, log);
    gl->DeleteShader(s);
    return 0;
}

int hfx_rt_program_link(hfx_shared *sh, hfx_rt_program *p, const hfx_fx_program *fp, GLuint vs, GLuint fs) {
    hfx_gl *gl = &sh->dev->gl->fn;
    p->object = gl->CreateProgram();
    if (!p->object) return hfx_rt_fail(sh->dev, HFX_ERR_GL, "glCreateProgram failed");
    gl->AttachShader(p->object, vs);
    gl->AttachShader(p->object, fs);
    /* GLSL 330 carries layout qualifiers; GLSL 110 needs the locations bound before linking.
     * SPIR-V (fp NULL) has its locations in the module. */
    for (uint32_t a = 0; fp && a < fp->attribute_count; a++)
        if (fp->attributes[a].glsl_name && fp->attributes[a].location >= 0)
            gl->BindAttribLocation(p->object, (GLuint)fp->attributes[a].location, fp->attributes[a].glsl_name);
    hfx_rt_program_binary_hint(sh->dev, p->object);
    gl->LinkProgram(p->object);
    gl->DetachShader(p->object, vs);
    gl->DetachShader(p->object, fs);
    GLint ok = 0;
    gl->GetProgramiv(p->object, GL_LINK_STATUS, &ok);
    if (ok) return HFX_OK;
    char log[768] = "";
    gl->GetProgramInfoLog(p->object, sizeof log, NULL, log);
    return hfx_rt_fail(sh->dev, HFX_ERR_GL, "%s: GL refused to link a program: %s",
                       sh->fx->source_name ? sh->fx->source_name : "effect", log);
}

static int read_active(build *b) {
    hfx_gl *gl = &b->sh->dev->gl->fn;
    gl->GetProgramiv(b->p->object, GL_ACTIVE_UNIFORMS, &b->active_count);
    if (b->active_count <= 0) return HFX_OK;
    b->active = calloc((size_t)b->active_count, sizeof *b->active);
    if (!b->active) return HFX_ERR_MEMORY;
    for (GLint i = 0; i < b->active_count; i++) {
        active_uniform *u = &b->active[i];
        gl->GetActiveUniform(b->p->object, (GLuint)i, sizeof u->name, NULL, &u->size, &u->type, u->name);
        char *bracket = strstr(u->name, "[0]");
        if (bracket && bracket[3] == '\0') *bracket = '\0'; /* arrays report "name[0]" */
    }
    return HFX_OK;
}

static const active_uniform *find_active(const build *b, const char *name) {
    for (GLint i = 0; i < b->active_count; i++)
        if (strcmp(b->active[i].name, name) == 0) return &b->active[i];
    return NULL;
}

static int upload_fn(GLenum type, uint16_t *fn, uint32_t *comps, int *is_int) {
    *is_int = 0;
    switch (type) {
    case GL_FLOAT: *fn = UP_F1, *comps = 1; return 1;
    case GL_FLOAT_VEC2: *fn = UP_F2, *comps = 2; return 1;
    case GL_FLOAT_VEC3: *fn = UP_F3, *comps = 3; return 1;
    case GL_FLOAT_VEC4: *fn = UP_F4, *comps = 4; return 1;
    case GL_INT: case GL_BOOL: *fn = UP_I1, *comps = 1, *is_int = 1; return 1;
    case GL_INT_VEC2: case GL_BOOL_VEC2: *fn = UP_I2, *comps = 2, *is_int = 1; return 1;
    case GL_INT_VEC3: case GL_BOOL_VEC3: *fn = UP_I3, *comps = 3, *is_int = 1; return 1;
    case GL_INT_VEC4: case GL_BOOL_VEC4: *fn = UP_I4, *comps = 4, *is_int = 1; return 1;
    case GL_UNSIGNED_INT: *fn = UP_U1, *comps = 1, *is_int = 1; return 1;
    case GL_UNSIGNED_INT_VEC2: *fn = UP_U2, *comps = 2, *is_int = 1; return 1;
    case GL_UNSIGNED_INT_VEC3: *fn = UP_U3, *comps = 3, *is_int = 1; return 1;
    case GL_UNSIGNED_INT_VEC4: *fn = UP_U4, *comps = 4, *is_int = 1; return 1;
    case GL_FLOAT_MAT2: *fn = UP_M2, *comps = 4; return 1;
    case GL_FLOAT_MAT3: *fn = UP_M3, *comps = 9; return 1;
    case GL_FLOAT_MAT4: *fn = UP_M4, *comps = 16; return 1;
    case GL_FLOAT_MAT2x3: *fn = UP_M2x3, *comps = 6; return 1;
    case GL_FLOAT_MAT3x2: *fn = UP_M3x2, *comps = 6; return 1;
    case GL_FLOAT_MAT2x4: *fn = UP_M2x4, *comps = 8; return 1;
    case GL_FLOAT_MAT4x2: *fn = UP_M4x2, *comps = 8; return 1;
    case GL_FLOAT_MAT3x4: *fn = UP_M3x4, *comps = 12; return 1;
    case GL_FLOAT_MAT4x3: *fn = UP_M4x3, *comps = 12; return 1;
    default: return 0;
    }
}

/* glUniform{1..4}uiv for a uint uniform (D3D9 has no uint registers: HLSL uint parameters hold
 * ints, whose bits the GLSL uint takes). */
static void upload_uint(hfx_device *dev, const hfx_upload *up, const void *v) {
    const GLuint *u = v;
    switch (up->fn) {
    case UP_U1: dev->gl->fn.Uniform1uiv(up->location, up->count, u); break;
    case UP_U2: dev->gl->fn.Uniform2uiv(up->location, up->count, u); break;
    case UP_U3: dev->gl->fn.Uniform3uiv(up->location, up->count, u); break;
    default: dev->gl->fn.Uniform4uiv(up->location, up->count, u); break;
    }
}

static void set_call(const hfx_gl *gl, hfx_upload *up) {
    switch (up->fn) {
    case UP_F1: up->call.f = gl->Uniform1fv; break;
    case UP_F2: up->call.f = gl->Uniform2fv; break;
    case UP_F3: up->call.f = gl->Uniform3fv; break;
    case UP_F4: up->call.f = gl->Uniform4fv; break;
    case UP_I1: up->call.i = gl->Uniform1iv; break;
    case UP_I2: up->call.i = gl->Uniform2iv; break;
    case UP_I3: up->call.i = gl->Uniform3iv; break;
    case UP_I4: up->call.i = gl->Uniform4iv; break;
    case UP_M2: up->call.m = gl->UniformMatrix2fv; break;
    case UP_M3: up->call.m = gl->UniformMatrix3fv; break;
    case UP_M4: up->call.m = gl->UniformMatrix4fv; break;
    case UP_M2x3: up->call.m = gl->UniformMatrix2x3fv; break;
    case UP_M3x2: up->call.m = gl->UniformMatrix3x2fv; break;
    case UP_M2x4: up->call.m = gl->UniformMatrix2x4fv; break;
    case UP_M4x2: up->call.m = gl->UniformMatrix4x2fv; break;
    case UP_M3x4: up->call.m = gl->UniformMatrix3x4fv; break;
    default: up->call.m = gl->UniformMatrix4x3fv; break;
    }
}

int hfx_rt_upload_setup(const hfx_gl *gl, GLenum type, const hfx_fx_param *p, hfx_upload *up, uint32_t *comps) {
    int is_int;
    uint32_t elem_words = p->elements ? p->words / p->elements : p->words;
    if (!upload_fn(type, &up->fn, comps, &is_int) || *comps != elem_words) return 0;
    if (is_int != (p->type != HFX_TYPE_FLOAT)) up->kind = UK_CONVERT;
    else if (is_int) up->kind = up->fn >= UP_U1 && up->fn <= UP_U4 ? UK_UINT : UK_INT;
    else if (up->fn >= UP_M2) up->kind = UK_MATRIX;
    else up->kind = UK_FLOAT;
    set_call(gl, up);
    return 1;
}

int hfx_rt_upload_add(hfx_device *dev, hfx_rt_program *p, uint32_t *cap, const hfx_upload *up) {
    if (!HFX_GROW(p->uploads, p->upload_count, *cap, 8)) return HFX_ERR_MEMORY;
    p->uploads[p->upload_count++] = *up;
    if (up->kind == UK_CONVERT && up->words > dev->gl->scratch_size) {
        float *s = realloc(dev->gl->scratch, up->words * sizeof *s);
        if (!s) return HFX_ERR_MEMORY;
        dev->gl->scratch = s;
        dev->gl->scratch_size = up->words;
    }
    return HFX_OK;
}

/* One call for a value or an array of values (a hfx_param_leaves callback). */
static int add_upload(void *ctx, const char *name, const hfx_fx_param *p) {
    build *b = ctx;
    uint32_t count = p->elements ? p->elements : 1;
    const active_uniform *u = find_active(b, name);
    if (!u) return HFX_OK; /* optimised out by GL */
    hfx_upload up;
    memset(&up, 0, sizeof up);
    uint32_t comps;
    const hfx_gl *gl = &b->sh->dev->gl->fn;
    if (!hfx_rt_upload_setup(gl, u->type, p, &up, &comps)) {
        hfx_shared_warn(b->sh, NULL, "uniform '%s': its GLSL type does not match parameter '%s'; not uploaded", name,
                        p->name ? p->name : "");
        return HFX_OK;
    }
    char loc_name[300];
    int n = snprintf(loc_name, sizeof loc_name, "%s%s", name, u->size > 1 || p->elements ? "[0]" : "");
    if (n < 0 || (size_t)n >= sizeof loc_name) return HFX_OK;
    up.location = gl->GetUniformLocation(b->p->object, loc_name);
    if (up.location < 0) up.location = gl->GetUniformLocation(b->p->object, name);
    if (up.location < 0) return HFX_OK;
    up.count = (GLsizei)(count < (uint32_t)u->size ? count : (uint32_t)u->size);
    up.offset = p->offset;
    up.words = (uint32_t)up.count * comps;
    return hfx_rt_upload_add(b->sh->dev, b->p, &b->upload_cap, &up);
}

static int resolve_uniforms(build *b, const hfx_fx_program *fp) {
    hfx_rt_program *p = b->p;
    uint32_t tops = b->sh->fx->top_param_count;
    p->slots = calloc((size_t)tops + 1, sizeof *p->slots); /* + 1: parameters outside any top-level one */
    p->reads = calloc(fp->uniform_count ? fp->uniform_count : 1, sizeof *p->reads);
    if (!p->slots || !p->reads) return HFX_ERR_MEMORY;
    for (uint32_t i = 0; i < fp->uniform_count; i++) {
        uint32_t param = fp->uniforms[i].param;
        if (param >= tops || !b->sh->fx->params[param].glsl_name) continue;
        hfx_slot *slot = &p->slots[param];
        if (slot->held) continue; /* listed twice */
        slot->held = 1;
        if (hfx_fx_use_packed(fp, &fp->uniforms[i])) {
            hfx_rt_slot_pack(slot, b->sh->fx, &fp->uniforms[i]);
            p->reads[p->read_count++] = param;
            continue;
        }
        slot->first = p->upload_count;
        int rc = hfx_param_leaves(b->sh->fx, param, b->sh->fx->params[param].glsl_name, add_upload, b);
        if (rc) return rc;
        slot->count = p->upload_count - slot->first;
        if (slot->count) p->reads[p->read_count++] = param;
    }
    return HFX_OK;
}

void hfx_rt_slot_pack(hfx_slot *slot, const hfx_fx_effect *fx, const hfx_fx_uniform_use *u) {
    const hfx_fx_param *p = &fx->params[u->param];
    slot->mode = SLOT_REG;
    slot->reg = u->reg;
    slot->reg_rows = (uint16_t)hfx_fx_param_packable(fx, u->param);
    slot->reg_cols = (uint16_t)p->cols;
    slot->up.offset = p->offset;
}

int hfx_rt_regs_setup(hfx_device *dev, hfx_rt_program *p, uint32_t size, GLint (*loc_of)(void *ctx, uint32_t i), void *ctx) {
    if (!size) return HFX_OK;
    p->regs = calloc((size_t)size * 4, sizeof *p->regs);
    p->reg_locs = calloc(size, sizeof *p->reg_locs);
    if (!p->regs || !p->reg_locs) return HFX_ERR_MEMORY;
    p->reg_size = size;
    p->reg_call = dev->gl->fn.Uniform4fv;
    /* GL keeps the elements up to the last one a shader reads; the rest are never sent */
    while (p->reg_active < size && (p->reg_locs[p->reg_active] = loc_of(ctx, p->reg_active)) >= 0) p->reg_active++;
    return HFX_OK;
}

static GLint glsl_reg_location(void *ctx, uint32_t i) {
    build *b = ctx;
    char name[32];
    snprintf(name, sizeof name, "%s[%u]", HFX_FX_REGS_NAME, (unsigned)i);
    return b->sh->dev->gl->fn.GetUniformLocation(b->p->object, name);
}

/* A packed parameter whose registers hold its words as they are (4 components a row) and all
 * reach GL: Apply's one-change path sends it like a separate uniform, one glUniform4fv. */
static void reg4_of(const hfx_rt_program *p, hfx_slot *slot) {
    if (slot->reg_cols != 4 || slot->reg >= p->reg_active || slot->reg_rows > p->reg_active - slot->reg) return;
    slot->mode = SLOT_REG4;
    slot->up.call.f = p->reg_call;
    slot->up.location = p->reg_locs[slot->reg];
    slot->up.count = slot->reg_rows;
    slot->up.kind = UK_FLOAT;
    slot->up.fn = UP_F4;
    slot->up.words = 4u * slot->reg_rows;
}

/* What Apply reads, derived once the uploads and the extras' locations are known: shared with
 * spirv_load.c, which finds the locations its own way. */
void hfx_rt_program_ready(hfx_rt_program *p, uint32_t tops) {
    for (uint32_t i = 0; i < tops; i++) {
        hfx_slot *slot = &p->slots[i];
        slot->held = 0; /* GL holds no value yet */
        if (slot->mode == SLOT_REG || !slot->count) {
            /* preshaders read it: off the paths that do not look for them */
            if (hfx_preshaders_read(&p->pre, i)) slot->mode = slot->mode == SLOT_REG ? SLOT_REG_PRE : SLOT_PRE;
            else if (slot->mode == SLOT_REG) reg4_of(p, slot);
            continue;
        }
        slot->up = p->uploads[slot->first];
        slot->mode = slot->count > 1 || hfx_preshaders_read(&p->pre, i) ? SLOT_OTHER : slot->up.kind == UK_FLOAT ? SLOT_FLOAT
                   : slot->up.kind == UK_MATRIX ? SLOT_MATRIX : SLOT_OTHER;
    }
    p->alpha_test = p->alpha_func_loc >= 0 || p->alpha_ref_loc >= 0;
}

/* Sampler uniforms never change unit: set once, with the program bound briefly. */
static void set_sampler_units(hfx_shared *sh, hfx_rt_program *p, const hfx_fx_program *fp) {
    hfx_gl *gl = &sh->dev->gl->fn;
    GLint current = 0;
    gl->GetIntegerv(GL_CURRENT_PROGRAM, &current);
    gl->UseProgram(p->object);
    for (uint32_t i = 0; i < fp->sampler_count; i++) {
        if (!fp->samplers[i].glsl_name) continue;
        GLint loc = gl->GetUniformLocation(p->object, fp->samplers[i].glsl_name);
        if (loc >= 0) gl->Uniform1i(loc, fp->samplers[i].unit);
    }
    p->pos_fixup_loc = gl->GetUniformLocation(p->object, "hfx_pos_fixup");
    memset(p->pos_fixup, 0, sizeof p->pos_fixup); /* GL's value for an unset uniform */
    p->pos_fixup_serial = 0;                      /* the device's starts at 1: compare once */
    p->alpha_func_loc = gl->GetUniformLocation(p->object, "hfx_alpha_func");
    p->alpha_ref_loc = gl->GetUniformLocation(p->object, "hfx_alpha_ref");
    p->alpha_func = -1;
    p->alpha_ref = -1.0f;
    gl->UseProgram((GLuint)current);
}

/* Both stages compiled from GLSL and linked into p->object. */
static int link_sources(hfx_shared *sh, hfx_rt_program *p, const hfx_fx_program *fp, const char *vs_src,
                        const char *fs_src) {
    GLuint vs = compile_stage(sh, GL_VERTEX_SHADER, vs_src, "vertex");
    GLuint fs = vs ? compile_stage(sh, GL_FRAGMENT_SHADER, fs_src, "fragment") : 0;
    int rc = vs && fs ? hfx_rt_program_link(sh, p, fp, vs, fs) : HFX_ERR_GL;
    if (vs) sh->dev->gl->fn.DeleteShader(vs);
    if (fs) sh->dev->gl->fn.DeleteShader(fs);
    return rc;
}

/* Links the sources into p and resolves everything Apply needs from it. */
static int build_from(hfx_shared *sh, hfx_rt_program *p, const hfx_fx_program *fp, const char *vs_src, const char *fs_src) {
    int rc = hfx_rt_program_cached_link(sh, p, fp, vs_src, fs_src, link_sources);
    if (rc) return rc;
    build b = {sh, p, NULL, 0, 0};
    rc = read_active(&b);
    if (!rc) rc = resolve_uniforms(&b, fp);
    if (!rc) rc = hfx_rt_regs_setup(sh->dev, p, fp->reg_count, glsl_reg_location, &b);
    if (!rc) rc = hfx_rt_preshaders_setup(p, sh->fx, fp);
    free(b.active);
    if (rc) return rc == HFX_ERR_MEMORY ? hfx_rt_fail(sh->dev, rc, "out of memory") : rc;
    set_sampler_units(sh, p, fp);
    hfx_rt_program_ready(p, sh->fx->top_param_count);
    return HFX_OK;
}

/* The switches' words, in the order HFX_SWITCH_k numbers them. */
static void find_switches(const hfx_fx_effect *fx, const hfx_fx_program *fp, hfx_rt_program *p) {
    for (uint32_t k = 0; k < fp->uniform_count && p->switch_count < HFX_FX_MAX_SWITCHES; k++)
        if (fp->uniforms[k].flags & HFX_FX_USE_SWITCH) p->switch_words[p->switch_count++] = fx->params[fp->uniforms[k].param].offset;
}

int hfx_rt_program_build(hfx_shared *sh, uint32_t index, hfx_target target) {
    const hfx_fx_program *fp = &sh->fx->programs[index];
    hfx_rt_program *p = &sh->gl->programs[index];
    const char *vs_src = fp->code[HFX_STAGE_VERTEX][target].data;
    const char *fs_src = fp->code[HFX_STAGE_FRAGMENT][target].data;
    if (!vs_src || !fs_src)
        return hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "%s: program %u has no code for the requested GLSL target",
                           sh->fx->source_name ? sh->fx->source_name : "effect", (unsigned)index);
    p->index = index;
    p->target = target;
    find_switches(sh->fx, fp, p);
    return build_from(sh, p, fp, vs_src, fs_src);
}

/* src with `#define HFX_SWITCH_k true|false` for each switch after its #version line. */
static char *with_switches(const char *src, uint32_t count, uint32_t mask) {
    const char *eol = strchr(src, '\n');
    if (!eol) return NULL;
    size_t head = (size_t)(eol - src) + 1, rest = strlen(eol + 1);
    char *out = malloc(head + count * 40 + rest + 1);
    if (!out) return NULL;
    memcpy(out, src, head);
    size_t n = head;
    for (uint32_t k = 0; k < count; k++)
        n += (size_t)sprintf(out + n, "#define HFX_SWITCH_%u %s\n", (unsigned)k, mask >> k & 1 ? "true" : "false");
    memcpy(out + n, eol + 1, rest + 1);
    return out;
}

/* Variant `mask` of p: its sources with the switches defined, built as any program. */
static int build_switched(hfx_shared *sh, const hfx_rt_program *p, hfx_rt_program *v, uint32_t mask) {
    const hfx_fx_program *fp = &sh->fx->programs[p->index];
    char *vs = with_switches(fp->code[HFX_STAGE_VERTEX][p->target].data, p->switch_count, mask);
    char *fs = with_switches(fp->code[HFX_STAGE_FRAGMENT][p->target].data, p->switch_count, mask);
    int rc = vs && fs ? build_from(sh, v, fp, vs, fs) : hfx_rt_fail(sh->dev, HFX_ERR_MEMORY, "out of memory");
    free(vs);
    free(fs);
    v->index = p->index;
    v->target = p->target;
    return rc;
}

hfx_rt_program *hfx_rt_program_switched(hfx_shared *sh, hfx_rt_program *p, uint32_t mask) {
    if (p->switch_failed >> mask & 1) return p;
    if (!p->variants && !(p->variants = calloc((size_t)1 << p->switch_count, sizeof *p->variants))) return p;
    hfx_rt_program *v = &p->variants[mask];
    if (v->object) return v;
    if (build_switched(sh, p, v, mask) == HFX_OK) return v;
    hfx_rt_program_free(sh->dev, v); /* GL refused it (it never should): the uniform reads work as well */
    p->switch_failed |= 1u << mask;
    return p;
}

void hfx_rt_program_free(hfx_device *dev, hfx_rt_program *p) {
    /* GL frees the bound program's name once another is bound (a load binds one briefly) and
     * may hand it to a later program: the shadow must not then take that one for bound. */
    if (p->object && dev->gl->program == p->object) dev->gl->program = (GLuint)-1;
    if (p->object) dev->gl->fn.DeleteProgram(p->object);
    free(p->slots);
    free(p->reads);
    free(p->uploads);
    free(p->regs);
    free(p->reg_locs);
    hfx_preshaders_free(&p->pre);
    for (uint32_t m = 0; p->variants && m < (1u << p->switch_count); m++) hfx_rt_program_free(dev, &p->variants[m]);
    free(p->variants);
    memset(p, 0, sizeof *p);
}

/* What Apply does not inline: int uniforms, and uploads converting int <-> float through scratch. */
void hfx_rt_upload_slow(hfx_device *dev, const hfx_upload *up, const uint32_t *values) {
    const uint32_t *src = values + up->offset;
    if (up->kind == UK_FLOAT) {
        up->call.f(up->location, up->count, (const void *)src);
        return;
    }
    if (up->kind == UK_MATRIX) {
        up->call.m(up->location, up->count, GL_FALSE, (const void *)src);
        return;
    }
    if (up->kind == UK_INT) {
        up->call.i(up->location, up->count, (const void *)src);
        return;
    }
    if (up->kind == UK_UINT) { /* the int's bits as they are: set_int(3) is 3u */
        upload_uint(dev, up, (const GLuint *)src);
        return;
    }
    /* GLSL declared int where the data is float, or the reverse. */
    hfx_gl *gl = &dev->gl->fn;
    int to_int = up->fn >= UP_I1 && up->fn <= UP_U4;
    for (uint32_t i = 0; i < up->words; i++) {
        if (to_int) {
            float f;
            memcpy(&f, &src[i], sizeof f);
            int32_t v = hfx_ev_int(f);
            memcpy(&dev->gl->scratch[i], &v, sizeof v);
        } else {
            dev->gl->scratch[i] = (float)(int32_t)src[i];
        }
    }
    const void *d = dev->gl->scratch;
    GLsizei n = up->count;
    switch (up->fn) {
    case UP_F1: gl->Uniform1fv(up->location, n, d); break;
    case UP_F2: gl->Uniform2fv(up->location, n, d); break;
    case UP_F3: gl->Uniform3fv(up->location, n, d); break;
    case UP_F4: gl->Uniform4fv(up->location, n, d); break;
    case UP_I1: gl->Uniform1iv(up->location, n, d); break;
    case UP_I2: gl->Uniform2iv(up->location, n, d); break;
    case UP_I3: gl->Uniform3iv(up->location, n, d); break;
    case UP_I4: gl->Uniform4iv(up->location, n, d); break;
    case UP_U1: case UP_U2: case UP_U3: case UP_U4: upload_uint(dev, up, d); break;
    case UP_M2: gl->UniformMatrix2fv(up->location, n, GL_FALSE, d); break;
    case UP_M3: gl->UniformMatrix3fv(up->location, n, GL_FALSE, d); break;
    case UP_M4: gl->UniformMatrix4fv(up->location, n, GL_FALSE, d); break;
    case UP_M2x3: gl->UniformMatrix2x3fv(up->location, n, GL_FALSE, d); break;
    case UP_M3x2: gl->UniformMatrix3x2fv(up->location, n, GL_FALSE, d); break;
    case UP_M2x4: gl->UniformMatrix2x4fv(up->location, n, GL_FALSE, d); break;
    case UP_M4x2: gl->UniformMatrix4x2fv(up->location, n, GL_FALSE, d); break;
    case UP_M3x4: gl->UniformMatrix3x4fv(up->location, n, GL_FALSE, d); break;
    case UP_M4x3: gl->UniformMatrix4x3fv(up->location, n, GL_FALSE, d); break;
    default: break;
    }
}

/* Every parameter the program reads whose version differs from the one GL holds: when the
 * program last followed another instance (clones share programs; versions are device-wide, so
 * a clone's unchanged values are not sent again) or fell a whole log ring behind. */
void hfx_rt_upload_all(hfx_effect *fx, hfx_rt_program *p) {
    hfx_reg_range regs = {UINT32_MAX, 0};
    for (uint32_t k = 0; k < p->read_count; k++) {
        uint32_t r = p->reads[k];
        hfx_slot *s = &p->slots[r];
        if (s->held == fx->stamps[r]) continue;
        s->held = fx->stamps[r];
        if (s->mode == SLOT_REG || s->mode == SLOT_REG4 || s->mode == SLOT_REG_PRE) hfx_rt_reg_copy(p, s, fx->values, &regs);
        else hfx_rt_upload_slot(fx, p, s);
        if (hfx_preshaders_read(&p->pre, r)) hfx_preshaders_mark(&p->pre, r);
    }
    if (p->pre.pending) hfx_preshaders_run(&p->pre, fx->values, p->regs, p->reg_size, &regs);
    hfx_rt_reg_send(p, regs);
    p->memo_effect = fx->id;
    p->memo_seen = fx->log_len;
}

/* All the uploads of one parameter (one per leaf of a struct). */
void hfx_rt_upload_slot(hfx_effect *fx, const hfx_rt_program *p, const hfx_slot *s) {
    for (uint32_t k = 0; k < s->count; k++) hfx_rt_upload_slow(fx->dev, &p->uploads[s->first + k], fx->values);
}

/* The rarer slots: several uploads, or preshaders reading the parameter. */
static void upload_other(hfx_effect *fx, hfx_rt_program *p, const hfx_slot *s, uint32_t root, hfx_reg_range *regs) {
    if (s->mode == SLOT_OTHER) hfx_rt_upload_slot(fx, p, s);
    else if (s->mode == SLOT_REG_PRE) hfx_rt_reg_copy(p, s, fx->values, regs);
    if (hfx_preshaders_read(&p->pre, root)) hfx_preshaders_mark(&p->pre, root);
}

int hfx_rt_upload_changed(hfx_effect *fx, hfx_rt_program *p) {
    if (p->memo_effect != fx->id) {
        hfx_rt_upload_all(fx, p);
        return HFX_OK;
    }
    return hfx_rt_upload_log(fx, p);
}

/* The run of log entries [seen, len) that are packed rows of four (or held already): copies into
 * the image, widening *range; returns where the run stopped. On its own, so the loop keeps all it
 * reads in registers (the common frame: float4s and matrices only). */
static uint64_t copy_rows4(hfx_effect *fx, hfx_rt_program *p, uint64_t seen, uint64_t len, hfx_reg_range *range) {
    const uint32_t *log = fx->log, *values = fx->values;
    const uint64_t *stamps = fx->stamps;
    uint32_t mask = fx->log_mask, lo = range->lo, hi = range->hi;
    hfx_slot *slots = p->slots;
    float *regs = p->regs;
    for (; seen != len; seen++) {
        uint32_t r = log[seen & mask];
        hfx_slot *s = &slots[r];
        if (s->held == stamps[r]) continue;
        if (s->mode != SLOT_REG4) break;
        s->held = stamps[r];
        float *dst = regs + 4 * (size_t)s->reg;
        if (s->reg_rows == 1) memcpy(dst, values + s->up.offset, 16);
        else memcpy(dst, values + s->up.offset, 16 * (size_t)s->reg_rows);
        uint32_t last = s->reg + s->reg_rows - 1u;
        lo = s->reg < lo ? s->reg : lo;
        hi = last > hi ? last : hi;
    }
    range->lo = lo, range->hi = hi;
    return seen;
}

/* Visits the log entries written since the program last looked; an entry whose parameter the
 * program already holds at its latest version (changed twice, or not read) costs no call.
 * The fields the loop reads are copied first: the GL calls could, as far as the compiler
 * knows, write through fx and p. */
int hfx_rt_upload_log(hfx_effect *fx, hfx_rt_program *p) {
    uint64_t seen = p->memo_seen, len = fx->log_len;
    if (len - seen > (uint64_t)fx->log_mask + 1) { /* fell a whole ring behind */
        hfx_rt_upload_all(fx, p);
        return HFX_OK;
    }
    hfx_reg_range regs = {UINT32_MAX, 0};
    p->memo_seen = len;
    if (p->regs) seen = copy_rows4(fx, p, seen, len, &regs);
    const uint32_t *log = fx->log, *values = fx->values;
    const uint64_t *stamps = fx->stamps;
    uint32_t mask = fx->log_mask;
    hfx_slot *slots = p->slots;
    for (; seen != len; seen++) {
        uint32_t r = log[seen & mask];
        hfx_slot *s = &slots[r];
        if (s->held == stamps[r]) continue;
        s->held = stamps[r];
        if (s->mode == SLOT_REG4) /* packed float4 / matrix: into the image, one send at the end */
            hfx_rt_reg_copy(p, s, values, &regs);
        else if (s->mode == SLOT_FLOAT)
            s->up.call.f(s->up.location, s->up.count, (const void *)(values + s->up.offset));
        else if (s->mode == SLOT_MATRIX)
            s->up.call.m(s->up.location, s->up.count, GL_FALSE, (const void *)(values + s->up.offset));
        else if (s->mode == SLOT_REG)
            hfx_rt_reg_copy(p, s, values, &regs);
        else
            upload_other(fx, p, s, r, &regs);
    }
    if (p->pre.pending) hfx_preshaders_run(&p->pre, values, p->regs, p->reg_size, &regs);
    hfx_rt_reg_send(p, regs);
    return HFX_OK;
}

/* hfx_pos_fixup and the alpha test's uniforms, for programs that declare them. */
void hfx_rt_program_extras(hfx_device *dev, hfx_rt_program *p) {
    if (p->pos_fixup_serial != dev->gl->pos_fixup_serial) {
        p->pos_fixup_serial = dev->gl->pos_fixup_serial;
        if (p->pos_fixup_loc >= 0 && memcmp(p->pos_fixup, dev->gl->pos_fixup, sizeof p->pos_fixup) != 0) {
            memcpy(p->pos_fixup, dev->gl->pos_fixup, sizeof p->pos_fixup);
            dev->gl->fn.Uniform4fv(p->pos_fixup_loc, 1, p->pos_fixup);
        }
    }
    if (p->alpha_test) hfx_rs_alpha_test(dev, p);
}

/* A program's preshaders (preshader.c) once its registers are set up: the parameters they read
 * join the program's reads, so a full scan marks them too. */
static int add_read(hfx_rt_program *p, uint32_t r) {
    for (uint32_t k = 0; k < p->read_count; k++)
        if (p->reads[k] == r) return HFX_OK;
    uint32_t *grown = realloc(p->reads, ((size_t)p->read_count + 1) * sizeof *grown);
    if (!grown) return HFX_ERR_MEMORY;
    p->reads = grown;
    p->reads[p->read_count++] = r;
    return HFX_OK;
}

int hfx_rt_preshaders_setup(hfx_rt_program *p, const hfx_fx_effect *fx, const hfx_fx_program *fp) {
    if (!fp->preshader_count || !p->regs) return HFX_OK;
    int rc = hfx_preshaders_init(&p->pre, fx, fp);
    for (uint32_t r = 0; !rc && r < fx->top_param_count; r++)
        if (p->pre.count[r]) rc = add_read(p, r);
    return rc;
}
