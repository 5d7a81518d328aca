/* states.c: stub until the state table lands. */
#include "states.h"

#include <stddef.h>

const hfx_state_info *hfx_state_lookup(const char *name) { (void)name; return NULL; }
const hfx_state_info *hfx_state_by_id(uint32_t id) { (void)id; return NULL; }
int hfx_state_value_lookup(const hfx_state_info *st, const char *name, int32_t *out) { (void)st; (void)name; (void)out; return -1; }
const char *hfx_state_value_name(const hfx_state_info *st, int32_t value) { (void)st; (void)value; return NULL; }
