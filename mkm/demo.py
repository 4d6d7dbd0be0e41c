"""``mkm demo``: the paper's two bench tests on the simulated bench, and one report of both.

The paper (Antonelli et al., Actuators 2025, 14(3), 153, section 4) tests its prototype (D0
30 mm, t0 3 mm, L0 282 mm) at eps = 0 and 12.2 % from 0 to 2.5 bar; :func:`run_demo` records the
same two staircases with the simulated NI USB-6001 (virtual clock: seconds, not the hour the
real bench takes) and writes the validation report comparing them with every model. A demo
replaces the runs of the demo before it (listed in ``demo.json`` beside them), so ``mkm report
mkm-out/demo/runs/*`` always reports one pair; no other folder is touched.
"""

from __future__ import annotations

import json
import shutil
import sys
from pathlib import Path

from mkm.core.records import provenance, write_json_atomic
from mkm.paths import default_out

RECORD = "demo.json"  # the run folders this demo wrote, replaced by the next one

DEMO_EPS = (0.0, 0.122)  # the paper's two tests of the prototype


def run_demo(out_dir: str | Path | None = None, progress: bool = True,
             cache_dir=None, **report_options) -> Path:
    """Acquire the two simulated runs under ``out_dir/runs`` and report them in
    ``out_dir/report``; returns the path of ``report.html``. Raises
    :class:`mkm.bench.backend.BenchError` when the simulated bench is held by another process
    (another ``mkm acquire --backend sim``, another demo) or a run does not complete.

    ``out_dir`` defaults to ``mkm-out/demo`` (:func:`mkm.paths.default_out`); ``cache_dir``
    (default: the user's prediction cache) and ``report_options`` go to
    :func:`mkm.report.build_report`.
    """
    from mkm.bench.backend import BenchError
    from mkm.bench.config import load_config
    from mkm.bench.run import acquire
    from mkm.prediction_cache import DEFAULT_CACHE_DIR
    from mkm.report import build_report

    out = Path(out_dir) if out_dir is not None else default_out("demo")
    _remove_previous_runs(out)
    runs = []
    for eps in DEMO_EPS:
        result = acquire(load_config(eps=eps), backend="sim", clock="virtual",
                         out_root=out / "runs", progress=progress and sys.stderr.isatty(),
                         command="demo")
        if result.path is None or result.status != "complete":
            raise BenchError(f"simulated run at eps = {eps:g} ended {result.status}: "
                             f"{result.reason}")
        runs.append(result.path)
    write_json_atomic(out / RECORD, {"runs": [Path(r).name for r in runs], **provenance()})
    return build_report(runs, out_dir=out / "report", progress=progress,
                        cache_dir=DEFAULT_CACHE_DIR if cache_dir is None else cache_dir,
                        **report_options)



def _remove_previous_runs(out: Path) -> None:
    """Delete the run folders the previous demo in ``out`` listed, and nothing else."""
    record = out / RECORD
    try:
        names = json.loads(record.read_text(encoding="utf-8"))["runs"]
    except (OSError, ValueError, KeyError, TypeError):
        return  # no earlier demo here (or not ours): leave everything
    for name in names:
        folder = out / "runs" / Path(str(name)).name  # a name, never a path elsewhere
        if folder.is_dir() and (folder / "run.json").is_file():
            shutil.rmtree(folder)
