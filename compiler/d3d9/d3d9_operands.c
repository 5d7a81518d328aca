/* d3d9_operands.c: destination, source and declaration tokens, and which registers a model
 * and stage have (Microsoft's "Registers" pages per model). */
#include "d3d9/d3d9_int.h"

#include <stdio.h>

/* The register type of a parameter token: bits 28-30 and 11-12. */
static unsigned reg_type(uint32_t t) { return ((t >> 28) & 7) | ((t >> 8) & 0x18); }

/* c registers past 2047 come as CONST2..4: fold them into CONST. */
static void fold_const(uint8_t *type, uint16_t *num) {
    if (*type >= D3D9_REG_CONST2 && *type <= D3D9_REG_CONST4) {
        *num = (uint16_t)(*num + 2048 * (*type - D3D9_REG_CONST2 + 1));
        *type = D3D9_REG_CONST;
    }
}

/* How many registers of a type the model has (0: none). `dst`: written by an instruction. */
static unsigned reg_limit(d3d9_stage st, uint8_t m, unsigned type, bool dst) {
    bool vs = st == D3D9_VS, sm2 = m >= D3D9_SM(2, 0), sm3 = m >= D3D9_SM(3, 0);
    switch (type) {
    case D3D9_REG_TEMP: return 32;
    case D3D9_REG_INPUT: return dst ? 0 : vs ? 16 : sm3 ? 10 : 2;
    case D3D9_REG_CONST: return dst ? 0 : 8192;
    case D3D9_REG_ADDR: return vs ? 1 : sm3 ? 0 : !sm2 ? 8 : dst ? 0 : 8;
    case D3D9_REG_RASTOUT: return vs && !sm3 && dst ? 3 : 0;
    case D3D9_REG_ATTROUT: return vs && !sm3 && dst ? 2 : 0;
    case D3D9_REG_OUTPUT: return vs && dst ? (sm3 ? 12 : 8) : 0;
    case D3D9_REG_CONSTINT: case D3D9_REG_CONSTBOOL: /* static flow control: vs_2_0, ps_2_x */
        return !dst && m >= (vs ? D3D9_SM(2, 0) : D3D9_SM(2, 1)) ? 16 : 0;
    case D3D9_REG_COLOROUT: return !vs && sm2 && dst ? 4 : 0;
    case D3D9_REG_DEPTHOUT: return !vs && sm2 && dst ? 1 : 0;
    case D3D9_REG_SAMPLER: return dst ? 0 : vs ? (sm3 ? 4 : 0) : sm2 ? 16 : 0;
    case D3D9_REG_LOOP: return !dst && (vs ? sm2 : sm3) ? 1 : 0;
    case D3D9_REG_MISC: return !vs && sm3 && !dst ? 2 : 0;
    case D3D9_REG_LABEL: return sm2 && !dst ? 2048 : 0;
    case D3D9_REG_PREDICATE: return m >= D3D9_SM(2, 1) ? 1 : 0;
    default: return 0;
    }
}

static const char *const type_names[] = {
    "r", "v", "c", "a/t", "oPos/oFog/oPts", "oD", "oT/o", "i", "oC", "oDepth", "s", "c", "c", "c",
    "b", "aL", "half", "vPos/vFace", "l", "p"
};

static void check_reg(d3d9_reader *r, uint32_t at, unsigned type, unsigned num, bool dst) {
    unsigned lim = reg_limit(r->sh->stage, r->sh->model, type, dst);
    const char *name = type < 20 ? type_names[type] : "?";
    const char *model = hfx_d3d9_model_name(r->sh->stage, r->sh->model);
    if (!lim) hfx_d3d9_fail(r, at, X_D3D9_OPERAND, "register type %u (%s) cannot be %s in %s", type, name,
                        dst ? "written" : "read", model);
    else if (num >= lim) hfx_d3d9_fail(r, at, X_D3D9_OPERAND, "register %s%u out of range in %s (%u)", name, num, model, lim);
}

/* Declarations name a register of their own kind: v, t, s, o, vPos / vFace. */
static void check_decl_reg(d3d9_reader *r, uint32_t at, unsigned type, unsigned num) {
    d3d9_stage st = r->sh->stage;
    uint8_t m = r->sh->model;
    unsigned lim = 0;
    if (type == D3D9_REG_INPUT) lim = st == D3D9_VS ? 16 : m >= D3D9_SM(3, 0) ? 10 : 2;
    else if (type == D3D9_REG_OUTPUT) lim = st == D3D9_VS && m >= D3D9_SM(3, 0) ? 12 : 0;
    else if (type == D3D9_REG_SAMPLER) lim = reg_limit(st, m, type, false);
    else if (type == D3D9_REG_ADDR) lim = st == D3D9_PS && m < D3D9_SM(3, 0) ? 8 : 0;
    else if (type == D3D9_REG_MISC) lim = reg_limit(st, m, type, false);
    if (!lim) hfx_d3d9_fail(r, at, X_D3D9_OPERAND, "dcl of register type %u in %s", type, hfx_d3d9_model_name(st, m));
    else if (num >= lim) hfx_d3d9_fail(r, at, X_D3D9_OPERAND, "dcl of register %u out of range (%u)", num, lim);
}

typedef struct cursor { d3d9_reader *r; uint32_t at, end; bool short_; } cursor;

static bool next(cursor *c, uint32_t *t) {
    if (c->at >= c->end) { c->short_ = true; return false; }
    *t = hfx_d3d9_word(c->r, c->at++);
    return true;
}

/* The address register of a relative operand (SM2+: its own token; vs_1_1: a0.x). */
static void read_relative(cursor *c, uint8_t *type, uint16_t *num, uint8_t *comp) {
    d3d9_reader *r = c->r;
    if (r->sh->model < D3D9_SM(2, 0)) { *type = D3D9_REG_ADDR; *num = 0; *comp = 0; return; }
    uint32_t t, at = c->at;
    if (!next(c, &t)) return;
    *type = (uint8_t)reg_type(t);
    *num = t & 0x7ff;
    *comp = (t >> 16) & 3;
    if (*type != D3D9_REG_ADDR && *type != D3D9_REG_LOOP)
        hfx_d3d9_fail(r, at, X_D3D9_OPERAND, "relative addressing through register type %u (a0 or aL expected)", *type);
    else check_reg(r, at, *type, *num, false);
}

static void read_dst(cursor *c, d3d9_dst *d, bool check) {
    uint32_t t, at = c->at;
    if (!next(c, &t)) return;
    if (!(t & 0x80000000u)) hfx_d3d9_fail(c->r, at, X_D3D9_OPERAND, "parameter token with bit 31 clear");
    d->type = (uint8_t)reg_type(t);
    d->num = t & 0x7ff;
    d->relative = (t >> 13) & 1;
    d->mask = (t >> 16) & 0xf;
    d->mods = (t >> 20) & 0xf;
    d->shift = (int8_t)(((t >> 24) & 0xf) ^ 8) - 8;
    fold_const(&d->type, &d->num);
    if (d->relative) read_relative(c, &d->rel_type, &d->rel_num, &d->rel_comp);
    if (check) check_reg(c->r, at, d->type, d->num, true);
}

static void read_src(cursor *c, d3d9_src *s) {
    uint32_t t, at = c->at;
    if (!next(c, &t)) return;
    if (!(t & 0x80000000u)) hfx_d3d9_fail(c->r, at, X_D3D9_OPERAND, "parameter token with bit 31 clear");
    s->type = (uint8_t)reg_type(t);
    s->num = t & 0x7ff;
    s->relative = (t >> 13) & 1;
    s->swizzle = (t >> 16) & 0xff;
    s->mod = (t >> 24) & 0xf;
    fold_const(&s->type, &s->num);
    if (s->mod > D3D9_SMOD_NOT) hfx_d3d9_fail(c->r, at, X_D3D9_OPERAND, "unknown source modifier %u", s->mod);
    if (s->relative) read_relative(c, &s->rel_type, &s->rel_num, &s->rel_comp);
    check_reg(c->r, at, s->type, s->num, false);
}

/* dcl: the declaration token (usage or sampler type), then the register. */
static void read_dcl(cursor *c, d3d9_inst *in) {
    uint32_t t;
    if (!next(c, &t)) return;
    uint32_t at = c->at;
    read_dst(c, &in->dst, false);
    in->has_dst = true;
    if (c->short_) return;
    if (in->dst.type == D3D9_REG_SAMPLER) {
        in->sampler_type = (t >> 27) & 0xf;
        if (in->sampler_type < 1 || in->sampler_type > 4)
            hfx_d3d9_fail(c->r, at - 1, X_D3D9_OPERAND, "dcl of a sampler of unknown type %u", in->sampler_type);
    } else {
        in->usage = t & 0x1f;
        in->usage_index = (t >> 16) & 0xf;
        if (in->usage > 13) hfx_d3d9_fail(c->r, at - 1, X_D3D9_OPERAND, "dcl with unknown usage %u", in->usage);
    }
    check_decl_reg(c->r, at, in->dst.type, in->dst.num);
}

/* def / defi / defb: the register, then literal words. */
static void read_def(cursor *c, d3d9_inst *in, const d3d9_op_info *op) {
    uint32_t at = c->at;
    read_dst(c, &in->dst, false);
    in->has_dst = true;
    unsigned want = op->token == D3D9_DEF ? D3D9_REG_CONST : op->token == D3D9_DEFI ? D3D9_REG_CONSTINT
                                                                                     : D3D9_REG_CONSTBOOL;
    if (!c->short_ && in->dst.type != want)
        hfx_d3d9_fail(c->r, at, X_D3D9_OPERAND, "%s of register type %u", op->name, in->dst.type);
    unsigned n = op->flags & D3D9_OPF_DEF4 ? 4 : 1;
    for (unsigned k = 0; k < n; k++) next(c, &in->value.u[k]);
}

void hfx_d3d9_read_operands(d3d9_reader *r, d3d9_inst *in, const d3d9_op_info *op, uint32_t i, uint32_t len) {
    cursor c = {r, i + 1, i + 1 + len, false};
    unsigned ndst, nsrc;
    hfx_d3d9_operand_counts(op, r->sh->model, &ndst, &nsrc);
    if (op->token == D3D9_DCL) read_dcl(&c, in);
    else if (op->flags & (D3D9_OPF_DEF4 | D3D9_OPF_DEF1)) read_def(&c, in, op);
    else {
        if (ndst) { read_dst(&c, &in->dst, true); in->has_dst = true; }
        if (in->predicated) read_src(&c, &in->pred);
        for (unsigned k = 0; k < nsrc && !c.short_; k++) read_src(&c, &in->src[in->src_count++]);
    }
    unsigned want = op->token == D3D9_DCL ? 2 : (op->flags & D3D9_OPF_DEF4) ? 5 : (op->flags & D3D9_OPF_DEF1) ? 2
                  : ndst + nsrc + in->predicated;
    if (c.short_) hfx_d3d9_fail(r, i, X_D3D9_OPERAND, "%s needs %u operand tokens, has %u", op->name, want, len);
    else if (c.at != c.end) hfx_d3d9_fail(r, i, X_D3D9_OPERAND, "%s has %u operand tokens, expected %u", op->name,
                                      len, c.at - i - 1);
}

/* --- read ports --- */

unsigned hfx_d3d9_read_ports(d3d9_stage st, uint8_t m, unsigned type) {
    if (st == D3D9_PS && m < D3D9_SM(2, 0)) switch (type) { /* ps_1_x's "Read Port Limit" table */
        case D3D9_REG_CONST: case D3D9_REG_INPUT: return 2;
        case D3D9_REG_TEMP: return m == D3D9_SM(1, 4) ? 3 : 2;
        case D3D9_REG_ADDR: return m == D3D9_SM(1, 1) ? 2 : m == D3D9_SM(1, 4) ? 1 : 3;
        default: return 1;
        }
    return type == D3D9_REG_TEMP ? 3 : type == D3D9_REG_MISC ? 2 : 1;
}

bool hfx_d3d9_port_source(const d3d9_inst *in, uint8_t m, unsigned k) {
    return !(in->op == D3D9_SINCOS && m < D3D9_SM(3, 0) && k > 0);
}

bool hfx_d3d9_same_register(const d3d9_src *a, const d3d9_src *b) {
    if (a->type != b->type || a->num != b->num || a->relative != b->relative) return false;
    return !a->relative || (a->rel_type == b->rel_type && a->rel_num == b->rel_num && a->rel_comp == b->rel_comp);
}

/* Sources of `in` that take a port, texkill's operand (its destination token) among them. */
static unsigned port_sources(const d3d9_inst *in, uint8_t m, d3d9_src *out) {
    unsigned n = 0;
    for (unsigned k = 0; k < in->src_count && k < 4; k++)
        if (hfx_d3d9_port_source(in, m, k)) out[n++] = in->src[k];
    if (in->op == D3D9_TEXKILL && in->has_dst)
        out[n++] = (d3d9_src){.type = in->dst.type, .num = in->dst.num, .relative = in->dst.relative,
                              .rel_type = in->dst.rel_type, .rel_num = in->dst.rel_num, .rel_comp = in->dst.rel_comp};
    return n;
}

int hfx_d3d9_port_excess(d3d9_stage st, uint8_t m, const d3d9_inst *in, unsigned *count) {
    d3d9_src s[5];
    unsigned n = port_sources(in, m, s);
    for (unsigned k = 0; k < n; k++) {
        bool first = true; /* each type counted once, at its first source */
        for (unsigned j = 0; j < k; j++) first &= s[j].type != s[k].type;
        if (!first) continue;
        unsigned distinct = 0;
        for (unsigned j = k; j < n; j++) {
            bool fresh = s[j].type == s[k].type;
            for (unsigned i = k; i < j && fresh; i++) fresh = !hfx_d3d9_same_register(&s[i], &s[j]);
            distinct += fresh;
        }
        if (distinct > hfx_d3d9_read_ports(st, m, s[k].type)) {
            *count = distinct;
            return s[k].type;
        }
    }
    return -1;
}

/* A register as fxc's listing names it: c5, c5[a0.x], t0, vFace. */
static void put_reg(char *buf, size_t size, d3d9_stage st, const d3d9_src *s) {
    static const char *const names[] = {"r", "v", "c", "a", "oPos", "oD", "o", "i", "oC", "oDepth", "s", "c", "c", "c",
                                        "b", "aL", "h", "vPos", "l", "p"};
    const char *name = s->type < 20 ? names[s->type] : "?";
    if (s->type == D3D9_REG_ADDR && st == D3D9_PS) name = "t";
    if (s->type == D3D9_REG_MISC) { snprintf(buf, size, "%s", s->num ? "vFace" : "vPos"); return; }
    if (!s->relative) { snprintf(buf, size, "%s%u", name, s->num); return; }
    if (s->rel_type == D3D9_REG_LOOP) snprintf(buf, size, "%s%u[aL]", name, s->num);
    else snprintf(buf, size, "%s%u[a0.%c]", name, s->num, "xyzw"[s->rel_comp & 3]);
}

void hfx_d3d9_check_ports(d3d9_reader *r, const d3d9_inst *in, const d3d9_op_info *op, uint32_t at) {
    unsigned count;
    d3d9_stage st = r->sh->stage;
    uint8_t m = r->sh->model;
    int type = hfx_d3d9_port_excess(st, m, in, &count);
    if (type < 0) return;
    d3d9_src s[5];
    unsigned n = port_sources(in, m, s), listed = 0;
    char regs[96] = "", one[24];
    for (unsigned k = 0; k < n; k++) {
        bool fresh = s[k].type == (unsigned)type;
        for (unsigned j = 0; j < k && fresh; j++) fresh = !hfx_d3d9_same_register(&s[j], &s[k]);
        if (!fresh) continue;
        put_reg(one, sizeof one, st, &s[k]);
        if (listed++) strcat(regs, ", ");
        strcat(regs, one);
    }
    unsigned ports = hfx_d3d9_read_ports(st, m, (unsigned)type);
    hfx_d3d9_fail(r, at, X_D3D9_OPERAND, "%s reads %u different registers (%s); %s has %u read port%s for them",
                  op->name, count, regs, hfx_d3d9_model_name(st, m), ports, ports == 1 ? "" : "s");
}

/* --- scalar sources --- */

unsigned hfx_d3d9_scalar_sources(const d3d9_inst *in) {
    if (!(hfx_d3d9_op_find(in->op)->flags & D3D9_OPF_SCALAR)) return 0;
    return in->op == D3D9_SINCOS ? 1 : in->src_count; /* SM2's sincos: two constants follow */
}

/* From vs_2_0 / ps_2_0 on, Microsoft's instruction pages require a scalar instruction's sources
 * to name their one component by a replicate swizzle (`rsq r0.x, r1.y`). */
void hfx_d3d9_check_scalar_sources(d3d9_reader *r, const d3d9_inst *in, const d3d9_op_info *op, uint32_t at) {
    if (r->sh->model < D3D9_SM(2, 0)) return;
    for (unsigned k = 0, n = hfx_d3d9_scalar_sources(in); k < n; k++) {
        uint8_t sw = in->src[k].swizzle;
        if (sw == (uint8_t)((sw & 3u) * 0x55u)) continue;
        char reg[24];
        put_reg(reg, sizeof reg, r->sh->stage, &in->src[k]);
        hfx_d3d9_fail(r, at, X_D3D9_OPERAND, "%s reads %s without a replicate swizzle (.x, .y, .z or .w)", op->name, reg);
        return;
    }
}
