/* rtapi_app.h - firtp hal-shim: marks rtapi_app_main/rtapi_app_exit as the module's entry points.
 *
 * Include it from exactly one source file of a realtime component, which then defines
 *     int rtapi_app_main(void);   -- called by 'loadrt' after module parameters are set;
 *                                    returns 0, or a negative errno to refuse the load
 *     void rtapi_app_exit(void);  -- called by 'unloadrt' before the module is closed
 * with C linkage (in C++: extern "C"), as LinuxCNC 2.9 uspace expects.  Like the real header
 * this one declares neither function, so a C++ definition without extern "C" fails the same way
 * on both: the runner reports "no rtapi_app_main".
 */
#ifndef RTAPI_APP_H
#define RTAPI_APP_H

#include "rtapi.h"

EXPORT_SYMBOL(rtapi_app_main);
EXPORT_SYMBOL(rtapi_app_exit);

#endif /* RTAPI_APP_H */
