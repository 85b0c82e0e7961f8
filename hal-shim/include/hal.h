/* hal.h - firtp hal-shim: the HAL API subset of LinuxCNC 2.9 that realtime components use.
 *
 * Same names, types and signatures as LinuxCNC 2.9's <hal.h>, so one component source builds
 * against either.  A pin is a pointer the component reads through; it points at a dummy until
 * 'net' links it, then at the signal's storage.  All pin/param storage comes from hal_malloc()
 * (one fixed arena, allocated at first use, never freed while the process runs).
 * Implemented by libfirtp_hal_shim.so; see hal-shim/README.md for the differences.
 */
#ifndef HAL_H
#define HAL_H

#include "rtapi.h"

#if (!defined RTAPI) && (!defined ULAPI)
#error HAL needs RTAPI/ULAPI, check makefile and flags
#endif

#ifdef ULAPI
#include <signal.h>
#endif

#include "rtapi_bool.h"
#include "rtapi_errno.h"
#include "rtapi_stdint.h"

RTAPI_BEGIN_DECLS

#define HAL_NAME_LEN 47 /* longest pin, param, signal, function or thread name */

/* ---- components ---------------------------------------------------------------------------- */

/** Registers component 'name' (unique, <= HAL_NAME_LEN); returns its positive id or -errno. */
extern int hal_init(const char *name);
/** Removes the component with its pins, params and functions; 0 or -errno. */
extern int hal_exit(int comp_id);
/** Allocates 'size' zeroed bytes of HAL memory (16-byte aligned, never freed); NULL if full. */
extern void *hal_malloc(long int size);
/** Marks the component ready (no more pins/params/functions); 0 or -errno. */
extern int hal_ready(int comp_id);
/** Makes a ready component unready again so it can add pins; 0 or -errno. */
extern int hal_set_unready(int comp_id);
/** Same as hal_set_unready (LinuxCNC keeps both names). */
extern int hal_unready(int comp_id);
/** Name of component 'comp_id', or NULL when there is none. */
extern char *hal_comp_name(int comp_id);

/* ---- data types ---------------------------------------------------------------------------- */

/** Type of a pin, param or signal. */
typedef enum {
    HAL_TYPE_UNSPECIFIED = -1,
    HAL_TYPE_UNINITIALIZED = 0,
    HAL_BIT = 1,
    HAL_FLOAT = 2,
    HAL_S32 = 3,
    HAL_U32 = 4,
    HAL_PORT = 5 /* declared for compatibility; the shim has no port pins */
} hal_type_t;

/** Pin direction: a signal has at most one HAL_OUT writer, or any number of HAL_IO pins. */
typedef enum {
    HAL_DIR_UNSPECIFIED = -1,
    HAL_IN = 16,
    HAL_OUT = 32,
    HAL_IO = (HAL_IN | HAL_OUT),
} hal_pin_dir_t;

/** Parameter direction: HAL_RO params are set by their component only, HAL_RW also by setp. */
typedef enum {
    HAL_RO = 64,
    HAL_RW = HAL_RO | 128,
} hal_param_dir_t;

typedef volatile bool hal_bit_t;
typedef volatile rtapi_u32 hal_u32_t;
typedef volatile rtapi_s32 hal_s32_t;
typedef volatile int hal_port_t;
typedef double real_t __attribute__((aligned(8)));
typedef rtapi_u64 ireal_t __attribute__((aligned(8)));
#define hal_float_t volatile real_t

/** Any one HAL value. */
typedef union {
    hal_bit_t b;
    hal_s32_t s;
    hal_u32_t u;
    hal_float_t f;
    hal_port_t p;
} hal_data_u;

/* ---- pins ---------------------------------------------------------------------------------- */

/** Creates pin 'name'; *data_ptr_addr (in hal_malloc memory) then points at the pin's value. */
extern int hal_pin_bit_new(const char *name, hal_pin_dir_t dir, hal_bit_t **data_ptr_addr,
                           int comp_id);
/** As hal_pin_bit_new, for a float pin. */
extern int hal_pin_float_new(const char *name, hal_pin_dir_t dir, hal_float_t **data_ptr_addr,
                             int comp_id);
/** As hal_pin_bit_new, for a u32 pin. */
extern int hal_pin_u32_new(const char *name, hal_pin_dir_t dir, hal_u32_t **data_ptr_addr,
                           int comp_id);
/** As hal_pin_bit_new, for an s32 pin. */
extern int hal_pin_s32_new(const char *name, hal_pin_dir_t dir, hal_s32_t **data_ptr_addr,
                           int comp_id);

/** As hal_pin_bit_new, with a printf-style name. */
extern int hal_pin_bit_newf(hal_pin_dir_t dir, hal_bit_t **data_ptr_addr, int comp_id,
                            const char *fmt, ...) __attribute__((format(printf, 4, 5)));
/** As hal_pin_float_new, with a printf-style name. */
extern int hal_pin_float_newf(hal_pin_dir_t dir, hal_float_t **data_ptr_addr, int comp_id,
                              const char *fmt, ...) __attribute__((format(printf, 4, 5)));
/** As hal_pin_u32_new, with a printf-style name. */
extern int hal_pin_u32_newf(hal_pin_dir_t dir, hal_u32_t **data_ptr_addr, int comp_id,
                            const char *fmt, ...) __attribute__((format(printf, 4, 5)));
/** As hal_pin_s32_new, with a printf-style name. */
extern int hal_pin_s32_newf(hal_pin_dir_t dir, hal_s32_t **data_ptr_addr, int comp_id,
                            const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/** Untyped form of hal_pin_xxx_new (prefer the typed ones). */
extern int hal_pin_new(const char *name, hal_type_t type, hal_pin_dir_t dir,
                       void **data_ptr_addr, int comp_id);

/* ---- signals ------------------------------------------------------------------------------- */

/** Creates signal 'name' of 'type' with its own storage (initially 0). */
extern int hal_signal_new(const char *name, hal_type_t type);
/** Deletes a signal, unlinking its pins first. */
extern int hal_signal_delete(const char *name);
/** Links a pin to a signal: the pin's pointer is repointed at the signal's storage. */
extern int hal_link(const char *pin_name, const char *sig_name);
/** Unlinks a pin; it keeps the signal's last value in its dummy. */
extern int hal_unlink(const char *pin_name);

/* ---- parameters ---------------------------------------------------------------------------- */

/** Creates parameter 'name' stored at data_addr (hal_malloc memory); the value is not touched. */
extern int hal_param_bit_new(const char *name, hal_param_dir_t dir, hal_bit_t *data_addr,
                             int comp_id);
/** As hal_param_bit_new, for a float parameter. */
extern int hal_param_float_new(const char *name, hal_param_dir_t dir, hal_float_t *data_addr,
                               int comp_id);
/** As hal_param_bit_new, for a u32 parameter. */
extern int hal_param_u32_new(const char *name, hal_param_dir_t dir, hal_u32_t *data_addr,
                             int comp_id);
/** As hal_param_bit_new, for an s32 parameter. */
extern int hal_param_s32_new(const char *name, hal_param_dir_t dir, hal_s32_t *data_addr,
                             int comp_id);

/** As hal_param_bit_new, with a printf-style name. */
extern int hal_param_bit_newf(hal_param_dir_t dir, hal_bit_t *data_addr, int comp_id,
                              const char *fmt, ...) __attribute__((format(printf, 4, 5)));
/** As hal_param_float_new, with a printf-style name. */
extern int hal_param_float_newf(hal_param_dir_t dir, hal_float_t *data_addr, int comp_id,
                                const char *fmt, ...) __attribute__((format(printf, 4, 5)));
/** As hal_param_u32_new, with a printf-style name. */
extern int hal_param_u32_newf(hal_param_dir_t dir, hal_u32_t *data_addr, int comp_id,
                              const char *fmt, ...) __attribute__((format(printf, 4, 5)));
/** As hal_param_s32_new, with a printf-style name. */
extern int hal_param_s32_newf(hal_param_dir_t dir, hal_s32_t *data_addr, int comp_id,
                              const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/** Untyped form of hal_param_xxx_new (prefer the typed ones). */
extern int hal_param_new(const char *name, hal_type_t type, hal_param_dir_t dir,
                         void *data_addr, int comp_id);

/** Sets a HAL_RW bit parameter by name. */
extern int hal_param_bit_set(const char *name, int value);
/** Sets a HAL_RW float parameter by name. */
extern int hal_param_float_set(const char *name, double value);
/** Sets a HAL_RW u32 parameter by name. */
extern int hal_param_u32_set(const char *name, unsigned long value);
/** Sets a HAL_RW s32 parameter by name. */
extern int hal_param_s32_set(const char *name, signed long value);
/** Sets a HAL_RW parameter of 'type' from *value_addr. */
extern int hal_param_set(const char *name, hal_type_t type, void *value_addr);

/* ---- lookups by name ----------------------------------------------------------------------- */

/** Finds a pin: its type, its value's address, whether a signal is linked; 0 or -1. */
extern int hal_get_pin_value_by_name(const char *name, hal_type_t *type, hal_data_u **data,
                                     bool *connected);
/** Finds a signal: its type, its value's address, whether it has a writer; 0 or -1. */
extern int hal_get_signal_value_by_name(const char *name, hal_type_t *type, hal_data_u **data,
                                        bool *has_writers);
/** Finds a parameter: its type and its value's address; 0 or -1. */
extern int hal_get_param_value_by_name(const char *name, hal_type_t *type, hal_data_u **data);

/* ---- functions and threads ----------------------------------------------------------------- */

#ifdef RTAPI
/** Exports funct(arg, period_ns) as HAL function 'name' (plus params name.time, name.tmax). */
extern int hal_export_funct(const char *name, void (*funct)(void *, long), void *arg,
                            int uses_fp, int reentrant, int comp_id);
/** As hal_export_funct, with a printf-style name (newer LinuxCNC; see README). */
extern int hal_export_functf(void (*funct)(void *, long), void *arg, int uses_fp, int reentrant,
                             int comp_id, const char *fmt, ...)
    __attribute__((format(printf, 6, 7)));
/** Creates a periodic thread; the first sets the base period, later ones are rounded to a
    multiple of it.  Returns a positive id or -errno. */
extern int hal_create_thread(const char *name, unsigned long period_nsec, int uses_fp);
/** Deletes a thread (its functions are removed from it first). */
extern int hal_thread_delete(const char *name);
#endif /* RTAPI */

/** Adds a function to a thread at 'position' (1 = first, -1 = last). */
extern int hal_add_funct_to_thread(const char *funct_name, const char *thread_name,
                                   int position);
/** Removes a function from a thread. */
extern int hal_del_funct_from_thread(const char *funct_name, const char *thread_name);
/** Starts every thread (realtime clock). */
extern int hal_start_threads(void);
/** Stops every thread, returning after their current cycle ended. */
extern int hal_stop_threads(void);

/** Instance constructor ('newinst'); stored but never called by the shim. */
typedef int (*constructor)(char *prefix, char *arg);
/** Stores a component's instance constructor. */
extern int hal_set_constructor(int comp_id, constructor make);

/* ---- streams: lock-free single-producer single-consumer rings found by key ----------------- */

/** One element of a stream record. */
union hal_stream_data {
    real_t f;
    bool b;
    int32_t s;
    uint32_t u;
};

/** A handle on a stream (create or attach fills it). */
typedef struct {
    int comp_id, shmem_id;
    struct hal_stream_shm *fifo;
} hal_stream_t;

#define HAL_STREAM_MAX_PINS (21)

/** Creates stream 'key' with 'depth' slots (depth-1 records fit) of 'typestring' ("fbsu"). */
extern int hal_stream_create(hal_stream_t *stream, int comp, int key, int depth,
                             const char *typestring);
/** Detaches from a stream; the memory is freed when the last user detaches. */
extern void hal_stream_destroy(hal_stream_t *stream);
/** Attaches to stream 'key'; typestring (or NULL) must match its element types. */
extern int hal_stream_attach(hal_stream_t *stream, int comp, int key, const char *typestring);
/** Detaches from a stream. */
extern int hal_stream_detach(hal_stream_t *stream);

/** Number of elements in one record. */
extern int hal_stream_element_count(hal_stream_t *stream);
/** Type of element 'idx' of a record. */
extern hal_type_t hal_stream_element_type(hal_stream_t *stream, int idx);

/** Reader: pops one record into buf (and its sample number); 0, or -ENOSPC when empty. */
extern int hal_stream_read(hal_stream_t *stream, union hal_stream_data *buf, unsigned *sampleno);
/** Reader: true when a record is waiting. */
extern bool hal_stream_readable(hal_stream_t *stream);
/** Number of records waiting. */
extern int hal_stream_depth(hal_stream_t *stream);
/** Number of slots given at creation (one more than the records that fit). */
extern int hal_stream_maxdepth(hal_stream_t *stream);
/** Reads that found the stream empty. */
extern int hal_stream_num_underruns(hal_stream_t *stream);
/** Writes that found the stream full. */
extern int hal_stream_num_overruns(hal_stream_t *stream);
#ifdef ULAPI
/** Sleeps in 10 ms steps until readable or *stop is set. */
extern void hal_stream_wait_readable(hal_stream_t *stream, sig_atomic_t *stop);
#endif

/** Writer: pushes one record from buf; 0, or -ENOSPC (and an overrun counted) when full. */
extern int hal_stream_write(hal_stream_t *stream, union hal_stream_data *buf);
/** Writer: true when a record fits. */
extern bool hal_stream_writable(hal_stream_t *stream);
#ifdef ULAPI
/** Sleeps in 10 ms steps until writable or *stop is set. */
extern void hal_stream_wait_writable(hal_stream_t *stream, sig_atomic_t *stop);
#endif

RTAPI_END_DECLS

#endif /* HAL_H */
