/* The preprocessor: macros (object-like, function-like, variadic, # and ##, recursion guard,
 * runaway expansion), conditionals and their expressions, #error, #line, #pragma, __FILE__ and
 * __LINE__, -D options, with exact diagnostics. Includes are in test_pp_include.c, the seed
 * corpus in test_pp_seeds.c. */
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "pp/token.h"

typedef struct {
    hfx_arena arena;
    hfx_diags diags;
    hfx_token *toks;
    char *out;   /* token spellings joined by single spaces */
    char *diag;  /* formatted diagnostics */
} pp_run;

static char *join_all(hfx_arena *a, const hfx_token *t) {
    size_t cap = 1;
    for (const hfx_token *u = t; u; u = u->next) cap += u->len + 1;
    char *out = hfx_arena_alloc(a, cap), *p = out;
    for (; t && t->kind != TK_EOF; t = t->next) {
        if (p != out) *p++ = ' ';
        memcpy(p, t->text, t->len);
        p += t->len;
    }
    *p = 0;
    return out;
}

static void pp_opts(pp_run *r, const char *text, const hfx_pp_options *opt) {
    hfx_arena_init(&r->arena);
    hfx_diags_init(&r->diags, &r->arena, 0);
    r->toks = hfx_preprocess(&r->arena, &r->diags, "t.fx", text, (uint32_t)strlen(text), opt);
    r->out = join_all(&r->arena, r->toks);
    char *d = hfx_diags_format(&r->diags, 0);
    r->diag = hfx_arena_strdup(&r->arena, d);
    free(d);
}

static void pp(pp_run *r, const char *text) { pp_opts(r, text, NULL); }

/* The expected output written as text, re-cut by the lexer, so spacing does not matter. */
static char *tokens_of(pp_run *r, const char *text) {
    return join_all(&r->arena, hfx_tokenize_text(&r->arena, &r->diags, text, (uint32_t)strlen(text),
                                                 (hfx_loc){0, 1, 1}));
}

static hfx_token *find_tok(pp_run *r, const char *text, int nth) {
    for (hfx_token *t = r->toks; t; t = t->next)
        if (strcmp(t->text, text) == 0 && nth-- == 0) return t;
    return NULL;
}

static void done(pp_run *r) { hfx_arena_free(&r->arena); }

static void object_like_macro_loc_is_use_site(void) {
    pp_run r;
    pp(&r, "#define MaxLights 50\n\nfloat3 LightPosition[MaxLights];\n");
    CHECK_STR(r.out, "float3 LightPosition [ 50 ] ;");
    CHECK_STR(r.diag, "");
    hfx_token *t = find_tok(&r, "50", 0);
    CHECK(t != NULL);
    if (t) {
        CHECK_INT(t->kind, TK_INT);
        CHECK_INT(t->loc.line, 3);
        CHECK_INT(t->loc.col, 22);
        CHECK_INT(t->spelling.line, 1);
        CHECK_INT(t->spelling.col, 19);
    }
    CHECK_INT(r.toks->flags & TF_BOL, TF_BOL);
    done(&r);
}

static void function_like_macros(void) {
    pp_run r;
    pp(&r, "#define SQ(x) ((x)*(x))\n#define ADD(a, b) a + b\n#define NOARGS() 7\n"
           "SQ(a+1) ADD((1,2), f(3,4)) NOARGS() SQ SQ (2) ADD(\n  p,\n  q)");
    CHECK_STR(r.out, tokens_of(&r, "((a+1)*(a+1)) (1,2) + f(3,4) 7 SQ ((2)*(2)) p + q"));
    CHECK_STR(r.diag, "");
    /* Argument tokens keep their own place; body tokens take the use site. */
    hfx_token *q = find_tok(&r, "q", 0);
    CHECK_INT(q->loc.line, 6);
    CHECK_INT(q->loc.col, 3);
    hfx_token *plus = find_tok(&r, "+", 2);
    CHECK_INT(plus->loc.line, 4);
    CHECK_INT(plus->loc.col, 9);
    done(&r);
}

/* The example of C11 6.10.3.5 paragraph 5 (its char-literal-free part). */
static void c_standard_example_expansion(void) {
    pp_run r;
    pp(&r, "#define x 3\n#define f(a) f(x * (a))\n#undef x\n#define x 2\n#define g f\n#define z z[0]\n"
           "#define h g(~\n#define m(a) a(w)\n#define w 0,1\n#define t(a) a\n#define p() int\n"
           "#define q(x) x\n#define r(x,y) x ## y\n#define str(x) # x\n"
           "f(y+1) + f(f(z)) % t(t(g)(0) + t)(1);\n"
           "g(x+(3,4)-w) | h 5) & m\n(f)^m(m);\n"
           "p() i[q()] = { q(1), r(2,3), r(4,), r(,5), r(,) };\n"
           "char c[2][6] = { str(hello), str() };\n");
    CHECK_STR(r.out, tokens_of(&r, "f(2 * (y+1)) + f(2 * (f(2 * (z[0])))) % f(2 * (0)) + t(1);\n"
                                   "f(2 * (2+(3,4)-0,1)) | f(2 * (~ 5)) & f(2 * (0,1))^m(0,1);\n"
                                   "int i[] = { 1, 23, 4, 5, };\n"
                                   "char c[2][6] = { \"hello\", \"\" };"));
    CHECK_STR(r.diag, "");
    done(&r);
}

/* The example of C11 6.10.3.5 paragraph 7: # and ## together. */
static void c_standard_example_stringize_paste(void) {
    pp_run r;
    pp(&r, "#define str(s) # s\n#define xstr(s) str(s)\n"
           "#define debug(s, t) printf(\"x\" # s \"= %d, x\" # t \"= %s\", \\\n x ## s, x ## t)\n"
           "#define INCFILE(n) vers ## n\n#define glue(a, b) a ## b\n#define xglue(a, b) glue(a, b)\n"
           "#define HIGHLOW \"hello\"\n#define LOW LOW \", world\"\n"
           "debug(1, 2);\n"
           "fputs(str(strncmp(\"abc\\0d\", \"abc\") // this goes away\n == 0) str(: @\\n), s);\n"
           "xstr(INCFILE(2).h)\nglue(HIGH, LOW);\nxglue(HIGH, LOW)\n");
    CHECK_STR(r.out, tokens_of(&r, "printf(\"x\" \"1\" \"= %d, x\" \"2\" \"= %s\", x1, x2);\n"
                                   "fputs(\"strncmp(\\\"abc\\\\0d\\\", \\\"abc\\\") == 0\" \": @\\n\", s);\n"
                                   "\"vers2.h\"\n\"hello\";\n\"hello\" \", world\""));
    CHECK_STR(r.diag, "");
    done(&r);
}

static void stringize_spacing(void) {
    pp_run r;
    pp(&r, "#define S(x) #x\nS(  a   +b  ) S(\"q\\\\\") S() S(\"\\\\\" \\ n)");
    /* S("\\" \ n): the string's backslashes are escaped, the stray one outside is not. */
    CHECK_STR(r.out, "\"a +b\" \"\\\"q\\\\\\\\\\\"\" \"\" \"\\\"\\\\\\\\\\\" \\ n\"");
    done(&r);
    /* Spacing survives substitution: the argument's first token takes the parameter's. */
    pp(&r, "#define STR(x) #x\n#define XSTR(x) STR(x)\n#define AB(a, b) a b\n#define P(a) [a]\n"
           "XSTR(AB(1,2)) XSTR(P(x)) XSTR( AB(p,q)+AB(r,s))");
    CHECK_STR(r.out, "\"1 2\" \"[x]\" \"p q+r s\"");
    done(&r);
}

/* The macro style of XNA / MonoGame stock effects (Macros.fxh): ## builds sampler and register names. */
static void xna_style_macros(void) {
    pp_run r;
    pp(&r, "#if SM4\n#define DECLARE_TEXTURE(Name, index) Texture2D<float4> Name : register(t##index);\n"
           "#else\n#define DECLARE_TEXTURE(Name, index) \\\n    texture2D Name; \\\n"
           "    sampler Name##Sampler : register(s##index) = sampler_state { Texture = (Name); };\n"
           "#define SAMPLE_TEXTURE(Name, texCoord)  tex2D(Name##Sampler, texCoord)\n#endif\n"
           "#define TECHNIQUE(name, vsname, psname ) \\\n"
           "  technique name { pass { VertexShader = compile vs_2_0 vsname (); PixelShader = compile ps_2_0 psname(); } }\n"
           "DECLARE_TEXTURE(Texture, 0);\n"
           "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return SAMPLE_TEXTURE(Texture, uv); }\n"
           "TECHNIQUE(SpriteBatch, SpriteVertexShader, SpritePixelShader);\n");
    CHECK_STR(r.out, tokens_of(&r, "texture2D Texture; sampler TextureSampler : register(s0) = sampler_state "
                                   "{ Texture = (Texture); };;\n"
                                   "float4 PS(float2 uv : TEXCOORD0) : COLOR0 { return tex2D(TextureSampler, uv); }\n"
                                   "technique SpriteBatch { pass { VertexShader = compile vs_2_0 SpriteVertexShader (); "
                                   "PixelShader = compile ps_2_0 SpritePixelShader(); } };"));
    CHECK_STR(r.diag, "");
    hfx_token *s0 = find_tok(&r, "s0", 0);
    CHECK(s0 && s0->kind == TK_IDENT);
    if (s0) CHECK_INT(s0->loc.line, 11); /* the use site */
    done(&r);
}

static void pasting(void) {
    pp_run r;
    pp(&r, "#define CAT(a, b) a ## b\n#define CAT3(a, b, c) a ## b ## c\n#define E\n"
           "CAT(float, 4) CAT(+, =) CAT(1, .5f) CAT3(x, , z) CAT(, ) CAT(a, E) CAT(<<, =)\n");
    CHECK_STR(r.out, "float4 += 1.5f xz aE <<=");
    CHECK_INT(find_tok(&r, "float4", 0)->kind, TK_IDENT);
    CHECK_INT(find_tok(&r, "+=", 0)->punct, P_PLUSEQ);
    CHECK_INT(find_tok(&r, "1.5f", 0)->kind, TK_FLOAT);
    CHECK_STR(r.diag, "");
    done(&r);
}

static void variadic_macros(void) {
    pp_run r;
    pp(&r, "#define V(fmt, ...) f(fmt, __VA_ARGS__)\n#define E(...) [__VA_ARGS__]\n"
           "#define G(a, ...) g(a, ## __VA_ARGS__)\n#define N(args...) n(args)\n"
           "V(a, b, (c, d)) E() E(1, 2) G(1) G(1, 2) N(x, y)");
    CHECK_STR(r.out, tokens_of(&r, "f(a, b, (c, d)) [] [1, 2] g(1) g(1, 2) n(x, y)"));
    CHECK_STR(r.diag, "");
    done(&r);
}

static void recursion_guard(void) {
    pp_run r;
    pp(&r, "#define foo foo bar\n#define a b\n#define b a\n#define f(x) x f\nfoo a b f(1)(2)");
    /* C leaves f(1)(2) open (C11 6.10.3.4p4): hidesets paint the second f, as chibicc does. */
    CHECK_STR(r.out, "foo bar a b 1 f ( 2 )");
    CHECK_STR(r.diag, "");
    CHECK(find_tok(&r, "foo", 0)->flags & TF_NOEXPAND);
    done(&r);
}

static void runaway_expansion_is_an_error(void) {
    /* Each level doubles: 2^30 tokens if nothing stopped it. */
    char text[4096];
    size_t n = (size_t)snprintf(text, sizeof text, "#define a0 x x\n");
    for (int i = 1; i <= 29; i++) n += (size_t)snprintf(text + n, sizeof text - n, "#define a%d a%d a%d\n", i, i - 1, i - 1);
    snprintf(text + n, sizeof text - n, "y a29 z\nw");
    pp_run r;
    pp(&r, text);
    CHECK_STR(r.diag, "t.fx(31,3): error X1000: macro expansion produces more than 262144 tokens\n");
    CHECK_STR(r.toks->text, "y");
    hfx_token *t = r.toks;
    while (t->next && t->next->kind != TK_EOF) t = t->next;
    CHECK_STR(t->text, "w");
    done(&r);
}

/* Cubic hideset work (190-deep chains, nested arguments) hits the budget instead of taking minutes. */
static void expansion_work_is_bounded(void) {
    size_t cap = 1 << 20, n = 0;
    char *text = malloc(cap);
    for (int i = 0; i < 190; i++) n += (size_t)snprintf(text + n, cap - n, "#define g%d(x) g%d(x)\n", i, i + 1);
    n += (size_t)snprintf(text + n, cap - n, "#define g190(x) x\n");
    for (int i = 0; i < 2000; i++) n += (size_t)snprintf(text + n, cap - n, "g0(g0(g0(g0(g0(g0(1))))))\n");
    pp_run r;
    pp(&r, text);
    /* Which use of the first line runs out depends on the accounting: check the line and the text. */
    CHECK_INT(r.diags.count, 1);
    CHECK_INT(r.diags.items[0].line, 192);
    CHECK_INT(r.diags.items[0].code, 1000);
    CHECK_STR(r.diags.items[0].message, "macro expansion is too complex: the preprocessor's work limit is exceeded");
    /* Past the budget nothing expands: the last line comes out as written. */
    CHECK_CONTAINS(r.out, "g0 ( g0 ( g0 ( g0 ( g0 ( g0 ( 1 ) ) ) ) ) )");
    done(&r);
    free(text);
}

static void deep_expansion_is_an_error(void) {
    char text[16384];
    size_t n = 0;
    for (int i = 0; i < 300; i++) n += (size_t)snprintf(text + n, sizeof text - n, "#define m%d m%d\n", i, i + 1);
    snprintf(text + n, sizeof text - n, "#define m300 end\nm0;");
    pp_run r;
    pp(&r, text);
    CHECK_STR(r.diag, "t.fx(302,1): error X1000: macro expansion of 'm200' nested too deeply\n");
    CHECK_STR(r.out, "m200 ;");
    done(&r);
    /* Arguments nested in arguments. */
    n = (size_t)snprintf(text, sizeof text, "#define F(x) x\n");
    for (int i = 0; i < 300; i++) n += (size_t)snprintf(text + n, sizeof text - n, "F(");
    n += (size_t)snprintf(text + n, sizeof text - n, "1");
    for (int i = 0; i < 300; i++) n += (size_t)snprintf(text + n, sizeof text - n, ")");
    pp(&r, text);
    CHECK_STR(r.diag, "t.fx(2,401): error X1000: macro arguments of 'F' nested too deeply\n");
    done(&r);
}

static void macro_errors(void) {
    pp_run r;
    pp(&r, "#define\n#define 3\n#define F(a, a) a\n#define G(a) #b\n#define H ## x\n#define I(a b\n"
           "#define J(x) x\nJ(1, 2) J(\n");
    CHECK_STR(r.diag, "t.fx(1,2): error X1500: #define: macro name expected\n"
                      "t.fx(2,9): error X1500: #define: macro name expected\n"
                      "t.fx(3,14): error X1511: 'a' : duplicate macro parameter\n"
                      "t.fx(4,14): error X1500: '#' is not followed by a macro parameter\n"
                      "t.fx(5,11): error X1500: '##' cannot occur at either end of a macro expansion\n"
                      "t.fx(6,13): error X1500: expected ')' in macro parameter list\n"
                      "t.fx(8,1): error X1516: too many actual parameters for macro 'J'\n"
                      "t.fx(8,9): error X1515: unexpected end of file in macro expansion of 'J'\n");
    CHECK_STR(r.out, "1 J (");
    done(&r);
}

static void redefinition_warns_unless_identical(void) {
    pp_run r;
    pp(&r, "#define A 1 + 2\n#define A 1  +  2\n#define A 1+2\n#undef A\n#define A 3\nA");
    CHECK_STR(r.diag, "t.fx(3,9): warning X1519: 'A' : macro redefinition\n");
    CHECK_STR(r.out, "3");
    done(&r);
}

static void conditionals(void) {
    pp_run r;
    pp(&r, "#define ONE 1\n#if ONE\na\n#else\nb\n#endif\n"
           "#ifdef ONE\nc\n#endif\n#ifndef ONE\nd\n#elif 1\ne\n#else\nf\n#endif\n"
           "#if 0\n#if 1\ng\n#else\nh\n#endif\n#elif defined ONE && !defined(TWO)\ni\n#elif 1\nj\n#endif\n"
           "#if 0\n#bogus directive ' \" unmatched\n#error not reached\n#else\nk\n#endif\n");
    CHECK_STR(r.out, "a c e i k");
    /* An unterminated string in a skipped group is no error (prose in #if 0 is common). */
    CHECK_STR(r.diag, "");
    done(&r);
}

static void unterminated_strings_reported_when_used(void) {
    pp_run r;
    pp(&r, "#define S \"abc\nS S\nx = \"def;\n#include \"inc\n#error don\"t\n#if 0\n\"skipped\n#endif\n");
    CHECK_STR(r.diag, "t.fx(1,11): error X1005: newline in string literal\n"
                      "t.fx(3,5): error X1005: newline in string literal\n"
                      "t.fx(4,10): error X1005: newline in string literal\n"
                      "t.fx(5,1): error X1003: don\"t\n");
    CHECK_STR(r.out, "\"abc \"abc x = \"def;");
    done(&r);
}

static void if_expressions(void) {
    pp_run r;
    pp(&r, "#define X 5\n"
           "#if 1 + 2 * 3 == 7 && (1 + 2) * 3 == 9\na\n#endif\n"
           "#if 10 / 3 == 3 && 10 % 3 == 1 && -7 / 2 == -3 && -7 % 2 == -1\nb\n#endif\n"
           "#if (1 << 4) == 16 && (256 >> 4) == 16 && (-16 >> 2) == -4\nc\n#endif\n"
           "#if 0x10 == 16 && 010 == 8 && 10u == 10 && 7L == 7\nd\n#endif\n"
           "#if (6 & 3) == 2 && (6 | 3) == 7 && (6 ^ 3) == 5 && ~0 == -1\ne\n#endif\n"
           "#if -1 > 0u && !(-1 > 0) && X >= 5 && X <= 5 && X != 4 && !(X < 5) && !(X > 5)\nf\n#endif\n"
           "#if UNKNOWN == 0 && !UNKNOWN && (1 ? 2 : 3) == 2 && (0 ? 2 : 3) == 3\ng\n#endif\n"
           "#if 0 && 1 / 0 || 1 || 1 % 0\nh\n#endif\n"
           "#if (1, 0)\nno\n#endif\n"
           "#if defined X + defined(X) + defined Y == 2\ni\n#endif\n"
           "#define HAS_X defined(X)\n#define HAS(m) defined m\n#if HAS_X && !HAS(Y)\nj\n#endif\n");
    CHECK_STR(r.out, "a b c d e f g h i j");
    CHECK_STR(r.diag, "");
    done(&r);
}

static void if_expression_errors(void) {
    pp_run r;
    pp(&r, "#if 1 / 0\na\n#endif\n#if\n#endif\n#if (1\n#endif\n#if 1.0\n#endif\n#if 1 +\n#endif\n"
           "#if 2 3\n#endif\n#if defined(\n#endif\n#if 08\n#endif\nz\n");
    CHECK_STR(r.diag, "t.fx(1,7): error X1503: division by zero in preprocessor expression\n"
                      "t.fx(4,1): error X1518: #if with no expression\n"
                      "t.fx(6,1): error X1518: missing ')' in preprocessor expression\n"
                      "t.fx(8,5): error X1518: floating-point constant in preprocessor expression\n"
                      "t.fx(10,1): error X1518: expected a value in preprocessor expression\n"
                      "t.fx(12,7): error X1518: invalid integer constant expression\n"
                      "t.fx(14,1): error X1518: 'defined' expects an identifier\n"
                      "t.fx(16,5): error X1518: invalid integer constant in preprocessor expression\n");
    CHECK_STR(r.out, "z");
    done(&r);
}

static void deep_if_expression_is_an_error(void) {
    char text[4200];
    size_t n = (size_t)snprintf(text, sizeof text, "#if ");
    for (int i = 0; i < 2000; i++) text[n++] = '(';
    text[n++] = '1';
    for (int i = 0; i < 2000; i++) text[n++] = ')';
    snprintf(text + n, sizeof text - n, "\nno\n#endif\nyes");
    pp_run r;
    pp(&r, text);
    /* Each '(' nests two levels (conditional, then operand): the 129th goes past 256. */
    CHECK_STR(r.diag, "t.fx(1,133): error X1518: preprocessor expression nested too deeply\n");
    CHECK_STR(r.out, "yes");
    done(&r);
}

static void conditional_structure_errors(void) {
    pp_run r;
    pp(&r, "#endif\n#else\n#elif 1\n#if 1\na\n#else\nb\n#else\nc\n#endif\n#ifdef\n#endif\n  #if 1\nd\n");
    CHECK_STR(r.diag, "t.fx(1,1): error X1510: unexpected #endif\n"
                      "t.fx(2,1): error X1509: unexpected #else\n"
                      "t.fx(3,1): error X1508: unexpected #elif\n"
                      "t.fx(8,1): error X1514: #else after #else\n"
                      "t.fx(11,2): error X1500: #ifdef: identifier expected\n"
                      "t.fx(13,3): error X1502: unterminated '#if'\n");
    CHECK_STR(r.out, "a d");
    done(&r);
}

static void error_directive(void) {
    pp_run r;
    pp(&r, "float a;\n#error Shader model  \"3\" needed, sorry\n#if 0\n#error hidden\n#endif\nfloat b;\n");
    CHECK_STR(r.diag, "t.fx(2,1): error X1003: Shader model \"3\" needed, sorry\n");
    CHECK_STR(r.out, "float a ; float b ;");
    done(&r);
    /* found by fuzz/fuzz_compile.c: an #error without text gave an empty message */
    pp(&r, "#error\n#error  \n");
    CHECK_STR(r.diag, "t.fx(1,1): error X1003: #error\nt.fx(2,1): error X1003: #error\n");
    done(&r);
}

static void line_directive(void) {
    pp_run r;
    pp(&r, "a\n#line 100 \"other.fx\"\nb\n\nc __LINE__ __FILE__\n#line 7\nd\n#error here\n");
    CHECK_STR(r.out, "a b c 102 \"other.fx\" d");
    hfx_token *b = find_tok(&r, "b", 0), *c = find_tok(&r, "c", 0), *a = r.toks;
    CHECK_INT(a->loc.line, 1);
    CHECK_STR(r.diags.files[a->loc.file].name, "t.fx");
    CHECK_INT(b->loc.line, 100);
    CHECK_STR(r.diags.files[b->loc.file].name, "other.fx");
    CHECK_INT(c->loc.line, 102);
    CHECK_STR(r.diag, "other.fx(8,1): error X1003: here\n");
    done(&r);
    pp(&r, "#line 3 \"C:\\\\fx\\\\a \\\"b\\\".fx\"\n#error e\n");
    CHECK_STR(r.diag, "C:\\fx\\a \"b\".fx(3,1): error X1003: e\n");
    done(&r);
    pp(&r, "#line x\n#line 5 \"a\" junk\n");
    CHECK_STR(r.diag, "t.fx(1,7): error X1500: #line: expected a line number between 0 and 2147483647\n"
                      "t.fx(2,13): warning X1501: unexpected tokens following preprocessor directive - expected a newline\n");
    done(&r);
}

static void file_and_line_macros(void) {
    pp_run r;
    pp(&r, "#define L __LINE__\nint x = __LINE__;\n\n  L __FILE__\n#define F(a) a __LINE__\nF(\n1\n)");
    CHECK_STR(r.out, "int x = 2 ; 4 \"t.fx\" 1 6"); /* a multi-line use: the name's line */
    done(&r);
}

static void pragmas(void) {
    pp_run r;
    pp(&r, "#pragma pack_matrix(row_major)\nfloat4x4 m;\n#pragma pack_matrix( column_major )\n"
           "#pragma warning(disable : 3206)\n#pragma def(vs_2_0, c0, 1, 0, 0, 0)\n#pragma once\n"
           "#pragma message(\"hello\")\n#pragma foo bar\n#pragma pack_matrix(diagonal)\n#pragma\n");
    CHECK_STR(r.out, "__hfx_pack_matrix ( row_major ) float4x4 m ; __hfx_pack_matrix ( column_major )");
    CHECK_STR(r.diag, "t.fx(7,1): note: hello\n"
                      "t.fx(8,9): warning X3568: 'foo' : unknown pragma ignored\n"
                      "t.fx(9,9): warning X3568: 'pack_matrix' : expected (row_major) or (column_major), pragma ignored\n");
    hfx_token *t = r.toks;
    CHECK_INT(t->kind, TK_IDENT);
    CHECK_INT(t->loc.line, 1);
    CHECK_INT(t->loc.col, 9);
    done(&r);
}

static void bad_directives(void) {
    pp_run r;
    pp(&r, "#foo\n# \n#\n#undef\n#undef X Y\n#include\n#include <x\n#define X(a) a\n# 12\na # b\n");
    CHECK_STR(r.diag, "t.fx(1,2): error X1504: invalid preprocessor command 'foo'\n"
                      "t.fx(4,2): error X1500: #undef: identifier expected\n"
                      "t.fx(5,10): warning X1501: unexpected tokens following preprocessor directive - expected a newline\n"
                      "t.fx(6,1): error X1500: #include expects \"FILENAME\" or <FILENAME>\n"
                      "t.fx(7,10): error X1500: missing '>' in #include <file>\n"
                      "t.fx(9,3): error X1504: invalid preprocessor command '12'\n");
    CHECK_STR(r.out, "a # b");
    done(&r);
}

static void command_line_defines(void) {
    const char *defs[] = {"A", "B=2", "F(x)=x*B", "EMPTY="};
    hfx_pp_options opt = {defs, 4, NULL, 0, 0, NULL};
    pp_run r;
    pp_opts(&r, "A B F(3) [EMPTY]\n#if A + B == 3\nyes\n#endif", &opt);
    CHECK_STR(r.out, "1 2 3 * 2 [ ] yes");
    CHECK_STR(r.diag, "");
    done(&r);
}

static void directive_from_macro_is_not_a_directive(void) {
    pp_run r;
    pp(&r, "#define H #\n#define D define\nH D X 1\nX");
    CHECK_STR(r.out, "# define X 1 X");
    done(&r);
}

static void memory_text_need_not_be_terminated(void) {
    hfx_arena a;
    hfx_arena_init(&a);
    hfx_diags d;
    hfx_diags_init(&d, &a, 0);
    const char text[] = {'a', ' ', 'b', 'X', 'Y'};
    hfx_token *t = hfx_preprocess(&a, &d, "m.fx", text, 3, NULL);
    CHECK_STR(join_all(&a, t), "a b");
    CHECK_INT(d.count, 0);
    hfx_arena_free(&a);
}

static void missing_root_file(void) {
    hfx_arena a;
    hfx_arena_init(&a);
    hfx_diags d;
    hfx_diags_init(&d, &a, 0);
    hfx_token *t = hfx_preprocess(&a, &d, "/nonexistent/x.fx", NULL, 0, NULL);
    CHECK_INT(t->kind, TK_EOF);
    CHECK(t->next == NULL);
    char *s = hfx_diags_format(&d, 0);
    CHECK_STR(s, "/nonexistent/x.fx(1,1): error X1507: failed to open source file: '/nonexistent/x.fx'\n");
    free(s);
    hfx_arena_free(&a);
}

static void tokens_back_to_text(void) {
    pp_run r;
    pp(&r, "#define N 4\n#define NEG -N\n#define CAT(a, b) a b\nfloat a[N];\n\n\n  b = -NEG +CAT(x, y)-CAT(1,2);\n"
           "#line 90 \"other.fx\"\nc\n");
    char *text = hfx_tokens_to_text(&r.diags, r.toks);
    CHECK_STR(text, "\n\n\nfloat a[4];\n\n\nb = - -4 +x y-1 2;\n#line 90 \"other.fx\"\nc\n");
    free(text);
    done(&r);
}

/* 100 000 lines with a macro use, a conditional and a comment on each: all expanded, nothing lost. */
static void hundred_thousand_lines(void) {
    enum { LINES = 100000 };
    const char *head = "#define SCALE(x) ((x) * 2.0f)\n#define N 3\n";
    const char *line = "float v = SCALE(N); /* c */\n#if N > 2\nv;\n#endif\n";
    size_t hn = strlen(head), ln = strlen(line);
    char *text = malloc(hn + ln * LINES + 1);
    memcpy(text, head, hn);
    for (int i = 0; i < LINES; i++) memcpy(text + hn + ln * (size_t)i, line, ln);
    text[hn + ln * LINES] = 0;
    pp_run r;
    hfx_arena_init(&r.arena);
    hfx_diags_init(&r.diags, &r.arena, 0);
    r.toks = hfx_preprocess(&r.arena, &r.diags, "big.fx", text, (uint32_t)(hn + ln * LINES), NULL);
    free(text);
    /* float v = ( ( 3 ) * 2.0f ) ; v ; is 13 tokens a line */
    size_t count = 0;
    hfx_token *last = NULL;
    for (hfx_token *t = r.toks; t->kind != TK_EOF; t = t->next) { count++; last = t; }
    CHECK_INT(count, 13 * (size_t)LINES);
    CHECK_INT(r.diags.count, 0);
    CHECK_STR(last->text, ";");
    CHECK_INT(last->loc.line, 2 + 4 * LINES - 1);
    CHECK_INT(last->loc.col, 2);
    done(&r);
}

int main(void) {
    RUN(object_like_macro_loc_is_use_site);
    RUN(function_like_macros);
    RUN(c_standard_example_expansion);
    RUN(c_standard_example_stringize_paste);
    RUN(stringize_spacing);
    RUN(xna_style_macros);
    RUN(pasting);
    RUN(variadic_macros);
    RUN(recursion_guard);
    RUN(runaway_expansion_is_an_error);
    RUN(deep_expansion_is_an_error);
    RUN(expansion_work_is_bounded);
    RUN(macro_errors);
    RUN(redefinition_warns_unless_identical);
    RUN(conditionals);
    RUN(unterminated_strings_reported_when_used);
    RUN(if_expressions);
    RUN(if_expression_errors);
    RUN(conditional_structure_errors);
    RUN(deep_if_expression_is_an_error);
    RUN(error_directive);
    RUN(line_directive);
    RUN(file_and_line_macros);
    RUN(pragmas);
    RUN(bad_directives);
    RUN(command_line_defines);
    RUN(directive_from_macro_is_not_a_directive);
    RUN(memory_text_need_not_be_terminated);
    RUN(missing_root_file);
    RUN(tokens_back_to_text);
    RUN(hundred_thousand_lines);
    return test_summary();
}
