#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Moves C (or any text) from disksim 2.x's names to 3.0's, in place.

    python3 tools/migrate/disksim3.py [--names-only] FILE...

Renames every function, type, enumerator and macro of the 2.x header to
its 3.0 name (CHANGELOG.md has the table) and rewrites the calls whose
arguments changed: a NULL for the new `ds_error *err` of every call that
can fail, NULL for the mixture of ds_sim_create, ds_params_check and
ds_params_memory, and the velocities flag of ds_frame_write. What it
cannot rewrite alone it leaves as it is and names on standard error,
FILE:LINE, for a person to finish:

  - ds_get_radii(sim, radii, masses) with both arrays: now two calls,
    ds_sim_get_radii and ds_sim_get_masses;
  - ds_radius_of(sim, i) and ds_mass_of(sim, i): removed, read the arrays;
  - ds_psi6(sim), which returned NaN on failure: now
    ds_sim_get_psi6(sim, &psi6, err), a status;
  - ds_frame_error's .line: ds_error's .index;
  - ds_run and ds_step return a ds_status now (a growth that runs out of
    memory stops the run: DS_ERR_NOMEM), worth checking.

It works on text, one file at a time, and is exact for calls whose
arguments balance their brackets; read the diff it makes. A call whose
arguments are not 2.x's in number is left alone (a second run over a
file changes nothing). Names are renamed everywhere, strings and
comments included. With
--names-only it renames and leaves every argument list alone (for the
definitions of the functions themselves, or prose).
"""
import re
import sys

# 2.x function -> (3.0 function, how its arguments change).
APPEND = "append"  # a last NULL, the err
CALLS = {
    "ds_check_params": ("ds_params_check", lambda a: [a[0], "NULL", a[1], "NULL"]),
    "ds_diagnose_params": ("ds_params_check", lambda a: [a[0], "NULL", a[1], a[2]]),
    "ds_diagnose_mixture": ("ds_params_check", lambda a: a),
    "ds_memory_needed": ("ds_params_memory", lambda a: [a[0], "NULL", a[1], "NULL"]),
    "ds_memory_needed_mixture": ("ds_params_memory", APPEND),
    "ds_create": ("ds_sim_create", lambda a: [a[0], "NULL", a[1], "NULL"]),
    "ds_create_mixture": ("ds_sim_create", APPEND),
    "ds_step": ("ds_sim_step", APPEND),
    "ds_run": ("ds_sim_run", APPEND),
    "ds_get_all": ("ds_sim_get_disks", APPEND),
    "ds_get_images": ("ds_sim_get_images", APPEND),
    "ds_get_unwrapped": ("ds_sim_get_unwrapped", APPEND),
    "ds_set": ("ds_sim_set_disk", APPEND),
    "ds_set_all": ("ds_sim_set_disks", lambda a: a),
    "ds_scale_velocities": ("ds_sim_scale_velocities", APPEND),
    "ds_set_growth": ("ds_sim_set_growth", APPEND),
    "ds_count_contacts": ("ds_sim_get_contacts", APPEND),
    "ds_stress_integral": ("ds_sim_get_stress_integral", APPEND),
    "ds_local_psi6": ("ds_psi6_local", APPEND),
    "ds_pair_histogram": ("ds_pair_histogram", APPEND),
    "ds_transport_create": ("ds_transport_create", APPEND),
    "ds_transport_add": ("ds_transport_add", APPEND),
    "ds_transport_sample": ("ds_transport_sample", APPEND),
    "ds_transport_get": ("ds_transport_get", APPEND),
    "ds_transport_diffusion": ("ds_transport_get_diffusion", APPEND),
    "ds_format_frame": ("ds_frame_format", APPEND),
    "ds_write_frame": ("ds_frame_write", lambda a: [a[0], "0", a[1], "NULL"]),
    "ds_write_frame_velocities": ("ds_frame_write", lambda a: [a[0], "1", a[1], "NULL"]),
    "ds_parse_frame": ("ds_frame_parse", lambda a: a),
    "ds_read_frame": ("ds_frame_read", lambda a: a),
    "ds_format_xyz_frame": ("ds_xyz_format", APPEND),
    "ds_write_xyz_frame": ("ds_xyz_write", APPEND),
    "ds_format_state": ("ds_checkpoint_format", APPEND),
    "ds_save_state": ("ds_checkpoint_save", APPEND),
    "ds_parse_state": ("ds_checkpoint_parse", lambda a: a),
    "ds_load_state": ("ds_checkpoint_load", lambda a: a),
    "ds_get_radii": (None, None),  # below
}

# How many arguments each took in 2.1.0's disk_sim.h: a call with another
# count is not a 2.x call (a second run over a file already moved, whose
# ds_transport_add has 3.0's err), so it is left as it is.
ARITY_2X = {
    "ds_check_params": 2, "ds_diagnose_params": 3, "ds_diagnose_mixture": 4,
    "ds_memory_needed": 2, "ds_memory_needed_mixture": 3, "ds_create": 2,
    "ds_create_mixture": 3, "ds_step": 1, "ds_run": 2, "ds_get_all": 2, "ds_get_images": 2,
    "ds_get_unwrapped": 2, "ds_set": 3, "ds_set_all": 3, "ds_scale_velocities": 2,
    "ds_set_growth": 4, "ds_count_contacts": 3, "ds_stress_integral": 2, "ds_local_psi6": 9,
    "ds_pair_histogram": 9, "ds_transport_create": 4, "ds_transport_add": 3,
    "ds_transport_sample": 2, "ds_transport_get": 4, "ds_transport_diffusion": 6,
    "ds_format_frame": 5, "ds_write_frame": 2, "ds_write_frame_velocities": 2,
    "ds_parse_frame": 4, "ds_read_frame": 3, "ds_format_xyz_frame": 4,
    "ds_write_xyz_frame": 2, "ds_format_state": 4, "ds_save_state": 2, "ds_parse_state": 4,
    "ds_load_state": 3, "ds_get_radii": 3,
}

# Names whose meaning is the same: one for one.
RENAMES = {
    "ds_status_str": "ds_status_name",
    "ds_now": "ds_timer_now",
    "ds_default_params": "ds_params_default",
    "ds_destroy": "ds_sim_destroy",
    "ds_count": "ds_sim_get_count",
    "ds_radius": "ds_sim_get_radius",
    "ds_radius_max": "ds_sim_get_radius_max",
    "ds_box": "ds_sim_get_box_width",
    "ds_box_y": "ds_sim_get_box_height",
    "ds_area_fraction": "ds_sim_get_area_fraction",
    "ds_dt": "ds_sim_get_dt",
    "ds_time": "ds_sim_get_time",
    "ds_steps": "ds_sim_get_steps",
    "ds_integrator_used": "ds_sim_get_integrator",
    "ds_boundary_used": "ds_sim_get_boundary",
    "ds_broadphase_used": "ds_sim_get_broadphase",
    "ds_collision_seconds": "ds_sim_get_collision_seconds",
    "ds_collision_count": "ds_sim_get_collision_count",
    "ds_pairs_tested": "ds_sim_get_pairs_tested",
    "ds_get": "ds_sim_get_disk",
    "ds_growth_state_of": "ds_sim_get_growth_state",
    "ds_growth_z": "ds_sim_get_growth_z",
    "ds_kinetic_energy": "ds_sim_get_kinetic_energy",
    "ds_momentum": "ds_sim_get_momentum",
    "ds_wall_count": "ds_sim_get_wall_count",
    "ds_wall_impulse": "ds_sim_get_wall_impulse",
    "ds_pressure": "ds_sim_get_pressure",
    "ds_virial_pressure": "ds_sim_get_virial_pressure",
    "ds_temperature": "ds_sim_get_temperature",
    "ds_compressibility": "ds_sim_get_compressibility_factor",
    "ds_reset_observables": "ds_sim_reset_observables",
    "ds_psi6": "ds_sim_get_psi6",
    "ds_transport_lags": "ds_transport_get_lags",
    "ds_frame_size": "ds_frame_get_size",
    "ds_xyz_frame_size": "ds_xyz_get_size",
    "ds_state_size": "ds_checkpoint_get_size",
    "ds_params_error": "ds_error",
    "ds_state_error": "ds_error",
    "ds_frame_error": "ds_error",
    "DS_TIME_STEP": "DS_INTEGRATOR_TIME_STEP",
    "DS_EVENT_DRIVEN": "DS_INTEGRATOR_EVENT_DRIVEN",
    "DS_WALLS": "DS_BOUNDARY_WALLS",
    "DS_PERIODIC": "DS_BOUNDARY_PERIODIC",
    "DS_RANDOM": "DS_PLACEMENT_RANDOM",
    "DS_LATTICE": "DS_PLACEMENT_LATTICE",
    "DS_AUTO": "DS_BROADPHASE_AUTO",
    "DS_SAP": "DS_BROADPHASE_SAP",
    "DS_SAP_STRIPS": "DS_BROADPHASE_STRIPS",
    "DS_CELLS": "DS_BROADPHASE_CELLS",
    "DS_BRUTE_FORCE": "DS_BROADPHASE_BRUTE",
    "DS_GROWING": "DS_GROWTH_GROWING",
    "DS_STATE_FORMAT_VERSION": "DS_CHECKPOINT_FORMAT_VERSION",
}
for old, (new, _) in CALLS.items():
    if new:
        RENAMES.setdefault(old, new)
RENAMES["ds_get_radii"] = "ds_sim_get_radii"

BY_HAND = {
    "ds_radius_of": "removed: read ds_sim_get_radii's array",
    "ds_mass_of": "removed: read ds_sim_get_masses's array",
    "ds_psi6": "ds_sim_get_psi6(sim, &psi6, err) returns a status (2.x: NaN on failure)",
}

CALL_RE = re.compile(r"\b(ds_[a-z0-9_]+)(\s*)\(")


def closing(text, start):
    """The index of the ')' closing the '(' at start, and the top-level
    argument spans; None if they do not balance."""
    depth, k, args, begin = 0, start, [], start + 1
    while k < len(text):
        c = text[k]
        if c in "\"'":
            q, k = c, k + 1
            while k < len(text) and text[k] != q:
                k += 2 if text[k] == "\\" else 1
        elif text.startswith("/*", k):
            k = text.find("*/", k + 2)
            if k < 0:
                return None
            k += 1
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth -= 1
            if depth == 0:
                args.append((begin, k))
                return k, args
        elif c == "," and depth == 1:
            args.append((begin, k))
            begin = k + 1
        k += 1
    return None


def code_mask(text):
    """For each character of C text, whether it is code (not inside a
    string, a character literal or a comment): calls are rewritten in
    code only, names everywhere."""
    mask, k, n = bytearray(b"\1" * len(text)), 0, len(text)
    while k < n:
        c = text[k]
        if text.startswith("//", k):
            end = text.find("\n", k)
            end = n if end < 0 else end
        elif text.startswith("/*", k):
            end = text.find("*/", k + 2)
            end = n if end < 0 else end + 2
        elif c in "\"'":
            end = k + 1
            while end < n and text[end] not in (c, "\n"):
                end += 2 if text[end] == "\\" else 1
            end += 1
        else:
            k += 1
            continue
        mask[k:end] = b"\0" * (min(end, n) - k)
        k = end
    return mask


def rewrite_calls(text, where):
    out, at = [], 0
    code = code_mask(text)
    for m in CALL_RE.finditer(text):
        if m.start() < at or not code[m.start()]:
            continue
        name = m.group(1)
        if name in BY_HAND:
            where(m.start(), f"{name}: {BY_HAND[name]}")
        if name not in CALLS:
            continue
        found = closing(text, m.end() - 1)
        if not found:
            where(m.start(), f"{name}: unbalanced call, not rewritten")
            continue
        end, spans = found
        args = [text[a:b].strip() for a, b in spans]
        if args == [""]:
            args = []
        new, how = CALLS[name]
        if len(args) != ARITY_2X[name]:
            if not (new == name and len(args) == ARITY_2X[name] + 1):  # moved already
                where(m.start(), f"{name}: {len(args)} arguments where 2.x took "
                      f"{ARITY_2X[name]}, not rewritten")
            continue
        if name == "ds_get_radii":
            if len(args) == 3 and args[2] == "NULL":
                new, args = "ds_sim_get_radii", [args[0], args[1], "NULL"]
            elif len(args) == 3 and args[1] == "NULL":
                new, args = "ds_sim_get_masses", [args[0], args[2], "NULL"]
            else:
                where(m.start(), "ds_get_radii with radii and masses: two calls now, "
                      "ds_sim_get_radii and ds_sim_get_masses")
                continue
        elif how == APPEND:
            args = args + ["NULL"]
        else:
            try:
                args = how(args)
            except IndexError:
                where(m.start(), f"{name}: not the 2.x arguments, not rewritten")
                continue
        out.append(text[at:m.start()])
        out.append(f"{new}{m.group(2)}(" + ", ".join(args) + ")")
        at = end + 1
    out.append(text[at:])
    return "".join(out)


NAME_RE = re.compile(r"\b(" + "|".join(sorted(RENAMES, key=len, reverse=True)) + r")\b")


def migrate(path, names_only=False):
    text = open(path, encoding="utf-8").read()
    notes = []

    def where(offset, what):
        notes.append(f"{path}:{text.count(chr(10), 0, offset) + 1}: {what}")

    new = text if names_only else rewrite_calls(text, where)
    new = NAME_RE.sub(lambda m: RENAMES[m.group(1)], new)
    if "ds_frame_error" in text:
        for m in re.finditer(r"(?:\.|->)\s*line\b", text):
            where(m.start(), "ds_frame_error's .line is ds_error's .index")
    for note in notes:
        print(note, file=sys.stderr)
    if new != text:
        with open(path, "w", encoding="utf-8") as f:
            f.write(new)


if __name__ == "__main__":
    args = sys.argv[1:]
    if "-h" in args or "--help" in args:
        print(__doc__)
        sys.exit(0)
    names_only = "--names-only" in args
    paths = [a for a in args if a != "--names-only"]
    unknown = [a for a in paths if a.startswith("-")]
    if unknown:
        sys.exit(f"disksim3.py: unknown option {unknown[0]!r} (try --help)")
    if not paths:
        sys.exit(__doc__)
    status = 0
    for p in paths:
        try:
            migrate(p, names_only)
        except (OSError, UnicodeDecodeError) as e:
            print(f"disksim3.py: {p}: {e.strerror if isinstance(e, OSError) else e}",
                  file=sys.stderr)
            status = 1
    sys.exit(status)
