/* states.c: the Direct3D 9 effect state table (names from d3dx9 effect files, values from
 * d3d9types.h). The list itself is in state_list.h; this file holds the named values. */
#include "states.h"

#include <stdbool.h>
#include <stddef.h>
#include <string.h>
#include <strings.h>

#define END {NULL, 0}

static const hfx_state_enum_value zenable[] = {{"False", 0}, {"True", 1}, {"UseW", 2}, END};
static const hfx_state_enum_value fill[] = {{"Point", 1}, {"Wireframe", 2}, {"Solid", 3}, END};
static const hfx_state_enum_value shade[] = {{"Flat", 1}, {"Gouraud", 2}, {"Phong", 3}, END};
static const hfx_state_enum_value blend[] = {
    {"Zero", 1}, {"One", 2}, {"SrcColor", 3}, {"InvSrcColor", 4}, {"SrcAlpha", 5}, {"InvSrcAlpha", 6},
    {"DestAlpha", 7}, {"InvDestAlpha", 8}, {"DestColor", 9}, {"InvDestColor", 10}, {"SrcAlphaSat", 11},
    {"BothSrcAlpha", 12}, {"BothInvSrcAlpha", 13}, {"BlendFactor", 14}, {"InvBlendFactor", 15},
    {"SrcColor2", 16}, {"InvSrcColor2", 17}, END};
static const hfx_state_enum_value cull[] = {{"None", 1}, {"CW", 2}, {"CCW", 3}, END};
static const hfx_state_enum_value cmp[] = {
    {"Never", 1}, {"Less", 2}, {"Equal", 3}, {"LessEqual", 4}, {"Greater", 5}, {"NotEqual", 6},
    {"GreaterEqual", 7}, {"Always", 8}, END};
static const hfx_state_enum_value fog[] = {{"None", 0}, {"Exp", 1}, {"Exp2", 2}, {"Linear", 3}, END};
static const hfx_state_enum_value stencilop[] = {
    {"Keep", 1}, {"Zero", 2}, {"Replace", 3}, {"IncrSat", 4}, {"DecrSat", 5}, {"Invert", 6},
    {"Incr", 7}, {"Decr", 8}, END};
static const hfx_state_enum_value wrap[] = {
    {"U", 1}, {"V", 2}, {"W", 4}, {"Coord0", 1}, {"Coord1", 2}, {"Coord2", 4}, {"Coord3", 8}, END};
static const hfx_state_enum_value mcs[] = {{"Material", 0}, {"Color1", 1}, {"Color2", 2}, END};
static const hfx_state_enum_value vbf[] = {
    {"Disable", 0}, {"1Weights", 1}, {"2Weights", 2}, {"3Weights", 3}, {"Tweening", 255},
    {"0Weights", 256}, END};
static const hfx_state_enum_value clipplane[] = {
    {"ClipPlane0", 1}, {"ClipPlane1", 2}, {"ClipPlane2", 4}, {"ClipPlane3", 8}, {"ClipPlane4", 16},
    {"ClipPlane5", 32}, END};
static const hfx_state_enum_value patchedge[] = {{"Discrete", 0}, {"Continuous", 1}, END};
static const hfx_state_enum_value dmt[] = {{"Enable", 0}, {"Disable", 1}, END};
/* All and None are MonoGame's spellings (ColorWriteChannels), which its effect compiler takes. */
static const hfx_state_enum_value colorwrite[] = {{"Red", 1}, {"Green", 2}, {"Blue", 4}, {"Alpha", 8}, {"All", 15}, {"None", 0}, END};
static const hfx_state_enum_value blendop[] = {
    {"Add", 1}, {"Subtract", 2}, {"RevSubtract", 3}, {"Min", 4}, {"Max", 5}, END};
static const hfx_state_enum_value degree[] = {{"Linear", 1}, {"Quadratic", 2}, {"Cubic", 3}, {"Quintic", 5}, END};
static const hfx_state_enum_value top[] = {
    {"Disable", 1}, {"SelectArg1", 2}, {"SelectArg2", 3}, {"Modulate", 4}, {"Modulate2x", 5},
    {"Modulate4x", 6}, {"Add", 7}, {"AddSigned", 8}, {"AddSigned2x", 9}, {"Subtract", 10},
    {"AddSmooth", 11}, {"BlendDiffuseAlpha", 12}, {"BlendTextureAlpha", 13}, {"BlendFactorAlpha", 14},
    {"BlendTextureAlphaPM", 15}, {"BlendCurrentAlpha", 16}, {"PreModulate", 17},
    {"ModulateAlpha_AddColor", 18}, {"ModulateColor_AddAlpha", 19}, {"ModulateInvAlpha_AddColor", 20},
    {"ModulateInvColor_AddAlpha", 21}, {"BumpEnvMap", 22}, {"BumpEnvMapLuminance", 23},
    {"DotProduct3", 24}, {"MultiplyAdd", 25}, {"Lerp", 26}, END};
static const hfx_state_enum_value ta[] = {
    {"Diffuse", 0}, {"Current", 1}, {"Texture", 2}, {"TFactor", 3}, {"Specular", 4}, {"Temp", 5},
    {"Constant", 6}, {"Complement", 0x10}, {"AlphaReplicate", 0x20}, END};
static const hfx_state_enum_value tci[] = {
    {"PassThru", 0}, {"CameraSpaceNormal", 0x10000}, {"CameraSpacePosition", 0x20000},
    {"CameraSpaceReflectionVector", 0x30000}, {"SphereMap", 0x40000}, END};
static const hfx_state_enum_value ttff[] = {
    {"Disable", 0}, {"Count1", 1}, {"Count2", 2}, {"Count3", 3}, {"Count4", 4}, {"Projected", 256}, END};
static const hfx_state_enum_value light[] = {{"Point", 1}, {"Spot", 2}, {"Directional", 3}, END};
static const hfx_state_enum_value taddress[] = {
    {"Wrap", 1}, {"Mirror", 2}, {"Clamp", 3}, {"Border", 4}, {"MirrorOnce", 5}, END};
static const hfx_state_enum_value texf[] = {
    {"None", 0}, {"Point", 1}, {"Linear", 2}, {"Anisotropic", 3}, {"PyramidalQuad", 6},
    {"GaussianQuad", 7}, {"ConvolutionMono", 8}, END};
static const hfx_state_enum_value boolean[] = {{"False", 0}, {"True", 1}, END};

/* The d3d9types.h prefix of each value table: D3DBLEND_SRCALPHA is SrcAlpha. */
static const struct {
    const hfx_state_enum_value *values;
    const char *prefix;
} prefixes[] = {
    {zenable, "D3DZB_"}, {fill, "D3DFILL_"}, {shade, "D3DSHADE_"}, {blend, "D3DBLEND_"},
    {cull, "D3DCULL_"}, {cmp, "D3DCMP_"}, {fog, "D3DFOG_"}, {stencilop, "D3DSTENCILOP_"},
    {wrap, "D3DWRAP_"}, {mcs, "D3DMCS_"}, {vbf, "D3DVBF_"},
    {clipplane, "D3D"}, {patchedge, "D3DPATCHEDGE_"}, {dmt, "D3DDMT_"},
    {colorwrite, "D3DCOLORWRITEENABLE_"}, {blendop, "D3DBLENDOP_"}, {degree, "D3DDEGREE_"},
    {top, "D3DTOP_"}, {ta, "D3DTA_"}, {tci, "D3DTSS_TCI_"}, {ttff, "D3DTTFF_"}, {light, "D3DLIGHT_"},
    {taddress, "D3DTADDRESS_"}, {texf, "D3DTEXF_"},
};

#define NONE NULL
#define HFX_STATE_ROW_(id, name, scope, kind, values, max) \
    {HFX_ST_##id, name, HFX_SS_##scope, HFX_SV_##kind, values, max},
static const hfx_state_info table[] = {HFX_STATE_LIST(HFX_STATE_ROW_)};
#undef HFX_STATE_ROW_
#undef NONE

#define TABLE_SIZE (sizeof table / sizeof table[0])
_Static_assert(TABLE_SIZE == HFX_ST_COUNT_ - 1, "state ids are table positions + 1");

uint32_t hfx_state_count(void) { return (uint32_t)TABLE_SIZE; }

static char lower(char c) { return c >= 'A' && c <= 'Z' ? (char)(c - 'A' + 'a') : c; }

/* Case-insensitive, first letters compared before the whole names: the builder looks up every
 * state of every pass, and strcasecmp over the whole table was 2% of a compile. */
static bool same_name(const char *a, const char *b) { return lower(*a) == lower(*b) && strcasecmp(a, b) == 0; }

const hfx_state_info *hfx_state_lookup(const char *name) {
    if (!name) return NULL;
    for (size_t i = 0; i < TABLE_SIZE; i++)
        if (same_name(table[i].name, name)) return &table[i];
    return NULL;
}

const hfx_state_info *hfx_state_by_id(uint32_t id) {
    if (id == 0 || id > TABLE_SIZE) return NULL;
    return &table[id - 1];
}

/* BOOL states take TRUE / FALSE; ENUM and FLAGS states take their table. */
static const hfx_state_enum_value *values_of(const hfx_state_info *st) {
    if (st->values) return st->values;
    return st->kind == HFX_SV_BOOL ? boolean : NULL;
}

static int find_value(const hfx_state_enum_value *v, const char *name, int32_t *out) {
    for (; v->name; v++)
        if (same_name(v->name, name)) {
            if (out) *out = v->value;
            return 0;
        }
    return -1;
}

int hfx_state_value_lookup(const hfx_state_info *st, const char *name, int32_t *out) {
    if (!st || !name) return -1;
    const hfx_state_enum_value *v = values_of(st);
    if (!v) return -1;
    if (find_value(v, name, out) == 0) return 0;
    /* D3DBLEND_SRCALPHA: strip the table's prefix (several tables may share one). */
    for (size_t i = 0; i < sizeof prefixes / sizeof prefixes[0]; i++) {
        size_t n = strlen(prefixes[i].prefix);
        if (prefixes[i].values == v && strncasecmp(name, prefixes[i].prefix, n) == 0 && name[n] &&
            find_value(v, name + n, out) == 0)
            return 0;
    }
    return -1;
}

const char *hfx_state_value_name(const hfx_state_info *st, int32_t value) {
    if (!st) return NULL;
    const hfx_state_enum_value *v = values_of(st);
    for (; v && v->name; v++)
        if (v->value == value) return v->name;
    return NULL;
}
