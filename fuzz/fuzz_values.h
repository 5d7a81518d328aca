/* fuzz_values.h: what a game can do to a loaded effect with hostile values, for the runtime
 * harnesses (GL and Vulkan): every parameter (elements and members too) through every setter
 * and getter with NaN, infinities, FLT_MAX, denormals, INT_MIN and INT_MAX; every annotation
 * through every getter; a scene bound with hostile matrices (hfx_effect_bind_scene). Which
 * value goes where follows `seed` (a hash of the input), so a finding reproduces. */
#ifndef HFX_FUZZ_VALUES_H
#define HFX_FUZZ_VALUES_H

#include <stddef.h>
#include <stdint.h>

#include <hfx/hfx.h>

/* FNV-1a of the bytes: the seed of the values below. */
uint32_t fuzz_seed(const uint8_t *data, size_t size);
/* Every annotation of the effect read through every getter; the technique and pass annotations
 * by the names the file holds (hfxo: the same bytes the effect was loaded from). */
void fuzz_read_annotations(hfx_effect *fx, const uint8_t *hfxo, size_t size);
/* Every parameter set and read back through every setter and getter, the last set leaving a
 * hostile value in each; then hfx_effect_bind_scene with hostile matrices. */
void fuzz_hostile_values(hfx_effect *fx, uint32_t seed);

#endif
