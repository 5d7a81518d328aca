/* lexer.re: cuts source text into tokens (re2c). Line continuations are removed before
 * lexing (into a copy that remembers where each byte came from), so every rule below sees
 * plain text, and locations are still exact 1-based line/byte-column positions in the file.
 * The lexer keeps going after every problem: a bad byte becomes TK_OTHER, an unterminated
 * comment or string is reported and ends where the text does. */
#include <stdbool.h>
#include <string.h>

#include "pp/token.h"

typedef struct lexer {
    hfx_arena *arena;
    hfx_diags *diags;
    uint32_t file;
    const char *orig;      /* the file's text as read */
    const char *buf;       /* what the rules scan: orig, or orig without backslash-newlines */
    const uint32_t *map;   /* buf offset -> orig offset, NULL when buf == orig */
    uint32_t size;         /* bytes in buf (a NUL follows them) */
    const hfx_loc *fixed;  /* every token gets this loc (re-lexing pasted text), or NULL */
    bool defer_strings;    /* flag unterminated strings instead of reporting them */
    /* Lines are counted where the rules meet a '\n' (see newline_at), so the current line and
     * the orig offset it starts at are always those of the scan position. A removed
     * backslash-newline ended a line too: cont_at[i] is the buf offset it was removed before,
     * cont_end[i] the orig offset after its '\n'; cont_next is the first one not counted yet. */
    uint32_t line, line_start;
    const uint32_t *cont_at, *cont_end;
    uint32_t cont_count, cont_next;
    /* Token spellings point into text, a copy of buf where each one gets a NUL after it;
     * text_end is where the last such NUL went (UINT32_MAX: none yet). */
    char *text;
    uint32_t text_end;
    hfx_token head, *tail;
} lexer;

enum { /* what scan() found besides real tokens */
    S_SPACE = 100, S_NEWLINE, S_LINE_COMMENT, S_BLOCK_COMMENT, S_STRING, S_NUL, S_UTF8
};

static uint32_t orig_offset(const lexer *lx, uint32_t off) { return lx->map ? lx->map[off] : off; }

/* Counts the removed backslash-newlines that come before buf offset `off`. */
static void pass_continuations(lexer *lx, uint32_t off) {
    while (lx->cont_next < lx->cont_count && lx->cont_at[lx->cont_next] <= off) {
        lx->line++;
        lx->line_start = lx->cont_end[lx->cont_next++];
    }
}

/* The '\n' at buf offset `off` ends a line: the next one starts after it. */
static void newline_at(lexer *lx, uint32_t off) {
    pass_continuations(lx, off);
    lx->line++;
    lx->line_start = orig_offset(lx, off) + 1;
}

/* The location of byte `off` of buf, which is on the current line: every '\n' before it has
 * gone through newline_at. Columns are bytes of the file's line, continuations included. */
static hfx_loc loc_at(lexer *lx, uint32_t off) {
    if (lx->fixed) return *lx->fixed;
    if (lx->cont_count) pass_continuations(lx, off);
    return (hfx_loc){lx->file, lx->line, orig_offset(lx, off) - lx->line_start + 1};
}

/* Whether text at p is a backslash followed by a line end; returns its length or 0. */
static uint32_t continuation_len(const char *p, const char *end) {
    if (p[0] != '\\') return 0;
    if (p + 1 < end && p[1] == '\n') return 2;
    if (p + 2 < end && p[1] == '\r' && p[2] == '\n') return 3;
    return 0;
}

/* Number of backslash-newlines in orig from `hit` (the first one) on. */
static uint32_t count_continuations(const char *hit, const char *end) {
    uint32_t n = 0;
    for (const char *q = hit; q < end && (q = memchr(q, '\\', (size_t)(end - q))); q++) {
        uint32_t c = continuation_len(q, end);
        if (c) {
            n++;
            q += c - 1;
        }
    }
    return n;
}

/* Builds buf without backslash-newlines, the map back to the original offsets, and the list of
 * the line ends removed (see lexer.cont_at). */
static void splice_lines(lexer *lx, uint32_t start, uint32_t size) {
    const char *p = lx->orig, *end = lx->orig + size;
    const char *hit = NULL;
    for (const char *q = p + start; q < end && (q = memchr(q, '\\', (size_t)(end - q))); q++)
        if (continuation_len(q, end)) { hit = q; break; }
    if (!hit) {
        lx->buf = lx->orig;
        lx->size = size;
        return;
    }
    uint32_t conts = count_continuations(hit, end);
    char *out = hfx_arena_alloc(lx->arena, (size_t)size + 1);
    uint32_t *map = HFX_NEW_ARRAY(lx->arena, uint32_t, (size_t)size + 1);
    uint32_t *cont_at = HFX_NEW_ARRAY(lx->arena, uint32_t, conts);
    uint32_t *cont_end = HFX_NEW_ARRAY(lx->arena, uint32_t, conts);
    uint32_t n = 0, k = 0;
    for (uint32_t i = 0; i < size;) {
        uint32_t c = continuation_len(p + i, end);
        if (c) {
            i += c;
            cont_at[k] = n;
            cont_end[k++] = i;
            continue;
        }
        map[n] = i;
        out[n++] = p[i++];
    }
    map[n] = size;
    out[n] = 0;
    lx->buf = out;
    lx->map = map;
    lx->size = n;
    lx->cont_at = cont_at;
    lx->cont_end = cont_end;
    lx->cont_count = k;
}

/* Punctuators' spellings, by hfx_punct: they need no copy. */
static const char *const punct_text[] = {
    "(", ")", "[", "]", "{", "}", ";", ",", ".", ":", "?", "+", "-", "*", "/", "%", "&", "|", "^", "~", "!",
    "<", ">", "<=", ">=", "==", "!=", "&&", "||", "<<", ">>", "=", "+=", "-=", "*=", "/=", "%=", "&=", "|=",
    "^=", "<<=", ">>=", "++", "--", "::", "->", "..."};
_Static_assert(sizeof punct_text / sizeof punct_text[0] == P_ELLIPSIS + 1, "one spelling per hfx_punct");

/* The spelling of the token at [start, end) of buf: in place in lx->text, NUL-terminated there.
 * A token that starts where the previous one's NUL went (`1.xxx`, `"a"b`) gets its own copy. */
static const char *spelling(lexer *lx, uint32_t start, uint32_t end) {
    if (start == lx->text_end) return hfx_arena_strndup(lx->arena, lx->buf + start, end - start);
    lx->text[end] = 0;
    lx->text_end = end;
    return lx->text + start;
}

/* Spellings that need no copy: punctuators by hfx_punct, and the ones of '#' and '##' (a '#'
 * is right before its directive's name, so an in-place NUL would cost that name a copy). */
static const char *fixed_spelling(hfx_token_kind kind, uint32_t punct, uint32_t len) {
    if (kind == TK_PUNCT) return punct_text[punct];
    if (kind == TK_HASH) return len == 1 ? "#" : "%:";
    if (kind == TK_HASHHASH) return len == 2 ? "##" : "%:%:";
    if (kind == TK_EOF) return "";
    return NULL;
}

/* Inline: it runs once per token, and the call cost as much as the work. */
static inline hfx_token *emit(lexer *lx, hfx_token_kind kind, uint32_t punct, uint32_t start, uint32_t end,
                              uint32_t flags) {
    hfx_token *t = hfx_arena_alloc_raw(lx->arena, sizeof *t);
    const char *text = fixed_spelling(kind, punct, end - start);
    t->kind = kind;
    t->punct = punct;
    t->flags = flags;
    t->text = text ? text : spelling(lx, start, end);
    t->len = end - start;
    t->loc = t->spelling = loc_at(lx, start);
    t->next = NULL;
    t->hideset = NULL;
    lx->tail->next = t;
    lx->tail = t;
    return t;
}

/* End of a block comment starting at p (on its slash-star), or NULL when the text ends first. */
static const char *block_comment_end(const char *p, const char *end) {
    for (p += 2; p + 1 < end; p++) {
        p = memchr(p, '*', (size_t)(end - p));
        if (!p || p + 1 >= end) return NULL;
        if (p[1] == '/') return p + 2;
    }
    return NULL;
}

/* End of a string literal starting at p (on the quote); *closed says whether a quote ended it. */
static const char *string_end(const char *p, const char *end, int *closed) {
    for (p++; p < end; p++) {
        if (*p == '"') { *closed = 1; return p + 1; }
        if (*p == '\n' || (*p == '\r' && p + 1 < end && p[1] == '\n')) break;
        if (*p == '\\' && p + 1 < end && p[1] != '\n') p++;
    }
    *closed = 0;
    return p;
}

/* Length of the UTF-8 sequence at p when it is well formed, else 1. */
static uint32_t utf8_len(const unsigned char *p, const unsigned char *end) {
    uint32_t n = p[0] >= 0xF0 && p[0] < 0xF5 ? 4 : p[0] >= 0xE0 ? 3 : p[0] >= 0xC2 && p[0] < 0xE0 ? 2 : 1;
    if (n == 1 || p + n > end) return 1;
    for (uint32_t i = 1; i < n; i++)
        if ((p[i] & 0xC0) != 0x80) return 1;
    return n;
}

/* Matches one token at p; returns its kind (or an S_ code) and sets *endp and *punct. */
static int scan(const unsigned char *p, const unsigned char **endp, uint32_t *punct) {
    const unsigned char *YYCURSOR = p, *YYMARKER = p;
    *punct = 0;
#define PUNCT(x) do { *punct = (x); *endp = YYCURSOR; return TK_PUNCT; } while (0)
#define KIND(x) do { *endp = YYCURSOR; return (x); } while (0)
    /*!re2c
        re2c:define:YYCTYPE = "unsigned char";
        re2c:yyfill:enable = 0;

        ident = [a-zA-Z_][a-zA-Z_0-9]*;
        isuf  = [uUlL]*;
        exp   = [eE] [+-]? [0-9]+;
        fsuf  = [fFhHlL];

        ident                                   { KIND(TK_IDENT); }
        [0-9]+ isuf                             { KIND(TK_INT); }
        "0" [xX] [0-9a-fA-F]+ isuf              { KIND(TK_INT); }
        ([0-9]* "." [0-9]+ exp? | [0-9]+ "." exp? | [0-9]+ exp) fsuf? { KIND(TK_FLOAT); }

        [ \t\v\f\r]+                            { KIND(S_SPACE); }
        "\n"                                    { KIND(S_NEWLINE); }
        "//"                                    { KIND(S_LINE_COMMENT); }
        "/*"                                    { KIND(S_BLOCK_COMMENT); }
        ["]                                     { KIND(S_STRING); }
        "\x00"                                  { KIND(S_NUL); }
        [\x80-\xff]                             { KIND(S_UTF8); }

        "#" | "%:"                              { KIND(TK_HASH); }
        "##" | "%:%:"                           { KIND(TK_HASHHASH); }

        "("   { PUNCT(P_LPAREN); }    ")"   { PUNCT(P_RPAREN); }
        "["   { PUNCT(P_LBRACKET); }  "]"   { PUNCT(P_RBRACKET); }
        "{"   { PUNCT(P_LBRACE); }    "}"   { PUNCT(P_RBRACE); }
        ";"   { PUNCT(P_SEMI); }      ","   { PUNCT(P_COMMA); }
        "."   { PUNCT(P_DOT); }       ":"   { PUNCT(P_COLON); }
        "?"   { PUNCT(P_QUESTION); }  "+"   { PUNCT(P_PLUS); }
        "-"   { PUNCT(P_MINUS); }     "*"   { PUNCT(P_STAR); }
        "/"   { PUNCT(P_SLASH); }     "%"   { PUNCT(P_PERCENT); }
        "&"   { PUNCT(P_AMP); }       "|"   { PUNCT(P_PIPE); }
        "^"   { PUNCT(P_CARET); }     "~"   { PUNCT(P_TILDE); }
        "!"   { PUNCT(P_BANG); }      "<"   { PUNCT(P_LT); }
        ">"   { PUNCT(P_GT); }        "<="  { PUNCT(P_LE); }
        ">="  { PUNCT(P_GE); }        "=="  { PUNCT(P_EQEQ); }
        "!="  { PUNCT(P_NE); }        "&&"  { PUNCT(P_ANDAND); }
        "||"  { PUNCT(P_OROR); }      "<<"  { PUNCT(P_SHL); }
        ">>"  { PUNCT(P_SHR); }       "="   { PUNCT(P_ASSIGN); }
        "+="  { PUNCT(P_PLUSEQ); }    "-="  { PUNCT(P_MINUSEQ); }
        "*="  { PUNCT(P_STAREQ); }    "/="  { PUNCT(P_SLASHEQ); }
        "%="  { PUNCT(P_PERCENTEQ); } "&="  { PUNCT(P_AMPEQ); }
        "|="  { PUNCT(P_PIPEEQ); }    "^="  { PUNCT(P_CARETEQ); }
        "<<=" { PUNCT(P_SHLEQ); }     ">>=" { PUNCT(P_SHREQ); }
        "++"  { PUNCT(P_INC); }       "--"  { PUNCT(P_DEC); }
        "::"  { PUNCT(P_COLONCOLON); } "->" { PUNCT(P_ARROW); }
        "..." { PUNCT(P_ELLIPSIS); }

        [^]                                     { KIND(TK_OTHER); }
    */
#undef PUNCT
#undef KIND
}

/* Skips a comment or a string that scan() found the start of; returns where it ends and sets
 * *unterminated for a string that its line's end cut short. */
static uint32_t finish_long_token(lexer *lx, int kind, uint32_t start, bool *unterminated) {
    const char *p = lx->buf + start, *end = lx->buf + lx->size;
    if (kind == S_LINE_COMMENT) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        return nl ? (uint32_t)(nl - lx->buf) : lx->size;
    }
    if (kind == S_BLOCK_COMMENT) {
        const char *e = block_comment_end(p, end);
        if (e) return (uint32_t)(e - lx->buf);
        hfx_error(lx->diags, loc_at(lx, start), X_PP_UNTERMINATED_COMMENT, "unexpected end of file in comment");
        return lx->size;
    }
    int closed;
    const char *e = string_end(p, end, &closed);
    *unterminated = !closed;
    if (!closed && !lx->defer_strings)
        hfx_error(lx->diags, loc_at(lx, start), X_PP_STRING_EOL, "newline in string literal");
    return (uint32_t)(e - lx->buf);
}

/* The line ends inside [from, to) of buf: a block comment is the only token that holds any. */
static void count_newlines(lexer *lx, uint32_t from, uint32_t to) {
    const char *p = lx->buf + from, *end = lx->buf + to;
    while ((p = memchr(p, '\n', (size_t)(end - p)))) newline_at(lx, (uint32_t)(p++ - lx->buf));
}

/* Lexes all of buf, appending tokens and a final TK_EOF. */
static void run(lexer *lx, uint32_t pos) {
    uint32_t flags = TF_BOL;
    lx->text = hfx_arena_alloc_raw(lx->arena, (size_t)lx->size + 1);
    memcpy(lx->text, lx->buf, lx->size);
    lx->text[lx->size] = 0;
    lx->text_end = UINT32_MAX;
    const unsigned char *base = (const unsigned char *)lx->buf;
    for (;;) {
        const unsigned char *endp;
        uint32_t punct;
        int kind = scan(base + pos, &endp, &punct);
        uint32_t end = (uint32_t)(endp - base);
        bool unterminated = false;
        switch (kind) {
        case S_SPACE: flags |= TF_SPACE; break;
        case S_NEWLINE:
            newline_at(lx, pos);
            flags = TF_BOL;
            break;
        case S_LINE_COMMENT:
            end = finish_long_token(lx, kind, pos, &unterminated);
            flags |= TF_SPACE;
            break;
        case S_BLOCK_COMMENT:
            end = finish_long_token(lx, kind, pos, &unterminated);
            count_newlines(lx, pos, end);
            flags |= TF_SPACE;
            break;
        case S_STRING:
            end = finish_long_token(lx, kind, pos, &unterminated);
            emit(lx, TK_STRING, 0, pos, end, flags | (unterminated ? TF_UNTERMINATED : 0));
            flags = 0;
            break;
        case S_NUL:
            if (pos >= lx->size) {
                emit(lx, TK_EOF, 0, lx->size, lx->size, flags);
                return;
            }
            emit(lx, TK_OTHER, 0, pos, end, flags);
            flags = 0;
            break;
        case S_UTF8:
            end = pos + utf8_len(base + pos, base + lx->size);
            emit(lx, TK_OTHER, 0, pos, end, flags);
            flags = 0;
            break;
        default:
            emit(lx, (hfx_token_kind)kind, punct, pos, end, flags);
            flags = 0;
            break;
        }
        pos = end;
    }
}

static hfx_token *tokenize_file(hfx_arena *arena, hfx_diags *diags, uint32_t file, bool defer_strings) {
    lexer lx;
    memset(&lx, 0, sizeof lx);
    lx.defer_strings = defer_strings;
    lx.arena = arena;
    lx.diags = diags;
    lx.file = file;
    lx.tail = &lx.head;
    lx.line = 1;
    const hfx_source *src = file < diags->file_count ? &diags->files[file] : NULL;
    lx.orig = src && src->text ? src->text : "";
    uint32_t size = src && src->text ? src->size : 0;
    uint32_t start = 0;
    if (size >= 3 && memcmp(lx.orig, "\xEF\xBB\xBF", 3) == 0) {
        /* A byte-order mark is no part of line 1: columns count from after it. */
        start = 3;
        lx.line_start = 3;
    }
    splice_lines(&lx, start, size);
    run(&lx, start);
    return lx.head.next;
}

hfx_token *hfx_tokenize(hfx_arena *arena, hfx_diags *diags, uint32_t file) {
    return tokenize_file(arena, diags, file, false);
}

hfx_token *hfx_tokenize_deferred(hfx_arena *arena, hfx_diags *diags, uint32_t file) {
    return tokenize_file(arena, diags, file, true);
}

hfx_token *hfx_tokenize_text(hfx_arena *arena, hfx_diags *diags, const char *text, uint32_t size, hfx_loc loc) {
    lexer lx;
    memset(&lx, 0, sizeof lx);
    lx.arena = arena;
    lx.diags = diags;
    lx.tail = &lx.head;
    lx.line = 1;
    lx.fixed = &loc;
    char *copy = hfx_arena_strndup(arena, text, size);
    lx.orig = lx.buf = copy;
    lx.size = size;
    run(&lx, 0);
    return lx.head.next;
}
