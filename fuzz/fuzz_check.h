/* fuzz_check.h: what every fuzz harness asserts about a compile result. A broken promise
 * aborts, which libFuzzer reports as a finding with the input that caused it. */
#ifndef HFX_FUZZ_CHECK_H
#define HFX_FUZZ_CHECK_H

#include <stddef.h>
#include <stdint.h>

#include <hfx/hfxc.h>

/* ok <=> an effect and no error; every diagnostic has a file, a line, a code and a message. */
void fuzz_check_result(const hfxc_result *r);
/* Aborts with `why` on stderr when cond is false (kept in release builds, unlike assert). */
void fuzz_require(int cond, const char *why);
/* A .hfxo whose size field and CRC-32 match its bytes again, so that mutations reach the
 * reader's section checks. Writes into out (size bytes); returns out. */
uint8_t *fuzz_repair_hfxo(const uint8_t *data, size_t size, uint8_t *out);

#endif
