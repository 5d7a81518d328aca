/* intrinsics.c: the intrinsic table and its signature matching. Each rule computes the type
 * every argument converts to and the result type; the conversion costs come from conv.c so
 * an intrinsic call ranks like a user function call. */
#include "check/intrinsics.h"

#include <string.h>

#include "check/conv.h"

static const hfx_intrinsic_info table[HFX_INTR_COUNT] = {
#define HFX_INTRINSIC(id, name, mn, mx, sig, dim, texf, lower, ev, glsl_emit, glsl_fn) {name, mn, mx, sig, dim, texf, lower, ev},
#include "check/intrinsics.def"
#undef HFX_INTRINSIC
};

int hfx_intrinsic_find(const char *name) {
    for (int i = 0; i < HFX_INTR_COUNT; i++) /* the first byte rules out almost every entry cheaply */
        if (table[i].name[0] == name[0] && strcmp(table[i].name, name) == 0) return i;
    return -1;
}

const hfx_intrinsic_info *hfx_intrinsic_info_of(int id) {
    return id >= 0 && id < HFX_INTR_COUNT ? &table[id] : NULL;
}

const char *hfx_intrinsic_name(int id) {
    return id >= 0 && id < HFX_INTR_COUNT ? table[id].name : NULL;
}

/* The float counterpart of an element type: half stays half, int and bool become float. */
static hfx_base float_base(hfx_base b) { return hfx_base_is_float(b) ? b : B_FLOAT; }

/* The type all arguments of a componentwise intrinsic combine to; NULL if some is not numeric
 * or the shapes do not combine. */
static const hfx_type *common_of(hfx_types *t, const hfx_type *const *args, unsigned n, bool *trunc) {
    *trunc = false;
    if (n == 0 || !hfx_type_is_numeric(args[0])) return NULL;
    const hfx_type *ty = args[0];
    for (unsigned i = 1; i < n; i++) {
        bool tr;
        if (!hfx_type_is_numeric(args[i])) return NULL;
        ty = hfx_common_shape(t, ty, args[i], hfx_base_common(ty->base, args[i]->base), &tr);
        if (!ty) return NULL;
        *trunc |= tr;
    }
    return ty;
}

static bool is_vectorish(const hfx_type *ty) { return ty->kind == TY_SCALAR || ty->kind == TY_VECTOR; }

static const hfx_type *vec_or_scalar(hfx_types *t, hfx_base b, unsigned n) {
    return n == 1 ? hfx_type_scalar(t, b) : hfx_type_vector(t, b, n);
}

/* Fills params with `ty` for all n arguments. */
static void all_params(hfx_intrinsic_match *m, const hfx_type *ty, unsigned n) {
    for (unsigned i = 0; i < n; i++) m->params[i] = ty;
}

/* One call's arguments as the rules see them; T, TF and fb are set for the componentwise rules. */
typedef struct rule {
    hfx_types *t;
    const hfx_intrinsic_info *info;
    const hfx_type *const *args;
    unsigned n;
    const hfx_type *T;  /* the common type of the arguments */
    const hfx_type *TF; /* T with a float element type */
    hfx_base fb;        /* TF's element type */
} rule;

typedef bool rule_fn(const rule *r, hfx_intrinsic_match *m);

static bool rule_mul(const rule *r, hfx_intrinsic_match *m) {
    hfx_types *t = r->t;
    const hfx_type *a = r->args[0], *b = r->args[1];
    if (!hfx_type_is_numeric(a) || !hfx_type_is_numeric(b)) return false;
    hfx_base base = hfx_base_common(a->base, b->base);
    if (base == B_BOOL) base = B_INT;
    if (hfx_type_is_scalarlike(a) || hfx_type_is_scalarlike(b)) {
        m->params[0] = hfx_type_is_scalarlike(a) ? hfx_type_scalar(t, base) : hfx_type_with_base(t, a, base);
        m->params[1] = hfx_type_is_scalarlike(b) ? hfx_type_scalar(t, base) : hfx_type_with_base(t, b, base);
        m->ret = hfx_type_is_scalarlike(a) ? m->params[1] : m->params[0];
        return true;
    }
    /* vectors are a row on the left and a column on the right; the inner dimension is clamped
     * to the smaller side (fxc does this without a warning) */
    unsigned ar = a->kind == TY_VECTOR ? 1 : a->rows, ac = a->cols;
    unsigned br = b->kind == TY_VECTOR ? b->cols : b->rows, bc = b->kind == TY_VECTOR ? 1 : b->cols;
    unsigned k = ac < br ? ac : br;
    m->params[0] = a->kind == TY_VECTOR ? hfx_type_vector(t, base, k) : hfx_type_matrix(t, base, ar, k);
    m->params[1] = b->kind == TY_VECTOR ? hfx_type_vector(t, base, k) : hfx_type_matrix(t, base, k, bc);
    if (a->kind == TY_VECTOR && b->kind == TY_VECTOR) m->ret = hfx_type_scalar(t, base);
    else if (a->kind == TY_VECTOR) m->ret = hfx_type_vector(t, base, bc);
    else if (b->kind == TY_VECTOR) m->ret = hfx_type_vector(t, base, ar);
    else m->ret = hfx_type_matrix(t, base, ar, bc);
    return true;
}

static unsigned tex_coord_size(hfx_dim dim) {
    switch (dim) {
    case DIM_1D: return 1;
    case DIM_2D: return 2;
    default: return 3;
    }
}

static bool rule_tex(const rule *r, hfx_intrinsic_match *m) {
    const hfx_type *s = r->args[0];
    hfx_dim dim = r->info->dim;
    hfx_tex_form form = r->info->tex_form;
    if (s->kind != TY_SAMPLER || (s->dim != DIM_GENERIC && s->dim != dim)) return false;
    if (r->n == 3) return false;
    m->params[0] = hfx_type_object(r->t, TY_SAMPLER, dim);
    const hfx_type *coord = vec_or_scalar(r->t, B_FLOAT, tex_coord_size(dim));
    if (form == TEXF_BIAS || form == TEXF_LOD || form == TEXF_PROJ) coord = hfx_type_vector(r->t, B_FLOAT, 4);
    for (unsigned i = 1; i < r->n; i++) m->params[i] = coord;
    m->ret = hfx_type_vector(r->t, B_FLOAT, 4);
    return true;
}

static bool rule_lit(const rule *r, hfx_intrinsic_match *m) {
    for (unsigned i = 0; i < r->n; i++)
        if (!hfx_type_is_scalarlike(r->args[i])) return false;
    all_params(m, hfx_type_scalar(r->t, B_FLOAT), r->n);
    m->ret = hfx_type_vector(r->t, B_FLOAT, 4);
    return true;
}

static bool rule_cross(const rule *r, hfx_intrinsic_match *m) {
    all_params(m, hfx_type_vector(r->t, B_FLOAT, 3), r->n);
    m->ret = m->params[0];
    return hfx_type_is_numeric(r->args[0]) && hfx_type_is_numeric(r->args[1]);
}

static bool rule_dst(const rule *r, hfx_intrinsic_match *m) {
    all_params(m, hfx_type_vector(r->t, B_FLOAT, 4), r->n);
    m->ret = m->params[0];
    return hfx_type_is_numeric(r->args[0]) && hfx_type_is_numeric(r->args[1]);
}

static bool rule_d3dcolor(const rule *r, hfx_intrinsic_match *m) {
    m->params[0] = hfx_type_vector(r->t, B_FLOAT, 4);
    m->ret = hfx_type_vector(r->t, B_INT, 4);
    return hfx_type_is_numeric(r->args[0]);
}

/* The componentwise rules: T is the arguments' common type. */
static const hfx_type *int_if_bool(const rule *r) {
    return r->T->base == B_BOOL ? hfx_type_with_base(r->t, r->T, B_INT) : r->T;
}

static bool rule_same(const rule *r, hfx_intrinsic_match *m) {
    all_params(m, int_if_bool(r), r->n);
    m->ret = m->params[0];
    return true;
}

static bool rule_same_float(const rule *r, hfx_intrinsic_match *m) {
    all_params(m, r->TF, r->n);
    m->ret = r->TF;
    return true;
}

static bool rule_clip(const rule *r, hfx_intrinsic_match *m) {
    m->params[0] = r->TF;
    m->ret = hfx_type_void(r->t);
    return true;
}

static bool rule_all_any(const rule *r, hfx_intrinsic_match *m) {
    m->params[0] = r->T;
    m->ret = hfx_type_scalar(r->t, B_BOOL);
    return true;
}

static bool rule_classify(const rule *r, hfx_intrinsic_match *m) {
    m->params[0] = r->TF;
    m->ret = hfx_type_with_base(r->t, r->T, B_BOOL);
    return true;
}

static bool rule_dot(const rule *r, hfx_intrinsic_match *m) {
    if (!is_vectorish(r->T)) return false;
    all_params(m, int_if_bool(r), r->n);
    m->ret = hfx_type_scalar(r->t, m->params[0]->base);
    return true;
}

/* length, distance, noise: a float scalar of float vectors. */
static bool rule_to_scalar(const rule *r, hfx_intrinsic_match *m) {
    if (!is_vectorish(r->T)) return false;
    all_params(m, r->TF, r->n);
    m->ret = hfx_type_scalar(r->t, r->fb);
    return true;
}

static bool rule_vec_same(const rule *r, hfx_intrinsic_match *m) {
    if (!is_vectorish(r->T)) return false;
    all_params(m, r->TF, r->n);
    m->ret = r->TF;
    return true;
}

static bool rule_refract(const rule *r, hfx_intrinsic_match *m) {
    if (!is_vectorish(r->T) || !hfx_type_is_numeric(r->args[2])) return false;
    m->params[0] = m->params[1] = r->TF;
    m->params[2] = hfx_type_scalar(r->t, r->fb);
    m->ret = r->TF;
    return true;
}

static bool rule_determinant(const rule *r, hfx_intrinsic_match *m) {
    if (r->T->rows != r->T->cols || r->T->kind == TY_VECTOR) return false;
    m->params[0] = r->TF;
    m->ret = hfx_type_scalar(r->t, r->fb);
    return true;
}

static bool rule_transpose(const rule *r, hfx_intrinsic_match *m) {
    const hfx_type *T = r->T;
    if (T->kind == TY_VECTOR) return false;
    m->params[0] = T;
    m->ret = hfx_type_numeric(r->t, T->kind, T->base, T->cols, T->rows);
    return true;
}

/* The first argument's shape in float: sincos and the out-argument rules (modf, frexp). */
static const hfx_type *first_as_float(const rule *r) {
    return hfx_type_with_base(r->t, r->args[0], float_base(r->args[0]->base));
}

static bool rule_sincos(const rule *r, hfx_intrinsic_match *m) {
    all_params(m, first_as_float(r), r->n);
    m->out[1] = m->out[2] = true;
    m->ret = hfx_type_void(r->t);
    return true;
}

static bool rule_out2(const rule *r, hfx_intrinsic_match *m) {
    all_params(m, first_as_float(r), r->n);
    m->out[1] = true;
    m->ret = m->params[0];
    return true;
}

/* asfloat / asint / asuint: the bits of T as the element type the rule names. */
static bool rule_reinterpret(const rule *r, hfx_intrinsic_match *m) {
    const hfx_type *T = r->T;
    if (T->base == B_BOOL || T->base == B_DOUBLE) return false;
    hfx_sig sig = r->info->sig;
    hfx_base to = sig == SIG_AS_FLOAT ? B_FLOAT : sig == SIG_AS_INT ? B_INT : B_UINT;
    m->params[0] = hfx_base_is_float(T->base) ? hfx_type_with_base(r->t, T, B_FLOAT) : T;
    m->ret = hfx_type_with_base(r->t, T, to);
    return true;
}

/* Each signature's rule; `fixed` rules read the arguments themselves, the others get T. */
static const struct {
    rule_fn *fn;
    bool fixed;
} rules[] = {
    [SIG_SAME] = {rule_same, false},           [SIG_SAME_FLOAT] = {rule_same_float, false},
    [SIG_CLIP] = {rule_clip, false},           [SIG_ALL_ANY] = {rule_all_any, false},
    [SIG_CLASSIFY] = {rule_classify, false},   [SIG_DOT] = {rule_dot, false},
    [SIG_LENGTH] = {rule_to_scalar, false},    [SIG_DISTANCE] = {rule_to_scalar, false},
    [SIG_VEC_SAME] = {rule_vec_same, false},   [SIG_REFRACT] = {rule_refract, false},
    [SIG_CROSS] = {rule_cross, true},          [SIG_DETERMINANT] = {rule_determinant, false},
    [SIG_TRANSPOSE] = {rule_transpose, false}, [SIG_MUL] = {rule_mul, true},
    [SIG_LIT] = {rule_lit, true},              [SIG_SINCOS] = {rule_sincos, false},
    [SIG_DST] = {rule_dst, true},
    [SIG_OUT2] = {rule_out2, false},           [SIG_D3DCOLOR] = {rule_d3dcolor, true},
    [SIG_NOISE] = {rule_to_scalar, false},     [SIG_AS_FLOAT] = {rule_reinterpret, false},
    [SIG_AS_INT] = {rule_reinterpret, false},  [SIG_AS_UINT] = {rule_reinterpret, false},
    [SIG_TEX] = {rule_tex, true},
};

/* Fills params and ret by the intrinsic's rule; false when the arguments cannot fit. */
static bool match_rule(hfx_types *t, const hfx_intrinsic_info *info, const hfx_type *const *args, unsigned n,
                       hfx_intrinsic_match *m) {
    rule r = {t, info, args, n, NULL, NULL, B_FLOAT};
    if ((size_t)info->sig >= sizeof rules / sizeof rules[0] || !rules[info->sig].fn) return false;
    if (rules[info->sig].fixed) return rules[info->sig].fn(&r, m);
    bool trunc = false;
    r.T = common_of(t, args, info->sig == SIG_REFRACT ? 2 : n, &trunc);
    if (!r.T) return false;
    m->truncates = trunc;
    r.fb = float_base(r.T->base);
    r.TF = hfx_type_with_base(t, r.T, r.fb);
    return rules[info->sig].fn(&r, m);
}

/* float, float1 and float1x1 hold the same one value: an out argument may be any of them. */
static bool one_component_alike(const hfx_type *a, const hfx_type *b) {
    return hfx_type_is_numeric(a) && hfx_type_is_numeric(b) && a->base == b->base && hfx_type_components(a) == 1 &&
           hfx_type_components(b) == 1;
}

bool hfx_intrinsic_match_args(hfx_types *t, int id, const hfx_type *const *args, unsigned n,
                              hfx_intrinsic_match *out) {
    const hfx_intrinsic_info *info = hfx_intrinsic_info_of(id);
    memset(out, 0, sizeof *out);
    if (!info || n < info->min_args || n > info->max_args || n > 4) return false;
    for (unsigned i = 0; i < n; i++)
        if (!args[i]) return false;
    if (!match_rule(t, info, args, n, out)) return false;
    /* every argument must convert to its parameter; out arguments must match exactly */
    for (unsigned i = 0; i < n; i++) {
        hfx_conv c = hfx_conv_classify(args[i], out->params[i], false);
        if (!c.ok) return false;
        if (out->out[i] && !hfx_type_equal(args[i], out->params[i]) && !one_component_alike(args[i], out->params[i]))
            return false;
        if (c.truncates && info->sig != SIG_MUL) out->truncates = true;
        out->cost += hfx_conv_cost(c);
    }
    return true;
}
