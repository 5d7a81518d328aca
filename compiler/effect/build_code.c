/* build_code.c: a state value that reads parameters (`AlphaRef = (Ref * 255);`,
 * `CullMode = (Cull ? 2 : 1);`, `FillMode = (Modes[Index]);`) as a common/eval_code program in
 * fx->exprs, which the runtime runs at Apply with the compiler's arithmetic. The value is built
 * as IR (hfx_ir_build_value), folded as fxc folds it (hfx_ir_fold_value) and written by ir/pre_code.c,
 * the one writer of evaluator programs (preshaders are written by it too), so a state value and
 * a preshader of the same expression are the same program. Anything else is not compiled. */
#include <string.h>

#include "effect/build_int.h"

static uint32_t param_of(void *data, const hfx_expr *e) { return hfx_build_param_of(data, e); }

/* Appends the program to fx->exprs: its first word and length. */
static bool append(hfx_builder *b, const uint32_t *code, uint32_t n, uint32_t *first, uint32_t *words) {
    hfx_fx_effect *fx = b->fx;
    uint32_t start = fx->expr_words;
    for (uint32_t i = 0; i < n; i++) {
        if (!HFX_BUILD_GROW(b, fx->exprs, fx->expr_words, b->expr_cap)) {
            fx->expr_words = start; /* nothing of a program that could not be stored */
            return false;
        }
        fx->exprs[fx->expr_words++] = code[i];
    }
    *first = start;
    *words = n;
    return true;
}

/* e's program; clamp > 0: its value clamped into an array of clamp entries. */
static bool compile(hfx_builder *b, const hfx_expr *e, const hfx_state_info *names, uint32_t clamp, uint32_t *first,
                    uint32_t *words) {
    ir_ctx c = {b->arena, b->diags, b->types, b->ast, b->fx};
    ir_value_src src = {names, param_of, b};
    ir_expr *v = hfx_ir_build_value(&c, e, &src);
    if (!v) return false;
    hfx_ir_fold_value(&c, &v);
    uint32_t n = 0, *code = hfx_ir_value_code(&c, v, clamp, &n);
    return code && append(b, code, n, first, words);
}

bool hfx_build_code(hfx_builder *b, const hfx_expr *e, const hfx_state_info *names, uint32_t *first, uint32_t *words) {
    return compile(b, e, names, 0, first, words);
}

bool hfx_build_selector(hfx_builder *b, const hfx_expr *index, uint32_t count, uint32_t *first, uint32_t *words) {
    return count && compile(b, index, NULL, count, first, words);
}
