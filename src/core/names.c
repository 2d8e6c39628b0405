/* SPDX-License-Identifier: MIT */
/* The library's names for things: statuses, boundaries, broad phases
 * (the integrators' names are in their tables), and its version. */
#include "disk_sim.h"

const char *ds_status_str(ds_status status)
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
    }
    return "unknown status";
}

const char *ds_version(void) { return DS_VERSION_STRING; }

const char *ds_boundary_name(ds_boundary boundary)
{
    switch (boundary) {
    case DS_WALLS:
        return "walls";
    case DS_PERIODIC:
        return "periodic";
    }
    return "unknown";
}

const char *ds_broadphase_name(ds_broadphase bp)
{
    switch (bp) {
    case DS_SAP:
        return "sap";
    case DS_BRUTE_FORCE:
        return "brute";
    case DS_SAP_STRIPS:
        return "strips";
    case DS_AUTO:
        return "auto";
    case DS_CELLS:
        return "cells";
    }
    return "unknown";
}
