/* keywords.h: what an identifier's spelling can mean to the parser, looked up once per
 * identifier by hfx_parse_lex.c. The spelling alone decides it; the context (is this a keyword
 * here?) is hfx_parse_lex.c's business. Keywords are case-sensitive, as in fxc; the effect-layer
 * keywords also have an any-case reading (XNA and MonoGame accept `Technique`, `Pass`), and
 * the object type names (`texture2D`, `Texture2D`) ignore case. Pure and table-driven: the
 * tables are const, so threads compiling at once share nothing mutable. */
#ifndef HFX_KEYWORDS_H
#define HFX_KEYWORDS_H

#include <stdbool.h>
#include <stdint.h>

#include "base/types.h"

typedef enum {
    KW_TYPE_NONE,
    KW_TYPE_VOID,
    KW_TYPE_STRING,
    KW_TYPE_SCALAR,     /* float */
    KW_TYPE_VECTOR,     /* float3: cols is the size */
    KW_TYPE_MATRIX,     /* float3x4 */
    KW_TYPE_OBJECT      /* texture2D, sampler, vertexshader... */
} kw_type_form;

typedef struct kw_word {
    int keyword;            /* Bison code when the exact spelling is a keyword, else 0 */
    int any_case_keyword;   /* TECHNIQUE, PASS, SAMPLER_STATE or COMPILE for those words in any case */
    bool interp;            /* an interpolation modifier: a keyword only before a type */
    uint32_t mods;          /* MOD_* of a MODIFIER keyword or of an interpolation modifier */
    kw_type_form form;      /* the builtin type the spelling names, if any */
    hfx_base base;          /* numeric forms */
    uint8_t rows, cols;     /* matrix rows x cols; a vector's size is cols */
    hfx_type_kind kind;     /* KW_TYPE_OBJECT */
    hfx_dim dim;
} kw_word;

/* Fills *w for the identifier s of len bytes (s need not be NUL-terminated). */
void hfx_kw_lookup(const char *s, uint32_t len, kw_word *w);
/* The builtin type w names, or NULL when w->form is KW_TYPE_NONE. */
const hfx_type *hfx_kw_builtin_type(hfx_types *types, const kw_word *w);

#endif
