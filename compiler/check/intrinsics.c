/* intrinsics.c: the intrinsic table and its signature matching. Each rule computes the type
 * every argument converts to and the result type; the conversion costs come from conv.c so
 * an intrinsic call ranks like a user function call. */
#include "check/intrinsics.h"

#include <string.h>

#include "check/conv.h"

static const hfx_intrinsic_info table[HFX_INTR_COUNT] = {
#define HFX_INTRINSIC_ROW_(id, name, mn, mx, sig, dim, form, glsl) {name, mn, mx, sig, dim, form, glsl},
    HFX_INTRINSIC_LIST(HFX_INTRINSIC_ROW_)
#undef HFX_INTRINSIC_ROW_
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

static bool match_mul(hfx_types *t, const hfx_type *a, const hfx_type *b, hfx_intrinsic_match *m) {
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

static bool match_tex(hfx_types *t, const hfx_intrinsic_info *info, const hfx_type *const *args, unsigned n,
                      hfx_intrinsic_match *m) {
    const hfx_type *s = args[0];
    if (s->kind != TY_SAMPLER || (s->dim != DIM_GENERIC && s->dim != info->dim)) return false;
    if (n == 3) return false;
    m->params[0] = hfx_type_object(t, TY_SAMPLER, info->dim);
    unsigned cn = tex_coord_size(info->dim);
    const hfx_type *coord = vec_or_scalar(t, B_FLOAT, cn);
    if (info->form == TEXF_BIAS || info->form == TEXF_LOD || info->form == TEXF_PROJ)
        coord = hfx_type_vector(t, B_FLOAT, 4);
    for (unsigned i = 1; i < n; i++) m->params[i] = coord;
    m->ret = hfx_type_vector(t, B_FLOAT, 4);
    return true;
}

/* The rule of each signature: fills params and ret; false when the arguments cannot fit. */
static bool match_rule(hfx_types *t, const hfx_intrinsic_info *info, const hfx_type *const *args, unsigned n,
                       hfx_intrinsic_match *m) {
    bool trunc = false;
    const hfx_type *T = NULL;
    switch (info->sig) {
    case SIG_TEX: return match_tex(t, info, args, n, m);
    case SIG_MUL: return match_mul(t, args[0], args[1], m);
    case SIG_LIT:
        for (unsigned i = 0; i < n; i++) if (!hfx_type_is_numeric(args[i])) return false;
        all_params(m, hfx_type_scalar(t, B_FLOAT), n);
        m->ret = hfx_type_vector(t, B_FLOAT, 4);
        return true;
    case SIG_CROSS:
        all_params(m, hfx_type_vector(t, B_FLOAT, 3), n);
        m->ret = m->params[0];
        return hfx_type_is_numeric(args[0]) && hfx_type_is_numeric(args[1]);
    case SIG_D3DCOLOR:
        m->params[0] = hfx_type_vector(t, B_FLOAT, 4);
        m->ret = hfx_type_vector(t, B_INT, 4);
        return hfx_type_is_numeric(args[0]);
    default: break;
    }
    T = common_of(t, args, info->sig == SIG_REFRACT ? 2 : n, &trunc);
    if (!T) return false;
    m->truncates = trunc;
    hfx_base fb = float_base(T->base);
    const hfx_type *TF = hfx_type_with_base(t, T, fb);
    switch (info->sig) {
    case SIG_SAME:
        all_params(m, T->base == B_BOOL ? hfx_type_with_base(t, T, B_INT) : T, n);
        m->ret = m->params[0];
        return true;
    case SIG_SAME_FLOAT:
        all_params(m, TF, n);
        m->ret = TF;
        return true;
    case SIG_CLIP:
        m->params[0] = TF;
        m->ret = hfx_type_void(t);
        return true;
    case SIG_ALL_ANY:
        m->params[0] = T;
        m->ret = hfx_type_scalar(t, B_BOOL);
        return true;
    case SIG_CLASSIFY:
        m->params[0] = TF;
        m->ret = hfx_type_with_base(t, T, B_BOOL);
        return true;
    case SIG_DOT:
        if (!is_vectorish(T)) return false;
        all_params(m, T->base == B_BOOL ? hfx_type_with_base(t, T, B_INT) : T, n);
        m->ret = hfx_type_scalar(t, m->params[0]->base);
        return true;
    case SIG_LENGTH: case SIG_DISTANCE: case SIG_NOISE:
        if (!is_vectorish(T)) return false;
        all_params(m, TF, n);
        m->ret = hfx_type_scalar(t, fb);
        return true;
    case SIG_VEC_SAME:
        if (!is_vectorish(T)) return false;
        all_params(m, TF, n);
        m->ret = TF;
        return true;
    case SIG_REFRACT:
        if (!is_vectorish(T) || !hfx_type_is_numeric(args[2])) return false;
        m->params[0] = m->params[1] = TF;
        m->params[2] = hfx_type_scalar(t, fb);
        m->ret = TF;
        return true;
    case SIG_DETERMINANT:
        if (T->rows != T->cols || T->kind == TY_VECTOR) return false;
        m->params[0] = TF;
        m->ret = hfx_type_scalar(t, fb);
        return true;
    case SIG_TRANSPOSE:
        if (T->kind == TY_VECTOR) return false;
        m->params[0] = T;
        m->ret = hfx_type_numeric(t, T->kind, T->base, T->cols, T->rows);
        return true;
    case SIG_SINCOS:
        all_params(m, hfx_type_with_base(t, args[0], float_base(args[0]->base)), n);
        m->out[1] = m->out[2] = true;
        m->ret = hfx_type_void(t);
        return true;
    case SIG_OUT2:
        all_params(m, hfx_type_with_base(t, args[0], float_base(args[0]->base)), n);
        m->out[1] = true;
        m->ret = m->params[0];
        return true;
    case SIG_REINTERPRET:
        if (T->base == B_BOOL || T->base == B_DOUBLE) return false;
        m->params[0] = hfx_base_is_float(T->base) ? hfx_type_with_base(t, T, B_FLOAT) : T;
        m->ret = hfx_type_with_base(t, T, (hfx_base)info->form);
        return true;
    default:
        return false;
    }
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
        if (out->out[i] && !hfx_type_equal(args[i], out->params[i])) return false;
        if (c.truncates && info->sig != SIG_MUL) out->truncates = true;
        out->cost += hfx_conv_cost(c);
    }
    return true;
}
