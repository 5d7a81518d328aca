/* glsl_pack.c: HFXC_PACK_UNIFORMS in the GLSL. A packed parameter keeps its GLSL name as a
 * private global, set at the start of main() from `uniform vec4 hfx_c[K]` (K the program's
 * reg_count in both stages, so the stages link), and the rest of the code reads it unchanged.
 * The runtime copies the parameter's row-major words into the registers row by row, so HLSL row
 * i is register reg + i; GLSL's matRxC takes its column i from there, which is what
 * glUniformMatrix*fv(transpose = GL_FALSE) of the same words gives the unpacked uniform. */
#include "glsl/glsl_int.h"

static uint32_t preshader_reg(const gp *p, const ir_var *v) {
    for (uint32_t k = 0; k < p->io->pre_count; k++)
        if (p->io->pre_vars[k] == v) return p->io->pre_regs[k];
    return HFX_NONE;
}

uint32_t hfx_glsl_packed_reg(const gp *p, const ir_var *v) {
    if (v->pre && p->io) return preshader_reg(p, v);
    if (v->kind != IRV_UNIFORM || v->param == HFX_NONE || !p->io) return HFX_NONE;
    for (uint32_t k = 0; k < p->io->uniform_count; k++) {
        const hfx_fx_uniform_use *u = &p->io->uniforms[k];
        if (u->param == v->param) return u->reg != HFX_NONE && u->reg < p->io->reg_count ? u->reg : HFX_NONE;
    }
    return HFX_NONE;
}

static bool stage_packs(const gp *p) {
    for (uint32_t i = 0; i < p->sh->global_count; i++)
        if (hfx_glsl_packed_reg(p, p->sh->globals[i]) != HFX_NONE) return true;
    return false;
}

void hfx_glsl_declare_regs(gp *p) {
    if (stage_packs(p))
        hfx_glsl_uniform(p, NULL, HFX_FX_REGS_NAME,
                     hfx_arena_printf(p->c->arena, "vec4 %s[%u]", HFX_FX_REGS_NAME, p->io->reg_count), false);
}

void hfx_glsl_declare_packed(gp *p, const ir_var *v, uint32_t reg) {
    const hfx_type *t = v->type;
    uint32_t n = t->kind == TY_MATRIX ? t->rows : 1;
    hfx_glsl_decl(p, p->out, t, v->glsl);
    if (n > 1) hfx_sb_printf(p->out, "; // %s[%u..%u]", HFX_FX_REGS_NAME, reg, reg + n - 1);
    else hfx_sb_printf(p->out, "; // %s[%u]", HFX_FX_REGS_NAME, reg);
    if (v->pre) hfx_sb_printf(p->out, " = %s, computed on the CPU (a preshader)", v->pre_text);
    hfx_sb_put(p->out, "\n");
}

/* Register r, narrowed to its first n components. */
static void reg_comps(gp *p, uint32_t r, unsigned n) {
    hfx_sb_printf(p->out, "%s[%u]", HFX_FX_REGS_NAME, r);
    if (n < 4) hfx_sb_printf(p->out, ".%.*s", (int)n, "xyzw");
}

/* The value of a packed parameter of type t whose first register is reg. A matrix of R > 1 rows
 * is built from R registers of C components each: matRxC's columns, or the components of the
 * vector an Rx1 matrix is in GLSL; a scalar, a vector or a 1xC matrix is its register's first
 * components. */
static void packed_value(gp *p, const hfx_type *t, uint32_t reg) {
    if (t->kind != TY_MATRIX || t->rows == 1) {
        reg_comps(p, reg, hfx_type_components(t));
        return;
    }
    hfx_sb_printf(p->out, "%s(", hfx_glsl_type(p, t));
    for (uint32_t i = 0; i < t->rows; i++) {
        if (i) hfx_sb_put(p->out, ", ");
        reg_comps(p, reg + i, t->cols);
    }
    hfx_sb_put(p->out, ")");
}

void hfx_glsl_init_packed(gp *p) {
    for (uint32_t i = 0; i < p->sh->global_count; i++) {
        const ir_var *v = p->sh->globals[i];
        uint32_t reg = hfx_glsl_packed_reg(p, v);
        if (reg == HFX_NONE) continue;
        for (int k = 0; k < p->indent; k++) hfx_sb_put(p->out, "    ");
        hfx_sb_printf(p->out, "%s = ", v->glsl);
        packed_value(p, v->type, reg);
        hfx_sb_put(p->out, ";\n");
    }
}
