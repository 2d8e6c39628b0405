/* SPDX-License-Identifier: MIT */
/* The protocols' hooks, called by the integrators (see protocol.h). */
#include <math.h>

#include "core/core.h"

void ds_protocols_refresh(ds_protocols *p)
{
    p->next = INFINITY;
    p->asap = p->watching = p->stepping = 0;
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k) {
        const ds_protocol_slot *s = &p->slot[k];
        if (!s->ops)
            continue;
        p->next = s->clock.next < p->next ? s->clock.next : p->next;
        p->asap |= s->clock.asap;
        p->watching |= s->clock.watching;
        p->stepping |= s->clock.stepping;
    }
}

void ds_protocols_fire(ds_sim *sim, double t, double end)
{
    ds_protocols *p = &sim->protocols;
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k) {
        ds_protocol_slot *s = &p->slot[k];
        if (s->ops && s->ops->fire &&
            ((s->clock.next <= t && s->clock.next <= end) || (s->clock.asap && t < end)))
            s->ops->fire(sim, s->self, t, end);
    }
    ds_protocols_refresh(p);
}

void ds_protocols_collided(ds_sim *sim, const ds_collision *c)
{
    ds_protocols *p = &sim->protocols;
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k)
        if (p->slot[k].ops && p->slot[k].clock.watching)
            p->slot[k].ops->collided(sim, p->slot[k].self, c);
    ds_protocols_refresh(p);
}

ds_status ds_protocols_step_end(ds_sim *sim, ds_error *err)
{
    ds_protocols *p = &sim->protocols;
    ds_status st = DS_OK;
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT && st == DS_OK; ++k)
        if (p->slot[k].ops && p->slot[k].clock.stepping) {
            st = p->slot[k].ops->step_end(sim, p->slot[k].self);
            if (st != DS_OK)
                ds_refuse(err, st, "steps", (double)sim->steps, NAN,
                          "steps: no memory for what the %s protocol needed after step %llu "
                          "(growth's wider cells, a barostat's new box): the run stopped there",
                          p->slot[k].ops->name, (unsigned long long)sim->steps);
        }
    ds_protocols_refresh(p);
    return st;
}

void ds_protocols_rebased(ds_sim *sim, double by)
{
    ds_protocols *p = &sim->protocols;
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k)
        if (p->slot[k].ops) { /* every clock moves; the hook for the times a protocol keeps */
            if (p->slot[k].ops->rebased)
                p->slot[k].ops->rebased(p->slot[k].self, by);
            p->slot[k].clock.next -= by;
        }
    ds_protocols_refresh(p);
}

void ds_protocols_rebuilt(ds_sim *sim)
{
    ds_protocols *p = &sim->protocols;
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k)
        if (p->slot[k].ops && p->slot[k].ops->rebuilt)
            p->slot[k].ops->rebuilt(sim, p->slot[k].self);
    ds_protocols_refresh(p);
}

void ds_protocols_disks_set(ds_sim *sim, int all)
{
    ds_protocols *p = &sim->protocols;
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k)
        if (p->slot[k].ops && p->slot[k].ops->disks_set)
            p->slot[k].ops->disks_set(sim, p->slot[k].self, all);
    ds_protocols_refresh(p);
}

void ds_protocols_scaled(ds_sim *sim, double factor)
{
    ds_protocols *p = &sim->protocols;
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k)
        if (p->slot[k].ops && p->slot[k].ops->scaled)
            p->slot[k].ops->scaled(sim, p->slot[k].self, factor);
    ds_protocols_refresh(p);
}

double ds_protocols_temperature(const ds_sim *sim)
{
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k) {
        const ds_protocol_slot *s = &sim->protocols.slot[k];
        const double kt = s->ops && s->ops->temperature ? s->ops->temperature(s->self) : 0.0;
        if (kt > 0.0)
            return kt;
    }
    return 0.0;
}

void ds_protocols_install(ds_sim *sim, const ds_protocol_ops *ops, void *self)
{
    ds_protocol_slot *s = &sim->protocols.slot[ops->kind];
    if (s->ops && s->self != self)
        s->ops->destroy(s->self);
    s->ops = ops;
    s->self = self;
    s->clock.next = INFINITY;
    s->clock.asap = s->clock.watching = s->clock.stepping = 0;
    ds_protocols_refresh(&sim->protocols);
}

void ds_protocols_remove(ds_sim *sim, ds_protocol_kind kind)
{
    ds_protocol_slot *s = &sim->protocols.slot[kind];
    if (s->ops)
        s->ops->destroy(s->self);
    s->ops = NULL;
    s->self = NULL;
    ds_protocols_refresh(&sim->protocols);
}

void ds_protocols_destroy_all(ds_protocols *p)
{
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k) {
        if (p->slot[k].ops)
            p->slot[k].ops->destroy(p->slot[k].self);
        p->slot[k].ops = NULL;
        p->slot[k].self = NULL;
    }
    ds_protocols_refresh(p);
}

void *ds_protocols_get(const ds_sim *sim, ds_protocol_kind kind)
{
    const ds_protocol_slot *s = &sim->protocols.slot[kind];
    return s->ops ? s->self : NULL;
}

ds_protocol_clock *ds_protocols_clock(ds_sim *sim, ds_protocol_kind kind)
{
    return &sim->protocols.slot[kind].clock;
}

void ds_protocols_save(const ds_sim *sim, ds_state_writer *w)
{
    const ds_protocols *p = &sim->protocols;
    uint32_t count = 0;
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k)
        count += p->slot[k].ops != NULL;
    ds_put_u32(w, count);
    for (int k = 0; k < DS_PROTOCOL_KIND_COUNT; ++k) {
        const ds_protocol_slot *s = &p->slot[k];
        if (!s->ops)
            continue;
        ds_put_u32(w, (uint32_t)k);
        ds_put_f64(w, s->clock.next);
        ds_put_u32(w, (uint32_t)s->clock.asap | (uint32_t)s->clock.watching << 1 |
                          (uint32_t)s->clock.stepping << 2);
        s->ops->save(sim, s->self, w);
    }
}

ds_status ds_protocols_load(ds_sim *sim, const ds_protocol_ops *const *table, ds_reader *r,
                            ds_error *err)
{
    const uint32_t count = ds_get_u32(r);
    if (r->failed || count > DS_PROTOCOL_KIND_COUNT)
        return ds_state_refuse(err, DS_ERR_FORMAT, "its protocols are not a list of them");
    int last = -1;
    for (uint32_t c = 0; c < count; ++c) {
        const uint32_t kind = ds_get_u32(r);
        const double next = ds_get_f64(r);
        const uint32_t flags = ds_get_u32(r);
        /* Each kind once, in slot order, as save writes them. */
        if (r->failed || kind >= DS_PROTOCOL_KIND_COUNT || (int)kind <= last || flags > 7u ||
            isnan(next))
            return ds_state_refuse(err, DS_ERR_FORMAT, "protocol %u of its list is not one", c);
        last = (int)kind;
        void *self = NULL;
        const ds_status st = table[kind]->load(sim, &self, r, err);
        if (st != DS_OK) {
            if (self)
                table[kind]->destroy(self);
            return st;
        }
        ds_protocol_slot *s = &sim->protocols.slot[kind];
        s->ops = table[kind];
        s->self = self;
        s->clock.next = next;
        s->clock.asap = (int)(flags & 1u);
        s->clock.watching = (int)(flags >> 1 & 1u);
        s->clock.stepping = (int)(flags >> 2 & 1u);
    }
    ds_protocols_refresh(&sim->protocols);
    return DS_OK;
}
