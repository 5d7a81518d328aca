/* preprocess.c: the fxc-compatible preprocessor's main loop and directives, working on token
 * lists as chibicc does: directives are done, macros expanded in place, included files spliced
 * into the list (their TK_EOF links back to the includer and pops an include frame). Every
 * error is reported where it happens and preprocessing goes on. #line is applied at the end:
 * tokens keep physical locations while preprocessing, and a per-file table maps them. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pp/pp_internal.h"
#include "pp/token_cache.h"

/* ---- diagnostics and small helpers ---- */

static pp_line_map *find_map(hfx_pp *pp, hfx_loc loc) {
    if (loc.file >= pp->files_cap) return NULL;
    pp_file_info *fi = &pp->files[loc.file];
    pp_line_map *best = NULL;
    uint32_t lo = 0, hi = fi->map_count;
    while (lo < hi) { /* last map with from <= line */
        uint32_t mid = (lo + hi) / 2;
        if (fi->maps[mid].from <= loc.line) { best = &fi->maps[mid]; lo = mid + 1; }
        else hi = mid;
    }
    return best;
}

hfx_loc hfx_pp_map_loc(hfx_pp *pp, hfx_loc loc) {
    pp_line_map *m = pp->has_line_maps ? find_map(pp, loc) : NULL;
    if (!m) return loc;
    int64_t line = (int64_t)loc.line + m->delta;
    return (hfx_loc){m->file, line < 0 ? 0 : line > UINT32_MAX ? UINT32_MAX : (uint32_t)line, loc.col};
}

void hfx_pp_error(hfx_pp *pp, hfx_loc loc, unsigned code, const char *fmt, ...) {
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    hfx_error(pp->diags, hfx_pp_map_loc(pp, loc), code, "%s", buf);
}

void hfx_pp_warning(hfx_pp *pp, hfx_loc loc, unsigned code, const char *fmt, ...) {
    char buf[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    hfx_warning(pp->diags, hfx_pp_map_loc(pp, loc), code, "%s", buf);
}

void hfx_pp_check_string(hfx_pp *pp, hfx_token *t) {
    if (!(t->flags & TF_UNTERMINATED)) return;
    t->flags &= ~(uint32_t)TF_UNTERMINATED;
    hfx_pp_error(pp, t->spelling, X_PP_STRING_EOL, "newline in string literal");
}

hfx_token *hfx_pp_new_eof(hfx_pp *pp, hfx_loc loc) {
    hfx_token *t = hfx_arena_alloc_raw(pp->arena, sizeof *t);
    *t = (hfx_token){.kind = TK_EOF, .text = "", .loc = loc, .spelling = loc};
    return t;
}

hfx_token *hfx_pp_copy_token(hfx_pp *pp, const hfx_token *t) {
    hfx_token *c = hfx_arena_alloc_raw(pp->arena, sizeof *c);
    *c = *t;
    c->next = NULL;
    return c;
}

pp_file_info *hfx_pp_file(hfx_pp *pp, uint32_t file) {
    if (file >= pp->files_cap) {
        uint32_t cap = pp->files_cap ? pp->files_cap : 8;
        while (cap <= file) cap *= 2;
        pp_file_info *files = HFX_NEW_ARRAY(pp->arena, pp_file_info, cap);
        if (pp->files_cap) memcpy(files, pp->files, sizeof *files * pp->files_cap);
        pp->files = files;
        pp->files_cap = cap;
    }
    return &pp->files[file];
}

static bool is_ident(const hfx_token *t, const char *s) { return t->kind == TK_IDENT && strcmp(t->text, s) == 0; }

static bool is_punct(const hfx_token *t, hfx_punct p) { return t->kind == TK_PUNCT && t->punct == p; }

/* Extra tokens after a directive's operands: fxc warns and ignores them. */
static void check_line_end(hfx_pp *pp, const hfx_token *t, const char *directive) {
    if (t->kind != TK_EOF)
        hfx_pp_warning(pp, t->loc, X_PP_UNEXPECTED_TOKENS,
                   "unexpected tokens following preprocessor directive - expected a newline");
    (void)directive;
}

/* ---- include frames and conditionals ---- */

static void push_frame(hfx_pp *pp, uint32_t file) {
    if (!HFX_ARENA_GROW(pp->arena, pp->frames, pp->frame_count, pp->frame_cap, 16)) return;
    pp->frames[pp->frame_count++] = (pp_frame){file, pp->cond_count};
}

static pp_frame *top_frame(hfx_pp *pp) { return &pp->frames[pp->frame_count - 1]; }

static void push_cond(hfx_pp *pp, hfx_loc loc, const char *name, bool taken) {
    if (!HFX_ARENA_GROW(pp->arena, pp->conds, pp->cond_count, pp->cond_cap, 16)) return;
    pp->conds[pp->cond_count++] = (pp_cond){loc, name, taken, false};
}

/* Conditionals are per file: the ones a file leaves open are errors at its end. */
static void close_file_conds(hfx_pp *pp) {
    pp_frame *f = top_frame(pp);
    while (pp->cond_count > f->cond_base) {
        pp_cond *c = &pp->conds[--pp->cond_count];
        hfx_pp_error(pp, c->loc, X_PP_UNEXPECTED_EOF, "unterminated '#%s'", c->name);
    }
}

/* Skips a group whose condition is false: returns the '#' of the #elif / #else / #endif that
 * ends it (nested groups are skipped whole), or the TK_EOF. */
static hfx_token *skip_group(hfx_token *tok) {
    uint32_t depth = 0;
    for (; tok->kind != TK_EOF; tok = tok->next) {
        if (tok->kind != TK_HASH || !(tok->flags & TF_BOL)) continue;
        hfx_token *n = tok->next;
        if (n->kind != TK_IDENT || (n->flags & TF_BOL)) continue;
        if (is_ident(n, "if") || is_ident(n, "ifdef") || is_ident(n, "ifndef")) depth++;
        else if (is_ident(n, "endif") && depth) depth--;
        else if (!depth && (is_ident(n, "elif") || is_ident(n, "else") || is_ident(n, "endif"))) return tok;
    }
    return tok;
}

static pp_cond *current_cond(hfx_pp *pp) {
    return pp->cond_count > top_frame(pp)->cond_base ? &pp->conds[pp->cond_count - 1] : NULL;
}

/* ---- directives ---- */

static hfx_token *do_if(hfx_pp *pp, hfx_token *hash, hfx_token *name) {
    hfx_token *rest;
    hfx_token *line = hfx_pp_copy_line(pp, name->next, &rest);
    bool value;
    if (is_ident(name, "if")) {
        value = hfx_pp_eval_condition(pp, line, hash->loc);
    } else {
        if (line->kind != TK_IDENT) {
            hfx_pp_error(pp, line->kind == TK_EOF ? name->loc : line->loc, X_PP_SYNTAX,
                     "#%s: identifier expected", name->text);
            value = false;
        } else {
            value = (hfx_pp_find_macro(pp, line->text) != NULL) == is_ident(name, "ifdef");
            check_line_end(pp, line->next, name->text);
        }
    }
    push_cond(pp, hash->loc, name->text, value);
    return value ? rest : skip_group(rest);
}

static hfx_token *do_elif_else(hfx_pp *pp, hfx_token *hash, hfx_token *name) {
    hfx_token *rest;
    hfx_token *line = hfx_pp_copy_line(pp, name->next, &rest);
    pp_cond *c = current_cond(pp);
    if (!c) {
        hfx_pp_error(pp, hash->loc, is_ident(name, "elif") ? X_PP_UNEXPECTED_ELIF : X_PP_UNEXPECTED_ELSE,
                 "unexpected #%s", name->text);
        return rest;
    }
    if (c->seen_else) {
        hfx_pp_error(pp, hash->loc, is_ident(name, "elif") ? X_PP_ELIF_AFTER_ELSE : X_PP_ELSE_AFTER_ELSE,
                 "#%s after #else", name->text);
        return skip_group(rest);
    }
    if (is_ident(name, "else")) {
        c->seen_else = true;
        check_line_end(pp, line, "else");
        if (c->taken) return skip_group(rest);
        c->taken = true;
        return rest;
    }
    if (c->taken) return skip_group(rest); /* the expression of a later #elif is never evaluated */
    c->taken = hfx_pp_eval_condition(pp, line, hash->loc);
    return c->taken ? rest : skip_group(rest);
}

static hfx_token *do_endif(hfx_pp *pp, hfx_token *hash, hfx_token *name) {
    hfx_token *rest;
    hfx_token *line = hfx_pp_copy_line(pp, name->next, &rest);
    if (!current_cond(pp)) hfx_pp_error(pp, hash->loc, X_PP_UNEXPECTED_ENDIF, "unexpected #endif");
    else pp->cond_count--;
    check_line_end(pp, line, "endif");
    return rest;
}

/* The file name of an #include line: "x" or <x>, after macro expansion when neither. */
static const char *include_name(hfx_pp *pp, hfx_token *line, bool *angled, bool expanded, bool *reported) {
    if (line->kind == TK_STRING && (line->flags & TF_UNTERMINATED)) {
        hfx_pp_check_string(pp, line);
        *reported = true;
        return NULL;
    }
    if (line->kind == TK_STRING && line->len >= 2) {
        *angled = false;
        check_line_end(pp, line->next, "include");
        return hfx_arena_strndup(pp->arena, line->text + 1, line->len - 2);
    }
    if (is_punct(line, P_LT)) {
        hfx_token *end = line->next;
        while (end->kind != TK_EOF && !is_punct(end, P_GT)) end = end->next;
        if (end->kind == TK_EOF) {
            hfx_pp_error(pp, line->loc, X_PP_SYNTAX, "missing '>' in #include <file>");
            *reported = true;
            return NULL;
        }
        *angled = true;
        check_line_end(pp, end->next, "include");
        return hfx_pp_join(pp, line->next, end);
    }
    if (!expanded && line->kind != TK_EOF) {
        pp->expansion_tokens = 0;
        return include_name(pp, hfx_pp_expand_all(pp, line), angled, true, reported);
    }
    return NULL;
}

static bool once_seen(hfx_pp *pp, const char *real) {
    for (uint32_t i = 0; real && i < pp->once_count; i++)
        if (strcmp(pp->once[i], real) == 0) return true;
    return false;
}

static bool on_include_stack(hfx_pp *pp, const char *real) {
    for (uint32_t i = 0; real && i < pp->frame_count; i++) {
        const char *r = hfx_pp_file(pp, pp->frames[i].file)->real;
        if (r && strcmp(r, real) == 0) return true;
    }
    return false;
}

/* Every byte of source read raises the compile's memory limit (hfxc.h: HFXC_MEMORY_PER_BYTE). */
static void admit_source(hfx_pp *pp, uint32_t size) {
    pp->source_bytes += size;
    if (pp->arena->limit) pp->arena->limit += (size_t)HFXC_MEMORY_PER_BYTE * size;
}

static hfx_token *do_include(hfx_pp *pp, hfx_token *hash, hfx_token *name) {
    hfx_token *rest;
    hfx_token *line = hfx_pp_copy_line(pp, name->next, &rest);
    bool angled = false, reported = false;
    const char *file = include_name(pp, line, &angled, false, &reported);
    if (!file) {
        if (!reported) hfx_pp_error(pp, hash->loc, X_PP_SYNTAX, "#include expects \"FILENAME\" or <FILENAME>");
        return rest;
    }
    const char *dir = hfx_pp_file(pp, top_frame(pp)->file)->dir;
    const char *path = hfx_pp_find_include(pp, file, angled, dir);
    uint32_t size = 0;
    char *text = path ? hfx_pp_read_file(pp->arena, path, &size) : NULL;
    if (!text && size > HFXC_MAX_SOURCE_BYTES) {
        hfx_pp_error(pp, hash->loc, X_SOURCE_TOO_LARGE, "'%s' is %u bytes: hfx compiles source files of up to %u MiB", file,
                 size, HFXC_MAX_SOURCE_BYTES >> 20);
        return rest;
    }
    if (!text) {
        hfx_pp_error(pp, hash->loc, X_PP_INCLUDE, "failed to open source file: '%s'", file);
        return rest;
    }
    const char *real = hfx_pp_realpath(pp->arena, path);
    if (once_seen(pp, real)) return rest;
    if (pp->frame_count >= pp->max_include_depth) {
        if (on_include_stack(pp, real))
            hfx_pp_error(pp, hash->loc, X_PP_TOO_MANY_INCLUDES, "#include cycle: '%s' includes itself (nesting depth %u)",
                     file, pp->frame_count);
        else
            hfx_pp_error(pp, hash->loc, X_PP_TOO_MANY_INCLUDES, "#include nested too deeply (more than %u files)",
                     pp->max_include_depth);
        return rest;
    }
    admit_source(pp, size);
    uint32_t f = hfx_diags_add_file(pp->diags, file, path, text, size);
    pp_file_info *fi = hfx_pp_file(pp, f);
    fi->dir = hfx_pp_dirname(pp->arena, path);
    fi->real = real;
    hfx_token *toks = hfx_token_cache_tokenize(pp->opt ? pp->opt->cache : NULL, pp->arena, pp->diags, f, real);
    hfx_token *eof = toks;
    while (eof->kind != TK_EOF) eof = eof->next;
    eof->next = rest;
    push_frame(pp, f);
    return toks;
}

/* A string literal's contents with \\ and \" undone (#line names are strings, unlike #include's). */
static char *unescape_string(hfx_pp *pp, const hfx_token *t) {
    char *out = hfx_arena_alloc(pp->arena, t->len), *o = out;
    for (uint32_t i = 1; i + 1 < t->len; i++) {
        if (t->text[i] == '\\' && i + 2 < t->len && (t->text[i + 1] == '\\' || t->text[i + 1] == '"')) i++;
        *o++ = t->text[i];
    }
    *o = 0;
    return out;
}

static hfx_token *do_line(hfx_pp *pp, hfx_token *hash, hfx_token *name) {
    hfx_token *rest;
    hfx_token *line = hfx_pp_copy_line(pp, name->next, &rest);
    /* The line after the directive gets the new number (the directive may span lines). */
    uint32_t from = name->loc.line + 1;
    for (hfx_token *t = line; t->kind != TK_EOF; t = t->next)
        if (t->loc.line >= from) from = t->loc.line + 1;
    pp->expansion_tokens = 0;
    line = hfx_pp_expand_all(pp, line);
    const char *digits = line->kind == TK_INT ? line->text : "";
    uint64_t n = 0;
    bool ok = *digits != 0;
    for (const char *p = digits; *p && ok; p++) {
        ok = *p >= '0' && *p <= '9';
        n = n * 10 + (uint64_t)(*p - '0');
        if (n > 2147483647u) ok = false;
    }
    if (!ok) {
        hfx_pp_error(pp, line->kind == TK_EOF ? hash->loc : line->loc, X_PP_SYNTAX,
                 "#line: expected a line number between 0 and 2147483647");
        return rest;
    }
    hfx_token *fname = line->next;
    pp_line_map map = {from, (int64_t)n - (int64_t)from, 0};
    pp_line_map *prev = find_map(pp, hash->loc);
    map.file = prev ? prev->file : hash->loc.file;
    bool cut_short = fname->flags & TF_UNTERMINATED;
    hfx_pp_check_string(pp, fname);
    if (fname->kind == TK_STRING && fname->len >= 2 && !cut_short) {
        const hfx_source *src = &pp->diags->files[hash->loc.file];
        char *n2 = unescape_string(pp, fname);
        map.file = hfx_diags_add_file(pp->diags, n2, src->path, src->text, src->size);
        hfx_pp_file(pp, map.file);
        fname = fname->next;
    }
    check_line_end(pp, fname, "line");
    pp_file_info *fi = hfx_pp_file(pp, hash->loc.file);
    if (!HFX_ARENA_GROW(pp->arena, fi->maps, fi->map_count, fi->map_cap, 4)) return rest;
    fi->maps[fi->map_count++] = map;
    pp->has_line_maps = true;
    return rest;
}

/* #pragma pack_matrix(x) is left in the token list as "__hfx_pack_matrix ( x )" for the parser. */
static hfx_token *pack_matrix(hfx_pp *pp, hfx_token *kw, hfx_token *rest) {
    hfx_token *open = kw->next, *arg = open->next, *close = arg->next;
    if (!is_punct(open, P_LPAREN) || !(is_ident(arg, "row_major") || is_ident(arg, "column_major")) ||
        !is_punct(close, P_RPAREN)) {
        hfx_pp_warning(pp, kw->loc, X_PP_UNKNOWN_PRAGMA,
                   "'pack_matrix' : expected (row_major) or (column_major), pragma ignored");
        return rest;
    }
    check_line_end(pp, close->next, "pragma");
    kw->text = "__hfx_pack_matrix";
    kw->len = (uint32_t)strlen(kw->text);
    kw->flags = TF_BOL | TF_NOEXPAND;
    arg->flags |= TF_NOEXPAND;
    close->next = rest;
    return kw;
}

static hfx_token *do_pragma(hfx_pp *pp, hfx_token *hash, hfx_token *name) {
    hfx_token *rest;
    hfx_token *line = hfx_pp_copy_line(pp, name->next, &rest);
    if (line->kind == TK_EOF) return rest;
    if (is_ident(line, "once")) {
        const char *real = hfx_pp_file(pp, top_frame(pp)->file)->real;
        if (real && !once_seen(pp, real)) {
            if (!HFX_ARENA_GROW(pp->arena, pp->once, pp->once_count, pp->once_cap, 8)) return rest;
            pp->once[pp->once_count++] = real;
        }
        return rest;
    }
    if (is_ident(line, "pack_matrix")) return pack_matrix(pp, line, rest);
    if (is_ident(line, "message")) {
        hfx_token *t = line->next;
        if (is_punct(t, P_LPAREN)) t = t->next;
        if (t->kind == TK_STRING && t->len >= 2)
            hfx_note(pp->diags, hfx_pp_map_loc(pp, hash->loc), "%.*s", (int)(t->len - 2), t->text + 1);
        return rest;
    }
    /* fxc's other pragmas change nothing that GLSL output depends on. */
    if (is_ident(line, "warning") || is_ident(line, "def") || is_ident(line, "ruledisable")) return rest;
    hfx_pp_warning(pp, line->loc, X_PP_UNKNOWN_PRAGMA, "'%s' : unknown pragma ignored", line->text);
    return rest;
}

/* An #error with no text still says what stopped the compile (an empty message reads as a bug). */
static hfx_token *do_error(hfx_pp *pp, hfx_token *hash, hfx_token *name) {
    hfx_token *end = hfx_pp_line_end(name->next);
    const char *text = hfx_pp_join(pp, name->next, end);
    hfx_pp_error(pp, hash->loc, X_PP_ERROR_DIRECTIVE, "%s", text && *text ? text : "#error");
    return end;
}

/* Runs the directive whose '#' is hash; returns the token to go on with. */
static hfx_token *directive(hfx_pp *pp, hfx_token *hash) {
    hfx_token *name = hash->next;
    if (name->kind == TK_EOF || (name->flags & TF_BOL)) return name; /* the null directive */
    hfx_token *rest;
    if (is_ident(name, "define")) {
        hfx_token *line = hfx_pp_copy_line(pp, name->next, &rest);
        hfx_pp_define(pp, line, name->loc);
        return rest;
    }
    if (is_ident(name, "undef")) {
        hfx_token *line = hfx_pp_copy_line(pp, name->next, &rest);
        if (line->kind != TK_IDENT) hfx_pp_error(pp, name->loc, X_PP_SYNTAX, "#undef: identifier expected");
        else {
            hfx_pp_undef(pp, line->text);
            check_line_end(pp, line->next, "undef");
        }
        return rest;
    }
    if (is_ident(name, "include")) return do_include(pp, hash, name);
    if (is_ident(name, "if") || is_ident(name, "ifdef") || is_ident(name, "ifndef")) return do_if(pp, hash, name);
    if (is_ident(name, "elif") || is_ident(name, "else")) return do_elif_else(pp, hash, name);
    if (is_ident(name, "endif")) return do_endif(pp, hash, name);
    if (is_ident(name, "line")) return do_line(pp, hash, name);
    if (is_ident(name, "pragma")) return do_pragma(pp, hash, name);
    if (is_ident(name, "error")) return do_error(pp, hash, name);
    hfx_pp_error(pp, name->loc, X_PP_INVALID_COMMAND, "invalid preprocessor command '%s'", name->text);
    return hfx_pp_line_end(name);
}

/* ---- the main loop ---- */

static hfx_token *run(hfx_pp *pp, hfx_token *tok) {
    hfx_token head = {0}, *cur = &head;
    for (;;) {
        if (tok->kind == TK_EOF) {
            close_file_conds(pp);
            if (pp->frame_count > 1) { /* the end of an included file */
                pp->frame_count--;
                tok = tok->next;
                continue;
            }
            cur->next = tok;
            tok->next = NULL;
            return head.next;
        }
        if (tok->kind == TK_HASH && (tok->flags & TF_BOL) && !tok->hideset) {
            tok = directive(pp, tok);
            continue;
        }
        if (!tok->hideset) pp->expansion_tokens = 0;
        if (tok->flags & TF_UNTERMINATED) hfx_pp_check_string(pp, tok);
        if (tok->kind == TK_IDENT && hfx_pp_expand_macro(pp, &tok, tok)) continue;
        cur = cur->next = tok;
        tok = tok->next;
    }
}

static void apply_line_maps(hfx_pp *pp, hfx_token *list) {
    if (!pp->has_line_maps) return;
    for (hfx_token *t = list; t; t = t->next) {
        t->loc = hfx_pp_map_loc(pp, t->loc);
        t->spelling = hfx_pp_map_loc(pp, t->spelling);
    }
}

static void define_options(hfx_pp *pp, const hfx_pp_options *opt) {
    if (!opt || !opt->define_count) return;
    uint32_t f = hfx_diags_add_file(pp->diags, "<command line>", NULL, "", 0);
    hfx_pp_file(pp, f);
    for (uint32_t i = 0; i < opt->define_count; i++)
        if (opt->defines[i]) hfx_pp_define_option(pp, opt->defines[i], (hfx_loc){f, 1, 1});
}

hfx_token *hfx_preprocess(hfx_arena *arena, hfx_diags *diags, const char *name, const char *text,
                          uint32_t size, const hfx_pp_options *opt) {
    hfx_pp *pp = HFX_NEW(arena, hfx_pp);
    pp->arena = arena;
    pp->diags = diags;
    pp->opt = opt;
    pp->max_include_depth = opt && opt->max_include_depth ? opt->max_include_depth : PP_DEFAULT_INCLUDE_DEPTH;
    pp->eof = hfx_pp_new_eof(pp, (hfx_loc){0, 0, 0});
    if (!name) name = "memory";
    bool too_large = text && size > HFXC_MAX_SOURCE_BYTES;
    char *copy = too_large ? NULL : text ? hfx_arena_strndup(arena, text, size) : hfx_pp_read_file(arena, name, &size);
    if (copy && text) copy = hfx_pp_decode_source(arena, copy, &size);
    uint32_t f = hfx_diags_add_file(diags, name, text ? NULL : name, copy ? copy : "", copy ? size : 0);
    if (!copy && size > HFXC_MAX_SOURCE_BYTES) {
        hfx_error(diags, (hfx_loc){f, 1, 1}, X_SOURCE_TOO_LARGE, "the source is %u bytes: hfx compiles source files of up to %u MiB",
                  size, HFXC_MAX_SOURCE_BYTES >> 20);
        return hfx_pp_new_eof(pp, (hfx_loc){f, 1, 1});
    }
    if (!copy) {
        hfx_error(diags, (hfx_loc){f, 1, 1}, X_PP_INCLUDE, "failed to open source file: '%s'", name);
        return hfx_pp_new_eof(pp, (hfx_loc){f, 1, 1});
    }
    admit_source(pp, size);
    pp_file_info *fi = hfx_pp_file(pp, f);
    fi->dir = pp->root_dir = hfx_pp_dirname(arena, name);
    fi->real = text ? NULL : hfx_pp_realpath(arena, name);
    push_frame(pp, f);
    hfx_pp_define_builtins(pp);
    define_options(pp, opt);
    hfx_token *out = run(pp, hfx_tokenize_deferred(arena, diags, f));
    apply_line_maps(pp, out);
    return out;
}
