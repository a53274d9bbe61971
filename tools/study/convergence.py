"""Convergence arithmetic and output for tools/study/porosph_study.py --converge.

Levels are ordered coarse to fine (dp falling). Between successive levels i and i+1, with the
refinement ratio r = dp_i / dp_{i+1} > 1:
  observed order      p = log(e_i / e_{i+1}) / log(r)
  Richardson value    Q_R = Q_{i+1} + (Q_{i+1} - Q_i) / (r^p - 1)   (the measured quantity Q, with
                      the observed p of the same pair; only where p is finite and > 0)
The verdict fails when the error grows (e_{i+1} > e_i) between any two successive levels, or when
a level has no error at all (a failed run, a check that printed nothing)."""
import csv
import math

FALLS = "error falls with refinement"
NOT_GROWING = "error does not grow with refinement (equal at some step)"
GROWS = "ERROR GROWS WITH REFINEMENT - verdict fails"
MISSING = "NO ERROR AT SOME LEVEL - verdict fails"


def observed_order(e_coarse, e_fine, dp_coarse, dp_fine):
    """p from one pair of levels; inf when the fine error is exactly 0, nan when undefined."""
    if not all(math.isfinite(x) for x in (e_coarse, e_fine)) or e_coarse < 0 or e_fine < 0:
        return math.nan
    if e_fine == 0:
        return math.inf if e_coarse > 0 else math.nan
    if e_coarse == 0:
        return -math.inf
    return math.log(e_coarse / e_fine) / math.log(dp_coarse / dp_fine)


def richardson(q_coarse, q_fine, ratio, order):
    """Q_R = Q_f + (Q_f - Q_c) / (r^p - 1); nan where it does not apply (p not finite or <= 0)."""
    if not (math.isfinite(order) and order > 0 and math.isfinite(q_coarse)
            and math.isfinite(q_fine)):
        return math.nan
    return q_fine + (q_fine - q_coarse) / (ratio ** order - 1)


def analyse(dps, errors, values):
    """Per-level order and Richardson value (nan at the coarsest level) and the verdict.
    dps must fall strictly. Returns (orders, extrapolated, verdict, passed)."""
    if len(dps) < 2 or any(b >= a for a, b in zip(dps, dps[1:])):
        raise ValueError(f"need >= 2 levels with dp falling strictly, got {dps}")
    orders, extrapolated = [math.nan], [math.nan]
    for i in range(1, len(dps)):
        p = observed_order(errors[i - 1], errors[i], dps[i - 1], dps[i])
        orders.append(p)
        extrapolated.append(richardson(values[i - 1], values[i], dps[i - 1] / dps[i], p))
    if not all(math.isfinite(e) for e in errors):
        return orders, extrapolated, MISSING, False
    if any(b > a for a, b in zip(errors, errors[1:])):
        return orders, extrapolated, GROWS, False
    if any(b == a for a, b in zip(errors, errors[1:])):
        return orders, extrapolated, NOT_GROWING, True
    return orders, extrapolated, FALLS, True


def fmt(x):
    return "" if isinstance(x, float) and math.isnan(x) else (f"{x:.6g}" if isinstance(x, float)
                                                              else str(x))


def write_csv(rows, columns, path):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        writer.writeheader()
        writer.writerows({c: fmt(row.get(c, "")) for c in columns} for row in rows)


def plot(dps, errors, orders, expected_order, title, ylabel, path):
    """Log-log error against dp, each segment labelled with its observed order, with a reference
    line of slope expected_order through the coarsest level with a positive error."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5.5, 4))
    points = [(d, e) for d, e in zip(dps, errors) if math.isfinite(e) and e > 0]
    if points:
        ax.plot(*zip(*points), "o-", color="tab:blue", label="measured")
        d0, e0 = points[0]
        ax.plot([dps[0], dps[-1]], [e0 * (d / d0) ** expected_order for d in (dps[0], dps[-1])],
                "--", color="gray", label=f"slope {expected_order:g} (expected)")
        ax.legend(fontsize=8)
    for i in range(1, len(dps)):
        if math.isfinite(orders[i]) and errors[i] > 0 and errors[i - 1] > 0:
            ax.annotate(f"p = {orders[i]:.2f}", (math.sqrt(dps[i] * dps[i - 1]),
                        math.sqrt(errors[i] * errors[i - 1])), fontsize=7,
                        xytext=(3, 3), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("dp [m]")
    ax.set_ylabel(ylabel)
    ax.set_title(title, fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
