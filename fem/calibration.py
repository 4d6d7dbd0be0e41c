"""theta0 calibration: the braid angle at rest is not published, so each model fits it.

A calibration file (JSON) maps a model's calibration key (``"eq2-inner"``, ``"thickwall"``,
``"axisym"``) to its fitted ``theta0_deg`` with the target, reference, residuals, command, date
and code version of the fit. A :class:`Calibration` is such a file, read and checked once: the
shipped ``fem/calibration.json`` (:meth:`Calibration.shipped`) is every model's default, and a
command given another file (a bench prototype's fit, ``--calibration FILE``) loads it with
:meth:`Calibration.load` and hands it to the models it builds (their ``calibration``
parameter); the shipped one is never touched. Only theta0 is fitted here; everything else in
the physics stays as measured or published.

Targets (:func:`fit_theta0`):

``force``
    Least squares on every reference force. Right for Equation 2, which like the paper's FE
    forces of muscle I goes through the origin.
``slope``
    The model's dF/dP above its own threshold pressure equals the reference's dF/dP above the
    reference's threshold. The slope is what the braid geometry fixes and what transfers from
    one muscle to another; the threshold is physics the wall models compute and the paper's
    muscle I does not show (its forces are proportional to P from 0 bar, which no wall can do).
    A force fit makes up for the missing threshold by steepening the slope: theta0 comes out
    about 0.9 deg low for axisym. Default for every model with a threshold.
``slope+threshold``
    As ``slope``, and also fits the reference's threshold offset (the pressure by which the
    reference's force line is shifted from the model's) and reports it with the residual of
    the shifted model.

The reference is one table, whatever its source (a CSV, or the settled steps of a bench run
folder, which the application loads): columns ``pressure_bar, D0_mm, t0_mm, eps, force_N``,
optional ``L0_mm`` and ``direction`` (``up``/``down``). When both sweep directions were measured,
the mean of the two branches is fitted at each pressure measured both ways: braid friction lowers
the rising branch and raises the falling one by about the same amount, and the frictionless
models sit between them; the staircase's turning point (measured rising only) is left out, as
it carries the whole friction offset. A run without a down sweep is fitted as it is.
"""

from __future__ import annotations

import json
import os
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from mkm.core.guards import regular_file
from mkm.core.records import (
    file_sha256,
    one_argument,
    package_file,
    provenance,
    source_version,
    write_atomic,
)
from mkm.fem.limits import LIMITS, check_value, limit_text, outside
from mkm.fem.materials import MooneyRivlin, mooney_rivlin

if TYPE_CHECKING:  # imported where used: every model reads a calibration, few fit one
    import pandas as pd

    from mkm.fem.interface import ForceModel

CALIBRATION_FILE = package_file("mkm.fem", "calibration.json")
THETA0_BOUNDS_DEG = (15.0, 50.0)  # practical braids are 20-30 deg; 54.7 deg is the lock angle
#: what a calibration fits, and how (``mkm fem calibrate --target``)
TARGETS = {"slope": "dF/dP above the threshold (default for models with a threshold pressure)",
           "force": "least squares on every force (default for eq2, where both coincide)",
           "slope+threshold": "slope, and report the reference's threshold offset"}
REFERENCE_COLUMNS = ("pressure_bar", "D0_mm", "t0_mm", "eps", "force_N")
MAX_FORCE_N = 1e6  # a reference force beyond this is a typo or a corrupt cell, not a muscle
#: Reference points at or below this share of a sweep's largest force count as "below the
#: reference's threshold" (a held muscle that has not shortened yet, plus sensor noise): they
#: enter the force residuals but not the slope.
THRESHOLD_FLOOR_FRACTION = 0.02


@dataclass(frozen=True, eq=False)
class Calibration:
    """A calibration file's entries, read and checked once (see the module docstring).

    Models take one as their ``calibration`` parameter (None: :meth:`shipped`); the dataset
    builder and the FE batch runner send their workers the resolved angle, so workers never read
    a calibration file of their own.
    """

    path: Path
    entries: Mapping[str, dict]

    @classmethod
    def load(cls, path: str | os.PathLike | None = None) -> Calibration:
        """The calibration in ``path`` (None: the shipped one); a one-line ``ValueError`` for a
        file that is unreadable, not JSON or holds an entry without a finite ``theta0_deg``."""
        path = CALIBRATION_FILE if path is None else Path(path)
        return cls(path, _load(path))

    @classmethod
    def shipped(cls) -> Calibration:
        """The shipped ``fem/calibration.json``."""
        return cls.load(None)

    @property
    def is_shipped(self) -> bool:
        return self.path == CALIBRATION_FILE

    def record(self) -> dict:
        """The file (``shipped fem/calibration.json`` for the shipped one) and its SHA-256: how
        the provenance of what a model computed with it names it."""
        return {"file": "shipped fem/calibration.json" if self.is_shipped else str(self.path),
                "sha256": file_sha256(self.path)}

    def entry(self, key: str) -> dict:
        """Entry ``key`` (for example ``"eq2-inner"``); ``ValueError`` naming the command that
        writes it if there is none (:meth:`missing`)."""
        if key not in self.entries:
            raise ValueError(self.missing(key))
        return self.entries[key]

    def missing(self, key: str, angle: str | None = "--theta0 ") -> str:
        """Why this calibration gives no braid angle to model entry ``key``, and what adds it
        (:meth:`how_to_add`)."""
        return (f"no calibrated theta0 for model {key!r} in {self.path}: "
                + self.how_to_add(key, angle))

    def how_to_add(self, key: str, angle: str | None = "--theta0 ") -> str:
        """What writes entry ``key``: for a muscle ``mkm identify`` identified with another
        model, that identification with this one (fem calibrate would fit the paper's muscle
        into the lab's file); or the angle given as the command takes it, ``angle`` followed
        by the value (None: the command takes none)."""
        identified = next(((k, e) for k, e in self.entries.items() if "identified" in e), None)
        if identified is None:
            return (f"pass {angle}DEG or run `{calibrate_command(key, self.path)}`" if angle
                    else f"run `{calibrate_command(key, self.path)}`")
        other, entry = identified
        rung = key.partition("-")[0]
        command = str(entry.get("command", ""))
        again = re.sub(r"--model \S+", f"--model {rung}", command) if "--model " in command \
            else f"{command} --model {rung}"
        again = re.sub(r"--out (\S+)", lambda m: f"--out {m[1]}-{rung}", again)
        return (f"it holds the muscle identified with {other} (theta0 {entry['theta0_deg']:g} "
                f"deg): identify it with {rung} too (`{again}`) and give that calibration"
                + (f", or pass {angle}{entry['theta0_deg']:g} (the {other} fit's angle; the "
                   "rubber then is not the identified one)" if angle else ""))


#: what a calibration file that cannot be read was expected to be
WANTED = (": expected the calibration.json mkm identify writes or the file of mkm fem calibrate "
          "--out FILE")


@cache
def _read(path: Path, mtime_ns: int) -> dict:
    try:
        # utf-8-sig: a file edited and saved by a Windows editor starts with a BOM
        entries = json.loads(path.read_text(encoding="utf-8-sig"))
    except OSError as exc:
        raise ValueError(f"calibration {path}: cannot read it: {exc.strerror}{WANTED}") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        # a parameters.csv or steps.csv beside calibration.json, handed by mistake
        raise ValueError(f"calibration {path}: not valid JSON ({exc}){WANTED}") from None
    except RecursionError:
        raise ValueError(f"calibration {path}: not valid JSON (nested too deep){WANTED}") \
            from None
    bad = [k for k, v in entries.items() if not isinstance(v, dict) or "theta0_deg" not in v] \
        if isinstance(entries, dict) else ["(the file)"]
    if bad:
        raise ValueError(f"calibration {path}: entry {bad[0]!r} has no theta0_deg: expected a "
                         "file written by `mkm fem calibrate --out FILE`")
    for key, entry in entries.items():
        _check_entry(path, key, entry)
    return entries


# what the models read from an entry: numbers (the rubber, a friction rung's settings) and the
# parameters of the fit
_NUMBERS = ("theta0_deg", "C10_MPa", "C01_MPa", "hysteresis_fraction", "creep_fraction",
            "creep_tau_s")


def _check_entry(path: Path, key: str, entry: dict) -> None:
    for name in _NUMBERS:
        value = entry.get(name)
        if name != "theta0_deg" and value is None:
            continue
        if isinstance(value, bool) or not isinstance(value, int | float) \
                or not -1e300 < value < 1e300:  # not inf, nan or beyond a float
            raise ValueError(f"calibration {path}: entry {key!r} has {name}="
                             f"{str(value)[:40]!r}: expected a finite number")
    if not isinstance(entry.get("model_params", {}), dict):
        raise ValueError(f"calibration {path}: entry {key!r} has model_params="
                         f"{str(entry['model_params'])[:40]!r}: expected a table of parameters")
    if "identified" in entry:
        _check_identified(path, key, entry["identified"])


def _number(value, none: bool = False) -> bool:
    return (value is None and none) or (isinstance(value, int | float)
                                        and not isinstance(value, bool))


def _text(value) -> bool:
    return isinstance(value, str)


def _number_or_null(value) -> bool:
    return _number(value, none=True)


def _muscle(value) -> bool:
    """A run's declared muscle: its id, and numbers."""
    return isinstance(value, dict) and all(_number(x) for k, x in value.items() if k != "id")


def _shift(value) -> bool:
    return isinstance(value, dict) and all(map(_number, value.values()))


def _objects(value, shape) -> bool:
    """Whether ``value`` is a list of objects each of whose ``shape`` keys (name -> check of
    its value) it holds passes its check."""
    return isinstance(value, list) and all(
        isinstance(item, dict) and all(check(item[name]) for name, check in shape.items()
                                       if name in item) for item in value)


def _check_identified(path: Path, key: str, identified) -> None:
    """``ValueError`` in one line unless ``identified`` is an object whose parts have the shape
    ``mkm identify`` records and the report, ``fem solve``'s band and identify's page read (a
    part left out is none: a file written by hand may hold the runs alone): an entry edited by
    hand or otherwise was a traceback where it was read."""
    band = identified.get("band", {}) if isinstance(identified, dict) else None
    n = len(band.get("parameters", [])) if isinstance(band, dict) \
        and isinstance(band.get("parameters"), list) else -1
    checks = {
        ".runs": (_objects(identified.get("runs", []), {"run": _text, "path": _text,
                                                         "muscle": _muscle})
                  and all("run" in r for r in identified.get("runs", [])),
                  "a list of runs, each an object naming its run"),
        ".parameters": (_objects(identified.get("parameters", []), {
            "parameter": _text, "value": _number_or_null, "ci_low": _number_or_null,
            "ci_high": _number_or_null, "status": _text})
            and all({"parameter", "value"} <= p.keys() for p in identified.get("parameters", [])),
            "a list of parameters, each an object naming it and its value"),
        ".interval_method": (_text(identified.get("interval_method", "")), "a text"),
        ".options, .notes, .dropped": (all(isinstance(identified.get(k, []), list)
                                           for k in ("options", "notes", "dropped")), "lists"),
        ".leave_one_run_out": (_objects(identified.get("leave_one_run_out", []), {}),
                               "a list of objects"),
        ".misfit": (isinstance(identified.get("misfit", {}), dict) and _number(
            identified.get("misfit", {}).get("chi2_per_nu"), none=True),
            "an object, its chi2_per_nu a number"),
        ".band": (isinstance(band, dict) and n >= 0
                  and all(map(_text, band["parameters"]))
                  and isinstance(band.get("values"), list) and len(band["values"]) == n
                  and all(_number(x) for x in band["values"])
                  and isinstance(band.get("covariance"), list) and len(band["covariance"]) == n
                  and all(isinstance(row, list) and len(row) == n and all(map(_number, row))
                          for row in band["covariance"])
                  and _objects(band.get("terms", []), {"kind": _text, "shift": _shift})
                  and all({"kind", "shift"} <= t.keys() for t in band.get("terms", []))
                  and all(_number(band.get(k, 0.0)) for k in ("sensitivity_tolerance",
                                                              "misfit_rms_N"))
                  if "band" in identified else True,
                  "an object of parameters, their values and an n x n covariance, and terms"),
    } if isinstance(identified, dict) else {"": (False, "an object")}
    for where, (good, expected) in checks.items():
        if not good:
            raise ValueError(f"calibration {path}: entry {key!r} has identified{where} of "
                             f"another shape: expected {expected}, as mkm identify writes it")


def _load(path: Path) -> dict:
    if path.is_symlink():  # a link may lead anywhere: refused, never quoted
        regular_file(path, "calibration ")
    try:
        mtime = path.stat().st_mtime_ns
    except OSError as exc:
        raise ValueError(f"calibration {path}: cannot read it: {exc.strerror}{WANTED}") from None
    return _read(path, mtime)


def calibrate_command(key: str, path) -> str:
    """The command that writes entry ``key`` (``eq2-braid``: a rung and the value of one of its
    text parameters, which the command takes as the option of the same name) into the
    calibration file ``path``."""
    from mkm.fem.ladder import entry

    rung, _, variant = key.partition("-")
    option = "".join(f" --{name} {variant}"
                     for name, parameter in (entry(rung).parameters.items() if variant else ())
                     if variant in parameter.options())
    return f"mkm fem calibrate --model {rung}{option} --out {one_argument(path)}"


def calibrated(key: str, calibration: Calibration | None = None) -> dict:
    """Entry ``key`` (for example ``"eq2-inner"``) of ``calibration`` (None: the shipped one)."""
    return (calibration or Calibration.shipped()).entry(key)


class CalibratedTheta0:
    """Mixin of models whose braid angle defaults to their entry in their ``calibration`` (None:
    the shipped one), and whose rubber (if they have one) to the entry's ``C10_MPa``,
    ``C01_MPa`` where a muscle was identified (``mkm identify``), else to Silastic S, and whose
    gap between tube and braid (if they take one) to the entry's ``gap_mm``, else 0."""

    theta0_deg: float | None
    calibration: Calibration | None = None
    gap_mm: float | None = None

    def calibrated_entry(self) -> dict:
        """This model's entry in its calibration."""
        return calibrated(self.calibration_key, self.calibration)

    def _theta0(self) -> float:
        if self.theta0_deg is not None:
            return float(self.theta0_deg)
        return self.calibrated_entry()["theta0_deg"]

    def _gap(self) -> float:
        """The radial gap between tube and braid [mm] of a model that takes one (``gap_mm``):
        given, else the entry's where a muscle was identified with one, else 0."""
        if self.gap_mm is not None:
            return self.gap_mm
        try:
            entry = self.calibrated_entry()
        except ValueError:  # no entry for this model: an explicit angle needs none
            return 0.0
        return check_value("gap_mm", entry.get("gap_mm", 0.0), prefix="calibration ")

    def _rubber(self) -> MooneyRivlin:
        given = {"C10_MPa": self.C10_MPa, "C01_MPa": self.C01_MPa}
        if None in given.values():
            try:
                entry = self.calibrated_entry()
            except ValueError:  # an explicit angle needs no entry, nor does the nominal rubber
                entry = {}
            given = {k: entry.get(k) if v is None else v for k, v in given.items()}
        return mooney_rivlin(**given)


def read_reference(path) -> pd.DataFrame:
    """A reference sweep from a CSV with :data:`REFERENCE_COLUMNS` (see :func:`check_reference`)."""
    import pandas as pd

    try:
        frame = pd.read_csv(path, comment="#")
    except OSError as exc:
        raise ValueError(f"reference {path}: cannot read it: {exc.strerror}") from None
    return check_reference(frame, str(path))


def check_reference(frame: pd.DataFrame, name: str = "reference") -> pd.DataFrame:
    """``frame`` with its columns checked, one row per pressure and muscle (branches averaged).

    Rows of the same muscle, direction and level are averaged (repeats); the level is the
    optional ``set_pressure_bar`` (a run's steps: a gauge's noise reads the two branches' holds
    of one set pressure a few mbar apart), else the pressure rounded to 1 mbar. With ``up`` and
    ``down`` rows, only levels measured in both directions are kept and the two directions
    averaged (their mean is what a frictionless model predicts). Raises ``ValueError`` naming
    a missing column or too few rows.
    """
    import pandas as pd

    missing = [c for c in REFERENCE_COLUMNS if c not in frame.columns]
    if missing:
        raise ValueError(f"{name} lacks columns {missing}: expected "
                         f"{', '.join(REFERENCE_COLUMNS)} (optional L0_mm, direction, "
                         "set_pressure_bar)")
    frame = _numeric(frame, name).dropna(subset=list(REFERENCE_COLUMNS))
    keys = ["D0_mm", "t0_mm", "eps"] + (["L0_mm"] if "L0_mm" in frame else [])
    values = ["pressure_bar", "force_N"]
    level = frame["pressure_bar"]
    if "set_pressure_bar" in frame:
        level = pd.to_numeric(frame["set_pressure_bar"], errors="coerce").fillna(level)
    frame = frame.assign(level=level.round(3))
    if "direction" in frame:
        frame = frame.groupby(keys + ["level", "direction"], as_index=False)[values].mean()
        if frame["direction"].nunique() > 1:
            # the turning point of a staircase is measured on one branch only, where friction
            # biases it by the whole half-loop: fit only the levels measured both ways
            both = frame.groupby(keys + ["level"])["direction"].transform("nunique") > 1
            frame = pd.concat([_branches_met(sweep, both.loc[sweep.index])
                               for _, sweep in frame.groupby(keys)])
    frame = frame.groupby(keys + ["level"], as_index=False)[values].mean()
    if len(frame) < 2:
        raise ValueError(f"{name} has {len(frame)} usable pressures: expected at least 2")
    return frame[keys + values]


def _branches_met(sweep: pd.DataFrame, both: pd.Series) -> pd.DataFrame:
    """The rows of one sweep whose level was measured both ways (``both``); where its falling
    branch was held at other pressures than its rising one (a lab's table: up 0, 1, 2, 3, 4,
    down 3.5, 2.5, ...), the rising steps within the falling branch's range, each with the
    falling branch's force interpolated there beside its own (a force smooth in pressure)."""
    import pandas as pd

    if sweep["direction"].nunique() < 2 or sweep.loc[both, "level"].nunique() >= 2:
        return sweep[both]
    up = sweep[sweep["direction"] == "up"]
    down = sweep[sweep["direction"] == "down"].sort_values("pressure_bar")
    up = up[up["pressure_bar"].between(down["pressure_bar"].min(), down["pressure_bar"].max())]
    falling_N = np.interp(up["pressure_bar"], down["pressure_bar"], down["force_N"])
    return pd.concat([up, up.assign(direction="down", force_N=falling_N)])


def _numeric(frame: pd.DataFrame, name: str) -> pd.DataFrame:
    """``frame`` with its number columns as floats (a blank cell is NaN: the row is dropped).

    Text, a value outside the muscle limits (:data:`mkm.fem.limits.LIMITS`), a force beyond
    :data:`MAX_FORCE_N` or a direction other than up/down is refused, naming the value.
    """
    import pandas as pd

    frame = frame.copy()
    for column in [c for c in (*REFERENCE_COLUMNS, "L0_mm") if c in frame]:
        values = pd.to_numeric(frame[column], errors="coerce")
        if column in LIMITS:
            beyond = outside(column, values) & values.notna()
        else:
            beyond = values.abs() > MAX_FORCE_N
        bad = (values.isna() & frame[column].notna()) | beyond
        if bad.any():
            expected = limit_text(column) if column in LIMITS else \
                f"expected a force within +-{MAX_FORCE_N:g} N"
            raise ValueError(f"{name}: {column}={str(frame[column][bad].iloc[0])[:40]!r} is "
                             f"invalid: {expected}")
        frame[column] = values.astype(float)
    if "direction" in frame:
        bad = ~frame["direction"].isin(["up", "down"])
        if bad.any():
            raise ValueError(f"{name}: direction={str(frame['direction'][bad].iloc[0])[:40]!r} "
                             "is invalid: expected up or down")
    return frame


def _sweeps(reference: pd.DataFrame) -> list[pd.DataFrame]:
    keys = [k for k in ("D0_mm", "t0_mm", "eps", "L0_mm") if k in reference]
    return [group for _, group in reference.groupby(keys, sort=True)]


def line_above_threshold(pressure_bar, force_N, floor_N: float = 0.0):
    """Least-squares line ``F = s (P - P*)`` through the points with force above ``floor_N``.

    Returns the slope ``s`` [N/bar] and the threshold ``P*`` [bar] (NaN with fewer than two
    such points). Points at or below the floor are below the threshold: the held muscle has
    not shortened yet there, so they carry no information on the slope.
    """
    P, F = np.asarray(pressure_bar, dtype=float), np.asarray(force_N, dtype=float)
    above = np.isfinite(F) & (F > floor_N)
    if above.sum() < 2 or np.ptp(P[above]) == 0:
        return np.nan, np.nan
    slope, intercept = np.polyfit(P[above], F[above], 1)
    return float(slope), float(-intercept / slope)


def reference_line(sweep: pd.DataFrame) -> tuple[float, float, float]:
    """The floor [N], slope [N/bar] and threshold [bar] of one sweep of a checked reference
    (:func:`check_reference`: its turning point dropped, its branches averaged): the line
    through its forces above :data:`THRESHOLD_FLOOR_FRACTION` of its largest (slope NaN when
    fewer than two lie above)."""
    floor = THRESHOLD_FLOOR_FRACTION * sweep["force_N"].max()
    return (floor, *line_above_threshold(sweep.pressure_bar, sweep.force_N, floor))


def has_slope(reference: pd.DataFrame) -> bool:
    """Whether every sweep of the checked ``reference`` has a rising line to fit a slope to
    (:func:`reference_line`), as :func:`fit_theta0` asks of a slope target."""
    return all(reference_line(sweep)[1] > 0 for sweep in _sweeps(reference))


def fit_theta0(make_model, reference: pd.DataFrame, target: str = "slope",
               bounds=THETA0_BOUNDS_DEG, xatol: float = 1e-3) -> dict:
    """Fit theta0 [deg] of ``make_model(theta0_deg)`` to ``reference`` (see the module doc).

    Parameters
    ----------
    make_model : callable
        ``theta0_deg -> ForceModel``.
    reference : pandas.DataFrame
        As returned by :func:`check_reference`; may hold several sweeps (muscles).
    target : {"slope", "force", "slope+threshold"}
        What is fitted. ``slope`` minimises the squared relative slope residuals of the sweeps
        (with one sweep: the model's slope equals the reference's).
    bounds : (float, float)
        Search interval [deg].
    xatol : float
        Tolerance on theta0 [deg]; the fit is stored rounded to 1e-3 deg.

    Returns
    -------
    dict
        ``theta0_deg``, ``target``, per-fit ``slope_model_N_per_bar`` and
        ``slope_reference_N_per_bar`` (first sweep), ``slope_residual_pct`` (largest over the
        sweeps, model minus reference), ``threshold_model_bar``, ``threshold_reference_bar``,
        ``rmse_N`` and ``max_abs_residual_N`` of the model against every reference force,
        ``threshold_offset_bar`` and ``rmse_shifted_N`` (``slope+threshold`` only),
        ``force_N`` (the model's forces at the reference points), ``evaluations``.

    Raises ``ValueError`` for an unknown target or a reference without a slope, and
    ``RuntimeError`` when the model cannot produce valid forces at the optimum.
    """
    if target not in TARGETS:
        raise ValueError(f"target={target!r} is invalid: expected one of {', '.join(TARGETS)}")
    reference = check_reference(reference)
    sweeps = _sweeps(reference)
    ref_lines = []
    for sweep in sweeps:
        floor, slope, threshold = reference_line(sweep)
        if target != "force" and not slope > 0:
            raise ValueError("reference sweep at D0_mm={:g}, t0_mm={:g}, eps={:g} has fewer than "
                             "two forces above its threshold: expected a rising force to fit a "
                             "slope to".format(*sweep[["D0_mm", "t0_mm", "eps"]].iloc[0]))
        ref_lines.append((floor, slope, threshold))
    args = [reference[c].to_numpy() for c in ("pressure_bar", "D0_mm", "t0_mm", "eps")]
    measured = reference["force_N"].to_numpy()
    n_eval = 0

    def predict(theta0):
        nonlocal n_eval
        n_eval += 1
        return make_model(theta0).predict(*args)

    def model_lines(pred):
        lines = []
        for sweep, (floor, _, _) in zip(sweeps, ref_lines, strict=True):
            idx = sweep.index.to_numpy()
            use = measured[idx] > floor  # the reference points above its threshold
            lines.append(line_above_threshold(args[0][idx][use], pred.force_N[idx][use]))
        return lines

    def objective(theta0):
        pred = predict(theta0)
        if not pred.valid.all():
            return 1e12
        if target == "force":
            return float(np.sqrt(np.mean((pred.force_N - measured) ** 2)))
        residuals = [(s - ref[1]) / ref[1] for (s, _), ref in
                     zip(model_lines(pred), ref_lines, strict=True)]
        return 1e12 if not np.all(np.isfinite(residuals)) else float(np.sum(np.square(residuals)))

    from scipy.optimize import minimize_scalar

    res = minimize_scalar(objective, bounds=bounds, method="bounded", options={"xatol": xatol})
    theta0 = round(float(res.x), 3)
    pred = predict(theta0)
    if not pred.valid.all():
        raise RuntimeError(f"calibration failed: the search over theta0 in [{bounds[0]:g}, "
                           f"{bounds[1]:g}] deg found no angle giving valid forces")
    lines = model_lines(pred)
    residual = pred.force_N - measured
    slope_res = [(s - ref[1]) / ref[1] for (s, _), ref in zip(lines, ref_lines, strict=True)]
    fit = {
        "theta0_deg": theta0, "target": target,
        "slope_model_N_per_bar": lines[0][0], "slope_reference_N_per_bar": ref_lines[0][1],
        "slope_residual_pct": 100.0 * float(max(slope_res, key=abs)),
        "threshold_model_bar": lines[0][1], "threshold_reference_bar": ref_lines[0][2],
        "rmse_N": float(np.sqrt(np.mean(residual**2))),
        "max_abs_residual_N": float(np.max(np.abs(residual))),
        "force_N": pred.force_N, "evaluations": n_eval, "sweeps": len(sweeps),
    }
    if target == "slope+threshold":
        # shift the model along the pressure axis by the reference's threshold offset
        offset = ref_lines[0][2] - lines[0][1]
        shifted = make_model(theta0).predict(np.maximum(args[0] - offset, 0.0), *args[1:])
        shifted_force = np.where(args[0] - offset > 0, shifted.force_N, 0.0)
        # a point the model could not solve is left out of the shifted residual
        ok = np.isfinite(shifted_force)
        fit["threshold_offset_bar"] = float(offset)
        fit["rmse_shifted_N"] = float(np.sqrt(np.mean((shifted_force[ok] - measured[ok]) ** 2)))
    return fit


@dataclass(frozen=True)
class Fitted:
    """What :func:`calibrate` found: the fit (:func:`fit_theta0`'s dict), the model at the fitted
    angle, and the reference fitted."""

    fit: dict
    model: ForceModel
    reference: pd.DataFrame

    def summary(self, reference_name: str) -> str:
        """One line: the angle, the target, the slopes and residuals."""
        fit = self.fit
        extra = (f", threshold offset {fit['threshold_offset_bar']:+.3f} bar (shifted RMSE "
                 f"{fit['rmse_shifted_N']:.2f} N)" if "threshold_offset_bar" in fit else "")
        return (f"model {self.model.calibration_key}: theta0 = {fit['theta0_deg']:.3f} deg "
                f"(target {fit['target']}), slope {fit['slope_model_N_per_bar']:.2f} N/bar "
                f"against {fit['slope_reference_N_per_bar']:.2f} "
                f"({fit['slope_residual_pct']:+.3f} %), RMSE {fit['rmse_N']:.2f} N, largest "
                f"residual {fit['max_abs_residual_N']:.2f} N{extra} ({fit['evaluations']} "
                f"evaluations) against {reference_name}")

    def table_csv(self) -> str:
        """The reference and the calibrated model's forces, as CSV lines."""
        rows = zip(self.reference["pressure_bar"], self.reference["force_N"],
                   self.fit["force_N"], strict=True)
        return "pressure_bar,reference_N,model_N\n" + "".join(
            f"{p:g},{ref:.2f},{f:.2f}\n" for p, ref, f in rows)


def calibrate(build: Callable[..., ForceModel], reference: pd.DataFrame,
              target: str | None = None, L0_mm: float | None = None) -> Fitted:
    """theta0 of the model ``build(theta0_deg=..., L0_mm=...)`` fitted to ``reference``
    (:func:`fit_theta0`; ``target`` None: :func:`default_target`).

    The model's length is ``L0_mm``, else the reference's (one length: a model has one), else
    the model's default. Only the static physics rungs have an angle to calibrate.
    """
    from mkm.fem.ladder import static_names

    lengths = reference["L0_mm"].unique() if "L0_mm" in reference else []
    if L0_mm is None and len(lengths) > 1:
        raise ValueError(f"the reference holds muscles of lengths "
                         f"{', '.join(f'{v:g}' for v in lengths)} mm: expected one L0_mm "
                         "(a model has one length)")
    if L0_mm is None and len(lengths):
        L0_mm = float(lengths[0])
    model = build(theta0_deg=30.0, L0_mm=L0_mm)
    if model.name not in static_names():
        raise ValueError(f"model {model.name!r}: only the physics models "
                         f"{', '.join(static_names())} have a theta0 to calibrate")
    fit = fit_theta0(lambda th: build(theta0_deg=th, L0_mm=L0_mm), reference,
                     target or default_target(model))
    return Fitted(fit, build(theta0_deg=fit["theta0_deg"], L0_mm=L0_mm), reference)


def default_target(model) -> str:
    """``slope`` for a model with a threshold pressure (``model.has_threshold``), ``force``
    otherwise (Equation 2: through the origin, where slope and force fits coincide)."""
    return "slope" if getattr(model, "has_threshold", False) else "force"


def calibration_entry(fit: dict, model, reference_name: str, reference_sha256: str | None,
                      module: str) -> dict:
    """The record of one fit: target, reference, theta0, residuals, command, date, code
    version (:func:`mkm.core.records.source_version` of the model's module, without its data files,
    so that writing the calibration does not change the version it records) and the checkout's
    git revision (null from a wheel)."""
    info = provenance()
    entry = {
        "theta0_deg": fit["theta0_deg"],
        "target": fit["target"],
        "reference": reference_name,
        "reference_sha256": reference_sha256,
        "slope_N_per_bar": {"model": _round(fit["slope_model_N_per_bar"], 4),
                            "reference": _round(fit["slope_reference_N_per_bar"], 4)},
        "slope_residual_pct": _round(fit["slope_residual_pct"], 4),
        "threshold_pressure_bar": {"model": _round(fit["threshold_model_bar"], 4),
                                   "reference": _round(fit["threshold_reference_bar"], 4)},
        "rmse_N": _round(fit["rmse_N"], 4),
        "max_abs_residual_N": _round(fit["max_abs_residual_N"], 4),
        "model_params": {k: v for k, v in model.params().items() if k != "theta0_deg"},
        "command": info["command"],
        "date_utc": info["date_utc"],
        "code_version": source_version(module, data=False),
        "git": info["git"],
        "versions": info["versions"],
    }
    if "threshold_offset_bar" in fit:
        entry["threshold_offset_bar"] = _round(fit["threshold_offset_bar"], 4)
        entry["rmse_shifted_N"] = _round(fit["rmse_shifted_N"], 4)
    return entry


def _round(value, digits):
    # + 0.0: a -0.0 from rounding a tiny negative number is stored as 0.0
    return None if value is None or not np.isfinite(value) else round(float(value), digits) + 0.0


def store_calibration(path: str | os.PathLike, key: str, entry: dict) -> Path:
    """Write (or replace) entry ``key`` of the calibration file ``path``, keeping the others.

    Written atomically. Writing the shipped ``fem/calibration.json`` is the caller's explicit
    choice (``mkm fem calibrate --update-shipped``).
    """
    path = Path(path)
    entries = dict(_load(path)) if path.exists() else {}
    entries[key] = entry
    write_atomic(path, json.dumps(entries, indent=2, sort_keys=True) + "\n")
    return path


def calibration_provenance(model) -> dict:
    """Which calibration gave ``model`` its theta0, for the provenance of what it computes.

    The file (``shipped`` for ``fem/calibration.json``), its SHA-256, the model's key and the
    whole entry (target, reference, residuals, command, date, code version); or, for a model
    built with an explicit angle, that angle.
    """
    if getattr(model, "theta0_deg", None) is not None:
        return {"source": "theta0_deg given explicitly", "theta0_deg": model.theta0_deg}
    calibration = getattr(model, "calibration", None) or Calibration.shipped()
    key = model.calibration_key
    return {**calibration.record(), "key": key, "entry": calibration.entry(key)}
