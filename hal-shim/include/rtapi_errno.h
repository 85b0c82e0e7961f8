/* rtapi_errno.h - firtp hal-shim: errno codes (EINVAL, ENOMEM, ...) returned negated by HAL calls. */
#ifndef RTAPI_ERRNO_H
#define RTAPI_ERRNO_H
#include <errno.h>
#endif /* RTAPI_ERRNO_H */
