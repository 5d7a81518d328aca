/* d3d9_dis.c: fxc's assembly listing of a decoded shader, as `fxc /Fc` and `fxc /dumpbin`
 * print it: the CTAB header (parameters sorted by name, registers in the table's order), the
 * model, one instruction a line indented by four spaces (two more inside if / loop / rep), and
 * the slot summary. Floats as fxc prints them: nine significant digits, three-digit exponents. */
#include "d3d9/d3d9_int.h"

#include <stdio.h>
#include <stdlib.h>

static const char comps[] = "xyzw";

/* %.9g with the exponent of Microsoft's C runtime (e-006, e+038). */
static void put_float(sbuf *b, float f) {
    char t[40];
    snprintf(t, sizeof t, "%.9g", (double)f);
    char *e = strchr(t, 'e');
    if (e && strlen(e) == 4) hfx_sb_printf(b, "%.*s%c0%s", (int)(e - t + 1), t, e[1], e + 2);
    else hfx_sb_put(b, t);
}

static void put_reg(sbuf *b, const d3d9_shader *s, unsigned type, unsigned num) {
    bool vs = s->stage == D3D9_VS;
    switch (type) {
    case D3D9_REG_TEMP: hfx_sb_printf(b, "r%u", num); break;
    case D3D9_REG_INPUT: hfx_sb_printf(b, "v%u", num); break;
    case D3D9_REG_CONST: hfx_sb_printf(b, "c%u", num); break;
    case D3D9_REG_ADDR: hfx_sb_printf(b, vs ? "a%u" : "t%u", num); break;
    case D3D9_REG_RASTOUT: hfx_sb_put(b, num == 0 ? "oPos" : num == 1 ? "oFog" : "oPts"); break;
    case D3D9_REG_ATTROUT: hfx_sb_printf(b, "oD%u", num); break;
    case D3D9_REG_OUTPUT: hfx_sb_printf(b, s->model >= D3D9_SM(3, 0) ? "o%u" : "oT%u", num); break;
    case D3D9_REG_CONSTINT: hfx_sb_printf(b, "i%u", num); break;
    case D3D9_REG_COLOROUT: hfx_sb_printf(b, "oC%u", num); break;
    case D3D9_REG_DEPTHOUT: hfx_sb_put(b, "oDepth"); break;
    case D3D9_REG_SAMPLER: hfx_sb_printf(b, "s%u", num); break;
    case D3D9_REG_CONSTBOOL: hfx_sb_printf(b, "b%u", num); break;
    case D3D9_REG_LOOP: hfx_sb_put(b, "aL"); break;
    case D3D9_REG_MISC: hfx_sb_put(b, num == 0 ? "vPos" : "vFace"); break;
    case D3D9_REG_LABEL: hfx_sb_printf(b, "l%u", num); break;
    case D3D9_REG_PREDICATE: hfx_sb_printf(b, "p%u", num); break;
    default: hfx_sb_printf(b, "?%u", num); break;
    }
}

static void put_relative(sbuf *b, const d3d9_shader *s, unsigned type, unsigned num, unsigned comp) {
    hfx_sb_put(b, "[");
    put_reg(b, s, type, num);
    if (type != D3D9_REG_LOOP) hfx_sb_printf(b, ".%c", comps[comp & 3]);
    hfx_sb_put(b, "]");
}

static void put_mask(sbuf *b, unsigned mask) {
    if (mask == 0xf || !mask) return;
    hfx_sb_put(b, ".");
    for (unsigned k = 0; k < 4; k++)
        if (mask & (1u << k)) hfx_sb_printf(b, "%c", comps[k]);
}

/* Identity: nothing; one component four times: that letter; otherwise all four. */
static void put_swizzle(sbuf *b, unsigned sw) {
    if (sw == 0xe4) return;
    unsigned c0 = sw & 3;
    if (sw == c0 * 0x55) { hfx_sb_printf(b, ".%c", comps[c0]); return; }
    hfx_sb_printf(b, ".%c%c%c%c", comps[sw & 3], comps[(sw >> 2) & 3], comps[(sw >> 4) & 3], comps[(sw >> 6) & 3]);
}

static void put_src(sbuf *b, const d3d9_shader *s, const d3d9_src *x) {
    static const char *const suffix[] = {"", "", "_bias", "_bias", "_bx2", "_bx2", "", "_x2", "_x2",
                                         "_dz", "_dw", "_abs", "_abs", ""};
    unsigned m = x->mod;
    if (m == D3D9_SMOD_NEG || m == D3D9_SMOD_BIASNEG || m == D3D9_SMOD_SIGNNEG || m == D3D9_SMOD_X2NEG ||
        m == D3D9_SMOD_ABSNEG)
        hfx_sb_put(b, "-");
    else if (m == D3D9_SMOD_COMP) hfx_sb_put(b, "1 - ");
    else if (m == D3D9_SMOD_NOT) hfx_sb_put(b, "!");
    put_reg(b, s, x->type, x->num);
    if (x->relative) put_relative(b, s, x->rel_type, x->rel_num, x->rel_comp);
    if (m <= D3D9_SMOD_NOT) hfx_sb_put(b, suffix[m]);
    /* b, s, l and aL have no components: fxc prints no swizzle whatever the token holds. */
    if (x->type != D3D9_REG_CONSTBOOL && x->type != D3D9_REG_SAMPLER && x->type != D3D9_REG_LABEL &&
        x->type != D3D9_REG_LOOP)
        put_swizzle(b, x->swizzle);
}

static void put_dst(sbuf *b, const d3d9_shader *s, const d3d9_dst *d) {
    put_reg(b, s, d->type, d->num);
    if (d->relative) put_relative(b, s, d->rel_type, d->rel_num, d->rel_comp);
    put_mask(b, d->mask);
}

static void put_dst_mods(sbuf *b, const d3d9_dst *d) {
    static const char *const shifts[] = {"", "_x2", "_x4", "_x8", "", "", "", "", "", "", "", "", "",
                                         "_d8", "_d4", "_d2"};
    hfx_sb_put(b, shifts[d->shift & 0xf]);
    if (d->mods & D3D9_DMOD_SAT) hfx_sb_put(b, "_sat");
    if (d->mods & D3D9_DMOD_PP) hfx_sb_put(b, "_pp");
    if (d->mods & D3D9_DMOD_CENTROID) hfx_sb_put(b, "_centroid");
}

static void put_dcl(sbuf *b, const d3d9_shader *s, const d3d9_inst *in) {
    static const char *const usage[] = {"position", "blendweight", "blendindices", "normal", "psize",
                                        "texcoord", "tangent", "binormal", "tessfactor", "positiont",
                                        "color", "fog", "depth", "sample"};
    static const char *const tex[] = {"", "_1d", "_2d", "_cube", "_volume"};
    hfx_sb_put(b, "dcl");
    const d3d9_dst *d = &in->dst;
    if (d->type == D3D9_REG_SAMPLER) hfx_sb_put(b, tex[in->sampler_type <= 4 ? in->sampler_type : 0]);
    else if (d->type != D3D9_REG_MISC && (s->stage == D3D9_VS || s->model >= D3D9_SM(3, 0))) {
        hfx_sb_printf(b, "_%s", usage[in->usage < 14 ? in->usage : 0]);
        if (in->usage_index) hfx_sb_printf(b, "%u", in->usage_index);
    }
    put_dst_mods(b, d);
    hfx_sb_put(b, " ");
    put_dst(b, s, d);
}

static void put_def(sbuf *b, const d3d9_shader *s, const d3d9_inst *in) {
    hfx_sb_printf(b, "%s ", hfx_d3d9_op_find(in->op)->name);
    put_dst(b, s, &in->dst);
    if (in->op == D3D9_DEFB) { hfx_sb_put(b, in->value.u[0] ? ", true" : ", false"); return; }
    for (unsigned k = 0; k < 4; k++) {
        hfx_sb_put(b, ", ");
        if (in->op == D3D9_DEFI) hfx_sb_printf(b, "%d", (int)in->value.i[k]);
        else put_float(b, in->value.f[k]);
    }
}

/* The mnemonic with its control and destination modifiers: texldp, if_lt, mul_sat_pp. */
static void put_name(sbuf *b, const d3d9_shader *s, const d3d9_inst *in, const d3d9_op_info *op) {
    static const char *const cmp[] = {"", "_gt", "_eq", "_ge", "_lt", "_ne", "_le", ""};
    if (in->op == D3D9_TEX) hfx_sb_put(b, s->model < D3D9_SM(1, 4) ? "tex" : in->control == 1 ? "texldp"
                                   : in->control == 2 ? "texldb" : "texld");
    else if (in->op == D3D9_TEXCOORD) hfx_sb_put(b, s->model == D3D9_SM(1, 4) ? "texcrd" : "texcoord");
    else hfx_sb_put(b, op->name);
    if (op->flags & D3D9_OPF_COMPARE) hfx_sb_put(b, cmp[in->control & 7]);
    if (in->has_dst) put_dst_mods(b, &in->dst);
}

static void put_inst(sbuf *b, const d3d9_shader *s, const d3d9_inst *in) {
    const d3d9_op_info *op = hfx_d3d9_op_find(in->op);
    if (in->op == D3D9_DCL) { put_dcl(b, s, in); return; }
    if (op->flags & (D3D9_OPF_DEF4 | D3D9_OPF_DEF1)) { put_def(b, s, in); return; }
    if (in->coissue) hfx_sb_put(b, "+");
    if (in->predicated) {
        hfx_sb_put(b, "(");
        put_src(b, s, &in->pred);
        hfx_sb_put(b, ") ");
    }
    put_name(b, s, in, op);
    const char *sep = " ";
    if (in->has_dst) { hfx_sb_put(b, sep); put_dst(b, s, &in->dst); sep = ", "; }
    for (unsigned k = 0; k < in->src_count; k++) { hfx_sb_put(b, sep); put_src(b, s, &in->src[k]); sep = ", "; }
}

static int by_name(const void *x, const void *y) {
    const d3d9_constant *a = *(const d3d9_constant *const *)x, *c = *(const d3d9_constant *const *)y;
    return strcmp(a->name, c->name);
}

static void put_type(sbuf *b, const d3d9_constant *k) {
    static const char *const objects[] = {"sampler", "sampler1D", "sampler2D", "sampler3D", "samplerCUBE"};
    const char *base = k->type == 1 ? "bool" : k->type == 2 ? "int" : "float";
    if (k->cls == 4) hfx_sb_put(b, k->type >= 10 && k->type <= 14 ? objects[k->type - 10] : "texture");
    else if (k->cls == 5) hfx_sb_put(b, "struct");
    else if (k->cls == 0) hfx_sb_put(b, base);
    else if (k->cls == 1) hfx_sb_printf(b, "%s%u", base, k->cols);
    else hfx_sb_printf(b, "%s%s%ux%u", k->cls == 2 ? "row_major " : "", base, k->rows, k->cols);
    hfx_sb_printf(b, " %s", k->name);
    if (k->elements > 1) hfx_sb_printf(b, "[%u]", k->elements);
    hfx_sb_put(b, ";\n");
}

static void put_registers(sbuf *b, const d3d9_shader *s) {
    static const char sets[] = "bics";
    size_t w = 12;
    for (uint32_t i = 0; i < s->constant_count; i++)
        if (strlen(s->constants[i].name) > w) w = strlen(s->constants[i].name);
    hfx_sb_printf(b, "// Registers:\n//\n//   %-*s Reg   Size\n//   ", (int)w, "Name");
    for (size_t i = 0; i < w; i++) hfx_sb_put(b, "-");
    hfx_sb_put(b, " ----- ----\n");
    for (uint32_t i = 0; i < s->constant_count; i++) {
        const d3d9_constant *k = &s->constants[i];
        char reg[16];
        snprintf(reg, sizeof reg, "%c%u", sets[k->regset & 3], k->reg);
        hfx_sb_printf(b, "//   %-*s %-5s %4u\n", (int)w, k->name, reg, k->count);
    }
    hfx_sb_put(b, "//\n");
}

static void put_header(sbuf *b, const d3d9_shader *s) {
    if (!s->creator && !s->constants) return;
    hfx_sb_printf(b, "//\n// Generated by %s\n//\n", s->creator ? s->creator : "");
    if (s->constant_count) {
        const d3d9_constant **sorted = malloc(sizeof *sorted * s->constant_count);
        if (!sorted) { b->oom = true; return; }
        for (uint32_t i = 0; i < s->constant_count; i++) sorted[i] = &s->constants[i];
        qsort(sorted, s->constant_count, sizeof *sorted, by_name);
        hfx_sb_put(b, "// Parameters:\n//\n");
        for (uint32_t i = 0; i < s->constant_count; i++) { hfx_sb_put(b, "//   "); put_type(b, sorted[i]); }
        free(sorted);
        hfx_sb_put(b, "//\n//\n");
        put_registers(b, s);
    }
    hfx_sb_put(b, "\n");
}

void hfx_d3d9_count_slots(const d3d9_shader *s, uint32_t *arith, uint32_t *tex) {
    *arith = *tex = 0;
    for (uint32_t i = 0; i < s->inst_count; i++) {
        const d3d9_op_info *op = hfx_d3d9_op_find(s->insts[i].op);
        if (!op || (op->flags & D3D9_OPF_DECL)) continue;
        if (op->flags & D3D9_OPF_TEX) *tex += op->slots;
        else *arith += op->slots;
    }
}

void hfx_d3d9_disassemble(const d3d9_shader *s, sbuf *b) {
    put_header(b, s);
    hfx_sb_printf(b, "    %s\n", hfx_d3d9_model_name(s->stage, s->model));
    unsigned depth = 0;
    for (uint32_t i = 0; i < s->inst_count; i++) {
        const d3d9_inst *in = &s->insts[i];
        const d3d9_op_info *op = hfx_d3d9_op_find(in->op);
        bool out = (op->flags & D3D9_OPF_CLOSE) || in->op == D3D9_ELSE;
        if (out && depth) depth--;
        hfx_sb_printf(b, "    %*s", (int)depth * 2, "");
        put_inst(b, s, in);
        hfx_sb_put(b, "\n");
        if ((op->flags & D3D9_OPF_OPEN) || in->op == D3D9_ELSE) depth++;
    }
    uint32_t arith, tex;
    hfx_d3d9_count_slots(s, &arith, &tex);
    uint32_t n = arith + tex;
    hfx_sb_printf(b, "\n// approximately %u instruction slot%s used", n, n == 1 ? "" : "s");
    if (s->stage == D3D9_PS) hfx_sb_printf(b, " (%u texture, %u arithmetic)", tex, arith);
    hfx_sb_put(b, "\n");
}
