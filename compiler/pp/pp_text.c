/* pp_text.c: a token list back to text, for fxc's /P (preprocess to a file). Lines are kept in
 * step with the source so that compiling the output reports the same line numbers: blank lines
 * fill small gaps, a #line directive marks a change of file or a large jump. */
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/sbuf.h"
#include "pp/token.h"

typedef sbuf text_buf;

static void put(text_buf *b, const char *s, size_t n) { hfx_sb_putn(b, s, n); }
static void put_str(text_buf *b, const char *s) { put(b, s, strlen(s)); }

static bool is_word_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
}

/* Whether two tokens written without a space between would be cut differently. */
static bool would_merge(const hfx_token *a, const hfx_token *b) {
    if (!a || !a->len || !b->len) return false;
    char x = a->text[a->len - 1], y = b->text[0];
    if (is_word_char(x) && is_word_char(y)) return true;
    if (a->kind == TK_STRING || b->kind == TK_STRING) return false;
    static const char joiners[] = "+-*/%&|^!=<>#:.";
    return strchr(joiners, x) && strchr(joiners, y);
}

static void put_line_directive(text_buf *b, const hfx_diags *d, hfx_loc loc) {
    char head[32];
    snprintf(head, sizeof head, "#line %u \"", loc.line);
    put_str(b, head);
    const char *name = loc.file < d->file_count ? d->files[loc.file].name : "";
    for (const char *p = name; *p; p++) {
        if (*p == '"' || *p == '\\') put(b, "\\", 1);
        put(b, p, 1);
    }
    put_str(b, "\"\n");
}

char *hfx_tokens_to_text(const hfx_diags *d, const hfx_token *t) {
    text_buf b = {0};
    put(&b, "", 0);
    uint32_t file = t ? t->loc.file : 0, line = 1;
    const hfx_token *prev = NULL;
    for (; t && t->kind != TK_EOF; prev = t, t = t->next) {
        if (t->flags & TF_BOL && (t->loc.file != file || t->loc.line != line)) {
            bool jump = t->loc.file != file || t->loc.line < line || t->loc.line > line + 8;
            if (jump) {
                if (prev) put(&b, "\n", 1);
                put_line_directive(&b, d, t->loc);
            } else {
                for (; line < t->loc.line; line++) put(&b, "\n", 1);
            }
            file = t->loc.file;
            line = t->loc.line;
        } else if ((t->flags & TF_SPACE) || would_merge(prev, t)) {
            put(&b, " ", 1);
        }
        put(&b, t->text, t->len);
    }
    put(&b, "\n", 1);
    return hfx_sb_take(&b);
}
