/* hfx_parse_lex.c: turns the preprocessed hfx_token list into Bison tokens. The lexer knows no
 * keywords, so they are decided here, as are type names: builtin ones by spelling (keywords.c:
 * float4x3, Texture2D...), user ones (struct and typedef names) from a scope table fed while
 * tokens go by (the classic C "lexer hack"; tokens come from a list, so peeking is free).
 * Also here: bracket nesting limits and the X3000 syntax error messages. */
#include <string.h>
#include <strings.h>

#include "parse/keywords.h"
#include "parser.h"

/* ---- the user type-name scopes ---- */

static bool is_punct(const hfx_token *t, hfx_punct p) {
    return t && t->kind == TK_PUNCT && t->punct == (uint32_t)p;
}

parse_typename *hfx_parse_find_typename(parse_ctx *ctx, const char *name) {
    for (uint32_t i = ctx->name_count; i-- > 0;)
        if (ctx->names[i]->name[0] == name[0] && strcmp(ctx->names[i]->name, name) == 0) return ctx->names[i];
    return NULL;
}

static parse_typename *add_typename(parse_ctx *ctx, const char *name) {
    if (!HFX_ARENA_GROW(ctx->arena, ctx->names, ctx->name_count, ctx->name_cap, 32)) return NULL;
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
    parse_typename *e = hfx_parse_find_typename(ctx, t->text);
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

bool hfx_parse_ctx_init(parse_ctx *ctx, hfx_arena *arena, hfx_diags *diags, hfx_types *types, hfx_token *tokens) {
    memset(ctx, 0, sizeof *ctx);
    ctx->oom_expr = HFX_NEW(arena, parse_expr_node);
    ctx->oom_stmt = HFX_NEW(arena, parse_stmt_node);
    ctx->oom_specs = HFX_NEW(arena, parse_specs);
    ctx->arena = arena;
    ctx->diags = diags;
    ctx->types = types;
    ctx->next = tokens;
    ctx->typedef_depth = -1;
    ctx->globals = hfx_parse_vec_new();
    return ctx->oom_expr && ctx->oom_stmt && ctx->oom_specs && tokens;
}

hfx_ast *hfx_parse_ctx_finish(parse_ctx *ctx) {
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
    kw_word w;
    hfx_kw_lookup(t->text, t->len, &w);
    if (w.keyword) return w.keyword == MODIFIER || w.keyword == STRUCT || w.keyword == VECTOR || w.keyword == MATRIX;
    return w.interp || w.form != KW_TYPE_NONE || hfx_parse_find_typename(ctx, t->text);
}

/* The effect-layer keywords in another case (`Technique`, `Pass`, `SAMPLER_STATE`, `Compile`),
 * as XNA and MonoGame accept them: keywords only where they start their construct, so such
 * spellings stay free as names elsewhere. */
static int effect_keyword_any_case(const parse_ctx *ctx, const hfx_token *t, int code) {
    if (!code) return 0;
    if (ctx->prev_code == PASS || ctx->prev_code == TECHNIQUE) return 0; /* `pass Pass {` names it */
    const hfx_token *n = t->next;
    switch (code) {
    case TECHNIQUE:
    case PASS: return n && (n->kind == TK_IDENT || is_punct(n, P_LBRACE) || is_punct(n, P_LT)) ? code : 0;
    case SAMPLER_STATE: return is_punct(n, P_LBRACE) ? code : 0;
    case D3D10_STATE: case FXGROUP: /* `BlendState b {`, `fxgroup g {`: a global's first word */
        return ctx->brace_depth == 0 && n && n->kind == TK_IDENT ? code : 0;
    default: return n && n->kind == TK_IDENT && n->next && n->next->kind == TK_IDENT ? code : 0; /* COMPILE */
    }
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

/* ---- builtin type spellings used as names ----
 * fxc lets a declaration name a variable with a builtin type's spelling: `texture Texture;`,
 * `sampler Sampler = sampler_state {...};`, `sampler samplerState;` (XNA's DECLARE_TEXTURE
 * does). Such a spelling right after a complete type, before what ends a declarator, is the
 * name; from then on that exact spelling is a name wherever no identifier follows it (where
 * one does, `Texture t2;`, it still declares with the type). */

static bool ends_declarator(const hfx_token *n) {
    return is_punct(n, P_SEMI) || is_punct(n, P_ASSIGN) || is_punct(n, P_COLON) || is_punct(n, P_LT) ||
           is_punct(n, P_LBRACKET) || is_punct(n, P_COMMA) || is_punct(n, P_RPAREN);
}

static bool is_shadowed(const parse_ctx *ctx, const hfx_token *t) {
    for (uint32_t i = 0; i < ctx->shadow_count; i++)
        if (strcmp(ctx->shadows[i], t->text) == 0) return true;
    return false;
}

/* True when the builtin type spelling t is a name here (and remembers a new one). A
 * semantic spelled like a type (`Texture xTexture : TEXTURE;`) is a name too, and so is a
 * function named like one (`float4 PixelShader(float2 uv : TEXCOORD0) : COLOR0`, as XNA
 * tutorials write it) and a name after a template type (`Texture2D<float4> Texture`). */
static bool type_spelling_is_name(parse_ctx *ctx, const hfx_token *t) {
    if (ctx->prev_code == ':' && ends_declarator(t->next) && !is_punct(t->next, P_COLON)) return true;
    bool after_type = ctx->prev_code == TYPE_NAME || (ctx->prev_code == '>' && ctx->brace_depth == 0);
    if (after_type && (ends_declarator(t->next) || (ctx->prev_code == TYPE_NAME && is_punct(t->next, P_LPAREN)))) {
        if (!is_shadowed(ctx, t) && HFX_ARENA_GROW(ctx->arena, ctx->shadows, ctx->shadow_count, ctx->shadow_cap, 8))
            ctx->shadows[ctx->shadow_count++] = t->text;
        return true;
    }
    return is_shadowed(ctx, t) && !(t->next && t->next->kind == TK_IDENT);
}

/* `VertexShader = null;`: fxc takes the lower-case spelling as NULL in a state value. */
static bool is_state_null(const parse_ctx *ctx, const hfx_token *t) {
    return ctx->prev_code == '=' && in_state_block(ctx) && t->len == 4 && strncasecmp(t->text, "null", 4) == 0;
}

static int classify_ident(parse_ctx *ctx, const hfx_token *t, parse_tok *val) {
    if (ctx->prev_code == STRUCT) {
        (void)declare_struct(ctx, t);
        return IDENT;
    }
    if (ctx->prev_code == '.') return IDENT; /* a member or swizzle may be spelled like anything */
    kw_word w;
    hfx_kw_lookup(t->text, t->len, &w);
    if (w.keyword) {
        val->mods = w.mods;
        return w.keyword;
    }
    if (w.interp && starts_type(ctx, t->next)) {
        val->mods = w.mods;
        return MODIFIER;
    }
    int tp = effect_keyword_any_case(ctx, t, w.any_case_keyword);
    if (tp) return tp;
    if (is_state_null(ctx, t)) return NULL_KW;
    parse_typename *e = hfx_parse_find_typename(ctx, t->text);
    const hfx_type *builtin = e ? NULL : hfx_kw_builtin_type(ctx->types, &w);
    if (builtin && type_spelling_is_name(ctx, t)) return IDENT;
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
    if (code == PASS || code == SAMPLER_STATE || code == D3D10_STATE) ctx->state_block_next = true;
    if (code == TECHNIQUE) ctx->technique_next = true;
    uint32_t *top = ctx->state_block_count ? &ctx->state_blocks[ctx->state_block_count - 1] : NULL;
    if (code == '{') {
        /* `pass P <float3 v = {1,2,3};> {`: only the brace after the name or annotations opens it */
        bool after_head = ctx->prev_code == IDENT || ctx->prev_code == PASS || ctx->prev_code == SAMPLER_STATE ||
                          ctx->prev_code == TECHNIQUE || ctx->prev_code == '>' || ctx->prev_code == ']';
        if (ctx->technique_next && after_head) { /* a technique's body holds passes, not states */
            ctx->technique_next = false;
            return;
        }
        /* `sampler2D s {` or, with annotations, `sampler2D s <...> {` */
        bool sampler_style = (ctx->prev_code == IDENT && ctx->hist_code[0] == TYPE_NAME) || ctx->prev_code == '>';
        /* `pass P { ZEnable = true; { CullMode = None; } }`: braces nested in a state block */
        bool nested = ctx->state_block_count && ctx->state_blocks[ctx->state_block_count - 1] + 1 == ctx->brace_depth &&
                      (ctx->prev_code == ';' || ctx->prev_code == '{' || ctx->prev_code == '}');
        bool opens_block = (ctx->state_block_next && after_head) || sampler_style || nested;
        if (opens_block && ctx->state_block_count < 4) ctx->state_blocks[ctx->state_block_count++] = ctx->brace_depth;
        if (opens_block) ctx->state_block_next = false;
    } else if (code == '}' && top && *top > ctx->brace_depth) {
        ctx->state_block_count--;
    }
}

static void track_nesting(parse_ctx *ctx, int code, hfx_loc loc) {
    if (opens(code)) {
        if (++ctx->depth > PARSE_MAX_NESTING)
            hfx_parse_fatal(ctx, loc, "nesting too deep: more than 256 levels of ( [ {");
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
    return t->len == 3 && strcasecmp(t->text, "asm") == 0 && is_punct(t->next, P_LBRACE);
}

/* ---- yylex ---- */

static int token_code(parse_ctx *ctx, hfx_token *t, parse_tok *val) {
    switch (t->kind) {
    case TK_EOF: return HFX_YYEOF;
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
    if (t->kind != TK_IDENT || t->len != 17 || strcmp(t->text, "__hfx_pack_matrix") != 0) return false;
    hfx_token *open = t->next, *arg = open ? open->next : NULL, *close = arg ? arg->next : NULL;
    if (!is_punct(open, P_LPAREN) || !arg || arg->kind != TK_IDENT || !is_punct(close, P_RPAREN)) return false;
    if (strcmp(arg->text, "row_major") == 0) ctx->pack_mods = MOD_ROW_MAJOR;
    else if (strcmp(arg->text, "column_major") == 0) ctx->pack_mods = MOD_COLUMN_MAJOR;
    else return false;
    ctx->next = close->next;
    return true;
}

int hfx_parse_lex(HFX_YYSTYPE *lval, hfx_loc *lloc, parse_ctx *ctx) {
    while (ctx->next && !ctx->fatal && take_pack_matrix(ctx, ctx->next)) continue;
    hfx_token *t = ctx->next;
    memset(&lval->tok, 0, sizeof lval->tok);
    if (ctx->fatal || !t) {
        *lloc = ctx->prev ? ctx->prev->loc : (hfx_loc){0, 0, 0};
        return HFX_YYEOF;
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
    return ctx->fatal ? HFX_YYEOF : code;
}

/* ---- diagnostics ---- */

static bool same_loc(hfx_loc a, hfx_loc b) { return a.file == b.file && a.line == b.line && a.col == b.col; }

void hfx_parse_report_syntax(parse_ctx *ctx, bool at_eof, hfx_loc loc) {
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

void hfx_parse_report_failure(parse_ctx *ctx, hfx_loc loc, const char *msg) {
    if (strstr(msg, "exhausted")) hfx_parse_fatal(ctx, loc, "nesting too deep: the parser's stack is exhausted");
    else if (!ctx->fatal) hfx_error(ctx->diags, loc, X_SYNTAX, "%s", msg);
}

void hfx_parse_fatal(parse_ctx *ctx, hfx_loc loc, const char *msg) {
    if (ctx->fatal) return;
    hfx_error(ctx->diags, loc, X_SYNTAX, "%s", msg);
    ctx->fatal = true;
}
