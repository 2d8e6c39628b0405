/* Filling a ds_params_error: the refusals of params.c and of each
 * integrator's own check (core.h). */
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
