/* rtapi_bool.h - firtp hal-shim: 'bool' for C and C++ (LinuxCNC 2.9 layout). */
#ifndef RTAPI_BOOL_H
#define RTAPI_BOOL_H
#if !defined(__cplusplus)
#include <stdbool.h>
#endif
#endif /* RTAPI_BOOL_H */
