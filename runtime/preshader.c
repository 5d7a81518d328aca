/* preshader.c: the runtime side of preshaders (common/effect.h, compiler/ir/lower/preshade.c),
 * for any back end. At load, a program's preshaders learn which top-level parameters each reads;
 * Apply marks those of a parameter that changed and, before the registers go to the GPU, runs
 * the marked ones with the one evaluator (common/eval_code) into the register image. An
 * unchanged parameter costs nothing; a changed one recomputes only what depends on it. GL-free. */
#include <stdlib.h>
#include <string.h>

#include "eval_code.h"
#include "internal.h"

/* Calls fn(root) for every parameter read by the code (a root may come more than once). */
static void each_root(const hfx_fx_effect *fx, const uint32_t *code, uint32_t words, void (*fn)(void *, uint32_t),
                      void *ctx) {
    for (uint32_t at = 0; at < words; at = hfx_evc_next(code, at, words)) {
        uint32_t r = hfx_fx_param_read_at(fx, code, at);
        if (r != HFX_NONE) fn(ctx, r);
    }
}

typedef struct walk {
    hfx_preshaders *ps;
    uint32_t pre;       /* the preshader being walked */
    uint32_t *last;     /* per root: 1 + the last preshader counted for it */
    uint32_t *filled;   /* per root: entries written (second walk), or NULL (first: counting) */
} walk;

/* A root read twice by one preshader is listed once. */
static void note_root(void *ctx, uint32_t r) {
    walk *w = ctx;
    if (w->last[r] == w->pre + 1) return;
    w->last[r] = w->pre + 1;
    if (w->filled) w->ps->deps[w->ps->first[r] + w->filled[r]++] = w->pre;
    else w->ps->count[r]++;
}

static void walk_all(walk *w, const hfx_fx_effect *fx, const hfx_fx_program *fp) {
    memset(w->last, 0, (fx->top_param_count + 1) * sizeof *w->last);
    for (w->pre = 0; w->pre < fp->preshader_count; w->pre++)
        each_root(fx, fp->pre_code + fp->preshaders[w->pre].first, fp->preshaders[w->pre].words, note_root, w);
}

/* Per root, the preshaders that read it: deps[first[r] .. first[r] + count[r]). */
static int link_roots(hfx_preshaders *ps, const hfx_fx_effect *fx, const hfx_fx_program *fp) {
    uint32_t tops = fx->top_param_count, total = 0;
    walk w = {ps, 0, calloc(tops + 1, sizeof *w.last), NULL};
    int rc = w.last ? HFX_OK : HFX_ERR_MEMORY;
    if (!rc) walk_all(&w, fx, fp);
    for (uint32_t r = 0; !rc && r < tops; r++) ps->first[r] = total, total += ps->count[r];
    if (!rc && !(ps->deps = malloc((total ? total : 1) * sizeof *ps->deps))) rc = HFX_ERR_MEMORY;
    if (!rc && !(w.filled = calloc(tops + 1, sizeof *w.filled))) rc = HFX_ERR_MEMORY;
    if (!rc) walk_all(&w, fx, fp);
    free(w.last);
    free(w.filled);
    return rc;
}

int hfx_preshaders_init(hfx_preshaders *ps, const hfx_fx_effect *fx, const hfx_fx_program *fp) {
    memset(ps, 0, sizeof *ps);
    if (!fp->preshader_count) return HFX_OK;
    ps->src = fp;
    ps->total = ps->pending = fp->preshader_count;
    ps->dirty = malloc(fp->preshader_count);
    ps->first = calloc((size_t)fx->top_param_count + 1, sizeof *ps->first);
    ps->count = calloc((size_t)fx->top_param_count + 1, sizeof *ps->count);
    if (!ps->dirty || !ps->first || !ps->count) return HFX_ERR_MEMORY;
    memset(ps->dirty, 1, fp->preshader_count); /* the first upload computes them all */
    return link_roots(ps, fx, fp);
}

void hfx_preshaders_free(hfx_preshaders *ps) {
    free(ps->deps);
    free(ps->dirty);
    free(ps->first);
    free(ps->count);
    memset(ps, 0, sizeof *ps);
}

void hfx_preshaders_mark(hfx_preshaders *ps, uint32_t root) {
    const uint32_t *list = ps->deps + ps->first[root];
    for (uint32_t k = 0; k < ps->count[root]; k++) {
        ps->pending += !ps->dirty[list[k]];
        ps->dirty[list[k]] = 1;
    }
}

/* One preshader's value into its registers (regs: reg_size vec4s), rows padded to 4; false when
 * it did not compute (an operation that does not fold: the registers keep their last value). */
static bool run_one(const hfx_preshaders *ps, const hfx_fx_preshader *q, const uint32_t *values, float *regs,
                    uint32_t reg_size) {
    hfx_ev_value v;
    if (q->reg >= reg_size || q->rows > reg_size - q->reg) return false;
    if (!hfx_evc_run(ps->src->pre_code + q->first, q->words, values, &v) || v.n != q->rows * q->cols) return false;
    float *dst = regs + 4 * (size_t)q->reg;
    for (uint32_t r = 0; r < q->rows; r++)
        for (uint32_t c = 0; c < q->cols; c++) dst[4 * r + c] = (float)v.c[r * q->cols + c];
    return true;
}

void hfx_preshaders_run(hfx_preshaders *ps, const uint32_t *values, float *regs, uint32_t reg_size,
                        hfx_reg_range *range) {
    for (uint32_t k = 0; k < ps->total && ps->pending; k++) {
        if (!ps->dirty[k]) continue;
        const hfx_fx_preshader *q = &ps->src->preshaders[k];
        ps->dirty[k] = 0;
        ps->pending--;
        ps->runs++;
        if (!run_one(ps, q, values, regs, reg_size)) continue;
        uint32_t last = q->reg + q->rows - 1u;
        if (q->reg < range->lo) range->lo = q->reg;
        if (last > range->hi) range->hi = last;
    }
}
