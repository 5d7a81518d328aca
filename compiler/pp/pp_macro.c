/* pp_macro.c: the macro table, #define parsing and macro expansion. Expansion follows
 * Prosser's algorithm as C describes it: each token carries the set of macros it came out of
 * (its hideset) and never expands as one of those again, so a macro cannot expand inside
 * itself. That always terminates, but output can still grow exponentially, so the tokens one
 * top-level use may produce and the nesting depth are bounded: past them the expansion stops
 * with a located error. */
#include <stdio.h>
#include <string.h>

#include "pp/pp_internal.h"

/* ---- the table ---- */

static unsigned hash_name(const char *s) {
    unsigned h = 2166136261u;
    for (; *s; s++) h = (h ^ (unsigned char)*s) * 16777619u;
    return h % PP_MACRO_BUCKETS;
}

/* The bit of macro_starts for a name (an identifier's bytes are ASCII; others share bits). */
static uint32_t start_bit(const char *name) {
    uint32_t a = (unsigned char)name[0] & 127u, b = a ? (unsigned char)name[1] & 127u : 0;
    return a * 128 + b;
}

pp_macro *hfx_pp_find_macro(hfx_pp *pp, const char *name) {
    uint32_t bit = start_bit(name);
    if (!(pp->macro_starts[bit / 64] >> (bit % 64) & 1)) return NULL;
    for (pp_macro *m = pp->macros[hash_name(name)]; m; m = m->next)
        if (strcmp(m->name, name) == 0) return m;
    return NULL;
}

void hfx_pp_undef(hfx_pp *pp, const char *name) {
    for (pp_macro **p = &pp->macros[hash_name(name)]; *p; p = &(*p)->next) {
        if (strcmp((*p)->name, name) == 0) {
            *p = (*p)->next;
            return;
        }
    }
}

static void add_macro(hfx_pp *pp, pp_macro *m) {
    hfx_pp_undef(pp, m->name);
    uint32_t bit = start_bit(m->name);
    pp->macro_starts[bit / 64] |= (uint64_t)1 << (bit % 64);
    unsigned h = hash_name(m->name);
    m->next = pp->macros[h];
    pp->macros[h] = m;
}

void hfx_pp_define_builtins(hfx_pp *pp) {
    static const struct { const char *name; pp_builtin kind; } builtins[] = {
        {"__FILE__", PP_BUILTIN_FILE}, {"__LINE__", PP_BUILTIN_LINE}};
    for (size_t i = 0; i < sizeof builtins / sizeof builtins[0]; i++) {
        pp_macro *m = HFX_NEW(pp->arena, pp_macro);
        m->name = builtins[i].name;
        m->builtin = builtins[i].kind;
        m->body = pp->eof;
        add_macro(pp, m);
    }
}

/* ---- token helpers ---- */

static bool is_punct(const hfx_token *t, hfx_punct p) { return t->kind == TK_PUNCT && t->punct == p; }

hfx_token *hfx_pp_line_end(hfx_token *tok) {
    while (tok->kind != TK_EOF && !(tok->flags & TF_BOL)) tok = tok->next;
    return tok;
}

hfx_token *hfx_pp_copy_line(hfx_pp *pp, hfx_token *tok, hfx_token **rest) {
    hfx_token head = {0}, *cur = &head;
    hfx_token *end = hfx_pp_line_end(tok);
    for (; tok != end; tok = tok->next) cur = cur->next = hfx_pp_copy_token(pp, tok);
    cur->next = hfx_pp_new_eof(pp, end->loc);
    *rest = end;
    return head.next;
}

char *hfx_pp_join(hfx_pp *pp, const hfx_token *from, const hfx_token *to) {
    size_t len = 1;
    for (const hfx_token *t = from; t != to && t->kind != TK_EOF; t = t->next) len += t->len + 1;
    char *buf = hfx_arena_alloc(pp->arena, len), *p = buf;
    for (const hfx_token *t = from; t != to && t->kind != TK_EOF; t = t->next) {
        if (t != from && (t->flags & TF_SPACE)) *p++ = ' ';
        memcpy(p, t->text, t->len);
        p += t->len;
    }
    *p = 0;
    return buf;
}

/* ---- hidesets ---- */

/* Names in hidesets are always a pp_macro's own name string, so pointers compare. (A macro
 * redefined while its old expansion is still being read would only expand once more.) */
static bool hs_contains(hfx_pp *pp, const pp_hideset *hs, const char *name) {
    for (; hs; hs = hs->next) {
        pp->work++;
        if (hs->name == name) return true;
    }
    return false;
}

static const pp_hideset *hs_add(hfx_pp *pp, const pp_hideset *hs, const char *name) {
    if (hs_contains(pp, hs, name)) return hs;
    pp_hideset *n = HFX_NEW(pp->arena, pp_hideset);
    n->name = name;
    n->next = hs;
    return n;
}

static const pp_hideset *hs_union(hfx_pp *pp, const pp_hideset *a, const pp_hideset *b) {
    if (!a) return b;
    if (!b || a == b) return a;
    /* Nested expansions share list tails: when one set is the tail of the other, that is the union. */
    for (const pp_hideset *p = b; p; p = p->next)
        if (p == a) return b;
    for (const pp_hideset *p = a; p; p = p->next)
        if (p == b) return a;
    for (; a; a = a->next) b = hs_add(pp, b, a->name);
    return b;
}

static const pp_hideset *hs_intersection(hfx_pp *pp, const pp_hideset *a, const pp_hideset *b) {
    if (a == b) return a; /* the name and its ')' came out of the same expansion */
    const pp_hideset *out = NULL;
    for (; a; a = a->next)
        if (hs_contains(pp, b, a->name)) out = hs_add(pp, out, a->name);
    return out;
}

static uint32_t hs_length(const pp_hideset *hs) {
    uint32_t n = 0;
    for (; hs; hs = hs->next) n++;
    return n;
}

/* ---- #define ---- */

static int param_index(const pp_macro *m, const hfx_token *t) {
    if (!m->function_like || t->kind != TK_IDENT) return -1;
    for (uint32_t i = 0; i < m->param_count; i++)
        if (strcmp(m->params[i], t->text) == 0) return (int)i;
    return -1;
}

/* Reads "(a, b, ...)" after a function-like macro's name; returns the body's first token or NULL. */
static hfx_token *parse_params(hfx_pp *pp, pp_macro *m, hfx_token *t) {
    const char *names[256];
    uint32_t n = 0;
    t = t->next;
    if (is_punct(t, P_RPAREN)) return t->next;
    for (;;) {
        if (is_punct(t, P_ELLIPSIS)) {
            m->variadic = true;
            names[n++] = "__VA_ARGS__";
            t = t->next;
        } else if (t->kind == TK_IDENT) {
            for (uint32_t i = 0; i < n; i++)
                if (strcmp(names[i], t->text) == 0) {
                    hfx_pp_error(pp, t->loc, X_PP_DUPLICATE_PARAMETER, "'%s' : duplicate macro parameter", t->text);
                    return NULL;
                }
            if (n == sizeof names / sizeof names[0]) {
                hfx_pp_error(pp, t->loc, X_PP_SYNTAX, "too many macro parameters");
                return NULL;
            }
            names[n++] = t->text;
            t = t->next;
            if (is_punct(t, P_ELLIPSIS)) { /* GNU named variadic: "args..." */
                m->variadic = true;
                t = t->next;
            }
        } else {
            hfx_pp_error(pp, t->loc, X_PP_SYNTAX, "expected a macro parameter name, found '%s'",
                     t->kind == TK_EOF ? "end of line" : t->text);
            return NULL;
        }
        if (is_punct(t, P_RPAREN)) break;
        if (m->variadic || !is_punct(t, P_COMMA)) {
            hfx_pp_error(pp, t->loc, X_PP_SYNTAX, "expected ')' in macro parameter list");
            return NULL;
        }
        t = t->next;
    }
    m->param_count = n;
    m->params = HFX_NEW_ARRAY(pp->arena, const char *, n);
    memcpy(m->params, names, sizeof *names * n);
    return t->next;
}

static bool body_is_valid(hfx_pp *pp, const pp_macro *m) {
    const hfx_token *first = m->body, *last = NULL;
    for (const hfx_token *t = m->body; t->kind != TK_EOF; t = t->next) {
        last = t;
        if (m->function_like && t->kind == TK_HASH && param_index(m, t->next) < 0) {
            hfx_pp_error(pp, t->loc, X_PP_SYNTAX, "'#' is not followed by a macro parameter");
            return false;
        }
    }
    if ((first->kind == TK_HASHHASH) || (last && last->kind == TK_HASHHASH)) {
        hfx_pp_error(pp, first->kind == TK_HASHHASH ? first->loc : last->loc, X_PP_SYNTAX,
                 "'##' cannot occur at either end of a macro expansion");
        return false;
    }
    return true;
}

static bool same_definition(const pp_macro *a, const pp_macro *b) {
    if (a->builtin || b->builtin || a->function_like != b->function_like || a->variadic != b->variadic ||
        a->param_count != b->param_count)
        return false;
    for (uint32_t i = 0; i < a->param_count; i++)
        if (strcmp(a->params[i], b->params[i]) != 0) return false;
    const hfx_token *x = a->body, *y = b->body;
    for (; x->kind != TK_EOF && y->kind != TK_EOF; x = x->next, y = y->next) {
        if (x->kind != y->kind || strcmp(x->text, y->text) != 0) return false;
        if (x != a->body && (x->flags & TF_SPACE) != (y->flags & TF_SPACE)) return false;
    }
    return x->kind == y->kind;
}

void hfx_pp_define(hfx_pp *pp, hfx_token *line, hfx_loc directive) {
    hfx_token *name = line;
    if (name->kind != TK_IDENT) {
        hfx_pp_error(pp, name->kind == TK_EOF ? directive : name->loc, X_PP_SYNTAX, "#define: macro name expected");
        return;
    }
    if (strcmp(name->text, "defined") == 0) {
        hfx_pp_error(pp, name->loc, X_PP_SYNTAX, "'defined' cannot be used as a macro name");
        return;
    }
    pp_macro *m = HFX_NEW(pp->arena, pp_macro);
    m->name = name->text;
    m->loc = name->loc;
    hfx_token *body = name->next;
    if (is_punct(body, P_LPAREN) && !(body->flags & TF_SPACE)) {
        m->function_like = true;
        body = parse_params(pp, m, body);
        if (!body) return;
    }
    m->body = body;
    for (hfx_token *t = body; t->kind != TK_EOF; t = t->next) hfx_pp_check_string(pp, t);
    if (!body_is_valid(pp, m)) return;
    pp_macro *old = hfx_pp_find_macro(pp, m->name);
    if (old && !same_definition(old, m))
        hfx_pp_warning(pp, name->loc, X_PP_MACRO_REDEFINITION, "'%s' : macro redefinition", m->name);
    add_macro(pp, m);
}

void hfx_pp_define_option(hfx_pp *pp, const char *def, hfx_loc loc) {
    const char *eq = strchr(def, '=');
    size_t name_len = eq ? (size_t)(eq - def) : strlen(def);
    char *text = hfx_arena_printf(pp->arena, "%.*s %s", (int)name_len, def, eq ? eq + 1 : "1");
    hfx_token *line = hfx_tokenize_text(pp->arena, pp->diags, text, (uint32_t)strlen(text), loc);
    for (hfx_token *t = line; t; t = t->next) t->flags &= ~(uint32_t)TF_BOL;
    hfx_pp_define(pp, line, loc);
}

/* ---- expansion ---- */

/* A token copy made by an expansion: charged to the work budget (a token costs 4 units). */
static hfx_token *copy_for_expansion(hfx_pp *pp, const hfx_token *t) {
    pp->work += 4;
    return hfx_pp_copy_token(pp, t);
}

/* The budget for all expansions of one preprocess call: past it, nothing expands any more. */
static bool over_budget(hfx_pp *pp, const hfx_token *use) {
    if (pp->work <= PP_MAX_EXPANSION_WORK + PP_EXPANSION_WORK_PER_BYTE * pp->source_bytes) return false;
    if (!pp->budget_reported)
        hfx_pp_error(pp, use->loc, X_PP_ERROR, "macro expansion is too complex: the preprocessor's work limit is exceeded");
    pp->budget_reported = true;
    return true;
}

typedef struct macro_arg {
    hfx_token *raw;      /* as written, ending with TK_EOF */
    hfx_token *expanded; /* fully macro-expanded, made on first use */
} macro_arg;

/* A token list under construction; tokens can be dropped from its end (GNU ", ## __VA_ARGS__"). */
typedef struct tok_vec {
    hfx_token **items;
    uint32_t count, cap;
} tok_vec;

static void vec_push(hfx_pp *pp, tok_vec *v, hfx_token *t) {
    if (!HFX_ARENA_GROW(pp->arena, v->items, v->count, v->cap, 32)) return;
    v->items[v->count++] = t;
}

/* Appends copies of an argument's tokens; the first takes the spacing of the parameter it replaces. */
static void vec_push_list(hfx_pp *pp, tok_vec *v, const hfx_token *list, const hfx_token *param) {
    uint32_t first = v->count;
    for (; list->kind != TK_EOF; list = list->next) vec_push(pp, v, copy_for_expansion(pp, list));
    if (v->count > first)
        v->items[first]->flags = (v->items[first]->flags & ~(uint32_t)TF_SPACE) | (param->flags & TF_SPACE);
}

static bool count_tokens(hfx_pp *pp, const hfx_token *use, uint32_t n) {
    pp->expansion_tokens += n;
    if (pp->expansion_tokens <= PP_MAX_EXPANSION_TOKENS) return true;
    if (!pp->runaway_reported)
        hfx_pp_error(pp, use->loc, X_PP_ERROR, "macro expansion produces more than %u tokens",
                 (unsigned)PP_MAX_EXPANSION_TOKENS);
    pp->runaway_reported = true;
    return false;
}

static hfx_token *builtin_token(hfx_pp *pp, const pp_macro *m, const hfx_token *use) {
    hfx_loc at = hfx_pp_map_loc(pp, use->loc);
    char *text;
    hfx_token_kind kind;
    if (m->builtin == PP_BUILTIN_LINE) {
        text = hfx_arena_printf(pp->arena, "%u", at.line);
        kind = TK_INT;
    } else {
        const char *name = at.file < pp->diags->file_count ? pp->diags->files[at.file].name : "";
        size_t n = strlen(name);
        text = hfx_arena_alloc(pp->arena, 2 * n + 3);
        char *p = text;
        *p++ = '"';
        for (size_t i = 0; i < n; i++) {
            if (name[i] == '"' || name[i] == '\\') *p++ = '\\';
            *p++ = name[i];
        }
        *p++ = '"';
        *p = 0;
        kind = TK_STRING;
    }
    hfx_token *t = hfx_pp_copy_token(pp, use);
    t->kind = kind;
    t->text = text;
    t->len = (uint32_t)strlen(text);
    return t;
}

/* "#x": the argument's spelling as a string literal. */
static hfx_token *stringize(hfx_pp *pp, const hfx_token *hash, const hfx_token *arg, const hfx_token *use) {
    size_t n = 3;
    for (const hfx_token *t = arg; t->kind != TK_EOF; t = t->next) n += 2 * t->len + 1;
    char *text = hfx_arena_alloc(pp->arena, n), *p = text;
    *p++ = '"';
    for (const hfx_token *t = arg; t->kind != TK_EOF; t = t->next) {
        if (t != arg && (t->flags & TF_SPACE)) *p++ = ' ';
        for (uint32_t i = 0; i < t->len; i++) {
            /* String literals of the argument keep their meaning: their quotes and backslashes
             * get escaped. */
            if (t->kind == TK_STRING && (t->text[i] == '"' || t->text[i] == '\\')) *p++ = '\\';
            *p++ = t->text[i];
        }
    }
    *p++ = '"';
    *p = 0;
    hfx_token *t = hfx_pp_copy_token(pp, hash);
    t->kind = TK_STRING;
    t->punct = 0;
    t->text = text;
    t->len = (uint32_t)(p - text);
    t->loc = use->loc;
    return t;
}

/* "a ## b": the two spellings joined and cut again. Pasting that does not make one token
 * keeps the pieces, as Microsoft's preprocessor does. */
static void paste(hfx_pp *pp, tok_vec *out, const hfx_token *rhs, const hfx_token *use) {
    hfx_token *lhs = out->items[--out->count];
    char *text = hfx_arena_printf(pp->arena, "%s%s", lhs->text, rhs->text);
    hfx_token *toks = hfx_tokenize_text(pp->arena, pp->diags, text, (uint32_t)strlen(text), use->loc);
    for (hfx_token *t = toks; t->kind != TK_EOF; t = t->next) {
        t->flags = t == toks ? lhs->flags : 0;
        t->spelling = lhs->spelling;
        t->hideset = hs_intersection(pp, lhs->hideset, rhs->hideset);
        t->loc = lhs->loc;
        vec_push(pp, out, t);
    }
}

static hfx_token *expanded_arg(hfx_pp *pp, macro_arg *arg, const hfx_token *use) {
    if (arg->expanded) return arg->expanded;
    if (pp->arg_depth >= PP_MAX_EXPANSION_DEPTH) {
        if (!pp->runaway_reported)
            hfx_pp_error(pp, use->loc, X_PP_ERROR, "macro arguments of '%s' nested too deeply", use->text);
        pp->runaway_reported = true;
        return arg->expanded = arg->raw;
    }
    hfx_token head = {0}, *cur = &head;
    for (const hfx_token *t = arg->raw; t->kind != TK_EOF; t = t->next) cur = cur->next = copy_for_expansion(pp, t);
    cur->next = hfx_pp_new_eof(pp, use->loc);
    pp->arg_depth++;
    arg->expanded = hfx_pp_expand_all(pp, head.next);
    pp->arg_depth--;
    return arg->expanded;
}

/* The body of m with its parameters replaced: #, ## and pre-expanded arguments. */
static void substitute(hfx_pp *pp, const pp_macro *m, macro_arg *args, const hfx_token *use, tok_vec *out) {
    bool placemarker = false; /* the last thing added was an empty argument */
    for (const hfx_token *t = m->body; t->kind != TK_EOF; t = t->next) {
        int p;
        if (out->count > PP_MAX_EXPANSION_TOKENS) return; /* count_tokens reports it */
        if (t->kind == TK_HASH && m->function_like && (p = param_index(m, t->next)) >= 0) {
            vec_push(pp, out, stringize(pp, t, args[p].raw, use));
            t = t->next;
            placemarker = false;
            continue;
        }
        if (t->kind == TK_HASHHASH) {
            const hfx_token *rhs = t->next;
            t = rhs;
            p = param_index(m, rhs);
            const hfx_token *list = p >= 0 ? args[p].raw : NULL;
            if (p >= 0 && list->kind == TK_EOF) {
                /* GNU: ", ## __VA_ARGS__" drops the comma when there are no variadic arguments. */
                if (m->variadic && (uint32_t)p == m->param_count - 1 && !placemarker && out->count &&
                    is_punct(out->items[out->count - 1], P_COMMA))
                    out->count--;
                continue; /* x ## <empty> is x */
            }
            if (placemarker || out->count == 0) {
                if (p >= 0) vec_push_list(pp, out, list, rhs);
                else vec_push(pp, out, copy_for_expansion(pp, rhs));
            } else if (p >= 0) {
                paste(pp, out, list, use);
                vec_push_list(pp, out, list->next, list->next);
            } else {
                paste(pp, out, rhs, use);
            }
            placemarker = false;
            continue;
        }
        if ((p = param_index(m, t)) >= 0) {
            bool pasted = t->next->kind == TK_HASHHASH;
            const hfx_token *list = pasted ? args[p].raw : expanded_arg(pp, &args[p], use);
            vec_push_list(pp, out, list, t);
            placemarker = list->kind == TK_EOF;
            continue;
        }
        hfx_token *copy = copy_for_expansion(pp, t);
        copy->loc = use->loc;
        vec_push(pp, out, copy);
        placemarker = false;
    }
}

/* Collects the arguments of a function-like macro use; tok is the '('. Returns the ')' or NULL. */
static hfx_token *collect_args(hfx_pp *pp, const pp_macro *m, const hfx_token *use, hfx_token *tok,
                               macro_arg **out) {
    uint32_t n = m->param_count ? m->param_count : 1;
    macro_arg *args = HFX_NEW_ARRAY(pp->arena, macro_arg, n);
    uint32_t count = 0, depth = 0;
    hfx_token head = {0}, *cur = &head;
    for (tok = tok->next;; tok = tok->next) {
        if (tok->kind == TK_EOF) {
            hfx_pp_error(pp, use->loc, X_PP_EOF_IN_MACRO, "unexpected end of file in macro expansion of '%s'", m->name);
            return NULL;
        }
        bool ends_arg = depth == 0 && (is_punct(tok, P_RPAREN) ||
                                       (is_punct(tok, P_COMMA) && !(m->variadic && count + 1 >= n)));
        if (ends_arg) {
            cur->next = hfx_pp_new_eof(pp, tok->loc);
            if (count < n) args[count].raw = head.next;
            count++;
            head.next = NULL;
            cur = &head;
            if (is_punct(tok, P_RPAREN)) break;
            continue;
        }
        if (is_punct(tok, P_LPAREN)) depth++;
        else if (is_punct(tok, P_RPAREN)) depth--;
        cur = cur->next = copy_for_expansion(pp, tok);
        cur->flags &= ~(uint32_t)TF_BOL;
        if (cur == head.next) cur->flags &= ~(uint32_t)TF_SPACE;
    }
    bool empty_va = m->variadic && count + 1 == n;
    if (count > n || (m->param_count == 0 && args[0].raw->kind != TK_EOF)) {
        hfx_pp_error(pp, use->loc, X_PP_MACRO_ARGUMENTS, "too many actual parameters for macro '%s'", m->name);
    } else if (count < n && !empty_va) {
        hfx_pp_error(pp, use->loc, X_PP_MACRO_ARGUMENTS, "not enough actual parameters for macro '%s'", m->name);
    }
    for (uint32_t i = count; i < n; i++) args[i].raw = pp->eof;
    *out = args;
    return tok;
}

static hfx_token *link_expansion(hfx_pp *pp, tok_vec *body, const pp_hideset *hs, const hfx_token *use,
                                 hfx_token *after) {
    const pp_hideset *last_in = NULL, *last_out = hs; /* runs of tokens share a hideset */
    for (uint32_t i = 0; i < body->count; i++) {
        hfx_token *t = body->items[i];
        if (t->hideset != last_in) {
            last_in = t->hideset;
            last_out = hs_union(pp, t->hideset, hs);
        }
        t->hideset = last_out;
        t->next = i + 1 < body->count ? body->items[i + 1] : after;
    }
    if (!body->count) return after;
    hfx_token *first = body->items[0];
    first->flags = (first->flags & ~(uint32_t)(TF_BOL | TF_SPACE)) | (use->flags & (TF_BOL | TF_SPACE));
    return first;
}

bool hfx_pp_expand_macro(hfx_pp *pp, hfx_token **rest, hfx_token *tok) {
    if (tok->kind != TK_IDENT || (tok->flags & TF_NOEXPAND)) return false;
    pp_macro *m = hfx_pp_find_macro(pp, tok->text);
    if (!m) return false;
    if (over_budget(pp, tok)) return false;
    if (hs_contains(pp, tok->hideset, m->name)) {
        tok->flags |= TF_NOEXPAND; /* painted blue: it stays an identifier for good */
        return false;
    }
    if (m->builtin) {
        hfx_token *t = builtin_token(pp, m, tok);
        t->next = tok->next;
        *rest = t;
        return true;
    }
    if (m->function_like && !is_punct(tok->next, P_LPAREN)) return false;
    if (hs_length(tok->hideset) >= PP_MAX_EXPANSION_DEPTH) {
        if (!pp->runaway_reported)
            hfx_pp_error(pp, tok->loc, X_PP_ERROR, "macro expansion of '%s' nested too deeply", m->name);
        pp->runaway_reported = true;
        return false;
    }
    if (pp->runaway_reported && pp->expansion_tokens > PP_MAX_EXPANSION_TOKENS) return false;
    tok_vec body = {0};
    if (!m->function_like) {
        substitute(pp, m, NULL, tok, &body);
        if (!count_tokens(pp, tok, body.count)) return false;
        *rest = link_expansion(pp, &body, hs_add(pp, tok->hideset, m->name), tok, tok->next);
        return true;
    }
    macro_arg *args;
    hfx_token *rparen = collect_args(pp, m, tok, tok->next, &args);
    if (!rparen) {
        tok->flags |= TF_NOEXPAND;
        return false;
    }
    substitute(pp, m, args, tok, &body);
    if (!count_tokens(pp, tok, body.count)) return false;
    const pp_hideset *hs = hs_add(pp, hs_intersection(pp, tok->hideset, rparen->hideset), m->name);
    *rest = link_expansion(pp, &body, hs, tok, rparen->next);
    return true;
}

hfx_token *hfx_pp_expand_all(hfx_pp *pp, hfx_token *list) {
    hfx_token head = {0}, *cur = &head;
    for (hfx_token *tok = list;;) {
        if (tok->kind == TK_EOF) {
            cur->next = tok;
            break;
        }
        if (hfx_pp_expand_macro(pp, &tok, tok)) continue;
        cur = cur->next = tok;
        tok = tok->next;
    }
    return head.next;
}
