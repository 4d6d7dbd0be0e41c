"""The speed-against-accuracy study and the stability maps (``mkm study``).

Speed against accuracy: every predictor (Equation 2 with both diameter conventions, the
thick-wall model, the FE model at each mesh level, every surrogate kind including the paper's 27
nets) predicts the pressure sweeps of the study muscles (the paper's test muscles I, II, III, a
box of held-out geometries around the paper's grid, and the bench prototype at eps = 12.2 %);
its error is the paper's Equation 7 against the reference, the finest FE mesh, on the points
where the reference converged; its cost is seconds per predicted force, timed in this run on
this machine. The Pareto front is the set of predictors that no other beats in both.

Stability: each method over a grid of pressure and eps for the smallest and the largest tube of
the practical range (:data:`mkm.fem.limits.PRACTICAL_RANGE`), and the largest with the thinnest
wall, classified per point (valid, invalid by the model's own limit, not
converged, outside the training domain, negative, falling with pressure).

The point-by-point errors go to ``mkm/data/model_errors.csv``, the table the ``auto`` model reads.
FE sweeps go through :mod:`mkm.prediction_cache`; FE timings are measured afresh on muscle I
in every run, so a warm cache never reports stale speeds.
"""

from __future__ import annotations

import platform
import time
import warnings
from collections.abc import Callable
from contextvars import ContextVar
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.auto import DEFAULT_TOLERANCE, MODEL_ERRORS_FILE, read_model_errors
from mkm.core.ranges import list_items
from mkm.core.records import provenance, save_figure, write_atomic, write_json_atomic
from mkm.fem import ladder
from mkm.fem.calibration import Calibration
from mkm.fem.interface import ForceModel, Prediction
from mkm.fem.limits import PRACTICAL_RANGE
from mkm.fem.outcomes import PHYSICAL_LIMITS, classify
from mkm.fem.paper import equation7_err_pct
from mkm.figures import speed_accuracy_figure, stability_figure
from mkm.html import esc, figure_html, html_page, provenance_details, table_html
from mkm.paths import default_out
from mkm.prediction_cache import (
    DEFAULT_CACHE_DIR,
    cached_predict,
    model_origin,
    model_version,
    predict_many,
)
from mkm.progress import progress_bar
from mkm.registry import parse_spec
from mkm.scoring import error_summary, pareto_front
from mkm.surrogate import kinds as kind_registry
from mkm.verdict import format_seconds

STUDY_PRESSURES = tuple(np.round(np.arange(0.0, 2.5001, 0.25), 2))  # the paper's test sweep
# name, D0 [mm], t0 [mm], eps, role. I-III: the paper's test muscles (section 3.3); H1-H8 a box
# just inside the corners of the paper's grid (D0 30-50, t0 2-4, eps 0-0.2), none on it, so
# surrogates are scored on geometries they were not trained on; P12 the bench prototype
# (D0 30, t0 3) at the paper's eps = 12.2 %.
STUDY_MUSCLES = (
    ("I", 35.0, 2.5, 0.05, "test"), ("II", 40.0, 3.0, 0.15, "test"),
    ("III", 45.0, 3.5, 0.20, "test"),
    *((f"H{1 + i}", d, t, e, "held-out") for i, (d, t, e) in enumerate(
        (d, t, e) for d in (32.0, 48.0) for t in (2.2, 3.8) for e in (0.02, 0.18))),
    ("P12", 30.0, 3.0, 0.122, "prototype"),
)
# The stability maps span the practical range (mkm.fem.limits): its smallest and its largest
# tube, and the largest with the thinnest wall, up to its top pressure.
_D0, _t0 = PRACTICAL_RANGE.D0_mm, PRACTICAL_RANGE.t0_mm
_t0_largest = min(_t0[1], PRACTICAL_RANGE.t0_per_D0_max * _D0[1])
STABILITY_MUSCLES = (
    (f"smallest: D0 {_D0[0]:g} mm, t0 {_t0[0]:g} mm", _D0[0], _t0[0]),
    (f"largest: D0 {_D0[1]:g} mm, t0 {_t0_largest:g} mm", _D0[1], _t0_largest),
    (f"largest, thinnest wall: D0 {_D0[1]:g} mm, t0 {_t0[0]:g} mm", _D0[1], _t0[0]))
STABILITY_PRESSURES = tuple(np.round(np.arange(0.0, PRACTICAL_RANGE.pressure_bar[1] + 1e-4,
                                               0.5), 2))
STABILITY_EPS = tuple(np.round(np.arange(0.0, 0.3501, 0.05), 3))
# whether run_study shows progress, seen by the predictor factories it calls
_SHOW_PROGRESS: ContextVar[bool] = ContextVar("mkm_study_progress", default=False)
#: Surrogate kinds trained at a time when no number of workers is given: one per core of the
#: two a CI machine has (training is minutes, cold)
TRAINING_JOBS = 2
# the processes run_study's workers allow the predictor factories it calls (None: TRAINING_JOBS)
_WORKERS: ContextVar[int | None] = ContextVar("mkm_study_workers", default=None)


@dataclass
class Predictor:
    """A model in the study: display label, family, how to build it, and its spec for ``auto``
    (JSON understood by :func:`mkm.registry.build_spec`; empty: auto does not use it)."""

    label: str
    family: str
    build: Callable[[], ForceModel]
    spec: str = ""
    cached: bool = False
    #: mapped by the stability study unless the study names its own methods
    stability: bool = False


def registry_predictor(label: str, spec: str, cached: bool = False) -> Predictor:
    """A study predictor from a registry spec (``axisym:mesh=coarse``); ``auto`` may use it."""
    parsed = parse_spec(spec)
    return Predictor(label, parsed.entry.family, parsed.build, parsed.text, cached)


def physics_predictors() -> list[Predictor]:
    """The study variants of every physics model in the registry (Equation 2 on both
    diameters, thick-wall, the FE model at every mesh level, the FE model with a sliding braid:
    another physical assumption than the reference's bonded braid, shown but never a candidate
    of ``auto``)."""
    out = []
    for known in ladder.MODELS.entries():
        for variant in known.study:
            parsed = parse_spec(variant.spec)
            out.append(Predictor(variant.label, known.family, parsed.build,
                                 parsed.text if variant.auto_candidate else "", known.expensive,
                                 variant.stability))
    return out


# The study's surrogates unless asked for more: the default kind, the physics ridge and the
# paper's best net. The generic GP (about 2.5 min of training cold on two cores) and the paper's
# 54 Table 2 nets (about 10 min) are dominated on the front; `mkm study --surrogates all` adds them.
STUDY_SURROGATES = kind_registry.study_default()
# the surrogates whose failures the stability study maps: the physics ridge and the paper's net
# (the default kind refuses what it was not trained on instead of failing)
STABILITY_SURROGATES = ("physics", "mlp-paper")


def surrogate_kinds(text: str) -> tuple[str, ...]:
    """The kinds named by ``--surrogates``: a comma list of kinds, or ``all`` (every kind, the
    54 paper nets included); a one-line error naming an unknown kind."""
    known = kind_registry.names(include_families=True)
    if text.strip() == "all":
        return tuple(known)
    kinds = tuple(filter(None, list_items(text)))
    unknown = [k for k in kinds if k not in known]
    if unknown or not kinds:
        every = [k.name for k in kind_registry.registered()]  # a family by its pattern
        raise ValueError(f"--surrogates {text!r}: unknown kind {', '.join(unknown) or '(none)'};"
                         f" expected all or a comma list of {', '.join(every)} (see `mkm "
                         "models`)")
    return kinds


def surrogate_predictors(dataset=None, cache_dir=DEFAULT_CACHE_DIR, n_jobs: int | None = None,
                         kinds=STUDY_SURROGATES) -> list[Predictor]:
    """The surrogate ``kinds`` trained on ``dataset`` (default: the shipped one); the default
    kind is the one ``auto`` may use. Kinds not yet in ``cache_dir`` are trained first,
    ``n_jobs`` at a time (None: the workers :func:`run_study` was given, else
    :data:`TRAINING_JOBS`)."""
    BEST = kind_registry.BEST
    from mkm.surrogate.training_data import DEFAULT_DATASET

    dataset = dataset or DEFAULT_DATASET
    if cache_dir is not None:
        train_surrogates(kinds, dataset, cache_dir, n_jobs or _WORKERS.get() or TRAINING_JOBS)
    # the default kind fitted on the whole design is the default surrogate itself (its
    # muscle-held-out refits only add metrics, which the study does not read): auto's spec
    out = [Predictor(f"surrogate-{BEST}", "surrogate",
                     lambda: trained_surrogate(BEST, dataset, cache_dir), "surrogate")
           ] if BEST in kinds else []
    for kind in (kind for kind in kinds if kind != BEST):
        family = ("surrogate" if not kind.startswith("net-") else
                  "paper net, standardised force" if kind.endswith("standardised")
                  else "paper net")
        out.append(Predictor(f"surrogate-{kind}", family,
                             lambda kind=kind: trained_surrogate(kind, dataset, cache_dir),
                             stability=kind in STABILITY_SURROGATES))
    return out


def trained_surrogate(kind: str, dataset, cache_dir=DEFAULT_CACHE_DIR) -> ForceModel:
    """Surrogate ``kind`` fitted once on the whole ``dataset`` (no split metrics: the study
    scores on its own muscles), from the surrogate package's one cache unless ``cache_dir`` is
    None (no cache). One BLAS thread: on two shared cores threaded BLAS in two processes made
    training several times slower."""
    from threadpoolctl import threadpool_limits

    from mkm.surrogate.train import cached_model, train_surrogate

    with threadpool_limits(1), warnings.catch_warnings():
        warnings.simplefilter("ignore")  # ConvergenceWarning of the paper's nets: reproduced
        if cache_dir is None:
            return train_surrogate(kind, dataset, splits=0)
        return cached_model(kind, dataset, splits=0)


def train_surrogates(kinds, dataset, cache_dir, n_jobs: int = TRAINING_JOBS) -> None:
    """Train the ``kinds`` not yet cached, ``n_jobs`` processes at a time (1: in this one; a
    progress bar per kind while :func:`run_study` shows progress: cold, this is minutes)."""
    from joblib import Parallel, delayed

    jobs = Parallel(n_jobs=n_jobs, return_as="generator_unordered")(
        delayed(trained_surrogate)(kind, dataset, cache_dir) for kind in kinds)
    # the command's name leads a status line (mkm study: 1/3 trained surrogates, ...)
    with progress_bar(len(kinds), "study", _SHOW_PROGRESS.get(),
                      unit="trained surrogate") as bar:
        for _ in jobs:
            bar.update(1)


@dataclass
class StudyConfig:
    """What the study measures; the defaults are the study of the README."""

    muscles: tuple = STUDY_MUSCLES
    pressures: tuple = STUDY_PRESSURES
    # called with the cache folder (None: no cache), where the study keeps trained surrogates
    predictors: Callable[[Path | str | None], list[Predictor]] = field(
        default=lambda cache_dir: physics_predictors() + surrogate_predictors(
            cache_dir=cache_dir))

    @classmethod
    def with_surrogates(cls, kinds) -> StudyConfig:
        """The default study with the surrogate ``kinds`` (see :func:`surrogate_kinds`)."""
        return cls(predictors=lambda cache_dir: physics_predictors() + surrogate_predictors(
            cache_dir=cache_dir, kinds=tuple(kinds)))
    reference: str = "axisym-fine"
    #: the predictors whose failures are mapped; None: every predictor marked ``stability``
    stability_methods: tuple | None = None
    stability_muscles: tuple = STABILITY_MUSCLES
    stability_pressures: tuple = STABILITY_PRESSURES
    stability_eps: tuple = STABILITY_EPS
    timing_muscle: str = "I"


def stability_methods(config: StudyConfig, predictors: list[Predictor]) -> tuple[str, ...]:
    """The labels the stability study maps: the config's own, else every predictor marked
    ``stability`` (the registry's study variants say which)."""
    if config.stability_methods is not None:
        return tuple(config.stability_methods)
    return tuple(p.label for p in predictors if p.stability)


def machine_name() -> str:
    """CPU model, cores and Python, so timings are read against the machine that made them."""
    cpu = platform.processor() or platform.machine()
    try:
        cpuinfo = Path("/proc/cpuinfo").read_text(encoding="utf-8", errors="replace")
        for line in cpuinfo.splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    import os

    return f"{cpu}, {os.cpu_count()} cores, Python {platform.python_version()}"


def _predict(p: Predictor, model: ForceModel, muscle, pressures, cache_dir):
    args = (np.asarray(pressures, float), muscle[1], muscle[2], muscle[3])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # out-of-domain is recorded per point, not shouted
        if p.cached:
            return cached_predict(model, *args, cache_dir=cache_dir)
        return model.predict(*args), False


def measure_errors(config: StudyConfig, predictors: list[Predictor],
                   models: dict[str, ForceModel], cache_dir,
                   bar=None) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Point-by-point errors of every predictor against the reference, and its timing rows
    (``bar``: a progress bar advanced once per predictor)."""
    by_label = {p.label: p for p in predictors}
    if config.reference not in by_label:
        raise ValueError(f"reference {config.reference!r} is not among the predictors: "
                         f"expected one of {', '.join(by_label)}")
    reference = {m[0]: _predict(by_label[config.reference], models[config.reference], m,
                                config.pressures, cache_dir)[0] for m in config.muscles}
    rows, timings = [], []
    for p in predictors:
        model = models[p.label]
        for muscle in config.muscles:
            if p.label == config.reference:
                pred, cached = reference[muscle[0]], True
            else:
                pred, cached = _predict(p, model, muscle, config.pressures, cache_dir)
            rows.append(_error_rows(p, pred, reference[muscle[0]], muscle))
            if not cached:
                timings.append({"predictor": p.label, "muscle": muscle[0],
                                "seconds_per_point": pred.seconds / pred.force_N.size})
        if p.cached:  # time the FE afresh on one muscle: the cache holds old timings
            muscle = next(m for m in config.muscles if m[0] == config.timing_muscle)
            pred = model.predict(np.asarray(config.pressures, float), *muscle[1:4])
            timings.append({"predictor": p.label, "muscle": muscle[0],
                            "seconds_per_point": pred.seconds / pred.force_N.size})
        if bar is not None:
            bar.update(1)
    return pd.concat(rows, ignore_index=True), pd.DataFrame(timings)


def _error_rows(p: Predictor, pred: Prediction, ref: Prediction, muscle) -> pd.DataFrame:
    ok_ref = np.ravel(ref.valid)
    scale = np.nanmax(np.where(ok_ref, np.ravel(ref.force_N), np.nan))
    valid = np.ravel(pred.valid)
    force = np.where(valid, np.ravel(pred.force_N), np.nan)
    err = (equation7_err_pct(np.ravel(ref.force_N), force, scale) if np.isfinite(scale)
           else np.full(force.shape, np.nan))
    return pd.DataFrame({
        "predictor": p.label, "family": p.family, "spec": p.spec, "muscle": muscle[0],
        "role": muscle[4], "D0_mm": muscle[1], "t0_mm": muscle[2], "eps": muscle[3],
        "pressure_bar": np.ravel(pred.pressure_bar),
        "force_ref_N": np.where(ok_ref, np.ravel(ref.force_N), np.nan), "force_N": force,
        "valid": valid, "err_pct": np.where(ok_ref, err, np.nan),
    })


def summarise(errors: pd.DataFrame, timings: pd.DataFrame, reference: str) -> pd.DataFrame:
    """One row per predictor: seconds per force, largest |Err%| (all, test, held-out), RMSE,
    valid share, and whether it is on the Pareto front."""
    speed = timings.groupby("predictor")["seconds_per_point"].median()
    rows = []
    for label, g in errors.groupby("predictor", sort=False):
        scored = g[g["force_ref_N"].notna()]
        ok = scored[scored["valid"]]
        errors_of = error_summary(scored["force_ref_N"], scored["force_N"], scored["valid"],
                                  scored["err_pct"])
        rows.append({
            "predictor": label, "family": g["family"].iloc[0],
            "seconds_per_point": float(speed.get(label, np.nan)),
            "max_abs_err_pct": errors_of["max_abs_err_pct"] if label != reference else 0.0,
            "max_abs_err_pct_test": ok.loc[ok["role"] == "test", "err_pct"].abs().max(),
            "max_abs_err_pct_held_out": ok.loc[ok["role"] != "test", "err_pct"].abs().max(),
            "rmse_N": errors_of["rmse_N"],
            "valid_share": errors_of["valid_points"] / max(len(scored), 1),
        })
    summary = pd.DataFrame(rows)
    # A predictor invalid somewhere in the study cannot answer every scene: not on the front.
    complete = summary["valid_share"] >= 1.0
    summary["pareto"] = complete & pareto_front(summary["seconds_per_point"].to_numpy(),
                                                summary["max_abs_err_pct"].to_numpy())
    return summary


def stability_cells(p: Predictor, model: ForceModel, config: StudyConfig,
                    cache_dir) -> pd.DataFrame:
    """Status of every (muscle, eps, pressure) point of the stability grid for one method."""
    frames = []
    P = np.asarray(config.stability_pressures, float)
    for name, D0, t0 in config.stability_muscles:
        for e in config.stability_eps:
            try:
                pred, _ = _predict(p, model, (name, D0, t0, e), P, cache_dir)
            except ValueError as exc:  # the model refuses the input: its own limit
                frames.append(pd.DataFrame({"method": p.label, "muscle": name, "eps": e,
                                            "pressure_bar": P, "force_N": np.nan,
                                            "status": "invalid (model's own limit)",
                                            "cutbacks": 0, "message": str(exc)}))
                continue
            message = np.ravel(pred.extras.get("failure", np.full(P.size, "")))
            frames.append(pd.DataFrame({"method": p.label, "muscle": name, "eps": e,
                                        "pressure_bar": P, "force_N": np.ravel(pred.force_N),
                                        "status": classify(pred), "message": message,
                                        "cutbacks": np.ravel(pred.extras.get(
                                            "cutbacks", np.zeros(P.size))).astype(int)}))
    return pd.concat(frames, ignore_index=True)


def write_model_errors(errors: pd.DataFrame, timings: pd.DataFrame, path: Path,
                       info: dict) -> Path:
    """The table ``auto`` reads: one row per predictor usable by auto, muscle and pressure.

    A plain CSV (no comment lines) and its metadata as a JSON sidecar (``.json`` beside it):
    what the numbers are, the machine that timed them and the provenance.
    """
    speed = timings.groupby("predictor")["seconds_per_point"].median()
    table = errors[errors["spec"] != ""].copy()
    table["seconds_per_point"] = table["predictor"].map(speed)
    write_atomic(path, table.to_csv(index=False, float_format="%.6g", lineterminator="\n"))
    write_json_atomic(path.with_suffix(".json"), {
        "description": "Model errors measured by `mkm study`: Err% (Equation 7 of Antonelli et "
                       "al., Actuators 2025, 14(3), 153) of each predictor against the finest "
                       "FE mesh per study muscle and pressure, and seconds per predicted force "
                       "on this machine.", **info})
    read_model_errors.cache_clear()
    return path


def solve_fe_sweeps(config: StudyConfig, predictors: list[Predictor],
                    models: dict[str, ForceModel], cache_dir, progress: bool = False,
                    workers: int | None = None, scheduler: str | None = None) -> None:
    """Every FE sweep of the study (the cached predictors on the study muscles, and on the
    stability grid) missing from the prediction cache, solved as one batch on the FE batch
    runner; :func:`measure_errors` and :func:`stability_cells` then read them from the cache."""
    P = np.asarray(config.pressures, float)
    requests = [(models[p.label], P, *m[1:4]) for p in predictors if p.cached
                for m in config.muscles]
    P_map = np.asarray(config.stability_pressures, float)
    requests += [(models[p.label], P_map, D0, t0, e) for p in predictors
                 if p.cached and p.label in stability_methods(config, predictors)
                 for _, D0, t0 in config.stability_muscles for e in config.stability_eps]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # out-of-domain is recorded per point, not shouted
        predict_many(requests, cache_dir, workers=workers, scheduler=scheduler,
                     progress=progress, desc="study FE sweeps")


def run_study(out_dir=None, config: StudyConfig | None = None,
              cache_dir: Path | str | None = DEFAULT_CACHE_DIR, update_shipped: bool = False,
              progress: bool = False, workers: int | None = None,
              scheduler: str | None = None, notify=lambda line: None) -> Path:
    """Run the study; write figures, CSVs, ``study.html`` and the error table for ``auto``
    (``model_errors.csv`` with its ``.json`` sidecar) into ``out_dir`` (default
    ``mkm-out/study``) and nowhere else, unless ``update_shipped`` also replaces the shipped
    table :data:`mkm.auto.MODEL_ERRORS_FILE`. Returns the HTML path. The FE sweeps run on
    ``workers`` local processes or the Dask cluster at ``scheduler`` (:func:`solve_fe_sweeps`;
    with a cache only: without one, each is solved where it is used); ``workers`` also bounds
    the processes that train the surrogates (:func:`surrogate_predictors`). ``notify`` receives the
    study's verdict, the page's first lines (:func:`verdict_lines`)."""
    start = time.perf_counter()
    config = config or StudyConfig()
    out = Path(out_dir) if out_dir is not None else default_out("study")
    out.mkdir(parents=True, exist_ok=True)
    machine = machine_name()
    info = {**provenance(), "machine_name": machine, "reference": config.reference,
            # the predictors' angles and rubber: its entries
            "calibration": Calibration.shipped().record(),
            "muscles": [list(m) for m in config.muscles],
            "pressures_bar": list(config.pressures)}
    token, bound = _SHOW_PROGRESS.set(progress), _WORKERS.set(workers)
    try:
        predictors = config.predictors(cache_dir)
    finally:
        _SHOW_PROGRESS.reset(token)
        _WORKERS.reset(bound)
    models = {p.label: p.build() for p in predictors}
    labels = {p.label for p in predictors}
    methods = [m for m in stability_methods(config, predictors) if m in labels]
    if cache_dir is not None:
        solve_fe_sweeps(config, predictors, models, cache_dir, progress, workers, scheduler)
    bar = progress_bar(len(predictors) + len(methods), "study", progress, unit="method")
    errors, timings = measure_errors(config, predictors, models, cache_dir, bar)
    summary = summarise(errors, timings, config.reference)
    info["predictors"] = {p.label: {"params": models[p.label].params(), "spec": p.spec,
                                    "version": model_version(models[p.label]),
                                    **model_origin(models[p.label])}
                          for p in predictors}
    errors.to_csv(out / "study_errors.csv", index=False, float_format="%.6g")
    summary.to_csv(out / "speed_accuracy.csv", index=False, float_format="%.6g")
    figures = [(save_figure(speed_accuracy_figure(summary, machine), out / "speed_accuracy.png"),
                "Seconds per predicted force (log) against the largest |Err%| over the study "
                "muscles (log), against the finest FE mesh; red: the Pareto front.")]

    by_label = {p.label: p for p in predictors}
    cells = []
    for label in methods:
        p = by_label[label]
        frame = stability_cells(p, models[label], config, cache_dir)
        bar.update(1)
        cells.append(frame)
        safe = label.replace("/", "_")
        figures.append((save_figure(stability_figure(frame, label), out / f"stability_{safe}.png"),
                        f"Where {esc(label)} fails over pressure and eps."))
    cells = pd.concat(cells, ignore_index=True) if cells else pd.DataFrame()
    stability = stability_table(cells)
    if not cells.empty:
        cells.to_csv(out / "stability.csv", index=False, float_format="%.6g")
        stability.to_csv(out / "stability_summary.csv", index=False)
    bar.close()
    elapsed = time.perf_counter() - start
    info["study_seconds"] = round(elapsed, 1)
    table = write_model_errors(errors, timings, out / "model_errors.csv", info)
    if update_shipped:
        write_model_errors(errors, timings, MODEL_ERRORS_FILE, info)
    write_json_atomic(out / "provenance.json", info)
    body = (f"<p>Measured on {esc(machine)}; {esc(info['date_utc'])}; study time {elapsed:.0f} s "
            f"(FE sweeps cached in {esc(cache_dir)}). Reference: {esc(config.reference)}; "
            f"{len(config.muscles)} study muscles x {len(config.pressures)} pressures. Error: "
            "the paper's Equation 7 over each muscle's sweep, in %.</p>"
            f"<p><b>Pareto front</b> (fastest first): {esc(pareto_text(summary))}.</p>"
            + figure_html(*figures[0])
            + table_html(readable_summary(summary), "The named predictors and every one on the "
                         "Pareto front; all of them are in speed_accuracy.csv. Provenance: "
                         "below.", digits=3)
            + "<h2>Where methods fail</h2>"
            + "".join(figure_html(path, caption) for path, caption in figures[1:])
            + (table_html(stability, "Stability per method and muscle (stability_summary.csv)")
               if not stability.empty else "")
            + provenance_details(info, "provenance.json",
                                 f"the error table for auto: {table.name} (+ .json)"))
    path = out / "study.html"
    path.write_text(html_page("Speed against accuracy, and where methods fail", body),
                    encoding="utf-8")
    for line in verdict_lines(summary, config.reference,
                              specs={p.label: p.spec for p in predictors}):
        notify(line)
    return path


def verdict_lines(summary: pd.DataFrame, reference: str,
                  tolerance: float = DEFAULT_TOLERANCE,
                  specs: dict[str, str] | None = None) -> list[str]:
    """What the study tells a user first: the fastest predictor within ``tolerance`` (auto's
    default) of the reference on every study muscle, valid at every point, with the spec that
    asks for it (``specs``: predictor -> spec, where it has one), and the Pareto front."""
    within = summary[(summary["valid_share"] >= 1.0)
                     & (summary["max_abs_err_pct"] <= 100 * tolerance)]
    best = within.sort_values("seconds_per_point").iloc[0]
    spec = (specs or {}).get(best["predictor"])
    # the study's names are no spec: what --model takes is said with it
    asked = f"--model {spec}, " if spec and spec != best["predictor"] else ""
    return [f"the fastest predictor within {100 * tolerance:g} % of {reference} on every study "
            f"muscle: {best['predictor']} ({asked}"
            f"{format_seconds(best['seconds_per_point'])} per force, largest |Err%| "
            f"{best['max_abs_err_pct']:.3g} %)",
            f"Pareto front (fastest first): {pareto_text(summary)}"]


def pareto_text(summary: pd.DataFrame) -> str:
    """The front in words: each member with its cost and largest error."""
    front = summary[summary["pareto"]].sort_values("seconds_per_point")
    return "; ".join(f"{row.predictor} ({format_seconds(row.seconds_per_point)} per force, "
                     f"largest |Err%| {row.max_abs_err_pct:.3g} %)" for row in front.itertuples())


def readable_summary(summary: pd.DataFrame) -> pd.DataFrame:
    """The summary for people: named predictors and the front, plain column names."""
    nets = summary["family"].str.startswith("paper net")
    rows = summary[~nets | summary["pareto"]].sort_values("seconds_per_point")
    return pd.DataFrame({
        "predictor": rows["predictor"], "family": rows["family"],
        "s per force": rows["seconds_per_point"].map(lambda v: f"{v:.2g}"),
        "largest |Err%|": rows["max_abs_err_pct"],
        "test I-III": rows["max_abs_err_pct_test"],
        "held-out": rows["max_abs_err_pct_held_out"], "RMSE [N]": rows["rmse_N"],
        "valid [%]": 100 * rows["valid_share"], "Pareto": rows["pareto"].map({True: "yes",
                                                                            False: ""}),
    })


def stability_table(cells: pd.DataFrame) -> pd.DataFrame:
    """Per method and muscle: points per status, the smallest eps where something fails, and
    the Newton cut-backs the converged points needed."""
    if cells.empty:
        return pd.DataFrame()
    rows = []
    for (method, muscle), g in cells.groupby(["method", "muscle"], sort=False):
        counts = g["status"].value_counts()
        failed = g[g["status"] != "ok"]
        row = {"method": method, "muscle": muscle, "points": len(g)}
        row.update({status: int(n) for status, n in counts.items()})
        row["first failing eps [%]"] = (100 * failed["eps"].min()) if len(failed) else np.nan
        solved = ~g["status"].isin(("not converged", *PHYSICAL_LIMITS))
        row["cut-backs (converged points)"] = int(g.loc[solved, "cutbacks"].sum())
        reasons = failed["message"].fillna("").astype(str)
        row["failure reasons"] = "; ".join(sorted(set(reasons[reasons != ""]))) or ""
        rows.append(row)
    table = pd.DataFrame(rows)
    statuses = [c for c in table.columns if c in set(cells["status"])]
    table[statuses] = table[statuses].fillna(0).astype(int)
    return table
