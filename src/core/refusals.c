/* SPDX-License-Identifier: MIT */
/* Refusals with their reasons: a ds_params_error (sim/params.c and each
 * integrator's own check) and a ds_state_error (a state to set or load). */
#include <stdarg.h>
#include <stdio.h>

#include "core/core.h"

ds_status ds_refuse(ds_params_error *err, ds_status status, const char *field, const char *fmt, ...)
{
    if (err) {
        snprintf(err->field, sizeof err->field, "%s", field);
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
    }
    return status;
}

ds_status ds_state_refuse(ds_state_error *err, ds_status status, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
    }
    return status;
}
