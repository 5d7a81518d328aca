/* d3d9_ir.c: a decoded shader to hfx's IR, with D3D9's register semantics:
 *  - r registers are float4 locals (zero at the start), a0 an int4 local;
 *  - c registers are read from the effect's parameters by the CTAB (the constant covering the
 *    register; a column-major matrix's register j is its column j, a row-major one's row j, an
 *    array's element by register), or `def` values; registers nothing covers read zero; relative
 *    reads (c[a0.x + n]) go through a local register file filled from the same reads;
 *  - v / t / vPos / vFace inputs and oPos / oD / oT / o / oC / oDepth outputs are the entry's
 *    parameters by semantic (dcl usage, or the fixed meaning of ps_2_x's v and t), so attributes,
 *    varyings and fragment outputs work as for a compiled entry; outputs start at zero;
 *  - s registers are the CTAB sampler parameters, of the dcl's dimension.
 *  - ps_1_x: t registers (1.1-1.3) are locals tex / texcoord fill, results and constants are
 *    clamped to the model's range, the pixel is r0 at the end (docs/d3d9.md).
 * Anything not handled (d3d9_ir_ops.c, d3d9_ir_flow.c) is a located X5006. */
#include "d3d9/d3d9_ir.h"

#include <stdio.h>

void hfx_d3d9_tx_fail(d3d9_tx *t, const char *fmt, ...) {
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (!t->failed) hfx_error(t->c->diags, t->loc, X_D3D9_UNSUPPORTED, "%s", msg);
    t->failed = true;
}

ir_expr *hfx_d3d9_tx_var(d3d9_tx *t, ir_var *v) {
    ir_expr *e = hfx_ir_new_expr(t->c, IE_VAR, v->type, t->loc, 0);
    e->var = v;
    return e;
}

/* Whether the operation of x works component by component, each result component from the same
 * component of every vector operand (the translator's arithmetic, comparisons, selects). */
static bool componentwise(const ir_expr *x) {
    switch (x->kind) {
    case IE_UNARY: return x->op == OP_NEG;
    case IE_BINARY: return x->op >= OP_ADD && x->op <= OP_NE && x->op != OP_MOD && (x->op < OP_SHL || x->op > OP_BITXOR);
    case IE_SELECT: case IE_CONVERT: return true;
    case IE_INTRIN:
        switch (x->intrin) {
        case HFX_INTR_ABS: case HFX_INTR_MIN: case HFX_INTR_MAX: case HFX_INTR_CLAMP: case HFX_INTR_SATURATE:
        case HFX_INTR_FRAC: case HFX_INTR_EXP2: case HFX_INTR_LOG2: case HFX_INTR_RSQRT: case HFX_INTR_SIGN:
        case HFX_INTR_LERP: case HFX_INTR_DDX: case HFX_INTR_DDY: case HFX_INTR_ROUND:
            return true;
        default: return false;
        }
    default: return false;
    }
}

/* x.comps with the swizzle moved onto x's operands, when x works component by component on
 * vectors as wide as itself (scalar operands stay as they are), or onto a constant's values: the
 * components an instruction's write mask drops are then not computed, and the GLSL says
 * `r2.w = r4.y * r4.x` for fxc's `mul r2.w, r4.y, r4.x` instead of a float4 product and a pick.
 * NULL when x is no such expression. */
static ir_expr *narrowed(d3d9_tx *t, ir_expr *x, const uint8_t *comps, unsigned n) {
    unsigned width = hfx_type_components(x->type);
    if (x->type->kind != TY_VECTOR || n >= width) return NULL;
    const hfx_type *ty = n == 1 ? hfx_type_scalar(t->c->types, x->type->base) : hfx_type_vector(t->c->types, x->type->base, n);
    if (x->kind == IE_CONST) {
        ir_expr *e = hfx_ir_new_expr(t->c, IE_CONST, ty, x->loc, 0);
        for (unsigned k = 0; k < n; k++) e->cval[k] = x->cval[comps[k]];
        return e;
    }
    if (!componentwise(x)) return NULL;
    for (uint32_t i = 0; i < x->n; i++) {
        const hfx_type *at = x->a[i]->type;
        if (!(at->kind == TY_SCALAR || (at->kind == TY_VECTOR && hfx_type_components(at) == width))) return NULL;
    }
    ir_expr *e = hfx_ir_new_expr(t->c, x->kind, ty, x->loc, x->n);
    e->op = x->op;
    e->intrin = x->intrin;
    for (uint32_t i = 0; i < x->n; i++)
        e->a[i] = x->a[i]->type->kind == TY_SCALAR ? x->a[i] : hfx_d3d9_tx_swizzle(t, x->a[i], comps, n);
    return e;
}

/* The value x.comps already is without a swizzle: x itself (every component in order), or the
 * part a splat or a float4 padding was made from; NULL when there is none. */
static ir_expr *unswizzled(d3d9_tx *t, ir_expr *x, const uint8_t *comps, unsigned n) {
    bool in_order = true;
    unsigned top = 0;
    for (unsigned k = 0; k < n; k++) {
        in_order &= comps[k] == k;
        if (comps[k] > top) top = comps[k];
    }
    hfx_type_kind kind = x->type->kind;
    if (in_order && (kind == TY_VECTOR || kind == TY_SCALAR) && hfx_type_components(x->type) == n) return x;
    ir_expr *a = x->n ? x->a[0] : NULL;
    if (x->kind == IE_CONVERT && a && a->type->kind == TY_SCALAR) { /* a splat: n copies of a */
        const hfx_type *ty = n == 1 ? hfx_type_scalar(t->c->types, x->type->base) : hfx_type_vector(t->c->types, x->type->base, n);
        return hfx_type_equal(ty, a->type) ? a : hfx_ir_new_convert(t->c, ty, a);
    }
    if (x->kind == IE_CONSTRUCT && a && a->type->kind == TY_VECTOR && a->type->base == x->type->base &&
        top < hfx_type_components(a->type)) /* float4(v, 0...) read inside v */
        return hfx_d3d9_tx_swizzle(t, a, comps, n);
    return narrowed(t, x, comps, n);
}

/* x.comps; a swizzle of a swizzle is one, and what unswizzled finds has none. The translator
 * swizzles every register it reads and every value it writes: without this the GLSL spelled
 * `vec4(dot(a, b)).x` and `r0.xxxx.x` for each scalar instruction. */
ir_expr *hfx_d3d9_tx_swizzle(d3d9_tx *t, ir_expr *x, const uint8_t *comps, unsigned n) {
    uint8_t both[4];
    if (x->kind == IE_SWIZZLE) {
        for (unsigned k = 0; k < n; k++) both[k] = x->comps[comps[k]];
        comps = both;
        x = x->a[0];
    }
    ir_expr *plain = unswizzled(t, x, comps, n);
    if (plain) return plain;
    hfx_base b = x->type->base;
    ir_expr *e = hfx_ir_new_expr(t->c, IE_SWIZZLE, n == 1 ? hfx_type_scalar(t->c->types, b)
                                                      : hfx_type_vector(t->c->types, b, n), t->loc, 1);
    e->a[0] = x;
    memcpy(e->comps, comps, n);
    e->comp_count = (uint8_t)n;
    return e;
}

ir_expr *hfx_d3d9_tx_const4(d3d9_tx *t, const float v[4]) {
    ir_expr *e = hfx_ir_new_expr(t->c, IE_CONST, t->f4, t->loc, 0);
    for (int k = 0; k < 4; k++) e->cval[k] = v[k];
    return e;
}

ir_expr *hfx_d3d9_tx_float4(d3d9_tx *t, ir_expr *x) {
    unsigned n = hfx_type_components(x->type);
    if (n == 4 && x->type->kind == TY_VECTOR) return x;
    if (n == 1) return hfx_ir_new_convert(t->c, t->f4, x);
    ir_expr *e = hfx_ir_new_expr(t->c, IE_CONSTRUCT, t->f4, t->loc, 1 + (4 - n));
    e->a[0] = x;
    for (unsigned k = n; k < 4; k++) e->a[1 + k - n] = hfx_ir_const_scalar(t->c, t->f1, 0, t->loc);
    return e;
}

void hfx_d3d9_tx_add(d3d9_tx *t, uint32_t block, ir_stmt *s) {
    ir_stmt *b = t->blocks[block].s;
    if (!HFX_ARENA_GROW(t->c->arena, b->body, b->count, t->blocks[block].cap, 16)) return;
    b->body[b->count++] = s;
}

void hfx_d3d9_tx_emit(d3d9_tx *t, ir_expr *e) {
    ir_stmt *s = hfx_ir_new_stmt(t->c, IS_EXPR, t->loc);
    s->expr = e;
    hfx_d3d9_tx_add(t, t->depth, s);
}

static hfx_decl *fake_decl(d3d9_tx *t, hfx_decl_kind k, const char *name, const hfx_type *ty, uint32_t mods,
                           const char *semantic) {
    hfx_decl *d = HFX_NEW(t->c->arena, hfx_decl);
    d->kind = k;
    d->loc = t->loc;
    d->name = name;
    d->type = ty;
    d->mods = mods;
    d->semantic = semantic;
    return d;
}

/* A local of the entry, declared (zero) in the prologue. */
static ir_var *new_local(d3d9_tx *t, const char *name, const hfx_type *ty) {
    ir_var *v = HFX_NEW(t->c->arena, ir_var);
    v->kind = IRV_LOCAL;
    v->decl = fake_decl(t, DECL_VAR, name, ty, 0, NULL);
    v->name = name;
    v->glsl = name;
    v->type = ty;
    v->param = HFX_NONE;
    ir_stmt *s = hfx_ir_new_stmt(t->c, IS_DECL, t->loc);
    s->var = v;
    s->expr = ty->kind == TY_ARRAY ? NULL : hfx_ir_const_scalar(t->c, ty, 0, t->loc);
    hfx_d3d9_tx_add(t, 0, s);
    return v;
}

ir_var *hfx_d3d9_tx_local(d3d9_tx *t, const char *name, const hfx_type *ty) { return new_local(t, name, ty); }

static ir_var *new_param(d3d9_tx *t, const char *name, const hfx_type *ty, bool out, const char *semantic) {
    ir_var *v = HFX_NEW(t->c->arena, ir_var);
    v->kind = IRV_PARAM;
    v->mods = out ? MOD_OUT : MOD_IN;
    v->decl = fake_decl(t, DECL_PARAM, name, ty, v->mods, semantic);
    v->name = name;
    v->glsl = name;
    v->type = ty;
    v->param = HFX_NONE;
    if (HFX_ARENA_GROW(t->c->arena, t->params, t->param_count, t->param_cap, 8)) t->params[t->param_count++] = v;
    if (out) { /* D3D9 leaves unwritten output components undefined; hfx makes them zero */
        ir_expr *e = hfx_ir_new_expr(t->c, IE_ASSIGN, ty, t->loc, 2);
        e->op = OP_NONE;
        e->a[0] = hfx_d3d9_tx_var(t, v);
        e->a[1] = hfx_ir_const_scalar(t->c, ty, 0, t->loc);
        ir_stmt *s = hfx_ir_new_stmt(t->c, IS_EXPR, t->loc);
        s->expr = e;
        hfx_d3d9_tx_add(t, 0, s);
    }
    return v;
}

static const char *usage_semantic(d3d9_tx *t, unsigned usage, unsigned index) {
    static const char *const names[] = {"POSITION", "BLENDWEIGHT", "BLENDINDICES", "NORMAL", "PSIZE", "TEXCOORD",
                                        "TANGENT", "BINORMAL", "TESSFACTOR", "POSITIONT", "COLOR", "FOG", "DEPTH",
                                        "SAMPLE"};
    return hfx_arena_printf(t->c->arena, "%s%u", names[usage < 14 ? usage : 0], index);
}

/* The dcl of a register, or NULL. */
static const d3d9_inst *find_dcl(const d3d9_shader *s, unsigned type, unsigned num) {
    for (uint32_t i = 0; i < s->inst_count; i++)
        if (s->insts[i].op == D3D9_DCL && s->insts[i].dst.type == type && s->insts[i].dst.num == num) return &s->insts[i];
    return NULL;
}

/* An input register's parameter: vs and ps_3_0 by their dcl's usage; ps_2_x's v by COLOR, t by TEXCOORD. */
static ir_var *input(d3d9_tx *t, unsigned type, unsigned num) {
    int slot = type == D3D9_REG_INPUT ? 0 : type == D3D9_REG_ADDR ? 1 : 2;
    if (num >= 16) return NULL;
    if (t->inputs[slot][num]) return t->inputs[slot][num];
    const d3d9_shader *s = t->s;
    const char *sem;
    const hfx_type *ty = t->f4;
    if (slot == 2) {
        sem = num == 0 ? "VPOS" : "VFACE";
        ty = num == 0 ? t->f2 : t->f1;
    } else if (slot == 1 || (s->stage == D3D9_PS && s->model < D3D9_SM(3, 0))) {
        sem = hfx_arena_printf(t->c->arena, "%s%u", slot == 1 ? "TEXCOORD" : "COLOR", num);
    } else {
        const d3d9_inst *d = find_dcl(s, type, num);
        if (!d) { hfx_d3d9_tx_fail(t, "v%u is read but never declared", num); return NULL; }
        sem = usage_semantic(t, d->usage, d->usage_index);
    }
    return t->inputs[slot][num] = new_param(t, hfx_arena_printf(t->c->arena, "hfx_in_%s", sem), ty, false, sem);
}

/* An output register's parameter. */
static ir_var *output(d3d9_tx *t, unsigned type, unsigned num) {
    int slot = type == D3D9_REG_RASTOUT ? 0 : type == D3D9_REG_ATTROUT ? 1 : type == D3D9_REG_OUTPUT ? 2
             : type == D3D9_REG_COLOROUT ? 3 : 4;
    if (num >= 12) return NULL;
    if (t->outputs[slot][num]) return t->outputs[slot][num];
    const char *sem;
    const hfx_type *ty = t->f4;
    switch (slot) {
    case 0: sem = num == 0 ? "POSITION0" : num == 1 ? "FOG0" : "PSIZE0"; if (num) ty = t->f1; break;
    case 1: sem = hfx_arena_printf(t->c->arena, "COLOR%u", num); break;
    case 2:
        if (t->s->model >= D3D9_SM(3, 0)) {
            const d3d9_inst *d = find_dcl(t->s, type, num);
            if (!d) { hfx_d3d9_tx_fail(t, "o%u is written but never declared", num); return NULL; }
            sem = usage_semantic(t, d->usage, d->usage_index);
            if (d->usage == 4 || d->usage == 11) ty = t->f1; /* psize, fog */
        } else sem = hfx_arena_printf(t->c->arena, "TEXCOORD%u", num);
        break;
    case 3: sem = hfx_arena_printf(t->c->arena, "COLOR%u", num); break;
    default: sem = "DEPTH0"; ty = t->f1; break;
    }
    return t->outputs[slot][num] = new_param(t, hfx_arena_printf(t->c->arena, "hfx_out_%s", sem), ty, true, sem);
}

/* The CTAB constant of a register set covering register n, or -1. */
static int constant_at(const d3d9_shader *s, unsigned set, unsigned n) {
    for (uint32_t i = 0; i < s->constant_count; i++) {
        const d3d9_constant *k = &s->constants[i];
        if (k->regset == set && n >= k->reg && n < (unsigned)k->reg + k->count) return (int)i;
    }
    return -1;
}

/* The effect parameter a CTAB constant names: its uniform (or sampler) variable, made once. */
static ir_var *constant_var(d3d9_tx *t, uint32_t i, ir_var_kind kind, const hfx_type *ty) {
    if (t->consts[i]) return t->consts[i];
    const d3d9_constant *k = &t->s->constants[i];
    const hfx_fx_effect *fx = t->c->fx;
    uint32_t p = HFX_NONE;
    for (uint32_t j = 0; fx && j < fx->top_param_count && j < fx->param_count; j++)
        if (fx->params[j].name && strcmp(fx->params[j].name, k->name) == 0) { p = j; break; }
    if (p == HFX_NONE || !fx->params[p].glsl_name) {
        hfx_d3d9_tx_fail(t, "constant '%s' names no parameter of the effect", k->name);
        return NULL;
    }
    /* fxc lists a parameter once per register set it uses (an int in c for arithmetic and in i
     * for a loop): one variable, so the GLSL declares the uniform once */
    for (uint32_t j = 0; j < t->s->constant_count; j++) {
        ir_var *o = t->consts[j];
        if (!o || o->param != p) continue;
        if (o->kind == kind && hfx_type_equal(o->type, ty)) return t->consts[i] = o;
        hfx_d3d9_tx_fail(t, "constant '%s' is read as two different types", k->name);
        return NULL;
    }
    ir_var *v = HFX_NEW(t->c->arena, ir_var);
    v->kind = kind;
    v->name = k->name;
    v->glsl = fx->params[p].glsl_name;
    v->type = ty;
    v->param = p;
    hfx_decl *d = fake_decl(t, DECL_VAR, k->name, ty, 0, NULL);
    d->is_global = true;
    d->index = p;
    v->decl = d;
    return t->consts[i] = v;
}

/* The HLSL type of a float CTAB constant (one element). */
/* The HLSL type of a constant in float registers (one element): fxc keeps int and bool
 * parameters used in arithmetic there, so the parameter keeps its own type and is converted. */
static const hfx_type *constant_type(d3d9_tx *t, const d3d9_constant *k) {
    unsigned r = k->rows ? k->rows : 1, c = k->cols ? k->cols : 1;
    hfx_base b = k->type == 1 ? B_BOOL : k->type == 2 ? B_INT : k->type == 3 ? B_FLOAT : B_NONE;
    if (r > 4 || c > 4 || b == B_NONE) return NULL;
    if (k->cls == 0) return hfx_type_scalar(t->c->types, b);
    if (k->cls == 1) return hfx_type_vector(t->c->types, b, c);
    if (k->cls == 2 || k->cls == 3) return hfx_type_matrix(t->c->types, b, r, c);
    return NULL;
}

/* x (a scalar or vector of the constant's base) as float4, for a register read. */
static ir_expr *register_value(d3d9_tx *t, ir_expr *x) {
    if (x->type->base != B_FLOAT) {
        unsigned n = hfx_type_components(x->type);
        x = hfx_ir_new_convert(t->c, n == 1 ? t->f1 : hfx_type_vector(t->c->types, B_FLOAT, n), x);
    }
    return hfx_d3d9_tx_float4(t, x);
}

/* Register `num` of the float constant i: column j of a column-major matrix, row j of a row-major
 * one, the value of a scalar or vector; arrays by element. */
static ir_expr *constant_register(d3d9_tx *t, uint32_t i, unsigned num) {
    const d3d9_constant *k = &t->s->constants[i];
    const hfx_type *el = constant_type(t, k);
    if (!el) { hfx_d3d9_tx_fail(t, "constant '%s' of this type is not supported yet", k->name); return NULL; }
    unsigned per = k->cls == 3 ? el->cols : k->cls == 2 ? el->rows : 1, elems = k->elements > 1 ? k->elements : 1;
    const hfx_type *ty = elems > 1 ? hfx_type_array(t->c->types, el, elems) : el;
    ir_var *v = constant_var(t, i, IRV_UNIFORM, ty);
    if (!v) return NULL;
    unsigned off = num - k->reg, e = off / per, j = off % per;
    ir_expr *x = hfx_d3d9_tx_var(t, v);
    if (elems > 1) {
        if (e >= elems) return hfx_d3d9_tx_const4(t, (const float[4]){0, 0, 0, 0});
        ir_expr *ix = hfx_ir_new_expr(t->c, IE_INDEX, el, t->loc, 2);
        ix->a[0] = x;
        ix->a[1] = hfx_ir_const_scalar(t->c, t->i1, e, t->loc);
        ix->range = IR_RANGE_IN_BOUNDS;
        x = ix;
    }
    if (k->cls == 2 || k->cls == 3) {
        uint8_t comps[4];
        unsigned n = k->cls == 3 ? el->rows : el->cols;
        for (unsigned q = 0; q < n; q++) comps[q] = (uint8_t)(k->cls == 3 ? q * el->cols + j : j * el->cols + q);
        x = hfx_d3d9_tx_swizzle(t, x, comps, n);
    }
    return register_value(t, x);
}

/* Register num of preshader output i: the variable codegen gives hfx_c registers (glsl_pack.c);
 * a b# or i# output is a float4 there too, converted where the shader reads it. */
static ir_expr *preshader_register(d3d9_tx *t, uint32_t i, unsigned num) {
    const d3d9_preshader_out *o = &t->s->pres[i];
    if (!t->pres[i]) {
        if (!t->pack) {
            hfx_d3d9_tx_fail(t, "preshaders need packed registers (HFXC_PACK_UNIFORMS)");
            return NULL;
        }
        ir_var *v = HFX_NEW(t->c->arena, ir_var);
        v->kind = IRV_PRIVATE;
        v->name = v->glsl = hfx_arena_printf(t->c->arena, "hfx_pre_%c%u", "cbi"[o->file], o->reg);
        v->type = o->count == 1 ? t->f4 : hfx_type_matrix(t->c->types, B_FLOAT, o->count, 4);
        v->param = HFX_NONE;
        v->pre = hfx_d3d9_tx_const4(t, (const float[4]){0, 0, 0, 0}); /* marks it a preshader; never evaluated here */
        v->pre_code = o->code;
        v->pre_words = o->words;
        v->pre_text = o->text ? o->text : hfx_arena_printf(t->c->arena, "%c%u", "cbi"[o->file], o->reg);
        if (!HFX_ARENA_GROW(t->c->arena, t->sh->pres, t->sh->pre_count, t->sh->pre_cap, 4)) return NULL;
        t->sh->pres[t->sh->pre_count++] = v;
        t->pres[i] = v;
    }
    ir_expr *x = hfx_d3d9_tx_var(t, t->pres[i]);
    if (o->count == 1) return x;
    unsigned row = num - o->reg;
    const uint8_t comps[4] = {(uint8_t)(row * 4), (uint8_t)(row * 4 + 1), (uint8_t)(row * 4 + 2), (uint8_t)(row * 4 + 3)};
    return hfx_d3d9_tx_swizzle(t, x, comps, 4);
}

/* The preshader output setting register num of a file, or -1. */
static int preshader_of(const d3d9_shader *s, d3d9_pre_file file, unsigned num) {
    for (uint32_t i = 0; i < s->pre_count; i++)
        if (s->pres[i].file == file && num >= s->pres[i].reg && num < s->pres[i].reg + s->pres[i].count &&
            s->pres[i].count <= 4)
            return (int)i;
    return -1;
}

/* A c register as float4: its def, a preshader's output, the parameter covering it, or zero. */
static ir_expr *const_register(d3d9_tx *t, unsigned num) {
    for (uint32_t i = 0; i < t->s->inst_count; i++) {
        const d3d9_inst *in = &t->s->insts[i];
        if (in->op == D3D9_DEF && in->dst.num == num) return hfx_d3d9_tx_const4(t, in->value.f);
    }
    int pre = preshader_of(t->s, D3D9_PRE_C, num);
    if (pre >= 0) return preshader_register(t, (uint32_t)pre, num);
    int k = constant_at(t->s, D3D9_RS_FLOAT4, num);
    if (k >= 0) return constant_register(t, (uint32_t)k, num);
    return hfx_d3d9_tx_const4(t, (const float[4]){0, 0, 0, 0});
}

/* Whether a `def` sets c register num. */
static bool def_at(const d3d9_shader *s, unsigned num) {
    for (uint32_t i = 0; i < s->inst_count; i++)
        if (s->insts[i].op == D3D9_DEF && s->insts[i].dst.num == num) return true;
    return false;
}

/* The register file for relative reads: every c register up to the highest one declared or
 * defined, filled once at the start. */
static ir_var *register_file(d3d9_tx *t) {
    if (t->regfile) return t->regfile;
    unsigned n = 0;
    for (uint32_t i = 0; i < t->s->constant_count; i++)
        if (t->s->constants[i].regset == D3D9_RS_FLOAT4 && (unsigned)t->s->constants[i].reg + t->s->constants[i].count > n)
            n = t->s->constants[i].reg + t->s->constants[i].count;
    for (uint32_t i = 0; i < t->s->inst_count; i++)
        if (t->s->insts[i].op == D3D9_DEF && t->s->insts[i].dst.num + 1u > n) n = t->s->insts[i].dst.num + 1u;
    if (!n) n = 1;
    if (n > HFX_FX_MAX_REGS) { hfx_d3d9_tx_fail(t, "relative addressing over %u registers", n); return NULL; }
    t->regfile = new_local(t, "hfx_c_file", hfx_type_array(t->c->types, t->f4, n));
    t->regfile_size = n;
    for (unsigned r = 0; r < n && !t->failed; r++) {
        ir_expr *ix = hfx_ir_new_expr(t->c, IE_INDEX, t->f4, t->loc, 2);
        ix->a[0] = hfx_d3d9_tx_var(t, t->regfile);
        ix->a[1] = hfx_ir_const_scalar(t->c, t->i1, r, t->loc);
        ix->range = IR_RANGE_IN_BOUNDS;
        ir_expr *as = hfx_ir_new_expr(t->c, IE_ASSIGN, t->f4, t->loc, 2);
        as->op = OP_NONE;
        as->a[0] = ix;
        as->a[1] = const_register(t, r);
        ir_stmt *s = hfx_ir_new_stmt(t->c, IS_EXPR, t->loc);
        s->expr = as;
        hfx_d3d9_tx_add(t, 0, s);
    }
    return t->regfile;
}

static ir_expr *int_op(d3d9_tx *t, hfx_op op, ir_expr *a, int k) {
    return hfx_ir_new_binary(t->c, op, t->i1, a, hfx_ir_const_scalar(t->c, t->i1, k, t->loc));
}

/* `type local = e;` declared where the instruction that reads it is; the local's value. */
static ir_expr *held(d3d9_tx *t, const char *name, ir_expr *e) {
    ir_var *v = HFX_NEW(t->c->arena, ir_var);
    v->kind = IRV_LOCAL;
    v->name = v->glsl = hfx_arena_printf(t->c->arena, "%s%u", name, t->held_count++);
    v->decl = fake_decl(t, DECL_VAR, v->name, e->type, 0, NULL);
    v->type = e->type;
    v->param = HFX_NONE;
    ir_stmt *s = hfx_ir_new_stmt(t->c, IS_DECL, t->loc);
    s->var = v;
    s->expr = e;
    hfx_d3d9_tx_add(t, t->depth, s);
    return hfx_d3d9_tx_var(t, v);
}

/* A relative read inside an array constant (fxc's indexing of `float4x3 Bones[72]`): the
 * element and, for matrices, the row or column, from the index; past the array it reads zero.
 * The element (bounds-checked) and the register within it are read once into locals: a column
 * register gathers one component of each row, and repeating the checked read and the division
 * for each made skinned shaders far longer for drivers to compile (bench/bench_fx2_load). */
static ir_expr *array_register(d3d9_tx *t, uint32_t i, ir_expr *idx) {
    const d3d9_constant *k = &t->s->constants[i];
    const hfx_type *el = constant_type(t, k);
    if (!el) { hfx_d3d9_tx_fail(t, "constant '%s' of this type is not supported yet", k->name); return NULL; }
    unsigned per = k->cls == 3 ? el->cols : k->cls == 2 ? el->rows : 1;
    ir_var *v = constant_var(t, i, IRV_UNIFORM, hfx_type_array(t->c->types, el, k->elements));
    if (!v) return NULL;
    ir_expr *off = int_op(t, OP_SUB, idx, k->reg);
    if (per > 1) off = held(t, "hfx_rel_reg", off);
    ir_expr *e = hfx_ir_new_expr(t->c, IE_INDEX, el, t->loc, 2);
    e->a[0] = hfx_d3d9_tx_var(t, v);
    e->a[1] = per > 1 ? int_op(t, OP_DIV, off, (int)per) : off;
    e->range = IR_RANGE_ANY;
    if (k->cls != 2 && k->cls != 3) return register_value(t, e);
    e = held(t, "hfx_rel_elem", e);
    ir_expr *j = int_op(t, OP_MOD, hfx_ir_clone_expr(t->c, off), (int)per);
    if (k->cls == 2) { /* row j */
        ir_expr *row = hfx_ir_new_expr(t->c, IE_INDEX, hfx_type_vector(t->c->types, el->base, el->cols), t->loc, 2);
        row->a[0] = e;
        row->a[1] = j;
        row->range = IR_RANGE_IN_BOUNDS;
        return register_value(t, row);
    }
    j = held(t, "hfx_rel_comp", j);
    ir_expr *col = hfx_ir_new_expr(t->c, IE_CONSTRUCT, hfx_type_vector(t->c->types, el->base, el->rows), t->loc, el->rows);
    for (unsigned q = 0; q < el->rows; q++) { /* column j: element q of each row */
        ir_expr *row = hfx_ir_new_expr(t->c, IE_INDEX, hfx_type_vector(t->c->types, el->base, el->cols), t->loc, 2);
        row->a[0] = hfx_ir_clone_expr(t->c, e);
        row->a[1] = hfx_ir_const_scalar(t->c, t->i1, q, t->loc);
        row->range = IR_RANGE_IN_BOUNDS;
        ir_expr *c = hfx_ir_new_expr(t->c, IE_INDEX, hfx_type_scalar(t->c->types, el->base), t->loc, 2);
        c->a[0] = row;
        c->a[1] = hfx_ir_clone_expr(t->c, j);
        c->range = IR_RANGE_IN_BOUNDS;
        col->a[q] = c;
    }
    return register_value(t, el->rows == 1 ? col->a[0] : col);
}

/* c[a0.x + n] or c[aL + n]. */
static ir_expr *relative_const(d3d9_tx *t, const d3d9_src *x) {
    ir_var *base = x->rel_type == D3D9_REG_ADDR ? t->a0 : t->aL;
    if (!base) { hfx_d3d9_tx_fail(t, "relative addressing through a register never written"); return NULL; }
    ir_expr *idx = x->rel_type == D3D9_REG_ADDR ? hfx_d3d9_tx_swizzle(t, hfx_d3d9_tx_var(t, base), &x->rel_comp, 1)
                                                : hfx_d3d9_tx_var(t, base);
    if (x->num) idx = hfx_ir_new_binary(t->c, OP_ADD, t->i1, idx, hfx_ir_const_scalar(t->c, t->i1, x->num, t->loc));
    int k = constant_at(t->s, D3D9_RS_FLOAT4, x->num);
    if (k >= 0 && t->s->constants[k].elements > 1) return array_register(t, (uint32_t)k, idx);
    ir_var *file = register_file(t);
    if (!file) return NULL;
    ir_expr *ix = hfx_ir_new_expr(t->c, IE_INDEX, t->f4, t->loc, 2);
    ix->a[0] = hfx_d3d9_tx_var(t, file);
    ix->a[1] = idx;
    ix->range = IR_RANGE_ANY;
    return ix;
}

bool hfx_d3d9_tx_ps1(const d3d9_tx *t) { return t->s->stage == D3D9_PS && t->s->model < D3D9_SM(2, 0); }

ir_var *hfx_d3d9_tx_texcoord(d3d9_tx *t, unsigned n) { return input(t, D3D9_REG_ADDR, n); }

/* ps_1_1..1_3's t registers: what tex / texcoord put there. */
static ir_var *texture_register(d3d9_tx *t, unsigned num) {
    if (num >= 8) return NULL;
    if (!t->texregs[num]) t->texregs[num] = new_local(t, hfx_arena_printf(t->c->arena, "hfx_t%u", num), t->f4);
    return t->texregs[num];
}

ir_expr *hfx_d3d9_tx_reg(d3d9_tx *t, unsigned type, unsigned num) {
    ir_var *v = NULL;
    switch (type) {
    case D3D9_REG_TEMP:
        if (num >= 32) break;
        if (!t->temps[num]) t->temps[num] = new_local(t, hfx_arena_printf(t->c->arena, "hfx_r%u", num), t->f4);
        v = t->temps[num];
        break;
    case D3D9_REG_CONST:
        if (hfx_d3d9_tx_ps1(t)) { /* ps_1_x constants are clamped to [-1, 1] when read */
            ir_expr *x = const_register(t, num);
            if (!x || x->kind == IE_CONST) {
                for (int q = 0; x && q < 4; q++) x->cval[q] = x->cval[q] < -1 ? -1 : x->cval[q] > 1 ? 1 : x->cval[q];
                return x;
            }
            ir_expr *c = hfx_ir_new_expr(t->c, IE_INTRIN, t->f4, t->loc, 3);
            c->intrin = HFX_INTR_CLAMP;
            c->a[0] = x;
            c->a[1] = hfx_ir_const_scalar(t->c, t->f4, -1, t->loc);
            c->a[2] = hfx_ir_const_scalar(t->c, t->f4, 1, t->loc);
            return c;
        }
        return const_register(t, num);
    case D3D9_REG_PREDICATE:
        if (!t->p0) t->p0 = new_local(t, "hfx_p0", t->b4);
        return hfx_d3d9_tx_var(t, t->p0);
    case D3D9_REG_CONSTBOOL: { ir_expr *b = hfx_d3d9_tx_bool(t, num); return b ? hfx_ir_new_convert(t->c, t->b4, b) : NULL; }
    case D3D9_REG_INPUT: case D3D9_REG_MISC: v = input(t, type, num); break;
    case D3D9_REG_RASTOUT: case D3D9_REG_ATTROUT: case D3D9_REG_OUTPUT: case D3D9_REG_COLOROUT: case D3D9_REG_DEPTHOUT:
        v = output(t, type, num); /* the old value, for a predicated write */
        break;
    case D3D9_REG_ADDR:
        if (t->s->stage == D3D9_PS && t->s->model < D3D9_SM(1, 4)) { v = texture_register(t, num); break; }
        if (t->s->stage == D3D9_PS) { v = input(t, type, num); break; }
        hfx_d3d9_tx_fail(t, "a0 read as a value");
        return NULL;
    default:
        hfx_d3d9_tx_fail(t, "reading register type %u is not supported yet", type);
        return NULL;
    }
    if (!v) return NULL;
    return hfx_d3d9_tx_float4(t, hfx_d3d9_tx_var(t, v));
}

/* Source modifiers of SM2+ (ps_1_x's are refused with the model). */
static ir_expr *modify(d3d9_tx *t, ir_expr *x, unsigned mod) {
    if (x->type->base == B_BOOL) {
        if (mod == D3D9_SMOD_NOT) {
            ir_expr *n = hfx_ir_new_expr(t->c, IE_UNARY, x->type, t->loc, 1);
            n->op = OP_NOT;
            n->a[0] = x;
            return n;
        }
        if (mod != D3D9_SMOD_NONE) { hfx_d3d9_tx_fail(t, "source modifier %u on a bool is not supported", mod); return NULL; }
        return x;
    }
    if (mod == D3D9_SMOD_ABS || mod == D3D9_SMOD_ABSNEG) {
        ir_expr *a = hfx_ir_new_expr(t->c, IE_INTRIN, t->f4, t->loc, 1);
        a->intrin = HFX_INTR_ABS;
        a->a[0] = x;
        x = a;
    }
    if (mod == D3D9_SMOD_NEG || mod == D3D9_SMOD_ABSNEG) {
        ir_expr *n = hfx_ir_new_expr(t->c, IE_UNARY, t->f4, t->loc, 1);
        n->op = OP_NEG;
        n->a[0] = x;
        x = n;
    }
    if (mod == D3D9_SMOD_NONE || mod == D3D9_SMOD_NEG || mod == D3D9_SMOD_ABS || mod == D3D9_SMOD_ABSNEG) return x;
    /* ps_1_x: bias x - 0.5, bx2 2x - 1, comp 1 - x, x2 2x, each optionally negated */
    float mul = 1, add = 0;
    switch (mod) {
    case D3D9_SMOD_BIAS: add = -0.5f; break;
    case D3D9_SMOD_BIASNEG: mul = -1; add = 0.5f; break;
    case D3D9_SMOD_SIGN: mul = 2; add = -1; break;
    case D3D9_SMOD_SIGNNEG: mul = -2; add = 1; break;
    case D3D9_SMOD_COMP: mul = -1; add = 1; break;
    case D3D9_SMOD_X2: mul = 2; break;
    case D3D9_SMOD_X2NEG: mul = -2; break;
    default: hfx_d3d9_tx_fail(t, "source modifier %u is not supported here", mod); return NULL;
    }
    if (mul != 1) x = hfx_ir_new_binary(t->c, OP_MUL, t->f4, x, hfx_ir_const_scalar(t->c, t->f4, mul, t->loc));
    if (add != 0) x = hfx_ir_new_binary(t->c, OP_ADD, t->f4, x, hfx_ir_const_scalar(t->c, t->f4, add, t->loc));
    return x;
}

ir_expr *hfx_d3d9_tx_read(d3d9_tx *t, const d3d9_src *x) {
    ir_expr *r = NULL;
    if (x->relative) {
        if (x->type != D3D9_REG_CONST) { hfx_d3d9_tx_fail(t, "relative addressing of register type %u is not supported yet", x->type); return NULL; }
        r = relative_const(t, x);
    } else r = hfx_d3d9_tx_reg(t, x->type, x->num);
    if (!r) return NULL;
    if (x->swizzle != 0xe4) {
        uint8_t comps[4] = {x->swizzle & 3, (x->swizzle >> 2) & 3, (x->swizzle >> 4) & 3, (x->swizzle >> 6) & 3};
        r = hfx_d3d9_tx_swizzle(t, r, comps, 4);
    }
    return modify(t, r, x->mod);
}

/* The def* instruction defining register num of a type, or NULL. */
static const d3d9_inst *find_def(const d3d9_shader *s, unsigned op, unsigned num) {
    for (uint32_t i = 0; i < s->inst_count; i++)
        if (s->insts[i].op == op && s->insts[i].dst.num == num) return &s->insts[i];
    return NULL;
}

ir_expr *hfx_d3d9_tx_bool(d3d9_tx *t, unsigned num) {
    const hfx_type *b1 = hfx_type_scalar(t->c->types, B_BOOL);
    const d3d9_inst *d = find_def(t->s, D3D9_DEFB, num);
    if (d) return hfx_ir_const_scalar(t->c, b1, d->value.u[0] != 0, t->loc);
    int pre = preshader_of(t->s, D3D9_PRE_B, num);
    if (pre >= 0) { /* the preshader's x, as D3DX sets a bool register from a float: nonzero is true */
        ir_expr *x = preshader_register(t, (uint32_t)pre, num);
        static const uint8_t first = 0;
        return x ? hfx_ir_new_binary(t->c, OP_NE, b1, hfx_d3d9_tx_swizzle(t, x, &first, 1),
                                     hfx_ir_const_scalar(t->c, t->f1, 0, t->loc)) : NULL;
    }
    int k = constant_at(t->s, D3D9_RS_BOOL, num);
    if (k < 0) return hfx_ir_const_scalar(t->c, b1, 0, t->loc);
    const d3d9_constant *c = &t->s->constants[k];
    if (c->count > 1 || c->elements > 1 || c->cls != 0) { hfx_d3d9_tx_fail(t, "bool constant '%s' of this shape is not supported yet", c->name); return NULL; }
    ir_var *v = constant_var(t, (uint32_t)k, IRV_UNIFORM, b1);
    return v ? hfx_d3d9_tx_var(t, v) : NULL;
}

ir_expr *hfx_d3d9_tx_int4(d3d9_tx *t, unsigned num) {
    const d3d9_inst *d = find_def(t->s, D3D9_DEFI, num);
    if (d) {
        ir_expr *e = hfx_ir_new_expr(t->c, IE_CONST, t->i4, t->loc, 0);
        for (int q = 0; q < 4; q++) e->cval[q] = d->value.i[q];
        return e;
    }
    int pre = preshader_of(t->s, D3D9_PRE_I, num);
    if (pre >= 0) { /* each component truncated, as D3DX converts a float for an int register */
        ir_expr *x = preshader_register(t, (uint32_t)pre, num);
        return x ? hfx_ir_new_convert(t->c, t->i4, x) : NULL;
    }
    int k = constant_at(t->s, D3D9_RS_INT4, num);
    if (k < 0) return hfx_ir_const_scalar(t->c, t->i4, 0, t->loc);
    const d3d9_constant *c = &t->s->constants[k];
    if (c->count > 1 || c->elements > 1 || c->cls > 1 || c->cols > 4) { hfx_d3d9_tx_fail(t, "int constant '%s' of this shape is not supported yet", c->name); return NULL; }
    const hfx_type *ty = c->cls == 0 ? t->i1 : hfx_type_vector(t->c->types, B_INT, c->cols ? c->cols : 1);
    ir_var *v = constant_var(t, (uint32_t)k, IRV_UNIFORM, ty);
    if (!v) return NULL;
    unsigned n = hfx_type_components(ty);
    if (n == 4) return hfx_d3d9_tx_var(t, v);
    ir_expr *e = hfx_ir_new_expr(t->c, IE_CONSTRUCT, t->i4, t->loc, 1 + 4 - n);
    e->a[0] = hfx_d3d9_tx_var(t, v);
    for (unsigned q = n; q < 4; q++) e->a[1 + q - n] = hfx_ir_const_scalar(t->c, t->i1, 0, t->loc);
    return e;
}

/* Register first + e of a sampler array constant: element e of the array parameter, the
 * variable the HLSL path makes for S[e] (D3DX binds the elements to the run of registers). */
static ir_var *array_sampler(d3d9_tx *t, uint32_t k, unsigned e, const hfx_type *elem) {
    const d3d9_constant *x = &t->s->constants[k];
    const hfx_fx_effect *fx = t->c->fx;
    for (uint32_t p = 0; fx && p < fx->top_param_count && p < fx->param_count; p++) {
        if (!fx->params[p].name || strcmp(fx->params[p].name, x->name) != 0) continue;
        if (e >= fx->params[p].child_count) break;
        hfx_decl *d = fake_decl(t, DECL_VAR, x->name, hfx_type_array(t->c->types, elem, fx->params[p].child_count), 0, NULL);
        d->is_global = true;
        d->index = p;
        ir_var *v = hfx_ir_sampler_element(t->c, t->sh, d, e);
        if (v) v->dim = elem->dim;
        return v;
    }
    hfx_d3d9_tx_fail(t, "sampler constant '%s' names no sampler array of the effect with an element %u", x->name, e);
    return NULL;
}

ir_var *hfx_d3d9_tx_sampler(d3d9_tx *t, unsigned num) {
    if (num >= 16) return NULL;
    if (t->samplers[num]) return t->samplers[num];
    int k = constant_at(t->s, D3D9_RS_SAMPLER, num);
    const d3d9_inst *d = find_dcl(t->s, D3D9_REG_SAMPLER, num);
    if (k < 0) { hfx_d3d9_tx_fail(t, "s%u is sampled but no constant names it", num); return NULL; }
    unsigned st = d ? d->sampler_type : t->s->constants[k].type == 14 ? 3 : t->s->constants[k].type == 13 ? 4
                : t->s->constants[k].type == 11 ? 1 : 2; /* ps_1_x declares no samplers: the CTAB's type */
    hfx_dim dim = st == 2 ? DIM_2D : st == 3 ? DIM_CUBE : st == 4 ? DIM_3D : DIM_1D;
    const hfx_type *ty = hfx_type_object(t->c->types, TY_SAMPLER, dim);
    if (t->s->constants[k].count > 1 || t->s->constants[k].elements > 1)
        return t->samplers[num] = array_sampler(t, (uint32_t)k, num - t->s->constants[k].reg, ty);
    ir_var *v = constant_var(t, (uint32_t)k, IRV_SAMPLER, ty);
    if (v) v->dim = dim;
    return t->samplers[num] = v;
}

/* An output or temporary as an l-value, or NULL. */
static ir_var *dst_var(d3d9_tx *t, const d3d9_dst *d) {
    switch (d->type) {
    case D3D9_REG_TEMP: hfx_d3d9_tx_reg(t, D3D9_REG_TEMP, d->num); return d->num < 32 ? t->temps[d->num] : NULL;
    case D3D9_REG_RASTOUT: case D3D9_REG_ATTROUT: case D3D9_REG_OUTPUT: case D3D9_REG_COLOROUT: case D3D9_REG_DEPTHOUT:
        return output(t, d->type, d->num);
    case D3D9_REG_PREDICATE:
        if (!t->p0) t->p0 = new_local(t, "hfx_p0", t->b4);
        return t->p0;
    case D3D9_REG_ADDR:
        if (t->s->stage == D3D9_VS) {
            if (!t->a0) t->a0 = new_local(t, "hfx_a0", t->i4);
            return t->a0;
        }
        if (t->s->model < D3D9_SM(1, 4)) return texture_register(t, d->num);
        hfx_d3d9_tx_fail(t, "writing t registers (ps_1_x) is not supported yet");
        return NULL;
    default:
        hfx_d3d9_tx_fail(t, "writing register type %u is not supported yet", d->type);
        return NULL;
    }
}

/* _sat on the register just written (r = value): r = isnan(r) ? 0 : clamp(r, 0, 1). D3D10 and
 * later hardware, which runs D3D9 shaders today, saturates NaN to 0; GLSL leaves clamp, min and
 * max of NaN undefined (and an optimiser may turn a select on a comparison into them), isnan
 * says the case. The register is read back rather than the value repeated, so the GLSL grows by
 * one statement. */
static void saturate_in_place(d3d9_tx *t, ir_expr *lhs) {
    const hfx_type *ty = lhs->type;
    unsigned n = hfx_type_components(ty);
    const hfx_type *bt = n == 1 ? hfx_type_scalar(t->c->types, B_BOOL) : hfx_type_vector(t->c->types, B_BOOL, n);
    ir_expr *nan = hfx_ir_new_expr(t->c, IE_INTRIN, bt, t->loc, 1);
    nan->intrin = HFX_INTR_ISNAN;
    nan->a[0] = hfx_ir_clone_expr(t->c, lhs);
    ir_expr *sat = hfx_ir_new_expr(t->c, IE_INTRIN, ty, t->loc, 1);
    sat->intrin = HFX_INTR_SATURATE;
    sat->a[0] = hfx_ir_clone_expr(t->c, lhs);
    ir_expr *sel = hfx_ir_new_expr(t->c, IE_SELECT, ty, t->loc, 3);
    sel->a[0] = nan;
    sel->a[1] = hfx_ir_const_scalar(t->c, ty, 0, t->loc);
    sel->a[2] = sat;
    ir_expr *as = hfx_ir_new_expr(t->c, IE_ASSIGN, ty, t->loc, 2);
    as->op = OP_NONE;
    as->a[0] = hfx_ir_clone_expr(t->c, lhs);
    as->a[1] = sel;
    hfx_d3d9_tx_emit(t, as);
}

void hfx_d3d9_tx_write(d3d9_tx *t, const d3d9_dst *d, ir_expr *value) {
    if (!value || t->failed) return;
    if (d->relative) { hfx_d3d9_tx_fail(t, "relative destinations are not supported yet"); return; }
    ir_var *v = dst_var(t, d);
    if (!v) return;
    if (d->shift && value->type->base == B_FLOAT) { /* ps_1_x: _x2 _x4 _x8 _d2 _d4 _d8 */
        float k = d->shift > 0 ? (float)(1 << d->shift) : 1.0f / (float)(1 << -d->shift);
        value = hfx_ir_new_binary(t->c, OP_MUL, value->type, value, hfx_ir_const_scalar(t->c, value->type, k, t->loc));
    }
    bool sat_nan = (d->mods & D3D9_DMOD_SAT) && value->type->base == B_FLOAT;
    if ((d->mods & D3D9_DMOD_SAT) && !sat_nan) {
        ir_expr *s = hfx_ir_new_expr(t->c, IE_INTRIN, value->type, t->loc, 1);
        s->intrin = HFX_INTR_SATURATE;
        s->a[0] = value;
        value = s;
    } else if (!sat_nan && hfx_d3d9_tx_ps1(t) && value->type->base == B_FLOAT) {
        /* ps_1_x registers hold [-1, 1] (ps_1_4: [-8, 8], D3D's minimum MaxPixelShaderValue) */
        float r = t->s->model == D3D9_SM(1, 4) ? 8.0f : 1.0f;
        ir_expr *c = hfx_ir_new_expr(t->c, IE_INTRIN, value->type, t->loc, 3);
        c->intrin = HFX_INTR_CLAMP;
        c->a[0] = value;
        c->a[1] = hfx_ir_const_scalar(t->c, value->type, -r, t->loc);
        c->a[2] = hfx_ir_const_scalar(t->c, value->type, r, t->loc);
        value = c;
    }
    uint8_t comps[4];
    unsigned n = 0, width = hfx_type_components(v->type);
    for (unsigned k = 0; k < 4; k++)
        if (d->mask & (1u << k) && k < width) comps[n++] = (uint8_t)k;
    if (!n) return;
    ir_expr *lhs = hfx_d3d9_tx_var(t, v), *rhs = value;
    if (v->type->base != value->type->base) rhs = hfx_ir_new_convert(t->c, hfx_type_vector(t->c->types, v->type->base, 4), rhs);
    if (width == 1) rhs = hfx_d3d9_tx_swizzle(t, rhs, comps, 1);
    else if (n < 4) {
        lhs = hfx_d3d9_tx_swizzle(t, lhs, comps, n);
        rhs = hfx_d3d9_tx_swizzle(t, rhs, comps, n);
    }
    ir_expr *as = hfx_ir_new_expr(t->c, IE_ASSIGN, lhs->type, t->loc, 2);
    as->op = OP_NONE;
    as->a[0] = lhs;
    as->a[1] = rhs;
    hfx_d3d9_tx_emit(t, as);
    if (sat_nan) saturate_in_place(t, lhs);
}

static bool model_supported(d3d9_tx *t) {
    if (t->s->model >= D3D9_SM(2, 0) || t->s->stage == D3D9_PS || t->s->model == D3D9_SM(1, 1)) return true;
    hfx_d3d9_tx_fail(t, "%s bytecode to GLSL is not supported yet", hfx_d3d9_model_name(t->s->stage, t->s->model));
    return false;
}

static void setup(d3d9_tx *t, ir_ctx *c, const d3d9_shader *s) {
    t->c = c;
    t->s = s;
    hfx_types *ty = c->types;
    t->f1 = hfx_type_scalar(ty, B_FLOAT);
    t->f2 = hfx_type_vector(ty, B_FLOAT, 2);
    t->f3 = hfx_type_vector(ty, B_FLOAT, 3);
    t->f4 = hfx_type_vector(ty, B_FLOAT, 4);
    t->i1 = hfx_type_scalar(ty, B_INT);
    t->i4 = hfx_type_vector(ty, B_INT, 4);
    t->b4 = hfx_type_vector(ty, B_BOOL, 4);
    t->loc = (hfx_loc){s->file_index, 0, s->base};
    t->consts = HFX_NEW_ARRAY(c->arena, ir_var *, s->constant_count ? s->constant_count : 1);
    t->pres = HFX_NEW_ARRAY(c->arena, ir_var *, s->pre_count ? s->pre_count : 1);
    t->prologue = hfx_ir_new_stmt(c, IS_BLOCK, t->loc);
    t->blocks[0].s = t->prologue;
    t->blocks[1].s = hfx_ir_new_stmt(c, IS_BLOCK, t->loc);
    t->depth = 1;
}

/* The entry: `void hfx_d3d9_main(in ..., out ...)`, body = prologue then instructions. */
static ir_shader *finish(d3d9_tx *t) {
    ir_ctx *c = t->c;
    const d3d9_shader *s = t->s;
    hfx_func *src = HFX_NEW(c->arena, hfx_func);
    src->ret = hfx_type_void(c->types);
    src->name = s->stage == D3D9_VS ? "hfx_d3d9_vs" : "hfx_d3d9_ps";
    src->loc = (hfx_loc){s->file_index, 0, s->base};
    ir_func *f = HFX_NEW(c->arena, ir_func);
    f->name = f->glsl = src->name;
    f->ret = src->ret;
    f->src = src;
    f->is_entry = true;
    f->params = t->params;
    f->param_count = t->param_count;
    t->depth = 0;
    ir_stmt *body = t->blocks[1].s;
    hfx_d3d9_tx_add(t, 0, body);
    f->body = t->prologue;
    hfx_expr *compile = HFX_NEW(c->arena, hfx_expr);
    compile->kind = EX_COMPILE;
    compile->profile = hfx_d3d9_model_name(s->stage, s->model);
    compile->name = src->name;
    compile->intrinsic = -1;
    compile->loc = src->loc;
    ir_shader *sh = t->sh;
    sh->stage = s->stage == D3D9_VS ? IR_VERTEX : IR_PIXEL;
    sh->entry = f;
    sh->funcs = HFX_NEW_ARRAY(c->arena, ir_func *, 1);
    sh->funcs[0] = f;
    sh->func_count = sh->func_cap = 1;
    sh->compile = compile;
    return sh;
}

static bool same_src(const d3d9_src *a, const d3d9_src *b) {
    return a->type == b->type && a->mod == b->mod && a->swizzle == b->swizzle && a->relative == b->relative &&
           a->num == b->num && a->rel_type == b->rel_type && a->rel_comp == b->rel_comp && a->rel_num == b->rel_num;
}

/* The CTAB constant whose registers m.num .. m.num + count - 1 are, as a float matrix (or one
 * element of a matrix array) with `width` components a register, read whole (no index, modifier
 * or swizzle) and not under a def or a preshader; -1 otherwise. *off: m.num's register within the
 * matrix, *elem: the element (0 for no array). */
static int matrix_constant(const d3d9_tx *t, const d3d9_src *m, unsigned count, unsigned width, unsigned *off,
                           unsigned *elem) {
    if (m->type != D3D9_REG_CONST || m->relative || m->mod != D3D9_SMOD_NONE || m->swizzle != 0xe4) return -1;
    int c = constant_at(t->s, D3D9_RS_FLOAT4, m->num);
    if (c < 0) return -1;
    const d3d9_constant *k = &t->s->constants[c];
    if (k->type != 3 || (k->cls != 2 && k->cls != 3)) return -1;
    unsigned per = k->cls == 3 ? k->cols : k->rows;
    if (!per) return -1; /* a constant table that says 0 rows or columns */
    *off = (m->num - k->reg) % per;
    *elem = (m->num - k->reg) / per;
    if ((k->cls == 3 ? k->rows : k->cols) != width || *off + count > per || m->num + count > k->reg + k->count)
        return -1; /* past the registers fxc gave the constant: another constant's, or none */
    for (unsigned q = 0; q < count; q++)
        if (preshader_of(t->s, D3D9_PRE_C, m->num + q) >= 0 || def_at(t->s, m->num + q)) return -1;
    return c;
}

/* dot(v, register j of M) for every register j of matrix constant c (element elem of an array)
 * at once: mul(v, M) when the registers are M's columns, mul(M, v) when they are its rows; as
 * float4. */
static ir_expr *matrix_product(d3d9_tx *t, uint32_t c, unsigned elem, const d3d9_src *vs, unsigned width) {
    const d3d9_constant *k = &t->s->constants[c];
    const hfx_type *el = constant_type(t, k);
    bool array = k->elements > 1;
    ir_var *mv = el ? constant_var(t, c, IRV_UNIFORM, array ? hfx_type_array(t->c->types, el, k->elements) : el) : NULL;
    ir_expr *v = mv ? hfx_d3d9_tx_read(t, vs) : NULL;
    if (!v) return NULL;
    if (width == 3) {
        static const uint8_t xyz[3] = {0, 1, 2};
        v = hfx_d3d9_tx_swizzle(t, v, xyz, 3);
    }
    ir_expr *m = hfx_d3d9_tx_var(t, mv);
    if (array) { /* matrix_constant keeps the registers inside the array */
        ir_expr *ix = hfx_ir_new_expr(t->c, IE_INDEX, el, t->loc, 2);
        ix->a[0] = m;
        ix->a[1] = hfx_ir_const_scalar(t->c, t->i1, elem, t->loc);
        ix->range = IR_RANGE_IN_BOUNDS;
        m = ix;
    }
    bool cols = k->cls == 3;
    ir_expr *e = hfx_ir_new_expr(t->c, IE_INTRIN, hfx_type_vector(t->c->types, B_FLOAT, cols ? el->cols : el->rows), t->loc, 2);
    e->intrin = HFX_INTR_MUL;
    e->a[cols ? 0 : 1] = v;
    e->a[cols ? 1 : 0] = m;
    return hfx_d3d9_tx_float4(t, e);
}

ir_expr *hfx_d3d9_tx_matrix_mul(d3d9_tx *t, const d3d9_src *v, const d3d9_src *m, unsigned width, unsigned count) {
    unsigned off, elem;
    int c = matrix_constant(t, m, count, width, &off, &elem);
    return c >= 0 && off == 0 ? matrix_product(t, (uint32_t)c, elem, v, width) : NULL;
}

/* The one component a write mask names, or -1. */
static int one_component(unsigned mask) { return mask == 1 ? 0 : mask == 2 ? 1 : mask == 4 ? 2 : mask == 8 ? 3 : -1; }

/* Whether `next` continues the run `first` starts, as its m-th instruction, writing a component
 * the run has not (`written`). */
static bool run_continues(const d3d9_inst *first, const d3d9_inst *next, unsigned m, unsigned written) {
    return next->op == first->op && !next->predicated && !next->coissue && next->dst.type == first->dst.type &&
           next->dst.num == first->dst.num && next->dst.mods == first->dst.mods && next->dst.shift == 0 &&
           !next->dst.relative && one_component(next->dst.mask) >= 0 && !(next->dst.mask & written) &&
           same_src(&next->src[0], &first->src[0]) && next->src[1].type == D3D9_REG_CONST &&
           next->src[1].num == first->src[1].num + m && !next->src[1].relative &&
           next->src[1].mod == D3D9_SMOD_NONE && next->src[1].swizzle == 0xe4;
}

/* fxc writes mul(v, M) as one dp4 (dp3) per register of M: `dp4 r0.x, v0, c0; dp4 r0.y, v0, c1;
 * ...`. The number of instructions from i that do so for one matrix parameter (or one element of
 * a matrix array: consecutive registers, each to a component of one register, v not the register
 * written), if 2 or more, or 1 for a column-major matrix's register (a gather of one component of
 * each row otherwise), else 0; *c its CTAB constant, *elem the element. Read back as one mul, the
 * GLSL is the source's `M * v` instead of a gather of every register's components, which drivers
 * take several times longer to compile (bench/bench_fx2_load). */
static unsigned matrix_run(const d3d9_tx *t, uint32_t i, uint32_t *c, unsigned *elem) {
    const d3d9_inst *in = &t->s->insts[i];
    const d3d9_src *v = &in->src[0];
    if ((in->op != D3D9_DP4 && in->op != D3D9_DP3) || in->predicated || in->coissue || in->dst.shift ||
        in->dst.relative || v->relative || (v->type == in->dst.type && v->num == in->dst.num) ||
        one_component(in->dst.mask) < 0)
        return 0;
    unsigned width = in->op == D3D9_DP4 ? 4 : 3, off, n = 1, written = in->dst.mask;
    int k = matrix_constant(t, &in->src[1], 1, width, &off, elem);
    if (k < 0) return 0;
    while (off + n < 4 && i + n < t->s->inst_count && run_continues(in, &t->s->insts[i + n], n, written))
        written |= t->s->insts[i + n++].dst.mask;
    while (n >= 1 && (k = matrix_constant(t, &in->src[1], n, width, &off, elem)) < 0) n--;
    if (n == 0 || (n == 1 && t->s->constants[k].cls != 3)) return 0;
    *c = (uint32_t)k;
    return n;
}

/* The n instructions matrix_run found: each dst component = the product's component of its register. */
static void translate_matrix_run(d3d9_tx *t, const d3d9_inst *in, uint32_t c, unsigned elem, unsigned n) {
    ir_expr *e = matrix_product(t, c, elem, &in->src[0], in->op == D3D9_DP4 ? 4 : 3);
    if (!e) {
        if (!t->failed) hfx_d3d9_tx_fail(t, "%s could not be translated", hfx_d3d9_op_find(in->op)->name);
        return;
    }
    const d3d9_constant *k = &t->s->constants[c];
    unsigned first = (in->src[1].num - k->reg) % (k->cls == 3 ? k->cols : k->rows);
    uint8_t comps[4] = {(uint8_t)first, (uint8_t)first, (uint8_t)first, (uint8_t)first};
    d3d9_dst d = in->dst;
    d.mask = 0;
    for (unsigned m = 0; m < n; m++) {
        unsigned mask = in[m].dst.mask;
        comps[one_component(mask)] = (uint8_t)(first + m);
        d.mask = (uint8_t)(d.mask | mask);
    }
    hfx_d3d9_tx_write(t, &d, hfx_d3d9_tx_swizzle(t, e, comps, 4));
}

struct ir_shader *hfx_d3d9_to_ir(struct ir_ctx *c, const d3d9_shader *s, bool packed) {
    d3d9_tx t;
    memset(&t, 0, sizeof t);
    setup(&t, c, s);
    t.pack = packed;
    t.sh = HFX_NEW(c->arena, ir_shader);
    if (!model_supported(&t)) return NULL;
    for (uint32_t i = 0; i < s->inst_count && !t.failed; i++) {
        t.loc = (hfx_loc){s->file_index, 0, s->base + s->insts[i].offset};
        uint32_t k;
        unsigned elem, n = matrix_run(&t, i, &k, &elem);
        if (n) translate_matrix_run(&t, &s->insts[i], k, elem, n);
        else if (!(n = hfx_d3d9_tx_scalar_run(&t, i))) hfx_d3d9_tx_inst(&t, &s->insts[i]);
        if (n) i += n - 1;
    }
    if (t.failed) return NULL;
    if (t.depth != 1) { hfx_d3d9_tx_fail(&t, "flow control does not close"); return NULL; }
    if (hfx_d3d9_tx_ps1(&t)) { /* ps_1_x has no oC0: the pixel is r0 at the end */
        d3d9_dst oc = {D3D9_REG_COLOROUT, 0xf, 0, 0, false, 0, 0, 0, 0};
        hfx_d3d9_tx_write(&t, &oc, hfx_d3d9_tx_reg(&t, D3D9_REG_TEMP, 0));
        if (t.failed) return NULL;
    }
    t.loc = (hfx_loc){s->file_index, 0, s->base};
    return finish(&t);
}
