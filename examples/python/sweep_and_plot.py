"""A notebook's cells as a script: sweep the Wander robots' speed over seeds from Python, tabulate and plot.

    pip install ./python pandas matplotlib        # pandas and matplotlib for the table and the plot
    python examples/python/sweep_and_plot.py      # about half a minute on two cores; writes wander-speed.png

Each run is a warm RoboSim JVM's (robosim.sweep keeps one a core), so the tenth sweep costs what the first did.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import robosim

HERE = Path(__file__).resolve().parent


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=600, help="steps a run (default: %(default)s)")
    parser.add_argument("--seeds", type=int, default=5, help="seeds 1..N a speed (default: %(default)s)")
    parser.add_argument("--speeds", default="200,400,600,800", help="mm/s, comma-separated (default: %(default)s)")
    parser.add_argument("--out", type=Path, default=Path("wander-speed.png"), help="the plot (default: %(default)s)")
    args = parser.parse_args(argv)
    speeds = [int(s) for s in args.speeds.split(",")]

    # cell 1: the sweep, a row per run
    table = robosim.sweep(HERE / "wander.xml", steps=args.steps, seeds=range(1, args.seeds + 1),
                          params={"speed": speeds})
    failed = table[table["status"] != "ok"]
    if len(failed):
        print(failed[["index", "speed", "seed", "error"]].to_string(index=False), file=sys.stderr)
        return 1

    # cell 2: the mean and its spread per speed
    summary = table.groupby("speed")[["distance_m", "contacts", "turns"]].agg(["mean", "std"])
    print(summary.round(2).to_string())

    # cell 3: the plot
    import matplotlib  # noqa: PLC0415

    matplotlib.use("Agg")  # (no display needed)
    import matplotlib.pyplot as plt  # noqa: PLC0415

    figure, axes = plt.subplots(figsize=(6, 4))
    means = summary["distance_m"]
    axes.errorbar(means.index, means["mean"], yerr=means["std"], marker="o", capsize=4)
    axes.set_xlabel("speed (mm/s)")
    axes.set_ylabel("distance driven by six robots (m)")
    axes.set_title(f"Wander, {args.steps} steps, {args.seeds} seeds a speed")
    figure.tight_layout()
    figure.savefig(args.out, dpi=100)
    print(f"plot: {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
