/* d3d9_ir.c: a decoded shader to hfx's IR. Not written yet: every shader gets a located X5006,
 * so nothing half-translated ever reaches a driver. */
#include "d3d9/d3d9_int.h"
#include "ir/ir.h"

struct ir_shader *d3d9_to_ir(struct ir_ctx *c, const d3d9_shader *s) {
    hfx_loc loc = {s->file_index, 0, s->base};
    hfx_error(c->diags, loc, X_D3D9_UNSUPPORTED, "%s bytecode to GLSL is not supported yet",
              d3d9_model_name(s->stage, s->model));
    return NULL;
}
