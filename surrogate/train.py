"""Training surrogates and the one surrogate cache.

Every trained surrogate carries its metrics: errors over repeated splits that hold out whole
muscles (the same splits for every kind) and, when the FE reference exists and the surrogate
covers its muscles, its errors on the test muscles. Fits run on one BLAS thread, so results do
not depend on the machine's thread count (and ~100 rows gain nothing from threads).
"""

from __future__ import annotations

import hashlib
import json
import warnings
from contextlib import nullcontext
from pathlib import Path

from threadpoolctl import threadpool_limits

from mkm.core.durations import timed
from mkm.core.home import user_cache
from mkm.core.records import file_sha256, package_file, provenance
from mkm.surrogate.coverage import coverage
from mkm.surrogate.gp import kernels_path
from mkm.surrogate.kinds import BEST, entry, make_estimator, named
from mkm.surrogate.model import OutOfDomainWarning, SurrogateForceModel
from mkm.surrogate.quiet import quiet_fits
from mkm.surrogate.training_data import (
    DEFAULT_DATASET,
    STD_CALIBRATION_SET,
    STD_HOLDOUT_SET,
    load_training_data,
)
from mkm.surrogate.validation import (
    MUSCLE_SPLITS,
    fit_params,
    muscle_split_scores,
    predict_with_std,
    std_coverage,
)


def kind_files(kind: str) -> tuple[Path, Path, Path]:
    """The dataset ``kind`` trains on when none is given, and the random muscles that calibrate
    and rescale its std (its registry entry's, :class:`mkm.surrogate.kinds.Kind`; the default
    surrogate's when it names none)."""
    found = entry(kind)
    dataset = (package_file("mkm.surrogate", "data", found.dataset) if found.dataset
               else DEFAULT_DATASET)
    if found.std_sets is None:
        return dataset, STD_CALIBRATION_SET, STD_HOLDOUT_SET
    return (dataset, *(package_file("mkm.surrogate", "data", name) for name in found.std_sets))


def std_sets(kind: str, dataset) -> tuple[Path, Path]:
    """The random muscles that calibrate and rescale the std of ``kind`` trained on ``dataset``
    (None: its own): its own sets on its own dataset, the default surrogate's on any other (the
    sets belong with the muscles the dataset covers)."""
    own, calibration, holdout = kind_files(kind)
    if dataset is None or Path(dataset) == own:
        return calibration, holdout
    return STD_CALIBRATION_SET, STD_HOLDOUT_SET


def kind_splits(kind: str, splits: int | None) -> int:
    """``splits``, or when None the kind's own number of muscle-held-out refits."""
    if splits is not None:
        if isinstance(splits, bool) or int(splits) != splits or splits < 0:
            raise ValueError(f"splits={splits!r} is invalid: expected a whole number of "
                             "muscle-held-out splits >= 0 (0: none)")
        return int(splits)
    own = entry(kind).splits
    return MUSCLE_SPLITS if own is None else own


def train_surrogate(kind: str = "best", dataset=None, splits: int | None = None,
                    random_state: int = 0, progress: bool = False) -> SurrogateForceModel:
    """Fit ``kind`` on the whole dataset (None: the kind's, :func:`kind_files`); metrics from
    refits on ``splits`` muscle-held-out splits (0: none; None: the kind's number).
    ``progress``: a progress bar on stderr over the fits."""
    resolved = named(kind)
    own_dataset = kind_files(resolved)[0]
    splits = kind_splits(resolved, splits)
    data, estimator, calibration, holdout, post_fit = _training_setup(resolved, dataset,
                                                                      random_state)
    bar = _bar(splits + 1, f"train {resolved}", progress)
    with quiet_fits(), threadpool_limits(limits=1), bar:
        # the shipped refits are those of random_state 0 on the kind's own dataset
        shipped = (shipped_held_out(resolved, own_dataset if dataset is None else dataset,
                                    splits) if splits and random_state == 0 else None)
        if shipped:
            bar.update(splits)
        held_out = shipped or (_held_out(estimator, data, splits, post_fit, progress=bar.update)
                               if splits else None)
        estimator.fit(data.X, data.y, **fit_params(estimator, data.threshold_pressure_bar))
        if post_fit is not None:
            post_fit(estimator)
        bar.update()
    metrics = {"muscle_held_out": None if held_out is None else held_out["summary"],
               "splits": splits, "split_method": "GroupShuffleSplit(test_size=0.2, "
               "random_state=0), one group per FE sweep (muscle)"}
    if shipped:
        metrics["muscle_held_out_from"] = {"path": HELD_OUT_FILE.name,
                                           "sha256": file_sha256(HELD_OUT_FILE),
                                           "computed": shipped["provenance"]}
    metadata = {"kind_requested": kind, "random_state": random_state,
                "dataset": data.summary(), "metrics": metrics, "trained": provenance()}
    if getattr(estimator, "kernels_reused_", 0):
        metadata["gp_kernels_from"] = {
            "path": KERNELS_PATH.name, "sha256": file_sha256(KERNELS_PATH),
            "processes": int(estimator.kernels_reused_),
            "why": "the processes' hyperparameters optimised on these same points "
                   "(tools/record_gp_kernels.py), fitted at them without the search"}
    if calibration is not None:
        # what the calibration reached on its own muscles (the errors are not normal: not 68 / 95 %)
        force, std = predict_with_std(estimator, calibration.X)
        metadata["std_calibration"] = {
            "path": calibration.path, "sha256": calibration.sha256,
            "n_muscles": calibration.n_muscles, "seeds": calibration.provenance.get("seeds"),
            "std_scale": float(estimator.std_scale_), "std_power": float(estimator.std_power_),
            "std_reference": float(estimator.std_reference_),
            "within_1std": coverage(calibration.y - force, std, 1.0),
            "within_2std": coverage(calibration.y - force, std, 2.0)}
    if calibration is not None and holdout is not None:
        metadata["std_rescale"] = {
            "factor": float(estimator.std_rescale_),
            "shortening_power": float(estimator.std_rescale_power_),
            "angle_power": float(estimator.std_rescale_angle_power_),
            "path": holdout.path,
            "sha256": holdout.sha256, "n_muscles": holdout.n_muscles,
            "seeds": holdout.provenance.get("seeds"),
            "command": holdout.provenance.get("command"),
            "method": "factor * (k_A eps / 0.1)^shortening_power * (theta0 / 30 deg)^angle_power "
                      "times the whole std, the one whose 1/2/3 std bands hold closest to "
                      "68.27/95.45/99.73 % of the held-out errors, over all of them and in each "
                      "third by braid angle (largest miss smallest)",
            **std_coverage(estimator, holdout.X, holdout.y)}
    model = SurrogateForceModel(estimator, resolved, data.inputs, data.fixed, data.box,
                                metadata, data_file=Path(own_dataset if dataset is None
                                                         else dataset).resolve())
    metrics["test_muscles"] = _test_muscle_metrics(model)
    return model


def _training_setup(resolved: str, dataset, random_state: int = 0):
    """The training data of ``resolved`` on ``dataset`` (None: its own), its unfitted estimator,
    the random muscles that calibrate and rescale its std, and the step that applies them to a
    fitted model (None when it has no std to scale)."""
    own_dataset = kind_files(resolved)[0]
    calibration_path, holdout_path = std_sets(resolved, dataset)
    missing = [p for p in (calibration_path, holdout_path) if not p.is_file()]
    if entry(resolved).std_sets is not None and missing and dataset in (None, own_dataset):
        raise ValueError(f"surrogate kind {resolved!r} calibrates its std on {missing[0]}, "
                         "which is missing: expected the file shipped with the package "
                         "(reinstall it)")
    data = load_training_data(own_dataset if dataset is None else dataset)
    estimator = make_estimator(resolved, data.inputs, data.fixed, random_state=random_state)
    calibration = std_calibration_set(estimator, data, calibration_path)
    holdout = std_calibration_set(estimator, data, holdout_path)

    def post_fit(model):
        model.calibrate_std(calibration.X, calibration.y)
        if holdout is not None:
            model.rescale_std(holdout.X, holdout.y)

    return data, estimator, calibration, holdout, (None if calibration is None else post_fit)


def _held_out(estimator, data, splits, post_fit, progress=None, only=None) -> dict:
    """The muscle-held-out refits of training (scored inside the box's pressures)."""
    in_box = (data.X[:, 0] >= data.box["pressure_bar"][0]) & (
        data.X[:, 0] <= data.box["pressure_bar"][1])
    return muscle_split_scores(estimator, data.X, data.y, data.groups,
                               data.threshold_pressure_bar, splits, scored=in_box,
                               post_fit=post_fit, progress=progress, only=only)


# The default surrogate's muscle-held-out refits (most of its training time), computed once and
# shipped as JSON; training reuses them while their key matches what they depend on
# (benchmarks/bench_held_out.py writes the file; tests/surrogate/test_held_out.py refits a split
# and compares).
HELD_OUT_FILE = package_file("mkm.surrogate", "data", "muscle_held_out.json")
KERNELS_PATH = kernels_path()


def held_out_key(kind: str, dataset, splits: int, versions: dict | None = None) -> str:
    """What the held-out refits of ``kind`` on ``dataset`` depend on: the surrogate's cache key
    (data, kind, splits, libraries, model code, std sets) and the training code. ``versions``:
    the libraries' (None: those installed)."""
    from mkm.core.records import source_version

    parts = {"cache_key": cache_key(Path(dataset), kind, splits, versions),
             "training_code": source_version("mkm.surrogate.train")}
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()[:16]


def compute_held_out(kind: str = BEST, splits: int | None = None, only=None) -> dict:
    """The muscle-held-out refits of ``kind`` on its own dataset as :func:`train_surrogate`
    computes them, with the key and provenance :data:`HELD_OUT_FILE` records. ``only``: the
    indices of the splits to refit (the summary then covers those only)."""
    splits = kind_splits(kind, splits)
    data, estimator, _, _, post_fit = _training_setup(kind, None)
    with quiet_fits(), threadpool_limits(limits=1):
        held_out = _held_out(estimator, data, splits, post_fit, only=only)
    dataset = kind_files(kind)[0]
    return {"kind": kind, "splits_n": splits, "key": held_out_key(kind, dataset, splits),
            "dataset": dataset.name, "dataset_sha256": file_sha256(dataset),
            "provenance": provenance(), "splits": held_out["splits"],
            "summary": held_out["summary"]}


def shipped_held_out(kind: str, dataset, splits: int) -> dict | None:
    """The shipped held-out refits (:data:`HELD_OUT_FILE`) when they are those of ``kind`` on
    ``dataset`` with ``splits`` and today's code and libraries; None otherwise (refit)."""
    if not HELD_OUT_FILE.is_file():
        return None
    shipped = json.loads(HELD_OUT_FILE.read_text(encoding="utf-8"))
    if (shipped.get("kind") != kind or shipped.get("splits_n") != splits
            or shipped.get("key") != held_out_key(kind, dataset, splits)):
        return None
    return shipped


def std_calibration_set(estimator, data, path=STD_CALIBRATION_SET):
    """The shipped random muscles at ``path`` that scale the std of ``estimator`` (the
    calibration set, or the held-out set :data:`STD_HOLDOUT_SET`; ``None`` when it has no std
    to scale, or is trained on other inputs: a surrogate of one length, angle and rubber keeps
    the scale of its own training muscles)."""

    if not hasattr(estimator, "calibrate_std") or not path.is_file():
        return None
    calibration = load_training_data(path)
    return calibration if calibration.inputs == data.inputs else None


def _bar(total: int, desc: str, progress: bool):
    import sys

    from tqdm import tqdm

    return tqdm(total=total, desc=desc, unit="fit", file=sys.stderr,
                disable=not (progress and sys.stderr.isatty()))


def _test_muscle_metrics(model: SurrogateForceModel):
    """Errors on the FE reference of the test muscles, at the reference's muscle parameters,
    over the points the surrogate answers (``valid_points`` counts them: a box that leaves
    some out is recorded here, not warned about, for nobody asked to predict them); the reason
    instead when the surrogate does not cover them."""
    from mkm.surrogate.testset import FE_REFERENCE, compare_on_test_muscles, read_fe_reference

    if not FE_REFERENCE.is_file():
        return None
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", OutOfDomainWarning)
            _, summary = compare_on_test_muscles(model, read_fe_reference())
    except ValueError as exc:
        return {"not_evaluated": str(exc)}
    return summary.drop(columns=["model"]).to_dict(orient="records")


def cache_key(dataset=DEFAULT_DATASET, kind: str = BEST, splits: int = MUSCLE_SPLITS,
              versions: dict | None = None) -> str:
    """Hash of what a trained surrogate depends on: the data, the kind, the splits, the source
    of the surrogate and of every physics module it calls (calibration included), libraries
    (``versions``; None: those installed), and the random muscles that scale its std."""
    from mkm.surrogate.io import code_version

    parts = {"dataset": file_sha256(dataset), "kind": kind, "splits": splits,
             "versions": provenance()["versions"] if versions is None else versions,
             "code": code_version(kind),
             "gp_kernels": file_sha256(KERNELS_PATH) if KERNELS_PATH.is_file() else None,
             "std_sets": [file_sha256(p) for p in std_sets(named(kind),
                                                           dataset) if p.is_file()]}
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()[:16]


def default_cache_dir() -> Path:
    """Folder of the trained models in the user's cache (:func:`mkm.core.home.user_cache`)."""
    return user_cache("surrogate")


def training_task(kind: str, dataset=None) -> str:
    """The name under which :mod:`mkm.core.durations` keeps how long training ``kind`` on
    ``dataset`` (None: the kind's own, :func:`kind_files`) took."""
    kind = named(kind)
    if dataset is None:
        dataset = kind_files(kind)[0]
    return f"surrogate-training-{kind}-{Path(dataset).stem}"


def _cache_folder(kind, dataset, cache_dir, splits) -> tuple[Path, Path, int]:
    """The cache folder of ``kind`` on ``dataset`` (None: the kind's), the dataset and the
    splits resolved; ``best`` and the kind it names share one folder (one model, trained once)."""
    resolved = named(kind)
    dataset = kind_files(resolved)[0] if dataset is None else Path(dataset)
    splits = kind_splits(resolved, splits)
    cache_dir = Path(cache_dir) if cache_dir is not None else default_cache_dir()
    return cache_dir / f"{resolved}-{cache_key(dataset, resolved, splits)}", dataset, splits


def is_cached(kind: str = "best", dataset=None, cache_dir=None,
              splits: int | None = None) -> bool:
    """Whether :func:`cached_model` would load ``kind`` rather than train it (callers name the
    training phase before it starts)."""
    return (_cache_folder(kind, dataset, cache_dir, splits)[0] / "metadata.json").is_file()


def cached_model(kind: str = "best", dataset=None, cache_dir=None,
                 splits: int | None = None, progress: bool = False) -> SurrogateForceModel:
    """Surrogate ``kind`` trained on ``dataset``, as a fitted ForceModel: the one surrogate cache.

    Trained on first use and kept under ``cache_dir`` (default: the user's cache folder) as
    ``<kind>-<key>`` (:func:`cache_key`), so a fresh install needs no manual step and a changed
    dataset, code or library retrains it. Processes that ask at once wait for each other on a
    lock file (portable: ``filelock``): one trains and saves, the others load its model.
    """
    from filelock import FileLock

    from mkm.surrogate.io import UncheckedDataWarning, load_model, save_model

    directory, dataset, splits = _cache_folder(kind, dataset, cache_dir, splits)
    if not dataset.is_file():
        load_training_data(dataset)  # raises the ValueError that says what is missing
    directory.parent.mkdir(parents=True, exist_ok=True)
    with FileLock(str(directory) + ".lock"):
        if (directory / "metadata.json").is_file():
            with warnings.catch_warnings():
                warnings.simplefilter("error")  # a stale cache entry is retrained, never trusted
                # its folder's name holds the data's sha256 (cache_key): checked already
                warnings.simplefilter("ignore", UncheckedDataWarning)
                try:
                    model = load_model(directory)
                except (Warning, ValueError):
                    pass
                else:  # the data is the one this process hashed for the key, not the trainer's
                    model.data_file = dataset.resolve()
                    return model
        with timed(training_task(kind, dataset)):  # the next first-use promise is this machine's
            model = train_surrogate(kind, dataset, splits=splits, progress=progress)
        # its folder's name holds the data's sha256; a path from the user's cache to the data
        # would name the folders of this machine
        save_model(model, directory, lock=nullcontext(), locate_data=False)  # lock held
    return model


def default_model(dataset=None, cache_dir=None, progress: bool = False,
                  **parameters) -> SurrogateForceModel:
    """The default (``best``) surrogate trained on ``dataset`` (see :func:`cached_model`), for
    the muscle ``parameters`` (``L0_mm``, ``theta0_deg``, ``C10_MPa``, ``C01_MPa``);
    ``progress``: a bar on stderr while it trains (first use only)."""
    model = cached_model("best", dataset, cache_dir, progress=progress)
    return model.with_parameters(**parameters) if parameters else model
