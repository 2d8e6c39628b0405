/* SPDX-License-Identifier: MIT */
/* A stream read into memory up to a length its header announced, the
 * memory following the bytes that arrive (io/io.h). */
#include <stdlib.h>
#include <string.h>

#include "io/io.h"

ds_status ds_read_up_to(FILE *in, const uint8_t *head, size_t len, size_t want, uint8_t **out,
                        size_t *got)
{
    size_t cap = want < ((size_t)1 << 16) ? want : (size_t)1 << 16;
    cap = cap > len ? cap : len;
    uint8_t *buf = malloc(cap ? cap : 1);
    if (!buf)
        return DS_ERR_NOMEM;
    memcpy(buf, head, len);
    for (;;) {
        len += fread(buf + len, 1, cap - len, in);
        if (len < cap || cap >= want)
            break; /* the stream ended, or all that was wanted is here */
        const size_t next = cap > want / 2 ? want : 2 * cap;
        uint8_t *more = realloc(buf, next);
        if (!more) {
            free(buf);
            return DS_ERR_NOMEM;
        }
        buf = more;
        cap = next;
    }
    *out = buf;
    *got = len;
    return DS_OK;
}
