/* spirv_load.c: GL programs from the SPIR-V target (HFX_TARGET_SPIRV) through ARB_gl_spirv.
 * Each stage is a glShaderBinary(GL_SHADER_BINARY_FORMAT_SPIR_V) specialised at "main"; the
 * attribute locations are in the modules already. A SPIR-V program has no uniform names to look
 * up, so every uniform is driven at the location the compiler gave it: the rule of
 * docs/conventions.md ("SPIR-V"), computed by common/spirv_loc.c, the code the compiler itself
 * places them with. GL's program interface query says which locations are active and with what
 * type, so the glUniform* call follows the declaration as on the GLSL path (program.c). Samplers
 * carry binding = unit: no glUniform1i. */
#include <stdlib.h>
#include <string.h>

#include "gl/gl_int.h"
#include "spirv_loc.h"

void hfx_rt_spirv_init(hfx_device *dev, hfx_gl_loader load) {
    hfx_gl_spirv *s = &dev->gl->spirv;
    memset(s, 0, sizeof *s);
    GLint major = 0, minor = 0;
    dev->gl->fn.GetIntegerv(GL_MAJOR_VERSION, &major);
    dev->gl->fn.GetIntegerv(GL_MINOR_VERSION, &minor);
    int core = major * 10 + minor >= 46;
    if (!core && !hfx_gl_has_extension(&dev->gl->fn, "GL_ARB_gl_spirv")) return;
    *(void **)&s->ShaderBinary = load("glShaderBinary");
    *(void **)&s->SpecializeShader = load(core ? "glSpecializeShader" : "glSpecializeShaderARB");
    if (!s->SpecializeShader)
        *(void **)&s->SpecializeShader = load(core ? "glSpecializeShaderARB" : "glSpecializeShader");
    *(void **)&s->GetProgramInterfaceiv = load("glGetProgramInterfaceiv");
    *(void **)&s->GetProgramResourceiv = load("glGetProgramResourceiv");
    s->ok = s->ShaderBinary && s->SpecializeShader && s->GetProgramInterfaceiv && s->GetProgramResourceiv;
}

int hfx_rt_spirv_check(hfx_device *dev, const hfx_fx_effect *fx) {
    if (dev->gl->spirv.ok) return HFX_OK;
    return hfx_rt_fail(dev, HFX_ERR_GL,
                       "%s: this GL cannot load SPIR-V (it has neither OpenGL 4.6 nor GL_ARB_gl_spirv with "
                       "glShaderBinary and the program interface queries); load the effect with a GLSL target",
                       fx->source_name ? fx->source_name : "effect");
}

static const char *name_of(const hfx_shared *sh) { return sh->fx->source_name ? sh->fx->source_name : "effect"; }

static GLuint specialize_stage(hfx_shared *sh, GLenum type, const hfx_fx_code *code, const char *what) {
    hfx_gl *gl = &sh->dev->gl->fn;
    if (!code->data || code->size < 20 || code->size % 4 || code->size > 0x7fffffff) {
        hfx_rt_fail(sh->dev, HFX_ERR_LOAD, "%s: the %s shader's SPIR-V is missing or truncated", name_of(sh), what);
        return 0;
    }
    GLuint s = gl->CreateShader(type);
    if (!s) {
        hfx_rt_fail(sh->dev, HFX_ERR_GL, "glCreateShader failed");
        return 0;
    }
    sh->dev->gl->spirv.ShaderBinary(1, &s, GL_SHADER_BINARY_FORMAT_SPIR_V, code->data, (GLsizei)code->size);
    sh->dev->gl->spirv.SpecializeShader(s, "main", 0, NULL, NULL);
    GLint ok = 0;
    gl->GetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (ok) return s;
    char log[768] = "";
    gl->GetShaderInfoLog(s, sizeof log, NULL, log);
    hfx_rt_fail(sh->dev, HFX_ERR_GL, "%s: GL refused the %s shader's SPIR-V: %s", name_of(sh), what, log);
    gl->DeleteShader(s);
    return 0;
}

/* An active uniform as the program interface reports it: locations [location, location + size). */
typedef struct active_loc {
    GLint location, size;
    GLenum type;
} active_loc;

typedef struct build {
    hfx_shared *sh;
    hfx_rt_program *p;
    active_loc *active;
    GLint active_count;
    uint32_t upload_cap;
} build;

static int read_active(build *b) {
    const hfx_gl_spirv *s = &b->sh->dev->gl->spirv;
    GLint n = 0;
    s->GetProgramInterfaceiv(b->p->object, GL_UNIFORM, GL_ACTIVE_RESOURCES, &n);
    if (n <= 0) return HFX_OK;
    b->active = calloc((size_t)n, sizeof *b->active);
    if (!b->active) return HFX_ERR_MEMORY;
    static const GLenum props[3] = {GL_LOCATION, GL_TYPE, GL_ARRAY_SIZE};
    for (GLint i = 0; i < n; i++) {
        GLint v[3] = {-1, 0, 0};
        s->GetProgramResourceiv(b->p->object, GL_UNIFORM, (GLuint)i, 3, props, 3, NULL, v);
        if (v[0] < 0) continue; /* in a block, or an atomic counter: not ours */
        b->active[b->active_count++] = (active_loc){v[0], v[2] > 0 ? v[2] : 1, (GLenum)v[1]};
    }
    return HFX_OK;
}

/* The active uniform holding location loc, or NULL (GL dropped it: nothing reads it). */
static const active_loc *find_active(const build *b, uint64_t loc) {
    for (GLint i = 0; i < b->active_count; i++) {
        const active_loc *a = &b->active[i];
        if ((uint64_t)a->location <= loc && loc < (uint64_t)a->location + (uint64_t)a->size) return a;
    }
    return NULL;
}

/* One call for a value or an array of values at location loc (count elements from the
 * parameter's first word). */
static int add_upload(build *b, const hfx_fx_param *p, uint64_t loc, uint32_t count) {
    const active_loc *a = find_active(b, loc);
    if (!a) return HFX_OK;
    hfx_upload up;
    memset(&up, 0, sizeof up);
    uint32_t comps;
    if (!hfx_rt_upload_setup(&b->sh->dev->gl->fn, a->type, p, &up, &comps)) {
        hfx_shared_warn(b->sh, NULL,
                        "SPIR-V uniform at location %llu: its type does not match parameter '%s'; not uploaded",
                        (unsigned long long)loc, p->name ? p->name : "");
        return HFX_OK;
    }
    uint64_t room = (uint64_t)a->location + (uint64_t)a->size - loc;
    up.location = (GLint)loc;
    up.count = (GLsizei)(count < room ? count : room);
    up.offset = p->offset;
    up.words = (uint32_t)up.count * comps;
    return hfx_rt_upload_add(b->sh->dev, b->p, &b->upload_cap, &up);
}

/* A parameter's uploads from location loc on: struct members and the elements of an array of
 * structs one after the other, as common/spirv_loc.c counts them. */
static int add_param(build *b, uint32_t index, uint64_t loc, int depth) {
    const hfx_fx_effect *fx = b->sh->fx;
    if (index >= fx->param_count || depth > 64) return HFX_OK;
    const hfx_fx_param *p = &fx->params[index];
    if (p->klass == HFX_CLASS_OBJECT) return HFX_OK;
    if (p->elements && p->child_count && fx->params[p->first_child].klass == HFX_CLASS_STRUCT) {
        for (uint32_t e = 0; e < p->child_count; e++) {
            int rc = add_param(b, p->first_child + e, loc, depth + 1);
            if (rc) return rc;
            loc += hfx_fx_param_locations(fx, p->first_child + e);
        }
        return HFX_OK;
    }
    if (p->klass == HFX_CLASS_STRUCT) {
        for (uint32_t m = 0; m < p->child_count; m++) {
            int rc = add_param(b, p->first_child + m, loc, depth + 1);
            if (rc) return rc;
            loc += hfx_fx_param_locations(fx, p->first_child + m);
        }
        return HFX_OK;
    }
    return add_upload(b, p, loc, p->elements ? p->elements : 1);
}

static int resolve_uniforms(build *b, const hfx_fx_program *fp) {
    hfx_rt_program *p = b->p;
    const hfx_fx_effect *fx = b->sh->fx;
    uint32_t tops = fx->top_param_count;
    p->slots = calloc((size_t)tops + 1, sizeof *p->slots);
    p->reads = calloc(fp->uniform_count ? fp->uniform_count : 1, sizeof *p->reads);
    if (!p->slots || !p->reads) return HFX_ERR_MEMORY;
    for (uint32_t i = 0; i < fp->uniform_count; i++) {
        uint32_t param = fp->uniforms[i].param;
        if (param >= tops || !fx->params[param].glsl_name) continue;
        hfx_slot *slot = &p->slots[param];
        if (slot->held) continue; /* listed twice */
        if (hfx_fx_use_packed(fp, &fp->uniforms[i])) {
            slot->held = 1;
            hfx_rt_slot_pack(slot, fx, &fp->uniforms[i]);
            p->reads[p->read_count++] = param;
            continue;
        }
        int32_t loc = hfx_fx_spirv_location(fx, fp, fx->params[param].glsl_name);
        if (loc < 0) continue;
        slot->held = 1;
        slot->first = p->upload_count;
        int rc = add_param(b, param, (uint64_t)loc, 0);
        if (rc) return rc;
        slot->count = p->upload_count - slot->first;
        if (slot->count) p->reads[p->read_count++] = param;
    }
    return HFX_OK;
}

/* hfx_c[i] sits at hfx_c[0]'s location + i, as SPIR-V's explicit locations lay out arrays. */
typedef struct reg_ctx { const build *b; uint64_t first; } reg_ctx;

static GLint spirv_reg_location(void *ctx, uint32_t i) {
    const reg_ctx *r = ctx;
    uint64_t loc = r->first + i;
    return loc <= INT32_MAX && find_active(r->b, loc) ? (GLint)loc : -1;
}

/* hfx_pos_fixup, hfx_alpha_func, hfx_alpha_ref: at their places after the samplers, when active. */
static GLint known_location(const build *b, const hfx_fx_program *fp, const char *name) {
    int32_t loc = hfx_fx_spirv_location(b->sh->fx, fp, name);
    return loc >= 0 && find_active(b, (uint64_t)loc) ? loc : -1;
}

int hfx_rt_spirv_program_build(hfx_shared *sh, uint32_t index) {
    const hfx_fx_program *fp = &sh->fx->programs[index];
    hfx_rt_program *p = &sh->gl->programs[index];
    if (!sh->dev->gl->spirv.ok) return hfx_rt_spirv_check(sh->dev, sh->fx);
    const hfx_fx_code *vcode = &fp->code[HFX_STAGE_VERTEX][HFX_TARGET_SPIRV];
    const hfx_fx_code *fcode = &fp->code[HFX_STAGE_FRAGMENT][HFX_TARGET_SPIRV];
    GLuint vs = specialize_stage(sh, GL_VERTEX_SHADER, vcode, "vertex");
    GLuint fs = vs ? specialize_stage(sh, GL_FRAGMENT_SHADER, fcode, "fragment") : 0;
    int rc = vs && fs ? hfx_rt_program_link(sh, p, NULL, vs, fs) : HFX_ERR_GL;
    if (vs) sh->dev->gl->fn.DeleteShader(vs);
    if (fs) sh->dev->gl->fn.DeleteShader(fs);
    if (rc) return rc;
    build b = {sh, p, NULL, 0, 0};
    rc = read_active(&b);
    if (!rc) rc = resolve_uniforms(&b, fp);
    reg_ctx regs = {&b, hfx_fx_spirv_regs_location(sh->fx, fp)};
    if (!rc) rc = hfx_rt_regs_setup(sh->dev, p, fp->reg_count, spirv_reg_location, &regs);
    if (!rc) rc = hfx_rt_preshaders_setup(p, sh->fx, fp);
    if (!rc) {
        p->pos_fixup_loc = known_location(&b, fp, "hfx_pos_fixup");
        memset(p->pos_fixup, 0, sizeof p->pos_fixup); /* GL's value for an unset uniform */
        p->pos_fixup_serial = 0;                      /* the device's starts at 1: compare once */
        p->alpha_func_loc = known_location(&b, fp, "hfx_alpha_func");
        p->alpha_ref_loc = known_location(&b, fp, "hfx_alpha_ref");
        p->alpha_func = -1;
        p->alpha_ref = -1.0f;
        hfx_rt_program_ready(p, sh->fx->top_param_count);
    }
    free(b.active);
    return rc == HFX_ERR_MEMORY ? hfx_rt_fail(sh->dev, rc, "out of memory") : rc;
}
