/* json.h: the little JSON writer the page's glue answers JavaScript with (a growable string;
 * an allocation failure leaves it NULL and every later append does nothing). */
#ifndef HFX_WEB_JSON_H
#define HFX_WEB_JSON_H

#include <stddef.h>

typedef struct hfxw_json { char *s; size_t len, cap; int failed; } hfxw_json;

void hfxw_json_raw(hfxw_json *j, const char *text);               /* text as is */
void hfxw_json_str(hfxw_json *j, const char *text);               /* a quoted, escaped string (NULL: null) */
void hfxw_json_num(hfxw_json *j, double v);                        /* a number (non-finite: null) */
void hfxw_json_key(hfxw_json *j, const char *key);                 /* "key": */
char *hfxw_json_take(hfxw_json *j);                                /* the text (caller frees), or NULL */

#endif
