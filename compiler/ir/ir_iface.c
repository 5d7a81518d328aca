/* ir_iface.c: the entry point's interface as (semantic, type, access path) leaves, each with its
 * place in IR terms (parameter and fields, for lower/varyings.c). Struct
 * parameters contribute one leaf per member with a semantic; semantics are compared
 * case-insensitively, POSITION meaning POSITION0. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#include "ir/ir.h"

const char *hfx_ir_canonical_semantic(hfx_arena *a, const char *semantic) {
    char buf[64];
    size_t n = 0;
    for (; semantic[n] && n < sizeof buf - 2; n++) buf[n] = (char)toupper((unsigned char)semantic[n]);
    buf[n] = 0;
    if (buf[0] == 'S' && buf[1] == 'V' && buf[2] == '_') {
        if (strncmp(buf + 3, "POSITION", 8) == 0) return hfx_ir_canonical_semantic(a, buf + 3);
        if (strncmp(buf + 3, "TARGET", 6) == 0) return hfx_arena_printf(a, "COLOR%s", buf[9] ? buf + 9 : "0");
        if (strncmp(buf + 3, "DEPTH", 5) == 0) return "DEPTH0";
    }
    if (n == 0 || !isdigit((unsigned char)buf[n - 1])) {
        buf[n++] = '0';
        buf[n] = 0;
    }
    return hfx_arena_strdup(a, buf);
}

typedef struct leaves { ir_leaf *items; uint32_t count, cap; bool bad; } leaves;

/* Where a value is: its GLSL access path from main's locals and its IR place (ir_leaf). */
typedef struct spot {
    const char *path;
    ir_var *root;
    uint32_t fields[IR_LEAF_DEPTH], depth;
    bool indexed;
} spot;

/* s one step further: field f (HFX_NONE: an array element or a matrix row), `path` its text. */
static spot spot_in(const spot *s, uint32_t f, const char *path) {
    spot r = *s;
    r.path = path;
    if (f == HFX_NONE || r.depth == IR_LEAF_DEPTH) r.indexed = true;
    else r.fields[r.depth++] = f;
    return r;
}

static void push(ir_ctx *c, leaves *l, const char *sem, const hfx_type *ty, const spot *s, hfx_loc loc, uint32_t mods) {
    if (!HFX_ARENA_GROW(c->arena, l->items, l->count, l->cap, 8)) return;
    ir_leaf *x = &l->items[l->count++];
    *x = (ir_leaf){ hfx_ir_canonical_semantic(c->arena, sem), ty, s->path, loc, NULL, NULL,
                    (mods & MOD_NOINTERPOLATION) != 0, mods, s->root, {0}, s->depth, s->indexed };
    memcpy(x->fields, s->fields, sizeof x->fields);
}

/* The semantic `k` registers after sem: TEXCOORD1 + 2 = TEXCOORD3. */
static const char *semantic_plus(ir_ctx *c, const char *sem, uint32_t k) {
    const char *canon = hfx_ir_canonical_semantic(c->arena, sem);
    size_t n = strlen(canon);
    while (n && isdigit((unsigned char)canon[n - 1])) n--;
    return hfx_arena_printf(c->arena, "%.*s%lu", (int)n, canon, strtoul(canon + n, NULL, 10) + k);
}

/* What a leaf belongs to, for the messages: an input or output parameter, or the return value.
 * Spelled out only when a message needs it. */
typedef struct owner { const char *fn; bool outputs, is_return; const char *param; } owner;

static const char *owner_text(ir_ctx *c, const owner *o) {
    if (o->is_return) return "function return value";
    return hfx_arena_printf(c->arena, "%s parameter '%s'", o->outputs ? "output" : "input", o->param);
}

static void walk(ir_ctx *c, leaves *l, const hfx_type *ty, const char *sem, const spot *at, hfx_loc loc,
                 const owner *o, uint32_t mods) {
    const char *path = at->path;
    if (ty->kind == TY_STRUCT) {
        for (uint32_t i = 0; i < ty->st->field_count; i++) {
            const hfx_field *f = &ty->st->fields[i];
            /* fxc lets an output struct carry members without a semantic: they go nowhere */
            if (o->outputs && !f->semantic && f->type->kind != TY_STRUCT) continue;
            spot s = spot_in(at, i, hfx_arena_printf(c->arena, "%s.%s", path, hfx_glsl_name(c->arena, f->name)));
            walk(c, l, f->type, f->semantic, &s, f->loc, o, f->mods);
        }
        return;
    }
    if (!sem) {
        hfx_error(c->diags, loc, 3502, "'%s': %s missing semantics", o->fn, owner_text(c, o));
        l->bad = true;
        return;
    }
    if (ty->kind == TY_ARRAY && ty->elem && ty->array_len) { /* `float2 uv[8] : TEXCOORD0`: one register each */
        for (uint32_t i = 0; i < ty->array_len; i++) {
            spot s = spot_in(at, HFX_NONE, hfx_arena_printf(c->arena, "%s[%u]", path, i));
            walk(c, l, ty->elem, semantic_plus(c, sem, i), &s, loc, o, mods);
        }
        return;
    }
    if (ty->kind == TY_MATRIX && ty->rows > 1 && ty->cols > 1) {
        for (uint32_t r = 0; r < ty->rows; r++) {
            spot s = spot_in(at, HFX_NONE, hfx_arena_printf(c->arena, "%s[%u]", path, r));
            push(c, l, semantic_plus(c, sem, r), hfx_type_vector(c->types, ty->base, ty->cols), &s, loc, mods);
        }
        if (l->count) l->items[l->count - 1].matrix_path = path, l->items[l->count - 1].matrix_type = ty;
        return;
    }
    if (!hfx_type_is_numeric(ty)) {
        hfx_error(c->diags, loc, X_UNSUPPORTED, "'%s': %s of this type cannot carry a semantic", o->fn, owner_text(c, o));
        l->bad = true;
        return;
    }
    push(c, l, sem, ty, at, loc, mods);
}

int hfx_ir_entry_leaves(ir_ctx *c, const ir_func *entry, bool outputs, ir_leaf **out) {
    leaves l = {0};
    for (uint32_t i = 0; i < entry->param_count; i++) {
        const ir_var *v = entry->params[i];
        bool is_out = (v->mods & MOD_OUT) != 0, is_in = !is_out || (v->mods & MOD_IN);
        if (outputs ? !is_out : !is_in) continue;
        owner o = {entry->name, outputs, false, v->name};
        spot s = {hfx_arena_printf(c->arena, "hfx_arg%u", i), entry->params[i], {0}, 0, false};
        walk(c, &l, v->type, v->decl ? v->decl->semantic : NULL, &s, v->decl ? v->decl->loc : entry->src->loc, &o, v->mods);
    }
    owner ret = {entry->name, outputs, true, NULL};
    if (outputs && entry->ret && entry->ret->kind != TY_VOID)
        walk(c, &l, entry->ret, entry->ret_semantic, &(spot){"hfx_ret", NULL, {0}, 0, false}, entry->src->loc, &ret, 0);
    *out = l.items;
    return l.bad ? -1 : (int)l.count;
}
