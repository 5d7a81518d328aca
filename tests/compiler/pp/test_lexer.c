/* The re2c lexer: token kinds, spellings, exact locations and flags, comments, continuations,
 * line ends, encodings, errors, and a 100 000-line input. */
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "pp/token.h"

typedef struct {
    hfx_arena arena;
    hfx_diags diags;
    hfx_token *toks;
} lexed;

static void lex(lexed *l, const char *text, size_t size) {
    hfx_arena_init(&l->arena);
    hfx_diags_init(&l->diags, &l->arena, 0);
    char *copy = hfx_arena_strndup(&l->arena, text, size);
    uint32_t f = hfx_diags_add_file(&l->diags, "t.fx", NULL, copy, (uint32_t)size);
    l->toks = hfx_tokenize(&l->arena, &l->diags, f);
}

static void lex_str(lexed *l, const char *text) { lex(l, text, strlen(text)); }

static char *diag_text(lexed *l) {
    char *s = hfx_diags_format(&l->diags, 0);
    char *r = hfx_arena_strdup(&l->arena, s);
    free(s);
    return r;
}

/* Spellings joined by single spaces, with a kind letter before each: i n f s p # % h o. */
static char *dump(lexed *l) {
    static const char kinds[] = "Einfsp#%ho";
    size_t cap = 64, len = 0;
    for (hfx_token *t = l->toks; t; t = t->next) cap += t->len + 4;
    char *out = hfx_arena_alloc(&l->arena, cap);
    for (hfx_token *t = l->toks; t && t->kind != TK_EOF; t = t->next) {
        if (len) out[len++] = ' ';
        out[len++] = kinds[t->kind];
        out[len++] = ':';
        memcpy(out + len, t->text, t->len);
        len += t->len;
    }
    out[len] = 0;
    return out;
}

static hfx_token *nth(lexed *l, int n) {
    hfx_token *t = l->toks;
    while (n-- > 0 && t) t = t->next;
    return t;
}

static void identifiers_and_numbers(void) {
    lexed l;
    lex_str(&l, "_a1 B 12 0x1F 017 12u 7UL 0 1.0 .5 1. 1e3 1.0e-3f 2.5F 3h 4.0H 5.0l 6L 1E+2");
    CHECK_STR(dump(&l), "i:_a1 i:B n:12 n:0x1F n:017 n:12u n:7UL n:0 f:1.0 f:.5 f:1. f:1e3 f:1.0e-3f f:2.5F "
                        "n:3 i:h f:4.0H f:5.0l n:6L f:1E+2");
    CHECK_INT(l.diags.count, 0);
    hfx_arena_free(&l.arena);
}

static void number_edges(void) {
    lexed l;
    /* A swizzle on a literal, an exponent with no digits, a member access after an int. */
    lex_str(&l, "1.xxx 1e 1.0.x a.b");
    CHECK_STR(dump(&l), "f:1. i:xxx n:1 i:e f:1.0 p:. i:x i:a p:. i:b");
    hfx_arena_free(&l.arena);
}

static void punctuators(void) {
    lexed l;
    lex_str(&l, "( ) [ ] { } ; , . : ? + - * / % & | ^ ~ ! < > <= >= == != && || << >> = += -= *= /= "
                "%= &= |= ^= <<= >>= ++ -- :: -> ...");
    hfx_punct want[] = {P_LPAREN, P_RPAREN, P_LBRACKET, P_RBRACKET, P_LBRACE, P_RBRACE, P_SEMI, P_COMMA,
                        P_DOT, P_COLON, P_QUESTION, P_PLUS, P_MINUS, P_STAR, P_SLASH, P_PERCENT, P_AMP,
                        P_PIPE, P_CARET, P_TILDE, P_BANG, P_LT, P_GT, P_LE, P_GE, P_EQEQ, P_NE, P_ANDAND,
                        P_OROR, P_SHL, P_SHR, P_ASSIGN, P_PLUSEQ, P_MINUSEQ, P_STAREQ, P_SLASHEQ,
                        P_PERCENTEQ, P_AMPEQ, P_PIPEEQ, P_CARETEQ, P_SHLEQ, P_SHREQ, P_INC, P_DEC,
                        P_COLONCOLON, P_ARROW, P_ELLIPSIS};
    hfx_token *t = l.toks;
    for (size_t i = 0; i < sizeof want / sizeof want[0]; i++, t = t->next) {
        CHECK_INT(t->kind, TK_PUNCT);
        CHECK_INT(t->punct, want[i]);
    }
    CHECK_INT(t->kind, TK_EOF);
    hfx_arena_free(&l.arena);
}

static void longest_match_without_spaces(void) {
    lexed l;
    lex_str(&l, "a+++b<<=c>>d->e||f");
    CHECK_STR(dump(&l), "i:a p:++ p:+ i:b p:<<= i:c p:>> i:d p:-> i:e p:|| i:f");
    hfx_arena_free(&l.arena);
}

static void hashes(void) {
    lexed l;
    lex_str(&l, "#define A(x) #x ## y %: %:%:");
    CHECK_STR(dump(&l), "#:# i:define i:A p:( i:x p:) #:# i:x %:## i:y #:%: %:%:%:");
    hfx_arena_free(&l.arena);
}

static void strings_keep_escapes(void) {
    lexed l;
    lex_str(&l, "\"a\\\"b\" \"\\\\\" \"\" \"caf\xC3\xA9\"");
    CHECK_STR(dump(&l), "s:\"a\\\"b\" s:\"\\\\\" s:\"\" s:\"caf\xC3\xA9\"");
    CHECK_INT(l.diags.count, 0);
    hfx_arena_free(&l.arena);
}

static void unterminated_string(void) {
    lexed l;
    lex_str(&l, "x = \"abc\ny");
    CHECK_STR(dump(&l), "i:x p:= s:\"abc i:y");
    CHECK_STR(diag_text(&l), "t.fx(1,5): error X1005: newline in string literal\n");
    CHECK_INT(nth(&l, 3)->loc.line, 2);
    hfx_arena_free(&l.arena);
}

static void locations_and_flags(void) {
    lexed l;
    lex_str(&l, "float4 x;\n  \t y = 1; // c\n\n/* a\n b */ z");
    /* float4 x ; y = 1 ; z EOF */
    int lines[] = {1, 1, 1, 2, 2, 2, 2, 5, 5};
    int cols[] = {1, 8, 9, 5, 7, 9, 10, 7, 8};
    unsigned flags[] = {TF_BOL, TF_SPACE, 0, TF_BOL | TF_SPACE, TF_SPACE, TF_SPACE, 0,
                        TF_BOL | TF_SPACE, 0};
    hfx_token *t = l.toks;
    for (int i = 0; i < 9; i++, t = t->next) {
        CHECK_INT(t->loc.line, lines[i]);
        CHECK_INT(t->loc.col, cols[i]);
        CHECK_INT(t->flags, flags[i]);
        CHECK_INT(t->spelling.line, lines[i]);
    }
    CHECK(t == NULL);
    hfx_arena_free(&l.arena);
}

static void comments(void) {
    lexed l;
    lex_str(&l, "a//x /* y\nb/**/c/* // */d/***/e");
    CHECK_STR(dump(&l), "i:a i:b i:c i:d i:e");
    CHECK_INT(nth(&l, 2)->flags, TF_SPACE); /* a comment separates like a space */
    CHECK_INT(l.diags.count, 0);
    hfx_arena_free(&l.arena);
}

/* A newline inside a block comment does not start a new logical line (C: the comment is one space). */
static void block_comment_newline_is_not_bol(void) {
    lexed l;
    lex_str(&l, "#define X /*\n*/ 1\n");
    CHECK_STR(dump(&l), "#:# i:define i:X n:1");
    CHECK_INT(nth(&l, 3)->flags, TF_SPACE);
    CHECK_INT(nth(&l, 3)->loc.line, 2);
    CHECK_INT(nth(&l, 3)->loc.col, 4);
    hfx_arena_free(&l.arena);
}

static void unterminated_comment(void) {
    lexed l;
    lex_str(&l, "a\n  /* never\nclosed *");
    CHECK_STR(dump(&l), "i:a");
    CHECK_STR(diag_text(&l), "t.fx(2,3): error X1001: unexpected end of file in comment\n");
    CHECK_INT(nth(&l, 1)->kind, TK_EOF);
    hfx_arena_free(&l.arena);
}

static void line_continuations(void) {
    lexed l;
    lex_str(&l, "#define A 1 \\\n + 2\nfl\\\noat b\\\r\n;\n");
    CHECK_STR(dump(&l), "#:# i:define i:A n:1 p:+ n:2 i:float i:b p:;");
    hfx_token *plus = nth(&l, 4), *fl = nth(&l, 6), *semi = nth(&l, 8);
    CHECK_INT(plus->flags, TF_SPACE); /* the continued line is the same logical line */
    CHECK_INT(plus->loc.line, 2);
    CHECK_INT(plus->loc.col, 2);
    CHECK_INT(fl->flags, TF_BOL);
    CHECK_INT(fl->loc.line, 3);
    CHECK_INT(fl->loc.col, 1);
    CHECK_INT(nth(&l, 7)->loc.line, 4);
    CHECK_INT(nth(&l, 7)->loc.col, 5);
    CHECK_INT(semi->loc.line, 5);
    CHECK_INT(semi->loc.col, 1);
    CHECK_INT(semi->flags, 0);
    hfx_arena_free(&l.arena);
}

static void crlf_line_ends(void) {
    lexed l;
    lex_str(&l, "a\r\n b\r\n\r\n  c \"s\"\r\n");
    CHECK_STR(dump(&l), "i:a i:b i:c s:\"s\"");
    CHECK_INT(nth(&l, 1)->loc.line, 2);
    CHECK_INT(nth(&l, 1)->loc.col, 2);
    CHECK_INT(nth(&l, 1)->flags, TF_BOL | TF_SPACE);
    CHECK_INT(nth(&l, 2)->loc.line, 4);
    CHECK_INT(nth(&l, 2)->loc.col, 3);
    CHECK_INT(nth(&l, 3)->len, 3);
    CHECK_INT(l.diags.count, 0);
    hfx_arena_free(&l.arena);
}

static void bom_is_skipped(void) {
    lexed l;
    lex_str(&l, "\xEF\xBB\xBF" "float x;");
    CHECK_STR(dump(&l), "i:float i:x p:;");
    CHECK_INT(l.toks->loc.col, 1);
    CHECK_INT(l.toks->flags, TF_BOL);
    hfx_arena_free(&l.arena);
}

static void high_bytes(void) {
    lexed l;
    /* UTF-8 and Latin-1 in comments and strings are fine; a stray one is TK_OTHER. */
    lex_str(&l, "// Código \xE9\n/* \xC3\xA1\xFF */ a \"\xE9\" \xE9 b \xC3\xB3");
    CHECK_STR(dump(&l), "i:a s:\"\xE9\" o:\xE9 i:b o:\xC3\xB3");
    CHECK_INT(nth(&l, 2)->loc.col, 17);
    CHECK_INT(nth(&l, 4)->len, 2); /* one well-formed UTF-8 character */
    CHECK_INT(l.diags.count, 0);
    hfx_arena_free(&l.arena);
}

static void stray_bytes_and_nul(void) {
    lexed l;
    lex(&l, "a @ $ ` ' \\ \0 b", 15);
    CHECK_STR(dump(&l), "i:a o:@ o:$ o:` o:' o:\\ o:"); /* the dump stops at the NUL byte */
    CHECK_STR(nth(&l, 7)->text, "b");
    CHECK_INT(nth(&l, 6)->len, 1);
    CHECK_INT(nth(&l, 7)->loc.col, 15);
    CHECK_INT(nth(&l, 8)->kind, TK_EOF);
    hfx_arena_free(&l.arena);
}

static void empty_and_eof_location(void) {
    lexed l;
    lex_str(&l, "");
    CHECK_INT(l.toks->kind, TK_EOF);
    CHECK(l.toks->next == NULL);
    hfx_arena_free(&l.arena);
    lex_str(&l, "a\n b");
    CHECK_INT(nth(&l, 2)->kind, TK_EOF);
    CHECK_INT(nth(&l, 2)->loc.line, 2);
    CHECK_INT(nth(&l, 2)->loc.col, 3);
    hfx_arena_free(&l.arena);
}

static void tokenize_text_uses_given_loc(void) {
    hfx_arena a;
    hfx_arena_init(&a);
    hfx_diags d;
    hfx_diags_init(&d, &a, 0);
    hfx_token *t = hfx_tokenize_text(&a, &d, "ab12 +=", 7, (hfx_loc){0, 7, 3});
    CHECK_INT(t->kind, TK_IDENT);
    CHECK_STR(t->text, "ab12");
    CHECK_INT(t->loc.line, 7);
    CHECK_INT(t->loc.col, 3);
    CHECK_INT(t->next->punct, P_PLUSEQ);
    CHECK_INT(t->next->loc.col, 3);
    CHECK_INT(t->next->next->kind, TK_EOF);
    hfx_arena_free(&a);
}

/* Checks tokens' (line, col) against a list whose last entry is the TK_EOF's. */
static void check_positions(lexed *l, const int (*want)[2], int count) {
    hfx_token *t = l->toks, *last = NULL;
    for (int i = 0; i < count && t; i++, last = t, t = t->next) {
        CHECK_INT(t->loc.line, want[i][0]);
        CHECK_INT(t->loc.col, want[i][1]);
        CHECK_INT(t->spelling.line, want[i][0]);
        CHECK_INT(t->spelling.col, want[i][1]);
    }
    CHECK(last && last->kind == TK_EOF && !t);
}

/* Every kind of line end in one CRLF file: comment, plain, continuation; a tab counts one byte. */
static void crlf_positions(void) {
    lexed l;
    lex_str(&l, "a /* x\r\n y\r\n */ b\r\n\tc\r\n#define M 1 \\\r\n + 2\r\n d");
    CHECK_STR(dump(&l), "i:a i:b i:c #:# i:define i:M n:1 p:+ n:2 i:d");
    static const int want[][2] = {{1, 1}, {3, 5}, {4, 2}, {5, 1}, {5, 2}, {5, 9}, {5, 11}, {6, 2}, {6, 4},
                                  {7, 2}, {7, 3}};
    check_positions(&l, want, 11);
    CHECK_INT(nth(&l, 7)->flags, TF_SPACE); /* still the #define's line */
    CHECK_INT(nth(&l, 9)->flags, TF_BOL | TF_SPACE);
    hfx_arena_free(&l.arena);
}

static void block_comment_over_lines_then_token(void) {
    lexed l;
    lex_str(&l, "x /*\n\n  */y /* a */ z\n/* 1\n2 */\n w");
    CHECK_STR(dump(&l), "i:x i:y i:z i:w");
    static const int want[][2] = {{1, 1}, {3, 5}, {3, 15}, {6, 2}, {6, 3}};
    check_positions(&l, want, 5);
    CHECK_INT(nth(&l, 1)->flags, TF_SPACE);
    CHECK_INT(nth(&l, 3)->flags, TF_BOL | TF_SPACE);
    hfx_arena_free(&l.arena);
}

/* Continuations inside tokens, two in a row, one right before a line end, one inside a comment:
 * each ends a line of the file, and columns count from the line the token starts on. */
static void continuations_inside_token_runs(void) {
    lexed l;
    lex_str(&l, "int ab\\\ncd = x\\\n\\\ny+1;\n  q\\\n\nr /* a\\\n\n b */ s");
    CHECK_STR(dump(&l), "i:int i:abcd p:= i:xy p:+ n:1 p:; i:q i:r i:s");
    static const int want[][2] = {{1, 1}, {1, 5}, {2, 4}, {2, 6}, {4, 2}, {4, 3}, {4, 4}, {5, 3}, {7, 1},
                                  {9, 7}, {9, 8}};
    check_positions(&l, want, 11);
    CHECK_INT(nth(&l, 8)->flags, TF_BOL);
    CHECK_INT(nth(&l, 9)->flags, TF_SPACE);
    hfx_arena_free(&l.arena);
}

static void tabs_are_one_byte(void) {
    lexed l;
    lex_str(&l, "\t\tx\t=\t1;\n\t y");
    static const int want[][2] = {{1, 3}, {1, 5}, {1, 7}, {1, 8}, {2, 3}, {2, 4}};
    check_positions(&l, want, 6);
    hfx_arena_free(&l.arena);
}

/* The first token after #line gets the new number and name; the lines after it follow on. */
static void first_token_after_line_directive(void) {
    hfx_arena a;
    hfx_arena_init(&a);
    hfx_diags d;
    hfx_diags_init(&d, &a, 0);
    const char *text = "a\r\n#line 10 \"other.fx\"\r\n\tb c\r\n d\n#line 3\ne";
    hfx_token *t = hfx_preprocess(&a, &d, "t.fx", text, (uint32_t)strlen(text), NULL);
    const char *names[] = {"a", "b", "c", "d", "e"};
    static const int want[][2] = {{1, 1}, {10, 2}, {10, 4}, {11, 2}, {3, 1}};
    for (int i = 0; i < 5; i++, t = t->next) {
        CHECK_STR(t->text, names[i]);
        CHECK_INT(t->loc.line, want[i][0]);
        CHECK_INT(t->loc.col, want[i][1]);
        CHECK_STR(d.files[t->loc.file].name, i == 0 ? "t.fx" : "other.fx");
    }
    CHECK_INT(t->kind, TK_EOF);
    CHECK_INT(d.count, 0);
    hfx_arena_free(&a);
}

/* Spellings live in the lexer's copy of the text, NUL-terminated there; a token that starts
 * where the one before it ended still gets its whole spelling, and the file's text is intact. */
static void adjacent_spellings(void) {
    lexed l;
    const char *src = "\"s\"x 1.f\"t\" a#b%:c 1.xx";
    lex_str(&l, src);
    CHECK_STR(dump(&l), "s:\"s\" i:x f:1.f s:\"t\" i:a #:# i:b #:%: i:c f:1. i:xx");
    for (hfx_token *t = l.toks; t; t = t->next) CHECK_INT(strlen(t->text), t->len);
    CHECK_STR(nth(&l, 1)->text, "x");
    CHECK_STR(nth(&l, 3)->text, "\"t\"");
    CHECK_STR(l.diags.files[0].text, src);
    hfx_arena_free(&l.arena);
}

static void hundred_thousand_lines(void) {
    enum { LINES = 100000 };
    const char *line = "float4 v = mul(float4(p, 1.0f), World); /* c */ // x\n";
    size_t n = strlen(line);
    char *text = malloc(n * LINES + 1);
    for (int i = 0; i < LINES; i++) memcpy(text + n * (size_t)i, line, n);
    text[n * LINES] = 0;
    lexed l;
    lex(&l, text, n * LINES);
    free(text);
    size_t count = 0;
    hfx_token *last = NULL;
    for (hfx_token *t = l.toks; t->kind != TK_EOF; t = t->next) { count++; last = t; }
    CHECK_INT(count, 15 * (size_t)LINES);
    CHECK_INT(last->loc.line, LINES);
    CHECK_INT(last->loc.col, 39);
    CHECK_INT(l.diags.count, 0);
    hfx_arena_free(&l.arena);
}

int main(void) {
    RUN(identifiers_and_numbers);
    RUN(number_edges);
    RUN(punctuators);
    RUN(longest_match_without_spaces);
    RUN(hashes);
    RUN(strings_keep_escapes);
    RUN(unterminated_string);
    RUN(locations_and_flags);
    RUN(comments);
    RUN(block_comment_newline_is_not_bol);
    RUN(unterminated_comment);
    RUN(line_continuations);
    RUN(crlf_line_ends);
    RUN(bom_is_skipped);
    RUN(high_bytes);
    RUN(stray_bytes_and_nul);
    RUN(empty_and_eof_location);
    RUN(tokenize_text_uses_given_loc);
    RUN(crlf_positions);
    RUN(block_comment_over_lines_then_token);
    RUN(continuations_inside_token_runs);
    RUN(tabs_are_one_byte);
    RUN(first_token_after_line_directive);
    RUN(adjacent_spellings);
    RUN(hundred_thousand_lines);
    return test_summary();
}
