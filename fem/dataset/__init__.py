"""The MKM dataset: forces of a model over a grid of muscles (``grid``), built resumably on
local workers or a Dask cluster (``build``, through the FE batch runner :mod:`mkm.fem.batch`)."""

from mkm.fem.dataset.build import (
    DatasetRun,
    Job,
    JobCache,
    build_dataset,
    make_jobs,
    run_job,
    run_jobs,
)
from mkm.fem.dataset.grid import GRID_KEYS, Grid, load_grid, parse_grid

__all__ = ["GRID_KEYS", "DatasetRun", "Grid", "Job", "JobCache", "build_dataset", "load_grid",
           "make_jobs", "parse_grid", "run_job", "run_jobs"]
