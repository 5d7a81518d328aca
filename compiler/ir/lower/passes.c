/* passes.c: the order of the lowering passes, in one place. */
#include "ir/ir.h"

int ir_lower(ir_ctx *c, ir_shader *sh) {
    uint32_t errors = c->diags->errors;
    ir_pass_specialise(c, sh); /* compile arguments replace the entry's uniform parameters */
    ir_pass_arrays(c, sh);     /* arrays of arrays flattened (GLSL 330 has none) */
    ir_pass_intrinsics(c, sh); /* mul by a truncated matrix: pad the vector instead; abs(M) row by row */
    ir_pass_lvalues(c, sh);    /* m._11_22 = v: a constructor of single components as the target */
    ir_pass_fold(c, sh);       /* constant folding and propagation of const variables */
    ir_pass_calls(c, sh);      /* f(x, 1): a copy of f with the 1 bound, as fxc inlines it */
    ir_pass_dce(c, sh);        /* if (false) branches, code after return, unreached functions */
    ir_pass_once(c, sh);       /* pow(x, 3) as fxc's products; coordinates read twice computed once */
    ir_pass_flatten(c, sh);    /* a small if / else choosing a local's value: a select, as fxc flattens it */
    ir_pass_distances(c, sh);  /* distance(P, L) beside L - P: length(L - P), the driver shares the difference */
    ir_pass_globals(c, sh);    /* private copies of the uniforms some function writes */
    ir_pass_licm(c, sh);       /* loop-invariant work before the loop; after globals, so a written uniform is its copy */
    ir_pass_ranges(c, sh);     /* arr[i] with a for counter i >= 0 (below a bound): a cheaper guard, or none */
    ir_pass_uses(c, sh);       /* globals and samplers the stage reads, in first-use order */
    ir_pass_registers(c, sh);  /* register(c0) reservations: overlaps and ranges, as fxc refuses them */
    if (ir_pass_check(c, sh) != 0) return -1;
    return c->diags->errors > errors ? -1 : 0;
}
