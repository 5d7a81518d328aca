/* passes.c: THE order of the passes over the IR, in one table. hfx_ir_lower runs a stage's rows,
 * hfx_ir_lower_program a program's (a vertex and a pixel stage together); a row's `when` says when
 * it runs, so no caller runs a pass of its own. After each pass the IR can be dumped
 * (hfxc --dump-ir=PASS); docs/architecture.md lists this table, and tests/compiler/ir/
 * test_passes.c fails when the two disagree. */
#include <stdlib.h>
#include <string.h>

#include "ir/ir.h"

/* When a row runs. */
typedef enum {
    WHEN_ALWAYS,
    WHEN_PRESHADE,     /* HLSL stages, parameters packed, preshaders on (IR_LOWER_PRESHADE); fxc's bytecode
                        * brings its own preshaders (d3d9_ir.c) */
    WHEN_PRESHADERS,   /* the same, and the preshade pass made some */
    WHEN_DERIVE        /* a program's pass: derived varyings on (IR_LOWER_DERIVE) */
} when;

typedef struct pass_row {
    const char *name;
    void (*stage)(ir_ctx *c, ir_shader *sh);      /* a stage's pass, or NULL */
    void (*program)(ir_ctx *c, ir_program *p);    /* a program's pass, or NULL */
    when when;
    bool gate;         /* the list stops here with -1 when any pass so far reported an error */
    const char *why;
} pass_row;

static void check(ir_ctx *c, ir_shader *sh) { (void)hfx_ir_pass_check(c, sh); } /* its errors are in diags */

static void varyings(ir_ctx *c, ir_program *p) {
    p->derived_count = hfx_ir_pass_varyings(c, &p->vs, &p->ps, (p->opts & IR_LOWER_PACKED) != 0, &p->derived);
}

#define STAGE(name, fn, w, why) {name, fn, NULL, w, false, why}

static const pass_row ROWS[] = {
    STAGE("specialise", hfx_ir_pass_specialise, WHEN_ALWAYS, "compile arguments replace the entry's uniform parameters"),
    STAGE("arrays", hfx_ir_pass_arrays, WHEN_ALWAYS, "arrays of arrays flattened (GLSL 330 has none)"),
    STAGE("intrinsics", hfx_ir_pass_intrinsics, WHEN_ALWAYS, "mul by a truncated matrix pads the vector; abs(M) row by row"),
    STAGE("lvalues", hfx_ir_pass_lvalues, WHEN_ALWAYS, "m._11_22 = v: a constructor of single components as the target"),
    STAGE("fold", hfx_ir_pass_fold, WHEN_ALWAYS, "constant folding and propagation of const variables"),
    STAGE("calls", hfx_ir_pass_calls, WHEN_ALWAYS, "f(x, 1): a copy of f with the 1 bound, as fxc inlines it (folds again)"),
    STAGE("samplers", hfx_ir_pass_samplers, WHEN_ALWAYS, "S[i] of a sampler array: loops i counts unrolled, constant indexes an element's sampler"),
    STAGE("dce", hfx_ir_pass_dce, WHEN_ALWAYS, "if (false) branches, code after return, unreached functions go"),
    STAGE("once", hfx_ir_pass_once, WHEN_ALWAYS, "pow(x, 3) as fxc's products; coordinates read twice computed once"),
    STAGE("flatten", hfx_ir_pass_flatten, WHEN_ALWAYS, "a small if / else choosing a local's value becomes a select"),
    STAGE("distances", hfx_ir_pass_distances, WHEN_ALWAYS, "distance(P, L) beside L - P: length(L - P), sharing the difference"),
    STAGE("globals", hfx_ir_pass_globals, WHEN_ALWAYS, "private copies of the uniforms some function writes"),
    STAGE("licm", hfx_ir_pass_licm, WHEN_ALWAYS, "loop-invariant work before the loop (after globals: a written uniform is its copy)"),
    STAGE("ranges", hfx_ir_pass_ranges, WHEN_ALWAYS, "arr[i] with a counter kept in range: a cheaper guard, or none"),
    STAGE("uses", hfx_ir_pass_uses, WHEN_ALWAYS, "globals and samplers the stage reads, in first-use order"),
    STAGE("registers", hfx_ir_pass_registers, WHEN_ALWAYS, "register(c0) reservations: overlaps and ranges fxc refuses"),
    {"check", check, NULL, WHEN_ALWAYS, true, "target limits: what GLSL cannot express is an error"},
    STAGE("sums", hfx_ir_pass_sums, WHEN_PRESHADE, "a loop's sum of parameter-only terms added once before it"),
    STAGE("forward", hfx_ir_pass_forward, WHEN_PRESHADE, "single-use locals forward, matrix chains regrouped"),
    STAGE("factors", hfx_ir_pass_factors, WHEN_PRESHADE, "vector products: parameters, then scalars, then vectors"),
    STAGE("preshade", hfx_ir_pass_preshade, WHEN_PRESHADE, "parameter-only work to preshaders the CPU runs once per change"),
    STAGE("uses-again", hfx_ir_pass_uses, WHEN_PRESHADERS, "parameters read only by preshaders leave the stage"),
    {"varyings", NULL, varyings, WHEN_DERIVE, false, "program: vertex outputs the pixel stage derives from another"},
};

enum { ROW_COUNT = sizeof ROWS / sizeof *ROWS };

uint32_t hfx_ir_pass_count(void) { return ROW_COUNT; }
const char *hfx_ir_pass_name(uint32_t i) { return i < ROW_COUNT ? ROWS[i].name : NULL; }
const char *hfx_ir_pass_why(uint32_t i) { return i < ROW_COUNT ? ROWS[i].why : NULL; }

const char *hfx_ir_pass_runs(uint32_t i) {
    static const char *const text[] = {
        [WHEN_ALWAYS] = "every stage",
        [WHEN_PRESHADE] = "HLSL stages, parameters packed, preshaders on",
        [WHEN_PRESHADERS] = "preshade made a preshader",
        [WHEN_DERIVE] = "each program, derived varyings on",
    };
    return i < ROW_COUNT ? text[ROWS[i].when] : NULL;
}

static bool runs(const pass_row *r, unsigned opts, const ir_shader *sh) {
    switch (r->when) {
    case WHEN_ALWAYS: return true;
    case WHEN_PRESHADE: return (opts & IR_LOWER_PRESHADE) != 0;
    case WHEN_PRESHADERS: return (opts & IR_LOWER_PRESHADE) && sh && sh->pre_count;
    case WHEN_DERIVE: return (opts & IR_LOWER_DERIVE) != 0;
    }
    return false;
}

/* hfxc --dump-ir: the stage after pass `name`, when it is the one asked for (or "all"). */
static void dump(ir_ctx *c, const char *name, const ir_shader *sh) {
    const char *want = c->diags->dump_ir;
    if (!want || !sh || (strcmp(want, "all") != 0 && strcmp(want, name) != 0)) return;
    sbuf *b = &c->diags->dump_text;
    const hfx_loc *at = sh->compile ? &sh->compile->loc : NULL;
    if (at && at->file < c->diags->file_count)
        hfx_sb_printf(b, "// after %s: %s(%u,%u)\n", name, c->diags->files[at->file].name, at->line, at->col);
    else
        hfx_sb_printf(b, "// after %s\n", name);
    char *text = hfx_ir_dump_shader(sh);
    if (text) hfx_sb_put(b, text);
    else b->oom = true;
    free(text);
}

int hfx_ir_lower(ir_ctx *c, ir_shader *sh, unsigned opts) {
    uint32_t errors = c->diags->errors;
    for (uint32_t i = 0; i < ROW_COUNT; i++) {
        const pass_row *r = &ROWS[i];
        if (!r->stage || !runs(r, opts, sh)) continue;
        r->stage(c, sh);
        dump(c, r->name, sh);
        if (r->gate && c->diags->errors > errors) return -1;
    }
    return c->diags->errors > errors ? -1 : 0;
}

void hfx_ir_lower_program(ir_ctx *c, ir_program *p) {
    for (uint32_t i = 0; i < ROW_COUNT; i++) {
        const pass_row *r = &ROWS[i];
        if (!r->program || !runs(r, p->opts, NULL)) continue;
        r->program(c, p);
        dump(c, r->name, p->vs);
        dump(c, r->name, p->ps);
    }
}
