/* token_cache.c: see token_cache.h. An entry holds the file's text (a later read must match it
 * byte for byte, so a header edited on disk is cut again), its tokens with file index 0, and
 * their spellings packed in one block; a hit copies both into the compile's arena and points
 * the copies at it, so nothing of a result refers to the cache. */
#include "pp/token_cache.h"

#include <stdlib.h>
#include <string.h>

enum {
    CACHE_BUCKETS = 256,
    CACHE_MAX_BYTES = 64 << 20, /* past this a session stops remembering files */
    NO_SPELLING = UINT32_MAX    /* the token's spelling is a constant string of the lexer's */
};

typedef struct cached_file cached_file;
struct cached_file {
    char *real;                 /* canonical path */
    char *text;                 /* the text the tokens were cut from */
    uint32_t size;
    hfx_token *tokens;          /* count of them, the last TK_EOF; `next` unused */
    uint32_t *spelling_at;      /* offset of each spelling in `spellings`, or NO_SPELLING */
    uint32_t count;
    char *spellings;
    size_t spellings_size;
    cached_file *next;          /* same bucket */
};

struct hfx_token_cache {
    cached_file *buckets[CACHE_BUCKETS];
    size_t bytes;
};

hfx_token_cache *hfx_token_cache_new(void) { return calloc(1, sizeof(hfx_token_cache)); }

static void free_entry(cached_file *e) {
    free(e->real);
    free(e->text);
    free(e->tokens);
    free(e->spelling_at);
    free(e->spellings);
    free(e);
}

void hfx_token_cache_free(hfx_token_cache *c) {
    if (!c) return;
    for (int b = 0; b < CACHE_BUCKETS; b++) {
        for (cached_file *e = c->buckets[b], *next; e; e = next) {
            next = e->next;
            free_entry(e);
        }
    }
    free(c);
}

static uint32_t bucket_of(const char *s) {
    uint32_t h = 2166136261u;
    for (; *s; s++) h = (h ^ (unsigned char)*s) * 16777619u;
    return h % CACHE_BUCKETS;
}

static cached_file **slot_of(hfx_token_cache *c, const char *real) {
    cached_file **p = &c->buckets[bucket_of(real)];
    while (*p && strcmp((*p)->real, real) != 0) p = &(*p)->next;
    return p;
}

/* Punctuators, '#', '##' and the end spell with the lexer's constant strings (lexer.re). */
static bool constant_spelling(hfx_token_kind kind) {
    return kind == TK_PUNCT || kind == TK_HASH || kind == TK_HASHHASH || kind == TK_EOF;
}

/* ---- a hit: the remembered tokens copied into the arena ---- */

static hfx_token *copy_out(const cached_file *e, hfx_arena *arena, uint32_t file) {
    char *spellings = hfx_arena_alloc_raw(arena, e->spellings_size ? e->spellings_size : 1);
    hfx_token *out = hfx_arena_alloc_raw(arena, sizeof *out * e->count);
    if (!spellings || !out) return NULL;
    memcpy(spellings, e->spellings, e->spellings_size);
    /* Field by field, in one pass (a memcpy of the array first was a second pass over it); a
     * field added to hfx_token must be added here. */
    for (uint32_t i = 0; i < e->count; i++) {
        const hfx_token *from = &e->tokens[i];
        hfx_token *t = &out[i];
        t->kind = from->kind;
        t->punct = from->punct;
        t->flags = from->flags;
        t->text = e->spelling_at[i] != NO_SPELLING ? spellings + e->spelling_at[i] : from->text;
        t->len = from->len;
        t->loc = (hfx_loc){file, from->loc.line, from->loc.col};
        t->spelling = t->loc; /* the lexer gives both the same place */
        t->next = t + 1;
        t->hideset = NULL;
    }
    out[e->count - 1].next = NULL;
    return out;
}

/* ---- a miss: remembering what the lexer made ---- */

static bool count_list(const hfx_token *list, uint32_t *count, size_t *spellings_size) {
    *count = 0;
    *spellings_size = 0;
    for (const hfx_token *t = list; t; t = t->next) {
        if (++*count == UINT32_MAX) return false;
        if (!constant_spelling(t->kind)) *spellings_size += (size_t)t->len + 1;
    }
    return *count > 0 && *spellings_size < NO_SPELLING;
}

/* Fills the entry's arrays from the list; they are allocated with room for all of it. */
static void fill_entry(cached_file *e, const hfx_token *list) {
    size_t at = 0;
    uint32_t i = 0;
    for (const hfx_token *t = list; t; t = t->next, i++) {
        e->tokens[i] = *t;
        e->tokens[i].next = NULL;
        e->spelling_at[i] = NO_SPELLING;
        if (constant_spelling(t->kind)) continue;
        memcpy(e->spellings + at, t->text, t->len);
        e->spellings[at + t->len] = 0;
        e->spelling_at[i] = (uint32_t)at;
        at += (size_t)t->len + 1;
    }
}

static cached_file *new_entry(const char *real, const hfx_source *src, const hfx_token *list) {
    cached_file *e = calloc(1, sizeof *e);
    if (!e || !count_list(list, &e->count, &e->spellings_size)) return free(e), NULL;
    e->real = strdup(real);
    e->text = malloc((size_t)src->size + 1);
    e->size = src->size;
    e->tokens = malloc(sizeof *e->tokens * e->count);
    e->spelling_at = malloc(sizeof *e->spelling_at * e->count);
    e->spellings = malloc(e->spellings_size ? e->spellings_size : 1);
    if (!e->real || !e->text || !e->tokens || !e->spelling_at || !e->spellings) {
        free_entry(e);
        return NULL;
    }
    memcpy(e->text, src->text, src->size);
    fill_entry(e, list);
    return e;
}

static size_t entry_bytes(const cached_file *e) {
    return e->size + e->spellings_size + (size_t)e->count * (sizeof *e->tokens + sizeof *e->spelling_at);
}

/* Replaces what *slot held for the path (a stale text) with the new entry. */
static void remember(hfx_token_cache *c, cached_file **slot, const char *real, const hfx_source *src,
                     const hfx_token *list) {
    if (c->bytes + (size_t)src->size * 2 > CACHE_MAX_BYTES && !*slot) return;
    cached_file *e = new_entry(real, src, list);
    if (!e) return;
    if (*slot) {
        e->next = (*slot)->next;
        c->bytes -= entry_bytes(*slot);
        free_entry(*slot);
    }
    *slot = e;
    c->bytes += entry_bytes(e);
}

hfx_token *hfx_token_cache_tokenize(hfx_token_cache *c, hfx_arena *arena, hfx_diags *diags, uint32_t file,
                                    const char *real) {
    const hfx_source *src = file < diags->file_count ? &diags->files[file] : NULL;
    if (!c || !real || !src || !src->text) return hfx_tokenize_deferred(arena, diags, file);
    cached_file **slot = slot_of(c, real);
    cached_file *e = *slot;
    if (e && e->size == src->size && memcmp(e->text, src->text, src->size) == 0) {
        hfx_token *copy = copy_out(e, arena, file);
        if (copy) return copy;
    }
    uint32_t said = diags->errors + diags->warnings; /* a hit would not say it again */
    hfx_token *list = hfx_tokenize_deferred(arena, diags, file);
    if (diags->errors + diags->warnings == said) remember(c, slot, real, src, list);
    return list;
}
