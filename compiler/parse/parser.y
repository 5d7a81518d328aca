/* parser.y: the grammar of D3D9 effect files (fx_2_0: SM2/SM3 HLSL plus techniques, passes,
 * annotations and state blocks). Actions are one line: nodes are built by parse_expr.c and
 * parse_decl.c, tokens come from hfx_parse_lex.c (keywords, type names, the typedef/struct lexer
 * hack, nesting limits, the X3000 messages). Recovery: `error` at ';' and '}' in statements,
 * struct bodies, annotations, state blocks and at top level, so every syntax error in a file
 * is reported. The only conflicts are the dangling else and the binary operators, both
 * settled by the precedence declarations. */
%define api.prefix {hfx_yy}
%define api.pure full
%define api.location.type {hfx_loc}
%define parse.error custom
%locations
%param {parse_ctx *ctx}

%code requires {
#include "parse/parse_ctx.h"
}

%code {
#include <stdlib.h>
#define YYLLOC_DEFAULT(Cur, Rhs, N) do { (Cur) = (N) ? YYRHSLOC(Rhs, 1) : YYRHSLOC(Rhs, 0); } while (0)
#define YYMAXDEPTH 50000 /* then "nesting too deep", not a crash (the C stack is not involved) */
/* A deeper stack comes from the arena: nothing to free if an allocation failure escapes. */
#define YYSTACK_ALLOC(n) hfx_arena_alloc_raw(ctx->arena, (n))
#define YYSTACK_ALLOC_MAXIMUM ((size_t)1 << 30)
static int yylex(YYSTYPE *lval, YYLTYPE *lloc, parse_ctx *ctx) { return hfx_parse_lex(lval, lloc, ctx); }
static void yyerror(YYLTYPE *loc, parse_ctx *ctx, const char *msg);
}

%union {
    parse_tok tok;
    hfx_expr *expr;
    hfx_stmt *stmt;
    hfx_decl *decl;
    const hfx_type *type;
    parse_specs *specs;
    parse_declarator *dtor;
    parse_vec vec;
    hfx_state_assign *state;
    hfx_pass_ast *pass;
    hfx_attribute *attr;
    hfx_annotation_ast *anno;
    uint32_t mods;
}

%token <tok> IDENT TYPE_NAME INTCONST FLOATCONST STRING ASM_BLOCK MODIFIER ASSIGN_OP
%token <tok> STRUCT TYPEDEF TECHNIQUE PASS COMPILE SAMPLER_STATE REGISTER TRUE_KW FALSE_KW NULL_KW
%token <tok> IF ELSE FOR WHILE DO SWITCH CASE DEFAULT BREAK CONTINUE DISCARD RETURN VECTOR MATRIX
%token <tok> LE GE EQ NE ANDAND OROR SHL SHR INC DEC OTHER CBUFFER UNSIGNED FXGROUP D3D10_STATE

%precedence LOWER_THAN_ELSE
%precedence ELSE
%left OROR
%left ANDAND
%left '|'
%left '^'
%left '&'
%left EQ NE
%left '<' '>' LE GE
%left SHL SHR
%left '+' '-'
%left '*' '/' '%'

%type <expr> postfix unary binary assign expr
%type <expr> expr_opt initializer state_value strings
%type <vec> args args_opt init_items declarators fields params params_opt annotations anno_list
%type <vec> states passes stmt_list attrs dims
%type <stmt> stmt block for_init
%type <decl> function fn_head technique param
%type <type> type_spec ctor_type struct_spec
%type <specs> decl_specs
%type <dtor> declarator decl_head decl_post
%type <mods> mods
%type <state> state
%type <pass> pass
%type <attr> attr
%type <anno> annotation
%type <tok> name_opt semantic_opt state_name

%%

file
    : %empty
    | file global
    ;

global
    : decl_specs declarators ';'             { hfx_pb_globals(ctx, hfx_pb_vars(ctx, $1, $2, true)); }
    | decl_specs ';'                         { hfx_pb_global(ctx, hfx_pb_struct_decl(ctx, $1)); }
    | TYPEDEF decl_specs declarators ';'     { hfx_pb_globals(ctx, hfx_pb_typedefs(ctx, $2, $3)); }
    | function                               { hfx_pb_global(ctx, $1); }
    | technique                              { hfx_pb_global(ctx, $1); }
    | CBUFFER name_opt cbuffer_register '{' cbuffer_members '}'
    | D3D10_STATE IDENT '{' states '}'       { hfx_pb_d3d10_ignored(ctx, $1.text, $2.text, @2); }
    | D3D10_STATE IDENT dims '{' states '}'  { hfx_pb_d3d10_ignored(ctx, $1.text, $2.text, @2); }
    | FXGROUP name_opt '{' group_techniques '}' { hfx_pb_d3d10_ignored(ctx, "fxgroup", $2.text, @1); }
    | ';'
    | error ';'
    | error '}'
    ;

/* Direct3D 10 / 11 groups of techniques: parsed, then dropped (hfx_pb_d3d10_ignored). */
group_techniques
    : %empty
    | group_techniques technique
    | group_techniques ';'
    ;

/* SM4 constant buffers in SM2/SM3 code: the members are ordinary globals (parameters). */
cbuffer_register
    : %empty
    | ':' REGISTER '(' IDENT ')'
    ;

cbuffer_members
    : %empty
    | cbuffer_members decl_specs declarators ';' { hfx_pb_globals(ctx, hfx_pb_vars(ctx, $2, $3, true)); }
    | cbuffer_members error ';'
    ;

/* ---- types and declarations ---- */

mods
    : MODIFIER                               { $$ = $1.mods; }
    | mods MODIFIER                          { $$ = hfx_pb_more_mods(ctx, $1, $2.mods, @2); }
    ;

decl_specs
    : type_spec                              { $$ = hfx_pb_specs(ctx, 0, $1, @1); }
    | mods type_spec                         { $$ = hfx_pb_specs(ctx, $1, $2, @1); }
    ;

type_spec
    : ctor_type
    | struct_spec
    ;

ctor_type
    : TYPE_NAME                              { $$ = hfx_pb_typename(ctx, &$1, @1); }
    | TYPE_NAME '<' ctor_type '>'            { $$ = hfx_pb_template(ctx, hfx_pb_typename(ctx, &$1, @1), $3, @2); }
    | TYPE_NAME '<' ctor_type ',' INTCONST '>' { $$ = hfx_pb_template(ctx, hfx_pb_typename(ctx, &$1, @1), $3, @2); }
    | UNSIGNED TYPE_NAME                     { $$ = hfx_pb_unsigned(ctx, hfx_pb_typename(ctx, &$2, @2), @1); }
    | VECTOR                                 { $$ = hfx_pb_generic_vector(ctx, NULL, NULL, @1); }
    | VECTOR '<' TYPE_NAME ',' INTCONST '>'  { $$ = hfx_pb_generic_vector(ctx, $3.type, $5.text, @3); }
    | MATRIX                                 { $$ = hfx_pb_generic_matrix(ctx, NULL, NULL, NULL, @1); }
    | MATRIX '<' TYPE_NAME ',' INTCONST ',' INTCONST '>' { $$ = hfx_pb_generic_matrix(ctx, $3.type, $5.text, $7.text, @3); }
    ;

struct_spec
    : STRUCT IDENT '{' fields '}'            { $$ = hfx_pb_struct(ctx, $2.text, $4, @2); }
    | STRUCT '{' fields '}'                  { $$ = hfx_pb_struct(ctx, NULL, $3, @1); }
    | STRUCT IDENT '{' fields error '}'      { $$ = hfx_pb_struct(ctx, $2.text, $4, @2); }
    | STRUCT IDENT ':' TYPE_NAME '{' fields '}' { $$ = hfx_pb_struct_derived(ctx, $2.text, hfx_pb_typename(ctx, &$4, @4), $6, @2); }
    | STRUCT IDENT                           { $$ = hfx_pb_struct_ref(ctx, $2.text, @2); }
    ;

fields
    : %empty                                 { $$ = hfx_parse_vec_new(); }
    | fields decl_specs declarators ';'      { $$ = hfx_pb_fields(ctx, $1, $2, $3); }
    | fields error ';'                       { $$ = $1; }
    ;

declarators
    : declarator                             { $$ = hfx_parse_vec_one(ctx, $1); }
    | declarators ',' declarator             { $$ = hfx_parse_vec_push(ctx, $1, $3); }
    ;

decl_head
    : IDENT                                  { $$ = hfx_pb_declarator(ctx, $1.text, @1); }
    | IDENT dims                             { $$ = hfx_pb_decl_dims(ctx, hfx_pb_declarator(ctx, $1.text, @1), $2); }
    ;

dims
    : '[' expr ']'                           { $$ = hfx_parse_vec_one(ctx, $2); }
    | '[' ']'                                { $$ = hfx_parse_vec_one(ctx, NULL); }
    | dims '[' expr ']'                      { $$ = hfx_parse_vec_push(ctx, $1, $3); }
    | dims '[' ']'                           { $$ = hfx_parse_vec_push(ctx, $1, NULL); }
    ;

decl_post
    : decl_head
    | decl_post ':' IDENT                    { $$ = hfx_pb_decl_semantic($1, $3.text); }
    | decl_post ':' REGISTER '(' IDENT ')'   { $$ = hfx_pb_decl_register(ctx, $1, $5.text); }
    | decl_post ':' REGISTER '(' IDENT ',' IDENT ')' { $$ = hfx_pb_decl_register(ctx, $1, hfx_arena_printf(ctx->arena, "%s,%s", $5.text, $7.text)); }
    | decl_post ':' REGISTER '(' IDENT '[' expr ']' ')' { $$ = hfx_pb_decl_register(ctx, $1, $5.text); }
    | decl_post ':' REGISTER '(' IDENT ',' IDENT '[' expr ']' ')' { $$ = hfx_pb_decl_register(ctx, $1, $7.text); }
    | decl_post annotations                  { $$ = hfx_pb_decl_annotations(ctx, $1, $2); }
    ;

declarator
    : decl_post
    | decl_post '=' initializer              { $$ = hfx_pb_decl_init($1, $3); }
    | decl_post '{' states '}'               { $$ = hfx_pb_decl_init($1, hfx_pb_sampler_state(ctx, $3, @2)); }
    | decl_post '{' states error '}'         { $$ = hfx_pb_decl_init($1, hfx_pb_sampler_state(ctx, $3, @2)); }
    ;

initializer
    : assign
    | '{' init_items '}'                     { $$ = hfx_pb_init_list(ctx, $2, @1); }
    | '{' init_items ',' '}'                 { $$ = hfx_pb_init_list(ctx, $2, @1); }
    | '{' '}'                                { $$ = hfx_pb_init_list(ctx, hfx_parse_vec_new(), @1); }
    | ASM_BLOCK                              { $$ = hfx_pb_asm(ctx, $1.text, @1); }
    ;

init_items
    : initializer                            { $$ = hfx_parse_vec_one(ctx, $1); }
    | init_items ',' initializer             { $$ = hfx_parse_vec_push(ctx, $1, $3); }
    ;

annotations
    : '<' anno_list '>'                      { $$ = $2; }
    | '<' anno_list error '>'                { $$ = $2; }
    ;

anno_list
    : %empty                                 { $$ = hfx_parse_vec_new(); }
    | anno_list annotation                   { $$ = hfx_parse_vec_push(ctx, $1, $2); }
    | anno_list error ';'                    { $$ = $1; }
    ;

annotation
    : type_spec declarator ';'               { $$ = hfx_pb_annotation(ctx, $1, $2); }
    ;

/* ---- functions ---- */

function
    : fn_head block                          { $$ = hfx_pb_function_body(ctx, $1, hfx_parse_vec_new(), $2); }
    | fn_head ';'                            { $$ = hfx_pb_function_body(ctx, $1, hfx_parse_vec_new(), NULL); }
    | attrs fn_head block                    { $$ = hfx_pb_function_body(ctx, $2, $1, $3); }
    | attrs fn_head ';'                      { $$ = hfx_pb_function_body(ctx, $2, $1, NULL); }
    ;

fn_head
    : decl_specs IDENT '(' params_opt ')' semantic_opt { $$ = hfx_pb_function(ctx, $1, $2.text, @2, $4, $6.text); }
    ;

semantic_opt
    : %empty                                 { $$.text = NULL; }
    | ':' IDENT                              { $$ = $2; }
    ;

params_opt
    : %empty                                 { $$ = hfx_parse_vec_new(); }
    | params
    ;

params
    : param                                  { $$ = hfx_parse_vec_one(ctx, $1); }
    | params ',' param                       { $$ = hfx_parse_vec_push(ctx, $1, $3); }
    ;

param
    : decl_specs                             { $$ = hfx_pb_param(ctx, $1, NULL, @1); }
    | decl_specs declarator                  { $$ = hfx_pb_param(ctx, $1, $2, @1); }
    ;

attrs
    : attr                                   { $$ = hfx_parse_vec_one(ctx, $1); }
    | attrs attr                             { $$ = hfx_parse_vec_push(ctx, $1, $2); }
    ;

attr
    : '[' IDENT ']'                          { $$ = hfx_pb_attribute(ctx, $2.text, hfx_parse_vec_new(), @2); }
    | '[' IDENT '(' args_opt ')' ']'         { $$ = hfx_pb_attribute(ctx, $2.text, $4, @2); }
    ;

/* ---- techniques, passes, state blocks ---- */

technique
    : TECHNIQUE name_opt '{' passes '}'             { $$ = hfx_pb_technique(ctx, $1.text, $2.text, hfx_parse_vec_new(), $4, @2); }
    | TECHNIQUE name_opt annotations '{' passes '}' { $$ = hfx_pb_technique(ctx, $1.text, $2.text, $3, $5, @2); }
    | TECHNIQUE name_opt '{' passes error '}'       { $$ = hfx_pb_technique(ctx, $1.text, $2.text, hfx_parse_vec_new(), $4, @2); }
    ;

/* A technique or pass may share its name with a type (struct T {...}; technique T {...}) */
name_opt
    : %empty                                 { $$.text = NULL; }
    | IDENT
    | TYPE_NAME
    ;

passes
    : %empty                                 { $$ = hfx_parse_vec_new(); }
    | passes pass                            { $$ = hfx_parse_vec_push(ctx, $1, $2); }
    | passes ';'                             { $$ = $1; }
    ;

pass
    : PASS name_opt '{' states '}'             { $$ = hfx_pb_pass(ctx, $2.text, hfx_parse_vec_new(), $4, @2); }
    | PASS name_opt annotations '{' states '}' { $$ = hfx_pb_pass(ctx, $2.text, $3, $5, @2); }
    | PASS name_opt '{' states error '}'       { $$ = hfx_pb_pass(ctx, $2.text, hfx_parse_vec_new(), $4, @2); }
    | PASS name_opt annotations '{' states error '}' { $$ = hfx_pb_pass(ctx, $2.text, $3, $5, @2); }
    ;

states
    : %empty                                 { $$ = hfx_parse_vec_new(); }
    | states state                           { $$ = hfx_parse_vec_push(ctx, $1, $2); }
    | states error ';'                       { $$ = $1; }
    | states '{' states '}'                  { $$ = hfx_parse_vec_concat(ctx, $1, $3); }
    ;

state
    : state_name '=' state_value ';'              { $$ = hfx_pb_state(ctx, $1.text, NULL, $3, @1); }
    | state_name '[' expr ']' '=' state_value ';' { $$ = hfx_pb_state(ctx, $1.text, $3, $6, @1); }
    | IDENT '(' args_opt ')' ';'                  { $$ = hfx_pb_state(ctx, $1.text, NULL, hfx_pb_call(ctx, $1.text, $3, @1), @1); }
    ;

state_name
    : IDENT
    | TYPE_NAME
    ;

state_value
    : initializer
    | '<' IDENT '>'                          { $$ = hfx_pb_state_ref(ctx, $2.text, @2); }
    | '<' IDENT '[' expr ']' '>'             { $$ = hfx_pb_index(ctx, hfx_pb_state_ref(ctx, $2.text, @2), $4, @3); }
    ;

/* ---- statements ---- */

block
    : '{' stmt_list '}'                      { $$ = hfx_pb_block(ctx, $2, @1); }
    | '{' stmt_list error '}'                { $$ = hfx_pb_block(ctx, $2, @1); }
    ;

stmt_list
    : %empty                                 { $$ = hfx_parse_vec_new(); }
    | stmt_list stmt                         { $$ = hfx_parse_vec_push(ctx, $1, $2); }
    ;

stmt
    : block
    | decl_specs declarators ';'             { $$ = hfx_pb_decl_stmt(ctx, hfx_pb_vars(ctx, $1, $2, false), @1); }
    | decl_specs ';'                         { $$ = hfx_pb_decl_stmt(ctx, hfx_parse_vec_one(ctx, hfx_pb_struct_decl(ctx, $1)), @1); }
    | TYPEDEF decl_specs declarators ';'     { $$ = hfx_pb_decl_stmt(ctx, hfx_pb_typedefs(ctx, $2, $3), @1); }
    | expr ';'                               { $$ = hfx_pb_expr_stmt(ctx, ST_EXPR, $1, @1); }
    | ';'                                    { $$ = hfx_pb_stmt(ctx, ST_EMPTY, @1); }
    | IF '(' expr ')' stmt %prec LOWER_THAN_ELSE { $$ = hfx_pb_if(ctx, $3, $5, NULL, @1); }
    | IF '(' expr ')' stmt ELSE stmt         { $$ = hfx_pb_if(ctx, $3, $5, $7, @1); }
    | WHILE '(' expr ')' stmt                { $$ = hfx_pb_loop(ctx, ST_WHILE, $3, $5, @1); }
    | DO stmt WHILE '(' expr ')' ';'         { $$ = hfx_pb_loop(ctx, ST_DO, $5, $2, @1); }
    | FOR '(' for_init expr_opt ';' expr_opt ')' stmt { $$ = hfx_pb_for(ctx, $3, $4, $6, $8, @1); }
    | SWITCH '(' expr ')' '{' stmt_list '}'  { $$ = hfx_pb_switch(ctx, $3, $6, @1); }
    | CASE expr ':'                          { $$ = hfx_pb_expr_stmt(ctx, ST_CASE, $2, @1); }
    | DEFAULT ':'                            { $$ = hfx_pb_stmt(ctx, ST_DEFAULT, @1); }
    | BREAK ';'                              { $$ = hfx_pb_stmt(ctx, ST_BREAK, @1); }
    | CONTINUE ';'                           { $$ = hfx_pb_stmt(ctx, ST_CONTINUE, @1); }
    | DISCARD ';'                            { $$ = hfx_pb_stmt(ctx, ST_DISCARD, @1); }
    | RETURN expr_opt ';'                    { $$ = hfx_pb_expr_stmt(ctx, ST_RETURN, $2, @1); }
    | ASM_BLOCK                              { $$ = hfx_pb_asm_stmt(ctx, $1.text, @1); }
    | attr stmt                              { $$ = hfx_pb_attributed(ctx, $1, $2); }
    | error ';'                              { $$ = hfx_pb_stmt(ctx, ST_EMPTY, @1); }
    ;

for_init
    : ';'                                    { $$ = NULL; }
    | expr ';'                               { $$ = hfx_pb_expr_stmt(ctx, ST_EXPR, $1, @1); }
    | decl_specs declarators ';'             { $$ = hfx_pb_decl_stmt(ctx, hfx_pb_vars(ctx, $1, $2, false), @1); }
    ;

expr_opt
    : %empty                                 { $$ = NULL; }
    | expr
    ;

/* ---- expressions, C precedence ---- */

strings
    : STRING                                 { $$ = hfx_pb_string(ctx, $1.text, @1); }
    | strings STRING                         { $$ = hfx_pb_string_join(ctx, $1, $2.text); }
    ;

/* The primary expressions are alternatives of postfix itself: one unit reduction less for
 * every operand. */
postfix
    : IDENT                                  { $$ = hfx_pb_ident(ctx, $1.text, @1); }
    | INTCONST                               { $$ = hfx_pb_int(ctx, $1.text, @1); }
    | FLOATCONST                             { $$ = hfx_pb_float(ctx, $1.text, @1); }
    | TRUE_KW                                { $$ = hfx_pb_bool(ctx, true, @1); }
    | FALSE_KW                               { $$ = hfx_pb_bool(ctx, false, @1); }
    | strings
    | '(' expr ')'                           { $$ = hfx_pb_paren($2); }
    | IDENT '(' args_opt ')'                 { $$ = hfx_pb_call(ctx, $1.text, $3, @1); }
    | ctor_type '(' args_opt ')'             { $$ = hfx_pb_construct(ctx, $1, $3, @1); }
    | COMPILE IDENT IDENT '(' args_opt ')'   { $$ = hfx_pb_compile(ctx, $2.text, $3.text, $5, @3); }
    | COMPILE IDENT IDENT                    { $$ = hfx_pb_compile(ctx, $2.text, $3.text, hfx_parse_vec_new(), @3); }
    | SAMPLER_STATE '{' states '}'           { $$ = hfx_pb_sampler_state(ctx, $3, @1); }
    | SAMPLER_STATE '{' states error '}'     { $$ = hfx_pb_sampler_state(ctx, $3, @1); }
    | NULL_KW                                { $$ = hfx_pb_expr(ctx, EX_NULL, @1); }
    | postfix '[' expr ']'                   { $$ = hfx_pb_index(ctx, $1, $3, @2); }
    | postfix '.' IDENT                      { $$ = hfx_pb_member(ctx, $1, $3.text, @2); }
    | postfix '.' IDENT '(' args_opt ')'     { $$ = hfx_pb_method(ctx, $1, $3.text, $5, @3); }
    | postfix INC                            { $$ = hfx_pb_unary(ctx, OP_POSTINC, $1, @2); }
    | postfix DEC                            { $$ = hfx_pb_unary(ctx, OP_POSTDEC, $1, @2); }
    ;

unary
    : postfix
    | INC unary                              { $$ = hfx_pb_unary(ctx, OP_PREINC, $2, @1); }
    | DEC unary                              { $$ = hfx_pb_unary(ctx, OP_PREDEC, $2, @1); }
    | '-' unary                              { $$ = hfx_pb_unary(ctx, OP_NEG, $2, @1); }
    | '+' unary                              { $$ = hfx_pb_unary(ctx, OP_POS, $2, @1); }
    | '!' unary                              { $$ = hfx_pb_unary(ctx, OP_NOT, $2, @1); }
    | '~' unary                              { $$ = hfx_pb_unary(ctx, OP_BITNOT, $2, @1); }
    | '(' ctor_type ')' unary                { $$ = hfx_pb_cast(ctx, $2, $4, @1); }
    | '(' ctor_type dims ')' unary           { $$ = hfx_pb_cast(ctx, hfx_pb_array_type(ctx, $2, $3), $5, @1); }
    | '(' struct_spec ')' unary              { ctx->pending_struct = NULL; $$ = hfx_pb_cast(ctx, $2, $4, @1); }
    ;

/* The binary operators in one rule: precedence declarations order them like C, which keeps
 * each operand's climb through unit rules short. */
binary
    : unary
    | binary '*' binary                      { $$ = hfx_pb_binary(ctx, OP_MUL, $1, $3, @2); }
    | binary '/' binary                      { $$ = hfx_pb_binary(ctx, OP_DIV, $1, $3, @2); }
    | binary '%' binary                      { $$ = hfx_pb_binary(ctx, OP_MOD, $1, $3, @2); }
    | binary '+' binary                      { $$ = hfx_pb_binary(ctx, OP_ADD, $1, $3, @2); }
    | binary '-' binary                      { $$ = hfx_pb_binary(ctx, OP_SUB, $1, $3, @2); }
    | binary SHL binary                      { $$ = hfx_pb_binary(ctx, OP_SHL, $1, $3, @2); }
    | binary SHR binary                      { $$ = hfx_pb_binary(ctx, OP_SHR, $1, $3, @2); }
    | binary '<' binary                      { $$ = hfx_pb_binary(ctx, OP_LT, $1, $3, @2); }
    | binary '>' binary                      { $$ = hfx_pb_binary(ctx, OP_GT, $1, $3, @2); }
    | binary LE binary                       { $$ = hfx_pb_binary(ctx, OP_LE, $1, $3, @2); }
    | binary GE binary                       { $$ = hfx_pb_binary(ctx, OP_GE, $1, $3, @2); }
    | binary EQ binary                       { $$ = hfx_pb_binary(ctx, OP_EQ, $1, $3, @2); }
    | binary NE binary                       { $$ = hfx_pb_binary(ctx, OP_NE, $1, $3, @2); }
    | binary '&' binary                      { $$ = hfx_pb_binary(ctx, OP_BITAND, $1, $3, @2); }
    | binary '^' binary                      { $$ = hfx_pb_binary(ctx, OP_BITXOR, $1, $3, @2); }
    | binary '|' binary                      { $$ = hfx_pb_binary(ctx, OP_BITOR, $1, $3, @2); }
    | binary ANDAND binary                   { $$ = hfx_pb_binary(ctx, OP_AND, $1, $3, @2); }
    | binary OROR binary                     { $$ = hfx_pb_binary(ctx, OP_OR, $1, $3, @2); }
    ;

/* The conditional operator is one of assign's alternatives (no unit rule between them). */
assign
    : binary
    | binary '?' expr ':' assign             { $$ = hfx_pb_ternary(ctx, $1, $3, $5, @2); }
    | unary '=' assign                       { $$ = hfx_pb_assign(ctx, OP_NONE, $1, $3, @2); }
    | unary ASSIGN_OP assign                 { $$ = hfx_pb_assign(ctx, $2.op, $1, $3, @2); }
    ;

expr
    : assign
    | expr ',' assign                        { $$ = hfx_pb_comma(ctx, $1, $3, @2); }
    ;

args_opt
    : %empty                                 { $$ = hfx_parse_vec_new(); }
    | args
    ;

args
    : assign                                 { $$ = hfx_parse_vec_one(ctx, $1); }
    | args ',' assign                        { $$ = hfx_parse_vec_push(ctx, $1, $3); }
    ;

%%

static void yyerror(YYLTYPE *loc, parse_ctx *ctx, const char *msg) {
    hfx_parse_report_failure(ctx, *loc, msg);
}

static int yyreport_syntax_error(const yypcontext_t *yyctx, parse_ctx *ctx) {
    hfx_parse_report_syntax(ctx, yypcontext_token(yyctx) == YYSYMBOL_YYEOF, *yypcontext_location(yyctx));
    return 0;
}

hfx_ast *hfx_parse(hfx_arena *arena, hfx_diags *diags, hfx_types *types, struct hfx_token *tokens) {
    parse_ctx ctx;
    if (hfx_parse_ctx_init(&ctx, arena, diags, types, tokens)) (void)yyparse(&ctx);
    return hfx_parse_ctx_finish(&ctx);
}
