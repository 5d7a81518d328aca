/* states.h: the Direct3D 9 effect states (render, sampler, shader, texture-stage, fixed
 * function): their names as effect files spell them, the kind of value each takes, and the
 * named values (Wrap, Linear, CCW, SrcAlpha...) with their D3D9 numbers. Shared by the
 * compiler (to check and fold `CullMode = None;`) and the runtime (to map them to GL).
 * Lookups are case-insensitive, as in fxc. */
#ifndef HFX_COMMON_STATES_H
#define HFX_COMMON_STATES_H

#include <stdint.h>

#include "state_list.h"

/* hfx_state_info.id: HFX_ST_ZENABLE... from state_list.h; 0 is no state. Stored in .hfxo. */
typedef enum {
    HFX_ST_NONE_ = 0,
#define HFX_STATE_ENUM_(id, name, scope, kind, values, max) HFX_ST_##id,
    HFX_STATE_LIST(HFX_STATE_ENUM_)
#undef HFX_STATE_ENUM_
    HFX_ST_COUNT_
} hfx_state_id;

typedef enum {
    HFX_SV_BOOL,     /* TRUE / FALSE / 0 / 1 */
    HFX_SV_INT,      /* a DWORD */
    HFX_SV_FLOAT,
    HFX_SV_COLOR,    /* float4 or a D3DCOLOR DWORD */
    HFX_SV_ENUM,     /* one of the named values */
    HFX_SV_FLAGS,    /* named values or'ed: ColorWriteEnable = Red | Green */
    HFX_SV_TEXTURE,  /* a texture parameter */
    HFX_SV_SAMPLER,  /* a sampler parameter */
    HFX_SV_SHADER,   /* compile ..., NULL, a shader variable */
    HFX_SV_MATRIX,   /* transform states */
    HFX_SV_VECTOR    /* float4 constants, light vectors */
} hfx_state_value_kind;

typedef enum {
    HFX_SS_RENDER,   /* D3DRS_* */
    HFX_SS_SAMPLER,  /* D3DSAMP_*: in sampler_state, or in a pass with [n] = sampler stage */
    HFX_SS_SHADER,   /* VertexShader, PixelShader */
    HFX_SS_TEXTURE,  /* Texture[n] in a pass, Texture in sampler_state */
    HFX_SS_STAGE,    /* texture stage states (fixed function) */
    HFX_SS_FIXED     /* lights, materials, transforms, shader constants: fixed function */
} hfx_state_scope;

typedef struct hfx_state_enum_value {
    const char *name;  /* without prefix: "SrcAlpha"; the D3D prefix (D3DBLEND_) is also accepted */
    int32_t value;
} hfx_state_enum_value;

typedef struct hfx_state_info {
    uint32_t id;                          /* stable number, stored in .hfxo */
    const char *name;                     /* as D3DX spells it: "AlphaBlendEnable" */
    hfx_state_scope scope;
    hfx_state_value_kind kind;
    const hfx_state_enum_value *values;   /* for ENUM / FLAGS, NULL-name terminated */
    uint32_t max_index;                   /* largest [n] allowed; 0 if not indexed */
} hfx_state_info;

const hfx_state_info *hfx_state_lookup(const char *name);          /* NULL if unknown */
const hfx_state_info *hfx_state_by_id(uint32_t id);                /* NULL if unknown */
/* Value of a named constant for this state (also TRUE/FALSE for BOOL); 0 on success. */
int hfx_state_value_lookup(const hfx_state_info *st, const char *name, int32_t *out);
const char *hfx_state_value_name(const hfx_state_info *st, int32_t value); /* NULL if none */
uint32_t hfx_state_count(void);                                    /* ids run 1 .. count */

#endif
