/* parse_lex.c: turns the preprocessed hfx_token list into Bison tokens. The lexer knows no
 * keywords, so they are decided here, as are type names: builtin ones by spelling
 * (float4x3, Texture2D...), user ones (struct and typedef names) from a scope table fed while
 * tokens go by (the classic C "lexer hack"; tokens come from a list, so peeking is free).
 * Also here: bracket nesting limits and the X3000 syntax error messages. */
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "parser.h"

/* ---- keyword tables ---- */

typedef struct keyword {
    const char *name;
    int code;
    uint32_t mods;
} keyword;

static const keyword keywords[] = {
    {"NULL", NULL_KW, 0},           {"break", BREAK, 0},
    {"case", CASE, 0},              {"column_major", MODIFIER, MOD_COLUMN_MAJOR},
    {"compile", COMPILE, 0},        {"const", MODIFIER, MOD_CONST},
    {"continue", CONTINUE, 0},      {"default", DEFAULT, 0},
    {"discard", DISCARD, 0},        {"do", DO, 0},
    {"else", ELSE, 0},              {"extern", MODIFIER, MOD_EXTERN},
    {"false", FALSE_KW, 0},         {"for", FOR, 0},
    {"groupshared", MODIFIER, MOD_GROUPSHARED}, {"if", IF, 0},
    {"in", MODIFIER, MOD_IN},       {"inline", MODIFIER, MOD_INLINE},
    {"inout", MODIFIER, MOD_IN | MOD_OUT}, {"matrix", MATRIX, 0},
    {"out", MODIFIER, MOD_OUT},     {"pass", PASS, 0},
    {"precise", MODIFIER, MOD_PRECISE}, {"register", REGISTER, 0},
    {"return", RETURN, 0},          {"row_major", MODIFIER, MOD_ROW_MAJOR},
    {"sampler_state", SAMPLER_STATE, 0}, {"shared", MODIFIER, MOD_SHARED},
    {"static", MODIFIER, MOD_STATIC}, {"struct", STRUCT, 0},
    {"switch", SWITCH, 0},          {"technique", TECHNIQUE, 0},
    {"technique10", TECHNIQUE, 0},  {"technique11", TECHNIQUE, 0},
    {"true", TRUE_KW, 0},           {"typedef", TYPEDEF, 0},
    {"uniform", MODIFIER, MOD_UNIFORM}, {"vector", VECTOR, 0},
    {"volatile", MODIFIER, MOD_VOLATILE}, {"while", WHILE, 0},
};

/* Interpolation modifiers are keywords only before a type or another modifier, so that
 * `MinFilter = linear;` and a variable named `sample` still read as identifiers. */
static const keyword interp_modifiers[] = {
    {"centroid", MODIFIER, MOD_CENTROID},   {"linear", MODIFIER, MOD_LINEAR},
    {"nointerpolation", MODIFIER, MOD_NOINTERPOLATION}, {"noperspective", MODIFIER, MOD_NOPERSPECTIVE},
    {"sample", MODIFIER, MOD_SAMPLE},
};

typedef struct scalar_name {
    const char *name;
    hfx_base base;
    bool vectors;   /* float4, float4x4 forms exist */
} scalar_name;

static const scalar_name scalar_names[] = {
    {"bool", B_BOOL, true},   {"int", B_INT, true},       {"uint", B_UINT, true},
    {"dword", B_UINT, false}, {"DWORD", B_UINT, false}, {"half", B_HALF, true},     {"float", B_FLOAT, true},
    {"double", B_DOUBLE, true}, {"min16float", B_MIN16FLOAT, true}, {"min10float", B_MIN16FLOAT, true},
    {"min16int", B_INT, true}, {"min12int", B_INT, true}, {"min16uint", B_UINT, true},
};

typedef struct object_name {
    const char *name;   /* compared without case: texture2D, Texture2D, TEXTURE2D */
    hfx_type_kind kind;
    hfx_dim dim;
} object_name;

static const object_name object_names[] = {
    {"texture", TY_TEXTURE, DIM_GENERIC},  {"texture1d", TY_TEXTURE, DIM_1D},
    {"texture2d", TY_TEXTURE, DIM_2D},     {"texture3d", TY_TEXTURE, DIM_3D},
    {"texturecube", TY_TEXTURE, DIM_CUBE}, {"sampler", TY_SAMPLER, DIM_GENERIC},
    {"sampler1d", TY_SAMPLER, DIM_1D},     {"sampler2d", TY_SAMPLER, DIM_2D},
    {"sampler3d", TY_SAMPLER, DIM_3D},     {"samplercube", TY_SAMPLER, DIM_CUBE},
    {"samplerstate", TY_SAMPLER, DIM_GENERIC}, {"samplercomparisonstate", TY_SAMPLER, DIM_GENERIC},
    {"vertexshader", TY_VERTEXSHADER, DIM_GENERIC}, {"pixelshader", TY_PIXELSHADER, DIM_GENERIC},
};

static int compare_keyword(const void *key, const void *elem) {
    return strcmp((const char *)key, ((const keyword *)elem)->name);
}

static const keyword *find_keyword(const char *s) {
    return bsearch(s, keywords, sizeof keywords / sizeof *keywords, sizeof *keywords, compare_keyword);
}

static const keyword *find_interp(const char *s) {
    for (size_t i = 0; i < sizeof interp_modifiers / sizeof *interp_modifiers; i++)
        if (interp_modifiers[i].name[0] == s[0] && strcmp(s, interp_modifiers[i].name) == 0)
            return &interp_modifiers[i];
    return NULL;
}

/* "float", "float3", "float3x4": the type, or NULL when `s` is no numeric type name. */
static const hfx_type *numeric_type(hfx_types *types, const char *s) {
    for (size_t i = 0; i < sizeof scalar_names / sizeof *scalar_names; i++) {
        const scalar_name *sn = &scalar_names[i];
        if (sn->name[0] != s[0]) continue; /* most identifiers stop here */
        size_t n = strlen(sn->name);
        if (strncmp(s, sn->name, n) != 0) continue;
        const char *rest = s + n;
        if (!*rest) return hfx_type_scalar(types, sn->base);
        if (!sn->vectors || rest[0] < '1' || rest[0] > '4') continue;
        if (!rest[1]) return hfx_type_vector(types, sn->base, (unsigned)(rest[0] - '0'));
        if (rest[1] == 'x' && rest[2] >= '1' && rest[2] <= '4' && !rest[3])
            return hfx_type_matrix(types, sn->base, (unsigned)(rest[0] - '0'), (unsigned)(rest[2] - '0'));
    }
    return NULL;
}

static const hfx_type *builtin_type(hfx_types *types, const char *s) {
    if (s[0] == 'v' && strcmp(s, "void") == 0) return hfx_type_void(types);
    if (s[0] == 's' && strcmp(s, "string") == 0) return hfx_type_object(types, TY_STRING, DIM_GENERIC);
    const hfx_type *t = numeric_type(types, s);
    if (t) return t;
    for (size_t i = 0; i < sizeof object_names / sizeof *object_names; i++)
        if (object_names[i].name[0] == (s[0] | 0x20) && strcasecmp(s, object_names[i].name) == 0)
            return hfx_type_object(types, object_names[i].kind, object_names[i].dim);
    return NULL;
}

/* ---- the user type-name scopes ---- */

static bool is_punct(const hfx_token *t, hfx_punct p) {
    return t && t->kind == TK_PUNCT && t->punct == (uint32_t)p;
}

parse_typename *parse_find_typename(parse_ctx *ctx, const char *name) {
    for (uint32_t i = ctx->name_count; i-- > 0;)
        if (ctx->names[i]->name[0] == name[0] && strcmp(ctx->names[i]->name, name) == 0) return ctx->names[i];
    return NULL;
}

static parse_typename *add_typename(parse_ctx *ctx, const char *name) {
    if (ctx->name_count == ctx->name_cap) {
        uint32_t cap = ctx->name_cap ? ctx->name_cap * 2 : 32;
        parse_typename **names = HFX_NEW_ARRAY(ctx->arena, parse_typename *, cap);
        if (!names) return NULL;
        if (ctx->name_count) memcpy(names, ctx->names, sizeof *names * ctx->name_count);
        ctx->names = names;
        ctx->name_cap = cap;
    }
    parse_typename *e = HFX_NEW(ctx->arena, parse_typename);
    if (!e) return NULL;
    e->name = name;
    e->depth = ctx->brace_depth;
    ctx->names[ctx->name_count++] = e;
    return e;
}

/* `struct S`: a use (`struct S x;`) finds the visible S; a definition (`struct S {`) or a
 * first sight declares S in this scope. */
static parse_typename *declare_struct(parse_ctx *ctx, const hfx_token *t) {
    parse_typename *e = parse_find_typename(ctx, t->text);
    bool defines = is_punct(t->next, P_LBRACE);
    if (e && e->st && (e->depth == ctx->brace_depth || !defines)) return e;
    e = add_typename(ctx, t->text);
    if (!e) return NULL;
    e->st = HFX_NEW(ctx->arena, hfx_struct);
    if (!e->st) return NULL;
    e->st->name = t->text;
    e->st->loc = t->loc;
    e->type = hfx_type_struct(ctx->types, e->st);
    return e;
}

static void pop_scope(parse_ctx *ctx) {
    while (ctx->name_count && ctx->names[ctx->name_count - 1]->depth > ctx->brace_depth) ctx->name_count--;
}

/* ---- context ---- */

bool parse_ctx_init(parse_ctx *ctx, hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_token *tokens) {
    memset(ctx, 0, sizeof *ctx);
    ctx->oom_expr = HFX_NEW(arena, parse_expr_node);
    ctx->oom_stmt = HFX_NEW(arena, parse_stmt_node);
    ctx->oom_specs = HFX_NEW(arena, parse_specs);
    ctx->arena = arena;
    ctx->diags = diags;
    ctx->types = types;
    ctx->next = tokens;
    ctx->typedef_depth = -1;
    ctx->globals = parse_vec_new();
    return ctx->oom_expr && ctx->oom_stmt && ctx->oom_specs && tokens;
}

hfx_ast *parse_ctx_finish(parse_ctx *ctx) {
    hfx_ast *ast = HFX_NEW(ctx->arena, hfx_ast);
    if (!ast) return NULL;
    ast->decls = (hfx_decl **)ctx->globals.items;
    ast->decl_count = ctx->globals.count;
    return ast;
}

/* ---- token classification ---- */

/* Does an identifier spell a type or a declaration modifier (for contextual keywords)? */
static bool starts_type(parse_ctx *ctx, const hfx_token *t) {
    if (!t || t->kind != TK_IDENT) return false;
    const keyword *k = find_keyword(t->text);
    if (k) return k->code == MODIFIER || k->code == STRUCT || k->code == VECTOR || k->code == MATRIX;
    return find_interp(t->text) || builtin_type(ctx->types, t->text) || parse_find_typename(ctx, t->text);
}

/* The effect-layer keywords in another case (`Technique`, `Pass`, `SAMPLER_STATE`, `Compile`),
 * as XNA and MonoGame accept them: keywords only where they start their construct, so such
 * spellings stay free as names elsewhere. */
static int effect_keyword_any_case(const parse_ctx *ctx, const hfx_token *t) {
    char c = (char)(t->text[0] | 0x20);
    if (c != 't' && c != 'p' && c != 's' && c != 'c') return 0;
    if (ctx->prev_code == PASS || ctx->prev_code == TECHNIQUE) return 0; /* `pass Pass {` names it */
    const hfx_token *n = t->next;
    bool named_block = n && (n->kind == TK_IDENT || is_punct(n, P_LBRACE) || is_punct(n, P_LT));
    if (named_block && (strcasecmp(t->text, "technique") == 0 || strcasecmp(t->text, "technique10") == 0 ||
                        strcasecmp(t->text, "technique11") == 0))
        return TECHNIQUE;
    if (named_block && strcasecmp(t->text, "pass") == 0) return PASS;
    if (is_punct(n, P_LBRACE) && strcasecmp(t->text, "sampler_state") == 0) return SAMPLER_STATE;
    if (n && n->kind == TK_IDENT && n->next && n->next->kind == TK_IDENT && strcasecmp(t->text, "compile") == 0)
        return COMPILE;
    return 0;
}

/* A typedef's declarator name: registered as a type name as soon as it goes by. */
static void note_typedef_name(parse_ctx *ctx, const hfx_token *t) {
    if (ctx->typedef_depth != (int)ctx->brace_depth || ctx->typedef_parens) return;
    const hfx_token *n = t->next;
    if (ctx->prev_code == TYPEDEF || ctx->prev_code == MODIFIER || ctx->prev_code == STRUCT) return;
    if (is_punct(n, P_SEMI) || is_punct(n, P_COMMA) || is_punct(n, P_LBRACKET)) add_typename(ctx, t->text);
}

/* Inside a pass, sampler_state or `sampler2D s { }` block's own braces. */
static bool in_state_block(const parse_ctx *ctx) {
    return ctx->state_block_count && ctx->state_blocks[ctx->state_block_count - 1] == ctx->brace_depth;
}

static int classify_ident(parse_ctx *ctx, const hfx_token *t, parse_tok *val) {
    if (ctx->prev_code == STRUCT) {
        (void)declare_struct(ctx, t);
        return IDENT;
    }
    if (ctx->prev_code == '.') return IDENT; /* a member or swizzle may be spelled like anything */
    const keyword *k = find_keyword(t->text);
    if (k) {
        val->mods = k->mods;
        return k->code;
    }
    if ((k = find_interp(t->text)) && starts_type(ctx, t->next)) {
        val->mods = k->mods;
        return k->code;
    }
    int tp = effect_keyword_any_case(ctx, t);
    if (tp) return tp;
    parse_typename *e = parse_find_typename(ctx, t->text);
    const hfx_type *builtin = e ? NULL : builtin_type(ctx->types, t->text);
    /* In `ColorArg1[0] = Texture;` or `VertexShader = ...` a type's spelling names a state
     * or a state value; only a constructor, `float4(...)`, is a type there. */
    if ((e || builtin) && in_state_block(ctx) && !is_punct(t->next, P_LPAREN)) return IDENT;
    if (e) {
        val->entry = e;
        val->type = e->type;
        return TYPE_NAME;
    }
    if ((val->type = builtin)) return TYPE_NAME;
    note_typedef_name(ctx, t);
    return IDENT;
}

static int punct_code(uint32_t p, parse_tok *val) {
    static const struct { hfx_punct p; hfx_op op; } assign_ops[] = {
        {P_PLUSEQ, OP_ADD}, {P_MINUSEQ, OP_SUB}, {P_STAREQ, OP_MUL}, {P_SLASHEQ, OP_DIV},
        {P_PERCENTEQ, OP_MOD}, {P_AMPEQ, OP_BITAND}, {P_PIPEEQ, OP_BITOR}, {P_CARETEQ, OP_BITXOR},
        {P_SHLEQ, OP_SHL}, {P_SHREQ, OP_SHR},
    };
    static const char chars[] = {
        [P_LPAREN] = '(', [P_RPAREN] = ')', [P_LBRACKET] = '[', [P_RBRACKET] = ']', [P_LBRACE] = '{',
        [P_RBRACE] = '}', [P_SEMI] = ';', [P_COMMA] = ',', [P_DOT] = '.', [P_COLON] = ':',
        [P_QUESTION] = '?', [P_PLUS] = '+', [P_MINUS] = '-', [P_STAR] = '*', [P_SLASH] = '/',
        [P_PERCENT] = '%', [P_AMP] = '&', [P_PIPE] = '|', [P_CARET] = '^', [P_TILDE] = '~',
        [P_BANG] = '!', [P_LT] = '<', [P_GT] = '>', [P_ASSIGN] = '=',
    };
    if (p < sizeof chars && chars[p]) return (unsigned char)chars[p];
    switch (p) {
    case P_LE: return LE;
    case P_GE: return GE;
    case P_EQEQ: return EQ;
    case P_NE: return NE;
    case P_ANDAND: return ANDAND;
    case P_OROR: return OROR;
    case P_SHL: return SHL;
    case P_SHR: return SHR;
    case P_INC: return INC;
    case P_DEC: return DEC;
    default: break;
    }
    for (size_t i = 0; i < sizeof assign_ops / sizeof *assign_ops; i++)
        if (assign_ops[i].p == p) {
            val->op = assign_ops[i].op;
            return ASSIGN_OP;
        }
    return OTHER;
}

/* ---- nesting and typedef bookkeeping on punctuation ---- */

static bool opens(int code) { return code == '(' || code == '[' || code == '{'; }
static bool closes(int code) { return code == ')' || code == ']' || code == '}'; }

/* State blocks (pass, sampler_state, `sampler2D s {`) hold `Name = value;` lists, where two
 * identifiers in a row are no unknown type: the syntax error message depends on it. */
static void track_state_blocks(parse_ctx *ctx, int code) {
    if (code == PASS || code == SAMPLER_STATE) ctx->state_block_next = true;
    if (code == TECHNIQUE) ctx->technique_next = true;
    uint32_t *top = ctx->state_block_count ? &ctx->state_blocks[ctx->state_block_count - 1] : NULL;
    if (code == '{') {
        /* `pass P <float3 v = {1,2,3};> {`: only the brace after the name or annotations opens it */
        bool after_head = ctx->prev_code == IDENT || ctx->prev_code == PASS || ctx->prev_code == SAMPLER_STATE ||
                          ctx->prev_code == TECHNIQUE || ctx->prev_code == '>';
        if (ctx->technique_next && after_head) { /* a technique's body holds passes, not states */
            ctx->technique_next = false;
            return;
        }
        /* `sampler2D s {` or, with annotations, `sampler2D s <...> {` */
        bool sampler_style = (ctx->prev_code == IDENT && ctx->hist_code[0] == TYPE_NAME) || ctx->prev_code == '>';
        bool opens_block = (ctx->state_block_next && after_head) || sampler_style;
        if (opens_block && ctx->state_block_count < 4) ctx->state_blocks[ctx->state_block_count++] = ctx->brace_depth;
        if (opens_block) ctx->state_block_next = false;
    } else if (code == '}' && top && *top > ctx->brace_depth) {
        ctx->state_block_count--;
    }
}

static void track_nesting(parse_ctx *ctx, int code, hfx_loc loc) {
    if (opens(code)) {
        if (++ctx->depth > PARSE_MAX_NESTING)
            parse_fatal(ctx, loc, "nesting too deep: more than 256 levels of ( [ {");
        if (code == '{') ctx->brace_depth++;
    } else if (closes(code)) {
        if (ctx->depth) ctx->depth--;
        if (code == '}' && ctx->brace_depth) {
            ctx->brace_depth--;
            pop_scope(ctx);
        }
    }
    if (ctx->typedef_depth < 0 || (int)ctx->brace_depth != ctx->typedef_depth) return;
    if (code == '(' || code == '[' || code == '<') ctx->typedef_parens++;
    else if ((code == ')' || code == ']' || code == '>') && ctx->typedef_parens) ctx->typedef_parens--;
    else if (code == ';') ctx->typedef_depth = -1;
}

/* ---- asm blocks ---- */

/* `asm { ... }`: the raw text between the braces (tokens joined), cursor past the '}'. */
static const char *take_asm_block(parse_ctx *ctx, hfx_token *t) {
    hfx_token *p = t->next->next;
    size_t len = 0;
    uint32_t depth = 1;
    hfx_token *end = p;
    for (; end->kind != TK_EOF; end = end->next) {
        if (is_punct(end, P_LBRACE)) depth++;
        if (is_punct(end, P_RBRACE) && --depth == 0) break;
        len += end->len + 1;
    }
    char *text = hfx_arena_alloc(ctx->arena, len + 1);
    if (!text) return "";
    size_t at = 0;
    for (hfx_token *q = p; q != end; q = q->next) {
        if (at) text[at++] = (q->flags & TF_BOL) ? '\n' : ' ';
        memcpy(text + at, q->text, q->len);
        at += q->len;
    }
    text[at] = 0;
    ctx->next = end->kind == TK_EOF ? end : end->next;
    return text;
}

static bool is_asm(const hfx_token *t) {
    return strcasecmp(t->text, "asm") == 0 && is_punct(t->next, P_LBRACE);
}

/* ---- yylex ---- */

static int token_code(parse_ctx *ctx, hfx_token *t, parse_tok *val) {
    switch (t->kind) {
    case TK_EOF: return YYEOF;
    case TK_IDENT:
        if (is_asm(t)) {
            val->text = take_asm_block(ctx, t);
            return ASM_BLOCK;
        }
        return classify_ident(ctx, t, val);
    case TK_INT: return INTCONST;
    case TK_FLOAT: return FLOATCONST;
    case TK_STRING: return STRING;
    case TK_PUNCT: return punct_code(t->punct, val);
    default: return OTHER;
    }
}

/* `#pragma pack_matrix(row_major)` reaches us as `__hfx_pack_matrix ( row_major )` (token.h):
 * it sets the majorness of the matrix declarations that follow; consumed here. */
static bool take_pack_matrix(parse_ctx *ctx, hfx_token *t) {
    if (t->kind != TK_IDENT || strcmp(t->text, "__hfx_pack_matrix") != 0) return false;
    hfx_token *open = t->next, *arg = open ? open->next : NULL, *close = arg ? arg->next : NULL;
    if (!is_punct(open, P_LPAREN) || !arg || arg->kind != TK_IDENT || !is_punct(close, P_RPAREN)) return false;
    if (strcmp(arg->text, "row_major") == 0) ctx->pack_mods = MOD_ROW_MAJOR;
    else if (strcmp(arg->text, "column_major") == 0) ctx->pack_mods = MOD_COLUMN_MAJOR;
    else return false;
    ctx->next = close->next;
    return true;
}

int parse_lex(YYSTYPE *lval, hfx_loc *lloc, parse_ctx *ctx) {
    while (ctx->next && !ctx->fatal && take_pack_matrix(ctx, ctx->next)) continue;
    hfx_token *t = ctx->next;
    memset(&lval->tok, 0, sizeof lval->tok);
    if (ctx->fatal || !t) {
        *lloc = ctx->prev ? ctx->prev->loc : (hfx_loc){0, 0, 0};
        return YYEOF;
    }
    if (t->kind != TK_EOF) ctx->next = t->next;
    lval->tok.text = t->text;
    *lloc = t->loc;
    int code = token_code(ctx, t, &lval->tok);
    track_nesting(ctx, code, t->loc);
    track_state_blocks(ctx, code);
    if (code == TYPEDEF) {
        ctx->typedef_depth = (int)ctx->brace_depth;
        ctx->typedef_parens = 0;
    }
    ctx->hist[1] = ctx->hist[0];
    ctx->hist_code[1] = ctx->hist_code[0];
    ctx->hist[0] = ctx->prev;
    ctx->hist_code[0] = ctx->prev_code;
    ctx->prev = t;
    ctx->prev_code = code;
    return ctx->fatal ? YYEOF : code;
}

/* ---- diagnostics ---- */

static bool same_loc(hfx_loc a, hfx_loc b) { return a.file == b.file && a.line == b.line && a.col == b.col; }

void parse_report_syntax(parse_ctx *ctx, bool at_eof, hfx_loc loc) {
    if (ctx->fatal) return;
    const hfx_token *t = ctx->prev;
    if (ctx->error_count && same_loc(loc, ctx->last_error)) return;
    ctx->error_count++;
    ctx->last_error = loc;
    if (at_eof || !t || t->kind == TK_EOF) {
        hfx_error(ctx->diags, loc, X_SYNTAX, "syntax error: unexpected end of file");
        return;
    }
    /* `Foo x;` with Foo unknown: fxc names the unknown type, not the token after it. */
    int start = ctx->hist_code[1];
    bool in_states = in_state_block(ctx);
    if (!in_states && ctx->prev_code == IDENT && ctx->hist_code[0] == IDENT && ctx->hist[0] &&
        (!ctx->hist[1] || start == ';' || start == '{' || start == '}' || start == '(' || start == ',' ||
         start == MODIFIER)) {
        hfx_error(ctx->diags, ctx->hist[0]->loc, X_SYNTAX, "unrecognized identifier '%s'", ctx->hist[0]->text);
        return;
    }
    if (!in_states && ctx->prev_code == IDENT && ctx->next && ctx->next->kind == TK_IDENT) {
        hfx_error(ctx->diags, loc, X_SYNTAX, "unrecognized identifier '%s'", t->text);
        return;
    }
    switch (t->kind) {
    case TK_INT: hfx_error(ctx->diags, loc, X_SYNTAX, "syntax error: unexpected integer constant"); break;
    case TK_FLOAT: hfx_error(ctx->diags, loc, X_SYNTAX, "syntax error: unexpected float constant"); break;
    case TK_STRING: hfx_error(ctx->diags, loc, X_SYNTAX, "syntax error: unexpected string constant"); break;
    default: hfx_error(ctx->diags, loc, X_SYNTAX, "syntax error: unexpected token '%s'", t->text); break;
    }
}

void parse_report_failure(parse_ctx *ctx, hfx_loc loc, const char *msg) {
    if (strstr(msg, "exhausted")) parse_fatal(ctx, loc, "nesting too deep: the parser's stack is exhausted");
    else if (!ctx->fatal) hfx_error(ctx->diags, loc, X_SYNTAX, "%s", msg);
}

void parse_fatal(parse_ctx *ctx, hfx_loc loc, const char *msg) {
    if (ctx->fatal) return;
    hfx_error(ctx->diags, loc, X_SYNTAX, "%s", msg);
    ctx->fatal = true;
}
