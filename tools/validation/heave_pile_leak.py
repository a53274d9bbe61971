#!/usr/bin/python3
"""Does water pass through the hydraulic heave's sheet pile? For a run of cases/hydraulic_heave:

  tools/validation/heave_pile_leak.py RUN

1. From timeseries.csv, per time window: the upstream pool's loss, -d(upstream_level)/dt times
   the pool's width (0.245 m, x = 0.005 .. 0.25 m), against the flow under the pile,
   -gap_velocity_x times the gap's height (0.03 m). With an impermeable pile the two agree (the
   sand under the pool is saturated and rigid enough that its storage is negligible); a ratio
   above 1 is water that reaches the pit by another way.
2. From water.h5: the free water particles that cross the pile's plane x = 0 from upstream
   (x > 0) to the pit (x < 0) between two snapshots, by the height they crossed at: more than
   dp/2 above the pile's tip (y = 0.03 m) is through the pile, within dp/2 of it at the tip's
   corner (a particle on the pile's mid-plane at the tip, stepping back and forth), below under
   it. dp is read from run.json.
Needs h5py and numpy (/usr/bin/python3).
"""
import json
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


def run_dp(run):
    """run.dp of the run (the first "dp" in run.json)."""
    def find(node):
        if isinstance(node, dict):
            if "dp" in node and isinstance(node["dp"], (int, float)):
                return float(node["dp"])
            node = list(node.values())
        if isinstance(node, list):
            for value in node:
                found = find(value)
                if found is not None:
                    return found
        return None
    with open(run + "/run.json") as f:
        return find(json.load(f))


def crossings(run):
    snapshots = h5py.File(run + "/water.h5", "r")["snapshots"]
    corner = 0.5 * run_dp(run)
    before, through, at_tip, under = None, 0, 0, 0
    for key in sorted(snapshots.keys()):
        snap = snapshots[key]
        free = snap["fixed"][:] == 0
        now = {i: x for i, x, f in zip(snap["id"][:], snap["position"][:], free) if f}
        if before is not None:
            for i, x in now.items():
                if i in before and before[i][0] > 0.0 and x[0] < 0.0:
                    height = 0.5 * (before[i][1] + x[1])
                    if height > TIP + corner:
                        through += 1
                    elif height > TIP - corner:
                        at_tip += 1
                    else:
                        under += 1
        before = now
    print("free water particles crossing x = 0 towards the pit: %d above the pile's tip (through "
          "the pile), %d at its corner (within dp/2 of its height), %d under it"
          % (through, at_tip, under))


def main():
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    balance(sys.argv[1])
    crossings(sys.argv[1])


if __name__ == "__main__":
    main()
