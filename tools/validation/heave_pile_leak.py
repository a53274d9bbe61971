#!/usr/bin/python3
"""Does water pass through the hydraulic heave's sheet pile? For a run of cases/hydraulic_heave:

  tools/validation/heave_pile_leak.py RUN

1. From timeseries.csv, per time window: the upstream pool's loss, -d(upstream_level)/dt times
   the pool's width (0.245 m, x = 0.005 .. 0.25 m), against the flow under the pile,
   -gap_velocity_x times the gap's height (0.03 m). With an impermeable pile the two agree (the
   sand under the pool is saturated and rigid enough that its storage is negligible); a ratio
   above 1 is water that reaches the pit by another way.
2. From water.h5: the free water particles that cross the pile's plane x = 0 from upstream
   (x > 0) to the pit (x < 0) between two snapshots, by the height they crossed at (above the
   pile's tip, y > 0.03 m, is through the pile).
Needs h5py and numpy (/usr/bin/python3).
"""
import sys

import h5py
import numpy as np

POOL_WIDTH, GAP_HEIGHT, TIP = 0.245, 0.03, 0.03


def balance(run):
    d = np.genfromtxt(run + "/timeseries.csv", delimiter=",", names=True)
    t = d["t"]
    print("window [s]    pool loss [m^2/s]  flow under the pile [m^2/s]  ratio")
    for a, b in ((0.6, 1.2), (1.2, 3.2), (3.2, 6.2)):
        s = (t >= a) & (t <= b)
        if s.sum() < 3:
            continue
        loss = -np.polyfit(t[s], d["upstream_level"][s], 1)[0] * POOL_WIDTH
        gap = -d["gap_velocity_x"][s].mean() * GAP_HEIGHT
        print("%.1f - %.1f    %.3e          %.3e                   %.1f" % (a, b, loss, gap,
                                                                           loss / gap))


def crossings(run):
    snapshots = h5py.File(run + "/water.h5", "r")["snapshots"]
    before, through, under = None, 0, 0
    for key in sorted(snapshots.keys()):
        snap = snapshots[key]
        free = snap["fixed"][:] == 0
        now = {i: x for i, x, f in zip(snap["id"][:], snap["position"][:], free) if f}
        if before is not None:
            for i, x in now.items():
                if i in before and before[i][0] > 0.0 and x[0] < 0.0:
                    if 0.5 * (before[i][1] + x[1]) > TIP:
                        through += 1
                    else:
                        under += 1
        before = now
    print("free water particles crossing x = 0 towards the pit: %d above the pile's tip (through "
          "the pile), %d under it" % (through, under))


def main():
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    balance(sys.argv[1])
    crossings(sys.argv[1])


if __name__ == "__main__":
    main()
