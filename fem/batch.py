"""One runner for every batch of FE muscles: in-process, on local workers, or on a Dask cluster.

A :class:`Job` is one model call, the pressure sweep of one muscle at one ``eps`` with every
input resolved (the braid angle included: workers never read a calibration file). Every command
that solves many muscles (the dataset, the surrogate's design and off-grid evaluation, the
study's references, design verification, the identification's FE search and confirmation) makes
jobs and hands them to :func:`run_jobs`, which

- computes only the jobs missing from the per-job cache (:class:`JobCache`, one JSON file per
  finished job in the user's cache, keyed by the job's inputs and the model's source version):
  an interrupted batch restarted computes only what is missing;
- runs them in-process (one worker), on a local Dask cluster of single-threaded worker processes
  (started once per :class:`Runner` and reused by every batch of a command), or on an existing
  Dask cluster given by its scheduler address; while a cluster starts (seconds), this process
  computes jobs itself;
- sizes the tasks for the scheduler: single jobs until the first answers, then chunks of about
  :data:`TASK_SECONDS` from the median time of the jobs done so far (small jobs batched so the
  per-task overhead of a few milliseconds is hidden; FE jobs on the fine mesh stay one per
  task), and never fewer than :data:`CHUNKS_PER_WORKER` chunks per worker, so the last ones
  balance; a few tasks per worker are queued at a time;
- writes each result to the cache on the client as it arrives (workers need no shared file
  system), and shows one progress bar on stderr when it is a terminal.

Each job is computed from its inputs alone (a fresh model solve; what a worker keeps between
jobs is the imported code and the model objects, which hold parameters only), so the numbers are
bit-identical whatever the number of workers or the chunking. A worker killed mid-batch loses
its running task; Dask's scheduler gives it to another worker (up to
``distributed.scheduler.allowed-failures`` deaths per task, 3 by default) and the batch finishes
with every job.

How to run it on a lab's own cluster or an HPC queue, and what the workers need, is in the
datasets guide (``docs/guide/datasets.md``, "Scale-out with Dask"). Before any job is sent, every
worker reports the source version of the model (:func:`mkm.core.records.source_version`); a
worker with other code is refused with the versions of both, and each result carries the version
it was computed with.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import statistics
import sys
from dataclasses import asdict, dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from mkm.core.home import user_cache
from mkm.core.records import provenance, source_version, write_atomic
from mkm.fem.ladder import entry, make_model

#: Target wall time of one Dask task [s]: a task costs a local worker a few milliseconds
#: (benchmarks/bench_batch.py measures it), which a second of work hides, while a killed
#: worker loses at most about that much work.
TASK_SECONDS = 1.0
#: At least this many chunks per worker: the last chunks are short enough to balance the load.
CHUNKS_PER_WORKER = 4
#: Tasks kept queued per worker: one running, the next already there when it finishes.
QUEUED_PER_WORKER = 2
#: Without ``workers`` given, a batch whose first job says it would take less than this in-process
#: [s] stays in-process: a local cluster's start-up and its workers' imports (seconds) would eat
#: the gain, and a handful of sweeps answers at once.
AUTO_CLUSTER_SECONDS = 20.0
#: Dask settings of the local cluster (and advice for a lab's workers): the nanny's
#: ``MALLOC_TRIM_THRESHOLD_`` makes glibc map and unmap every large temporary array (the FE ran
#: slower per job with it); the workers' statistical profiler samples the running task
#: every 10 ms, and the event loops tick every 20 ms, CPU a single-threaded solve can use.
QUIET_WORKERS = {"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None,
                 "distributed.worker.profile.enabled": False,
                 "distributed.admin.tick.interval": "500ms"}
#: This process computes jobs while its cluster starts (False: the cluster computes every job).
COMPUTE_WHILE_STARTING = True
#: How long a batch waits for a cluster without workers before giving up [s].
WORKER_WAIT_SECONDS = 60.0

COLUMNS = {
    "pressure_bar": "gauge pressure [bar]",
    "D0_mm": "inner tube diameter at rest [mm]",
    "t0_mm": "wall thickness at rest [mm]",
    "eps": "shortening ratio dL/L0 [fraction]",
    "force_N": "developed force [N]; NaN where the model did not converge",
    "converged": "the model's solve converged at this point",
    "valid": "converged and inside the model's validity range",
    "iterations": "Newton iterations at this point (models that iterate; empty otherwise)",
    "cutbacks": "load-step cutbacks at this point (models that iterate; empty otherwise)",
    "seconds": "wall time of the model's predict() for the job's whole pressure sweep [s]",
    "model": "model name in mkm.fem.ladder.MODELS",
    "mesh": "mesh level of the model (empty for mesh-free models)",
    "theta0_deg": "braid angle at rest [deg]",
    "L0_mm": "muscle length at rest [mm]",
}


def default_cache_dir():
    """One file per finished job, in the user's cache (:func:`mkm.core.home.user_cache`)."""
    return user_cache("dataset")


@dataclass(frozen=True)
class Job:
    """One model call: the pressure sweep of one muscle at one ``eps``, all inputs resolved."""

    model: str
    mesh: str | None
    D0_mm: float
    t0_mm: float
    eps: float
    L0_mm: float | None
    theta0_deg: float | None
    pressure_bar: tuple[float, ...]
    C10_MPa: float | None = None  # wall rubber (Mooney-Rivlin); None: the model's default
    C01_MPa: float | None = None

    def key(self, model_version: str) -> str:
        """Cache key: a hash of every input and of the code that computes the job."""
        job = asdict(self)
        for name in ("C10_MPa", "C01_MPa"):  # default rubber: the keys of jobs before it existed
            if job[name] is None:
                del job[name]
        text = json.dumps({"job": job, "model_version": model_version}, sort_keys=True)
        return hashlib.sha256(text.encode()).hexdigest()[:24]

    def describe(self) -> str:
        return (f"{self.model} D0_mm={self.D0_mm:g} t0_mm={self.t0_mm:g} eps={self.eps:g} "
                f"L0_mm={self.L0_mm} theta0_deg={self.theta0_deg}")


def mesh_label(mesh) -> str | None:
    return None if mesh is None else str(mesh)


def model_version(name: str) -> str:
    """The source version of rung ``name`` (:func:`mkm.core.records.source_version` of its
    module)."""
    return source_version(entry(name).module)


@lru_cache(maxsize=64)
def _model(name: str, mesh, theta0_deg, L0_mm, C10_MPa, C01_MPa):
    """The model of a job, built once per process and parameters (models hold parameters only:
    a job's numbers do not depend on which jobs ran before it in the process)."""
    return make_model(name, theta0_deg=theta0_deg, L0_mm=L0_mm, mesh=mesh, C10_MPa=C10_MPa,
                      C01_MPa=C01_MPa)


def run_job(job: Job) -> dict[str, Any]:
    """Compute one job: rows as plain lists, the model's parameters and the model version.

    Runs wherever the job is sent (in-process or on a Dask worker); returns plain data only.
    """
    model = _model(job.model, job.mesh, job.theta0_deg, job.L0_mm, job.C10_MPa, job.C01_MPa)
    n = len(job.pressure_bar)
    pred = model.predict(np.array(job.pressure_bar), job.D0_mm, job.t0_mm, job.eps)
    params = pred.params
    rows = {
        "pressure_bar": list(job.pressure_bar),
        "D0_mm": [job.D0_mm] * n, "t0_mm": [job.t0_mm] * n, "eps": [job.eps] * n,
        "force_N": pred.force_N.tolist(),
        "converged": pred.converged.tolist(),
        "valid": pred.valid.tolist(),
        "iterations": _optional_ints(pred.extras.get("iterations"), n),
        "cutbacks": _optional_ints(pred.extras.get("cutbacks"), n),
        "seconds": [pred.seconds] * n,
        "model": [job.model] * n,
        "mesh": [mesh_label(params.get("mesh", job.mesh))] * n,
        "theta0_deg": [params.get("theta0_deg", job.theta0_deg)] * n,
        "L0_mm": [params.get("L0_mm", job.L0_mm)] * n,
    }
    # the wall rubber, for models that have one (a surrogate learns across rubbers)
    rows.update({k: [params[k]] * n for k in ("C10_MPa", "C01_MPa") if k in params})
    # whatever else the model reports per point (an FE model's threshold pressure, failure
    # reason, ...) is kept: computed anyway, and useful to surrogates and to failure studies
    rows.update({k: np.ravel(v).tolist() for k, v in pred.extras.items() if k not in rows})
    return {"rows": rows, "params": _jsonable(params), "model_version": model_version(job.model)}


def run_chunk(jobs: tuple[Job, ...]) -> list[dict[str, Any]]:
    """One Dask task: :func:`run_job` of each job in order; a job that raises gives
    ``{"error": ...}`` instead of losing the chunk's other results."""
    out = []
    for job in jobs:
        try:
            out.append(run_job(job))
        except Exception as exc:  # reported by the client with the job it belongs to
            out.append({"error": f"{type(exc).__name__}: {exc}"})
    return out


def worker_model_version(name: str) -> str:
    """The model's source version where this runs (a worker answers the client's check), after
    importing the model's code: a worker imports it while the client still computes jobs
    itself, not at its first task."""
    import importlib

    importlib.import_module(entry(name).module)
    return model_version(name)


def _optional_ints(values, n: int) -> list[int | None]:
    if values is None:
        return [None] * n
    return [int(v) if np.isfinite(v) else None for v in np.ravel(values)]


def _jsonable(obj):
    return json.loads(json.dumps(obj, default=lambda o: o.tolist() if hasattr(o, "tolist")
                                 else str(o)))


class JobCache:
    """One JSON file per finished job in ``directory``, named by its key, written atomically."""

    def __init__(self, directory: str | os.PathLike):
        from pathlib import Path

        self.directory = Path(directory)

    def path(self, key: str):
        return self.directory / f"{key}.json"

    def get(self, key: str) -> dict | None:
        """The cached result, or None when absent or unreadable (a damaged file is recomputed)."""
        try:
            return json.loads(self.path(key).read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None

    def put(self, key: str, job: Job, result: dict) -> None:
        record = {"key": key, "job": asdict(job), **result, "date_utc": provenance()["date_utc"]}
        write_atomic(self.path(key), json.dumps(record, indent=1) + "\n")


def check_where(workers: int | None, scheduler: str | None) -> None:
    """Raise ``ValueError`` unless ``workers`` and ``scheduler`` name one place to run."""
    if scheduler is not None and workers is not None:
        raise ValueError(f"workers={workers} and scheduler={scheduler!r} given: a cluster has its "
                         "own workers; expected one of the two")
    if workers is not None and (int(workers) != workers or workers < 1):
        raise ValueError(f"workers={workers} is invalid: expected at least 1")


def chunk_size(job_seconds: float, jobs: int, workers: int) -> int:
    """Jobs per task: about :data:`TASK_SECONDS` of work, at least :data:`CHUNKS_PER_WORKER`
    tasks per worker, at least one job."""
    by_time = TASK_SECONDS / job_seconds if job_seconds > 0 else jobs
    by_balance = math.ceil(jobs / (CHUNKS_PER_WORKER * max(workers, 1)))
    return max(1, min(int(by_time), by_balance))


class Runner:
    """Where batches run: in-process (``workers=1``), a local Dask cluster of ``workers``
    single-threaded processes (default: the CPU count), or the cluster at ``scheduler``.

    Use it as a context manager to run several batches on the same workers: the local cluster
    starts at the first batch that needs it and closes at the end of the ``with`` block. Outside
    one, each :meth:`run` starts and closes its own.
    """

    def __init__(self, workers: int | None = None, scheduler: str | None = None):
        check_where(workers, scheduler)
        self.scheduler = scheduler
        # no choice made: the CPU count, for batches long enough to pay for a cluster
        self.auto = workers is None and scheduler is None
        self.workers = workers if workers is not None or scheduler else (os.cpu_count() or 1)
        self._cluster = None
        self._client = None
        self._open = False

    def __enter__(self) -> Runner:
        self._open = True
        return self

    def __exit__(self, *exc) -> None:
        self._open = False
        self.close()

    def close(self) -> None:
        """Close the client and the local cluster (a remote cluster is left running)."""
        if self._client is not None:
            self._client.close()
            self._client = None
        if self._cluster is not None:
            self._cluster.close()
            self._cluster = None

    def in_process(self, n_jobs: int, job_seconds: float | None = None) -> bool:
        """Whether ``n_jobs`` more jobs run in this process (``job_seconds``: one job's time,
        measured in-process, for the default choice)."""
        if self.scheduler is not None or self._client is not None:
            return False
        if min(self.workers, n_jobs) == 1:
            return True
        return (self.auto and job_seconds is not None
                and job_seconds * n_jobs < AUTO_CLUSTER_SECONDS)

    def describe(self) -> str:
        if self.scheduler is not None:
            return f"the Dask cluster at {self.scheduler}"
        if self._cluster is not None:
            return f"{len(self._cluster.workers)} local Dask workers"
        return "1 worker (in-process)"

    def client(self, n_jobs: int):
        """The Dask client, starting the local cluster (at most ``n_jobs`` workers) if needed."""
        if self._client is not None:
            return self._client
        import logging

        import dask
        from dask.distributed import Client, LocalCluster

        if self.scheduler is None:
            # processes, one thread each (the nanny sets OMP/MKL/OPENBLAS_NUM_THREADS=1 in
            # workers), without what steals CPU from a solve (QUIET_WORKERS)
            with dask.config.set(QUIET_WORKERS):
                self._cluster = LocalCluster(n_workers=min(self.workers, n_jobs),
                                             threads_per_worker=1, processes=True,
                                             dashboard_address=None,
                                             silence_logs=logging.ERROR)
            self._client = Client(self._cluster)
        else:
            try:
                self._client = Client(self.scheduler)
            except OSError as exc:
                raise ValueError(f"scheduler={self.scheduler!r}: {exc}: expected the address "
                                 "of a running Dask scheduler, e.g. tcp://HOST:8786") from None
            try:
                self._client.wait_for_workers(1, timeout=WORKER_WAIT_SECONDS)
            except TimeoutError:
                self.close()
                raise ValueError(f"scheduler={self.scheduler!r} has no worker after "
                                 f"{WORKER_WAIT_SECONDS:g} s: start some with `dask worker "
                                 f"{self.scheduler}`") from None
        return self._client

    def check_versions(self, client, model: str, expected: str) -> None:
        """Refuse the batch if a worker computes ``model`` with other code than this client.

        A worker that dies while it answers is left out: it computes nothing, and each result
        carries the version it was computed with, which the client checks again."""
        versions = client.run(worker_model_version, model, on_error="return")
        for address, version in sorted(versions.items()):
            if isinstance(version, ImportError):
                raise ValueError(f"the workers of {self.describe()} cannot import the model "
                                 f"({version}): install mkm-bench on them")
            if isinstance(version, BaseException):
                continue
            if version != expected:
                raise ValueError(f"worker {address} has {model} model version {version}, this "
                                 f"client has {expected}: install the same mkm-bench code on "
                                 "the workers")

    def run(self, jobs: list[Job], *, cache_dir=None, progress: bool = True,
            desc: str = "FE batch"):
        """Compute ``jobs`` through the cache: see :func:`run_jobs`."""
        try:
            return _run(self, jobs, cache_dir, progress, desc)
        finally:
            if not self._open:
                self.close()


def run_jobs(jobs: list[Job], *, workers: int | None = None, scheduler: str | None = None,
             runner: Runner | None = None, cache_dir=None, progress: bool = True,
             desc: str = "FE batch"):
    """Compute ``jobs`` (one model, any list: a grid's product or a space-filling design) through
    the per-job cache, on ``runner`` or on a :class:`Runner` of ``workers`` / ``scheduler``.

    Returns the rows of every job in order (:data:`COLUMNS` first, then whatever else the model
    reports per point) and what was done: ``computed``, ``cached``, ``workers`` (where),
    ``chunk_jobs`` (the most jobs in one Dask task; 1 in-process), ``model_version``,
    ``params`` (of the first job).
    """
    if runner is None:
        runner = Runner(workers, scheduler)
    elif workers is not None or scheduler is not None:
        raise ValueError("runner and workers/scheduler given: expected one of the two")
    return runner.run(jobs, cache_dir=cache_dir, progress=progress, desc=desc)


def _run(runner: Runner, jobs, cache_dir, progress, desc):
    import pandas as pd
    from tqdm import tqdm

    if not jobs:
        raise ValueError("no job to run: expected at least one muscle")
    models = sorted({job.model for job in jobs})
    if len(models) > 1:
        raise ValueError(f"jobs of several models ({', '.join(models)}): expected one")
    model_ver = model_version(models[0])
    keys = [job.key(model_ver) for job in jobs]
    store = JobCache(default_cache_dir() if cache_dir is None else cache_dir)
    results: dict[str, dict] = {}
    for key in keys:
        cached = store.get(key)
        if cached is not None:
            results[key] = cached
    missing = list({key: job for key, job in zip(keys, jobs, strict=True)
                    if key not in results}.items())  # a job listed twice is computed once
    n_cached = len(set(keys)) - len(missing)
    # shown on a terminal only: logs and pipes stay clean (as mkm.progress does)
    show = progress and hasattr(sys.stderr, "isatty") and sys.stderr.isatty()
    bar = tqdm(total=len(set(keys)), initial=n_cached, unit="job", desc=desc, disable=not show,
               file=sys.stderr, dynamic_ncols=True)
    failures: list[str] = []

    def finished(key: str, job: Job, result: dict) -> None:
        if "error" in result:
            failures.append(f"{job.describe()}: {result['error']}")
            return
        if result["model_version"] != model_ver:
            raise ValueError(f"a worker computed {job.describe()} with model version "
                             f"{result['model_version']}, this client has {model_ver}: "
                             "install the same mkm-bench code on the workers")
        store.put(key, job, result)
        results[key] = result
        bar.update()

    chunk, here = 1, 0
    with bar:
        if not missing:
            where = "no worker (all cached)"
        else:
            todo = list(missing)
            if runner.in_process(len(todo)) or runner.auto and runner._client is None:
                # one job in-process first: its time tells whether the rest is worth a cluster
                key, job = todo.pop(0)
                first = run_chunk((job,))[0]
                finished(key, job, first)
                seconds = first["rows"]["seconds"][0] if "rows" in first else 0.0
                if runner.in_process(len(todo), seconds):
                    for key, job in todo:
                        finished(key, job, run_chunk((job,))[0])
                    todo = []
            if todo:
                client, here = _start_while_computing(runner, todo, finished, models[0],
                                                      model_ver)
                todo = todo[:len(todo) - here]
                if todo:
                    chunk = _run_on_dask(client, todo, finished)
            where = runner.describe()
    if failures:
        raise RuntimeError(f"{len(failures)} of {len(missing)} jobs failed (the others are "
                           "cached; re-run to retry): " + "; ".join(failures))
    frame = pd.concat([pd.DataFrame(results[key]["rows"]) for key in keys], ignore_index=True)
    frame = frame.astype({"iterations": "Int64", "cutbacks": "Int64", "converged": bool,
                          "valid": bool})
    frame = frame[list(COLUMNS) + [c for c in frame.columns if c not in COLUMNS]]
    return frame, {"computed": len(missing), "cached": n_cached, "workers": where,
                   "computed_while_starting": here,
                   "chunk_jobs": chunk, "model_version": model_ver,
                   "params": results[keys[0]]["params"]}


def _start_while_computing(runner: Runner, todo: list, finished, model: str, version: str):
    """The runner's Dask client, started (or connected) and its workers' model version checked
    in a thread while this process computes jobs from the end of ``todo``: its core is idle
    while the workers start (seconds of process start and imports). Returns the client and how
    many jobs it computed (the last ones of ``todo``)."""
    from concurrent.futures import ThreadPoolExecutor

    def start():
        client = runner.client(len(todo))
        runner.check_versions(client, model, version)
        return client

    pool = ThreadPoolExecutor(1, thread_name_prefix="mkm-cluster-start")
    try:
        starting = pool.submit(start)
        here = 0
        while COMPUTE_WHILE_STARTING and here < len(todo) and not starting.done():
            key, job = todo[len(todo) - 1 - here]
            finished(key, job, run_chunk((job,))[0])
            here += 1
        return starting.result(), here
    finally:  # Ctrl-C does not wait for a scheduler that may take a minute to answer
        pool.shutdown(wait=False)


def _run_on_dask(client, missing, finished) -> int:
    """Run ``missing`` (key, job) pairs on ``client``'s cluster and return the largest number of
    jobs in one task.

    About :data:`QUEUED_PER_WORKER` tasks per worker are kept queued; each new one is sized
    (:func:`chunk_size`) from the median time of the jobs finished so far (single jobs until the
    first answers). The client caches each result as it arrives, so an interruption loses only
    the tasks in flight.
    """
    from dask.distributed import as_completed

    n_workers = max(1, sum(w.get("nthreads", 1)
                           for w in client.scheduler_info(n_workers=-1)["workers"].values()))
    pending = list(missing)
    seconds: list[float] = []  # of every job finished
    in_flight: dict = {}
    # this client's loop: another client of the process may be the default one
    queue = as_completed(loop=client.loop)
    largest = 1

    def top_up() -> None:
        nonlocal pending, largest
        while pending and len(in_flight) < QUEUED_PER_WORKER * n_workers:
            size = (chunk_size(statistics.median(seconds), len(pending), n_workers)
                    if seconds else 1)
            part, pending = pending[:size], pending[size:]
            future = client.submit(run_chunk, tuple(job for _, job in part),
                                   key=f"mkm-fe-{part[0][0]}-{len(part)}", pure=False)
            in_flight[future] = part
            queue.add(future)
            largest = max(largest, size)

    top_up()
    for future in queue:
        part = in_flight.pop(future)
        try:
            results = future.result()
        except Exception as exc:  # a task the cluster gave up on: each of its jobs fails
            results = [{"error": f"{type(exc).__name__}: {exc}"}] * len(part)
        for (key, job), result in zip(part, results, strict=True):
            finished(key, job, result)
        seconds += [r["rows"]["seconds"][0] for r in results if "rows" in r]
        top_up()
    return largest
