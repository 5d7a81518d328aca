/* sbuf.h: a growable, NUL-terminated text buffer. A failed allocation sets `oom` and later
 * writes do nothing, so callers check once at the end. With `arena` set the text lives in the
 * arena (nothing to free, nothing lost if an allocation failure escapes; base/arena.h). */
#ifndef HFX_SBUF_H
#define HFX_SBUF_H

#include <stdarg.h>
#include <stdbool.h>
#include <stddef.h>

struct hfx_arena;
typedef struct sbuf { char *d; size_t len, cap; bool oom; struct hfx_arena *arena; } sbuf;

void hfx_sb_put(sbuf *b, const char *s);                    /* appends a string */
void hfx_sb_putn(sbuf *b, const char *s, size_t n);         /* appends n bytes of s */
void hfx_sb_printf(sbuf *b, const char *fmt, ...) __attribute__((format(printf, 2, 3))); /* appends formatted text */
void hfx_sb_vprintf(sbuf *b, const char *fmt, va_list ap);     /* appends formatted text */
char *hfx_sb_take(sbuf *b); /* the text, the caller's to free (a malloc'ed copy for an arena buffer); NULL after a failed allocation */
void hfx_sb_free(sbuf *b);  /* frees the text unless it lives in an arena */

#endif
