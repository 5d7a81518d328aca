/* uniforms.c: an instance's uniform block per program, kept up to date from the parameters:
 * the change log says which top-level parameters changed since the program last looked (as on
 * GL), and only those are copied into the block's image; Apply then writes the image into a
 * new slice of the frame's ring only when something changed. Packed parameters go into hfx_c
 * row by row, exactly as GL's hfx_c[] holds them (D3D9's registers). */
#include <stdlib.h>
#include <string.h>

#include "eval.h"
#include "vk/vk.h"

int hfx_vk_bound_make(hfx_effect *fx, const vk_program *p, vk_bound **out) {
    vk_bound *b = calloc(1, sizeof *b);
    uint32_t n = p->sampler_count ? p->sampler_count : 1;
    if (!b) return hfx_rt_fail(fx->dev, HFX_ERR_MEMORY, "out of memory");
    b->image = calloc(p->block_size ? p->block_size : 16, 1);
    b->held = calloc((size_t)fx->sh->fx->top_param_count + 1, sizeof *b->held);
    b->views = calloc(n, sizeof *b->views);
    b->layouts = calloc(n, sizeof *b->layouts);
    b->vk_samplers = calloc(n, sizeof *b->vk_samplers);
    if (!b->image || !b->held || !b->views || !b->layouts || !b->vk_samplers) {
        hfx_vk_bound_free(b);
        return hfx_rt_fail(fx->dev, HFX_ERR_MEMORY, "out of memory");
    }
    if (p->regs_at >= 0 && p->fp && hfx_preshaders_init(&b->pre, fx->sh->fx, p->fp) != HFX_OK) {
        hfx_vk_bound_free(b);
        return hfx_rt_fail(fx->dev, HFX_ERR_MEMORY, "out of memory");
    }
    b->dirty = 1;
    *out = b;
    return HFX_OK;
}

void hfx_vk_bound_free(vk_bound *b) {
    if (!b) return;
    free(b->image), free(b->held), free(b->views), free(b->layouts), free(b->vk_samplers);
    hfx_preshaders_free(&b->pre);
    free(b);
}

/* A packed parameter's rows into its registers, padded to 4 components (hfx_rt_reg_fill's rule). */
static void write_regs(uint8_t *regs, const vk_slot *s, const uint32_t *values) {
    const uint32_t *src = values + s->offset;
    uint8_t *dst = regs + 16 * (size_t)s->reg;
    if (s->reg_cols == 4) {
        memcpy(dst, src, 16 * (size_t)s->reg_rows);
        return;
    }
    for (uint32_t i = 0; i < s->reg_rows; i++) memcpy(dst + 16 * i, src + i * s->reg_cols, 4 * (size_t)s->reg_cols);
}

static void convert(uint8_t *dst, const uint32_t *src, uint32_t n, uint16_t kind) {
    for (uint32_t i = 0; i < n; i++) {
        uint32_t w = src[i];
        if (kind == VK_UP_TO_INT) {
            float f;
            memcpy(&f, &w, 4);
            int32_t v = hfx_ev_int(f);
            memcpy(dst + 4 * i, &v, 4);
        } else {
            float f = (float)(int32_t)w;
            memcpy(dst + 4 * i, &f, 4);
        }
    }
}

/* One leaf: every element, every column (GL's column-major words) at the block's strides. */
static void write_upload(uint8_t *img, const vk_upload *u, const uint32_t *values) {
    uint32_t per = (uint32_t)u->comps * u->cols;
    for (uint32_t e = 0; e < u->count; e++)
        for (uint32_t c = 0; c < u->cols; c++) {
            uint8_t *dst = img + u->dst + e * u->stride + c * u->col_stride;
            const uint32_t *src = values + u->src + e * per + c * u->comps;
            if (u->kind == VK_UP_SAME) memcpy(dst, src, 4 * (size_t)u->comps);
            else convert(dst, src, u->comps, u->kind);
        }
}

/* Parameter r changed: its registers or uploads, and the preshaders that read it. */
static void write_slot(const vk_program *p, vk_bound *b, uint32_t r, const uint32_t *values) {
    const vk_slot *s = &p->slots[r];
    if (s->mode == VK_SLOT_REG) write_regs(b->image + p->regs_at, s, values);
    for (uint32_t k = 0; s->mode == VK_SLOT_OTHER && k < s->count; k++) write_upload(b->image, &p->uploads[s->first + k], values);
    if (hfx_preshaders_read(&b->pre, r)) hfx_preshaders_mark(&b->pre, r);
    b->dirty = 1;
}

/* A parameter this program's block depends on: read by the shaders or by a preshader. */
static bool depends_on(const vk_program *p, const vk_bound *b, uint32_t r) {
    return p->slots[r].mode || hfx_preshaders_read(&b->pre, r);
}

static void scan_all(hfx_effect *fx, const vk_program *p, vk_bound *b) {
    for (uint32_t r = 0; r < fx->sh->fx->top_param_count; r++) {
        if (b->held[r] == fx->stamps[r] || !depends_on(p, b, r)) continue;
        b->held[r] = fx->stamps[r];
        write_slot(p, b, r, fx->values);
    }
    b->seen = fx->log_len;
}

/* The marked preshaders into the image's registers. */
static void run_preshaders(hfx_effect *fx, const vk_program *p, vk_bound *b) {
    hfx_reg_range range = {UINT32_MAX, 0};
    hfx_preshaders_run(&b->pre, fx->values, (float *)(void *)(b->image + p->regs_at), p->reg_count, &range);
    if (range.lo <= range.hi) b->dirty = 1;
}

/* A packed parameter of rows of 4 components: its words are its registers as they are. */
static inline void put_rows4(uint8_t *regs, const vk_slot *s, const uint32_t *values) {
    uint8_t *dst = regs + 16 * (size_t)s->reg;
    if (s->reg_rows == 1) memcpy(dst, values + s->offset, 16); /* float4 in a fixed-size copy */
    else memcpy(dst, values + s->offset, 16 * (size_t)s->reg_rows);
}

/* The log entries written since the program last looked; a whole ring behind, everything. A
 * packed float4 or matrix no preshader reads (the common case) is a copy into the image in the
 * loop; anything else goes through write_slot. The fields the loop reads are copied first. */
static void scan_log(hfx_effect *fx, const vk_program *p, vk_bound *b) {
    uint64_t seen = b->seen, len = fx->log_len;
    if (len - seen > (uint64_t)fx->log_mask + 1) {
        scan_all(fx, p, b);
        return;
    }
    const uint32_t *log = fx->log, *values = fx->values;
    const uint64_t *stamps = fx->stamps;
    uint64_t *held = b->held;
    uint32_t mask = fx->log_mask;
    uint8_t *regs = p->regs_at >= 0 ? b->image + p->regs_at : NULL;
    int plain = !b->pre.total, dirty = 0;
    for (; seen != len; seen++) {
        uint32_t r = log[seen & mask];
        if (held[r] == stamps[r]) continue;
        const vk_slot *s = &p->slots[r];
        if (plain && s->mode == VK_SLOT_REG && s->reg_cols == 4) {
            held[r] = stamps[r];
            put_rows4(regs, s, values);
            dirty = 1;
            continue;
        }
        if (!depends_on(p, b, r)) continue;
        held[r] = stamps[r];
        write_slot(p, b, r, values);
    }
    b->seen = len;
    if (dirty) b->dirty = 1;
}

/* Inline, so the compare of a constant size is a load and a compare, not a call. */
static inline void put(vk_bound *b, int32_t at, const void *v, size_t n) {
    if (at < 0 || memcmp(b->image + at, v, n) == 0) return;
    memcpy(b->image + at, v, n);
    b->dirty = 1;
}

/* hfx_pos_fixup (D3D9's pixel centres and row order for the viewport) and the alpha test. */
static void write_internal(hfx_device *dev, const vk_program *p, vk_bound *b, const hfx_vk_target *t) {
    float fix[4] = {1.0f / (float)t->width, 1.0f / (float)t->height, 1.0f, (float)t->height};
    put(b, p->fixup_at, fix, sizeof fix);
    int32_t func = dev->rs[HFX_ST_ALPHATESTENABLE].i ? dev->rs[HFX_ST_ALPHAFUNC].i : 8;
    float ref = (float)(dev->rs[HFX_ST_ALPHAREF].i & 255) / 255.0f;
    put(b, p->alpha_func_at, &func, sizeof func);
    put(b, p->alpha_ref_at, &ref, sizeof ref);
}

void hfx_vk_uniforms_update(hfx_effect *fx, const vk_program *p, vk_bound *b, const hfx_vk_target *t) {
    if (b->seen == 0 && b->dirty) scan_all(fx, p, b); /* the first Apply: everything it reads */
    else if (b->seen != fx->log_len) scan_log(fx, p, b);
    if (b->pre.pending) run_preshaders(fx, p, b);
    write_internal(fx->dev, p, b, t);
}
