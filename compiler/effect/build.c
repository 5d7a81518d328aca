/* build.c: the checked tree becomes the compiled effect (effect.h). This file lays out the
 * parameters (top level in declaration order, then each one's children as a contiguous block),
 * their values and annotations; build_states.c does samplers, techniques, passes and programs;
 * build_values.c evaluates constants. Everything it makes is malloc'ed, so the effect outlives
 * the compilation's arena. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "effect/build_int.h"
#include "glsl/glslang.h"
#include "glsl/spirv.h"

bool hfx_build_grow(hfx_builder *b, void **arr, size_t elem, uint32_t count, uint32_t *cap) {
    if (hfx_grow(arr, elem, count, cap, 8, NULL, NULL)) return true;
    b->failed_alloc = true;
    return false;
}

char *hfx_build_strdup(hfx_builder *b, const char *s) {
    if (!s) return NULL;
    char *d = strdup(s);
    if (!d) b->failed_alloc = true;
    return d;
}

/* --- parameter classes and types, as XNA reflects them ------------------------------------ */

static hfx_param_type numeric_type(hfx_base base) {
    switch (base) {
    case B_BOOL: return HFX_TYPE_BOOL;
    case B_INT: case B_UINT: return HFX_TYPE_INT;
    default: return HFX_TYPE_FLOAT;
    }
}

static hfx_param_type object_type(const hfx_type *ty) {
    static const hfx_param_type textures[] = {HFX_TYPE_TEXTURE, HFX_TYPE_TEXTURE1D, HFX_TYPE_TEXTURE2D,
                                              HFX_TYPE_TEXTURE3D, HFX_TYPE_TEXTURECUBE};
    static const hfx_param_type samplers[] = {HFX_TYPE_SAMPLER, HFX_TYPE_SAMPLER1D, HFX_TYPE_SAMPLER2D,
                                              HFX_TYPE_SAMPLER3D, HFX_TYPE_SAMPLERCUBE};
    unsigned d = ty->dim <= DIM_CUBE ? (unsigned)ty->dim : 0;
    switch (ty->kind) {
    case TY_TEXTURE: return textures[d];
    case TY_SAMPLER: return samplers[d];
    case TY_STRING: return HFX_TYPE_STRING;
    case TY_VERTEXSHADER: return HFX_TYPE_VERTEXSHADER;
    case TY_PIXELSHADER: return HFX_TYPE_PIXELSHADER;
    default: return HFX_TYPE_VOID;
    }
}

/* Class, type, rows and columns of a non-array type. Objects and structs are 0x0. */
static void describe_type(const hfx_type *ty, hfx_fx_param *p) {
    p->rows = p->cols = 0;
    switch (ty->kind) {
    case TY_SCALAR: case TY_VECTOR: case TY_MATRIX:
        p->klass = ty->kind == TY_SCALAR ? HFX_CLASS_SCALAR : ty->kind == TY_VECTOR ? HFX_CLASS_VECTOR : HFX_CLASS_MATRIX;
        p->type = numeric_type(ty->base);
        p->rows = ty->rows;
        p->cols = ty->cols;
        break;
    case TY_STRUCT:
        p->klass = HFX_CLASS_STRUCT;
        p->type = HFX_TYPE_VOID;
        break;
    default:
        p->klass = HFX_CLASS_OBJECT;
        p->type = object_type(ty);
        break;
    }
}

const hfx_type *hfx_build_innermost(const hfx_type *ty, uint32_t *elements) {
    uint32_t n = 1;
    bool array = false;
    while (ty && ty->kind == TY_ARRAY && ty->elem) {
        n *= ty->array_len;
        ty = ty->elem;
        array = true;
    }
    if (elements) *elements = array ? n : 0;
    return ty;
}

/* Words and parameters a type needs, saturating far above any limit instead of wrapping. */
static uint64_t type_words64(const hfx_type *ty, uint64_t *params) {
    uint64_t n = 0;
    switch (ty->kind) {
    case TY_SCALAR: case TY_VECTOR: case TY_MATRIX: return (uint64_t)ty->rows * ty->cols;
    case TY_ARRAY:
        if (!ty->elem) return 0;
        n = type_words64(ty->elem, params);
        if (params) *params = *params * (ty->array_len ? ty->array_len : 1) + ty->array_len;
        n *= ty->array_len;
        break;
    case TY_STRUCT:
        for (uint32_t i = 0; ty->st && i < ty->st->field_count; i++) {
            uint64_t sub = 0;
            n += type_words64(ty->st->fields[i].type, params ? &sub : NULL);
            if (params) *params += sub + 1;
        }
        break;
    default: return 0;
    }
    if (params && *params > (1ull << 40)) *params = 1ull << 40;
    return n > (1ull << 40) ? 1ull << 40 : n;
}

uint32_t hfx_build_type_words(const hfx_type *ty) {
    uint64_t n = type_words64(ty, NULL);
    return n > UINT32_MAX ? UINT32_MAX : (uint32_t)n;
}

/* D3D9 has 256 float4 constants per shader; an effect parameter far beyond that is a mistake
 * (and would make the effect's tables huge). */
enum { MAX_PARAM_WORDS = 1u << 20, MAX_PARAM_CHILDREN = 1u << 16 };

static bool param_fits(hfx_builder *b, const hfx_decl *d) {
    uint64_t params = 0, words = type_words64(d->type, &params);
    if (words <= MAX_PARAM_WORDS && params <= MAX_PARAM_CHILDREN) return true;
    hfx_error(b->diags, d->loc, X_UNSUPPORTED, "'%s': parameter too large (%llu values, %llu elements and members)",
              d->name, (unsigned long long)words, (unsigned long long)params);
    return false;
}

/* --- parameters -------------------------------------------------------------------------- */

static bool is_parameter(const hfx_decl *d) {
    return d->kind == DECL_VAR && d->is_global && !(d->mods & MOD_STATIC) && d->type && d->type->kind != TY_VOID &&
           d->type->kind != TY_FUNCTION;
}

/* Where a top-level parameter is declared, for the runtime's reports (effect pools). */
static void declared_at(hfx_builder *b, hfx_fx_param *p, hfx_loc loc) {
    const hfx_diags *d = b->diags;
    p->file = loc.file < d->file_count ? hfx_build_strdup(b, d->files[loc.file].name) : NULL;
    p->line = loc.line;
    p->col = loc.col;
}

static uint32_t add_param(hfx_builder *b, const char *name, const char *semantic, const hfx_type *ty,
                          uint32_t parent, uint32_t offset) {
    hfx_fx_effect *fx = b->fx;
    /* three arrays, three capacities: a failure between growths cannot leave one short */
    if (!HFX_ARENA_GROW(b->arena, b->param_types, fx->param_count, b->param_type_cap, 8) ||
        !HFX_ARENA_GROW(b->arena, b->param_decls, fx->param_count, b->param_decl_cap, 8) ||
        !HFX_BUILD_GROW(b, fx->params, fx->param_count, b->param_cap)) {
        b->failed_alloc = true;
        return HFX_NONE;
    }
    uint32_t i = fx->param_count++;
    hfx_fx_param *p = &fx->params[i];
    memset(p, 0, sizeof *p);
    p->name = hfx_build_strdup(b, name ? name : "");
    p->semantic = hfx_build_strdup(b, semantic);
    const hfx_type *inner = hfx_build_innermost(ty, &p->elements);
    describe_type(inner, p);
    p->parent = parent;
    p->first_child = 0; /* empty ranges start at 0, so first + count stays inside every array */
    p->offset = offset;
    p->words = hfx_build_type_words(ty);
    p->first_annotation = 0;
    p->sampler = HFX_NONE;
    b->param_types[i] = ty;
    b->param_decls[i] = NULL;
    return i;
}

/* A GLSL name for params the shaders can read: numerics and samplers (not textures, strings, shaders). */
static char *glsl_name_for(hfx_builder *b, const char *name, const hfx_type *ty) {
    const hfx_type *inner = hfx_build_innermost(ty, NULL);
    if (inner->kind == TY_TEXTURE || inner->kind == TY_STRING || inner->kind == TY_VERTEXSHADER ||
        inner->kind == TY_PIXELSHADER)
        return NULL;
    return hfx_build_strdup(b, hfx_glsl_name(b->arena, name));
}

/* Appends param i's children (array elements, or struct members) as one contiguous block. */
static void add_children(hfx_builder *b, uint32_t i) {
    const hfx_type *ty = b->param_types[i];
    uint32_t offset = b->fx->params[i].offset, first = b->fx->param_count, count = 0;
    if (ty->kind == TY_ARRAY) {
        uint32_t elements;
        const hfx_type *elem = hfx_build_innermost(ty, &elements);
        uint32_t words = hfx_build_type_words(elem);
        for (uint32_t e = 0; e < elements; e++, count++) {
            /* Elements carry the array's name and semantic (its name is what users search for). */
            uint32_t c = add_param(b, b->fx->params[i].name, b->fx->params[i].semantic, elem, i, offset + e * words);
            if (c == HFX_NONE) return;
        }
    } else if (ty->kind == TY_STRUCT && ty->st) {
        for (uint32_t f = 0; f < ty->st->field_count; f++, count++) {
            const hfx_field *fd = &ty->st->fields[f];
            uint32_t c = add_param(b, fd->name, fd->semantic, fd->type, i, offset);
            if (c == HFX_NONE) return;
            b->fx->params[c].glsl_name = glsl_name_for(b, fd->name, fd->type);
            offset += hfx_build_type_words(fd->type);
        }
    }
    b->fx->params[i].first_child = count ? first : 0;
    b->fx->params[i].child_count = count;
}

/* Evaluates a parameter's initializer into its value words. */
static void store_default(hfx_builder *b, const hfx_decl *d, const hfx_fx_param *p) {
    if (!d->init || !p->words) return;
    if (d->init->kind == EX_SAMPLER_STATE) return;
    hfx_cvec c = {0};
    if (hfx_build_eval(b, d->init, &c, NULL))
        hfx_build_store(d->type, &c, b->fx->values + p->offset);
    else
        hfx_error(b->diags, d->init->loc, X_NOT_LITERAL, "'%s': initial value must be a literal expression", d->name);
    hfx_cvec_free(&c);
}

static void store_string(hfx_builder *b, const hfx_decl *d, hfx_fx_param *p) {
    if (d->type->kind == TY_STRING && d->init && d->init->kind == EX_STRING)
        p->string = hfx_build_strdup(b, d->init->sval ? d->init->sval : "");
}

static bool build_params(hfx_builder *b) {
    hfx_fx_effect *fx = b->fx;
    uint32_t offset = 0;
    for (uint32_t i = 0; i < b->ast->decl_count; i++) {
        hfx_decl *d = b->ast->decls[i];
        if (d->kind != DECL_VAR || !d->is_global) continue;
        if (!is_parameter(d)) {
            d->index = HFX_NONE;
            continue;
        }
        if (!param_fits(b, d)) {
            d->index = HFX_NONE;
            continue;
        }
        uint32_t p = add_param(b, d->name, d->semantic, d->type, HFX_NONE, offset);
        if (p == HFX_NONE) return false;
        d->index = p;
        b->param_decls[p] = d;
        fx->params[p].glsl_name = glsl_name_for(b, d->name, d->type);
        declared_at(b, &fx->params[p], d->loc);
        if (d->mods & MOD_SHARED) fx->params[p].flags |= HFX_FX_PARAM_SHARED;
        if (d->mods & MOD_ROW_MAJOR) fx->params[p].flags |= HFX_FX_PARAM_ROW_MAJOR;
        if (d->mods & MOD_COLUMN_MAJOR) fx->params[p].flags |= HFX_FX_PARAM_COLUMN_MAJOR;
        offset += fx->params[p].words;
    }
    fx->top_param_count = fx->param_count;
    /* Breadth first: children of params made earlier are appended after them. */
    for (uint32_t i = 0; i < fx->param_count && !b->failed_alloc; i++) add_children(b, i);
    if (b->failed_alloc) return false;
    fx->value_words = offset;
    fx->values = calloc(offset ? offset : 1, sizeof *fx->values);
    if (!fx->values) return !(b->failed_alloc = true);
    for (uint32_t i = 0; i < fx->top_param_count; i++) {
        hfx_decl *d = b->param_decls[i];
        store_default(b, d, &fx->params[i]);
        store_string(b, d, &fx->params[i]);
        fx->params[i].annotation_count =
            hfx_build_annotations(b, d->annotations, d->annotation_count, &fx->params[i].first_annotation);
    }
    return !b->failed_alloc;
}

uint32_t hfx_build_param_of(hfx_builder *b, const hfx_expr *e) {
    if (!e) return HFX_NONE;
    if (e->kind == EX_INDEX && e->arg_count == 2) { /* `Sampler[0] = (samplers[1])`: the element */
        uint32_t p = hfx_build_param_of(b, e->args[0]);
        hfx_cvec c = {0};
        bool constant = p != HFX_NONE && hfx_build_eval(b, e->args[1], &c, NULL) && c.integral;
        uint32_t i = constant && c.v[0] >= 0 && c.v[0] < b->fx->params[p].elements ? hfx_ev_uint(c.v[0]) : HFX_NONE;
        hfx_cvec_free(&c);
        return i == HFX_NONE ? HFX_NONE : b->fx->params[p].first_child + i;
    }
    if (e->kind == EX_IDENT && e->sym) {
        const hfx_decl *d = e->sym;
        if (d->kind == DECL_VAR && d->is_global && is_parameter(d) && d->index < b->fx->top_param_count &&
            b->param_decls[d->index] == d)
            return d->index;
        return HFX_NONE;
    }
    if ((e->kind == EX_IDENT || e->kind == EX_STATE_REF) && e->name) return hfx_fx_param_find(b->fx, e->name);
    return HFX_NONE;
}

hfx_decl *hfx_build_global(hfx_builder *b, const char *name) {
    if (!name) return NULL;
    for (uint32_t i = 0; i < b->ast->decl_count; i++) {
        hfx_decl *d = b->ast->decls[i];
        if (d->kind == DECL_VAR && d->is_global && d->name && strcmp(d->name, name) == 0) return d;
    }
    return NULL;
}

/* --- annotations ------------------------------------------------------------------------- */

static bool build_annotation(hfx_builder *b, const hfx_annotation_ast *a, hfx_fx_annotation *out) {
    const hfx_type *ty = a->type;
    out->name = hfx_build_strdup(b, a->name ? a->name : "");
    if (!ty || !a->value) return false;
    if (ty->kind == TY_STRING) {
        if (a->value->kind != EX_STRING) {
            hfx_error(b->diags, a->value->loc, X_TYPE_MISMATCH, "'%s': annotation value must be a string", a->name);
            return false;
        }
        out->type = HFX_TYPE_STRING;
        out->klass = HFX_CLASS_OBJECT;
        out->string = hfx_build_strdup(b, a->value->sval ? a->value->sval : "");
        return true;
    }
    if (!hfx_type_is_numeric(ty)) {
        hfx_warning(b->diags, a->loc, X_UNSUPPORTED, "'%s': annotations of type %s are ignored", a->name,
                    hfx_type_name(b->arena, ty));
        return false;
    }
    out->type = numeric_type(ty->base);
    out->klass = ty->kind == TY_SCALAR ? HFX_CLASS_SCALAR : ty->kind == TY_VECTOR ? HFX_CLASS_VECTOR : HFX_CLASS_MATRIX;
    out->rows = ty->rows;
    out->cols = ty->cols;
    out->count = (uint32_t)ty->rows * ty->cols;
    out->data = calloc(out->count, sizeof *out->data);
    if (!out->data) {
        b->failed_alloc = true;
        return false;
    }
    hfx_cvec c = {0};
    bool ok = hfx_build_eval(b, a->value, &c, NULL);
    if (ok)
        hfx_build_store(ty, &c, out->data);
    else
        hfx_error(b->diags, a->value->loc, X_NOT_LITERAL, "'%s': annotation value must be a literal expression",
                  a->name);
    hfx_cvec_free(&c);
    return ok;
}

uint32_t hfx_build_annotations(hfx_builder *b, const hfx_annotation_ast *list, uint32_t count, uint32_t *first) {
    hfx_fx_effect *fx = b->fx;
    *first = count ? fx->annotation_count : 0;
    uint32_t added = 0;
    for (uint32_t i = 0; i < count; i++) {
        if (!HFX_BUILD_GROW(b, fx->annotations, fx->annotation_count, b->annotation_cap)) break;
        hfx_fx_annotation *a = &fx->annotations[fx->annotation_count];
        memset(a, 0, sizeof *a);
        fx->annotation_count++;
        if (!build_annotation(b, &list[i], a)) {
            free(a->name);
            free(a->data);
            free(a->string);
            fx->annotation_count--;
            continue;
        }
        added++;
    }
    if (!added) *first = 0;
    return added;
}

/* --- the driver -------------------------------------------------------------------------- */

/* If an allocation failure escapes the build (base/arena.h), everything malloc'ed so far. */
static void builder_abandon(void *ctx) {
    hfx_builder *b = ctx;
    hfx_fx_program_clear(&b->pending);
    hfx_fx_effect_free(b->fx);
}

static hfx_fx_effect *out_of_memory(hfx_diags *diags) {
    hfx_error(diags, (hfx_loc){0, 1, 1}, X_MEMORY_LIMIT, "out of memory building the effect");
    return NULL;
}

/* The builder lives in the arena, so that builder_abandon can still reach it after an escape. */
static hfx_builder *builder_start(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                                  const char *source_name, unsigned targets) {
    hfx_builder *b = HFX_NEW(arena, hfx_builder);
    if (!b || !(b->cleanup = hfx_arena_on_escape(arena, builder_abandon, b))) return NULL;
    b->arena = arena;
    b->diags = diags;
    b->types = types;
    b->ast = ast;
    b->targets = hfx_build_code_targets(targets); /* SPIR-V is made from GLSL 330 */
    b->fx = ast ? calloc(1, sizeof *b->fx) : NULL;
    if (!b->fx) {
        hfx_arena_forget(arena, b->cleanup);
        return NULL;
    }
    b->fx->source_name = hfx_build_strdup(b, source_name ? source_name : "");
    b->fx->targets = targets;
    return b;
}

/* The targets every program has code for (what was asked for when there is no program). */
static unsigned present_targets(const hfx_fx_effect *fx) {
    unsigned all = fx->targets;
    for (uint32_t i = 0; i < fx->program_count; i++) {
        unsigned here = 0;
        for (int t = 0; t < HFX_TARGET_COUNT; t++)
            for (int s = 0; s < HFX_STAGE_COUNT; s++)
                if (fx->programs[i].code[s][t].data) here |= 1u << t;
        all &= here;
    }
    return all;
}

/* A name for program i in messages: its first pass, as technique.pass. */
static void program_name(const hfx_fx_effect *fx, uint32_t i, char *out, size_t size) {
    snprintf(out, size, "program %u", i);
    for (uint32_t t = 0; t < fx->technique_count; t++)
        for (uint32_t p = 0; p < fx->techniques[t].pass_count; p++) {
            const hfx_fx_pass *pass = &fx->passes[fx->techniques[t].first_pass + p];
            if (pass->program == i) {
                snprintf(out, size, "%s.%s", fx->techniques[t].name, pass->name);
                return;
            }
        }
}

/* A uniform holding a bool inside (a struct with bool members) stays bool in the SPIR-V, which
 * strict validators reject: worth a warning, once per name. */
static void warn_bool_uniforms(hfx_diags *diags, hfx_loc at, const hfx_fx_program *p) {
    char names[2][128] = {"", ""};
    for (int s = 0; s < HFX_STAGE_COUNT; s++) {
        const hfx_fx_code *c = &p->code[s][HFX_TARGET_SPIRV];
        if (!c->data || hfx_spirv_bool_uniform((const uint32_t *)(const void *)c->data, c->size / 4, names[s],
                                               sizeof names[s]) != 1)
            continue;
        if (s == 1 && strcmp(names[0], names[1]) == 0) continue;
        hfx_warning(diags, at, X_UNSUPPORTED,
                    "'%s': a uniform with bool members stays bool in SPIR-V, which spirv-val rejects", names[s]);
    }
}

/* One SPIR-V target for every program (spirv.c), each failure an error at the program. */
static void build_spirv_target(hfx_diags *diags, hfx_loc at, hfx_fx_effect *fx, int target) {
    for (uint32_t i = 0; i < fx->program_count; i++) {
        char *log = NULL;
        int rc = target == HFX_TARGET_SPIRV_VK ? hfx_spirv_vk_program(fx, &fx->programs[i], &log)
                                               : hfx_spirv_program(fx, &fx->programs[i], &log);
        if (rc != 0) {
            char name[256];
            program_name(fx, i, name, sizeof name);
            hfx_error(diags, at, X_UNSUPPORTED, "'%s': SPIR-V generation failed: %s", name,
                      log ? log : "glslang gave no reason");
        }
        free(log);
        if (target == HFX_TARGET_SPIRV) warn_bool_uniforms(diags, at, &fx->programs[i]);
    }
}

/* The GLSL the printer left in the SPIR-V targets' code (codegen.c) when no words are made of it. */
static void drop_spirv_text(hfx_fx_effect *fx) {
    for (uint32_t i = 0; i < fx->program_count; i++)
        for (int s = 0; s < HFX_STAGE_COUNT; s++)
            for (int t = HFX_TARGET_SPIRV; t <= HFX_TARGET_SPIRV_VK; t++) {
                free(fx->programs[i].code[s][t].data);
                fx->programs[i].code[s][t].data = NULL;
                fx->programs[i].code[s][t].size = 0;
            }
}

unsigned hfx_build_code_targets(unsigned requested) {
    return requested & (3u << HFX_TARGET_SPIRV) ? requested | 1u << HFX_TARGET_GLSL330 : requested;
}

/* HFX_TARGET_SPIRV and HFX_TARGET_SPIRV_VK: every program's GLSL 330 through glslang (spirv.c);
 * the GLSL 330 goes again unless it was asked for too. Without glslang nothing is made (hfxc
 * says so). */
void hfx_build_spirv(hfx_diags *diags, hfx_loc at, hfx_fx_effect *fx, unsigned requested) {
    if ((requested & (3u << HFX_TARGET_SPIRV)) && fx->program_count && hfx_spirv_available()) {
        if (!hfx_spirv_begin()) {
            hfx_error(diags, at, X_UNSUPPORTED, "SPIR-V: glslang could not start");
            drop_spirv_text(fx);
        } else {
            for (int t = HFX_TARGET_SPIRV; t <= HFX_TARGET_SPIRV_VK; t++)
                if (requested & (1u << t)) build_spirv_target(diags, at, fx, t);
            hfx_spirv_end();
        }
    } else {
        drop_spirv_text(fx);
    }
    if (!(requested & (1u << HFX_TARGET_GLSL330)))
        for (uint32_t i = 0; i < fx->program_count; i++)
            for (int s = 0; s < HFX_STAGE_COUNT; s++) {
                free(fx->programs[i].code[s][HFX_TARGET_GLSL330].data);
                fx->programs[i].code[s][HFX_TARGET_GLSL330].data = NULL;
                fx->programs[i].code[s][HFX_TARGET_GLSL330].size = 0;
            }
}

static const char *const target_names[HFX_TARGET_COUNT] = {"GLSL 330", "GLSL ES 300", "GLSL 110", "SPIR-V",
                                                                   "SPIR-V for Vulkan"};

/* glslang's first error line, for a one-line diagnostic. */
static void first_error(const char *log, char *out, size_t size) {
    const char *e = log ? strstr(log, "ERROR:") : NULL;
    if (!e) e = log ? log : "glslang gave no reason";
    size_t n = strcspn(e, "\n");
    snprintf(out, size, "%.*s", (int)(n < size ? n : size - 1), e);
}

/* One program's shaders of every GLSL target through glslang: a rejection is hfx's own bug,
 * reported at the entry point that was compiled, never handed to a driver. */
static void self_check_program(hfx_builder *b, uint32_t i) {
    const hfx_fx_program *p = &b->fx->programs[i];
    for (int s = 0; s < HFX_STAGE_COUNT; s++)
        for (int t = 0; t < HFX_TARGET_SPIRV; t++) {
            char *log = NULL, why[400], name[256];
            if (!p->code[s][t].data || hfx_glslang_check(p->code[s][t].data, s, (hfx_target)t, &log) == 0) continue;
            const hfx_expr *at = s == 0 ? b->keys[i].vs : b->keys[i].ps;
            first_error(log, why, sizeof why);
            program_name(b->fx, i, name, sizeof name);
            hfx_error(b->diags, at ? at->loc : (hfx_loc){0, 1, 1}, X_INTERNAL,
                      "internal: the %s %s shader hfx made for '%s' does not compile: %s", target_names[t],
                      s == 0 ? "vertex" : "pixel", name, why);
            free(log);
        }
}

/* The self-check (on unless HFXC_NO_SELF_CHECK): every emitted GLSL shader parsed by glslang. */
static void self_check(hfx_builder *b) {
    if ((b->diags->flags & HFXC_NO_SELF_CHECK) || !b->fx->program_count || !hfx_glslang_available()) return;
    if (!hfx_glslang_begin()) {
        hfx_error(b->diags, (hfx_loc){0, 1, 1}, X_INTERNAL, "internal: glslang could not start for the self-check");
        return;
    }
    for (uint32_t i = 0; i < b->fx->program_count; i++) self_check_program(b, i);
    hfx_glslang_end();
}

/* Hands the effect over, or frees it when anything went wrong since `errors`. */
static hfx_fx_effect *builder_finish(hfx_builder *b, bool ok, uint32_t errors) {
    hfx_arena_forget(b->arena, b->cleanup);
    /* glslang's work holds its own memory and process state: failures return NULL here */
    hfx_arena_escape_off(b->arena);
    if (ok && !b->failed_alloc && b->diags->errors == errors) self_check(b);
    if (ok && !b->failed_alloc && b->diags->errors == errors)
        hfx_build_spirv(b->diags, (hfx_loc){0, 1, 1}, b->fx, b->fx->targets);
    else drop_spirv_text(b->fx);
    hfx_arena_escape_on(b->arena);
    b->fx->targets = present_targets(b->fx);
    if (b->failed_alloc) hfx_error(b->diags, (hfx_loc){0, 1, 1}, X_MEMORY_LIMIT, "out of memory building the effect");
    if (!ok || b->failed_alloc || b->diags->errors > errors) {
        hfx_fx_effect_free(b->fx);
        return NULL;
    }
    return b->fx;
}

hfx_fx_effect *hfx_build_effect(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                                const char *source_name, unsigned targets) {
    uint32_t errors = diags->errors;
    hfx_builder *b = builder_start(arena, diags, types, ast, source_name, targets);
    if (!b) return out_of_memory(diags);
    bool ok = build_params(b) && hfx_build_samplers(b) && hfx_build_techniques(b);
    return builder_finish(b, ok, errors);
}

static hfx_decl *find_function(hfx_ast *ast, const char *name) {
    hfx_decl *found = NULL;
    for (uint32_t i = 0; i < ast->decl_count; i++) {
        hfx_decl *d = ast->decls[i];
        if (d->kind == DECL_FUNC && d->func && d->name && strcmp(d->name, name) == 0 && (!found || d->func->body))
            found = d;
    }
    return found;
}

/* A technique as if the source ended with `technique entry { pass p0 { XShader = compile profile entry(); } }`. */
static hfx_technique_ast *entry_technique(hfx_builder *b, const char *entry, const char *profile) {
    hfx_decl *fn = find_function(b->ast, entry);
    if (!fn) {
        hfx_error(b->diags, (hfx_loc){0, 1, 1}, X_NO_ENTRY, "'%s': entrypoint not found", entry);
        return NULL;
    }
    bool pixel = profile[0] == 'p' || profile[0] == 'P';
    hfx_expr *c = HFX_NEW(b->arena, hfx_expr);
    hfx_technique_ast *t = HFX_NEW(b->arena, hfx_technique_ast);
    hfx_pass_ast *p = HFX_NEW(b->arena, hfx_pass_ast);
    hfx_state_assign *sa = HFX_NEW(b->arena, hfx_state_assign);
    if (!c || !t || !p || !sa) {
        b->failed_alloc = true;
        return NULL;
    }
    c->kind = EX_COMPILE;
    c->loc = fn->loc;
    c->name = entry;
    c->profile = profile;
    c->intrinsic = -1;
    c->fn = fn->func->definition ? fn->func->definition : fn->func;
    sa->name = pixel ? "PixelShader" : "VertexShader";
    sa->value = c;
    sa->loc = fn->loc;
    p->name = "p0";
    p->states = sa;
    p->state_count = 1;
    p->loc = fn->loc;
    t->name = entry;
    t->keyword = "technique";
    t->passes = p;
    t->pass_count = 1;
    return t;
}

static bool shader_profile(const char *profile) {
    return profile && (profile[0] == 'v' || profile[0] == 'p') && profile[1] == 's' && profile[2] == '_';
}

hfx_fx_effect *hfx_build_entry_effect(hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_ast *ast,
                                      const char *source_name, unsigned targets, const char *entry,
                                      const char *profile) {
    if (!profile) profile = "ps_3_0";
    if (!shader_profile(profile)) {
        hfx_error(diags, (hfx_loc){0, 1, 1}, X_SYNTAX, "invalid profile '%s' for entry point '%s'", profile,
                  entry ? entry : "");
        return NULL;
    }
    uint32_t errors = diags->errors;
    hfx_builder *b = builder_start(arena, diags, types, ast, source_name, targets);
    if (!b) return out_of_memory(diags);
    bool ok = build_params(b) && hfx_build_samplers(b);
    hfx_technique_ast *t = ok && entry ? entry_technique(b, entry, profile) : NULL;
    if (t) hfx_build_technique(b, t);
    return builder_finish(b, ok && t, errors);
}
