/* SPDX-License-Identifier: MIT */
/* The error model (disksim/base.h): a ds_status returned, and an optional
 * ds_error filled with the field at fault, the value, the limit it broke
 * and a sentence. Every refusal of the library is made through here. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "core/core.h"

const char *ds_status_name(ds_status status)
{
    switch (status) {
    case DS_OK:
        return "success";
    case DS_ERR_ARG:
        return "invalid argument";
    case DS_ERR_NOMEM:
        return "out of memory";
    case DS_ERR_PLACEMENT:
        return "disks cannot be placed without overlap";
    case DS_ERR_IO:
        return "input/output error";
    case DS_ERR_FORMAT:
        return "malformed frame or checkpoint";
    case DS_ERR_OVERLAP:
        return "the disk would overlap another";
    case DS_STATUS_COUNT:
        break;
    }
    return "unknown status";
}

void ds_error_clear(ds_error *err)
{
    if (!err)
        return;
    memset(err, 0, sizeof *err);
    err->status = DS_OK;
    err->value = NAN;
    err->limit = NAN;
}

static ds_status vrefuse(ds_error *err, ds_status status, const char *field, double value,
                         double limit, const char *fmt, va_list ap)
{
    if (err) {
        err->status = status;
        snprintf(err->field, sizeof err->field, "%s", field);
        err->value = value;
        err->limit = limit;
        vsnprintf(err->message, sizeof err->message, fmt, ap);
    }
    return status;
}

ds_status ds_refuse(ds_error *err, ds_status status, const char *field, double value, double limit,
                    const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vrefuse(err, status, field, value, limit, fmt, ap);
    va_end(ap);
    return status;
}

ds_status ds_state_refuse(ds_error *err, ds_status status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vrefuse(err, status, "checkpoint", NAN, NAN, fmt, ap);
    va_end(ap);
    return status;
}

void ds_error_index(ds_error *err, size_t index)
{
    if (err)
        err->index = index;
}

ds_status ds_error_done(ds_error *err, ds_status status)
{
    if (!err)
        return status;
    err->status = status;
    if (status == DS_OK) {
        err->field[0] = '\0';
        err->message[0] = '\0';
        err->value = NAN;
        err->limit = NAN;
        err->index = 0;
    } else if (!err->message[0]) {
        snprintf(err->message, sizeof err->message, "%s", ds_status_name(status));
    }
    return status;
}
