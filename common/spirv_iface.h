/* spirv_iface.h: the user-defined inputs or outputs of one SPIR-V module, location by location.
 * A driver links two stages by these locations and sizes its tables by them; SPIRV-Tools checks
 * one module alone, so a location far past the device's limits, or a pixel shader input that no
 * vertex shader output feeds, passes it and can still crash a driver (lavapipe writes out of
 * bounds on Location 0x40000001). The runtime reads the interface with this before it creates a
 * pipeline and refuses what a driver need not survive. */
#ifndef HFX_COMMON_SPIRV_IFACE_H
#define HFX_COMMON_SPIRV_IFACE_H

#include <stddef.h>
#include <stdint.h>

/* Locations past this are refused whatever the device: D3D9 has at most 16 of any kind. */
enum { HFX_SPIRV_MAX_LOCATIONS = 32 };

/* What each location holds: 0 when nothing; else a 32-bit scalar kind (HFX_SPIRV_FLOAT...) times
 * 8 plus its component count (1-4). A matrix takes a location per column, an array one per element. */
enum { HFX_SPIRV_FLOAT = 1, HFX_SPIRV_INT = 2, HFX_SPIRV_UINT = 3 };

typedef struct hfx_spirv_iface {
    uint32_t end;                             /* one past the highest location used */
    uint8_t kind[HFX_SPIRV_MAX_LOCATIONS];
} hfx_spirv_iface;

/* Reads the user-defined Input (output 0) or Output (output 1) variables of words[0..count) into
 * *out; built-ins are left out. NULL when done, else why the interface is refused (a variable
 * without a Location, a location past HFX_SPIRV_MAX_LOCATIONS, two variables on one location,
 * a type no D3D9 varying has). */
const char *hfx_spirv_interface(const uint32_t *words, size_t count, int output, hfx_spirv_iface *out);

/* NULL when every location `to` reads is written by `from` with the same kind, else why not. */
const char *hfx_spirv_interface_fed(const hfx_spirv_iface *from, const hfx_spirv_iface *to);

#endif
