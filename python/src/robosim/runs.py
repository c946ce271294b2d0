"""Runs and sweeps of worlds from Python: ``robosim.run`` runs a world headless and gives back its numbers, its pose
log and its recording; ``robosim.sweep`` runs a world over seeds and parameter values and gives back a row per run
(a pandas DataFrame when pandas is installed). Both run on warm RoboSim JVMs this process keeps (the simulation
hosts of ``robosim.testing``, ``scripts/simulation-host.sh``): a run is ``headless.sh --one-jvm`` (or another
layout) as a sweep's warm worker runs it, so a notebook's hundredth run costs what a sweep's does.

    import robosim

    result = robosim.run("examples/python/wander.xml", steps=2000, seed=3, params={"speed": 600})
    result.metrics["distance_m"], result.summary["steps"], result.pose_log

    table = robosim.sweep("examples/python/wander.xml", steps=500, seeds=range(1, 11),
                          params={"speed": [300, 600, 900]})
"""

from __future__ import annotations

import itertools
import os
import tempfile
import threading
from collections.abc import Iterable, Mapping, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from robosim.hostprocess import HostError
from robosim.testing import SimulationHost, _warm_host, shared_host

__all__ = ["RunResult", "run", "sweep"]

#: The layouts of a run, as a sweep file names them, and the runner's options for each.
LAYOUTS = {"one-jvm": ["--one-jvm"], "processes": [], "one-process": ["--robots-in-one-process"]}


@dataclass(frozen=True)
class RunResult:
    """What a run gave: its exit code (0 every step ran; ``scripts/headless.sh``'s codes), the summary line's
    fields, its metrics (every built-in one, ``scripts/describe.sh metrics``, and every value the robots reported,
    summed over them), a failed run's reason, and its files (in ``folder``)."""

    exit_code: int
    summary: dict[str, str]
    metrics: dict[str, float]
    error: str
    folder: Path
    log: Path
    pose_log: Path | None
    recording: Path | None

    @property
    def ok(self) -> bool:
        """Every step ran, nothing failed."""
        return self.exit_code == 0 and not self.error


def run(world: str | os.PathLike[str], *, steps: int, seed: int | None = None,
        params: Mapping[str, object] | None = None, layout: str = "one-jvm", pose_log: bool = True,
        record: bool = True, out: str | os.PathLike[str] | None = None, timeout_s: float | None = None,
        host: SimulationHost | None = None) -> RunResult:
    """Runs ``world`` (an environment file) ``steps`` steps with ``seed`` (default the file's) and ``params``
    (``--param NAME=VALUE``), in ``layout`` (``one-jvm``, ``processes``, ``one-process``), on a warm RoboSim JVM;
    its files (``run.log``, ``poses.csv``, ``run.rec``, and what loop functions write) in ``out`` (default a new
    temporary folder). A bad file or parameter is a run that failed (exit code 2, its reason in ``error``)."""
    if layout not in LAYOUTS:
        raise ValueError(f"layout {layout!r}: one of {', '.join(LAYOUTS)}")
    if steps < 1:
        raise ValueError(f"steps must be >= 1, got {steps}")
    file = Path(world).resolve()
    if not file.is_file():
        raise ValueError(f"{world}: no such environment file")
    folder = Path(out) if out is not None else Path(tempfile.mkdtemp(prefix="robosim-run-"))
    folder.mkdir(parents=True, exist_ok=True)
    folder = folder.resolve()
    log = folder / "run.log"
    poses = folder / "poses.csv" if pose_log else None
    recording = folder / "run.rec" if record else None
    for kept in (poses, recording):
        if kept is not None and kept.exists():
            kept.unlink()  # (the runner writes only new files: a run again into the same folder replaces them)
    args = ["--env", str(file), "--steps", str(int(steps)), "--output-dir", str(folder), *LAYOUTS[layout]]
    if seed is not None:
        args += ["--seed", str(int(seed))]
    for name, value in (params or {}).items():
        args += ["--param", f"{name}={value}"]
    if poses is not None:
        args += ["--pose-log", str(poses)]
    if recording is not None:
        args += ["--record", str(recording)]
    if timeout_s is not None:
        args += ["--timeout-s", str(max(1, int(timeout_s)))]
    on = host or shared_host(file.parent)
    answer = on.call("headless", {"args": args, "log": str(log), "recording": None if recording is None
                                  else str(recording)})[1]
    if answer.get("broke"):
        on.close()  # (what the run left running goes with that JVM; the next run gets a new one)
    return RunResult(int(answer["exit_code"]), dict(answer["summary"]), dict(answer["metrics"]),
                     str(answer["error"]), folder, log, poses if poses is not None and poses.exists() else None,
                     recording if recording is not None and recording.exists() else None)


def sweep(world: str | os.PathLike[str], *, steps: int, seeds: Iterable[int] = range(1, 11),
          params: Mapping[str, Sequence[object]] | None = None, layout: str = "one-jvm",
          out: str | os.PathLike[str] | None = None, workers: int | None = None, keep_pose_logs: bool = False,
          timeout_s: float | None = None) -> Any:
    """Runs ``world`` for every combination of ``params``' values (the first's change slowest) and every seed, each
    ``steps`` steps, ``workers`` at a time (default: the cores, one warm JVM each), its runs' files in ``out``
    (default a new temporary folder, ``run-INDEX/``). A row per run, in run order: ``index``, ``seed``, the
    parameters, ``status`` (``ok`` or ``failed``), ``exit_code``, the summary's ``steps``, ``robots``,
    ``messages``, ``control_failed``, the metrics, ``error``: a pandas DataFrame when pandas is installed, else a
    list of dicts."""
    names = list((params or {}).keys())
    values = [list(v) for v in (params or {}).values()]
    for name, v in zip(names, values, strict=True):
        if not v:
            raise ValueError(f"parameter {name}: no values")
    seed_list = [int(s) for s in seeds]
    if not seed_list:
        raise ValueError("no seeds")
    runs = [(dict(zip(names, combination, strict=True)), s)
            for combination in itertools.product(*values) for s in seed_list]
    base = Path(out) if out is not None else Path(tempfile.mkdtemp(prefix="robosim-sweep-"))
    base.mkdir(parents=True, exist_ok=True)
    file = Path(world).resolve()
    count = max(1, min(workers or os.cpu_count() or 1, len(runs)))
    free: list[int] = list(range(count))
    free_lock = threading.Condition()

    def one(index: int) -> dict[str, Any]:
        combination, seed = runs[index]
        with free_lock:
            while not free:
                free_lock.wait()
            slot = free.pop()
        try:
            result = run(file, steps=steps, seed=seed, params=combination, layout=layout, pose_log=keep_pose_logs,
                         out=base / f"run-{index}", timeout_s=timeout_s, host=_warm_host(slot, file.parent))
        except HostError as e:  # (its JVM lost during the run: a failed row; the next run gets a new one)
            log = base / f"run-{index}" / "run.log"
            result = RunResult(1, {}, {}, f"the warm JVM was lost: {e}", base / f"run-{index}", log, None, None)
        finally:
            with free_lock:
                free.append(slot)
                free_lock.notify()
        row: dict[str, Any] = {"index": index, "seed": seed, **combination,
                               "status": "ok" if result.ok else "failed", "exit_code": result.exit_code}
        for field in ("steps", "robots", "messages", "control_failed"):
            text = result.summary.get(field)
            row[field] = int(text) if text is not None and text.isdigit() else None
        row.update(result.metrics)
        row["error"] = result.error
        return row

    with ThreadPoolExecutor(max_workers=count, thread_name_prefix="robosim-sweep") as pool:
        rows = list(pool.map(one, range(len(runs))))
    try:
        import pandas  # type: ignore[import-untyped]  # noqa: PLC0415 (optional: rows without it)
    except ImportError:
        return rows
    return pandas.DataFrame(rows)
