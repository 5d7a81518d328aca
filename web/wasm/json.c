/* json.c: see json.h. */
#include "json.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void append(hfxw_json *j, const char *p, size_t n) {
    if (j->failed) return;
    if (j->len + n + 1 > j->cap) {
        size_t cap = j->cap ? j->cap : 256;
        while (cap < j->len + n + 1) cap *= 2;
        char *s = realloc(j->s, cap);
        if (!s) {
            free(j->s);
            *j = (hfxw_json){NULL, 0, 0, 1};
            return;
        }
        j->s = s, j->cap = cap;
    }
    memcpy(j->s + j->len, p, n);
    j->len += n;
    j->s[j->len] = 0;
}

void hfxw_json_raw(hfxw_json *j, const char *text) { append(j, text, strlen(text)); }

void hfxw_json_str(hfxw_json *j, const char *text) {
    if (!text) {
        hfxw_json_raw(j, "null");
        return;
    }
    append(j, "\"", 1);
    for (const unsigned char *p = (const unsigned char *)text; *p; p++) {
        char esc[8];
        if (*p == '"' || *p == '\\') snprintf(esc, sizeof esc, "\\%c", *p);
        else if (*p < 0x20) snprintf(esc, sizeof esc, "\\u%04x", *p);
        else esc[0] = (char)*p, esc[1] = 0;
        hfxw_json_raw(j, esc);
    }
    append(j, "\"", 1);
}

void hfxw_json_num(hfxw_json *j, double v) {
    char buf[32];
    if (!isfinite(v)) snprintf(buf, sizeof buf, "null");
    else snprintf(buf, sizeof buf, "%.9g", v);
    hfxw_json_raw(j, buf);
}

void hfxw_json_key(hfxw_json *j, const char *key) {
    hfxw_json_str(j, key);
    append(j, ":", 1);
}

char *hfxw_json_take(hfxw_json *j) {
    char *s = j->failed ? NULL : j->s;
    *j = (hfxw_json){0};
    return s;
}
