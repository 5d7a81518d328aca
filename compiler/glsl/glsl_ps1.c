/* glsl_ps1.c: the texture coordinate registers of ps_1_1..ps_1_3. There a TEXCOORDn input is
 * either sampled (`tex tN`: sampler N at coordinates N, as they are) or read as a value
 * (`texcoord tN`: "the texture coordinate data is clamped to the range [0, 1]", w = 1;
 * Microsoft's reference page of texcoord). fxc picks by use, so Windows draws a light vector
 * passed in TEXCOORD1 with its negative components at 0; hfx's GLSL reads such an input the same
 * way. An input any sampling call or user function call takes is left as it is (the coordinate of
 * a `tex`, or a use this file does not follow). ps_1_4's `texcrd` does not clamp. */
#include <string.h>

#include "glsl/glsl_int.h"

bool hfx_glsl_ps1_clamps(const char *profile) {
    return profile && strncmp(profile, "ps_1_", 5) == 0 && profile[5] >= '1' && profile[5] <= '3' && !profile[6];
}

static bool touches(const ir_expr *e, const ir_leaf *l);

/* A field chain ending in a variable: whether it and l's path agree as far as both go (In.Tex
 * against In.Tex, or In against In.Tex). */
static bool chain_touches(const ir_expr *e, const ir_leaf *l) {
    uint32_t fields[IR_LEAF_DEPTH], n = 0;
    for (; e->kind == IE_FIELD; e = e->a[0]) {
        if (n == IR_LEAF_DEPTH) return true; /* deeper than a leaf records: assume it */
        fields[n++] = e->field;
    }
    if (e->kind != IE_VAR) return touches(e, l);
    if (e->var != l->root) return false;
    for (uint32_t i = 0; i < n && i < l->depth; i++)
        if (fields[n - 1 - i] != l->fields[i]) return false;
    return true;
}

static bool touches(const ir_expr *e, const ir_leaf *l) {
    if (!e) return false;
    if (e->kind == IE_FIELD || e->kind == IE_VAR) return chain_touches(e, l);
    for (uint32_t i = 0; i < e->n; i++)
        if (touches(e->a[i], l)) return true;
    return false;
}

typedef struct sampled { const ir_leaf *l; bool found; } sampled;

static void note_sample(ir_ctx *c, ir_expr **slot, void *data) {
    (void)c;
    sampled *s = data;
    const ir_expr *e = *slot;
    bool sampling = e->kind == IE_INTRIN && e->n > 1 && e->a[0]->type->kind == TY_SAMPLER;
    if (!sampling && e->kind != IE_CALL) return;
    for (uint32_t i = sampling ? 1 : 0; i < e->n && !s->found; i++) s->found = touches(e->a[i], s->l);
}

bool hfx_glsl_ps1_value_only(ir_ctx *c, const ir_shader *sh, const ir_leaf *l) {
    if (!l->root || l->indexed || strncmp(l->semantic, "TEXCOORD", 8) != 0) return false;
    sampled s = {l, false};
    for (uint32_t i = 0; i < sh->func_count && !s.found; i++) hfx_ir_walk_stmt_exprs(c, sh->funcs[i]->body, note_sample, &s);
    return !s.found;
}
