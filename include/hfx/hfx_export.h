/* hfx_export.h: HFX_API marks the functions hfx's libraries export. The libraries are built with
 * hidden visibility, so a shared libhfx exports these and nothing else (a program's own sb_put or
 * ir_lower never meets hfx's internals); with static libraries it documents the public surface. */
#ifndef HFX_EXPORT_H
#define HFX_EXPORT_H

#if defined(_WIN32) && defined(HFX_BUILDING_SHARED)
#define HFX_API __declspec(dllexport)
#elif defined(__GNUC__)
#define HFX_API __attribute__((visibility("default")))
#else
#define HFX_API
#endif

#endif
