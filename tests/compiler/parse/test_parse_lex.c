/* hfx_parse_lex's identifier classification: every keyword, interpolation modifier, effect-layer
 * keyword and builtin type name gives its exact Bison code and value, and near misses (other
 * case, truncated, extended, out-of-range sizes) stay plain identifiers. The expectations are
 * written out here, independent of keywords.c's tables. */
#include <stdio.h>
#include <string.h>

#include "parse/keywords.h"
#include "parser.h"
#include "test.h"
#include "pp/token.h"
#include "base/types.h"

typedef struct lex_run {
    hfx_arena arena;
    hfx_diags diags;
    hfx_types *types;
    parse_ctx ctx;
} lex_run;

static void lex_open(lex_run *r, const char *text) {
    hfx_arena_init(&r->arena);
    hfx_diags_init(&r->diags, &r->arena, 0);
    r->types = hfx_types_new(&r->arena);
    hfx_token *toks = hfx_tokenize_text(&r->arena, &r->diags, text, (uint32_t)strlen(text), (hfx_loc){0, 1, 1});
    CHECK(hfx_parse_ctx_init(&r->ctx, &r->arena, &r->diags, r->types, toks));
}

static int lex_next(lex_run *r, parse_tok *tok) {
    HFX_YYSTYPE v;
    hfx_loc loc;
    int code = hfx_parse_lex(&v, &loc, &r->ctx);
    *tok = v.tok;
    return code;
}

static void lex_close(lex_run *r) { hfx_arena_free(&r->arena); }

/* The code of the first token of `text`; its mods and type through the pointers. */
static int first_code(const char *text, uint32_t *mods) {
    lex_run r;
    lex_open(&r, text);
    parse_tok tok;
    int code = lex_next(&r, &tok);
    if (mods) *mods = tok.mods;
    lex_close(&r);
    return code;
}

#define EXPECT_CODE(text, code) do { \
    int got_ = first_code(text, NULL); \
    if (got_ != (code)) fprintf(stderr, "  for \"%s\"\n", text); \
    CHECK_INT(got_, code); } while (0)

typedef struct expected_keyword {
    const char *name;
    int code;
    uint32_t mods;
} expected_keyword;

static const expected_keyword keywords[] = {
    {"NULL", NULL_KW, 0}, {"break", BREAK, 0}, {"case", CASE, 0}, {"column_major", MODIFIER, MOD_COLUMN_MAJOR},
    {"compile", COMPILE, 0}, {"const", MODIFIER, MOD_CONST}, {"continue", CONTINUE, 0}, {"default", DEFAULT, 0},
    {"discard", DISCARD, 0}, {"do", DO, 0}, {"else", ELSE, 0}, {"extern", MODIFIER, MOD_EXTERN},
    {"false", FALSE_KW, 0}, {"for", FOR, 0}, {"groupshared", MODIFIER, MOD_GROUPSHARED}, {"if", IF, 0},
    {"in", MODIFIER, MOD_IN}, {"inline", MODIFIER, MOD_INLINE}, {"inout", MODIFIER, MOD_IN | MOD_OUT},
    {"matrix", MATRIX, 0}, {"out", MODIFIER, MOD_OUT}, {"pass", PASS, 0}, {"precise", MODIFIER, MOD_PRECISE},
    {"register", REGISTER, 0}, {"return", RETURN, 0}, {"row_major", MODIFIER, MOD_ROW_MAJOR},
    {"sampler_state", SAMPLER_STATE, 0}, {"shared", MODIFIER, MOD_SHARED}, {"static", MODIFIER, MOD_STATIC},
    {"struct", STRUCT, 0}, {"switch", SWITCH, 0}, {"technique", TECHNIQUE, 0}, {"technique10", TECHNIQUE, 0},
    {"technique11", TECHNIQUE, 0}, {"true", TRUE_KW, 0}, {"typedef", TYPEDEF, 0},
    {"uniform", MODIFIER, MOD_UNIFORM}, {"vector", VECTOR, 0}, {"volatile", MODIFIER, MOD_VOLATILE},
    {"while", WHILE, 0},
};
enum { KEYWORD_COUNT = sizeof keywords / sizeof *keywords };

static void every_keyword(void) {
    CHECK_INT(KEYWORD_COUNT, 40);
    for (int i = 0; i < KEYWORD_COUNT; i++) {
        char text[64];
        snprintf(text, sizeof text, "%s ;", keywords[i].name);
        uint32_t mods = 0;
        int code = first_code(text, &mods);
        if (code != keywords[i].code || mods != keywords[i].mods) fprintf(stderr, "  for \"%s\"\n", text);
        CHECK_INT(code, keywords[i].code);
        CHECK_INT(mods, keywords[i].mods);
    }
}

/* Keywords are case-sensitive; `;` after them keeps the any-case effect words names too. */
static void keyword_near_misses(void) {
    for (int i = 0; i < KEYWORD_COUNT; i++) {
        const char *name = keywords[i].name;
        size_t n = strlen(name);
        char text[64];
        snprintf(text, sizeof text, "%s ;", name);
        text[0] = (char)(text[0] ^ 0x20); /* NULL -> nULL, break -> Break */
        EXPECT_CODE(text, IDENT);
        snprintf(text, sizeof text, "%.*s ;", (int)(n - 1), name);
        EXPECT_CODE(text, IDENT);
        snprintf(text, sizeof text, "%s_ ;", name);
        EXPECT_CODE(text, IDENT);
        snprintf(text, sizeof text, "%s1 ;", name);
        EXPECT_CODE(text, IDENT);
        snprintf(text, sizeof text, "x%s ;", name);
        EXPECT_CODE(text, IDENT);
    }
    EXPECT_CODE("null ;", IDENT);
    EXPECT_CODE("Technique10 ;", IDENT);
    EXPECT_CODE("technique12 ;", IDENT);
    EXPECT_CODE("technique1 {", IDENT);
}

/* Interpolation modifiers are keywords only before a type or another modifier. */
static void interpolation_modifiers(void) {
    static const expected_keyword interp[] = {
        {"centroid", MODIFIER, MOD_CENTROID}, {"linear", MODIFIER, MOD_LINEAR},
        {"nointerpolation", MODIFIER, MOD_NOINTERPOLATION}, {"noperspective", MODIFIER, MOD_NOPERSPECTIVE},
        {"sample", MODIFIER, MOD_SAMPLE},
    };
    static const char *const followers[] = {"float4 x;", "const float x;", "struct S", "centroid float x;",
                                             "Texture2D t;", "half3x3 m;", "vector v;"};
    for (size_t i = 0; i < sizeof interp / sizeof *interp; i++) {
        char text[96];
        for (size_t f = 0; f < sizeof followers / sizeof *followers; f++) {
            snprintf(text, sizeof text, "%s %s", interp[i].name, followers[f]);
            uint32_t mods = 0;
            int code = first_code(text, &mods);
            if (code != MODIFIER) fprintf(stderr, "  for \"%s\"\n", text);
            CHECK_INT(code, MODIFIER);
            CHECK_INT(mods, interp[i].mods);
        }
        snprintf(text, sizeof text, "%s ;", interp[i].name);
        EXPECT_CODE(text, IDENT);
        snprintf(text, sizeof text, "%s = x;", interp[i].name);
        EXPECT_CODE(text, IDENT);
        snprintf(text, sizeof text, "%s x;", interp[i].name);
        EXPECT_CODE(text, IDENT);
        snprintf(text, sizeof text, "%s float x;", interp[i].name);
        text[0] = (char)(text[0] ^ 0x20);
        EXPECT_CODE(text, IDENT);
    }
}

/* technique / pass / sampler_state / compile in another case start their construct only. */
static void effect_keywords_in_any_case(void) {
    EXPECT_CODE("Technique T {", TECHNIQUE);
    EXPECT_CODE("TECHNIQUE {", TECHNIQUE);
    EXPECT_CODE("TechNique <", TECHNIQUE);
    EXPECT_CODE("Technique10 T", TECHNIQUE);
    EXPECT_CODE("TECHNIQUE11 {", TECHNIQUE);
    EXPECT_CODE("Technique ;", IDENT);
    EXPECT_CODE("Technique = 1;", IDENT);
    EXPECT_CODE("Pass P0 {", PASS);
    EXPECT_CODE("PASS {", PASS);
    EXPECT_CODE("Pass = 1;", IDENT);
    EXPECT_CODE("Sampler_State {", SAMPLER_STATE);
    EXPECT_CODE("SAMPLER_STATE {", SAMPLER_STATE);
    EXPECT_CODE("Sampler_State x", IDENT);
    EXPECT_CODE("Compile vs_2_0 main", COMPILE);
    EXPECT_CODE("COMPILE ps_3_0 ps", COMPILE);
    EXPECT_CODE("Compile vs_2_0 ;", IDENT);
    EXPECT_CODE("Compil vs_2_0 main", IDENT);
    EXPECT_CODE("Passe P0 {", IDENT);

    /* `pass Pass {` and `technique Technique {`: the second word is the name */
    static const char *const named[] = {"pass Pass {", "technique Technique {", "Pass PASS {"};
    for (size_t i = 0; i < sizeof named / sizeof *named; i++) {
        lex_run r;
        lex_open(&r, named[i]);
        parse_tok tok;
        int first = lex_next(&r, &tok);
        CHECK(first == PASS || first == TECHNIQUE);
        CHECK_INT(lex_next(&r, &tok), IDENT);
        lex_close(&r);
    }
}

static int expect_type(const char *spelling, const hfx_type *(*make)(hfx_types *, const void *), const void *arg) {
    lex_run r;
    char text[64];
    snprintf(text, sizeof text, "%s x;", spelling);
    lex_open(&r, text);
    parse_tok tok;
    int code = lex_next(&r, &tok);
    int ok = code == TYPE_NAME && tok.type == make(r.types, arg) && tok.entry == NULL;
    if (!ok) fprintf(stderr, "  \"%s\" is %d, not the expected type\n", spelling, code);
    lex_close(&r);
    return ok;
}

typedef struct numeric_spec {
    hfx_base base;
    unsigned rows, cols; /* 0 rows: a scalar (cols 0) or vector */
} numeric_spec;

static const hfx_type *make_numeric(hfx_types *types, const void *arg) {
    const numeric_spec *n = arg;
    if (n->rows) return hfx_type_matrix(types, n->base, n->rows, n->cols);
    if (n->cols) return hfx_type_vector(types, n->base, n->cols);
    return hfx_type_scalar(types, n->base);
}

static const struct { const char *name; hfx_base base; bool vectors; } scalars[] = {
    {"bool", B_BOOL, true}, {"int", B_INT, true}, {"uint", B_UINT, true}, {"dword", B_UINT, false},
    {"DWORD", B_UINT, false}, {"half", B_HALF, true}, {"float", B_FLOAT, true}, {"double", B_DOUBLE, true},
    {"min16float", B_MIN16FLOAT, true}, {"min10float", B_MIN16FLOAT, true}, {"min16int", B_INT, true},
    {"min12int", B_INT, true}, {"min16uint", B_UINT, true},
};

/* `spelling x;` lexes to a plain identifier first. */
static void expect_ident(const char *spelling) {
    char text[80];
    snprintf(text, sizeof text, "%s x;", spelling);
    EXPECT_CODE(text, IDENT);
}

/* Every scalar, vector and matrix spelling (1..4 by 1..4), and none other. */
static void numeric_types(void) {
    for (size_t i = 0; i < sizeof scalars / sizeof *scalars; i++) {
        const char *name = scalars[i].name;
        bool vectors = scalars[i].vectors;
        numeric_spec spec = {scalars[i].base, 0, 0};
        CHECK(expect_type(name, make_numeric, &spec));
        char s[64];
        for (unsigned r = 0; r <= 9; r++) {
            snprintf(s, sizeof s, "%s%u", name, r);
            spec = (numeric_spec){scalars[i].base, 0, r};
            if (vectors && r >= 1 && r <= 4) CHECK(expect_type(s, make_numeric, &spec));
            else expect_ident(s);
            for (unsigned c = 0; c <= 9; c++) {
                snprintf(s, sizeof s, "%s%ux%u", name, r, c);
                spec = (numeric_spec){scalars[i].base, r, c};
                if (vectors && r >= 1 && r <= 4 && c >= 1 && c <= 4) CHECK(expect_type(s, make_numeric, &spec));
                else expect_ident(s);
                snprintf(s, sizeof s, "%s%uX%u", name, r, c);
                expect_ident(s);
                snprintf(s, sizeof s, "%s%u%u", name, r, c);
                expect_ident(s);
            }
        }
    }
}

static void numeric_near_misses(void) {
    static const char *const misses[] = {
        "Float x;", "FLOAT4 x;", "Half3 x;", "Dword x;", "dWORD x;", "float4x x;", "floatx4 x;", "float4x4x4 x;",
        "float4x41 x;", "float_4 x;", "float4_ x;", "floa x;", "flo4 x;", "loat4 x;", "min16 x;", "min16floa x;",
        "min16float4x x;", "min8float x;", "min16uint4X4 x;", "in4 x;", "int4x4_ x;", "xfloat x;", "x4 x;",
        "float0 x;", "dword4 x;", "DWORD2x2 x;", "intx4 x;", "bool4x4y x;",
    };
    for (size_t i = 0; i < sizeof misses / sizeof *misses; i++) EXPECT_CODE(misses[i], IDENT);
}

typedef struct object_spec {
    hfx_type_kind kind;
    hfx_dim dim;
} object_spec;

static const hfx_type *make_object(hfx_types *types, const void *arg) {
    const object_spec *o = arg;
    return hfx_type_object(types, o->kind, o->dim);
}

static const hfx_type *make_void(hfx_types *types, const void *arg) {
    (void)arg;
    return hfx_type_void(types);
}

static char upper(char c) { return c >= 'a' && c <= 'z' ? (char)(c - 'a' + 'A') : c; }

/* Object type names in any case; void and string in lower case only. */
static void object_types(void) {
    static const struct { const char *name; object_spec o; } objects[] = {
        {"texture", {TY_TEXTURE, DIM_GENERIC}}, {"texture1d", {TY_TEXTURE, DIM_1D}},
        {"texture2d", {TY_TEXTURE, DIM_2D}}, {"texture3d", {TY_TEXTURE, DIM_3D}},
        {"texturecube", {TY_TEXTURE, DIM_CUBE}}, {"sampler", {TY_SAMPLER, DIM_GENERIC}},
        {"sampler1d", {TY_SAMPLER, DIM_1D}}, {"sampler2d", {TY_SAMPLER, DIM_2D}},
        {"sampler3d", {TY_SAMPLER, DIM_3D}}, {"samplercube", {TY_SAMPLER, DIM_CUBE}},
        {"samplerstate", {TY_SAMPLER, DIM_GENERIC}}, {"samplercomparisonstate", {TY_SAMPLER, DIM_GENERIC}},
        {"vertexshader", {TY_VERTEXSHADER, DIM_GENERIC}}, {"pixelshader", {TY_PIXELSHADER, DIM_GENERIC}},
    };
    for (size_t i = 0; i < sizeof objects / sizeof *objects; i++) {
        char name[64];
        size_t n = strlen(objects[i].name);
        CHECK(expect_type(objects[i].name, make_object, &objects[i].o));
        for (size_t k = 0; k <= n; k++) name[k] = upper(objects[i].name[k]);
        CHECK(expect_type(name, make_object, &objects[i].o)); /* TEXTURE2D */
        for (size_t k = 0; k < n; k++) { /* one letter capitalised at a time: Texture2D, textureCube */
            memcpy(name, objects[i].name, n + 1);
            name[k] = upper(name[k]);
            CHECK(expect_type(name, make_object, &objects[i].o));
        }
        char text[80];
        snprintf(text, sizeof text, "%.*s x;", (int)(n - 1), objects[i].name);
        EXPECT_CODE(text, IDENT);
        snprintf(text, sizeof text, "%s_ x;", objects[i].name);
        EXPECT_CODE(text, IDENT);
        snprintf(text, sizeof text, "%s4 x;", objects[i].name);
        EXPECT_CODE(text, IDENT);
    }
    static const char *const misses[] = {"texture4d x;", "texture2 x;", "texture_2d x;", "sampler_2d x;",
                                         "Texture2DArray x;", "samplerstates x;", "vertexshaders x;",
                                         "Void x;", "VOID x;", "STRING x;", "strin x;", "voi x;"};
    for (size_t i = 0; i < sizeof misses / sizeof *misses; i++) EXPECT_CODE(misses[i], IDENT);
    CHECK(expect_type("void", make_void, NULL));
    object_spec str = {TY_STRING, DIM_GENERIC};
    CHECK(expect_type("string", make_object, &str));
    CHECK(expect_type("String", make_object, &str)); /* fxc takes both spellings (issue 30) */
}

/* In a state block a type's spelling names a state (`VertexShader = ...`), except as a
 * constructor. */
static void types_inside_state_blocks(void) {
    lex_run r;
    lex_open(&r, "pass P { VertexShader = float4(1, 2, 3, 4); }");
    parse_tok tok;
    static const int codes[] = {PASS, IDENT, '{', IDENT, '=', TYPE_NAME, '('};
    for (size_t i = 0; i < sizeof codes / sizeof *codes; i++) CHECK_INT(lex_next(&r, &tok), codes[i]);
    lex_close(&r);
}

static void asm_blocks_and_pack_matrix(void) {
    EXPECT_CODE("asm { mov r0, c0 }", ASM_BLOCK);
    EXPECT_CODE("ASM { mov r0, c0 }", ASM_BLOCK);
    EXPECT_CODE("Asm { }", ASM_BLOCK);
    EXPECT_CODE("asm ;", IDENT);
    EXPECT_CODE("asmx { }", IDENT);
    EXPECT_CODE("as { }", IDENT);

    lex_run r;
    lex_open(&r, "__hfx_pack_matrix ( row_major ) float4x4 m;");
    parse_tok tok;
    CHECK_INT(lex_next(&r, &tok), TYPE_NAME);
    CHECK_INT(r.ctx.pack_mods, MOD_ROW_MAJOR);
    lex_close(&r);
    EXPECT_CODE("__hfx_pack_matri ( row_major )", IDENT);
}

/* hfx_kw_lookup reads only `len` bytes: hfx_parse_lex hands it token spellings by length. */
static void lookup_respects_length(void) {
    kw_word w;
    hfx_kw_lookup("float4x4abc", 6, &w);
    CHECK_INT(w.form, KW_TYPE_VECTOR);
    CHECK_INT(w.cols, 4);
    hfx_kw_lookup("inout", 2, &w);
    CHECK_INT(w.keyword, MODIFIER);
    CHECK_INT(w.mods, MOD_IN);
    hfx_kw_lookup("", 0, &w);
    CHECK_INT(w.form, KW_TYPE_NONE);
    CHECK_INT(w.keyword, 0);
}

int main(void) {
    RUN(every_keyword);
    RUN(keyword_near_misses);
    RUN(interpolation_modifiers);
    RUN(effect_keywords_in_any_case);
    RUN(numeric_types);
    RUN(numeric_near_misses);
    RUN(object_types);
    RUN(types_inside_state_blocks);
    RUN(asm_blocks_and_pack_matrix);
    RUN(lookup_respects_length);
    return test_summary();
}
