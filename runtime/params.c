/* params.c: Parameters, as XNA's EffectParameter: values live on the CPU; a set checks the
 * class, type and count (XNA throws InvalidCastException, hfx returns HFX_ERR_TYPE /
 * HFX_ERR_COUNT and changes nothing), then gives the top-level parameter a new version when
 * the value really changed, which is what Apply compares. */
#include <string.h>
#include <strings.h>

#include "eval.h"
#include "internal.h"

static const hfx_fx_param *info(const hfx_param *p) { return p->info; }
static hfx_device *dev_of(const hfx_param *p) { return p->fx->dev; }

static int fail(const hfx_param *p, int code, const char *what) {
    const hfx_fx_param *i = info(p);
    return hfx_rt_fail(dev_of(p), code, "parameter '%s': %s", i->name ? i->name : "", what);
}

void hfx_rt_param_changed(hfx_effect *fx, uint32_t root) {
    uint32_t tops = fx->sh->fx->top_param_count;
    hfx_rt_mark_changed(fx, root < tops ? root : tops);
}

/* Out of line, so the common sizes' path keeps no registers across a call. */
static __attribute__((noinline)) int copy_changed_long(uint32_t *dst, const void *src, size_t n) {
    const uint32_t *w = src;
    size_t k = 0;
    while (k < n && dst[k] == w[k]) k++;
    if (k == n) return 0;
    memcpy(dst + k, w + k, (n - k) * sizeof *dst);
    return 1;
}

/* Copies n words over dst; 1 when something changed (bitwise, as GL would see it). The common
 * sizes compare and copy with fixed-size code. */
static inline int copy_changed(uint32_t *dst, const void *src, size_t n) {
    if (n == 4) { /* float4 first, then the 4x4 matrix */
        if (memcmp(dst, src, 16) == 0) return 0;
        memcpy(dst, src, 16);
        return 1;
    }
    if (n == 16) {
        if (memcmp(dst, src, 64) == 0) return 0;
        memcpy(dst, src, 64);
        return 1;
    }
    switch (n) {
    case 1: {
        uint32_t w;
        memcpy(&w, src, sizeof w);
        if (*dst == w) return 0;
        *dst = w;
        return 1;
    }
#define FIXED_(words) case words: if (memcmp(dst, src, words * 4) == 0) return 0; memcpy(dst, src, words * 4); return 1;
    FIXED_(2) FIXED_(3) FIXED_(9) FIXED_(12)
#undef FIXED_
    default: return copy_changed_long(dst, src, n);
    }
}

/* A new version of p's value; in a pool, a shared parameter's other copies take it too. */
static inline void changed(hfx_param *p) {
    hfx_rt_mark_changed(p->fx, p->root);
    if (p->fx->pool) hfx_rt_pool_share(p->fx, p->root);
}

/* Writes words into the value buffer; a new version only when something changed. */
static inline int store(hfx_param *p, uint32_t offset, const void *words, size_t n) {
    if (copy_changed(p->value + offset, words, n)) changed(p);
    return HFX_OK;
}

static int is_numeric(const hfx_fx_param *i) {
    return i->klass == HFX_CLASS_SCALAR || i->klass == HFX_CLASS_VECTOR || i->klass == HFX_CLASS_MATRIX;
}

static int is_texture_like(const hfx_fx_param *i) {
    return (i->type >= HFX_TYPE_TEXTURE && i->type <= HFX_TYPE_SAMPLERCUBE) && !i->elements;
}

/* Arrays take a whole number of elements, up to their length (XNA sets a prefix of an
 * array, e.g. fewer bones than the shader holds); everything else takes exactly its size. */
static int count_ok(const hfx_fx_param *i, size_t count) {
    if (i->elements) {
        uint32_t elem = i->words / i->elements;
        return !(count == 0 || count > i->words || (elem && count % elem));
    }
    return count == i->words;
}

/* What the set functions accept, so their common case is one mask test and one compare. */
uint32_t hfx_rt_param_accept(const hfx_fx_param *i) {
    uint32_t a = 0;
    if (i->klass == HFX_CLASS_SCALAR && !i->elements) {
        if (i->type == HFX_TYPE_BOOL) a |= ACC_BOOL;
        if (i->type == HFX_TYPE_INT) a |= ACC_INT;
        if (i->type == HFX_TYPE_FLOAT) a |= ACC_FLOAT;
    }
    if (is_numeric(i)) {
        if (i->type == HFX_TYPE_FLOAT) a |= ACC_FLOATS;
        if (i->type == HFX_TYPE_INT || i->type == HFX_TYPE_BOOL) a |= ACC_INTS;
        if (i->type == HFX_TYPE_INT) a |= ACC_RAW_INTS;
    }
    if (i->type == HFX_TYPE_FLOAT && i->klass == HFX_CLASS_MATRIX && !i->elements && i->rows <= 4 && i->cols <= 4)
        a |= ACC_MATRIX;
    if (is_texture_like(i)) a |= ACC_TEXTURE;
    if (count_ok(i, i->words)) a |= ACC_WHOLE;
    return a;
}

static int check_scalar(const hfx_param *p, hfx_param_type type, const char *want) {
    const hfx_fx_param *i = info(p);
    if (i->type != type || i->klass != HFX_CLASS_SCALAR || i->elements) return fail(p, HFX_ERR_TYPE, want);
    return HFX_OK;
}

static inline int check_count(const hfx_param *p, size_t count) {
    return count_ok(info(p), count) ? HFX_OK : fail(p, HFX_ERR_COUNT, "wrong number of values");
}

int hfx_param_set_bool(hfx_param *p, int v) {
    if (!p) return HFX_ERR_NULL;
    if (!(p->accept & ACC_BOOL)) return check_scalar(p, HFX_TYPE_BOOL, "not a bool");
    int32_t w = v != 0;
    return store(p, 0, &w, 1);
}

int hfx_param_set_int(hfx_param *p, int v) {
    if (!p) return HFX_ERR_NULL;
    if (!(p->accept & ACC_INT)) return check_scalar(p, HFX_TYPE_INT, "not an int");
    int32_t w = v;
    return store(p, 0, &w, 1);
}

int hfx_param_set_float(hfx_param *p, float v) {
    if (!p) return HFX_ERR_NULL;
    if (!(p->accept & ACC_FLOAT)) return check_scalar(p, HFX_TYPE_FLOAT, "not a float");
    return store(p, 0, &v, 1);
}

/* The long way: a refusal, or a prefix of an array. */
static __attribute__((noinline)) int set_floats_checked(hfx_param *p, const float *v, size_t count) {
    if (!p) return HFX_ERR_NULL;
    if (!v) return fail(p, HFX_ERR_NULL, "NULL values");
    if (!(p->accept & ACC_FLOATS)) return fail(p, HFX_ERR_TYPE, "not float-valued");
    int rc = check_count(p, count);
    return rc ? rc : store(p, 0, v, count);
}

/* Any whole value, out of line so the float4 path below keeps no registers across a call. */
static __attribute__((noinline)) int store_whole(hfx_param *p, const void *v, size_t count) {
    return store(p, 0, v, count);
}

int hfx_param_set_floats(hfx_param *p, const float *v, size_t count) {
    if (!p || !v || count != p->floats_n) return set_floats_checked(p, v, count);
    if (count != 4) return store_whole(p, v, count);
    if (memcmp(p->value, v, 16) == 0) return HFX_OK; /* float4: the common case, compared in place */
    memcpy(p->value, v, 16);
    changed(p);
    return HFX_OK;
}

static __attribute__((noinline)) int set_ints_checked(hfx_param *p, const int *v, size_t count) {
    if (!p) return HFX_ERR_NULL;
    if (!v) return fail(p, HFX_ERR_NULL, "NULL values");
    if (!(p->accept & ACC_INTS)) return fail(p, HFX_ERR_TYPE, "not int- or bool-valued");
    int rc = check_count(p, count);
    if (rc) return rc;
    if (p->accept & ACC_RAW_INTS) return store(p, 0, v, count);
    int any = 0;
    for (size_t k = 0; k < count; k++) { /* bools are 0/1 */
        uint32_t b = v[k] != 0;
        if (p->value[k] != b) p->value[k] = b, any = 1;
    }
    if (any) changed(p);
    return HFX_OK;
}

int hfx_param_set_ints(hfx_param *p, const int *v, size_t count) {
    if (p && v && count == p->ints_n) return store(p, 0, v, count);
    return set_ints_checked(p, v, count);
}

static int check_matrix(const hfx_param *p) {
    return p->accept & ACC_MATRIX ? HFX_OK : fail(p, HFX_ERR_TYPE, "not a matrix");
}

/* Smaller matrices take the top-left rows x cols of the 4x4, as XNA does. */
static inline int set_matrix(hfx_param *p, const float m[16], int transpose) {
    if (!p) return HFX_ERR_NULL;
    if (!m) return fail(p, HFX_ERR_NULL, "NULL matrix");
    int rc = check_matrix(p);
    if (rc) return rc;
    const hfx_fx_param *i = info(p);
    if (!transpose && i->rows == 4 && i->cols == 4) return store(p, 0, m, 16); /* 4x4: as given */
    float out[16];
    for (uint32_t r = 0; r < i->rows; r++)
        for (uint32_t c = 0; c < i->cols; c++) out[r * i->cols + c] = transpose ? m[c * 4 + r] : m[r * 4 + c];
    return store(p, 0, out, i->rows * i->cols);
}

int hfx_param_set_matrix(hfx_param *p, const float m[16]) { return set_matrix(p, m, 0); }
int hfx_param_set_matrix_transpose(hfx_param *p, const float m[16]) { return set_matrix(p, m, 1); }

int hfx_param_set_texture(hfx_param *p, unsigned int tex) {
    if (!p) return HFX_ERR_NULL;
    if (!(p->accept & ACC_TEXTURE)) return fail(p, HFX_ERR_TYPE, "not a texture or sampler");
    p->fx->textures[p->index] = tex;
    if (p->fx->pool) hfx_rt_pool_share(p->fx, p->root); /* textures are bound from each copy at Apply */
    return HFX_OK;
}

int hfx_param_get_bool(const hfx_param *p, int *out) {
    if (!p) return HFX_ERR_NULL;
    if (!out) return fail(p, HFX_ERR_NULL, "NULL output");
    int rc = check_scalar(p, HFX_TYPE_BOOL, "not a bool");
    if (!rc) *out = p->fx->values[info(p)->offset] != 0;
    return rc;
}

int hfx_param_get_int(const hfx_param *p, int *out) {
    if (!p) return HFX_ERR_NULL;
    if (!out) return fail(p, HFX_ERR_NULL, "NULL output");
    int rc = check_scalar(p, HFX_TYPE_INT, "not an int");
    if (!rc) *out = (int32_t)p->fx->values[info(p)->offset];
    return rc;
}

int hfx_param_get_float(const hfx_param *p, float *out) {
    if (!p) return HFX_ERR_NULL;
    if (!out) return fail(p, HFX_ERR_NULL, "NULL output");
    int rc = check_scalar(p, HFX_TYPE_FLOAT, "not a float");
    if (!rc) memcpy(out, &p->fx->values[info(p)->offset], sizeof *out);
    return rc;
}

int hfx_param_get_floats(const hfx_param *p, float *out, size_t count) {
    if (!p) return HFX_ERR_NULL;
    if (!out) return fail(p, HFX_ERR_NULL, "NULL output");
    const hfx_fx_param *i = info(p);
    if (i->type != HFX_TYPE_FLOAT || !is_numeric(i)) return fail(p, HFX_ERR_TYPE, "not float-valued");
    int rc = check_count(p, count);
    if (!rc) memcpy(out, &p->fx->values[i->offset], count * sizeof *out);
    return rc;
}

int hfx_param_get_ints(const hfx_param *p, int *out, size_t count) {
    if (!p) return HFX_ERR_NULL;
    if (!out) return fail(p, HFX_ERR_NULL, "NULL output");
    const hfx_fx_param *i = info(p);
    if ((i->type != HFX_TYPE_INT && i->type != HFX_TYPE_BOOL) || !is_numeric(i))
        return fail(p, HFX_ERR_TYPE, "not int- or bool-valued");
    int rc = check_count(p, count);
    if (!rc) memcpy(out, &p->fx->values[i->offset], count * sizeof *out);
    return rc;
}

int hfx_param_get_matrix(const hfx_param *p, float out[16]) {
    if (!p) return HFX_ERR_NULL;
    if (!out) return fail(p, HFX_ERR_NULL, "NULL output");
    int rc = check_matrix(p);
    if (rc) return rc;
    const hfx_fx_param *i = info(p);
    const float *v = (const float *)(const void *)&p->fx->values[i->offset];
    memset(out, 0, 16 * sizeof *out);
    for (uint32_t r = 0; r < i->rows; r++)
        for (uint32_t c = 0; c < i->cols; c++) out[r * 4 + c] = v[r * i->cols + c];
    return HFX_OK;
}

int hfx_param_get_texture(const hfx_param *p, unsigned int *out) {
    if (!p) return HFX_ERR_NULL;
    if (!out) return fail(p, HFX_ERR_NULL, "NULL output");
    if (!is_texture_like(info(p))) return fail(p, HFX_ERR_TYPE, "not a texture or sampler");
    *out = p->fx->textures[p->index];
    return HFX_OK;
}

/* GL's enum values for a texture's target, which hfx_param_texture_target returns on every
 * device (hfx.h): written out so the core needs no GL header. */
enum { TARGET_2D = 0x0DE1, TARGET_3D = 0x806F, TARGET_CUBE = 0x8513 };

int hfx_rt_texture_dim(const hfx_fx_effect *fx, uint32_t param) {
    for (uint32_t i = 0; i < fx->sampler_count; i++) {
        const hfx_fx_sampler *s = &fx->samplers[i];
        if (s->texture_param == param || s->param == param) return s->dim == HFX_FX_DIM_1D ? HFX_FX_DIM_2D : (int)s->dim;
    }
    return -1;
}

/* The target the passes bind the texture on: the back end's answer where it binds textures
 * itself (GL); otherwise (Vulkan) the dimension its samplers are sampled with. */
unsigned int hfx_param_texture_target(const hfx_param *p) {
    if (!p || !is_texture_like(info(p))) return 0;
    const hfx_backend *be = p->fx->dev->be;
    if (be->texture_target) return be->texture_target(p);
    int dim = hfx_rt_texture_dim(p->fx->sh->fx, p->index);
    if (dim < 0) return 0;
    return dim == HFX_FX_DIM_CUBE ? TARGET_CUBE : dim == HFX_FX_DIM_3D ? TARGET_3D : TARGET_2D;
}

/* Lookup and description. */

hfx_param *hfx_effect_param(hfx_effect *fx, const char *name) {
    if (!fx) return NULL;
    if (!name) return hfx_rt_fail(fx->dev, HFX_ERR_NULL, "NULL parameter name"), NULL;
    uint32_t i = hfx_fx_param_find(fx->sh->fx, name);
    if (i == HFX_NONE) return hfx_rt_fail(fx->dev, HFX_ERR_NOT_FOUND, "no parameter named '%s'", name), NULL;
    return &fx->params[i];
}

hfx_param *hfx_effect_param_by_semantic(hfx_effect *fx, const char *semantic) {
    if (!fx) return NULL;
    if (!semantic) return hfx_rt_fail(fx->dev, HFX_ERR_NULL, "NULL semantic"), NULL;
    const hfx_fx_effect *cfx = fx->sh->fx;
    for (uint32_t i = 0; i < cfx->top_param_count; i++)
        if (cfx->params[i].semantic && strcasecmp(cfx->params[i].semantic, semantic) == 0) return &fx->params[i];
    return hfx_rt_fail(fx->dev, HFX_ERR_NOT_FOUND, "no parameter with semantic '%s'", semantic), NULL;
}

size_t hfx_effect_param_count(const hfx_effect *fx) { return fx ? fx->sh->fx->top_param_count : 0; }

hfx_param *hfx_effect_param_at(hfx_effect *fx, size_t i) {
    if (!fx) return NULL;
    if (i >= fx->sh->fx->top_param_count) return hfx_rt_fail(fx->dev, HFX_ERR_NOT_FOUND, "no parameter %zu", i), NULL;
    return &fx->params[i];
}

static int is_struct(const hfx_fx_param *i) { return i->klass == HFX_CLASS_STRUCT && !i->elements; }

hfx_param *hfx_param_member(hfx_param *p, const char *name) {
    if (!p) return NULL;
    const hfx_fx_param *i = info(p);
    if (!name) return fail(p, HFX_ERR_NULL, "NULL member name"), NULL;
    if (!is_struct(i)) return fail(p, HFX_ERR_TYPE, "not a struct"), NULL;
    for (uint32_t m = 0; m < i->child_count; m++) {
        const hfx_fx_param *c = &p->fx->sh->fx->params[i->first_child + m];
        if (c->name && strcmp(c->name, name) == 0) return &p->fx->params[i->first_child + m];
    }
    return hfx_rt_fail(dev_of(p), HFX_ERR_NOT_FOUND, "parameter '%s' has no member '%s'", i->name ? i->name : "", name), NULL;
}

hfx_param *hfx_param_member_at(hfx_param *p, size_t m) {
    if (!p) return NULL;
    const hfx_fx_param *i = info(p);
    if (!is_struct(i)) return fail(p, HFX_ERR_TYPE, "not a struct"), NULL;
    if (m >= i->child_count) return fail(p, HFX_ERR_NOT_FOUND, "member index out of range"), NULL;
    return &p->fx->params[i->first_child + m];
}

hfx_param *hfx_param_element(hfx_param *p, size_t e) {
    if (!p) return NULL;
    const hfx_fx_param *i = info(p);
    if (!i->elements) return fail(p, HFX_ERR_TYPE, "not an array"), NULL;
    if (e >= i->child_count) return fail(p, HFX_ERR_NOT_FOUND, "element index out of range"), NULL;
    return &p->fx->params[i->first_child + e];
}

const char *hfx_param_name(const hfx_param *p) { return p && info(p)->name ? info(p)->name : ""; }
const char *hfx_param_semantic(const hfx_param *p) { return p && info(p)->semantic ? info(p)->semantic : ""; }
hfx_param_class hfx_param_get_class(const hfx_param *p) { return p ? info(p)->klass : HFX_CLASS_SCALAR; }
hfx_param_type hfx_param_get_type(const hfx_param *p) { return p ? info(p)->type : HFX_TYPE_VOID; }
size_t hfx_param_rows(const hfx_param *p) { return p ? info(p)->rows : 0; }
size_t hfx_param_columns(const hfx_param *p) { return p ? info(p)->cols : 0; }
size_t hfx_param_elements(const hfx_param *p) { return p ? info(p)->elements : 0; }
size_t hfx_param_member_count(const hfx_param *p) { return p && is_struct(info(p)) ? info(p)->child_count : 0; }

/* Annotations. */

static hfx_annotation *find_annotation(hfx_shared *sh, uint32_t first, uint32_t count, const char *name) {
    if (!name) return NULL;
    for (uint32_t i = 0; i < count && first + i < sh->fx->annotation_count; i++)
        if (sh->fx->annotations[first + i].name && strcmp(sh->fx->annotations[first + i].name, name) == 0)
            return &sh->annotations[first + i];
    hfx_rt_fail(sh->dev, HFX_ERR_NOT_FOUND, "no annotation named '%s'", name);
    return NULL;
}

hfx_annotation *hfx_param_annotation(hfx_param *p, const char *name) {
    if (!p) return NULL;
    return find_annotation(p->fx->sh, info(p)->first_annotation, info(p)->annotation_count, name);
}

size_t hfx_param_annotation_count(const hfx_param *p) { return p ? info(p)->annotation_count : 0; }

hfx_annotation *hfx_param_annotation_at(hfx_param *p, size_t i) {
    if (!p || i >= info(p)->annotation_count) return NULL;
    return &p->fx->sh->annotations[info(p)->first_annotation + i];
}

hfx_annotation *hfx_technique_annotation(hfx_technique *t, const char *name) {
    if (!t) return NULL;
    const hfx_fx_technique *ft = &t->fx->sh->fx->techniques[t->index];
    return find_annotation(t->fx->sh, ft->first_annotation, ft->annotation_count, name);
}

hfx_annotation *hfx_pass_annotation(hfx_pass *p, const char *name) {
    if (!p) return NULL;
    const hfx_fx_pass *fp = &p->fx->sh->fx->passes[p->index];
    return find_annotation(p->fx->sh, fp->first_annotation, fp->annotation_count, name);
}

const char *hfx_annotation_name(const hfx_annotation *a) { return a && a->a->name ? a->a->name : ""; }
hfx_param_type hfx_annotation_type(const hfx_annotation *a) { return a ? a->a->type : HFX_TYPE_VOID; }
const char *hfx_annotation_string(const hfx_annotation *a) {
    return a && a->a->type == HFX_TYPE_STRING ? (a->a->string ? a->a->string : "") : NULL;
}

static float annotation_word(const hfx_fx_annotation *a, uint32_t k) {
    if (a->type == HFX_TYPE_FLOAT) {
        float f;
        memcpy(&f, &a->data[k], sizeof f);
        return f;
    }
    return (float)(int32_t)a->data[k];
}

int hfx_annotation_float(const hfx_annotation *a, float *out) {
    if (!a || !out) return HFX_ERR_NULL;
    if (a->a->type == HFX_TYPE_STRING || !a->a->count || !a->a->data)
        return hfx_rt_fail(a->sh->dev, HFX_ERR_TYPE, "annotation '%s' is not numeric", hfx_annotation_name(a));
    *out = annotation_word(a->a, 0);
    return HFX_OK;
}

int hfx_annotation_floats(const hfx_annotation *a, float *out, size_t count) {
    if (!a || !out) return HFX_ERR_NULL;
    if (a->a->type == HFX_TYPE_STRING || !a->a->data)
        return hfx_rt_fail(a->sh->dev, HFX_ERR_TYPE, "annotation '%s' is not numeric", hfx_annotation_name(a));
    if (count != a->a->count)
        return hfx_rt_fail(a->sh->dev, HFX_ERR_COUNT, "annotation '%s' has %u values", hfx_annotation_name(a),
                           (unsigned)a->a->count);
    for (size_t k = 0; k < count; k++) out[k] = annotation_word(a->a, (uint32_t)k);
    return HFX_OK;
}

int hfx_annotation_int(const hfx_annotation *a, int *out) {
    if (!a || !out) return HFX_ERR_NULL;
    if (a->a->type == HFX_TYPE_STRING || !a->a->count || !a->a->data)
        return hfx_rt_fail(a->sh->dev, HFX_ERR_TYPE, "annotation '%s' is not numeric", hfx_annotation_name(a));
    *out = a->a->type == HFX_TYPE_FLOAT ? hfx_ev_int(annotation_word(a->a, 0)) : (int)(int32_t)a->a->data[0];
    return HFX_OK;
}
