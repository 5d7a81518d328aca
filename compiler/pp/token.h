/* token.h: tokens as the re2c lexer (lexer.re) cuts them and the preprocessor hands them on.
 * The lexer knows no keywords: after preprocessing, the parser's yylex turns identifiers into
 * keywords and type names (HLSL's keywords depend on context, and macros may spell them). */
#ifndef HFX_TOKEN_H
#define HFX_TOKEN_H

#include <stdint.h>

#include "base/arena.h"
#include "base/diag.h"

typedef enum {
    TK_EOF,
    TK_IDENT,
    TK_INT,      /* 12, 0x1F, 017, 12u, 12L */
    TK_FLOAT,    /* 1.0, .5, 1e3, 1.0f, 1.0F, 1.0h, 1.0l */
    TK_STRING,   /* "..." with escapes kept as written; adjacent strings are joined by the parser */
    TK_PUNCT,    /* see hfx_punct */
    TK_HASH,     /* '#' or '%:' */
    TK_HASHHASH, /* '##' */
    TK_HEADER,   /* <file.fxh>, only produced when the preprocessor asks for it after #include */
    TK_OTHER     /* a byte no token starts with: reported by the parser, legal in skipped blocks */
} hfx_token_kind;

typedef enum {
    P_LPAREN, P_RPAREN, P_LBRACKET, P_RBRACKET, P_LBRACE, P_RBRACE,
    P_SEMI, P_COMMA, P_DOT, P_COLON, P_QUESTION,
    P_PLUS, P_MINUS, P_STAR, P_SLASH, P_PERCENT, P_AMP, P_PIPE, P_CARET, P_TILDE, P_BANG,
    P_LT, P_GT, P_LE, P_GE, P_EQEQ, P_NE, P_ANDAND, P_OROR, P_SHL, P_SHR,
    P_ASSIGN, P_PLUSEQ, P_MINUSEQ, P_STAREQ, P_SLASHEQ, P_PERCENTEQ, P_AMPEQ, P_PIPEEQ, P_CARETEQ,
    P_SHLEQ, P_SHREQ, P_INC, P_DEC, P_COLONCOLON, P_ARROW,
    P_ELLIPSIS             /* '...', for variadic macros */
} hfx_punct;

enum { /* hfx_token.flags */
    TF_BOL = 1u << 0,      /* first token of its line (directives start here) */
    TF_SPACE = 1u << 1,    /* white space before it (for # stringizing and -E output) */
    TF_NOEXPAND = 1u << 2,  /* a macro name that must not expand again (painted blue) */
    TF_UNTERMINATED = 1u << 3 /* a string cut short by its line's end, not reported yet (see
                                 hfx_tokenize_deferred); the preprocessor reports it when used */
};

typedef struct hfx_token hfx_token;
struct hfx_token {
    hfx_token_kind kind;
    uint32_t punct;        /* hfx_punct for TK_PUNCT */
    uint32_t flags;
    const char *text;      /* spelling, NUL-terminated, arena-owned */
    uint32_t len;
    hfx_loc loc;           /* where the user sees it: the macro call site for expanded tokens */
    hfx_loc spelling;      /* where its characters are (inside the macro body for expanded ones) */
    hfx_token *next;
    const struct hfx_hideset *hideset; /* preprocessor only: the macros it came out of */
};

/* Cuts one file into tokens (linked list ending with TK_EOF). Never fails: bad bytes become
 * TK_OTHER, unterminated comments and strings are reported in diags. */
hfx_token *hfx_tokenize(hfx_arena *arena, hfx_diags *diags, uint32_t file);
/* The same, except that a string cut short by its line's end is only flagged TF_UNTERMINATED:
 * the preprocessor reports it when the string is used, not inside a skipped #if group. */
hfx_token *hfx_tokenize_deferred(hfx_arena *arena, hfx_diags *diags, uint32_t file);
/* Cuts `size` bytes of text that belong to no file (a ## paste, a -D value) into tokens, all
 * located at `loc`; the list ends with TK_EOF. */
hfx_token *hfx_tokenize_text(hfx_arena *arena, hfx_diags *diags, const char *text, uint32_t size, hfx_loc loc);

typedef struct hfx_pp_options {
    const char *const *defines; uint32_t define_count;        /* "NAME" or "NAME=VALUE" */
    const char *const *include_dirs; uint32_t include_dir_count;
    uint32_t max_include_depth;                               /* 0 = default (64) */
    struct hfx_token_cache *cache;  /* NULL, or the session's tokens of files read before (token_cache.h) */
} hfx_pp_options;

/* What the preprocessor hands the parser, beyond plain tokens:
 *  - `#pragma pack_matrix(row_major)` / `(column_major)` stays in the list, at the pragma's place,
 *    as the four tokens `__hfx_pack_matrix ( row_major )` (TK_IDENT, '(', TK_IDENT, ')'; the first
 *    flagged TF_BOL | TF_NOEXPAND): the parser applies it to the declarations that follow. Every
 *    other pragma is consumed (`once` honoured; `warning`, `def`, `message` accepted; unknown ones
 *    give warning X3568).
 *  - Predefined macros: only __FILE__ and __LINE__ (fxc for fx_2_0 documents no others), plus the
 *    caller's defines ("NAME" is 1, "NAME=VALUE", "NAME(a)=..." for a function-like one).
 *  - Locations: an expanded token's `loc` is the outermost macro use, its `spelling` is where its
 *    characters are (the macro body); argument tokens keep their own place. #line is applied.
 *  - Included files get one diags file entry per inclusion, named as the #include wrote it. */
/* Reads `path` (or `text` when not NULL, named `name`), tokenizes and preprocesses it:
 * directives done, macros expanded, includes spliced. Returns the token list for the parser
 * (ending with TK_EOF), or a list holding only TK_EOF when the root file cannot be read.
 * Errors go to diags; preprocessing goes on after each one. */
hfx_token *hfx_preprocess(hfx_arena *arena, hfx_diags *diags, const char *name, const char *text,
                          uint32_t size, const hfx_pp_options *opt);
/* A token list as text, for fxc's /P: TF_SPACE becomes a space, TF_BOL a line break; blank lines
 * keep line numbers in step and `#line N "file"` marks a change of file. malloc'ed. */
char *hfx_tokens_to_text(const hfx_diags *diags, const hfx_token *tokens);

#endif
