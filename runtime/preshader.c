/* preshader.c: the runtime side of preshaders (common/effect.h, compiler/ir/lower/preshade.c).
 * At load, each parameter slot of a program learns which preshaders read it; Apply marks those
 * when the parameter changed and, before sending the registers, runs the marked ones with the
 * one evaluator (common/eval_code) into the register image. An unchanged parameter costs
 * nothing; a changed one recomputes only what depends on it. GL-free. */
#include <stdlib.h>
#include <string.h>

#include "eval_code.h"
#include "internal.h"

/* Calls fn(root) for every parameter read by the code (a root may come more than once). */
static void each_root(const hfx_fx_effect *fx, const uint32_t *code, uint32_t words, void (*fn)(void *, uint32_t),
                      void *ctx) {
    for (uint32_t at = 0; at < words; at = hfx_evc_next(code, at, words)) {
        uint32_t op = code[at] & 0xffu;
        if (op != HFX_EVC_PARAM && op != HFX_EVC_ELEMENT) continue;
        uint32_t r = hfx_fx_param_at_word(fx, code[at + 1]);
        if (r != HFX_NONE) fn(ctx, r);
    }
}

typedef struct deps {
    hfx_rt_program *p;
    uint32_t pre;       /* the preshader being walked */
    uint32_t *last;     /* per slot: 1 + the last preshader counted for it */
    uint32_t *count;    /* per slot: preshaders reading it (first walk), entries written (second) */
    bool filling;       /* the second walk: write the lists */
} deps;

/* A root read twice by one preshader is listed once. */
static void note_root(void *ctx, uint32_t r) {
    deps *d = ctx;
    if (d->last[r] == d->pre + 1) return;
    d->last[r] = d->pre + 1;
    if (d->filling) d->p->pre_deps[d->p->slots[r].pre_first + d->count[r]] = d->pre;
    d->count[r]++;
}

static void walk_all(deps *d, const hfx_fx_effect *fx, const hfx_fx_program *fp) {
    for (d->pre = 0; d->pre < fp->preshader_count; d->pre++)
        each_root(fx, fp->pre_code + fp->preshaders[d->pre].first, fp->preshaders[d->pre].words, note_root, d);
}

static int add_read(hfx_rt_program *p, uint32_t r) {
    for (uint32_t k = 0; k < p->read_count; k++)
        if (p->reads[k] == r) return HFX_OK;
    uint32_t *grown = realloc(p->reads, ((size_t)p->read_count + 1) * sizeof *grown);
    if (!grown) return HFX_ERR_MEMORY;
    p->reads = grown;
    p->reads[p->read_count++] = r;
    return HFX_OK;
}

/* Slot lists: where each begins, and the parameters read only by preshaders added to reads. */
static int place_lists(hfx_rt_program *p, const uint32_t *count, uint32_t tops) {
    uint32_t total = 0;
    for (uint32_t r = 0; r < tops; r++) {
        if (!count[r]) continue;
        if (total + count[r] > UINT16_MAX || add_read(p, r) != HFX_OK) return HFX_ERR_MEMORY;
        p->slots[r].pre_first = (uint16_t)total;
        p->slots[r].pre_count = (uint16_t)count[r];
        total += count[r];
    }
    p->pre_deps = malloc((total ? total : 1) * sizeof *p->pre_deps);
    return p->pre_deps ? HFX_OK : HFX_ERR_MEMORY;
}

/* Per slot, the preshaders that read its parameter (slot.pre_first / pre_count into pre_deps). */
static int link_slots(hfx_rt_program *p, const hfx_fx_effect *fx, const hfx_fx_program *fp) {
    uint32_t tops = fx->top_param_count;
    deps d = {p, 0, calloc(tops + 1, sizeof *d.last), calloc(tops + 1, sizeof *d.count), false};
    int rc = d.last && d.count ? HFX_OK : HFX_ERR_MEMORY;
    if (!rc) walk_all(&d, fx, fp);
    if (!rc) rc = place_lists(p, d.count, tops);
    if (!rc) {
        memset(d.last, 0, (tops + 1) * sizeof *d.last);
        memset(d.count, 0, (tops + 1) * sizeof *d.count);
        d.filling = true;
        walk_all(&d, fx, fp);
    }
    free(d.last);
    free(d.count);
    return rc;
}

int hfx_rt_preshaders_setup(hfx_rt_program *p, const hfx_fx_effect *fx, const hfx_fx_program *fp) {
    if (!fp->preshader_count || !p->regs) return HFX_OK;
    p->pre_dirty = calloc(fp->preshader_count, 1);
    if (!p->pre_dirty) return HFX_ERR_MEMORY;
    p->pre_source = fp;
    p->pre_total = p->pre_pending = fp->preshader_count;
    memset(p->pre_dirty, 1, fp->preshader_count); /* the first upload computes them all */
    return link_slots(p, fx, fp);
}

void hfx_rt_preshaders_mark(hfx_rt_program *p, const hfx_slot *s) {
    const uint32_t *list = p->pre_deps + s->pre_first;
    for (uint32_t k = 0; k < s->pre_count; k++) {
        p->pre_pending += !p->pre_dirty[list[k]];
        p->pre_dirty[list[k]] = 1;
    }
}

/* One preshader's value into its registers, rows padded to 4; false when it did not compute
 * (an operation that does not fold: the registers keep their last value). */
static bool run_one(hfx_rt_program *p, const hfx_fx_preshader *q, const uint32_t *values) {
    hfx_ev_value v;
    if (!hfx_evc_run(p->pre_source->pre_code + q->first, q->words, values, &v) || v.n != q->rows * q->cols) return false;
    float *dst = p->regs + 4 * (size_t)q->reg;
    for (uint32_t r = 0; r < q->rows; r++)
        for (uint32_t c = 0; c < q->cols; c++) dst[4 * r + c] = (float)v.c[r * q->cols + c];
    return true;
}

void hfx_rt_preshaders_run(hfx_rt_program *p, const uint32_t *values, hfx_reg_range *regs) {
    for (uint32_t k = 0; k < p->pre_total && p->pre_pending; k++) {
        if (!p->pre_dirty[k]) continue;
        const hfx_fx_preshader *q = &p->pre_source->preshaders[k];
        p->pre_dirty[k] = 0;
        p->pre_pending--;
        p->pre_runs++;
        if (!run_one(p, q, values) || q->reg >= p->reg_size) continue;
        uint32_t last = q->reg + q->rows - 1u;
        if (q->reg < regs->lo) regs->lo = q->reg;
        if (last > regs->hi) regs->hi = last;
    }
}
