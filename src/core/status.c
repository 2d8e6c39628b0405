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
        return "malformed frame";
    case DS_ERR_OVERLAP:
        return "the disk would overlap another";
    }
    return "unknown status";
}

const char *ds_version(void) { return DS_VERSION_STRING; }
