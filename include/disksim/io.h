/* SPDX-License-Identifier: MIT */
/*
 * disksim: files. Text frames ("x y R" lines, the seed's), extended XYZ
 * trajectories, writers behind one interface (ds_writer), and checkpoints
 * that save and load a simulation to the bit. Included by disk_sim.h.
 */
#ifndef DISKSIM_IO_H
#define DISKSIM_IO_H

#include <stdio.h>

#include "disksim/sim.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ */
/* Frames: text files of lines "x y R" or "x y R vx vy"                */
/* ------------------------------------------------------------------ */

/* One line per disk in generation order: x and y with 6 decimals, R (the
 * disk's own radius) in the shortest form that reads back as the same
 * double, and with velocities (velocities not 0) vx and vy with 6
 * decimals. ds_frame_format writes into buf (at most cap bytes, no NUL):
 * with cap too small it returns DS_ERR_ARG; *len receives the bytes
 * needed either way, so buf NULL with cap 0 asks only for the size.
 * ds_frame_get_size tells a capacity that is always enough (0 for NULL).
 * ds_frame_write writes to out, flushed (DS_ERR_IO if the write fails,
 * DS_ERR_NOMEM without memory for the text). */
size_t ds_frame_get_size(const ds_sim *sim, int velocities);
ds_status ds_frame_format(const ds_sim *sim, int velocities, char *buf, size_t cap, size_t *len,
                          ds_error *err);
ds_status ds_frame_write(const ds_sim *sim, int velocities, FILE *out, ds_error *err);

/* One disk read from a frame file. vx, vy are 0 in 3-column frames. */
typedef struct ds_frame_disk {
    double x, y, r, vx, vy;
} ds_frame_disk;

typedef struct ds_frame {
    ds_frame_disk *disks; /* malloc'd, free with ds_frame_free */
    size_t count;
    int columns; /* 3 or 5 (all lines agree); 0 for an empty frame */
} ds_frame;

/* Parses a frame held in memory (need not be NUL-terminated). Every line
 * must hold 3 or 5 finite numbers, all lines the same count, R > 0.
 * Blank lines and lines starting with '#' are skipped; an empty frame is
 * DS_ERR_FORMAT. err (field "frame", index the 1-based line, 0 if not
 * about a line) says why, its message the reason alone ("expected 3 or 5
 * numbers"). On error *frame is left empty. */
ds_status ds_frame_parse(const char *text, size_t len, ds_frame *frame, ds_error *err);
/* Reads and parses a file (DS_ERR_IO if it cannot be read, err's message
 * saying why). On error *frame is left empty, as with ds_frame_parse. */
ds_status ds_frame_read(const char *path, ds_frame *frame, ds_error *err);
void ds_frame_free(ds_frame *frame);

/* ------------------------------------------------------------------ */
/* Extended XYZ, read by ASE, OVITO and VMD                             */
/* ------------------------------------------------------------------ */

/* One frame of an extended XYZ trajectory; frames written one after
 * another to the same file make the trajectory. A frame is the disk count
 * on a line, the comment line
 *   Lattice="Lx 0 0 0 Ly 0 0 0 H" Properties=P Time=T pbc="F F F"
 * with walls (pbc="T T F" in a periodic box, "T F F" in a channel), P
 *   type:S:1:pos:R:3:radius:R:1:velo:R:3:momenta:R:3:mass:R:1:masses:R:1
 * and outside walls P:map_shift:I:3 (one line; Lx and Ly the box's sides,
 * ds_sim_get_box_width and ds_sim_get_box_height, and H twice the
 * largest radius, ds_sim_get_radius_max, each in the shortest form that
 * reads back exactly; T the simulated time with 6 decimals), then one
 * line per disk in generation order,
 *   K x y 0 r vx vy 0 px py 0 m m           with walls
 *   K x y 0 r vx vy 0 px py 0 m m ix iy 0   in a periodic box or channel
 * with K the name of the disk's kind (ds_sim_get_kind_name), x, y, vx, vy
 * and its momentum px = m vx, py = m vy written like frames (6
 * decimals), r its own radius (ds_sim_get_radii) and m its mass
 * (ds_sim_get_masses) in the shortest form that reads back exactly, and
 * ix, iy its image counts (ds_sim_get_images), so x + ix Lx, y + iy Ly is
 * its unwrapped centre. A sheared box (ds_sim_set_shear) ends the
 * comment line with " shear_offset=S", S its images' offset unwrapped
 * (ds_sim_get_shear_offset) in the shortest form that reads back: the
 * unwrapped x is then x + ix Lx + iy S; the cell stays rectangular. The
 * 2D box is written as a cell of height H with
 * every disk at z = 0, periodic along x and y only. The columns are named
 * for the two readers: OVITO maps type, pos, radius, velo, mass and
 * map_shift to Particle Type, Position, Radius, Velocity, Mass and
 * Periodic Image; ASE (ase.io.read) maps pos to positions and keeps the
 * rest as per-atom arrays of their names, reading momenta and masses as
 * its momenta and masses (so get_velocities() is vx, vy, 0), its atoms
 * the dummy "X" (no species column: a kind's name is no chemical symbol),
 * with cell, pbc and info "Time". OVITO takes a cell as 2D only without a
 * z column, which ASE needs: it sees a flat 3D cell. ds_xyz_format works
 * like ds_frame_format (ds_xyz_get_size is always enough); ds_xyz_write
 * writes one frame to out, flushed (DS_ERR_IO if the write fails). */
size_t ds_xyz_get_size(const ds_sim *sim);
ds_status ds_xyz_format(const ds_sim *sim, char *buf, size_t cap, size_t *len, ds_error *err);
ds_status ds_xyz_write(const ds_sim *sim, FILE *out, ds_error *err);

/* ------------------------------------------------------------------ */
/* Writers: every trajectory format behind one interface               */
/* ------------------------------------------------------------------ */

typedef enum ds_format {
    DS_FORMAT_FRAME = 0, /* "frame": a text frame a write, lines "x y R [vx vy]" */
    DS_FORMAT_XYZ,       /* "xyz": extended XYZ, a frame a write */
    DS_FORMAT_GSD,       /* "gsd": a GSD file (HOOMD schema), a frame a write */
    DS_FORMAT_COUNT
} ds_format;
const char *ds_format_name(ds_format format); /* "frame", "xyz", "gsd"; "unknown" */
ds_status ds_format_parse(const char *name, ds_format *out, ds_error *err);

/* "gsd" writes GSD 2.0 files in the HOOMD schema 1.4, the trajectory
 * format HOOMD-blue writes and OVITO, VMD, freud, MDAnalysis and the gsd
 * Python package read (gsd.hoomd.open). Each write is a frame holding:
 *   configuration/step        uint64  sim's step count (ds_sim_get_steps)
 *   configuration/dimensions  uint8   2
 *   configuration/box         float   Lx Ly 0 0 0 0 (a 2D box has Lz 0)
 *   particles/N               uint32  the disk count
 *   particles/types           int8    the kinds' names (ds_sim_get_kind_name)
 *   particles/typeid          uint32  each disk's kind (ds_sim_get_kinds)
 *   particles/mass            float   each disk's mass
 *   particles/diameter        float   each disk's 2 r
 *   particles/position        float   x - Lx/2, y - Ly/2, 0: the box centred
 *                                     on the origin, as HOOMD places it
 *   particles/velocity        float   vx, vy, 0
 *   particles/image           int32   ix, iy, 0 (ds_sim_get_images)
 *   log/disksim/NAME          the command's --stats columns after frame: time,
 *                             kinetic_energy, px, py, pressure,
 *                             virial_pressure, psi6 (NaN where the library
 *                             has none), area_fraction (float64) and
 *                             collisions, wall_reflections (uint64); and
 *                             shear_offset (float64): a sheared box's
 *                             image above stands that far along x, unwrapped
 *                             (ds_sim_get_shear_offset, 0 without shear),
 *                             so x + ix Lx + iy shear_offset unwraps; the
 *                             box keeps no tilt (its xy 0)
 * in generation order (HOOMD's tag order), every number little-endian.
 * Frame 0 holds every chunk; a later frame holds the step, positions,
 * velocities and log, and the other chunks only where they differ from
 * frame 0's (the schema reads a missing chunk from frame 0): the
 * diameters of a growth, the images of a periodic box. A centre that
 * float rounding puts on the box's +L/2 side of a periodic axis is
 * written at -L/2 with its image one more, as HOOMD requires -L/2 <= x <
 * L/2 (so x + ix Lx is the unwrapped centre to float rounding). GSD has
 * no walls: every HOOMD box is periodic, and a box with walls is written
 * with its sides and images 0. After every write the file is a valid
 * GSD file of the frames written: a frame's chunks are written before the
 * index entries that point at them, and the index is flushed with them.
 * The stream must be able to seek (DS_ERR_ARG otherwise: a pipe cannot
 * hold a GSD file). Empty, ds_writer_open writes the header, the chunks'
 * names and an empty index there (DS_ERR_IO if that fails); holding a GSD
 * file this writer wrote, it goes on with it: its frames are kept and
 * each write appends one (frame 0's chunks still decide what a frame
 * leaves out), which needs a stream it can read too, opened "r+b" or
 * "w+b" (DS_ERR_ARG otherwise); holding anything else, DS_ERR_FORMAT.
 * Offsets past LONG_MAX (2 GiB where long has 32 bits) are DS_ERR_IO. */

/* What a writer writes beyond positions and radii, where its format can
 * (bits of flags): velocities (a frame's vx vy columns; XYZ and GSD always
 * have them). */
#define DS_WRITE_VELOCITIES 1u

typedef struct ds_writer ds_writer; /* opaque */

/* A writer of format into out (opened by the caller, binary mode where it
 * matters; the writer never closes it): DS_ERR_ARG for an unknown format
 * or flag, or NULL. Each ds_writer_write writes the state of sim at
 * ds_sim_get_time as one frame and flushes (DS_ERR_IO if that fails),
 * so the file holds whole frames after every call. ds_writer_close
 * finishes the file (DS_ERR_IO if that fails) and frees the writer (NULL
 * is fine), whatever it returns. */
ds_status ds_writer_open(ds_format format, FILE *out, unsigned flags, ds_writer **writer,
                         ds_error *err);
ds_status ds_writer_write(ds_writer *writer, const ds_sim *sim, ds_error *err);
ds_status ds_writer_close(ds_writer *writer, ds_error *err);

/* ------------------------------------------------------------------ */
/* Checkpoints: a simulation saved and loaded to the bit               */
/* ------------------------------------------------------------------ */

/* A checkpoint holds everything the next step depends on: the parameters,
 * the time and step count, every disk's position and velocity to the bit
 * (in the order the broad phase keeps them), radius, mass and image
 * counts, the observables' accumulators (wall impulse and count, virial,
 * collision and test counts, the collision timer, the pressure tensor's
 * parts of ds_sim_get_stress_integral), the integrator's own state (the
 * time step's strips; the event-driven records, cells and clock) and
 * each protocol's (a growth's). A loaded simulation goes on bit for bit as the saved one
 * would have, for every integrator, boundary and broad phase
 * and a growth; its area fraction is the same double.
 *
 * The format (docs/library.md): the 8 bytes "DSIMSTAT", the format
 * version (32 bits, DS_CHECKPOINT_FORMAT_VERSION), a byte order mark
 * 0x01020304 (32 bits), the library version that wrote it (16 bytes of
 * text), the length of the payload (64 bits), the payload, and an FNV-1a
 * 64-bit checksum of all that precedes it. Every integer and double (by
 * its IEEE 754 bits) is little-endian whatever the machine, so a file
 * moves between machines. This library writes version 4 and reads every
 * earlier one: 2.x wrote 2 and 1. Version 3 names a bit per disk column
 * written, adds the kinds of disk and their names after the disks, and a
 * list of protocols after the integrator's part, then the caller's
 * metadata text (ds_sim_set_metadata) (2.x kept a growth inside
 * the event-driven integrator's, which loads as the growth protocol; a
 * 2.x file loads as disks of one kind); version 4 adds the granular
 * rules (restitution, contact time, field) and the energy books after
 * the stress integral's parts (an older file's run is elastic, without
 * a field); version 1 lacks the stress integral's parts (a run loaded
 * from it starts ds_sim_get_stress_integral at 0). */
#define DS_CHECKPOINT_FORMAT_VERSION 5

/* Bytes ds_checkpoint_format writes for sim (0 for NULL). */
size_t ds_checkpoint_get_size(const ds_sim *sim);
/* The checkpoint into buf (cap bytes); as ds_frame_format, *len receives
 * the bytes needed either way and a cap too small is DS_ERR_ARG. */
ds_status ds_checkpoint_format(const ds_sim *sim, void *buf, size_t cap, size_t *len,
                               ds_error *err);
/* The checkpoint to out, flushed: DS_ERR_IO if the write fails,
 * DS_ERR_NOMEM without memory for it, DS_ERR_ARG for NULL. */
ds_status ds_checkpoint_save(const ds_sim *sim, FILE *out, ds_error *err);
/* A simulation from a checkpoint of len bytes: on DS_OK *out owns it. A
 * truncated, corrupted, foreign or future-version checkpoint is
 * DS_ERR_FORMAT with the reason in err (field "checkpoint"), never a
 * crash; so is one (its checksum forged) whose parameters
 * ds_params_check refuses, or with a disk ds_sim_set_disk would refuse:
 * not finite, a velocity component beyond DS_VELOCITY_MAX, outside the
 * box (with walls, up to what a saved run may be past the band a radius
 * from them: 1e-9 of the box, and with the time step two steps of its
 * fastest disk). DS_ERR_NOMEM without memory for it. */
ds_status ds_checkpoint_parse(const void *data, size_t len, ds_sim **out, ds_error *err);
/* The same from a stream, read as far as its header announces and one
 * byte more (DS_ERR_IO if reading fails). Memory grows with the bytes
 * read, so a length beyond the end of the file is DS_ERR_FORMAT
 * ("truncated"), whatever it announces. */
ds_status ds_checkpoint_load(FILE *in, ds_sim **out, ds_error *err);

#ifdef __cplusplus
}
#endif

#endif /* DISKSIM_IO_H */
