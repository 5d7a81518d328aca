/* #include: where files are searched (the includer's folder, the root's folder, -I paths),
 * backslashes and case differences, missing files, cycles, depth, #pragma once, and the
 * locations of tokens that come from included files. Files are made in a temp folder. */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "files.h"
#include "test.h"
#include "pp/token.h"

static char *dir;

static void put(const char *rel, const char *text) {
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    for (char *p = path + strlen(dir) + 1; *p; p++) { /* make the folders on the way */
        if (*p != '/') continue;
        *p = 0;
        mkdir(path, 0755);
        *p = '/';
    }
    FILE *f = fopen(path, "wb");
    if (!f) return;
    fputs(text, f);
    fclose(f);
}

static char *path_of(const char *rel) {
    static char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, rel);
    return path;
}

typedef struct {
    hfx_arena arena;
    hfx_diags diags;
    hfx_token *toks;
    char *out, *diag;
} pp_run;

static char *join_all(hfx_arena *a, const hfx_token *t) {
    size_t cap = 1;
    for (const hfx_token *u = t; u; u = u->next) cap += u->len + 1;
    char *out = hfx_arena_alloc(a, cap), *p = out;
    for (; t && t->kind != TK_EOF; t = t->next) {
        if (p != out) *p++ = ' ';
        memcpy(p, t->text, t->len);
        p += t->len;
    }
    *p = 0;
    return out;
}

/* Preprocesses the file `rel` of the temp folder, read from disk. */
static void hfx_pp_file(pp_run *r, const char *rel, const hfx_pp_options *opt) {
    hfx_arena_init(&r->arena);
    hfx_diags_init(&r->diags, &r->arena, 0);
    r->toks = hfx_preprocess(&r->arena, &r->diags, path_of(rel), NULL, 0, opt);
    r->out = join_all(&r->arena, r->toks);
    char *d = hfx_diags_format(&r->diags, 0);
    /* Diagnostics name the root file by its full path: drop the temp folder for the checks. */
    size_t n = strlen(dir);
    char *clean = hfx_arena_alloc(&r->arena, strlen(d) + 1), *q = clean;
    for (const char *p = d; *p;) {
        if (strncmp(p, dir, n) == 0 && p[n] == '/') p += n + 1;
        else *q++ = *p++;
    }
    *q = 0;
    free(d);
    r->diag = clean;
}

static hfx_token *find_tok(pp_run *r, const char *text) {
    for (hfx_token *t = r->toks; t; t = t->next)
        if (strcmp(t->text, text) == 0) return t;
    return NULL;
}

static const char *file_of(pp_run *r, const hfx_token *t) { return r->diags.files[t->loc.file].name; }

static void done(pp_run *r) { hfx_arena_free(&r->arena); }

static void search_order(void) {
    put("b.fxh", "b_in_root\n");
    put("common.fxh", "common_in_root\n");
    put("sub/a.fxh", "a1\n#include \"b.fxh\"\n#include \"common.fxh\"\na2\n");
    put("sub/b.fxh", "b_in_sub\n");
    put("inc/lib.fxh", "lib\n");
    put("order.fx", "#include \"sub/a.fxh\"\n#include <lib.fxh>\n#include \"b.fxh\" // the root's own\nend\n");
    char inc[1024];
    snprintf(inc, sizeof inc, "%s", path_of("inc"));
    const char *dirs[] = {inc};
    hfx_pp_options opt = {NULL, 0, dirs, 1, 0, NULL};
    pp_run r;
    hfx_pp_file(&r, "order.fx", &opt);
    CHECK_STR(r.out, "a1 b_in_sub common_in_root a2 lib b_in_root end");
    CHECK_STR(r.diag, "");
    hfx_token *t = find_tok(&r, "b_in_sub");
    CHECK_STR(file_of(&r, t), "b.fxh");
    CHECK_INT(t->loc.line, 1);
    t = find_tok(&r, "a2");
    CHECK_STR(file_of(&r, t), "sub/a.fxh");
    CHECK_INT(t->loc.line, 4);
    CHECK_INT(t->loc.col, 1);
    CHECK_INT(find_tok(&r, "end")->loc.line, 4);
    done(&r);
    hfx_pp_file(&r, "order.fx", NULL); /* without -I, <lib.fxh> is missing */
    CHECK_STR(r.diag, "order.fx(2,1): error X1507: failed to open source file: 'lib.fxh'\n");
    CHECK_STR(r.out, "a1 b_in_sub common_in_root a2 b_in_root end");
    done(&r);
}

static void backslashes_and_case(void) {
    put("Mixed/Case.FXH", "mixed\n");
    put("cased.fx", "#include \"sub\\\\a.fxh\"\n#include \"mixed/case.fxh\"\n#include \"MIXED\\\\CASE.fxh\"\n");
    pp_run r;
    hfx_pp_file(&r, "cased.fx", NULL);
    CHECK_STR(r.out, "a1 b_in_sub common_in_root a2 mixed mixed");
    CHECK_STR(r.diag, "");
    done(&r);
}

static void missing_include(void) {
    put("bad.fx", "float a;\n\n#include \"missing.fxh\"\nfloat b;\n");
    pp_run r;
    hfx_pp_file(&r, "bad.fx", NULL);
    CHECK_STR(r.diag, "bad.fx(3,1): error X1507: failed to open source file: 'missing.fxh'\n");
    CHECK_STR(r.out, "float a ; float b ;");
    done(&r);
}

static void include_cycle(void) {
    put("cyc_a.fxh", "#include \"cyc_b.fxh\"\n");
    put("cyc_b.fxh", "#include \"cyc_a.fxh\"\n");
    put("cycle.fx", "#include \"cyc_a.fxh\"\nafter\n");
    pp_run r;
    hfx_pp_file(&r, "cycle.fx", NULL);
    /* Frames: cycle.fx, then cyc_a and cyc_b in turn; the 64th (cyc_a) may include no more. */
    CHECK_STR(r.diag, "cyc_a.fxh(1,1): error X1506: #include cycle: 'cyc_b.fxh' includes itself (nesting depth 64)\n");
    CHECK_STR(r.out, "after");
    done(&r);
}

static void guarded_cycle_is_fine(void) {
    put("g1.fxh", "#ifndef G1\n#define G1\n#include \"g2.fxh\"\ng1\n#endif\n");
    put("g2.fxh", "#include \"g1.fxh\"\ng2\n");
    put("guarded.fx", "#include \"g1.fxh\"\n#include \"g2.fxh\"\n");
    pp_run r;
    hfx_pp_file(&r, "guarded.fx", NULL);
    CHECK_STR(r.out, "g2 g1 g2");
    CHECK_STR(r.diag, "");
    done(&r);
}

static void include_depth_limit(void) {
    put("d1.fxh", "#include \"d2.fxh\"\nd1\n");
    put("d2.fxh", "#include \"d3.fxh\"\nd2\n");
    put("d3.fxh", "d3\n");
    put("deep.fx", "#include \"d1.fxh\"\n");
    hfx_pp_options opt = {NULL, 0, NULL, 0, 3, NULL};
    pp_run r;
    hfx_pp_file(&r, "deep.fx", &opt);
    CHECK_STR(r.diag, "d2.fxh(1,1): error X1506: #include nested too deeply (more than 3 files)\n");
    CHECK_STR(r.out, "d2 d1");
    done(&r);
    hfx_pp_file(&r, "deep.fx", NULL);
    CHECK_STR(r.out, "d3 d2 d1");
    done(&r);
}

static void pragma_once(void) {
    put("once.fxh", "#pragma once\nonce\n");
    put("twice.fxh", "twice\n");
    put("once.fx", "#include \"once.fxh\"\n#include \"./once.fxh\"\n#include \"twice.fxh\"\n#include \"twice.fxh\"\n");
    pp_run r;
    hfx_pp_file(&r, "once.fx", NULL);
    CHECK_STR(r.out, "once twice twice");
    done(&r);
}

static void conditionals_are_per_file(void) {
    put("open.fxh", "#if 1\nopen\n");
    put("close.fx", "#if 1\n#include \"open.fxh\"\n#endif\nx\n");
    pp_run r;
    hfx_pp_file(&r, "close.fx", NULL);
    CHECK_STR(r.diag, "open.fxh(1,1): error X1502: unterminated '#if'\n");
    CHECK_STR(r.out, "open x");
    done(&r);
}

static void include_from_macro_and_file_macro(void) {
    put("common2.fxh", "__FILE__ __LINE__\n");
    put("macro.fx", "#define HDR \"common2.fxh\"\n#define ANGLED <common2.fxh>\n#include HDR\n#include ANGLED\n");
    pp_run r;
    hfx_pp_file(&r, "macro.fx", NULL);
    CHECK_STR(r.out, "\"common2.fxh\" 1 \"common2.fxh\" 1");
    CHECK_STR(r.diag, "");
    done(&r);
}

static void root_read_from_disk_with_crlf_and_bom(void) {
    put("crlf.fx", "\xEF\xBB\xBF#define N 4\r\nfloat a[N];\r\n#if N > 3\r\nbig\r\n#endif\r\n");
    pp_run r;
    hfx_pp_file(&r, "crlf.fx", NULL);
    CHECK_STR(r.out, "float a [ 4 ] ; big");
    CHECK_STR(r.diag, "");
    CHECK_INT(find_tok(&r, "big")->loc.line, 4);
    done(&r);
}

/* Writes `text` as UTF-16 with its byte-order mark; \x01 stands for U+20AC (one unit) and \x02
 * for U+1F600 (the surrogate pair D83D DE00), both in comments here. */
static void put_utf16(const char *rel, const char *text, bool big_endian) {
    FILE *f = fopen(path_of(rel), "wb");
    if (!f) return;
    uint16_t units[512];
    size_t n = 0;
    units[n++] = 0xFEFF;
    for (const char *c = text; *c && n < 510; c++) {
        if (*c == 1) units[n++] = 0x20AC;
        else if (*c == 2) { units[n++] = 0xD83D; units[n++] = 0xDE00; }
        else units[n++] = (uint16_t)(unsigned char)*c;
    }
    for (size_t i = 0; i < n; i++) {
        unsigned char b[2] = {(unsigned char)(units[i] & 0xFF), (unsigned char)(units[i] >> 8)};
        if (big_endian) { unsigned char t = b[0]; b[0] = b[1]; b[1] = t; }
        fwrite(b, 1, 2, f);
    }
    fclose(f);
}

/* fxc and XNA's content pipeline read UTF-16 sources with a BOM, little or big endian (issue
 * 30): tokens, lines and columns as in the text, an included UTF-16 file as well. */
static void utf16_sources(void) {
    put_utf16("u16le.fx", "// \x01 \x02\r\n#include \"u16be.fxh\"\r\nfloat a[N];\r\n#error done\r\n", false);
    put_utf16("u16be.fxh", "#define N 4 // \x02\n", true);
    pp_run r;
    hfx_pp_file(&r, "u16le.fx", NULL);
    CHECK_STR(r.out, "float a [ 4 ] ;");
    CHECK_STR(r.diag, "u16le.fx(4,1): error X1003: done\n");
    hfx_token *a = find_tok(&r, "a");
    CHECK(a != NULL);
    if (a) {
        CHECK_INT(a->loc.line, 3);
        CHECK_INT(a->loc.col, 7);
    }
    done(&r);
    /* the same text in memory, big endian */
    static const char mem[] = "\xFE\xFF\0f\0l\0o\0a\0t\0 \0b\0;";
    hfx_arena_init(&r.arena);
    hfx_diags_init(&r.diags, &r.arena, 0);
    r.toks = hfx_preprocess(&r.arena, &r.diags, "mem.fx", mem, sizeof mem - 1, NULL);
    CHECK_STR(join_all(&r.arena, r.toks), "float b ;");
    CHECK_INT(r.diags.errors, 0);
    done(&r);
}

int main(void) {
    dir = test_temp_dir();
    if (!dir) test_skip("no temp folder");
    RUN(search_order);
    RUN(backslashes_and_case);
    RUN(missing_include);
    RUN(include_cycle);
    RUN(guarded_cycle_is_fine);
    RUN(include_depth_limit);
    RUN(pragma_once);
    RUN(conditionals_are_per_file);
    RUN(include_from_macro_and_file_macro);
    RUN(root_read_from_disk_with_crlf_and_bom);
    RUN(utf16_sources);
    int rc = test_summary();
    char cmd[1200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
    free(dir);
    return rc;
}
