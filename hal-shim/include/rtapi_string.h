/* rtapi_string.h - firtp hal-shim: <string.h> plus the bounded copy helpers of LinuxCNC 2.9. */
#ifndef RTAPI_STRING_H
#define RTAPI_STRING_H
#include "rtapi.h"
#include <string.h>

RTAPI_BEGIN_DECLS
/** Copies 'src' into 'dst' (at most size-1 chars, always terminated); returns strlen(src). */
static inline size_t rtapi_strlcpy(char *dst, const char *src, size_t size) {
    return (size_t)rtapi_snprintf(dst, size, "%s", src);
}
/** Appends 'src' to 'dst' within 'size' bytes (always terminated); returns the length it tried to make. */
static inline size_t rtapi_strlcat(char *dst, const char *src, size_t size) {
    size_t used = strlen(dst);
    return used + (size_t)rtapi_snprintf(dst + used, size - used, "%s", src);
}
RTAPI_END_DECLS

/* Array-only forms: the destination size is taken from the array itself. */
#define rtapi_strxcpy(dst, src) rtapi_strlcpy((dst), (src), sizeof(dst))
#define rtapi_strxcat(dst, src) rtapi_strlcat((dst), (src), sizeof(dst))
#endif /* RTAPI_STRING_H */
