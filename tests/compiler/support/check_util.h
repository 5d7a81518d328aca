/* check_util.h: running the front end (preprocess, parse, check) on a snippet and printing
 * the decorated tree compactly, for the checker's tests. */
#ifndef HFX_TEST_CHECK_UTIL_H
#define HFX_TEST_CHECK_UTIL_H

#include <stdbool.h>
#include <stddef.h>

#include "parse/ast.h"

typedef struct ckt_result {
    hfx_arena arena;
    hfx_diags diags;
    hfx_types *types;
    hfx_ast *ast;
    bool ok;              /* hfx_check returned true */
} ckt_result;

/* Checks `src` as the file "t.fx" (stops before checking when parsing fails). */
ckt_result *ckt_run(const char *src);
void ckt_free(ckt_result *r);
/* The diagnostics of `src`, one per line, fxc's format; malloc'ed. */
char *ckt_diags(const char *src);
/* The diagnostics of a result; malloc'ed. */
char *ckt_text(const ckt_result *r);
/* The last top-level declaration named `name`, or NULL. */
hfx_decl *ckt_find(ckt_result *r, const char *name);
/* Statement i (0-based) of function `fn`'s body. */
hfx_stmt *ckt_stmt(ckt_result *r, const char *fn, unsigned i);
/* The typed dump of an expression: literals and names as `x:type`, others as
 * `(op:type args...)`, implicit casts as `(implicit:type x)`; malloc'ed. */
char *ckt_dump(const hfx_expr *e);
/* The dump of statement i of fn: its expression, or the initializer of its first declarator. */
char *ckt_dump_stmt(ckt_result *r, const char *fn, unsigned i);

/* Walks every function body, initializer and pass of a checked result for ast.h's
 * invariants; returns the number of violations, the first described in `why`. */
int ckt_invariants(ckt_result *r, char *why, size_t n);

#endif
