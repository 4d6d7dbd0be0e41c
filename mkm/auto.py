"""The ``auto`` force model: the cheapest model whose error bound AT THE POINT ASKED meets a
tolerance.

"Model no more than a scene needs", as a feature. The scene is the query: a sweep, a bench run,
with every parameter of the muscle (``L0_mm``, ``theta0_deg``, the rubber ``C10_MPa``,
``C01_MPa``). ``auto`` bounds each candidate's error against the finest FE mesh (the paper's
Equation 7: the distance from the fine mesh's force scaled by the largest force of the
muscle's sweep) a posteriori, at those very points:

- the surrogate is the estimate of the reference there: its force ``R`` and its calibrated
  predictive standard deviation ``s`` (rescaled on held-out FE muscles so that 1, 2 and 3 std
  hold 68, 95 and 99.7 % of its errors: the model's metadata ``std_rescale`` records the
  factor, the muscles and what they measured). Its own bound is ``K s`` (:data:`STD_FACTOR`,
  K = 3: beyond it lies 0.3 % of the errors); where the practical range's surrogate is the
  reference (outside the default's box) K is :data:`RANGE_STD_FACTOR`: the largest error of
  a call over its largest std, measured on fresh calls of the range, exceeded 3 on some and
  that factor on none;
- a closed form's bound is ``|F - R| + K s``: its distance from the surrogate plus the
  surrogate's own uncertainty, so it holds wherever the surrogate's does;
- an FE mesh's bound is its mesh error at the scale of the call: ``a P* A + b F`` at each point
  of force ``F`` and slope ``A`` (the mesh's own), relative to the largest force of the call
  (:func:`mkm.mesh_errors.point_bound_pct`), with ``a`` the largest threshold shift (over
  ``P*``) and ``b`` the largest relative error measured on fresh random muscles of the practical
  range, half of them near the braid lock (``mkm/data/mesh_errors.csv``,
  :mod:`mkm.mesh_errors`), over the muscles whose clamped end the mesh resolves (its element
  at the cap at most :data:`~mkm.mesh_errors.MAX_END_RESOLUTION` bending lengths of the wall)
  and whose wall is at most :data:`~mkm.mesh_errors.SLENDERNESS_REACH` times as slender
  (``L0/t0``) as the call's (:meth:`mkm.mesh_errors.MeshBound.coefficients`: flat elements
  err most); a mesh does not answer for a muscle beyond the end zone it resolves. Over a
  sweep it is small; at a single point just above the threshold ``P*`` it is large, as the
  error is (a coarse mesh's
  threshold shifted by 0.003 bar is 0.8 % of the force 0.4 bar above it). Without that table,
  the largest |Err%| in the study's convergence table times :data:`MESH_SAFETY`. The fine mesh
  is the reference (bound 0).

Candidates are tried cheapest first (their measured seconds per force, from the study table); by
default ONE model answers the whole call, the cheapest whose largest bound over all points meets the
tolerance and whose prediction is valid at every point, so a curve never mixes models.
``per_point=True`` chooses per point, each point's surrogate std taken as the largest of its muscle
in the call (the factors K are measured on a call's largest error over its largest std). Outside the
surrogate's box (a point, or a muscle parameter it was not trained on) there is no estimate of the
reference: only the FE meshes qualify, and the fine mesh answers if nothing else does. A gap between
tube and braid (``gap_mm`` other than 0, given or held by the candidates' calibration: a muscle
identified with a gap) is modelled by the closed form and the FE (their registry entries take it),
not by the surrogate, so nothing estimates the reference with the gap and no closed form's error is
bounded there (its gap-free bound is not one): only the FE meshes answer, each by its recorded mesh
error (with a gap the coarse mesh is as close to the fine one: ``tests/fem/fe/test_contact.py``),
and the fine mesh, with the gap, if nothing else meets the tolerance; :func:`explain` says first
which models cannot answer. Each point records the model that answered (``model_used``), its bound
(``error_bound_pct``) and how the bound was obtained (``bound_source``); :func:`explain` says it in
words, and the parameters (the provenance) name the reference and the factor.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable
from functools import cache
from pathlib import Path

import numpy as np
import pandas as pd

from mkm import mesh_errors
from mkm.core.records import file_sha256, package_file, read_csv_checked
from mkm.fem.interface import ForceModel
from mkm.fem.ladder import MODELS
from mkm.surrogate import kinds

MODEL_ERRORS_FILE = package_file("mkm", "data", "model_errors.csv")
REFERENCE_SPEC = "surrogate"
#: Outside the default surrogate's box, the surrogate of the practical range is the reference
#: (:data:`mkm.surrogate.kinds.RANGE`); it answers in the default's place, under this name.
RANGE_SPEC = f"surrogate:kind={kinds.RANGE}"
RANGE_PREDICTOR = f"surrogate-{kinds.RANGE}"
FALLBACK = "axisym-fine"
FALLBACK_SPEC = "axisym:mesh=fine"
#: K of the default surrogate's own bound ``K s``, ``s`` its calibrated std: beyond 3 std lies
#: 0.3 % of a normal error.
STD_FACTOR = 3.0
#: What every bound resting on a surrogate's std says of itself (:func:`explain`): a surrogate's
#: error over its std has a heavy tail, so K of it bounds most calls, not every one
#: (docs/guide/force-models.md).
STD_BOUND = "calibrated std"
STD_CAVEAT = ("; an estimate from a surrogate's std, which most calls' errors stay within, not "
              "every one's")
#: The factor of the practical range's surrogate's std in the bounds where it is the reference
#: (its own, and a closed form's distance from it). Its std is calibrated per point; the largest
#: error of a call against the largest std of the call needs more than 3 of it on some fresh
#: calls of the range, and this factor holds every call of the recorded draw,
#: ``reference_std_factor`` in ``docs/measured/auto_practical.json``
#: (``benchmarks/bench_auto.py --range practical``; ``tests/test_docs.py`` holds this to it),
#: not every call of every fresh draw: the tail is heavy (docs/guide/force-models.md,
#: docs/guide/surrogates.md).
RANGE_STD_FACTOR = 6.0
#: Where the practical range's surrogate errs most, said where its bound keeps it out: its worst
#: muscles over fresh draws (``worst_muscles`` in docs/measured/surrogate_range_gp_pooled.json,
#: docs/guide/surrogates.md; ``tests/test_docs.py`` holds the guide to that file).
RANGE_WORST = ("a braid angle below 20 deg, a shortening near the braid lock, a threshold near "
               "the top pressure, a tube short (L0 near 3 D0) or thick-walled (docs/guide/"
               "surrogates.md, \"Beyond the box\")")
# A mesh's recorded error is the largest over the study's muscles; another muscle may do a
# little worse
MESH_SAFETY = 1.5
MIN_SCALE_N = mesh_errors.MIN_SCALE_N
PARAMETERS = ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")


@cache
def read_model_errors(path: Path | str = MODEL_ERRORS_FILE) -> pd.DataFrame:
    """The study table written by ``mkm study``: one row per predictor, muscle and pressure."""
    numeric = ("pressure_bar", "err_pct", "seconds_per_point")
    return read_csv_checked(path, "study table", "expected the table `mkm study` writes "
                            "(model_errors.csv; run `mkm study` to measure the models' errors)",
                            ("predictor", "spec", "family", "muscle", *numeric), numeric=numeric)


def candidates(table: pd.DataFrame) -> pd.DataFrame:
    """Predictors auto may use, cheapest first: predictor, spec, family, seconds per force and,
    for the FE meshes, the recorded mesh error [%]."""
    pick = table[table["spec"].notna() & (table["spec"] != "")]
    rows = (pick.assign(abs_err=pick["err_pct"].abs())
            .groupby(["predictor", "spec", "family"], as_index=False)
            .agg(seconds_per_point=("seconds_per_point", "median"),
                 recorded_err_pct=("abs_err", "max")))
    return rows.sort_values("seconds_per_point", kind="stable").reset_index(drop=True)


def takes_gap(spec: str) -> bool:
    """Whether the predictor of ``spec`` takes ``gap_mm`` (its registry entry's parameters)."""
    name = spec.partition(":")[0]
    return name in MODELS.names() and "gap_mm" in MODELS.entry(name).parameters


def physics_rungs(gap: bool) -> list[str]:
    """The registry's physics rungs (closed forms and FE) that take ``gap_mm`` (or not)."""
    return [name for name in MODELS.names()
            if MODELS.entry(name).family in ("closed form", "FE")
            and ("gap_mm" in MODELS.entry(name).parameters) == gap]


def _muscle_max(values: np.ndarray, geometry: np.ndarray) -> np.ndarray:
    """Per point, the largest of ``values`` over its muscle's points (same D0, t0, eps)."""
    out = np.empty(values.shape)
    _, which = np.unique(geometry, axis=0, return_inverse=True)
    for g in np.unique(which):
        here = which.ravel() == g
        out[here] = np.nanmax(values[here], initial=0.0)
    return out


def _sweep_scale(reference: np.ndarray, geometry: np.ndarray) -> np.ndarray:
    """Per point, the largest reference force of its muscle (same D0, t0, eps), at least
    :data:`MIN_SCALE_N`: Equation 7's denominator."""
    return np.maximum(_muscle_max(np.abs(reference), geometry), MIN_SCALE_N)


def _in_practical_range(P, D0, t0, eps) -> bool:
    """Whether every point lies in the practical range's box (:meth:`PracticalRange.hull
    <mkm.fem.limits.PracticalRange.hull>`: past the lock at every angle, or a tube no muscle of
    the range has, is outside)."""
    from mkm.fem.limits import PRACTICAL_RANGE

    box = PRACTICAL_RANGE.hull()
    return all(np.all((np.asarray(value) >= box[name][0]) & (np.asarray(value) <= box[name][1]))
               for name, value in (("pressure_bar", P), ("D0_mm", D0), ("t0_mm", t0),
                                   ("eps", eps)))


def _measured_points(muscle: dict, P, D0, t0, eps) -> np.ndarray:
    """Per point, whether it and the muscle ``muscle`` (a model's params) lie in the practical
    range, where the meshes' errors are measured (:mod:`mkm.mesh_errors`)."""
    from mkm.fem.limits import PRACTICAL_RANGE

    fixed = {k: muscle.get(k) for k in ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")}
    if PRACTICAL_RANGE.violations(**fixed):
        return np.zeros(np.shape(P), dtype=bool)
    return np.array([not PRACTICAL_RANGE.violations(pressure_bar=p, D0_mm=d, t0_mm=t, eps=e,
                                                    L0_mm=fixed["L0_mm"],
                                                    theta0_deg=fixed["theta0_deg"])
                     for p, d, t, e in zip(P, D0, t0, eps, strict=True)], dtype=bool)


def _announce_first_training(kind: str) -> None:
    """Say before a surrogate trains on first use (seconds at its shipped kernels, a minute for
    the practical range's without them), so that a command does not wait without a word."""
    from mkm.core.durations import estimate
    from mkm.surrogate.train import is_cached, training_task

    if not is_cached(kind):
        warnings.warn(f"training the surrogate {kind} on first use, "
                      f"{estimate(training_task(kind))}; later calls load "
                      "it", stacklevel=3)


#: auto's tolerance when none is given: the largest |Err%| against the finest FE, a fraction
DEFAULT_TOLERANCE = 0.02


class AutoModel(ForceModel):
    """The cheapest model meeting ``tolerance`` at the query (``--model auto --tolerance 2%``).

    Parameters
    ----------
    tolerance : float
        Largest acceptable |Err%| against the finest FE model, a fraction (0.02 = 2 %).
    table : str, optional
        Study table (default ``mkm/data/model_errors.csv``, written by ``mkm study``): the
        candidates, their measured cost and the FE meshes' recorded errors.
    mesh_errors : str, optional
        Mesh error table (default ``mkm/data/mesh_errors.csv``, :mod:`mkm.mesh_errors`): the
        FE meshes' bound at the scale of the call.
    per_point : bool
        False (default): one model for the whole call. True: the cheapest model per point,
        bounded by the reference surrogate's largest std of the muscle in the call.
    L0_mm, theta0_deg, C10_MPa, C01_MPa : float, optional
        The muscle: length at rest [mm], braid angle at rest [deg], rubber [MPa]; passed to
        every candidate (None: each model's default).
    gap_mm : float, optional
        Radial gap between tube and braid at rest [mm]; passed to the candidates that take it
        (the registry entry's parameters say which), and other than 0 only they may answer.
    build : callable
        ``build(spec, **muscle) -> ForceModel``: makes a candidate from a spec (the registry's
        :func:`mkm.registry.build_spec`, which passes itself when it builds auto).
    """

    name = "auto"

    def __init__(self, tolerance: float = DEFAULT_TOLERANCE, table: str | None = None,
                 per_point: bool = False, L0_mm: float | None = None,
                 theta0_deg: float | None = None, C10_MPa: float | None = None,
                 C01_MPa: float | None = None, gap_mm: float | None = None,
                 mesh_errors: str | None = None, *, build: Callable[..., ForceModel]):
        self.tolerance = tolerance
        self.table = table
        # the shipped table may be absent (then the study's recorded errors bound the meshes);
        # one named is meant to be read
        if mesh_errors is not None and not Path(mesh_errors).is_file():
            raise ValueError(f"mesh_errors={str(mesh_errors)!r} is invalid: no such file; "
                             "expected a mesh error table written by `mkm study --mesh-muscles "
                             "N` (mesh_errors.csv)")
        self.mesh_errors = mesh_errors
        self.per_point = bool(per_point)
        self.L0_mm, self.theta0_deg = L0_mm, theta0_deg
        self.C10_MPa, self.C01_MPa = C10_MPa, C01_MPa
        self.gap_mm = gap_mm
        self.build = build

    @property
    def muscle(self) -> dict[str, float]:
        return {k: getattr(self, k) for k in PARAMETERS if getattr(self, k) is not None}

    @property
    def gapped(self) -> bool:
        """Whether the muscle has a gap, which only some candidates model: given, or else the
        one a candidate of a gap takes from its calibration (a muscle identified with one)."""
        return bool(self.resolved_gap_mm())

    def resolved_gap_mm(self) -> float:
        """The gap [mm] the candidates of a gap answer with: ``gap_mm`` if given, else the
        largest their calibration entries hold (0 where they hold none)."""
        if self.gap_mm is not None:
            return float(self.gap_mm)
        gaps = [0.0]
        for name in physics_rungs(gap=True):
            try:
                gaps.append(float(self.build(name, **self.muscle).params().get("gap_mm", 0.0)))
            except ValueError:  # no entry in this calibration: it has no gap of its own
                continue
        return max(gaps)

    def params(self):
        path = Path(self.table or MODEL_ERRORS_FILE)
        digest = file_sha256(path)[:12] if path.exists() else None
        gap = {"gap_mm": self.gap_mm} if self.gap_mm is not None else {}
        resolved = self.resolved_gap_mm()
        gap.update({"resolved_gap_mm": resolved} if resolved else {})
        meshes = Path(self.mesh_errors or mesh_errors.MESH_ERRORS_FILE)
        return {"tolerance": self.tolerance, "per_point": self.per_point, **self.muscle, **gap,
                "table": path.name, "table_sha256": digest, "reference": REFERENCE_SPEC,
                "reference_outside_its_box": RANGE_SPEC,
                "std_factor": STD_FACTOR, "std_factor_outside_its_box": RANGE_STD_FACTOR,
                "mesh_safety": MESH_SAFETY,
                "mesh_errors": meshes.name,
                "mesh_errors_sha256": file_sha256(meshes)[:12] if meshes.exists() else None}

    @property
    def calibration_key(self) -> str:
        """The fine FE mesh's entry: auto predicts the muscle its reference, the fine mesh,
        predicts (each candidate at its own calibrated angle, bounded against it), so whatever
        asks auto's nominal braid angle (a report's tolerance band) gets the reference's."""
        return self._candidate(FALLBACK_SPEC).calibration_key

    @property
    def calibration(self):
        """The calibration auto's candidates are built with (the reference's)."""
        return getattr(self._candidate(FALLBACK_SPEC), "calibration", None)

    def _candidate(self, spec: str, gap: bool = True) -> ForceModel:
        """Candidate ``spec`` at the muscle; if it takes a gap, with the muscle's if ``gap``
        (given, else its calibration's), else with none."""
        extra = {}
        if takes_gap(spec):
            extra = ({"gap_mm": 0.0} if not gap
                     else {"gap_mm": self.gap_mm} if self.gap_mm is not None else {})
        return self.build(spec, **self.muscle, **extra)

    def reference(self, P, D0, t0, eps):
        """``(R, s, spec, prediction)``: the surrogate's force and standard deviation [N] at
        every point, the spec of the surrogate that gave them and its prediction; None where no
        surrogate can estimate the reference (a point or a muscle parameter outside its box, or
        no predictive std). The default surrogate (:data:`REFERENCE_SPEC`) wherever it covers
        the call; only where it does not, the practical range's (:data:`RANGE_SPEC`)."""
        for spec in (REFERENCE_SPEC, RANGE_SPEC):
            if spec == RANGE_SPEC:
                if not _in_practical_range(P, D0, t0, eps):
                    continue  # no surrogate answers there: none is trained for it
                _announce_first_training(kinds.RANGE)
            try:
                model = self._candidate(spec, gap=False)
            except ValueError:  # a muscle parameter the surrogate was not trained on
                continue
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")  # out of its box: handled below
                pred = model.predict(P, D0, t0, eps)
            if "force_std_N" in pred.extras and pred.valid.all():
                return (np.ravel(pred.force_N), np.ravel(pred.extras["force_std_N"]), spec,
                        pred)
        return None

    def choose(self, P, D0, t0, eps) -> dict[str, np.ndarray]:
        """Per point: the predictor that answers (``model_used``), its error bound [%], how
        the bound was obtained, and the forces of the candidate chosen; the fallback's points
        are left to :meth:`_forces` (NaN force, ``model_used`` = :data:`FALLBACK`)."""
        if not 0.0 < self.tolerance < 1.0:
            raise ValueError(f"tolerance={self.tolerance:g} is invalid: expected a fraction in "
                             "(0, 1), for example 0.02 or 2%")
        table = read_model_errors(self.table or MODEL_ERRORS_FILE)
        P, D0, t0, eps = (np.ravel(a) for a in np.broadcast_arrays(
            *(np.asarray(v, dtype=float) for v in (P, D0, t0, eps))))
        tol = 100.0 * self.tolerance
        force = np.full(P.shape, np.nan)
        used = np.full(P.shape, FALLBACK, dtype=object)
        bound_used = np.zeros(P.shape)
        source = np.full(P.shape, "the fine mesh is the reference", dtype=object)
        todo = np.ones(P.shape, dtype=bool)
        measured = None  # which points lie where the meshes' errors were measured
        ref = self.reference(P, D0, t0, eps)
        gapped = self.gapped
        # the reference surrogate's own bound [%], K s: where it exceeds the tolerance no model
        # bounded by it answers, and an FE mesh's answer says so (:func:`_declined`)
        own = np.full(P.shape, np.nan)
        meshes = {FALLBACK}
        if ref is not None:
            R, s, ref_spec, ref_pred = ref
            geometry = np.stack([D0, t0, eps], axis=1)
            scale = _sweep_scale(R, geometry)
            factor = RANGE_STD_FACTOR if ref_spec == RANGE_SPEC else STD_FACTOR
            if self.per_point:
                # the factors are measured as a call's largest error over its largest std, not
                # a point's error over its own: a point chosen alone takes its muscle's largest
                # std of the call
                s = _muscle_max(s, geometry)
            own = 100.0 * factor * s / scale
        for row in candidates(table).itertuples():
            if not todo.any():
                break
            if row.predictor == FALLBACK:
                continue
            if gapped and row.family != "FE":
                continue  # no reference bounds it with the gap
            model_pred, predictor = None, row.predictor
            if row.family == "FE":
                meshes.add(row.predictor)
                if measured is None:  # one muscle: the same for every mesh
                    measured = _measured_points(self._candidate(row.spec).params(), P, D0, t0,
                                                eps)
                model_pred, bound, why = self._mesh_bound(row, P, D0, t0, eps, measured)
            elif ref is None:
                continue  # no estimate of the reference here: only the FE may answer
            elif row.spec == REFERENCE_SPEC:
                bound = own
                why = f"{factor:g} x the surrogate's calibrated std"
                if ref_spec == RANGE_SPEC:  # it answers in the default's place
                    model_pred, predictor = ref_pred, RANGE_PREDICTOR
                    why = (f"{factor:g} x the calibrated std of the practical range's "
                           "surrogate (outside the default surrogate's box)")
            else:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")  # a point it flags goes to the next one
                    model_pred = self._candidate(row.spec, gap=False).predict(P, D0, t0, eps)
                distance = np.abs(np.ravel(model_pred.force_N) - R)
                bound = 100.0 * (distance + factor * s) / scale
                why = (f"|{row.predictor} - surrogate| + {factor:g} x the surrogate's "
                       "calibrated std")
            meets = bound <= tol  # NaN never meets it
            if not self.per_point and not meets[todo].all():
                continue
            idx = np.flatnonzero(todo & meets)
            if idx.size == 0:
                continue
            if model_pred is None:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    model_pred = self._candidate(row.spec).predict(P, D0, t0, eps)
            valid = np.ravel(model_pred.valid)
            if not self.per_point and not valid[idx].all():
                continue  # one model for the whole query: it must answer every point
            ok = idx[valid[idx]]
            force[ok] = np.ravel(model_pred.force_N)[ok]
            used[ok] = predictor
            bound_used[ok] = bound[ok]
            source[ok] = why
            todo[ok] = False
        if ref is None:
            source[todo] = "outside the surrogate's box: no estimate of the reference there"
        else:
            by_mesh = todo | np.isin(used, list(meshes))
            source[by_mesh] = source[by_mesh] + _declined(own[by_mesh], tol, ref_spec, factor)
        if todo.any():  # the reference answers: its bound 0 holds where its own error is known
            if measured is None:
                measured = _measured_points(self._candidate(FALLBACK_SPEC).params(), P, D0, t0,
                                            eps)
            beyond = todo & ~measured
            bound_used[beyond] = np.nan
            source[beyond] = source[beyond] + ("; outside the practical range, where the fine "
                                               "mesh's own error is not measured: no bound")
        return {"force_N": force, "model_used": used.astype(str),
                "error_bound_pct": bound_used, "bound_source": source.astype(str)}

    def _mesh_bound(self, row, P, D0, t0, eps, measured):
        """An FE mesh's prediction (None if not run), its bound [%] per point and how it was
        obtained: from the mesh error model at the call's scale when the model covers the mesh
        (:func:`mkm.mesh_errors.point_bound_pct`), else the study table's largest error; none
        at a point not ``measured`` (outside the practical range, :func:`_measured_points`)."""
        mesh = dict(part.split("=", 1) for part in row.spec.partition(":")[2].split(",")
                    if "=" in part).get("mesh")
        model = mesh_errors.mesh_model(self.mesh_errors or mesh_errors.MESH_ERRORS_FILE)
        if mesh not in model:
            return (None, np.full(P.shape, MESH_SAFETY * row.recorded_err_pct),
                    f"mesh error: {MESH_SAFETY:g} x its largest |Err%| against the fine mesh "
                    "in the study's convergence table")
        candidate = self._candidate(row.spec)
        L0 = candidate.params()["L0_mm"]
        a, b = model[mesh].coefficients(L0, t0)
        # the bound is measured on muscles of the practical range: beyond it, none is claimed
        if not np.any(measured):
            return (None, np.full(P.shape, np.inf), f"{mesh} mesh: its error is measured over "
                    "the practical range (`mkm models`), which the call leaves")
        resolved = mesh_errors.end_resolution(D0, t0, L0, mesh) \
            <= mesh_errors.MAX_END_RESOLUTION
        if not np.any(resolved):  # its bound is not measured there: not solved at all
            return (None, np.full(P.shape, np.inf), f"{mesh} mesh: its element at the clamp "
                    f"spans more than {mesh_errors.MAX_END_RESOLUTION:g} bending lengths of "
                    "the wall, where its error is not bounded")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            pred = candidate.predict(P, D0, t0, eps)
        force = np.ravel(pred.force_N)
        threshold = np.ravel(pred.extras.get("threshold_pressure_bar", np.full(P.shape, np.nan)))
        bound = mesh_errors.point_bound_pct(force, P, threshold, np.stack([D0, t0, eps], axis=1),
                                            a, b)
        bound[~np.ravel(pred.valid) | ~np.isfinite(bound) | ~np.ravel(resolved)
              | ~measured] = np.inf
        return pred, bound, (f"mesh error at this call's scale: {100 * a.max():.3f} % of P* x "
                             f"the slope + {100 * b.max():.3f} % of the force, the largest over "
                             "fresh random muscles whose clamped end it resolves, up to "
                             f"{mesh_errors.SLENDERNESS_REACH:g} x the call's L0/t0, x "
                             f"{mesh_errors.SAFETY:g}")

    def _forces(self, P, D0, t0, eps):
        out = self.choose(P, D0, t0, eps)
        valid = np.isfinite(out["force_N"])
        converged = valid.copy()
        # the physical limit the fallback FE names where it finds no state (mkm.fem.outcomes),
        # and why its solve failed where it did (a column `not converged` alone does not say)
        limit = np.full(valid.shape, "", dtype=object)
        failure = np.full(valid.shape, "", dtype=object)
        fallback = np.flatnonzero(out["model_used"] == FALLBACK)
        if fallback.size:
            args = (np.ravel(a)[fallback] for a in (P, D0, t0, eps))
            pred = self._candidate(FALLBACK_SPEC).predict(*args)
            out["force_N"][fallback] = pred.force_N
            valid[fallback] = pred.valid
            # a point the reference finds no force at has no error to bound
            out["error_bound_pct"][fallback[~np.ravel(pred.valid)]] = np.nan
            converged[fallback] = pred.converged
            for name, column in (("limit", limit), ("failure", failure)):
                column[fallback] = np.ravel(np.broadcast_to(pred.extras.get(name, ""),
                                                            pred.force_N.shape))
        return {key: value.reshape(P.shape) for key, value in
                {**out, "valid": valid, "converged": converged, "limit": limit,
                 "failure": failure}.items()}


def _declined(own: np.ndarray, tol: float, ref_spec: str, factor: float) -> str:
    """What an FE mesh's answer adds where the reference surrogate's own bound ``own`` [%]
    exceeds the tolerance ``tol`` [%] at some of its points (empty where it does not): that
    bound, which keeps the surrogate and the closed forms it bounds out. Outside the default's
    box it names the practical range's surrogate and where that one errs most."""
    if not np.any(own > tol):  # NaN (no std) never exceeds it
        return ""
    # "x its std", not STD_BOUND's words: the mesh's own bound does not rest on a std
    if ref_spec == RANGE_SPEC:
        return (f"; the practical range's surrogate's own bound here is up to "
                f"{np.nanmax(own):.3g}% ({factor:g} x its std), where it errs most: "
                f"{RANGE_WORST}")
    return f"; the surrogate's own bound here is up to {np.nanmax(own):.3g}% ({factor:g} x its std)"


def spec_of(predictor: str, table: Path | str | None = None) -> str:
    """The spec of a study predictor (``surrogate-muscle-gp`` -> ``surrogate``); the name itself
    if the study table does not list it."""
    if predictor == FALLBACK:
        return FALLBACK_SPEC
    if predictor == RANGE_PREDICTOR:
        return RANGE_SPEC
    rows = candidates(read_model_errors(table or MODEL_ERRORS_FILE))
    match = rows.loc[rows["predictor"] == predictor, "spec"]
    return str(match.iloc[0]) if len(match) else predictor


def gap_note(gap_mm: float | None) -> str | None:
    """What a gap between tube and braid leaves out of auto's candidates (None without one):
    everything but the FE models that take ``gap_mm``."""
    if not gap_mm:
        return None
    return (f"auto: gap_mm={gap_mm:g}: the surrogate models no gap between tube and braid, so "
            f"nothing bounds a closed form's error with one; the candidates are "
            f"{', '.join(n for n in physics_rungs(gap=True) if MODELS.entry(n).family == 'FE')}"
            ", with the gap")


def explain(prediction, tolerance: float | None = None,
            label: Callable[[str], str] = str, gap_mm: float | None = None) -> str:
    """One line per model used: how many points it answered, its bound and how it was bound;
    first, with a gap between tube and braid, which models could not answer (:func:`gap_note`).

    ``prediction``: a :class:`Prediction` of :class:`AutoModel`, or the dict of
    :meth:`AutoModel.choose` with ``tolerance`` (and the muscle's ``gap_mm``, if any) given;
    ``label`` names a study predictor (:func:`mkm.verdict.model_label`: the registry's name).
    """
    if isinstance(prediction, dict):
        extras = prediction
    else:
        extras, tolerance = prediction.extras, prediction.params["tolerance"]
        gap_mm = prediction.params.get("resolved_gap_mm")
    tol = 100.0 * tolerance
    used = np.ravel(extras["model_used"])
    bound = np.ravel(extras["error_bound_pct"])
    source = np.ravel(extras["bound_source"])
    lines = []
    for name in dict.fromkeys(used):
        here = used == name
        if name == FALLBACK:
            why = (f"nothing cheaper has an error bound <= {tol:g}% there ("
                   f"{source[here][0]}), so the finest FE mesh, the reference, answers")
        else:
            why = (f"the cheapest model whose error bound at these points is <= {tol:g}%: "
                   f"{np.nanmax(bound[here]):.2f}% ({source[here][0]})")
            if STD_BOUND in source[here][0]:
                why += STD_CAVEAT
        lines.append(f"auto: {label(name)} for {here.sum()} of {used.size} points: {why}")
    note = gap_note(gap_mm)
    return "\n".join([note, *lines] if note else lines)
