/* check_attrs.c: statement attributes ([unroll], [loop], [branch], [flatten]...) as fxc takes
 * them: a duplicated attribute, or two that contradict each other ([loop] with [unroll],
 * [branch] with [flatten]), is X3524; [unroll(n)] needs a positive literal integer (X3084); an
 * attribute on a statement it does not apply to is ignored with warning X3554, as fxc ignores it.
 * Error numbers from Microsoft's list of HLSL errors and warnings. */
#include <strings.h>

#include "check/check_ctx.h"

static bool named(const hfx_attribute *a, const char *name) { return a->name && strcasecmp(a->name, name) == 0; }

static bool is_loop(const hfx_stmt *s) { return s->kind == ST_FOR || s->kind == ST_WHILE || s->kind == ST_DO; }

/* The statements an attribute may stand before; NULL for one fxc does not know (left alone). */
static const char *applies_to(const hfx_attribute *a, const hfx_stmt *s, bool *ok) {
    static const char *const loop_attrs[] = {"unroll", "loop", "fastopt", "allow_uav_condition"};
    for (size_t i = 0; i < sizeof loop_attrs / sizeof *loop_attrs; i++)
        if (named(a, loop_attrs[i])) { *ok = is_loop(s); return "a loop"; }
    if (named(a, "branch") || named(a, "flatten")) { *ok = s->kind == ST_IF || s->kind == ST_SWITCH; return "an if or a switch"; }
    if (named(a, "forcecase") || named(a, "call")) { *ok = s->kind == ST_SWITCH; return "a switch"; }
    *ok = true;
    return NULL;
}

static void check_unroll_count(check_ctx *c, const hfx_attribute *a) {
    if (!named(a, "unroll") || a->arg_count == 0) return;
    const hfx_expr *n = a->args[0];
    if (a->arg_count > 1 || n->kind != EX_INT || n->ival <= 0)
        hfx_error(c->diags, n->loc, 3084, "'unroll': the iteration count must be a positive literal integer");
}

static bool contradict(const hfx_attribute *x, const hfx_attribute *y) {
    return (named(x, "loop") && named(y, "unroll")) || (named(x, "unroll") && named(y, "loop")) ||
           (named(x, "branch") && named(y, "flatten")) || (named(x, "flatten") && named(y, "branch"));
}

void hfx_ck_attributes(check_ctx *c, const hfx_stmt *s) {
    for (uint32_t i = 0; i < s->attr_count; i++) {
        const hfx_attribute *a = &s->attrs[i];
        bool ok;
        const char *where = applies_to(a, s, &ok);
        if (!ok) hfx_warning(c->diags, a->loc, 3554, "'%s': the attribute applies to %s only; ignored", a->name, where);
        check_unroll_count(c, a);
        for (uint32_t k = 0; k < i; k++) {
            const hfx_attribute *b = &s->attrs[k];
            if (named(a, b->name ? b->name : ""))
                hfx_error(c->diags, a->loc, 3524, "'%s': duplicate attribute", a->name);
            else if (contradict(a, b))
                hfx_error(c->diags, a->loc, 3524, "'%s' and '%s' cannot be used together", b->name, a->name);
        }
    }
}
