/* pp_internal.h: what the preprocessor's files (preprocess.c: directives and the main loop,
 * pp_macro.c: macro table and expansion, pp_expr.c: #if arithmetic, hfx_pp_file.c: finding and
 * reading files) share. One hfx_pp per hfx_preprocess call; all of it lives in the arena. */
#ifndef HFX_PP_INTERNAL_H
#define HFX_PP_INTERNAL_H

#include <stdbool.h>

#include "pp/token.h"

enum {
    PP_MACRO_BUCKETS = 512,
    PP_MAX_EXPANSION_DEPTH = 200,      /* nested macro calls, also a hideset's length */
    PP_MAX_EXPANSION_TOKENS = 1 << 18, /* tokens one top-level macro use may produce */
    PP_MAX_EXPANSION_WORK = 1 << 24,   /* all expansions of a call: 4 per token made, 1 per hideset */
    PP_EXPANSION_WORK_PER_BYTE = 64,   /*   step; plus this much per byte of source read */
    PP_MAX_EXPR_DEPTH = 256,           /* parentheses and operators nested in #if */
    PP_DEFAULT_INCLUDE_DEPTH = 64
};

/* fxc's numbers (the "HLSL errors and warnings" list of the Direct3D documentation); X1000
 * (X_PP_ERROR) for what fxc has no number for, such as runaway macro expansion. */
enum {
    X_PP_SYNTAX = 1500,                /* invalid preprocessor syntax */
    X_PP_UNEXPECTED_TOKENS = 1501,     /* warning: tokens after a directive's operands */
    X_PP_UNEXPECTED_EOF = 1502,        /* end of file inside #if */
    X_PP_DIVIDE_BY_ZERO = 1503,
    X_PP_INVALID_COMMAND = 1504,
    X_PP_TOO_MANY_INCLUDES = 1506,
    X_PP_UNEXPECTED_ELIF = 1508,
    X_PP_UNEXPECTED_ELSE = 1509,
    X_PP_UNEXPECTED_ENDIF = 1510,
    X_PP_DUPLICATE_PARAMETER = 1511,
    X_PP_ELIF_AFTER_ELSE = 1513,
    X_PP_ELSE_AFTER_ELSE = 1514,
    X_PP_EOF_IN_MACRO = 1515,
    X_PP_MACRO_ARGUMENTS = 1516,       /* not enough (or too many) actual parameters */
    X_PP_INVALID_INT_EXPR = 1518,
    X_PP_MACRO_REDEFINITION = 1519,    /* warning */
    X_PP_UNKNOWN_PRAGMA = 3568         /* warning: 'x' : unknown pragma ignored */
};

/* The macros a token came out of: it never expands as one of them again (Prosser's algorithm). */
typedef struct hfx_hideset pp_hideset;
struct hfx_hideset {
    const char *name;
    const pp_hideset *next;
};

typedef struct pp_macro pp_macro;
typedef enum { PP_BUILTIN_NONE, PP_BUILTIN_FILE, PP_BUILTIN_LINE } pp_builtin;
struct pp_macro {
    const char *name;
    bool function_like, variadic;
    const char **params; uint32_t param_count; /* the variadic one is last, named __VA_ARGS__ */
    hfx_token *body;                           /* ends with TK_EOF */
    hfx_loc loc;
    pp_builtin builtin;
    pp_macro *next;                            /* hash chain */
};

/* A #line directive: from physical line `from` of a file on, lines are shifted and renamed. */
typedef struct pp_line_map {
    uint32_t from;
    int64_t delta;
    uint32_t file; /* the diags file entry that carries the new name */
} pp_line_map;

typedef struct pp_file_info {   /* per diags file index (an inclusion) */
    pp_line_map *maps; uint32_t map_count, map_cap;
    const char *dir;            /* folder for "x" includes; NULL for text not on disk */
    const char *real;           /* canonical path for #pragma once; NULL when unknown */
} pp_file_info;

typedef struct pp_cond {
    hfx_loc loc;      /* the #if, for "unterminated" errors */
    const char *name; /* "if", "ifdef" or "ifndef" */
    bool taken;       /* some branch of this group was included */
    bool seen_else;
} pp_cond;

typedef struct pp_frame {       /* one file being read */
    uint32_t file;
    uint32_t cond_base;         /* conditionals open when the file was entered */
} pp_frame;

typedef struct hfx_pp {
    hfx_arena *arena;
    hfx_diags *diags;
    const hfx_pp_options *opt;
    pp_macro *macros[PP_MACRO_BUCKETS];
    /* One bit per (first, second) byte pair that some macro name ever started with (#undef
     * leaves it set): most identifiers are no macro, and this tells so without hashing them. */
    uint64_t macro_starts[128 * 128 / 64];
    pp_file_info *files; uint32_t files_cap;
    pp_frame *frames; uint32_t frame_count, frame_cap;
    pp_cond *conds; uint32_t cond_count, cond_cap;
    const char **once; uint32_t once_count, once_cap; /* real paths marked #pragma once */
    const char *root_dir;
    uint32_t max_include_depth;
    uint32_t expansion_tokens;  /* produced since the last top-level macro use */
    uint32_t arg_depth;         /* nested argument pre-expansions */
    bool runaway_reported;
    bool budget_reported;
    uint64_t work;              /* spent on expansions, see PP_MAX_EXPANSION_WORK */
    uint64_t source_bytes;      /* read so far: the root and every inclusion */
    bool has_line_maps;         /* some #line ran: locations need mapping at the end */
    hfx_token *eof;             /* a shared TK_EOF for token lists built here */
} hfx_pp;

/* preprocess.c */
void hfx_pp_error(hfx_pp *pp, hfx_loc loc, unsigned code, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
void hfx_pp_warning(hfx_pp *pp, hfx_loc loc, unsigned code, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
hfx_loc hfx_pp_map_loc(hfx_pp *pp, hfx_loc loc);      /* applies #line */
hfx_token *hfx_pp_new_eof(hfx_pp *pp, hfx_loc loc);
/* Reports a string the lexer flagged TF_UNTERMINATED (once), now that it is used. */
void hfx_pp_check_string(hfx_pp *pp, hfx_token *t);
hfx_token *hfx_pp_copy_token(hfx_pp *pp, const hfx_token *t);
pp_file_info *hfx_pp_file(hfx_pp *pp, uint32_t file); /* grows the per-file table */

/* pp_macro.c */
pp_macro *hfx_pp_find_macro(hfx_pp *pp, const char *name);
void hfx_pp_undef(hfx_pp *pp, const char *name);
void hfx_pp_define_builtins(hfx_pp *pp);
/* Parses a #define line (the tokens after "define", ending with TK_EOF). */
void hfx_pp_define(hfx_pp *pp, hfx_token *line, hfx_loc directive);
/* Defines NAME or NAME=VALUE given on the command line. */
void hfx_pp_define_option(hfx_pp *pp, const char *def, hfx_loc loc);
/* When tok is a macro use, replaces it (and its arguments) by the expansion in front of the
 * rest of the list: *rest is where to go on. Returns false when tok is not expanded. */
bool hfx_pp_expand_macro(hfx_pp *pp, hfx_token **rest, hfx_token *tok);
/* Expands every macro of a list ending with TK_EOF (for #if, #include and arguments). */
hfx_token *hfx_pp_expand_all(hfx_pp *pp, hfx_token *list);
/* The token after tok that starts a new line, or the TK_EOF. */
hfx_token *hfx_pp_line_end(hfx_token *tok);
/* A copy of the tokens from tok up to the line's end, ending with a TK_EOF. */
hfx_token *hfx_pp_copy_line(hfx_pp *pp, hfx_token *tok, hfx_token **rest);
/* Spellings joined with single spaces where the source had white space. */
char *hfx_pp_join(hfx_pp *pp, const hfx_token *from, const hfx_token *to);

/* pp_expr.c */
/* Evaluates a #if / #elif line (tokens after the directive name, ending with TK_EOF). */
bool hfx_pp_eval_condition(hfx_pp *pp, hfx_token *line, hfx_loc directive);

/* hfx_pp_file.c */
/* Reads a whole file into the arena, NUL-terminated; NULL when it cannot be read. */
char *hfx_pp_read_file(hfx_arena *arena, const char *path, uint32_t *size); /* UTF-16 decoded */
char *hfx_pp_decode_source(hfx_arena *arena, char *text, uint32_t *size); /* UTF-16 with a BOM to UTF-8 */
/* Finds an #include'd file as fxc does; returns the path it opened (arena) or NULL. */
const char *hfx_pp_find_include(hfx_pp *pp, const char *name, bool angled, const char *including_dir);
char *hfx_pp_dirname(hfx_arena *arena, const char *path);
char *hfx_pp_realpath(hfx_arena *arena, const char *path);

#endif
