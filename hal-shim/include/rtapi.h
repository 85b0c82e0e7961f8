/* rtapi.h - firtp hal-shim: the RTAPI subset of LinuxCNC 2.9 (uspace) that HAL components use.
 *
 * Names, types and signatures follow LinuxCNC 2.9's <rtapi.h> so one component source builds
 * against either.  Compile realtime components with -DRTAPI (user-space tools: -DULAPI).
 * Written for firtp; see hal-shim/README.md for what is implemented and how it differs.
 */
#ifndef RTAPI_H
#define RTAPI_H

#if (!defined RTAPI) && (!defined ULAPI)
#error "Please define either RTAPI or ULAPI!"
#endif
#if (defined RTAPI) && (defined ULAPI)
#error "Can't define both RTAPI and ULAPI!"
#endif

#include <stdarg.h>
#include <stddef.h>

#define RTAPI_NAME_LEN 31 /* longest module name */

#ifdef __cplusplus
#define RTAPI_BEGIN_DECLS extern "C" {
#define RTAPI_END_DECLS }
#else
#define RTAPI_BEGIN_DECLS
#define RTAPI_END_DECLS
#endif

RTAPI_BEGIN_DECLS

/* ---- modules ---------------------------------------------------------------------------- */

/** Registers a module; returns a positive module id or a negative errno. */
extern int rtapi_init(const char *modname);
/** Releases a module id obtained from rtapi_init(); returns 0 or a negative errno. */
extern int rtapi_exit(int module_id);

/* ---- text output -------------------------------------------------------------------------- */

/** snprintf(), safe to call from realtime code. */
extern int rtapi_snprintf(char *buf, unsigned long int size, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/** vsnprintf(), safe to call from realtime code. */
extern int rtapi_vsnprintf(char *buf, unsigned long size, const char *fmt, va_list ap);
/** Prints unconditionally (handler level RTAPI_MSG_ALL). */
extern void rtapi_print(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/** Message levels, most to least severe. */
typedef enum {
    RTAPI_MSG_NONE = 0,
    RTAPI_MSG_ERR,
    RTAPI_MSG_WARN,
    RTAPI_MSG_INFO,
    RTAPI_MSG_DBG,
    RTAPI_MSG_ALL
} msg_level_t;

/** Prints when 'level' <= the current message level. */
extern void rtapi_print_msg(msg_level_t level, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
/** Sets the message level; 0 or -EINVAL when out of range. */
extern int rtapi_set_msg_level(int level);
/** Returns the message level. */
extern int rtapi_get_msg_level(void);

/** Destination of rtapi_print and rtapi_print_msg. */
typedef void (*rtapi_msg_handler_t)(msg_level_t level, const char *fmt, va_list ap);
#ifdef RTAPI
/** Replaces the message handler; NULL restores the default (stderr/stdout). */
extern void rtapi_set_msg_handler(rtapi_msg_handler_t handler);
/** Returns the current message handler. */
extern rtapi_msg_handler_t rtapi_get_msg_handler(void);
#endif

/* ---- time ----------------------------------------------------------------------------------- */

#ifdef RTAPI
/** Sets (first call, nsecs > 0) or queries (nsecs == 0) the base thread period in ns. */
extern long int rtapi_clock_set_period(long int nsecs);
#endif
/** Sleeps 'nsec' ns (clock_nanosleep), at most rtapi_delay_max(). */
extern void rtapi_delay(long int nsec);
/** Longest delay rtapi_delay() honours, in ns. */
extern long int rtapi_delay_max(void);
/** Monotonic time in ns (CLOCK_MONOTONIC). */
extern long long int rtapi_get_time(void);
/** Monotonic "CPU clocks"; in the shim, ns (same clock as rtapi_get_time). */
extern long long int rtapi_get_clocks(void);

#define RTAPI_NO_FP 0
#define RTAPI_USES_FP 1

/* ---- shared memory (in-process blocks, found by key) ---------------------------------------- */

/** Creates, or attaches to, the block 'key' of at least 'size' bytes; returns an id or -errno. */
extern int rtapi_shmem_new(int key, int module_id, unsigned long int size);
/** Detaches from a block; the last detach frees it.  Returns 0 or -errno. */
extern int rtapi_shmem_delete(int shmem_id, int module_id);
/** Stores the block's address in *ptr; returns 0 or -errno. */
extern int rtapi_shmem_getptr(int shmem_id, void **ptr);

/** 0: never kernel space in the shim. */
extern int rtapi_is_kernelspace(void);
/** 1 when the threads run with a realtime (SCHED_FIFO) priority, else 0. */
extern int rtapi_is_realtime(void);

/* ---- module information and parameters ------------------------------------------------------
 * As in LinuxCNC uspace, each macro defines plain global variables that the loader finds with
 * dlsym(): rtapi_info_type_X ("i", "l" or "s"), rtapi_info_address_X (&X) and, for arrays,
 * rtapi_info_size_X.  'firtp-hal loadrt comp X=5' sets X before rtapi_app_main() runs.
 * Each macro ends without ';' so 'RTAPI_MP_INT(x, "doc");' is one declaration, even in ISO C.
 */
#ifdef RTAPI
#define MODULE_INFO1(t, a, c) t rtapi_info_##a = c
#define MODULE_INFO2(t, a, b, c) t rtapi_info_##a##_##b = c
#define MODULE_INFO2x(t, a, b, c) MODULE_INFO2(t, a, b, c)
#define MODULE_PARM(v, t)                                                                        \
    MODULE_INFO2(const char *, type, v, t);                                                      \
    MODULE_INFO2(void *, address, v, &v)
#define MODULE_PARM_DESC(v, t) MODULE_INFO2(const char *, description, v, t)
#define MODULE_LICENSE(s) MODULE_INFO1(const char *, license, s)
#define MODULE_AUTHOR(s) MODULE_INFO1(const char *, author, s)
#define MODULE_DESCRIPTION(s) MODULE_INFO1(const char *, description, s)
#define MODULE_SUPPORTED_DEVICE(s) MODULE_INFO1(const char *, supported_device, s)
#define MODULE_INFO(x, y) MODULE_INFO2x(const char *, x, __LINE__, y)
#define EXPORT_SYMBOL(x) char rtapi_exported_##x[] = #x
#define EXPORT_SYMBOL_GPL(x) EXPORT_SYMBOL(x)

#define RTAPI_STRINGIFY(x) #x
#define RTAPI_MP_INT(var, descr)                                                                 \
    MODULE_PARM(var, "i");                                                                       \
    MODULE_PARM_DESC(var, descr)
#define RTAPI_MP_LONG(var, descr)                                                                \
    MODULE_PARM(var, "l");                                                                       \
    MODULE_PARM_DESC(var, descr)
#define RTAPI_MP_STRING(var, descr)                                                              \
    MODULE_PARM(var, "s");                                                                       \
    MODULE_PARM_DESC(var, descr)
#define RTAPI_MP_ARRAY(type, var, num, descr)                                                    \
    MODULE_PARM(var, type);                                                                      \
    MODULE_INFO2(int, size, var, num);                                                           \
    MODULE_PARM_DESC(var, descr)
#define RTAPI_MP_ARRAY_INT(var, num, descr) RTAPI_MP_ARRAY("i", var, num, descr)
#define RTAPI_MP_ARRAY_LONG(var, num, descr) RTAPI_MP_ARRAY("l", var, num, descr)
#define RTAPI_MP_ARRAY_STRING(var, num, descr) RTAPI_MP_ARRAY("s", var, num, descr)
#endif /* RTAPI */

RTAPI_END_DECLS

#endif /* RTAPI_H */
