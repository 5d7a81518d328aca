/* parse_expr.c: vectors, literals, expression nodes and type specifiers for parser.y.
 * Every expression node carries its tree depth (in a wrapper the rest of the compiler never
 * sees), so a pathological operator chain is rejected here instead of overflowing the C stack
 * of a recursive pass later. */
#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "parse/parse_ctx.h"

/* ---- vectors ---- */

parse_vec hfx_parse_vec_new(void) { return (parse_vec){NULL, 0, 0}; }

parse_vec hfx_parse_vec_push(parse_ctx *ctx, parse_vec v, void *item) {
    if (!HFX_ARENA_GROW(ctx->arena, v.items, v.count, v.cap, 4)) return v;
    v.items[v.count++] = item;
    return v;
}

parse_vec hfx_parse_vec_one(parse_ctx *ctx, void *item) { return hfx_parse_vec_push(ctx, hfx_parse_vec_new(), item); }

parse_vec hfx_parse_vec_concat(parse_ctx *ctx, parse_vec a, parse_vec b) {
    for (uint32_t i = 0; i < b.count; i++) a = hfx_parse_vec_push(ctx, a, b.items[i]);
    return a;
}

/* ---- nodes with depth ---- */

typedef parse_expr_node expr_node;

static uint32_t expr_depth(const hfx_expr *e) { return e ? ((const expr_node *)e)->depth : 0; }

hfx_expr *hfx_pb_expr(parse_ctx *ctx, hfx_expr_kind kind, hfx_loc loc) {
    expr_node *n = HFX_NEW(ctx->arena, expr_node);
    if (!n) {
        hfx_parse_fatal(ctx, loc, "out of memory");
        n = ctx->oom_expr;
    }
    n->e.kind = kind;
    n->e.loc = loc;
    n->e.intrinsic = -1;
    n->depth = 1;
    return &n->e;
}

/* Hangs `count` operands under e, tracking depth against PARSE_MAX_EXPR_DEPTH. */
static hfx_expr *set_args(parse_ctx *ctx, hfx_expr *e, hfx_expr **args, uint32_t count) {
    e->args = args;
    e->arg_count = count;
    uint32_t d = 0;
    for (uint32_t i = 0; i < count; i++)
        if (expr_depth(args[i]) > d) d = expr_depth(args[i]);
    ((expr_node *)e)->depth = d + 1;
    if (d + 1 > PARSE_MAX_EXPR_DEPTH)
        hfx_parse_fatal(ctx, e->loc, "nesting too deep: expression more than 4096 levels deep");
    return e;
}

static hfx_expr *with_args(parse_ctx *ctx, hfx_expr *e, hfx_expr *a, hfx_expr *b, hfx_expr *c) {
    uint32_t n = c ? 3 : b ? 2 : a ? 1 : 0;
    hfx_expr **args = HFX_NEW_ARRAY(ctx->arena, hfx_expr *, n ? n : 1);
    if (!args) return e;
    hfx_expr *all[3] = {a, b, c};
    memcpy(args, all, sizeof *args * n);
    return set_args(ctx, e, args, n);
}

static hfx_expr *with_vec(parse_ctx *ctx, hfx_expr *e, parse_vec v) {
    return set_args(ctx, e, (hfx_expr **)v.items, v.count);
}

/* ---- literals ---- */

hfx_expr *hfx_pb_int(parse_ctx *ctx, const char *text, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_INT, loc);
    errno = 0;
    unsigned long long v = strtoull(text, NULL, 0); /* 0x.., 0.. octal; u/l suffixes stop it */
    bool range = errno == ERANGE;
    if (range || v > UINT32_MAX) {
        /* fxc's lexer keeps the low 32 bits, with a warning (Microsoft's list of HLSL errors and
         * warnings: 1002 / 1003 / 1004, "a hex / an octal / a decimal value was truncated to 32
         * bits"), so 4294967297 is 1 wherever it is used, a float included */
        bool hex = text[0] == '0' && (text[1] == 'x' || text[1] == 'X'), octal = !hex && text[0] == '0';
        hfx_warning(ctx->diags, loc, hex ? 1002 : octal ? 1003 : 1004, "%s value truncated to 32 bits",
                    hex ? "hex" : octal ? "octal" : "decimal");
        v = range ? UINT32_MAX : v & UINT32_MAX; /* past 64 bits: strtoull kept none of them */
    }
    e->ival = (int64_t)v;
    e->is_unsigned = strpbrk(text, "uU") != NULL || v > INT32_MAX;
    return e;
}

hfx_expr *hfx_pb_float(parse_ctx *ctx, const char *text, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_FLOAT, loc);
    e->fval = strtod(text, NULL); /* stops at the f/h/l suffix */
    return e;
}

hfx_expr *hfx_pb_bool(parse_ctx *ctx, bool v, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_BOOL, loc);
    e->ival = v;
    return e;
}

static int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* One escape after the backslash at *p; advances p. */
static char unescape(const char **p) {
    char c = *(*p)++;
    switch (c) {
    case 'n': return '\n';
    case 't': return '\t';
    case 'r': return '\r';
    case 'a': return '\a';
    case 'b': return '\b';
    case 'f': return '\f';
    case 'v': return '\v';
    case 'x': {
        int v = 0;
        while (hex_digit(**p) >= 0) v = v * 16 + hex_digit(*(*p)++);
        return (char)v;
    }
    default:
        if (c >= '0' && c <= '7') {
            int v = c - '0';
            for (int i = 0; i < 2 && **p >= '0' && **p <= '7'; i++) v = v * 8 + (*(*p)++ - '0');
            return (char)v;
        }
        return c; /* \\ \" \' \? and unknown ones stand for themselves */
    }
}

/* The contents of a "..." token, quotes dropped and escapes resolved. */
static char *string_value(parse_ctx *ctx, const char *text) {
    size_t n = strlen(text);
    char *out = hfx_arena_alloc(ctx->arena, n + 1);
    if (!out) return "";
    const char *p = text[0] == '"' ? text + 1 : text;
    const char *end = text + n;
    if (end > p && end[-1] == '"') end--;
    size_t at = 0;
    while (p < end) {
        if (*p == '\\' && p + 1 < end) {
            p++;
            out[at++] = unescape(&p);
        } else {
            out[at++] = *p++;
        }
    }
    out[at] = 0;
    return out;
}

hfx_expr *hfx_pb_string(parse_ctx *ctx, const char *text, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_STRING, loc);
    e->sval = string_value(ctx, text);
    return e;
}

hfx_expr *hfx_pb_string_join(parse_ctx *ctx, hfx_expr *s, const char *text) {
    const char *more = string_value(ctx, text);
    s->sval = hfx_arena_printf(ctx->arena, "%s%s", s->sval, more);
    return s;
}

/* ---- operators ---- */

hfx_expr *hfx_pb_ident(parse_ctx *ctx, const char *name, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_IDENT, loc);
    e->name = name;
    return e;
}

hfx_expr *hfx_pb_unary(parse_ctx *ctx, hfx_op op, hfx_expr *a, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_UNARY, loc);
    e->op = op;
    return with_args(ctx, e, a, NULL, NULL);
}

hfx_expr *hfx_pb_binary(parse_ctx *ctx, hfx_op op, hfx_expr *a, hfx_expr *b, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_BINARY, loc);
    e->op = op;
    return with_args(ctx, e, a, b, NULL);
}

hfx_expr *hfx_pb_assign(parse_ctx *ctx, hfx_op op, hfx_expr *a, hfx_expr *b, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_ASSIGN, loc);
    e->op = op;
    return with_args(ctx, e, a, b, NULL);
}

hfx_expr *hfx_pb_ternary(parse_ctx *ctx, hfx_expr *c, hfx_expr *a, hfx_expr *b, hfx_loc loc) {
    return with_args(ctx, hfx_pb_expr(ctx, EX_TERNARY, loc), c, a, b);
}

hfx_expr *hfx_pb_comma(parse_ctx *ctx, hfx_expr *a, hfx_expr *b, hfx_loc loc) {
    return with_args(ctx, hfx_pb_expr(ctx, EX_COMMA, loc), a, b, NULL);
}

hfx_expr *hfx_pb_call(parse_ctx *ctx, const char *name, parse_vec args, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_CALL, loc);
    e->name = name;
    return with_vec(ctx, e, args);
}

hfx_expr *hfx_pb_method(parse_ctx *ctx, hfx_expr *obj, const char *name, parse_vec args, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_METHOD, loc);
    e->name = name;
    parse_vec all = hfx_parse_vec_one(ctx, obj);
    for (uint32_t i = 0; i < args.count; i++) all = hfx_parse_vec_push(ctx, all, args.items[i]);
    return with_vec(ctx, e, all);
}

hfx_expr *hfx_pb_construct(parse_ctx *ctx, const hfx_type *type, parse_vec args, hfx_loc loc) {
    ctx->last_type = NULL;
    hfx_expr *e = hfx_pb_expr(ctx, EX_CONSTRUCT, loc);
    e->cast_type = type;
    return with_vec(ctx, e, args);
}

hfx_expr *hfx_pb_cast(parse_ctx *ctx, const hfx_type *type, hfx_expr *a, hfx_loc loc) {
    ctx->last_type = NULL;
    hfx_expr *e = hfx_pb_expr(ctx, EX_CAST, loc);
    e->cast_type = type;
    return with_args(ctx, e, a, NULL, NULL);
}

hfx_expr *hfx_pb_member(parse_ctx *ctx, hfx_expr *a, const char *name, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_MEMBER, loc);
    e->name = name;
    return with_args(ctx, e, a, NULL, NULL);
}

hfx_expr *hfx_pb_index(parse_ctx *ctx, hfx_expr *a, hfx_expr *i, hfx_loc loc) {
    return with_args(ctx, hfx_pb_expr(ctx, EX_INDEX, loc), a, i, NULL);
}

hfx_expr *hfx_pb_init_list(parse_ctx *ctx, parse_vec items, hfx_loc loc) {
    return with_vec(ctx, hfx_pb_expr(ctx, EX_INIT_LIST, loc), items);
}

hfx_expr *hfx_pb_compile(parse_ctx *ctx, const char *profile, const char *entry, parse_vec args, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_COMPILE, loc);
    e->profile = profile;
    e->name = entry;
    return with_vec(ctx, e, args);
}

hfx_expr *hfx_pb_sampler_state(parse_ctx *ctx, parse_vec states, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_SAMPLER_STATE, loc);
    e->states = HFX_NEW_ARRAY(ctx->arena, hfx_state_assign, states.count ? states.count : 1);
    if (!e->states) return e;
    for (uint32_t i = 0; i < states.count; i++) e->states[i] = *(hfx_state_assign *)states.items[i];
    e->state_count = states.count;
    return e;
}

hfx_expr *hfx_pb_state_ref(parse_ctx *ctx, const char *name, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_STATE_REF, loc);
    e->name = name;
    return e;
}

hfx_expr *hfx_pb_asm(parse_ctx *ctx, const char *text, hfx_loc loc) {
    hfx_expr *e = hfx_pb_expr(ctx, EX_ASM, loc);
    e->sval = text;
    return e;
}

hfx_expr *hfx_pb_paren(hfx_expr *e) {
    e->parenthesized = true;
    return e;
}

/* ---- type specifiers ---- */

static unsigned dimension(parse_ctx *ctx, const char *text, hfx_loc loc) {
    char *end;
    unsigned long v = strtoul(text, &end, 0);
    if (v < 1 || v > 4) {
        hfx_error(ctx->diags, loc, X_SYNTAX, "vector and matrix dimensions must be between 1 and 4");
        return 4;
    }
    return (unsigned)v;
}

/* The element type of vector<T,n> / matrix<T,r,c>: a scalar, else an error and float. */
static hfx_base generic_base(parse_ctx *ctx, const hfx_type *scalar, hfx_loc loc) {
    if (scalar && scalar->kind == TY_SCALAR) return scalar->base;
    hfx_error(ctx->diags, loc, X_SYNTAX, "vector and matrix element types must be scalar");
    return B_FLOAT;
}

const hfx_type *hfx_pb_generic_vector(parse_ctx *ctx, const hfx_type *scalar, const char *n, hfx_loc loc) {
    ctx->last_type = NULL;
    if (!n) return hfx_type_vector(ctx->types, B_FLOAT, 4);
    return hfx_type_vector(ctx->types, generic_base(ctx, scalar, loc), dimension(ctx, n, loc));
}

const hfx_type *hfx_pb_generic_matrix(parse_ctx *ctx, const hfx_type *scalar, const char *r, const char *c, hfx_loc loc) {
    ctx->last_type = NULL;
    if (!r) return hfx_type_matrix(ctx->types, B_FLOAT, 4, 4);
    hfx_base b = generic_base(ctx, scalar, loc);
    return hfx_type_matrix(ctx->types, b, dimension(ctx, r, loc), dimension(ctx, c, loc));
}

const hfx_type *hfx_pb_typename(parse_ctx *ctx, const parse_tok *t, hfx_loc loc) {
    const hfx_type *ty = t->entry ? t->entry->type : t->type;
    ctx->last_type = ty;
    ctx->last_type_mods = t->entry ? t->entry->mods : 0;
    if (ty) return ty;
    hfx_error(ctx->diags, loc, X_SYNTAX, "'%s': type used in its own definition", t->text);
    return hfx_type_scalar(ctx->types, B_FLOAT);
}

/* `unsigned int` is uint (unsigned int2 is uint2). */
const hfx_type *hfx_pb_unsigned(parse_ctx *ctx, const hfx_type *ty, hfx_loc loc) {
    ctx->last_type = NULL;
    if (ty && ty->kind == TY_SCALAR && ty->base == B_INT) return hfx_type_scalar(ctx->types, B_UINT);
    if (ty && ty->kind == TY_VECTOR && ty->base == B_INT) return hfx_type_vector(ctx->types, B_UINT, ty->cols);
    hfx_error(ctx->diags, loc, X_SYNTAX, "syntax error: 'unsigned' applies to int types");
    return hfx_type_scalar(ctx->types, B_UINT);
}

/* `Texture2D<float4>` (SM4 spelling): the element type is dropped, D3D9 textures have none. */
const hfx_type *hfx_pb_template(parse_ctx *ctx, const hfx_type *object, const hfx_type *elem, hfx_loc loc) {
    (void)elem;
    if (object->kind == TY_TEXTURE) return object;
    hfx_error(ctx->diags, loc, X_SYNTAX, "syntax error: unexpected token '<'");
    return object;
}

/* Folds a constant integer expression (array sizes) with int's rules (common/eval); false
 * when it is not one. Names are the checker's to fold (hfx_ck_fold_int). */
static bool fold_int(const hfx_expr *e, int64_t *out) {
    int64_t a, b;
    hfx_ev_op op;
    double r;
    switch (e->kind) {
    case EX_INT: case EX_BOOL: *out = hfx_ev_int(hfx_ev_normalise(HFX_EV_INT, (double)e->ival)); return true;
    case EX_UNARY:
        if (!fold_int(e->args[0], &a) || !hfx_op_ev(e->op, &op) || !hfx_ev_unary(op, HFX_EV_INT, (double)a, &r)) return false;
        *out = hfx_ev_int(r);
        return true;
    case EX_BINARY:
        if (!fold_int(e->args[0], &a) || !fold_int(e->args[1], &b) || !hfx_op_ev(e->op, &op)) return false;
        if (!hfx_ev_binary(op, HFX_EV_INT, (double)a, (double)b, &r)) return false;
        *out = hfx_ev_int(r);
        return true;
    case EX_TERNARY:
        if (!fold_int(e->args[0], &a)) return false;
        return fold_int(e->args[a ? 1 : 2], out);
    default: return false;
    }
}

/* One array dimension around t: folded size, 0 for [] or, unfolded, array_len_expr. */
static const hfx_type *array_of(parse_ctx *ctx, const hfx_type *t, hfx_expr *size) {
    int64_t n = 0;
    if (!size) return hfx_type_array(ctx->types, t, 0);
    if (!fold_int(size, &n)) {
        hfx_type *arr = (hfx_type *)hfx_type_array(ctx->types, t, 0); /* fresh: ours to finish */
        arr->array_len_expr = size;
        return arr;
    }
    if (n < 1 || n > 65536) {
        hfx_error(ctx->diags, size->loc, 3059, "array dimension must be between 1 and 65536");
        n = 1;
    }
    return hfx_type_array(ctx->types, t, (uint32_t)n);
}

const hfx_type *hfx_pb_array_type(parse_ctx *ctx, const hfx_type *elem, parse_vec dims) {
    const hfx_type *t = elem;
    for (uint32_t i = dims.count; i-- > 0;) t = array_of(ctx, t, dims.items[i]);
    return t;
}

uint32_t hfx_pb_more_mods(parse_ctx *ctx, uint32_t mods, uint32_t more, hfx_loc loc) {
    if (mods & more & (MOD_ROW_MAJOR | MOD_COLUMN_MAJOR))
        hfx_error(ctx->diags, loc, 3048, "duplicate usages specified");
    return mods | more;
}

parse_specs *hfx_pb_specs(parse_ctx *ctx, uint32_t mods, const hfx_type *type, hfx_loc loc) {
    parse_specs *s = HFX_NEW(ctx->arena, parse_specs);
    if (!s) return ctx->oom_specs;
    if (type && type == ctx->last_type) mods |= ctx->last_type_mods;
    ctx->last_type = NULL;
    s->mods = mods;
    s->type = type;
    s->loc = loc;
    const hfx_type *elem = type;
    while (elem && elem->kind == TY_ARRAY) elem = elem->elem;
    /* row_major / column_major: for matrices, once (X3048 for both; X3077 on a scalar or vector) */
    if ((mods & MOD_ROW_MAJOR) && (mods & MOD_COLUMN_MAJOR))
        hfx_error(ctx->diags, loc, 3048, "row_major and column_major cannot be used together");
    else if (elem && (mods & (MOD_ROW_MAJOR | MOD_COLUMN_MAJOR)) && (elem->kind == TY_SCALAR || elem->kind == TY_VECTOR))
        hfx_error(ctx->diags, loc, 3077, "non-matrix types cannot be declared row_major or column_major");
    /* #pragma pack_matrix: the default for matrices that name no majorness themselves */
    if (elem && elem->kind == TY_MATRIX && !(mods & (MOD_ROW_MAJOR | MOD_COLUMN_MAJOR))) s->mods |= ctx->pack_mods;
    if (type && type->kind == TY_STRUCT && ctx->pending_struct == type->st) {
        s->defines = type->st; /* `struct S {...} x;` also declares S */
        ctx->pending_struct = NULL;
    }
    return s;
}

static hfx_struct *struct_object(parse_ctx *ctx, const char *name, hfx_loc loc, const hfx_type **type) {
    parse_typename *e = name ? hfx_parse_find_typename(ctx, name) : NULL;
    if (e && e->st) {
        *type = e->type;
        return e->st;
    }
    hfx_struct *st = HFX_NEW(ctx->arena, hfx_struct);
    if (!st) return NULL;
    st->name = name;
    st->loc = loc;
    *type = hfx_type_struct(ctx->types, st);
    return st;
}

const hfx_type *hfx_pb_struct(parse_ctx *ctx, const char *name, parse_vec fields, hfx_loc loc) {
    ctx->last_type = NULL;
    const hfx_type *type = NULL;
    hfx_struct *st = struct_object(ctx, name, loc, &type);
    if (!st) return hfx_type_scalar(ctx->types, B_FLOAT);
    if (st->fields) hfx_error(ctx->diags, loc, X_REDEFINITION, "redefinition of '%s'", name);
    st->loc = loc;
    st->fields = HFX_NEW_ARRAY(ctx->arena, hfx_field, fields.count ? fields.count : 1);
    st->field_count = st->fields ? fields.count : 0;
    for (uint32_t i = 0; i < st->field_count; i++) st->fields[i] = *(hfx_field *)fields.items[i];
    ctx->pending_struct = st;
    return type;
}

/* `struct B : A { ... }`: B has A's members first, then its own (fxc's struct inheritance). */
const hfx_type *hfx_pb_struct_derived(parse_ctx *ctx, const char *name, const hfx_type *base, parse_vec fields,
                                  hfx_loc loc) {
    parse_vec all = hfx_parse_vec_new();
    if (base && base->kind == TY_STRUCT) {
        for (uint32_t i = 0; i < base->st->field_count; i++) all = hfx_parse_vec_push(ctx, all, &base->st->fields[i]);
    } else {
        hfx_error(ctx->diags, loc, X_TYPE_MISMATCH, "'%s': a struct can only inherit from a struct", name);
    }
    for (uint32_t i = 0; i < fields.count; i++) all = hfx_parse_vec_push(ctx, all, fields.items[i]);
    return hfx_pb_struct(ctx, name, all, loc);
}

const hfx_type *hfx_pb_struct_ref(parse_ctx *ctx, const char *name, hfx_loc loc) {
    ctx->last_type = NULL;
    const hfx_type *type = NULL;
    (void)struct_object(ctx, name, loc, &type);
    return type ? type : hfx_type_scalar(ctx->types, B_FLOAT);
}
