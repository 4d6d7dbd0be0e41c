"""Speed of the axisymmetric FE model: one 11-pressure isometric sweep per mesh level.

Run outside the test suite:

    .venv/bin/python benchmarks/bench_axisym.py [--levels coarse,medium,fine] [--repeats 3]
        [--eps 0.05,0.2] [--braids bonded,sliding] [--gaps 0,0.5] [--baseline main]

Muscle I (D0 35 mm, t0 2.5 mm, L0 282 mm) at the calibrated theta0, pressures 0 to 2.5 bar in
0.25 bar steps, as `mkm fem solve` runs it; each timed sweep follows an untimed one of the same
case (the sparse patterns and LU ordering of a mesh level are found once per process, by its
first muscle). For each level and eps it reports the median wall
time of the sweep and its median CPU time (``cpu_seconds``: on a shared machine the closer to
what an idle core takes), the unknowns, the Newton iterations (threshold search + pressure
ramp; a chord iteration counts as one), the number of tangent assemblies, residual-only
assemblies (chord iterations) and factorisations (counts do not depend on the machine's load),
and where the CPU time goes: mesh and operator set-up, assembly (tangents and residuals),
sparse LU (SuperLU's factorisation only) and the rest (back-substitutions, the pressure ramp's
symmetric permutation, Python). The split is measured by wrapping those functions with timers
in this script only.

``--gaps 0,0.5`` times each case at each radial gap between tube and braid [mm] (the
unilateral contact; a gap also makes eps = 0 solve its threshold state) and adds, per gapped
case, its median time over the gap-free case's (``vs_no_gap``: one run, both in turn).

``--baseline REV`` times the same sweeps with the FE code of git revision ``REV`` too (a copy
made with ``git archive``), each repeat of it and of the working tree in its own process, in
turn, and adds its median time, iterations and factorisations and the ratio of the medians:
on a shared machine a ratio measured in one run is the figure to quote.

Goals: medium <= 80 ms and fine <= 0.5 s per sweep on an idle core of the project's 2-core
machine; the sliding braid no more than twice the bonded one's time on the fine mesh (its one
sleeve tension is a dense row of the tangent, numbered last).
"""

from __future__ import annotations

import argparse
import io
import json
import os
import subprocess
import sys
import tarfile
import tempfile
import time
from pathlib import Path

import numpy as np

import mkm.fem.fe.model
import mkm.fem.fe.newton
from mkm.core.records import provenance

PRESSURES_BAR = np.arange(0.0, 2.51, 0.25)
MUSCLE_I = {"D0_mm": 35.0, "t0_mm": 2.5, "L0_mm": 282.0}
#: The source folders of the ``mkm`` import root (pyproject's package-dir)
PACKAGE_DIRS = {"mkm": "mkm", "fem": "mkm/fem", "bench": "mkm/bench", "surrogate": "mkm/surrogate"}


class Timers:
    """CPU time spent inside wrapped functions, by name (on a shared machine closer to what an
    idle core would take than wall time)."""

    def __init__(self):
        self.seconds: dict[str, float] = {}
        self.calls: dict[str, int] = {}

    def wrap(self, name, func, kind=lambda *args, **kwargs: ""):
        """``func`` timed under ``name`` plus ``kind(*args, **kwargs)`` (a suffix by call)."""
        def timed(*args, **kwargs):
            key = name + kind(*args, **kwargs)
            self.calls[key] = self.calls.get(key, 0) + 1
            start = time.process_time()
            try:
                return func(*args, **kwargs)
            finally:
                self.seconds[key] = self.seconds.get(key, 0.0) + time.process_time() - start

        return timed


def _assembly_kind(self, y, pressure_MPa, tangent=True):
    return "" if tangent else "_residual"


def bench_sweep(level: str, eps: float, theta0_deg: float, braid: str = "bonded",
                gap_mm: float = 0.0) -> dict:
    timers = Timers()
    half = mkm.fem.fe.model.HalfMuscle
    init, assemble, splu = half.__init__, half._assemble, mkm.fem.fe.newton.splu
    half.__init__ = timers.wrap("setup", init)
    half._assemble = timers.wrap("assembly", assemble, _assembly_kind)
    mkm.fem.fe.newton.splu = timers.wrap("lu", splu)
    try:
        start, cpu = time.perf_counter(), time.process_time()
        out = mkm.fem.fe.model.isometric_sweep(
            PRESSURES_BAR, MUSCLE_I["D0_mm"], MUSCLE_I["t0_mm"], eps, theta0_deg, MUSCLE_I["L0_mm"],
            level, braid=braid, **({"gap_mm": gap_mm} if gap_mm else {}))
        total, cpu = time.perf_counter() - start, time.process_time() - cpu
    finally:
        half.__init__, half._assemble = init, assemble
        mkm.fem.fe.newton.splu = splu
    below = out["force_N"] == 0
    threshold_iterations = int(out["iterations"][below].max()) if below.any() else 0
    t, calls = timers.seconds, timers.calls
    assembly_s = t.get("assembly", 0.0) + t.get("assembly_residual", 0.0)
    return {"mesh": level, "braid": braid, "eps": eps, "gap_mm": gap_mm,
            "dofs": int(out["dofs"][0]),
            "seconds": total, "cpu_seconds": cpu,
            "iterations": threshold_iterations + int(out["iterations"][~below].sum()),
            "assemblies": calls.get("assembly", 0), "residuals": calls.get("assembly_residual", 0),
            "factorisations": calls.get("lu", 0),
            "setup_s": t.get("setup", 0.0), "assembly_s": assembly_s, "lu_s": t.get("lu", 0.0),
            "other_s": cpu - t.get("setup", 0.0) - assembly_s - t.get("lu", 0.0),
            "converged": bool(out["converged"].all()), "force_2p5bar_N": float(out["force_N"][-1])}


def run_once(args) -> list[dict]:
    """One sweep of every case asked for, in this process, each after an untimed one of the
    same case: a mesh level's sparse patterns and LU ordering are found by the first muscle of
    a process and kept for every later one, as in a study or a design search."""
    theta0 = mkm.fem.fe.model.Axisym().params()["theta0_deg"]
    rows = []
    for level in args.levels.split(","):
        for eps in args.eps.split(","):
            for braid in args.braids.split(","):
                for gap in args.gaps.split(","):
                    bench_sweep(level, float(eps), theta0, braid, float(gap))  # warm-up
                    rows.append(bench_sweep(level, float(eps), theta0, braid, float(gap)))
    return rows


def checkout(revision: str, root: Path) -> Path:
    """The ``mkm`` import root of git ``revision`` laid out under ``root`` (for PYTHONPATH)."""
    repo = Path(__file__).resolve().parents[1]
    archive = subprocess.run(["git", "archive", "--format=tar", revision, *PACKAGE_DIRS],
                             cwd=repo, capture_output=True, check=True).stdout
    with tarfile.open(fileobj=io.BytesIO(archive)) as tar:
        for member in tar.getmembers():
            top, _, rest = member.name.partition("/")
            member.name = str(Path(PACKAGE_DIRS[top], rest))
            tar.extract(member, root, filter="data")
    return root


def in_process(args, pythonpath: Path | None) -> list[dict]:
    """One :func:`run_once` in a fresh interpreter (``pythonpath`` first on its path)."""
    env = dict(os.environ)
    if pythonpath is not None:
        env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(pythonpath),
                                                          env.get("PYTHONPATH")]))
    command = [sys.executable, __file__, "--levels", args.levels, "--eps", args.eps,
               "--braids", args.braids, "--gaps", args.gaps, "--once"]
    done = subprocess.run(command, env=env, capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def medians(runs: list[list[dict]]) -> list[dict]:
    """Per case, the run of median time with the median CPU time (the counts do not vary
    between runs)."""
    rows = []
    for case in zip(*runs, strict=True):
        row = dict(sorted(case, key=lambda r: r["seconds"])[len(case) // 2])
        row["cpu_seconds"] = float(np.median([r["cpu_seconds"] for r in case]))
        rows.append(row)
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", default="coarse,medium,fine")
    parser.add_argument("--eps", default="0.05,0.2")
    parser.add_argument("--braids", default="bonded")
    parser.add_argument("--gaps", default="0", help="radial gaps [mm], comma list")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--baseline", metavar="REV",
                        help="also time the FE code of this git revision (e.g. main)")
    parser.add_argument("--once", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.once:  # one repeat, for --baseline: JSON on stdout
        print(json.dumps(run_once(args)))
        return
    theta0 = mkm.fem.fe.model.Axisym().params()["theta0_deg"]
    columns = ["mesh", "braid", "eps", "gap_mm", "dofs", "seconds", "cpu_seconds", "iterations",
               "assemblies", "residuals", "factorisations", "setup_s", "assembly_s", "lu_s",
               "other_s", "converged", "force_2p5bar_N"]
    if args.baseline is None:
        rows = medians([run_once(args) for _ in range(args.repeats)])
    else:
        with tempfile.TemporaryDirectory() as tmp:
            base_root = checkout(args.baseline, Path(tmp))
            current, base = [], []
            for _ in range(args.repeats):  # in turn, so that both see the same load
                current.append(in_process(args, None))
                base.append(in_process(args, base_root))
        rows = medians(current)
        for row, old in zip(rows, medians(base), strict=True):
            row.update({f"{args.baseline}_seconds": old["seconds"],
                        f"{args.baseline}_cpu_seconds": old["cpu_seconds"],
                        f"{args.baseline}_iterations": old["iterations"],
                        f"{args.baseline}_factorisations": old["factorisations"],
                        "speedup": old["seconds"] / row["seconds"],
                        "cpu_speedup": old["cpu_seconds"] / row["cpu_seconds"]})
        columns += [f"{args.baseline}_seconds", f"{args.baseline}_cpu_seconds",
                    f"{args.baseline}_iterations",
                    f"{args.baseline}_factorisations", "speedup", "cpu_speedup"]
    if "," in args.gaps:
        no_gap = {(r["mesh"], r["braid"], r["eps"]): r["seconds"] for r in rows
                  if r["gap_mm"] == 0}
        for r in rows:
            r["vs_no_gap"] = r["seconds"] / no_gap.get((r["mesh"], r["braid"], r["eps"]), np.nan)
        columns.append("vs_no_gap")
    info = provenance()
    print(f"# muscle I, 11 pressures 0-2.5 bar, theta0 {theta0} deg, median of {args.repeats}; "
          f"{info['date_utc']}, {info['machine']}, {json.dumps(info['versions'])}")
    print(",".join(columns))
    for r in rows:
        print(",".join(_text(c, r[c]) for c in columns))


def _text(column: str, value) -> str:
    if column in ("eps", "gap_mm"):
        return f"{value:g}"
    if isinstance(value, float):
        return f"{value:.2f}" if abs(value) >= 100 else f"{value:.3f}"
    return str(value)


if __name__ == "__main__":
    main()
