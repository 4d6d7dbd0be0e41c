"""The FE batch runner (mkm.fem.batch) at scale: strong scaling, the scheduler's overhead, a
killed worker.

    .venv/bin/python benchmarks/bench_batch.py                 # everything, about 5 min
    .venv/bin/python benchmarks/bench_batch.py --jobs 200 --meshes coarse medium --workers 1 2

- Strong scaling: the same ``--jobs`` FE muscles on 1 worker (in-process) and on N local Dask
  workers, one mesh after the other, each from an empty cache; the wall time includes starting
  the local cluster, as a user sees it. Prints the ratio to the 1-worker time (the issue's
  targets: medium <= 0.6 on 2 workers, coarse <= 1.0).
- The scheduler: ``--tasks`` empty tasks through a local cluster give its task rate and the
  per-task overhead (wall x workers / tasks), and what they imply for 100 workers at the
  runner's task size (:data:`mkm.fem.batch.TASK_SECONDS`).
- A killed worker: a batch on a local cluster whose first worker process is killed (SIGKILL)
  once a third of the jobs are cached; prints the jobs finished and the largest difference from
  the in-process forces (0: bit-identical).

Prints the load average before and after (the machine may be shared); ``--json FILE`` writes
every figure with provenance.
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import statistics
import tempfile
import threading
import time
from pathlib import Path

import numpy as np

from mkm.core.records import provenance
from mkm.fem.batch import TASK_SECONDS, Job, run_jobs
from mkm.fem.calibration import calibrated

PRESSURES = tuple(float(p) for p in np.round(np.arange(0.0, 2.501, 0.25), 2))


def muscles(n: int) -> list[tuple[float, float, float]]:
    """``n`` muscles (D0_mm, t0_mm, eps) spread over the paper's box, in a fixed order."""
    rng = np.random.default_rng(0)
    unit = rng.random((n, 3))
    return [(round(30 + 20 * a, 3), round(2 + 2 * b, 3), round(0.2 * c, 4)) for a, b, c in unit]


def fe_jobs(n: int, mesh: str) -> list[Job]:
    theta0 = calibrated("axisym")["theta0_deg"]
    return [Job("axisym", mesh, D0, t0, eps, 282.0, theta0, PRESSURES)
            for D0, t0, eps in muscles(n)]


def cpu_seconds() -> float | None:
    """CPU time of this process and of its finished children (a closed local cluster's
    scheduler, nannies and workers) [s]; None where ``resource`` is missing (Windows)."""
    try:
        import resource
    except ImportError:
        return None
    return sum(resource.getrusage(who).ru_utime + resource.getrusage(who).ru_stime
               for who in (resource.RUSAGE_SELF, resource.RUSAGE_CHILDREN))


def timed_batch(jobs, **where) -> tuple[float, object, dict]:
    """Wall time, rows and run of ``jobs`` from an empty cache; ``run["cpu_s"]``: the CPU time
    of every process of the batch (client, and the local cluster's), independent of what else
    the machine runs."""
    with tempfile.TemporaryDirectory(prefix="mkm-bench-batch-") as tmp:
        cpu = cpu_seconds()
        start = time.perf_counter()
        frame, done = run_jobs(jobs, cache_dir=Path(tmp), progress=False, **where)
        wall = time.perf_counter() - start
        done["cpu_s"] = None if cpu is None else cpu_seconds() - cpu
        return wall, frame, done


def strong_scaling(n_jobs: int, meshes, workers) -> list[dict]:
    out = []
    for mesh in meshes:
        jobs = fe_jobs(n_jobs, mesh)
        base = None
        for n in workers:
            wall, frame, done = timed_batch(jobs, workers=n)
            solve = float(frame.groupby(["D0_mm", "t0_mm", "eps"], sort=False)["seconds"]
                          .first().sum())
            base = base or wall
            row = {"mesh": mesh, "jobs": len(jobs), "workers": n, "where": done["workers"],
                   "chunk_jobs": done["chunk_jobs"], "wall_s": wall, "sum_job_solve_s": solve,
                   "cpu_s": done["cpu_s"],
                   "computed_while_starting": done.get("computed_while_starting", 0),
                   "ratio_to_1_worker": wall / base,
                   "points_not_converged": int((~frame["converged"]).sum())}
            out.append(row)
            cpu = ("" if done["cpu_s"] is None else
                   f", CPU of all its processes {done['cpu_s']:.1f} s")
            print(f"  {mesh:6s} {len(jobs)} jobs, {n} worker(s): {wall:6.1f} s (jobs' solves "
                  f"{solve:.1f} s{cpu}, {done['chunk_jobs']} job(s)/task), ratio "
                  f"{row['ratio_to_1_worker']:.2f}", flush=True)
    return out


def _noop(x):
    return x


def scheduler_overhead(n_tasks: int, n_workers: int) -> dict:
    """Task rate and per-task overhead of empty tasks on a local cluster of ``n_workers``."""
    import logging

    from dask.distributed import Client, LocalCluster, wait

    with LocalCluster(n_workers=n_workers, threads_per_worker=1, processes=True,
                      dashboard_address=None, silence_logs=logging.ERROR) as cluster, \
            Client(cluster) as client:
        wait(client.map(_noop, range(2 * n_workers), pure=False))  # workers warm
        rounds = []
        for _ in range(5):  # one task's round trip
            start = time.perf_counter()
            client.submit(_noop, 0, pure=False).result()
            rounds.append(time.perf_counter() - start)
        start = time.perf_counter()
        wait(client.map(_noop, range(n_tasks), pure=False))
        wall = time.perf_counter() - start
    rate = n_tasks / wall
    overhead = wall * n_workers / n_tasks
    # 100 workers busy on tasks of TASK_SECONDS: the tasks per second the scheduler must handle,
    # and the efficiency per task if each still costs the overhead measured here
    need = 100 / TASK_SECONDS
    return {"tasks": n_tasks, "workers": n_workers, "wall_s": wall, "task_rate_per_s": rate,
            "overhead_per_task_s": overhead, "round_trip_s": statistics.median(rounds),
            "task_seconds": TASK_SECONDS, "rate_needed_by_100_workers_per_s": need,
            "scheduler_share_at_100_workers": need / rate,
            "efficiency_per_task": TASK_SECONDS / (TASK_SECONDS + overhead),
            "smallest_task_s_for_100_workers": 100 / rate}


def killed_worker(n_jobs: int, mesh: str) -> dict:
    """A batch on 2 local workers, the first worker killed once a third of the jobs are done."""
    import logging

    from dask.distributed import Client, LocalCluster

    jobs = fe_jobs(n_jobs, mesh)
    _, reference, _ = timed_batch(jobs, workers=1)
    with tempfile.TemporaryDirectory(prefix="mkm-bench-killed-") as tmp, \
            LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                         dashboard_address=None, silence_logs=logging.ERROR) as cluster, \
            Client(cluster) as client:
        pid = sorted(client.run(os.getpid).values())[0]
        cache, killed_at = Path(tmp), []

        def kill():
            while len(list(cache.glob("*.json"))) < n_jobs // 3:
                time.sleep(0.01)
            os.kill(pid, signal.SIGKILL)
            killed_at.append(len(list(cache.glob("*.json"))))

        killer = threading.Thread(target=kill, daemon=True)
        killer.start()
        start = time.perf_counter()
        frame, done = run_jobs(jobs, scheduler=cluster.scheduler_address, cache_dir=cache,
                               progress=False)
        wall = time.perf_counter() - start
        killer.join(timeout=1)
        finished = len(list(cache.glob("*.json")))
    a, b = frame["force_N"].to_numpy(), reference["force_N"].to_numpy()
    same_nan = bool(np.array_equal(np.isnan(a), np.isnan(b)))
    diff = float(np.nanmax(np.abs(a - b))) if same_nan else float("inf")
    return {"mesh": mesh, "jobs": n_jobs, "killed_after_jobs": killed_at[0] if killed_at else None,
            "jobs_finished": finished, "wall_s": wall, "max_abs_diff_N": diff,
            "chunk_jobs": done["chunk_jobs"]}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=200)
    parser.add_argument("--meshes", nargs="+", default=["coarse", "medium"])
    parser.add_argument("--workers", type=int, nargs="+", default=[1, 2])
    parser.add_argument("--tasks", type=int, default=2000)
    parser.add_argument("--killed-jobs", type=int, default=60)
    parser.add_argument("--skip", nargs="*", default=[],
                        choices=("scaling", "scheduler", "killed"))
    parser.add_argument("--json", type=Path, help="also write the figures here")
    args = parser.parse_args()
    load_before = os.getloadavg()
    print(f"load average before: {load_before[0]:.2f} (1 min), {os.cpu_count()} CPUs")
    results = {}
    if "scaling" not in args.skip:
        print("strong scaling (wall time from an empty cache, local cluster start included):")
        results["strong_scaling"] = strong_scaling(args.jobs, args.meshes, args.workers)
    if "scheduler" not in args.skip:
        s = scheduler_overhead(args.tasks, max(args.workers))
        results["scheduler"] = s
        print(f"scheduler: {s['tasks']} empty tasks on {s['workers']} workers in "
              f"{s['wall_s']:.2f} s: {s['task_rate_per_s']:.0f} tasks/s, overhead "
              f"{s['overhead_per_task_s'] * 1e3:.2f} ms per task per worker, one task's round "
              f"trip {s['round_trip_s'] * 1e3:.1f} ms")
        print(f"  100 workers on tasks of {TASK_SECONDS:g} s need "
              f"{s['rate_needed_by_100_workers_per_s']:.0f} tasks/s "
              f"({100 * s['scheduler_share_at_100_workers']:.0f} % of this scheduler's rate); "
              f"efficiency per task {100 * s['efficiency_per_task']:.1f} %; tasks shorter than "
              f"{s['smallest_task_s_for_100_workers'] * 1e3:.0f} ms would saturate it")
    if "killed" not in args.skip:
        k = killed_worker(args.killed_jobs, "coarse")
        results["killed_worker"] = k
        print(f"killed worker: {k['jobs']} coarse jobs on 2 workers, one killed after "
              f"{k['killed_after_jobs']} jobs: {k['jobs_finished']} of {k['jobs']} finished "
              f"in {k['wall_s']:.1f} s, largest difference from in-process "
              f"{k['max_abs_diff_N']:g} N")
    load_after = os.getloadavg()
    print(f"load average after: {load_after[0]:.2f} (1 min)")
    if args.json:
        args.json.write_text(json.dumps({**provenance(), "load_average_before": load_before,
                                         "load_average_after": load_after, **results,
                                         "rows": figures(results)},
                                        indent=2, default=str) + "\n")


#: the issue's targets for the ratio of N workers' wall time to one worker's, per mesh
RATIO_TARGETS = {"medium": 0.6, "coarse": 1.0}


def figures(results: dict) -> list[dict]:
    """The figures as one table (what the docs show): figure, value, unit, target."""
    rows = []
    for r in results.get("strong_scaling", []):
        rows.append({"figure": f"{r['jobs']} {r['mesh']}-mesh jobs on {r['workers']} worker(s)",
                     "value": round(r["wall_s"], 2), "unit": "s", "target": ""})
        if r["workers"] > 1:
            target = RATIO_TARGETS.get(r["mesh"])
            rows.append({"figure": f"{r['mesh']}: {r['workers']} workers / 1 worker",
                         "value": round(r["ratio_to_1_worker"], 3), "unit": "",
                         "target": "" if target is None else f"<= {target}"})
    s = results.get("scheduler")
    if s:
        rows += [{"figure": f"scheduler: task rate, {s['workers']} local workers",
                  "value": round(s["task_rate_per_s"]), "unit": "tasks/s", "target": ""},
                 {"figure": "scheduler: overhead per task per worker",
                  "value": round(s["overhead_per_task_s"] * 1e3, 2), "unit": "ms", "target": ""},
                 {"figure": f"100 workers on {s['task_seconds']:g} s tasks: share of that rate",
                  "value": round(100 * s["scheduler_share_at_100_workers"], 1), "unit": "%",
                  "target": "< 100"},
                 {"figure": "100 workers: efficiency per task",
                  "value": round(100 * s["efficiency_per_task"], 1), "unit": "%", "target": ""}]
    k = results.get("killed_worker")
    if k:
        rows += [{"figure": f"killed worker: jobs finished of {k['jobs']}",
                  "value": k["jobs_finished"], "unit": "jobs", "target": f"{k['jobs']}"},
                 {"figure": "killed worker: largest difference from in-process",
                  "value": k["max_abs_diff_N"], "unit": "N", "target": "0"}]
    return rows


if __name__ == "__main__":  # the guard lets Dask spawn worker processes from this script
    main()
