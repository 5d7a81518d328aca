/* hfxo.c: stub until the .hfxo format lands. */
#include "effect.h"

#include <stdio.h>

int hfx_fx_write_hfxo(const hfx_fx_effect *fx, void **out, size_t *out_size) {
    (void)fx; (void)out; (void)out_size;
    return -1;
}

hfx_fx_effect *hfx_fx_read_hfxo(const void *data, size_t size, char *err, size_t err_size) {
    (void)data; (void)size;
    if (err && err_size) snprintf(err, err_size, "hfxo: not implemented yet");
    return NULL;
}

int hfx_fx_is_hfxo(const void *data, size_t size) { (void)data; (void)size; return 0; }
