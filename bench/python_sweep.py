"""robosim.sweep from Python against scripts/sweep.sh on the same runs, in turn, several rounds: whole wall times.

    python bench/python_sweep.py [ROUNDS] [SEEDS]      (a Python with robosim and pandas: pip install "./python[test]")

Each round sweeps examples/python/wander.xml (six Python robots, 300 steps a run) over two speeds and SEEDS seeds
(default 10: 20 runs): first ``robosim.sweep`` (two workers, the warm hosts this process keeps: the first round
starts them, the next ones find them running, as a notebook's later sweeps do), then ``scripts/sweep.sh`` on a sweep
file of the same runs (its own pool of two warm workers, started by each sweep). Prints each round's times, then
the medians of the rounds after the first and their ratio. Writes nothing in the repository (temporary folders).
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import robosim

REPO = Path(__file__).resolve().parents[1]
WORLD = REPO / "examples/python/wander.xml"
STEPS = 300


def main() -> int:
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 4
    seeds = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    python_s: list[float] = []
    script_s: list[float] = []
    with tempfile.TemporaryDirectory(prefix="robosim-bench-") as tmp:
        spec = Path(tmp) / "wander.sweep.xml"
        spec.write_text(f'<sweep world="{WORLD}" steps="{STEPS}"><seeds from="1" to="{seeds}"/>'
                        '<param name="speed" values="300 600"/></sweep>\n')
        for r in range(rounds):
            start = time.perf_counter()
            rows = robosim.sweep(WORLD, steps=STEPS, seeds=range(1, seeds + 1), params={"speed": [300, 600]},
                                 out=Path(tmp) / f"py-{r}", workers=2)
            python_s.append(time.perf_counter() - start)
            failed = [row for row in (rows.to_dict("records") if hasattr(rows, "to_dict") else rows)
                      if row["status"] != "ok"]
            start = time.perf_counter()
            command = ["bash", str(REPO / "scripts/sweep.sh"), str(spec), "--out", str(Path(tmp) / f"sh-{r}"),
                       "--jobs", "2"]
            done = subprocess.run(command, capture_output=True, text=True)
            script_s.append(time.perf_counter() - start)
            if failed or done.returncode != 0:
                print(f"round {r}: a sweep failed: {failed[:1]} {done.stderr[-300:]}", file=sys.stderr)
                return 1
            print(f"round {r}: robosim.sweep {python_s[-1]:.2f} s, scripts/sweep.sh {script_s[-1]:.2f} s "
                  f"({2 * seeds} runs each)")
    py, sh = statistics.median(python_s[1:] or python_s), statistics.median(script_s[1:] or script_s)
    print(f"median after the first round: robosim.sweep {py:.2f} s, scripts/sweep.sh {sh:.2f} s, "
          f"sweep.sh / robosim.sweep = {sh / py:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
