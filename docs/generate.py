"""Write the generated parts of the documentation into ``docs/_generated/`` (run by ``conf.py``).

Nothing measured is typed into a page: each table and figure here is computed from a file that a
command wrote, and each include names that command, so rerunning it refreshes the page.

- ``api/``: one page per public module of ``mkm``, ``mkm.fem``, ``mkm.bench`` and
  ``mkm.surrogate`` (autodoc with numpydoc), and an index listing each package's ``__all__``;
- ``study_*.md`` and ``speed_accuracy.png``: the speed-accuracy table, its Pareto chart and the
  surrogates' errors per study muscle, from the shipped study table ``mkm/data/model_errors.csv``
  (``mkm study --update-shipped``);
- ``calibration.md``: the shipped braid-angle calibration ``fem/calibration.json``
  (``mkm fem calibrate --update-shipped``);
- ``datasets.md``: what the shipped FE datasets are, from their JSON sidecars;
- ``threshold_*.md``: the threshold study's before/after and simulated-truth tables;
- ``surrogate_std_fresh.md``: the default surrogate's std coverage on fresh draws, per run and
  pooled over their points (:data:`STD_COVERAGE_RUNS`);
- ``bench_*.md``: the benchmark tables, from the results the benchmark scripts wrote into
  ``docs/measured/`` (``make bench-docs`` runs them, the std coverage runs and the results the
  guides quote: :func:`measured_commands`);
- ``examples/``: one page per script of ``examples/``.

Usage: ``python docs/generate.py [--run-benchmarks [FILE ...]]`` (``sphinx-build`` runs it
without options through ``conf.py``).
"""

from __future__ import annotations

import functools
import importlib
import inspect
import json
import math
import pkgutil
import shutil
from pathlib import Path

import pandas as pd

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
OUT = DOCS / "_generated"
MEASURED = DOCS / "measured"
EXAMPLES = ROOT / "examples"
PACKAGES = ("mkm", "mkm.fem", "mkm.bench", "mkm.surrogate")
SKIPPED_MODULES = {"mkm.__main__"}  # runs the command line on import


# --- helpers ----------------------------------------------------------------------------------

def markdown_table(frame: pd.DataFrame, digits: int = 3) -> str:
    """A GitHub-flavoured Markdown table; floats to ``digits`` significant digits."""

    def cell(value) -> str:
        if isinstance(value, float):
            return "" if math.isnan(value) else f"{value:.{digits}g}"
        return str(value).replace("|", "\\|")

    lines = ["| " + " | ".join(cell(c) for c in frame.columns) + " |",
             "|" + "---|" * len(frame.columns)]
    lines += ["| " + " | ".join(cell(v) for v in row) + " |"
              for row in frame.itertuples(index=False)]
    return "\n".join(lines) + "\n"


def source_note(what: str, command: str, date: str | None = None) -> str:
    """The line under a generated table: where its numbers come from and how to refresh them."""
    when = f", measured {date}" if date else ""
    return f"\n*Generated from {what}{when}; regenerate with `{command}`.*\n"


def write(path: Path, text: str) -> None:
    """Write only when the content changed, so Sphinx rebuilds only what moved."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if not path.exists() or path.read_text(encoding="utf-8") != text:
        path.write_text(text, encoding="utf-8")


# --- API reference ----------------------------------------------------------------------------

def public_modules(package: str) -> list[str]:
    """The package and every module below it whose dotted name has no leading underscore."""
    names = [package]
    if package == "mkm":  # the other three are mapped folders, walked on their own
        path = importlib.import_module(package).__path__
        names += [m.name for m in pkgutil.walk_packages(path, "mkm.")]
    else:
        path = importlib.import_module(package).__path__
        names += [m.name for m in pkgutil.walk_packages(path, package + ".")]
    return [n for n in names if n not in SKIPPED_MODULES
            and not any(part.startswith("_") for part in n.split("."))]


@functools.cache
def all_modules() -> list[str]:
    """Every documented module of the four packages, each once."""
    return tuple(sorted({m for package in PACKAGES for m in public_modules(package)}))


def exported(module: str) -> list[str]:
    """A module's ``__all__`` (the package's front door), empty when it has none."""
    return list(getattr(importlib.import_module(module), "__all__", []))


def defining_module(module: str, name: str) -> str:
    """Where an exported name is documented: the module that defines it. A function or class
    names it; a constant is assigned at the top level of its module's source."""
    obj = getattr(importlib.import_module(module), name)
    if inspect.isfunction(obj) or inspect.isclass(obj):
        return obj.__module__
    for candidate in all_modules():
        if candidate.startswith(module) and name in _assigned(candidate) and vars(
                importlib.import_module(candidate)).get(name) is obj:
            return candidate
    return module


@functools.cache
def _assigned(module: str) -> frozenset[str]:
    """Names a module assigns at its top level (not those it imports); each module's source
    parsed once per build."""
    import ast

    source = inspect.getsource(importlib.import_module(module))
    names = set()
    for node in ast.parse(source).body:
        targets = node.targets if isinstance(node, ast.Assign) else (
            [node.target] if isinstance(node, ast.AnnAssign) else [])
        names |= {t.id for t in targets if isinstance(t, ast.Name)}
    return frozenset(names)


def module_page(module: str) -> str:
    title = f"``{module}``"
    lines = [title, "=" * len(title), ""]
    names = exported(module)
    if names:
        # Re-exports are documented where they are defined, so no object is described twice.
        lines += [f".. automodule:: {module}", "   :no-members:", "",
                  "Exported names (``__all__``):", ""]
        for name in sorted(names):
            target = defining_module(module, name)
            role = "obj" if target != module else "data"
            lines.append(f"- :{role}:`{name} <{target}.{name}>`" if target != module
                         else f"- ``{name}``")
        lines.append("")
        # the functions and classes defined here, each with its own (indexed) entry; the
        # constants below
        for name in sorted(n for n in names if defining_module(module, n) == module):
            obj = getattr(importlib.import_module(module), name)
            if inspect.isclass(obj) or inspect.isfunction(obj):
                directive = "autoclass" if inspect.isclass(obj) else "autofunction"
                lines += [f".. {directive}:: {module}.{name}", ""]
    else:
        lines += [f".. automodule:: {module}", ""]
    # constants a package exports from here that autodoc leaves out (no ``#:`` comment)
    from sphinx.pycode import ModuleAnalyzer

    commented = {name for (_, name) in ModuleAnalyzer.for_module(module).find_attr_docs()}
    constants = set(exported_constants().get(module, ()))
    if names:  # the automodule above documents no member: every exported constant here
        for name in sorted(constants):
            lines += [f".. autodata:: {module}.{name}", "   :no-value:", ""]
    else:
        for name in sorted(constants - commented):
            lines += [f".. autodata:: {module}.{name}", "   :no-value:", ""]
    return "\n".join(lines)


@functools.cache
def exported_constants() -> dict[str, list[str]]:
    """Home module -> the constants (not functions or classes) some module exports from it."""
    homes: dict[str, list[str]] = {}
    for module in all_modules():
        for name in exported(module):
            obj = getattr(importlib.import_module(module), name)
            if not (inspect.isfunction(obj) or inspect.isclass(obj) or inspect.ismodule(obj)):
                homes.setdefault(defining_module(module, name), []).append(name)
    return homes


def api_pages() -> None:
    folder = OUT / "api"
    modules = all_modules()
    for module in modules:
        write(folder / f"{module}.rst", module_page(module))
    index = ["API reference", "=============", "",
             "Generated from the docstrings (numpydoc). One page per module; a package's page",
             "lists its ``__all__``, each name linking to the module that defines it.", ""]
    for package in PACKAGES:
        heading = f"``{package}``"
        children = [m for m in modules if m == package or (
            m.startswith(package + ".") and not any(
                m.startswith(p + ".") for p in PACKAGES if p != package and p.startswith(package)))]
        index += [heading, "-" * len(heading), "", ".. toctree::", "   :maxdepth: 1", ""]
        index += [f"   {m}" for m in children] + [""]
    write(folder / "index.rst", "\n".join(index))
    # pages of modules that no longer exist would be orphans (a warning, so an error)
    for stale in set(folder.glob("mkm*.rst")) - {folder / f"{m}.rst" for m in modules}:
        stale.unlink()


# --- measured tables --------------------------------------------------------------------------

def study_tables() -> None:
    """The study's summary, Pareto chart and the surrogates' per-muscle errors, from the shipped
    table that ``mkm study --update-shipped`` writes (the same numbers ``auto`` reads)."""
    from mkm.auto import MODEL_ERRORS_FILE
    from mkm.core.records import save_figure
    from mkm.figures import speed_accuracy_figure
    from mkm.study import readable_summary, summarise

    errors = pd.read_csv(MODEL_ERRORS_FILE)
    info = json.loads(MODEL_ERRORS_FILE.with_suffix(".json").read_text(encoding="utf-8"))
    timings = errors[["predictor", "seconds_per_point"]].drop_duplicates()
    summary = summarise(errors, timings, info["reference"])
    note = source_note("the shipped study table `mkm/data/model_errors.csv` "
                       f"({info['machine_name']})", "mkm study --update-shipped",
                       info["date_utc"][:10])
    table = readable_summary(summary).drop(columns=["family"])
    write(OUT / "study_summary.md", markdown_table(table) + note)
    save_figure(speed_accuracy_figure(summary, info["machine_name"]), OUT / "speed_accuracy.png")

    muscles = pd.DataFrame(info["muscles"], columns=["muscle", "D0_mm", "t0_mm", "eps", "role"])
    pressures = info["pressures_bar"]
    lengths = sorted({p["params"]["L0_mm"] for p in info["predictors"].values()
                      if "L0_mm" in p["params"]})
    intro = (f"{len(muscles)} study muscles at L0 {', '.join(f'{v:g}' for v in lengths)} mm, "
             f"each at {len(pressures)} pressures from {min(pressures):g} to "
             f"{max(pressures):g} bar:\n\n")
    write(OUT / "study_muscles.md", intro + markdown_table(muscles) + note)

    scored = errors[errors["force_ref_N"].notna() & errors["valid"].astype(bool)]
    surrogates = scored[scored["family"].str.contains("surrogate", case=False)]
    per_muscle = (surrogates.assign(abs_err=surrogates["err_pct"].abs(),
                                    sq=(surrogates["force_N"] - surrogates["force_ref_N"]) ** 2)
                  .groupby(["predictor", "muscle"], sort=False)
                  .agg(largest_abs_err_pct=("abs_err", "max"), rmse_N=("sq", "mean"))
                  .reset_index())
    per_muscle["rmse_N"] = per_muscle["rmse_N"] ** 0.5
    wide = per_muscle.pivot(index="muscle", columns="predictor", values="largest_abs_err_pct")
    wide = wide.reindex(muscles["muscle"]).reset_index()
    wide.columns = ["muscle"] + [f"{c}: largest \\|Err%\\|" for c in wide.columns[1:]]
    write(OUT / "surrogate_errors.md", markdown_table(wide) + note)


def calibration_table() -> None:
    """The shipped braid-angle calibration, one row per model (``fem/calibration.json``)."""
    from mkm.fem.calibration import CALIBRATION_FILE

    data = json.loads(Path(CALIBRATION_FILE).read_text(encoding="utf-8"))
    rows = [{"model (key)": key, "target": e["target"], "theta0 [deg]": e["theta0_deg"],
             "slope residual [%]": e["slope_residual_pct"],
             "threshold [bar]": e["threshold_pressure_bar"]["model"],
             "force RMSE [N]": e["rmse_N"], "largest residual [N]": e["max_abs_residual_N"],
             "reference": e["reference"], "date": e["date_utc"][:10]}
            for key, e in sorted(data.items())]
    write(OUT / "calibration.md", markdown_table(pd.DataFrame(rows), digits=5)
          + source_note("`fem/calibration.json`",
                        "mkm fem calibrate --model SPEC --update-shipped"))


def practical_range() -> None:
    """The practical range as the code states it (:func:`mkm.fem.limits.range_text`)."""
    from mkm.fem.limits import range_text

    write(OUT / "practical_range.md", f"{range_text()[0].upper()}{range_text()[1:]}.\n")


def dataset_table() -> None:
    """What each shipped FE dataset is, from its JSON sidecar."""
    from mkm.surrogate.training_data import DEFAULT_DATASET

    rows = []
    for sidecar in sorted(Path(DEFAULT_DATASET).parent.glob("*.json")):
        meta = json.loads(sidecar.read_text(encoding="utf-8"))
        data = sidecar.with_suffix(".csv")
        n_rows = sum(1 for _ in data.open(encoding="utf-8")) - 1 if data.exists() else ""
        rows.append({"file": f"`{data.name}`", "rows": n_rows,
                     "what": meta.get("what") or f"grid `{meta.get('grid', '')}`",
                     "model": meta.get("model", ""), "mesh": meta.get("mesh", ""),
                     "command": f"`{meta.get('command', '')}`",
                     "date": meta.get("date_utc", "")[:10]})
    write(OUT / "datasets.md", markdown_table(pd.DataFrame(rows))
          + "\n*Generated from the JSON sidecars in `surrogate/data/`; each row names the "
            "command that wrote it.*\n")


#: The benchmarks whose tables the docs show: output file in docs/measured/ -> command (run from
#: the repository root by ``python docs/generate.py --run-benchmarks``, i.e. ``make bench-docs``).
#: A ``.csv`` output is the script's stdout (a ``#`` line of provenance, then CSV), unless the
#: command writes it into ``{dir}`` with its JSON sidecar.
BENCHMARKS = {
    "mesh_convergence.csv": "-m mkm fem convergence --out {dir}",
    "thickwall.csv": "benchmarks/bench_thickwall.py --points 200000 --repeats 5",
    "axisym.csv": "benchmarks/bench_axisym.py --levels coarse,medium,fine --repeats 3",
    "axisym_gap.csv": "benchmarks/bench_axisym.py --levels coarse,medium,fine --eps 0,0.05,0.2 "
                      "--gaps 0,0.5 --repeats 3",
    "design.json": "benchmarks/bench_design.py --repeats 5 --fe-repeats 2 --out {out}",
    "dataset.json": "benchmarks/bench_dataset.py --workers 1 2 --json {out}",
    "batch.json": "benchmarks/bench_batch.py --json {out}",
    "startup.json": "benchmarks/bench_startup.py --json {out}",
    "published.json": "benchmarks/bench_published.py --report-timing --json {out}",
    # whole commands, timed: record on an idle machine
    "published_commands.json": "benchmarks/bench_published_commands.py --repeats 3 --json {out}",
    "threshold_models.json": "benchmarks/bench_threshold_models.py --out {out}",
    "threshold_fe.json": "benchmarks/bench_threshold_fe.py --out {out} --muscles "
                         "DMSP-10-250,DMSP-20-300",
    "identify_gap.json": "benchmarks/bench_identify_gap.py --draws 8 --seed 20261206 "
                         "--out {out}",
    "identify_gap_wrong_bench.json": "benchmarks/bench_identify_gap.py --draws 8 --seed "
                                     "20261207 --wrong-bench --params "
                                     "theta0,rubber,gap,friction,creep,offset --out {out}",
    "identify_gap_itemised.json": "benchmarks/bench_identify_gap.py --draws 8 --seed "
                                  "20261207 --wrong-bench --itemised --params "
                                  "theta0,rubber,gap,friction,creep,offset --out {out}",
    "identify_rest_length.json": "benchmarks/bench_identify_rest_length.py --out {out}",
    "identify_rest_length_wall.json": "benchmarks/bench_identify_rest_length.py --fits "
                                      "thickwall:theta0,rubber,L0,t0 --out {out}",
    "identify_coverage.json": "benchmarks/bench_identify_coverage.py --draws 27 --out {out}",
    "identify_coverage_infamily.json": "benchmarks/bench_identify_coverage.py --draws 30 "
                                       "--seed 7 --departures in-family --out {out}",
    "identify_coverage_tables.json": "benchmarks/bench_identify_coverage.py --draws 24 "
                                     "--seed 41 --departures 'in-family,monitor offset,monitor "
                                     "gain,loadcell gain,rubber C01=0,rubber C01=2C10,true t0,"
                                     "true D0' --tables force=1N+0.1%,pressure=0.04bar "
                                     "--out {out}",
    "budget_coverage.json": "benchmarks/bench_uncertainty.py --runs 100 --eps 0 0.122 "
                            "--no-bands --out {out}",
    "identify_t0.json": "benchmarks/bench_identify_t0.py --draws 6 --seed 0 --out {out}",
    "identify_wrong_bench.json": "benchmarks/bench_identify_wrong_bench.py --draws 6 --seed "
                                 "20261240 --departures 'loadcell gain,loadcell offset,monitor "
                                 "offset,monitor gain,rubber ratio,theta0 at box edge,gap,"
                                 "friction and creep' --out {out}",
    "identify_wrong_bench_fresh.json": "benchmarks/bench_identify_wrong_bench.py --draws 6 "
                                       "--seed 20261300 --out {out}",
    "identify_wrong_bench_drift.json": "benchmarks/bench_identify_wrong_bench.py --departures "
                                       "'loadcell drift' --draws 8 --seed 20264501 --out {out}",
    "identify_wrong_bench_zero.json": "benchmarks/bench_identify_wrong_bench.py --departures "
                                      "'loadcell offset' --draws 24 --seed 20264401 --params "
                                      "theta0,rubber,friction,creep,offset,zero --out {out}",
    "identify_wrong_bench_zero_per_run.json": "benchmarks/bench_identify_wrong_bench.py "
                                              "--departures 'loadcell offset per run' --draws 8 "
                                              "--seed 20266001 --params theta0,rubber,friction,"
                                              "creep,offset,zero --out {out}",
    "identify_rubbers.json": "benchmarks/bench_identify_rubbers.py --draws 24 --seed 20261206 "
                             "--out {out}",
    "identify_wrong_range.json": "benchmarks/bench_identify_wrong_range.py --draws 8 --seed "
                                 "20261601 --out {out}",
    "identify_wrong_range_frame.json": "benchmarks/bench_identify_wrong_range.py --draws 6 "
                                       "--seed 20261601 --departures 'frame compliance' "
                                       "--out {out}",
    "identify_wrong_range_fibres.json": "benchmarks/bench_identify_wrong_range.py --draws 3 "
                                        "--seed 20261601 --departures 'stretching fibres' "
                                        "--out {out}",
    "identify_wrong_range_lag.json": "benchmarks/bench_identify_wrong_range.py --draws 8 "
                                     "--seed 20261601 --departures 'tubing lag,tubing lag on "
                                     "ramps' --out {out}",
    "identify_wrong_range_softening.json": "benchmarks/bench_identify_wrong_range.py --draws 6 "
                                           "--seed 20261601 --departures 'first-cycle "
                                           "softening,first-cycle softening with repeats,"
                                           "repeats without softening' --out {out}",
    "mesh_bound.json": "benchmarks/bench_mesh_bound.py --muscles 240 --seed 20264102 "
                       "--out {out}",
    # the guide's further checks of the bound, on the draws it names
    "mesh_bound_draw80.json": "benchmarks/bench_mesh_bound.py --muscles 80 --seed 20264101 "
                              "--out {out}",
    "mesh_bound_draw120.json": "benchmarks/bench_mesh_bound.py --muscles 120 --seed 20261210 "
                               "--out {out}",
    "failsafe.json": "benchmarks/bench_failsafe.py --json {out}",
    "console_close.json": "benchmarks/bench_console_close.py --json {out}",
    "recorder_lag.json": "benchmarks/bench_recorder_lag.py --repeats 20 --out {out}",
    # the guide quotes this draw's muscles: its seed, not a fresh one
    "stability_map.json": "benchmarks/bench_stability_map.py --muscles 200 --seed "
                          "2857834494527622234 --out {out}",
    # and the two fresh draws it names beside it
    "stability_map_draw40.json": "benchmarks/bench_stability_map.py --muscles 40 --seed "
                                 "2026120506 --out {out}",
    "stability_map_draw100.json": "benchmarks/bench_stability_map.py --muscles 100 --seed "
                                  "20263001 --out {out}",
}


#: The default surrogate's std coverage on fresh draws, one file per run of
#: ``benchmarks/bench_surrogate.py`` (output -> command, as in :data:`BENCHMARKS`; surrogates.md
#: gives the commands): ``make bench-docs`` runs them too, but they are pooled
#: (:func:`pooled_std_coverage`), not tabulated one by one, and they record no table of rows.
STD_COVERAGE_RUNS = {
    "surrogate_std_coverage.json": "benchmarks/bench_surrogate.py --draws 25 --muscles 12 "
                                   "--seed 20261501 --kinds muscle-gp --repeats 20 --out {out}",
    "surrogate_std_coverage_fresh.json": "benchmarks/bench_surrogate.py --draws 25 --muscles 12 "
                                         "--seed 20261901 --kinds muscle-gp --repeats 20 "
                                         "--out {out}",
}

#: Results the guides quote in their own words and hand-typed tables, each test-held to its
#: file, rather than as a generated table (output -> command, as in :data:`BENCHMARKS`):
#: ``make bench-docs`` runs them too.
QUOTED_RUNS = {
    "auto.json": "benchmarks/bench_auto.py --calls 200 --seed 20261203 --out {out}",
    "auto_practical.json": "benchmarks/bench_auto.py --calls 100 --range practical --seed "
                           "20261223 --out {out}",
    "surrogate_limits_range.json": "benchmarks/bench_surrogate_limits.py --kind muscle-gp-range "
                                   "--muscles 60 --draws 5 --seed 20261701 --fractions "
                                   "0.35,0.5,0.7,1 --repeats 2 --out {out}",
    "surrogate_limits_range_adaptive.json": "benchmarks/bench_surrogate_limits.py --kind "
                                            "muscle-gp-range --muscles 60 --draws 10 --seed "
                                            "20262101 --fractions 1 --adaptive 100 --pool-seed "
                                            "20262401 --out {out}",
    "surrogate_limits_box_adaptive.json": "benchmarks/bench_surrogate_limits.py --kind muscle-gp "
                                          "--muscles 40 --draws 15 --seed 20262301 --fractions 1 "
                                          "--adaptive 96 --pool-seed 20261303 --out {out}",
    "surrogate_limits_box_adaptive_pool2.json": "benchmarks/bench_surrogate_limits.py --kind "
                                                "muscle-gp --muscles 40 --draws 15 --seed "
                                                "20262301 --fractions 1 --adaptive 96 "
                                                "--pool-seed 20261304 --out {out}",
    "surrogate_range_gp.json": "benchmarks/bench_surrogate_range.py --kind muscle-gp-range "
                               "--muscles 60 --box-muscles 40 --seed 20261225 --out {out}",
    "surrogate_range_gp_fresh.json": "benchmarks/bench_surrogate_range.py --kind muscle-gp-range "
                                     "--muscles 60 --box-muscles 40 --seed 20261228 --out {out}",
    "surrogate_range_gp_pooled.json": "benchmarks/bench_surrogate_range.py --kind "
                                      "muscle-gp-range --muscles 60 --box-muscles 40 --seed "
                                      "20261701 --draws 5 --out {out}",
    "surrogate_range_gp_all.json": "benchmarks/bench_surrogate_range.py --kind muscle-gp-range "
                                   "--muscles 60 --box-muscles 40 --seeds 20261225 20261228 "
                                   "20261701 20261702 20261703 20261704 20261705 --pool-with "
                                   "tests/surrogate/data/range_check.csv --out {out}",
    "surrogate_range_lock.json": "benchmarks/bench_range_lock.py --out {out}",
    "repeats_ftest.json": "benchmarks/bench_repeats_ftest.py --fits 3000 --wrong-fits 400 "
                          "--gap-mm 0.05 --seed 2026121163 --out {out}",
    "identify_rest_length_shortened.json": "benchmarks/bench_identify_rest_length.py --fits "
                                           "thickwall:theta0,rubber,L0 --pairs shortened "
                                           "--out {out}",
    "design_band_dmsp20.json": "benchmarks/bench_design_band.py --cases "
                               "0,1,2,3,4,5,6,7,8,18 --out {out}",
    "design_band_tight_wide.json": "benchmarks/bench_design_band.py --cases "
                                   "9,10,11,12,13,14,15,16,17,19 --out {out}",
    "design_band_fresh.json": "benchmarks/bench_design_band_fresh.py --points 500 --seed "
                              "2026120741 --out {out}",
    "design_identified.json": "benchmarks/bench_design_identified.py --out {out}",
    "overforce_band.json": "benchmarks/bench_overforce_band.py --draws 12 --out {out}",
    "surrogate_range_decline.json": "benchmarks/bench_surrogate_decline.py --seeds 20261225 "
                                    "20261228 20261701 20261702 20261703 20261704 20261705 "
                                    "--pool-with tests/surrogate/data/range_check.csv "
                                    "--box-seeds 20261225 20261228 20261701 --out {out}",
}

#: Results measured on a training set the repository does not ship (output -> that file):
#: surrogates.md gives the commands that build it first, so ``make bench-docs`` cannot run them
#: from a checkout alone.
BUILT_FIRST = {"surrogate_range.json": "practical.csv", "surrogate_limits_box.json": "DESIGN2.csv"}


def measured_commands() -> dict[str, str]:
    """Every output ``make bench-docs`` measures again, with its command: the benchmark tables',
    the std coverage runs' and the results the guides quote (:data:`QUOTED_RUNS`)."""
    return {**BENCHMARKS, **STD_COVERAGE_RUNS, **QUOTED_RUNS}


def run_benchmarks(names=None) -> None:
    """Run the benchmarks of :func:`measured_commands` (all, or ``names``) and keep their results
    in ``docs/measured/``."""
    import shlex
    import subprocess
    import sys

    MEASURED.mkdir(exist_ok=True)
    for name, command in measured_commands().items():
        if names and name not in names:
            continue
        target = MEASURED / name
        # paths relative to the repository (the benchmarks run there): the recorded command
        # says what to type in any checkout, not where this one lies
        relative = {"out": target.relative_to(ROOT).as_posix(),
                    "dir": MEASURED.relative_to(ROOT).as_posix()}
        args = [sys.executable, *shlex.split(command.format(**relative))]
        print(f"running {' '.join(args[1:])}", file=sys.stderr)
        done = subprocess.run(args, cwd=ROOT, capture_output=True, text=True, check=True)
        if name.endswith(".csv") and "{dir}" not in command:
            target.write_text(done.stdout, encoding="utf-8")


def _benchmark_frame(path: Path) -> tuple[pd.DataFrame, str]:
    """A benchmark's result table and a line saying when and where it was measured."""
    sidecar = path.with_suffix(".json")
    if path.suffix == ".csv" and sidecar.exists():
        record = json.loads(sidecar.read_text(encoding="utf-8"))
        return pd.read_csv(path), _measured_on(record)
    if path.suffix == ".csv":
        first, _, rest = path.read_text(encoding="utf-8").partition("\n")
        import io

        return pd.read_csv(io.StringIO(rest)), first.lstrip("# ").strip()
    record = json.loads(path.read_text(encoding="utf-8"))
    rows = record.get("rows") or record.get("results")
    return pd.json_normalize(rows), _measured_on(record)


def _measured_on(record: dict) -> str:
    seed = f", seed {record['seed']}" if "seed" in record else ""  # fresh draws, recorded
    return f"{record.get('date_utc', '?')}, {record.get('machine', '?')}{seed}, " + ", ".join(
        f"{k} {v}" for k, v in record.get("versions", {}).items())


def _stage_seconds(path: Path) -> str:
    """The wall time of each stage a benchmark records under ``seconds`` (with the machine's
    load average: it may be shared), as a second table."""
    if path.suffix != ".json":
        return ""
    record = json.loads(path.read_text(encoding="utf-8"))
    if "seconds" not in record:
        return ""
    frame = pd.DataFrame({"stage": list(record["seconds"]),
                          "wall time [s]": list(record["seconds"].values())})
    load = record.get("load_average_before")
    return ("\nWall time of each stage" + (f" (load average {load[0]:.1f} before)" if load
                                           else "") + ":\n\n" + markdown_table(frame, 3))


def _second_table(path: Path) -> str:
    """A benchmark's second table, where it records one: the leave-one-length-out table
    (``leave_one_length_out``: its params and rows) or the coverage per set pressure
    (``by_set_pressure``)."""
    if path.suffix != ".json":
        return ""
    record = json.loads(path.read_text(encoding="utf-8"))
    if record.get("by_set_pressure"):
        return ("\nPressure coverage per set pressure [%], rising and falling steps pooled:\n\n"
                + markdown_table(pd.json_normalize(record["by_set_pressure"]), 4))
    held = record.get("leave_one_length_out")
    if not held:
        return ""
    return (f"\nLeave one length out (`mkm identify` on every length with `--params "
            f"{held['params']}`, each length predicted from the others):\n\n"
            + markdown_table(pd.json_normalize(held["rows"]), 4))


def benchmark_tables() -> None:
    """One Markdown table per benchmark result in ``docs/measured/``, with the command that
    measured it; a benchmark not run yet gets a note saying how to run it."""
    for name, command in BENCHMARKS.items():
        path = MEASURED / name
        shown = command.replace(" --out {out}", "").replace(" --json {out}", "").replace(
            "{dir}", "docs/measured")
        if not path.exists():
            text = (f"*Not measured in this checkout: run `make bench-docs` (or `python "
                    f"{shown}`).*\n")
        else:
            frame, measured = _benchmark_frame(path)
            text = (f"`python {shown}`; measured {measured}.\n\n" + markdown_table(frame, 6)
                    + _second_table(path) + _stage_seconds(path)
                    + source_note(f"`docs/measured/{name}`", "make bench-docs"))
        write(OUT / f"bench_{path.stem}.md", text)


def pooled_std_coverage(names=tuple(STD_COVERAGE_RUNS)) -> dict:
    """The std coverage of the runs in ``names`` pooled over their points: each run's fraction
    within 1, 2 and 3 std weighed by the points it counts (``offgrid_pooled.points``)."""
    runs = [json.loads((MEASURED / name).read_text(encoding="utf-8"))["offgrid_pooled"]
            for name in names]
    points = sum(run["points"] for run in runs)
    return {"muscles": sum(run["muscles"] for run in runs), "points": points,
            "seeds": [seed for run in runs for seed in run["seeds"]],
            **{f"within_{k}std": sum(round(run[f"within_{k}std"] * run["points"])
                                     for run in runs) / points for k in (1, 2, 3)},
            # one draw's spread: the least and the most of any draw of the runs
            **{f"within_{k}std_draws": [min(run[f"within_{k}std_draws"][0] for run in runs),
                                        max(run[f"within_{k}std_draws"][1] for run in runs)]
               for k in (1, 2)}}


def std_coverage_table() -> str:
    """The default surrogate's std coverage on each run of fresh draws and pooled over them
    (:func:`pooled_std_coverage`), as Markdown."""
    def pct(share):
        return "100" if share == 1 else f"{100 * share:.1f}"

    def row(label, part, bold=False):
        cover = " / ".join(pct(part[f"within_{k}std"]) for k in (1, 2, 3)) + " %"
        spread = " / ".join("-".join(map(pct, part[f"within_{k}std_draws"]))
                            for k in (1, 2)) + " %"
        return {"set": f"**{label}**" if bold else label, "muscles": str(part["muscles"]),
                "points": str(part["points"]),
                "within 1 / 2 / 3 std": f"**{cover}**" if bold else cover,
                "one draw, within 1 / 2 std": spread}

    if not all((MEASURED / name).exists() for name in STD_COVERAGE_RUNS):
        return "*Not measured in this checkout: run the commands above.*\n"
    rows = []
    for name in STD_COVERAGE_RUNS:
        run = json.loads((MEASURED / name).read_text(encoding="utf-8"))["offgrid_pooled"]
        rows.append(row(f"fresh, seeds {run['seeds'][0]}-{run['seeds'][-1]}", run))
    rows.append(row("fresh, pooled", pooled_std_coverage(), bold=True))
    files = " and ".join(f"`docs/measured/{name}`" for name in STD_COVERAGE_RUNS)
    return (markdown_table(pd.DataFrame(rows)) + f"\n*Generated from {files}, pooled by their "
            "points; regenerate with the commands above.*\n")


def threshold_model_tables() -> None:
    """The threshold study's before/after, simulated-truth, fitted rest-length and measured
    line tables (its selection table is the generic ``bench_threshold_models.md``), from
    ``docs/measured/threshold_models.json``."""
    path = MEASURED / "threshold_models.json"
    for key in ("before_after", "simulated", "rest_length", "lines"):
        if not path.exists():
            text = "*Not measured in this checkout: run `make bench-docs`.*\n"
        else:
            record = json.loads(path.read_text(encoding="utf-8"))
            text = (markdown_table(pd.DataFrame(record[key]), 4)
                    + source_note("`docs/measured/threshold_models.json`", "make bench-docs",
                                  record["date_utc"][:10]))
        write(OUT / f"threshold_{key}.md", text)


# --- examples ---------------------------------------------------------------------------------

def example_pages() -> None:
    """One page per example script: its docstring as the text, then the whole script."""
    import ast

    folder = OUT / "examples"
    if folder.exists():
        shutil.rmtree(folder)
    folder.mkdir(parents=True)
    index = ["# Examples", "",
             "Scripts to copy and run (`python examples/NAME.py` from a checkout). Each asserts",
             "one number it shows; the test suite runs every one (`tests/test_examples.py`).",
             "", "```{toctree}", ":maxdepth: 1", ""]
    for script in sorted(EXAMPLES.glob("*.py")):
        doc = ast.get_docstring(ast.parse(script.read_text(encoding="utf-8"))) or script.stem
        title, _, body = doc.partition("\n")
        page = [f"# {title.strip()}", "", body.strip(), "",
                f"```{{literalinclude}} ../../../examples/{script.name}",
                ":language: python", ":lines: " + f"{_code_start(script)}-", "```", ""]
        write(folder / f"{script.stem}.md", "\n".join(page))
        index.append(script.stem)
    write(folder / "index.md", "\n".join(index + ["```", ""]))


def _code_start(script: Path) -> int:
    """The first non-blank line after the module docstring."""
    import ast

    text = script.read_text(encoding="utf-8")
    line = ast.parse(text).body[0].end_lineno + 1
    lines = text.splitlines()
    while line <= len(lines) and not lines[line - 1].strip():
        line += 1
    return line


def main() -> None:
    OUT.mkdir(exist_ok=True)
    api_pages()
    study_tables()
    calibration_table()
    practical_range()
    dataset_table()
    benchmark_tables()
    threshold_model_tables()
    write(OUT / "surrogate_std_fresh.md", std_coverage_table())
    example_pages()


if __name__ == "__main__":
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--run-benchmarks", nargs="*", metavar="FILE",
                        help="first run the benchmarks (all, or these outputs: "
                             + ", ".join(measured_commands()) + ") into docs/measured/")
    options = parser.parse_args()
    unknown = [n for n in options.run_benchmarks or () if n not in measured_commands()]
    if unknown:  # before any runs: a typo would otherwise run nothing and say nothing
        import sys

        print(f"generate.py: error: --run-benchmarks {' '.join(unknown)}: expected some of "
              + ", ".join(measured_commands()), file=sys.stderr)
        sys.exit(2)
    if options.run_benchmarks is not None:
        run_benchmarks(options.run_benchmarks)
    main()
