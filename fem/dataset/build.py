"""The MKM dataset: forces of any registered model over a grid of muscles, resumable and parallel.

A grid (``fem/grids/paper.toml`` is Table 1 of Antonelli et al. 2025) lists values per parameter.
Its jobs are independent: one per muscle (``D0_mm``, ``t0_mm``, ``L0_mm``, ``theta0_deg``) and
``eps``, each the model's pressure sweep, run by the FE batch runner (:mod:`mkm.fem.batch`: the
per-job cache, so an interrupted build resumes where it stopped and editing the physics
invalidates what it computed; in-process, local workers or a Dask cluster).
"""

from __future__ import annotations

import itertools
import os
import time
from dataclasses import dataclass
from importlib.metadata import version
from pathlib import Path
from typing import Any

import pandas as pd

from mkm.core.records import (
    check_csv_with_sidecar,
    provenance,
    recorded_path,
    write_csv_with_sidecar,
)
from mkm.fem.batch import (
    COLUMNS,
    Job,
    JobCache,
    Runner,
    check_where,
    default_cache_dir,
    mesh_label,
    model_version,
    run_job,
    run_jobs,
)
from mkm.fem.calibration import Calibration
from mkm.fem.dataset.grid import Grid, load_grid
from mkm.fem.ladder import entry, make_model, static_names

__all__ = ["COLUMNS", "DEFAULT_OUT", "DatasetRun", "Job", "JobCache", "build_dataset",
           "default_cache_dir", "make_jobs", "model_version", "run_job", "run_jobs"]

DEFAULT_OUT = Path("data/mkm_dataset.csv")


#: families no dataset is built of: the surrogate and auto's pick are fitted to a dataset,
#: friction's branches and creep belong to a history, not to a muscle's static force
NOT_PHYSICS = ("surrogate", "auto", "friction")


def make_jobs(grid: Grid, model: str, mesh: str | None = None,
              calibration: Calibration | None = None) -> list[Job]:
    """One job per muscle and eps, with theta0 resolved (the default of ``calibration``, None:
    the shipped one, made explicit).

    Resolving theta0 here makes the cache key change when the calibration does, and sends
    workers the angle itself rather than a lookup in their own ``fem/calibration.json``.
    """
    if ":" in model:  # a predictor spec of the other commands: its parameters have no place
        name = model.partition(":")[0]
        raise ValueError(f"--model {model!r}: a dataset takes a model's name alone: expected one "
                         f"of {', '.join(static_names())} (--model {name}), the mesh given by "
                         "--mesh, theta0_deg and L0_mm by the grid")
    if entry(model).family in NOT_PHYSICS:
        raise ValueError(f"--model {model!r} is no physics model a dataset is built of: "
                         f"expected one of {', '.join(static_names())}")
    jobs = []
    for D0, t0, e, L0, theta0 in itertools.product(grid.D0_mm, grid.t0_mm, grid.eps,
                                                   grid.L0_mm, grid.theta0_deg):
        built = make_model(model, calibration, theta0_deg=theta0, L0_mm=L0, mesh=mesh)
        if theta0 is None and calibration is not None \
                and built.calibration_key not in calibration.entries:
            # a dataset's angle is the grid's: there is no --theta0
            raise ValueError(calibration.missing(built.calibration_key,
                                                 "--grid FILE with theta0_deg = "))
        params = built.params()
        jobs.append(Job(model=model, mesh=mesh_label(params.get("mesh", mesh)), D0_mm=D0,
                        t0_mm=t0, eps=e, L0_mm=params.get("L0_mm", L0),
                        theta0_deg=params.get("theta0_deg", theta0),
                        pressure_bar=grid.pressure_bar))
    return jobs


@dataclass
class DatasetRun:
    """What :func:`build_dataset` did: the rows, the counts and where they were written."""

    frame: pd.DataFrame
    jobs_total: int
    jobs_computed: int
    jobs_cached: int
    wall_seconds: float
    workers: str
    out: Path | None
    sidecar: Path | None

    @property
    def points_not_converged(self) -> int:
        return int((~self.frame["converged"]).sum())

    @property
    def jobs_not_converged(self) -> int:
        keys = ["D0_mm", "t0_mm", "eps", "L0_mm", "theta0_deg"]
        return int((~self.frame.groupby(keys, dropna=False)["converged"].all()).sum())

    def summary(self) -> str:
        where = f"; wrote {self.out} and {self.sidecar}" if self.out else ""
        return (f"{len(self.frame)} rows from {self.jobs_total} jobs ({self.jobs_computed} "
                f"computed, {self.jobs_cached} from cache) in {self.wall_seconds:.1f} s on "
                f"{self.workers}; {self.points_not_converged} of {len(self.frame)} points "
                f"({self.jobs_not_converged} of {self.jobs_total} jobs) did not converge, "
                f"{int((~self.frame['valid']).sum())} points flagged invalid{where}")


def build_dataset(grid: str | os.PathLike | Grid = "paper", model: str = "axisym", *,
                  mesh: str | None = None, out: str | os.PathLike | None = DEFAULT_OUT,
                  workers: int | None = None, scheduler: str | None = None,
                  runner: Runner | None = None, cache_dir: str | os.PathLike | None = None,
                  progress: bool = True, calibration: Calibration | None = None) -> DatasetRun:
    """Build the dataset of ``model`` over ``grid``: compute the jobs not in the cache, write the
    CSV ``out`` (one row per point: :data:`COLUMNS`, then any other per-point output of the
    model) and its provenance ``out.json``.

    ``workers=1`` runs in-process; more (default: the CPU count) start a local Dask cluster of
    single-threaded worker processes; ``scheduler="tcp://HOST:PORT"`` sends the jobs to an
    existing Dask cluster instead; ``runner`` runs it on a :class:`~mkm.fem.batch.Runner` already
    open (its workers reused). Non-converged points are kept with ``converged=False`` and
    NaN force. ``out=None`` writes nothing (the rows are in the returned ``frame``).
    ``calibration`` gives the default theta0 (None: the shipped one).
    """
    check_where(workers, scheduler)
    if out is not None:  # before hours of FE: a file in the way is said now
        check_csv_with_sidecar(out)
    grid = grid if isinstance(grid, Grid) else load_grid(grid)
    cache_dir = default_cache_dir() if cache_dir is None else cache_dir
    start = time.perf_counter()
    jobs = make_jobs(grid, model, mesh, calibration)
    frame, done = run_jobs(jobs, workers=workers, scheduler=scheduler, runner=runner,
                           cache_dir=cache_dir, progress=progress, desc=f"{model} dataset")
    run = DatasetRun(frame=frame, jobs_total=len(jobs), jobs_computed=done["computed"],
                     jobs_cached=done["cached"], wall_seconds=time.perf_counter() - start,
                     workers=done["workers"], out=None, sidecar=None)
    if out is not None:
        run.out = Path(out)
        run.sidecar = run.out.with_suffix(".json")
        info = _provenance(run, grid, jobs, done, cache_dir, calibration)
        write_csv_with_sidecar(run.out, frame.to_csv(index=False, lineterminator="\n"), info)
    return run


def _provenance(run: DatasetRun, grid: Grid, jobs: list[Job], done: dict,
                cache_dir, calibration: Calibration | None) -> dict[str, Any]:
    from mkm.fem.calibration import calibration_provenance

    info = provenance()
    info["versions"]["dask.distributed"] = version("distributed")
    model = make_model(jobs[0].model, calibration, mesh=jobs[0].mesh)
    if None not in grid.theta0_deg:
        calibration = {"key": model.calibration_key, "source": "theta0_deg given by the grid"}
    else:
        try:
            calibration = calibration_provenance(model)
        except ValueError:  # the model's default theta0 does not come from a calibration
            calibration = {"key": model.calibration_key,
                           "source": "the model's default theta0_deg"}
    return {
        **info,
        "model": jobs[0].model,
        "model_version": done["model_version"],
        "model_params": done["params"],
        "mesh": jobs[0].mesh,
        "calibration": calibration,
        "grid": grid.as_dict(),
        "rows": len(run.frame),
        "jobs": run.jobs_total,
        "jobs_computed": run.jobs_computed,
        "jobs_from_cache": run.jobs_cached,
        "points_not_converged": run.points_not_converged,
        "jobs_not_converged": run.jobs_not_converged,
        "wall_seconds": round(run.wall_seconds, 3),
        "workers": run.workers,
        "chunk_jobs": done["chunk_jobs"],
        "cache": ("the user cache" if Path(cache_dir) == Path(default_cache_dir())
                  else recorded_path(cache_dir)),
        "columns": {c: COLUMNS.get(c, "reported by the model (see "
                                      f"{entry(jobs[0].model).factory})")
                    for c in run.frame.columns},
    }
