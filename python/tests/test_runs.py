"""robosim.run and robosim.sweep against real warm hosts (scripts/simulation-host.sh)."""

from __future__ import annotations

from pathlib import Path

import pytest

import robosim

REPO = Path(__file__).resolve().parents[2]
WANDER = REPO / "examples/python/wander.xml"


def test_a_run_gives_its_numbers_its_pose_log_and_its_recording_and_repeats(tmp_path: Path) -> None:
    first = robosim.run(WANDER, steps=60, seed=3, params={"speed": 600}, out=tmp_path / "a")
    assert first.ok, first.error
    assert first.summary["steps"] == "60" and first.summary["robots"] == "6"
    assert first.metrics["distance_m"] > 0 and "turns" in first.metrics
    assert first.pose_log is not None and len(first.pose_log.read_text().splitlines()) == 6 * 60 + 1
    assert first.recording is not None and first.recording.stat().st_size > 0
    again = robosim.run(WANDER, steps=60, seed=3, params={"speed": 600}, out=tmp_path / "b")
    other = robosim.run(WANDER, steps=60, seed=4, params={"speed": 600}, out=tmp_path / "c", record=False)
    assert again.pose_log is not None and other.pose_log is not None
    assert again.pose_log.read_bytes() == first.pose_log.read_bytes(), "the same seed, the same run"
    assert other.pose_log.read_bytes() != first.pose_log.read_bytes()
    assert other.recording is None and other.metrics == {}


def test_a_bad_parameter_is_a_failed_run_that_says_why(tmp_path: Path) -> None:
    result = robosim.run(WANDER, steps=10, params={"sped": 1}, out=tmp_path)
    assert not result.ok and result.exit_code == 2
    assert "no parameter 'sped' here (its parameters: speed)" in result.error


def test_a_sweep_gives_a_row_per_run_in_run_order(tmp_path: Path) -> None:
    rows = robosim.sweep(WANDER, steps=30, seeds=[1, 2], params={"speed": [300, 900]}, out=tmp_path, workers=2)
    if not isinstance(rows, list):  # (a DataFrame where pandas is installed)
        rows = rows.to_dict("records")
    assert [(r["index"], r["speed"], r["seed"]) for r in rows] == [(0, 300, 1), (1, 300, 2), (2, 900, 1),
                                                                     (3, 900, 2)]
    assert all(r["status"] == "ok" and r["steps"] == 30 and r["robots"] == 6 for r in rows), rows
    assert rows[2]["distance_m"] > 2 * rows[0]["distance_m"], "three times the speed"


def test_without_pandas_a_sweep_is_a_list_of_dicts(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(__import__("sys").modules, "pandas", None)  # (an import of it then fails)
    rows = robosim.sweep(WANDER, steps=10, seeds=[1], out=tmp_path, workers=1)
    assert isinstance(rows, list) and rows[0]["status"] == "ok" and rows[0]["seed"] == 1
