/* diag.h: source positions and diagnostics. A location names a file by its index in the
 * compilation's file table; every diagnostic carries one and fxc's number. Nothing here
 * prints: the list goes back to the caller of the library. */
#ifndef HFX_DIAG_H
#define HFX_DIAG_H

#include <stdint.h>

#include "base/arena.h"
#include "base/sbuf.h"
#include "hfx/hfxc.h"

typedef struct hfx_loc {
    uint32_t file; /* index into hfx_diags.files */
    uint32_t line; /* 1-based */
    uint32_t col;  /* 1-based, in bytes */
} hfx_loc;

typedef struct hfx_source {
    const char *name; /* as the user or #include named it (a #line can rename) */
    const char *path; /* where it was read from; NULL for text that is no file (memory, -D) */
    const char *text; /* UTF-8, NUL-terminated, CRLF kept as is */
    uint32_t size;
} hfx_source;

typedef struct hfx_diags {
    hfx_arena *arena;
    hfx_source *files; uint32_t file_count, file_cap;
    hfxc_diag *items; uint32_t count, cap;
    uint32_t errors, warnings;
    unsigned flags;   /* hfxc_options.flags: HFXC_WERROR, HFXC_NO_WARNINGS here; HFXC_PACK_UNIFORMS for the builder */
    /* hfxc_options.dump_ir, carried like flags to ir/lower/passes.c: the pass after which
     * each stage's IR is dumped ("all": every pass; NULL: none), and the dumps (in the arena). */
    const char *dump_ir;
    sbuf dump_text;
} hfx_diags;

/* Common fxc error numbers. */
enum {
    X_SYNTAX = 3000,          /* syntax error */
    X_UNDECLARED = 3004,      /* undeclared identifier */
    X_REDEFINITION = 3003,
    X_TYPE_MISMATCH = 3017,   /* cannot convert */
    X_NO_OVERLOAD = 3013,     /* no matching N parameter function */
    X_AMBIGUOUS = 3067,
    X_INVALID_SUBSCRIPT = 3018,
    X_NOT_LVALUE = 3025,
    X_NOT_ALL_PATHS = 3507,   /* not all control paths return a value (checker, or per pass: ir/lower/limits.c) */
    X_IMPLICIT_TRUNCATION = 3206,
    X_PP_ERROR = 1000,        /* preprocessor errors: X1xxx */
    X_PP_INCLUDE = 1507,      /* failed to open source file */
    X_PP_ERROR_DIRECTIVE = 1003,
    X_PP_UNTERMINATED_COMMENT = 1001, /* a comment continues past the end of file */
    X_PP_STRING_EOL = 1005,   /* a string continues past the end of line */
    X_UNSUPPORTED = 3094,     /* unsupported construct (asm blocks...) */
    X_INTERNAL = 9000,        /* hfx's own GLSL failed its self-check (fxc has no such code) */
    X_MEMORY_LIMIT = 9001,    /* out of memory, or past the memory a source of its size may use (hfx's own) */
    X_SOURCE_TOO_LARGE = 9002, /* a source file past HFXC_MAX_SOURCE_BYTES (hfx's own) */
    X_POOL_MISMATCH = 9003    /* shared parameters of a pool that do not agree: the runtime's (runtime/pool.c) */
};

void hfx_diags_init(hfx_diags *d, hfx_arena *arena, unsigned flags);
uint32_t hfx_diags_add_file(hfx_diags *d, const char *name, const char *path, const char *text, uint32_t size);
void hfx_error(hfx_diags *d, hfx_loc loc, unsigned code, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
void hfx_warning(hfx_diags *d, hfx_loc loc, unsigned code, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
void hfx_note(hfx_diags *d, hfx_loc loc, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* "file(line,col): error X3000: msg\n" for each, with the source line and a caret when caret is set. malloc'ed. */
char *hfx_diags_format(const hfx_diags *d, int caret);

#endif
