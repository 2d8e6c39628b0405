#!/bin/sh
# SPDX-License-Identifier: MIT
# The mode-coupling line and the sound traversal time for a tools/transport
# output (docs/physics.md, "The 1/t tail"), printed as gnuplot settings for
# tools/analysis/plot_transport.plt:
#   tc=...; amp=...; ts=...
# tc the measured mean free time; amp = 1 / (8 pi n (D + nu)), with D the
# measured D of the window and nu = eta_E / (n m) Enskog's kinematic
# viscosity, eta_E = 1.022 eta_0 (1 / g + 2 eta + (1 + 8 / pi) eta^2 g),
# eta_0 = (1 / (2 sigma)) sqrt(m kT / pi) (Gass 1971), g the measured
# contact value; ts = L / c with the adiabatic sound speed of disks,
# c^2 = (kT / m) (Z + eta dZ/deta + Z^2), Z measured and dZ/deta from
# Henderson's equation of state. With -v, also the numbers behind them.
# Usage: sh tools/analysis/tail_theory.sh [-v] TRANSPORT_OUTPUT
set -eu
verbose=0
[ "${1:-}" = -v ] && { verbose=1; shift; }
[ $# -eq 1 ] || { echo "usage: tail_theory.sh [-v] TRANSPORT_OUTPUT" >&2; exit 2; }
awk -v verbose="$verbose" '
    /^# transport: / { eta = $6 }
    /^# sigma / { sigma = $3; n = $5; kt = $7 }
    /^# Z / { z = $3; g = $7; tc = $11 }
    /^# window / { for (i = 1; i <= NF; ++i) if ($i == "D_einstein") d = $(i + 1) }
    !/^#/ && $2 > 0 { m++; tt[m] = $2; dd[m] = $7 }
    END {
        if (!sigma || !d) { print "tail_theory.sh: not a tools/transport output" > "/dev/stderr"; exit 1 }
        pi = 3.14159265358979
        eta0 = sqrt(kt / pi) / (2 * sigma)
        visc = 1.022 * eta0 * (1 / g + 2 * eta + (1 + 8 / pi) * eta * eta * g)
        nu = visc / n
        amp = 1 / (8 * pi * n * (d + nu))
        zp = (eta / 4) / (1 - eta) ^ 2 + 2 * (1 + eta * eta / 8) / (1 - eta) ^ 3
        c = sqrt(kt * (z + eta * zp + z * z))
        box = 1000
        if (verbose) {
            printf "# D %g nu_E %g 8 pi n (D + nu) %g c %g L/c %g (%g t_c)\n", d, nu, 8 * pi * n * (d + nu), c, box / c, box / c / tc
            # D(t) against ln t from 20 t_c to half the sound traversal
            # time: least squares, against the tail (kT / m) amp.
            hi = box / c / tc / 2
            for (i = 1; i <= m; ++i)
                if (tt[i] >= 20 && tt[i] <= hi) {
                    x = log(tt[i]); k++; sx += x; sy += dd[i]; sxx += x * x; sxy += x * dd[i]
                }
            if (k > 2)
                printf "# dD/dln t from 20 to %g t_c: %g (mode coupling %g)\n", hi, (k * sxy - sx * sy) / (k * sxx - sx * sx), kt * amp
        }
        printf "tc=%g; amp=%g; ts=%g\n", tc, amp, box / c
    }' "$1"
