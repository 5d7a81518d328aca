/* specialise.c: `compile ps_3_0 mainPS(true)`: every use of a uniform parameter of the entry
 * becomes the compile argument, and the parameter leaves the entry's signature, so fold and
 * dce can remove what the argument switches off. */
#include "ir/ir.h"

void hfx_ir_pass_specialise(ir_ctx *c, ir_shader *sh) {
    ir_func *f = sh->entry;
    hfx_ir_put_values(c, f->body, &sh->args);
    uint32_t kept = 0;
    for (uint32_t i = 0; i < f->param_count; i++)
        if (!hfx_ir_var_map_get(&sh->args, f->params[i])) f->params[kept++] = f->params[i];
    f->param_count = kept;
}
