/* SPDX-License-Identifier: MIT */
/* A program written for disksim 2.1's API, as its users wrote them: a
 * check of the request, a mixture compressed by growth in a periodic box,
 * its contacts and observables, a checkpoint saved and loaded, the disks
 * read and set, a frame formatted. tests/migrate.sh moves it to 3.0 with
 * tools/migrate/disksim3.py, builds it against this library and holds
 * its output to program_2x.out, what it printed built against 2.1.0
 * (every number below is a double's bits or a count: 3.0 computes the
 * same). Not built by make. */
#include <stdio.h>
#include <stdlib.h>

#include <disk_sim.h>

static void print_state(const char *what, const ds_sim *sim)
{
    double px, py, s[3];
    ds_momentum(sim, &px, &py);
    ds_stress_integral(sim, s);
    printf("%s: t %.17g steps %llu collisions %llu eta %.17g K %.17g p (%.17g, %.17g)\n", what,
           ds_time(sim), (unsigned long long)ds_steps(sim),
           (unsigned long long)ds_collision_count(sim), ds_area_fraction(sim),
           ds_kinetic_energy(sim), px, py);
    printf("%s: P %.17g virial %.17g kT %.17g Z %.17g stress %.17g %.17g %.17g\n", what,
           ds_pressure(sim), ds_virial_pressure(sim), ds_temperature(sim),
           ds_compressibility(sim), s[0], s[1], s[2]);
}

int main(void)
{
    ds_params p = ds_default_params(120, 8.0);
    p.box = 400.0;
    p.box_y = 400.0;
    p.integrator = DS_EVENT_DRIVEN;
    p.boundary = DS_PERIODIC;
    p.broadphase = DS_CELLS;
    p.seed = 12345;

    /* A request refused, and why. */
    ds_params bad = p;
    bad.radius = 300.0;
    ds_params_error why;
    unsigned warnings = 0;
    if (ds_diagnose_params(&bad, &warnings, &why) != DS_ERR_ARG)
        return 1;
    printf("refused: %s (%s)\n", why.message, why.field);

    static const ds_species kinds[2] = {{60, 8.0, 0.0}, {60, 11.2, 0.0}};
    const ds_mixture mixture = {2, kinds, NULL, NULL, DS_MASS_AREA};
    size_t bytes = 0;
    if (ds_memory_needed_mixture(&p, &mixture, &bytes) != DS_OK || bytes == 0)
        return 1;
    ds_sim *sim = NULL;
    if (ds_create_mixture(&p, &mixture, &sim) != DS_OK)
        return 1;
    printf("%s, %s, %s: %zu disks, box %g x %g, R %g, largest %g\n",
           ds_integrator_name(ds_integrator_used(sim)), ds_boundary_name(ds_boundary_used(sim)),
           ds_broadphase_name(ds_broadphase_used(sim)), ds_count(sim), ds_box(sim),
           ds_box_y(sim), ds_radius(sim), ds_radius_max(sim));

    ds_run(sim, 200);
    print_state("fluid", sim);
    ds_reset_observables(sim);
    if (ds_set_growth(sim, 0.05, 0.70, 0.0) != DS_OK)
        return 1;
    while (ds_growth_state_of(sim) == DS_GROWING && ds_steps(sim) < 200000)
        ds_step(sim);
    printf("grown: state %d at step %llu, Z %.17g\n", (int)ds_growth_state_of(sim),
           (unsigned long long)ds_steps(sim), ds_growth_z(sim));
    ds_contacts c;
    if (ds_count_contacts(sim, 1e-3, &c) != DS_OK)
        return 1;
    printf("contacts: %zu pairs, %zu rattlers, %.17g per disk\n", c.pairs, c.rattlers,
           c.per_disk);

    /* A checkpoint to memory and back; both go on alike. */
    size_t len = ds_state_size(sim);
    char *buf = malloc(len);
    if (!buf || ds_format_state(sim, buf, len, &len) != DS_OK)
        return 1;
    ds_sim *copy = NULL;
    ds_state_error serr;
    if (ds_parse_state(buf, len, &copy, &serr) != DS_OK)
        return 1;
    free(buf);
    ds_run(sim, 300);
    ds_run(copy, 300);
    print_state("run on", sim);
    print_state("its copy", copy);

    /* The disks, read, slowed and set back; the radii and masses. */
    ds_disk *d = malloc(ds_count(sim) * sizeof *d);
    double *radii = malloc(ds_count(sim) * sizeof *radii);
    double *masses = malloc(ds_count(sim) * sizeof *masses);
    int32_t *image = malloc(2 * ds_count(sim) * sizeof *image);
    if (!d || !radii || !masses || !image || ds_get_all(sim, d) != DS_OK ||
        ds_get_radii(sim, radii, NULL) != DS_OK || ds_get_radii(sim, NULL, masses) != DS_OK ||
        ds_get_images(sim, image) != DS_OK)
        return 1;
    printf("disk 7: %.17g %.17g %.17g %.17g r %.17g m %.17g image %d %d\n", d[7].x, d[7].y,
           d[7].vx, d[7].vy, radii[7], masses[7], (int)image[14], (int)image[15]);
    if (ds_scale_velocities(sim, 0.5) != DS_OK || ds_set_all(sim, d, &serr) != DS_OK)
        return 1;
    ds_disk one = ds_get(sim, 3);
    one.vx = -one.vx;
    if (ds_set(sim, 3, one) != DS_OK)
        return 1;
    ds_run(sim, 100);
    print_state("set", sim);

    char frame[64];
    size_t need = 0;
    if (ds_format_frame(sim, 0, frame, sizeof frame, &need) != DS_ERR_ARG)
        return 1;
    printf("a frame takes %zu bytes (%zu at most)\n", need, ds_frame_size(sim, 0));
    ds_destroy(copy);
    ds_destroy(sim);
    free(d);
    free(radii);
    free(masses);
    free(image);
    return 0;
}
