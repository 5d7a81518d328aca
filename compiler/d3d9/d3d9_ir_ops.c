/* d3d9_ir_ops.c: each instruction as IR, from the definitions of Microsoft's "Asm Shader
 * Reference" (vs_2_0 .. ps_3_0). Where D3D9 differs from the plain GLSL function it says so:
 * rsq and log take |x|, pow takes |x| as its base, nrm scales all four components, sincos
 * writes cos to x and sin to y, cmp selects on >= 0, texkill tests the components of its
 * write mask. Flow control: d3d9_ir_flow.c. */
#include "d3d9/d3d9_ir.h"

static ir_expr *intrin(d3d9_tx *t, ir_intrin id, const hfx_type *ty, unsigned n, ir_expr *a, ir_expr *b, ir_expr *c) {
    if (!a || (n > 1 && !b) || (n > 2 && !c)) return NULL;
    ir_expr *e = hfx_ir_new_expr(t->c, IE_INTRIN, ty, t->loc, n);
    e->intrin = id;
    e->a[0] = a;
    if (n > 1) e->a[1] = b;
    if (n > 2) e->a[2] = c;
    return e;
}

static ir_expr *bin(d3d9_tx *t, hfx_op op, const hfx_type *ty, ir_expr *a, ir_expr *b) {
    return a && b ? hfx_ir_new_binary(t->c, op, ty, a, b) : NULL;
}

static ir_expr *comps(d3d9_tx *t, ir_expr *x, unsigned from, unsigned n) {
    static const uint8_t idx[4][4] = {{0, 1, 2, 3}, {1, 2, 3, 3}, {2, 3, 3, 3}, {3, 3, 3, 3}};
    return x ? hfx_d3d9_tx_swizzle(t, x, idx[from], n) : NULL;
}

static ir_expr *splat(d3d9_tx *t, ir_expr *scalar) { return scalar ? hfx_ir_new_convert(t->c, t->f4, scalar) : NULL; }

static ir_expr *zero4(d3d9_tx *t) { return hfx_d3d9_tx_const4(t, (const float[4]){0, 0, 0, 0}); }

/* dp3 / dp4 of two float4 values, as a scalar. */
static ir_expr *dot(d3d9_tx *t, ir_expr *a, ir_expr *b, unsigned n) {
    if (n == 4) return intrin(t, HFX_INTR_DOT, t->f1, 2, a, b, NULL);
    return intrin(t, HFX_INTR_DOT, t->f1, 2, comps(t, a, 0, n), comps(t, b, 0, n), NULL);
}

/* m4x4 family: component k = dot(src0, c[base + k]) over `width` components, for `rows` rows. */
static ir_expr *matrix(d3d9_tx *t, const d3d9_inst *in, unsigned width, unsigned rows) {
    if (in->src[1].relative || in->src[1].mod) { hfx_d3d9_tx_fail(t, "a modified matrix operand is not supported yet"); return NULL; }
    ir_expr *whole = hfx_d3d9_tx_matrix_mul(t, &in->src[0], &in->src[1], width, rows);
    if (whole || t->failed) return whole; /* one product, as the source's mul */
    ir_expr *v = hfx_d3d9_tx_read(t, &in->src[0]);
    if (!v) return NULL;
    ir_expr *e = hfx_ir_new_expr(t->c, IE_CONSTRUCT, t->f4, t->loc, 4);
    for (unsigned k = 0; k < 4; k++) {
        d3d9_src row = in->src[1];
        row.num = (uint16_t)(row.num + k);
        e->a[k] = k < rows ? dot(t, hfx_ir_clone_expr(t->c, v), hfx_d3d9_tx_read(t, &row), width) : hfx_ir_const_scalar(t->c, t->f1, 0, t->loc);
        if (!e->a[k]) return NULL;
    }
    return e;
}

/* slt / sge: 1 where the comparison holds, else 0. */
static ir_expr *compare(d3d9_tx *t, hfx_op op, ir_expr *a, ir_expr *b) {
    ir_expr *c = bin(t, op, t->b4, a, b);
    return c ? hfx_ir_new_convert(t->c, t->f4, c) : NULL;
}

static ir_expr *select4(d3d9_tx *t, ir_expr *cond, ir_expr *a, ir_expr *b) {
    if (!cond || !a || !b) return NULL;
    ir_expr *e = hfx_ir_new_expr(t->c, IE_SELECT, t->f4, t->loc, 3);
    e->a[0] = cond;
    e->a[1] = a;
    e->a[2] = b;
    return e;
}

static ir_expr *scalar_src(d3d9_tx *t, const d3d9_src *x) { return comps(t, hfx_d3d9_tx_read(t, x), 0, 1); }

/* The texture intrinsic of a dimension and form (hfx_tex_form order: plain, bias, lod, proj, grad). */
static ir_intrin tex_intrin(hfx_dim dim, int form) {
    static const ir_intrin t1[] = {HFX_INTR_TEX1D, HFX_INTR_TEX1DBIAS, HFX_INTR_TEX1DLOD, HFX_INTR_TEX1DPROJ, HFX_INTR_TEX1DGRAD};
    static const ir_intrin t2[] = {HFX_INTR_TEX2D, HFX_INTR_TEX2DBIAS, HFX_INTR_TEX2DLOD, HFX_INTR_TEX2DPROJ, HFX_INTR_TEX2DGRAD};
    static const ir_intrin t3[] = {HFX_INTR_TEX3D, HFX_INTR_TEX3DBIAS, HFX_INTR_TEX3DLOD, HFX_INTR_TEX3DPROJ, HFX_INTR_TEX3DGRAD};
    static const ir_intrin tc[] = {HFX_INTR_TEXCUBE, HFX_INTR_TEXCUBEBIAS, HFX_INTR_TEXCUBELOD, HFX_INTR_TEXCUBEPROJ,
                                   HFX_INTR_TEXCUBEGRAD};
    return dim == DIM_1D ? t1[form] : dim == DIM_3D ? t3[form] : dim == DIM_CUBE ? tc[form] : t2[form];
}

/* A plain read of sampler s at uv (float4; the dimension takes its components). */
static ir_expr *sample(d3d9_tx *t, ir_var *s, ir_expr *uv) {
    if (!s || !uv) return NULL;
    unsigned n = s->dim == DIM_1D ? 1 : s->dim == DIM_2D ? 2 : 3;
    return intrin(t, tex_intrin(s->dim, TEXF_PLAIN), t->f4, 2, hfx_d3d9_tx_var(t, s), comps(t, uv, 0, n), NULL);
}

/* ps_1_4's texld / texcrd source: a texture coordinate set (tN) or a register (rN, phase 2),
 * with _dz / _dw dividing xy by z / w. */
static ir_expr *ps14_coords(d3d9_tx *t, const d3d9_src *x) {
    d3d9_src plain = *x;
    plain.mod = D3D9_SMOD_NONE;
    ir_expr *c = x->type == D3D9_REG_ADDR ? hfx_d3d9_tx_float4(t, hfx_d3d9_tx_var(t, hfx_d3d9_tx_texcoord(t, x->num)))
                                          : hfx_d3d9_tx_read(t, &plain);
    if (!c || (x->mod != D3D9_SMOD_DZ && x->mod != D3D9_SMOD_DW)) return x->mod == D3D9_SMOD_NONE || !c ? c : NULL;
    const uint8_t by = x->mod == D3D9_SMOD_DZ ? 2 : 3, xy[2] = {0, 1};
    ir_expr *q = hfx_ir_new_binary(t->c, OP_DIV, t->f2, hfx_d3d9_tx_swizzle(t, c, xy, 2),
                               hfx_ir_new_convert(t->c, t->f2, hfx_d3d9_tx_swizzle(t, hfx_ir_clone_expr(t->c, c), &by, 1)));
    return hfx_d3d9_tx_float4(t, q);
}

/* ps_1_x: tex tN (1.1-1.3: sampler N at texture coordinates N), texld rN, src (1.4: sampler N). */
static ir_expr *ps1_tex(d3d9_tx *t, const d3d9_inst *in) {
    ir_var *tc = t->s->model < D3D9_SM(1, 4) ? hfx_d3d9_tx_texcoord(t, in->dst.num) : NULL;
    ir_expr *uv = t->s->model >= D3D9_SM(1, 4) ? ps14_coords(t, &in->src[0]) : tc ? hfx_d3d9_tx_float4(t, hfx_d3d9_tx_var(t, tc)) : NULL;
    if (!uv) { hfx_d3d9_tx_fail(t, "texture coordinates of this form are not supported"); return NULL; }
    return sample(t, hfx_d3d9_tx_sampler(t, in->dst.num), uv);
}

/* texcoord tN (1.1-1.3): the coordinates clamped to [0, 1], w = 1; texcrd rN, tM (1.4): as they are. */
static ir_expr *ps1_texcoord(d3d9_tx *t, const d3d9_inst *in) {
    if (t->s->model == D3D9_SM(1, 4)) return ps14_coords(t, &in->src[0]);
    ir_var *tc = hfx_d3d9_tx_texcoord(t, in->dst.num); /* NULL past the model's t registers (input's error given) */
    if (!tc) { hfx_d3d9_tx_fail(t, "t%u is no texture coordinate register of this model", in->dst.num); return NULL; }
    ir_expr *c = hfx_d3d9_tx_var(t, tc);
    ir_expr *e = hfx_ir_new_expr(t->c, IE_CONSTRUCT, t->f4, t->loc, 2);
    e->a[0] = intrin(t, HFX_INTR_SATURATE, t->f3, 1, comps(t, c, 0, 3), NULL, NULL);
    e->a[1] = hfx_ir_const_scalar(t->c, t->f1, 1, t->loc);
    return e->a[0] ? e : NULL;
}

/* texld / texldp / texldb / texldl / texldd: the coordinates as the form takes them. */
static ir_expr *texture(d3d9_tx *t, const d3d9_inst *in, int form) {
    if (in->src[1].type != D3D9_REG_SAMPLER) { hfx_d3d9_tx_fail(t, "texture read without a sampler operand"); return NULL; }
    ir_var *s = hfx_d3d9_tx_sampler(t, in->src[1].num);
    ir_expr *uv = hfx_d3d9_tx_read(t, &in->src[0]);
    if (!s || !uv) return NULL;
    unsigned n = s->dim == DIM_1D ? 1 : s->dim == DIM_2D ? 2 : 3;
    bool whole = form == TEXF_BIAS || form == TEXF_LOD || form == TEXF_PROJ;
    ir_expr *e = hfx_ir_new_expr(t->c, IE_INTRIN, t->f4, t->loc, form == TEXF_GRAD ? 4 : 2);
    e->intrin = tex_intrin(s->dim, form);
    e->a[0] = hfx_d3d9_tx_var(t, s);
    e->a[1] = whole ? uv : comps(t, uv, 0, n);
    if (form == TEXF_GRAD) {
        e->a[2] = comps(t, hfx_d3d9_tx_read(t, &in->src[2]), 0, n);
        e->a[3] = comps(t, hfx_d3d9_tx_read(t, &in->src[3]), 0, n);
        if (!e->a[2] || !e->a[3]) return NULL;
    }
    return e;
}

/* texkill: discard when a component of its write mask is negative (SM2+). */
static void texkill(d3d9_tx *t, const d3d9_inst *in) {
    bool ps1 = hfx_d3d9_tx_ps1(t); /* ps_1_x: texkill tN tests texture coordinates N, xyz */
    ir_expr *x = ps1 && in->dst.type == D3D9_REG_ADDR ? hfx_d3d9_tx_float4(t, hfx_d3d9_tx_var(t, hfx_d3d9_tx_texcoord(t, in->dst.num)))
                                                      : hfx_d3d9_tx_reg(t, in->dst.type, in->dst.num);
    if (!x) return;
    uint8_t c[4];
    unsigned n = 0;
    for (unsigned k = 0; k < 4; k++)
        if (ps1 ? k < 3 : (in->dst.mask & (1u << k)) != 0) c[n++] = (uint8_t)k;
    if (!n) return;
    x = hfx_d3d9_tx_swizzle(t, x, c, n);
    hfx_d3d9_tx_emit(t, intrin(t, HFX_INTR_CLIP, hfx_type_void(t->c->types), 1, x, NULL, NULL));
    t->sh->uses_discard = true;
}

/* sincos: x = cos(src), y = sin(src) (the replicate component); z and w are left as they were. */
static ir_expr *sincos(d3d9_tx *t, const d3d9_inst *in) {
    ir_expr *a = scalar_src(t, &in->src[0]);
    if (!a) return NULL;
    ir_expr *e = hfx_ir_new_expr(t->c, IE_CONSTRUCT, t->f4, t->loc, 4);
    e->a[0] = intrin(t, HFX_INTR_COS, t->f1, 1, a, NULL, NULL);
    e->a[1] = intrin(t, HFX_INTR_SIN, t->f1, 1, hfx_ir_clone_expr(t->c, a), NULL, NULL);
    e->a[2] = hfx_ir_const_scalar(t->c, t->f1, 0, t->loc);
    e->a[3] = hfx_ir_const_scalar(t->c, t->f1, 0, t->loc);
    return e;
}

/* The value an arithmetic instruction computes, as float4 (before the write mask). */
static ir_expr *arith(d3d9_tx *t, const d3d9_inst *in) {
    const d3d9_src *s = in->src;
    bool whole = in->op != D3D9_SINCOS && !(hfx_d3d9_op_find(in->op)->flags & D3D9_OPF_MATRIX);
    bool want_a = in->src_count > 0 && whole;
    bool want_b = in->src_count > 1 && whole && in->op != D3D9_TEX && in->op != D3D9_TEXLDL && in->op != D3D9_TEXLDD;
    bool want_c = in->src_count > 2 && in->op != D3D9_SINCOS && in->op != D3D9_TEXLDD;
    ir_expr *a = want_a ? hfx_d3d9_tx_read(t, &s[0]) : NULL;
    ir_expr *b = want_b ? hfx_d3d9_tx_read(t, &s[1]) : NULL;
    ir_expr *c = want_c ? hfx_d3d9_tx_read(t, &s[2]) : NULL;
    /* a source that could not be read has its error already; nothing is built on it */
    if ((want_a && !a) || (want_b && !b) || (want_c && !c)) return NULL;
    const hfx_type *f4 = t->f4;
    switch (in->op) {
    case D3D9_MOV: return a;
    case D3D9_ADD: return bin(t, OP_ADD, f4, a, b);
    case D3D9_SUB: return bin(t, OP_SUB, f4, a, b);
    case D3D9_MUL: return bin(t, OP_MUL, f4, a, b);
    case D3D9_MAD: return bin(t, OP_ADD, f4, bin(t, OP_MUL, f4, a, b), c);
    case D3D9_MIN: return intrin(t, HFX_INTR_MIN, f4, 2, a, b, NULL);
    case D3D9_MAX: return intrin(t, HFX_INTR_MAX, f4, 2, a, b, NULL);
    case D3D9_SLT: return compare(t, OP_LT, a, b);
    case D3D9_SGE: return compare(t, OP_GE, a, b);
    case D3D9_DP3: return splat(t, dot(t, a, b, 3));
    case D3D9_DP4: return splat(t, dot(t, a, b, 4));
    case D3D9_DP2ADD: return splat(t, bin(t, OP_ADD, t->f1, dot(t, a, b, 2), comps(t, c, 0, 1)));
    case D3D9_RCP: return splat(t, bin(t, OP_DIV, t->f1, hfx_ir_const_scalar(t->c, t->f1, 1, t->loc), comps(t, a, 0, 1)));
    case D3D9_RSQ: return splat(t, intrin(t, HFX_INTR_RSQRT, t->f1, 1, intrin(t, HFX_INTR_ABS, t->f1, 1, comps(t, a, 0, 1), NULL, NULL), NULL, NULL));
    case D3D9_EXP: case D3D9_EXPP: return splat(t, intrin(t, HFX_INTR_EXP2, t->f1, 1, comps(t, a, 0, 1), NULL, NULL));
    case D3D9_LOG: case D3D9_LOGP:
        return splat(t, intrin(t, HFX_INTR_LOG2, t->f1, 1, intrin(t, HFX_INTR_ABS, t->f1, 1, comps(t, a, 0, 1), NULL, NULL), NULL, NULL));
    case D3D9_POW:
        return splat(t, intrin(t, HFX_INTR_POW, t->f1, 2, intrin(t, HFX_INTR_ABS, t->f1, 1, comps(t, a, 0, 1), NULL, NULL),
                               comps(t, b, 0, 1), NULL));
    case D3D9_FRC: return intrin(t, HFX_INTR_FRAC, f4, 1, a, NULL, NULL);
    case D3D9_ABS: return intrin(t, HFX_INTR_ABS, f4, 1, a, NULL, NULL);
    case D3D9_SGN: return intrin(t, HFX_INTR_SIGN, f4, 1, a, NULL, NULL);
    case D3D9_NRM:
        return bin(t, OP_MUL, f4, a, splat(t, intrin(t, HFX_INTR_RSQRT, t->f1, 1, dot(t, hfx_ir_clone_expr(t->c, a), hfx_ir_clone_expr(t->c, a), 3), NULL, NULL)));
    case D3D9_LRP: return intrin(t, HFX_INTR_LERP, f4, 3, c, b, a);
    case D3D9_CMP: return select4(t, bin(t, OP_GE, t->b4, a, zero4(t)), b, c);
    case D3D9_CND: return select4(t, bin(t, OP_GT, t->b4, a, hfx_d3d9_tx_const4(t, (const float[4]){0.5f, 0.5f, 0.5f, 0.5f})), b, c);
    case D3D9_CRS: return hfx_d3d9_tx_float4(t, intrin(t, HFX_INTR_CROSS, t->f3, 2, comps(t, a, 0, 3), comps(t, b, 0, 3), NULL));
    case D3D9_LIT:
        return intrin(t, HFX_INTR_LIT, f4, 3, comps(t, a, 0, 1), comps(t, hfx_ir_clone_expr(t->c, a), 1, 1), comps(t, hfx_ir_clone_expr(t->c, a), 3, 1));
    case D3D9_DST: return intrin(t, HFX_INTR_DST, f4, 2, a, b, NULL);
    case D3D9_DSX: return intrin(t, HFX_INTR_DDX, f4, 1, a, NULL, NULL);
    case D3D9_DSY: return intrin(t, HFX_INTR_DDY, f4, 1, a, NULL, NULL);
    case D3D9_SINCOS: return sincos(t, in);
    case D3D9_M4X4: return matrix(t, in, 4, 4);
    case D3D9_M4X3: return matrix(t, in, 4, 3);
    case D3D9_M3X4: return matrix(t, in, 3, 4);
    case D3D9_M3X3: return matrix(t, in, 3, 3);
    case D3D9_M3X2: return matrix(t, in, 3, 2);
    case D3D9_MOVA: return intrin(t, HFX_INTR_ROUND, f4, 1, a, NULL, NULL);
    case D3D9_SETP: {
        static const hfx_op ops[] = {OP_NONE, OP_GT, OP_EQ, OP_GE, OP_LT, OP_NE, OP_LE, OP_NONE};
        if (ops[in->control & 7] == OP_NONE) break;
        return bin(t, ops[in->control & 7], t->b4, a, b);
    }
    case D3D9_TEX: return texture(t, in, in->control == 1 ? TEXF_PROJ : in->control == 2 ? TEXF_BIAS : TEXF_PLAIN);
    case D3D9_TEXLDL: return texture(t, in, TEXF_LOD);
    case D3D9_TEXLDD: return texture(t, in, TEXF_GRAD);
    default: break;
    }
    hfx_d3d9_tx_fail(t, "%s is not supported yet", hfx_d3d9_op_find(in->op)->name);
    return NULL;
}

void hfx_d3d9_tx_inst(d3d9_tx *t, const d3d9_inst *in) {
    const d3d9_op_info *op = hfx_d3d9_op_find(in->op);
    if (op->flags & D3D9_OPF_DECL || in->op == D3D9_NOP) return; /* dcl / def are read where used */
    if (op->flags & D3D9_OPF_FLOW) {
        if (in->predicated) hfx_d3d9_tx_fail(t, "predicated flow control is not supported yet");
        else if (!hfx_d3d9_tx_flow(t, in)) hfx_d3d9_tx_fail(t, "subroutines (%s) are not supported yet", op->name);
        return;
    }
    if (in->predicated && (in->op == D3D9_TEXKILL || in->op == D3D9_MOVA || in->op == D3D9_SETP)) {
        hfx_d3d9_tx_fail(t, "predicated %s is not supported yet", op->name);
        return;
    }
    if (in->op == D3D9_TEXKILL) { texkill(t, in); return; }
    if (t->s->stage == D3D9_VS && in->op == D3D9_MOV && in->dst.type == D3D9_REG_ADDR) {
        /* vs_1_1 loads a0 with mov, rounding to nearest as mova does */
        ir_expr *a = hfx_d3d9_tx_read(t, &in->src[0]);
        if (a) hfx_d3d9_tx_write(t, &in->dst, intrin(t, HFX_INTR_ROUND, t->f4, 1, a, NULL, NULL));
        return;
    }
    if (hfx_d3d9_tx_ps1(t) && (in->op == D3D9_TEX || in->op == D3D9_TEXCOORD)) {
        ir_expr *v = in->op == D3D9_TEX ? ps1_tex(t, in) : ps1_texcoord(t, in);
        if (v) hfx_d3d9_tx_write(t, &in->dst, v);
        else if (!t->failed) hfx_d3d9_tx_fail(t, "%s could not be translated", op->name);
        return;
    }
    if (in->op == D3D9_MOVA && t->s->stage != D3D9_VS) return;
    ir_expr *v = arith(t, in);
    if (!v) {
        if (!t->failed) hfx_d3d9_tx_fail(t, "%s could not be translated", op->name);
        return;
    }
    if (in->predicated) v = hfx_d3d9_tx_predicate(t, in, v);
    if (v) hfx_d3d9_tx_write(t, &in->dst, v);
}
