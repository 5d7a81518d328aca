/* keywords.c: the spelling tables behind hfx_kw_lookup (keywords.h). Every identifier of a file
 * goes through here, most of them user names, so the tables are grouped by first letter (in
 * lower case) and each entry carries its length: a lookup checks the lengths of the few words
 * of its letter and compares spellings only when one fits. Numeric type names are not listed
 * in all their forms: `float3x4` is read as `float` plus a size suffix. */
#include <string.h>

#include "parse/keywords.h"
#include "parser.h"

typedef enum {
    E_KEYWORD,          /* exact spelling */
    E_INTERP,           /* exact spelling */
    E_ANY_CASE_KEYWORD, /* name in lower case, matched in any case */
    E_VOID,
    E_STRING,
    E_SCALAR,           /* has the vector and matrix forms (float3, float3x4) */
    E_SCALAR_ONLY,      /* dword has none */
    E_OBJECT            /* name in lower case, matched in any case */
} entry_what;

typedef struct entry {
    const char *name;
    uint8_t len;
    entry_what what;
    int code;
    uint32_t mods;
    hfx_base base;
    hfx_type_kind kind;
    hfx_dim dim;
} entry;

#define KEYWORD(n, c) {n, sizeof n - 1, E_KEYWORD, .code = c}
#define MODIFIER_KW(n, m) {n, sizeof n - 1, E_KEYWORD, .code = MODIFIER, .mods = m}
#define INTERP(n, m) {n, sizeof n - 1, E_INTERP, .mods = m}
#define ANY_CASE(n, c) {n, sizeof n - 1, E_ANY_CASE_KEYWORD, .code = c}
#define SCALAR(n, b) {n, sizeof n - 1, E_SCALAR, .base = b}
#define SCALAR_ONLY(n, b) {n, sizeof n - 1, E_SCALAR_ONLY, .base = b}
#define OBJECT(n, k, d) {n, sizeof n - 1, E_OBJECT, .kind = k, .dim = d}
#define TYPE(n, what) {n, sizeof n - 1, what, .code = 0}

/* Each word is filed under its first letter in lower case (NULL under n, DWORD under d): one
 * under another letter would never be found, which test_parse_lex would see. A spelling may
 * match several entries (`technique` is a keyword and, in any case, an effect-layer word);
 * hfx_kw_lookup applies them all. */
/* Direct3D 10 state objects (`BlendState b { ... };`) are any-case words that start a global. */
static const entry b_words[] = {KEYWORD("break", BREAK), SCALAR("bool", B_BOOL), ANY_CASE("blendstate", D3D10_STATE)};
static const entry c_words[] = {
    KEYWORD("case", CASE), KEYWORD("cbuffer", CBUFFER), INTERP("centroid", MOD_CENTROID), MODIFIER_KW("column_major", MOD_COLUMN_MAJOR),
    KEYWORD("compile", COMPILE), ANY_CASE("compile", COMPILE), MODIFIER_KW("const", MOD_CONST),
    KEYWORD("continue", CONTINUE),
};
static const entry d_words[] = {
    ANY_CASE("depthstencilstate", D3D10_STATE), KEYWORD("default", DEFAULT), KEYWORD("discard", DISCARD), KEYWORD("do", DO), SCALAR("double", B_DOUBLE),
    SCALAR_ONLY("dword", B_UINT), SCALAR_ONLY("DWORD", B_UINT),
};
/* `export` marks a library function (fx_2_0 takes it and it changes nothing): a modifier of no bits */
static const entry e_words[] = {KEYWORD("else", ELSE), MODIFIER_KW("export", 0), MODIFIER_KW("extern", MOD_EXTERN)};
static const entry f_words[] = {
    KEYWORD("false", FALSE_KW), SCALAR("float", B_FLOAT), KEYWORD("for", FOR), ANY_CASE("fxgroup", FXGROUP),
};
static const entry g_words[] = {MODIFIER_KW("groupshared", MOD_GROUPSHARED)};
static const entry h_words[] = {SCALAR("half", B_HALF)};
static const entry i_words[] = {
    KEYWORD("if", IF), MODIFIER_KW("in", MOD_IN), MODIFIER_KW("inline", MOD_INLINE),
    MODIFIER_KW("inout", MOD_IN | MOD_OUT), SCALAR("int", B_INT),
};
static const entry l_words[] = {INTERP("linear", MOD_LINEAR)};
static const entry m_words[] = {
    KEYWORD("matrix", MATRIX), SCALAR("min10float", B_MIN16FLOAT), SCALAR("min12int", B_INT),
    SCALAR("min16float", B_MIN16FLOAT), SCALAR("min16int", B_INT), SCALAR("min16uint", B_UINT),
};
static const entry n_words[] = {
    KEYWORD("NULL", NULL_KW), INTERP("nointerpolation", MOD_NOINTERPOLATION),
    INTERP("noperspective", MOD_NOPERSPECTIVE),
};
static const entry o_words[] = {MODIFIER_KW("out", MOD_OUT)};
static const entry p_words[] = {
    KEYWORD("pass", PASS), ANY_CASE("pass", PASS), OBJECT("pixelshader", TY_PIXELSHADER, DIM_GENERIC),
    MODIFIER_KW("precise", MOD_PRECISE),
};
static const entry r_words[] = {
    ANY_CASE("rasterizerstate", D3D10_STATE), KEYWORD("register", REGISTER), KEYWORD("return", RETURN), MODIFIER_KW("row_major", MOD_ROW_MAJOR),
};
static const entry s_words[] = {
    INTERP("sample", MOD_SAMPLE), OBJECT("sampler", TY_SAMPLER, DIM_GENERIC),
    OBJECT("sampler1d", TY_SAMPLER, DIM_1D), OBJECT("sampler2d", TY_SAMPLER, DIM_2D),
    OBJECT("sampler3d", TY_SAMPLER, DIM_3D), OBJECT("samplercomparisonstate", TY_SAMPLER, DIM_GENERIC),
    OBJECT("samplercube", TY_SAMPLER, DIM_CUBE), OBJECT("samplerstate", TY_SAMPLER, DIM_GENERIC),
    KEYWORD("sampler_state", SAMPLER_STATE), ANY_CASE("sampler_state", SAMPLER_STATE),
    MODIFIER_KW("shared", MOD_SHARED), MODIFIER_KW("static", MOD_STATIC), TYPE("string", E_STRING), TYPE("String", E_STRING),
    KEYWORD("struct", STRUCT), KEYWORD("switch", SWITCH),
};
static const entry t_words[] = {
    KEYWORD("tbuffer", CBUFFER), KEYWORD("technique", TECHNIQUE), ANY_CASE("technique", TECHNIQUE), KEYWORD("technique10", TECHNIQUE),
    ANY_CASE("technique10", TECHNIQUE), KEYWORD("technique11", TECHNIQUE), ANY_CASE("technique11", TECHNIQUE),
    OBJECT("texture", TY_TEXTURE, DIM_GENERIC), OBJECT("texture1d", TY_TEXTURE, DIM_1D),
    OBJECT("texture2d", TY_TEXTURE, DIM_2D), OBJECT("texture3d", TY_TEXTURE, DIM_3D),
    OBJECT("texturecube", TY_TEXTURE, DIM_CUBE), KEYWORD("true", TRUE_KW), KEYWORD("typedef", TYPEDEF),
};
static const entry u_words[] = {SCALAR("uint", B_UINT), MODIFIER_KW("uniform", MOD_UNIFORM), KEYWORD("unsigned", UNSIGNED)};
static const entry v_words[] = {
    KEYWORD("vector", VECTOR), OBJECT("vertexshader", TY_VERTEXSHADER, DIM_GENERIC), TYPE("void", E_VOID),
    MODIFIER_KW("volatile", MOD_VOLATILE),
};
static const entry w_words[] = {KEYWORD("while", WHILE)};

typedef struct entry_list {
    const entry *items;
    uint32_t count;
} entry_list;

#define LIST(a) {a, sizeof a / sizeof *a}
static const entry_list by_letter[26] = {
    ['b' - 'a'] = LIST(b_words), ['c' - 'a'] = LIST(c_words), ['d' - 'a'] = LIST(d_words),
    ['e' - 'a'] = LIST(e_words), ['f' - 'a'] = LIST(f_words), ['g' - 'a'] = LIST(g_words),
    ['h' - 'a'] = LIST(h_words), ['i' - 'a'] = LIST(i_words), ['l' - 'a'] = LIST(l_words),
    ['m' - 'a'] = LIST(m_words), ['n' - 'a'] = LIST(n_words), ['o' - 'a'] = LIST(o_words),
    ['p' - 'a'] = LIST(p_words), ['r' - 'a'] = LIST(r_words), ['s' - 'a'] = LIST(s_words),
    ['t' - 'a'] = LIST(t_words), ['u' - 'a'] = LIST(u_words), ['v' - 'a'] = LIST(v_words),
    ['w' - 'a'] = LIST(w_words),
};

/* ASCII only, as strcasecmp in the C locale: other bytes stay as they are. */
static char fold(char c) { return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c; }

static bool same_any_case(const char *s, const char *lower, uint32_t len) {
    for (uint32_t i = 0; i < len; i++)
        if (fold(s[i]) != lower[i]) return false;
    return true;
}

static bool same_exact(const char *s, const char *name, uint32_t len) {
    for (uint32_t i = 0; i < len; i++)
        if (s[i] != name[i]) return false;
    return true;
}

/* e->len == len is the caller's test: inline in its loop, it rejects most entries at once. */
static bool matches(const entry *e, const char *s, uint32_t len) {
    if (e->what == E_ANY_CASE_KEYWORD || e->what == E_OBJECT) return same_any_case(s, e->name, len);
    return same_exact(s, e->name, len);
}

/* The words that may match s: those filed under its first letter in lower case. */
static entry_list words_for(const char *s, uint32_t len) {
    char c = len ? fold(s[0]) : 0;
    if (c < 'a' || c > 'z') return (entry_list){NULL, 0};
    return by_letter[c - 'a'];
}

static void apply(const entry *e, kw_word *w) {
    switch (e->what) {
    case E_KEYWORD: w->keyword = e->code; w->mods = e->mods; break;
    case E_INTERP: w->interp = true; w->mods = e->mods; break;
    case E_ANY_CASE_KEYWORD: w->any_case_keyword = e->code; break;
    case E_VOID: w->form = KW_TYPE_VOID; break;
    case E_STRING: w->form = KW_TYPE_STRING; break;
    case E_SCALAR:
    case E_SCALAR_ONLY: w->form = KW_TYPE_SCALAR; w->base = e->base; break;
    case E_OBJECT: w->form = KW_TYPE_OBJECT; w->kind = e->kind; w->dim = e->dim; break;
    }
}

static bool is_size(char c) { return c >= '1' && c <= '4'; }

/* The base of `float3` or `float3x4`: a scalar type name that has vector and matrix forms. */
static const entry *vector_base(const char *s, uint32_t len) {
    entry_list l = words_for(s, len);
    for (uint32_t i = 0; i < l.count; i++)
        if (l.items[i].len == len && l.items[i].what == E_SCALAR && matches(&l.items[i], s, len)) return &l.items[i];
    return NULL;
}

/* `float3` and `float3x4`: no scalar type name ends in a digit or in 'x', so the suffix
 * splits off unambiguously. */
static void numeric_form(const char *s, uint32_t len, kw_word *w) {
    if (len < 2 || !is_size(s[len - 1])) return;
    bool matrix = len >= 4 && s[len - 2] == 'x' && is_size(s[len - 3]);
    const entry *e = vector_base(s, matrix ? len - 3 : len - 1);
    if (!e) return;
    w->form = matrix ? KW_TYPE_MATRIX : KW_TYPE_VECTOR;
    w->base = e->base;
    w->rows = matrix ? (uint8_t)(s[len - 3] - '0') : 1;
    w->cols = (uint8_t)(s[len - 1] - '0');
}

void hfx_kw_lookup(const char *s, uint32_t len, kw_word *w) {
    memset(w, 0, sizeof *w);
    entry_list l = words_for(s, len);
    for (uint32_t i = 0; i < l.count; i++)
        if (l.items[i].len == len && matches(&l.items[i], s, len)) apply(&l.items[i], w);
    if (w->form == KW_TYPE_NONE) numeric_form(s, len, w);
}

const hfx_type *hfx_kw_builtin_type(hfx_types *types, const kw_word *w) {
    switch (w->form) {
    case KW_TYPE_VOID: return hfx_type_void(types);
    case KW_TYPE_STRING: return hfx_type_object(types, TY_STRING, DIM_GENERIC);
    case KW_TYPE_SCALAR: return hfx_type_scalar(types, w->base);
    case KW_TYPE_VECTOR: return hfx_type_vector(types, w->base, w->cols);
    case KW_TYPE_MATRIX: return hfx_type_matrix(types, w->base, w->rows, w->cols);
    case KW_TYPE_OBJECT: return hfx_type_object(types, w->kind, w->dim);
    case KW_TYPE_NONE: break;
    }
    return NULL;
}
