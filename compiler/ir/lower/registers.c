/* registers.c: `register(c0)` reservations as fxc allocates them for one shader: among the
 * globals the shader reads, two whose registers overlap is X4500 ("overlapping register
 * semantics not yet implemented"), and a register past the profile's bank is X4509 ("invalid
 * register semantic"). Only float constants (c) and samplers (s) are counted, each variable by
 * its first register; a reservation hfx does not read (other banks, `c[...]` offsets) is left
 * alone. */
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "ir/ir.h"

/* The float constant registers of a profile ("ps_2_0": 32, "ps_3_0": 224, vertex shaders 256)
 * and its samplers (vs_3_0: 4, pixel shaders 16). */
static void bank_sizes(const char *profile, uint32_t *c, uint32_t *s) {
    bool pixel = profile && (profile[0] == 'p' || profile[0] == 'P');
    bool three = profile && strlen(profile) > 3 && profile[3] == '3';
    *c = pixel ? (three ? 224 : 32) : 256;
    *s = pixel ? 16 : 4;
}

typedef struct reservation { const ir_var *v; char bank; uint32_t first, count; } reservation;

static bool parse_reg(const char *reg, char *bank, uint32_t *index) {
    if (!reg || (reg[0] != 'c' && reg[0] != 'C' && reg[0] != 's' && reg[0] != 'S') || reg[1] < '0' || reg[1] > '9') return false;
    char *end;
    unsigned long n = strtoul(reg + 1, &end, 10);
    if (*end || n > 0xffffffu) return false;
    *bank = (char)(reg[0] | 0x20);
    *index = (uint32_t)n;
    return true;
}

void hfx_ir_pass_registers(ir_ctx *c, ir_shader *sh) {
    uint32_t limit_c, limit_s, n = 0;
    const char *profile = sh->compile ? sh->compile->profile : NULL;
    bank_sizes(profile, &limit_c, &limit_s);
    reservation *r = HFX_NEW_ARRAY(c->arena, reservation, sh->global_count ? sh->global_count : 1);
    for (uint32_t i = 0; i < sh->global_count; i++) {
        const ir_var *v = sh->globals[i];
        reservation x = {v, 0, 0, 0};
        char buf[32]; /* the reservation for this shader's profile (`register(ps, c1)`, else `register(c1)`) */
        if ((v->kind != IRV_UNIFORM && v->kind != IRV_SAMPLER) || !v->decl ||
            !parse_reg(hfx_register_for(v->decl->reg, profile, buf, sizeof buf), &x.bank, &x.first))
            continue;
        /* the first register only: fxc allocates the registers a shader reads, and FNA's
         * EnvironmentMapEffect puts a float3x3 on the fourth column of a float4x4 whose first
         * three columns its shaders read */
        x.count = x.bank == 's' ? v->kind == IRV_SAMPLER : hfx_type_is_numeric(v->type) || v->type->kind == TY_ARRAY;
        if (!x.count) continue;
        uint32_t limit = x.bank == 's' ? limit_s : limit_c;
        if (x.first + x.count > limit) {
            hfx_error(c->diags, v->decl->loc, 4509, "invalid register semantic '%c%u'", x.bank, x.first);
            continue;
        }
        for (uint32_t k = 0; k < n; k++) {
            const reservation *y = &r[k];
            uint32_t lo = x.first > y->first ? x.first : y->first;
            if (y->bank == x.bank && x.first < y->first + y->count && y->first < x.first + x.count) {
                hfx_loc a = y->v->decl->loc, b = v->decl->loc;
                const ir_var *later = a.line > b.line || (a.line == b.line && a.col > b.col) ? y->v : v;
                hfx_error(c->diags, later->decl->loc, 4500, "overlapping register semantics not yet implemented '%c%u'", x.bank, lo);
                break;
            }
        }
        r[n++] = x;
    }
}
