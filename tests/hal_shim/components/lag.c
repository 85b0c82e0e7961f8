/* lag.c - test component: first-order lag, written exactly as a LinuxCNC 2.9 realtime component.
 *
 *   loadrt lag [count=N] [prefix=NAME]
 * per instance i:  pins  NAME.i.in (float in), NAME.i.out (float out), NAME.i.reset (bit in)
 *                  params NAME.i.tau (float rw, s; 0 = pass through), NAME.i.runs (s32 ro)
 *                  funct NAME.i: out += (in - out) * (1 - exp(-period/tau)); reset sets out = 0
 */
#include "rtapi.h"
#include "rtapi_app.h"
#include "hal.h"
#include "rtapi_math.h"

MODULE_AUTHOR("firtp");
MODULE_DESCRIPTION("First-order lag (hal-shim test component)");
MODULE_LICENSE("GPL");

static int count = 1;
RTAPI_MP_INT(count, "number of lags (1..8)");
static char *prefix = "lag";
RTAPI_MP_STRING(prefix, "name prefix of pins, params and functions");

struct lag {
    hal_float_t *in;
    hal_float_t *out;
    hal_bit_t *reset;
    hal_float_t tau;
    hal_s32_t runs;
};

static int comp_id;
static struct lag *lags;

/* One period: move 'out' towards 'in' with time constant tau. */
static void update(void *arg, long period) {
    struct lag *l = arg;
    double dt = (double)period * 1e-9;
    if (*l->reset) {
        *l->out = 0.0;
    } else if (l->tau <= 0.0) {
        *l->out = *l->in;
    } else {
        *l->out += (*l->in - *l->out) * (1.0 - exp(-dt / l->tau));
    }
    l->runs++;
}

/* Creates the pins, params and function of instance i. */
static int export_lag(int i) {
    struct lag *l = &lags[i];
    char name[HAL_NAME_LEN + 1];
    int r;
    r = hal_pin_float_newf(HAL_IN, &l->in, comp_id, "%s.%d.in", prefix, i);
    if (r < 0) return r;
    r = hal_pin_float_newf(HAL_OUT, &l->out, comp_id, "%s.%d.out", prefix, i);
    if (r < 0) return r;
    r = hal_pin_bit_newf(HAL_IN, &l->reset, comp_id, "%s.%d.reset", prefix, i);
    if (r < 0) return r;
    r = hal_param_float_newf(HAL_RW, &l->tau, comp_id, "%s.%d.tau", prefix, i);
    if (r < 0) return r;
    r = hal_param_s32_newf(HAL_RO, &l->runs, comp_id, "%s.%d.runs", prefix, i);
    if (r < 0) return r;
    l->tau = 0.01;
    l->runs = 0;
    rtapi_snprintf(name, sizeof(name), "%s.%d", prefix, i);
    return hal_export_funct(name, update, l, 1, 0, comp_id);
}

int rtapi_app_main(void) {
    int i, r;
    if (count < 1 || count > 8) {
        rtapi_print_msg(RTAPI_MSG_ERR, "lag: count=%d is not in 1..8\n", count);
        return -EINVAL;
    }
    comp_id = hal_init(prefix);
    if (comp_id < 0) return comp_id;
    lags = hal_malloc((long)(count * (int)sizeof(struct lag)));
    if (lags == 0) {
        hal_exit(comp_id);
        return -ENOMEM;
    }
    for (i = 0; i < count; i++) {
        r = export_lag(i);
        if (r < 0) {
            hal_exit(comp_id);
            return r;
        }
    }
    hal_ready(comp_id);
    return 0;
}

void rtapi_app_exit(void) {
    hal_exit(comp_id);
}
