/* rtapi_math.h - firtp hal-shim: user-space math for realtime code (libm, as in LinuxCNC uspace). */
#ifndef RTAPI_MATH_H
#define RTAPI_MATH_H
#include "rtapi.h"
#include <float.h>
#include <math.h>
#ifndef M_PI
#define M_PI 3.1415926535897932384626433832795029
#endif
#ifndef M_PIl
#define M_PIl 3.1415926535897932384626433832795029L
#endif
#ifndef M_PI_2l
#define M_PI_2l 1.570796326794896619231321691639751442L
#endif
#endif /* RTAPI_MATH_H */
