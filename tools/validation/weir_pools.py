#!/usr/bin/python3
"""What the seepage weir's discharge swings with: per snapshot of a run of cases/seepage_weir, the
discharge under the weir, each pool's mean depth (its water volume over its length) and the heads
next to the weir; their standard deviations, correlations and spectral peaks.

  tools/validation/weir_pools.py RUN DP [START]

RUN a run directory (water.h5), DP its particle spacing [m], START the first time used (1 s).
The geometry is the case's: layer 0-1.2 m x 0-0.2 m, weir 0.5-0.7 m, pools above y = 0.2 m.
The head is y + p / (rho g) with p inverted through the weakly compressible still-water law of
docs/verification.md (rho0 1000, c0 20 m/s, gamma 7). Needs h5py and numpy (/usr/bin/python3).
"""
import sys

import h5py
import numpy as np

RHO0, C0, GAMMA, G = 1000.0, 20.0, 7.0, 9.81
B = RHO0 * C0**2 / GAMMA


def head(y, p):
    """Piezometric head of still weakly compressible water at pressure p."""
    r = (1.0 + p / B) ** (1.0 / GAMMA)
    return y + B * GAMMA / (GAMMA - 1.0) / RHO0 * (r ** (GAMMA - 1.0) - 1.0) / G


def series(run, dp, start):
    rows = {k: [] for k in ("t", "q", "depth_up", "depth_down", "head_up", "head_down")}
    snapshots = h5py.File(run + "/water.h5", "r")["snapshots"]
    for key in sorted(snapshots.keys()):
        snap = snapshots[key]
        if snap.attrs["time"] < start:
            continue
        x, v = snap["position"][:], snap["velocity"][:]
        free = snap["fixed"][:] == 0
        vol = snap["mass"][:] / snap["density"][:]
        h = head(x[:, 1], snap["pressure"][:])
        under = free & (x[:, 0] > 0.5 + 2 * dp) & (x[:, 0] < 0.7 - 2 * dp) & (x[:, 1] < 0.2)
        pool_up = free & (x[:, 0] < 0.5) & (x[:, 1] > 0.2)
        pool_down = free & (x[:, 0] > 0.7) & (x[:, 1] > 0.2)
        near_up = pool_up & (x[:, 0] > 0.4) & (x[:, 0] < 0.5 - 2 * dp) & (x[:, 1] > 0.2 + 2 * dp)
        near_up &= x[:, 1] < 0.3
        near_down = pool_down & (x[:, 0] < 0.8) & (x[:, 0] > 0.7 + 2 * dp)
        near_down &= (x[:, 1] > 0.2 + 2 * dp) & (x[:, 1] < 0.26)
        rows["t"].append(snap.attrs["time"])
        rows["q"].append((vol[under] * v[under, 0]).sum() / (0.2 - 4 * dp))
        rows["depth_up"].append(vol[pool_up].sum() / 0.5)
        rows["depth_down"].append(vol[pool_down].sum() / 0.5)
        rows["head_up"].append(h[near_up].mean())
        rows["head_down"].append(h[near_down].mean())
    return {k: np.array(v) for k, v in rows.items()}


def peaks(y, interval, count=3):
    y = y - y.mean()
    spectrum = np.abs(np.fft.rfft(y * np.hanning(len(y))))
    freq = np.fft.rfftfreq(len(y), interval)
    return [freq[i] for i in np.argsort(spectrum[1:])[::-1][:count] + 1]


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    run, dp = sys.argv[1], float(sys.argv[2])
    s = series(run, dp, float(sys.argv[3]) if len(sys.argv) > 3 else 1.0)
    dh = s["head_up"] - s["head_down"]
    interval = np.diff(s["t"]).mean()
    print("%s: %d snapshots, t = %.2f .. %.2f s" % (run, len(s["t"]), s["t"][0], s["t"][-1]))
    print("quantity            mean        sd       sd/mean  corr(q)  corr(dh)  peaks [Hz]")
    for name in ("q", "depth_up", "depth_down", "head_up", "head_down"):
        y = s[name]
        print("%-18s %.5e %.3e %7.4f  %+6.2f   %+6.2f    %s" % (
            name, y.mean(), y.std(), y.std() / abs(y.mean()), np.corrcoef(y, s["q"])[0, 1],
            np.corrcoef(y, dh)[0, 1], ", ".join("%.2f" % f for f in peaks(y, interval))))
    print("%-18s %.5e %.3e %7.4f  %+6.2f   %+6.2f    %s" % (
        "dh next to weir", dh.mean(), dh.std(), dh.std() / dh.mean(), np.corrcoef(dh, s["q"])[0, 1],
        1.0, ", ".join("%.2f" % f for f in peaks(dh, interval))))
    ratio = s["q"] / dh
    print("q / dh varies by %.2f %% (sd / mean)" % (100 * ratio.std() / ratio.mean()))


if __name__ == "__main__":
    main()
