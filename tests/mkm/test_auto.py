"""The auto model: the cheapest model whose error bound at the point asked meets the tolerance.

The unit tests give auto a known reference: a fake "surrogate" that is the coarse FE model plus a
stated standard deviation, so every bound has a value computed by hand here. The slow tests use
the real default surrogate and check the promise against the FE itself.
"""

from __future__ import annotations

import json
import re
import warnings
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from mkm import mesh_errors
from mkm.auto import (
    MESH_SAFETY,
    RANGE_PREDICTOR,
    RANGE_SPEC,
    RANGE_STD_FACTOR,
    RANGE_WORST,
    STD_CAVEAT,
    STD_FACTOR,
    AutoModel,
    explain,
    read_model_errors,
    spec_of,
)
from mkm.fem.calibration import Calibration
from mkm.fem.interface import ForceModel
from mkm.fem.ladder import make_model
from mkm.registry import build_spec
from mkm.verdict import model_label

STD_N = 2.0
# costs in s per force; the FE meshes' recorded |Err%| against the fine mesh
TABLE = {"eq2-braid": ("eq2:diameter=braid", "closed form", 1e-6, 0.0),
         "thickwall": ("thickwall", "closed form", 1e-5, 0.0),
         "surrogate-muscle-gp": ("surrogate", "surrogate", 1e-4, 0.0),
         "axisym-coarse": ("axisym:mesh=coarse", "FE", 1e-2, 0.4),
         # the fallback: the coarse mesh stands in for the fine one to keep the test fast
         "axisym-fine": ("axisym:mesh=coarse", "FE", 1e-1, 0.0)}


class FakeSurrogate(ForceModel):
    """The coarse FE model with a constant predictive std of ``std_N`` (STD_N), valid for D0 <=
    ``D0_max_mm`` (50 mm: the default surrogate's box)."""

    name = "surrogate"

    def __init__(self, std_N=STD_N, D0_max_mm=50.0, **muscle):
        self.fe = make_model("axisym", mesh="coarse", **muscle)
        self.muscle = muscle
        self.std_N, self.D0_max_mm = std_N, D0_max_mm

    def params(self):
        return dict(self.muscle)

    def _forces(self, P, D0, t0, eps):
        pred = self.fe.predict(P, D0, t0, eps)
        return {"force_N": pred.force_N, "valid": pred.valid & (D0 <= self.D0_max_mm),
                "force_std_N": np.full(P.shape, self.std_N)}


def fake_build(spec: str, **muscle) -> ForceModel:
    if spec == "surrogate":
        return FakeSurrogate(**{k: v for k, v in muscle.items() if k != "L0_mm"},
                             L0_mm=muscle.get("L0_mm", 282.0))
    if spec == RANGE_SPEC:  # the unit tests' auto has no surrogate of the practical range
        raise ValueError("no surrogate of the practical range in these tests")
    return build_spec(spec, **muscle)


@pytest.fixture(scope="module")
def table_path(tmp_path_factory):
    rows = [{"predictor": name, "family": family, "spec": spec, "muscle": "M",
             "pressure_bar": p, "err_pct": err, "seconds_per_point": cost}
            for name, (spec, family, cost, err) in TABLE.items() for p in (0.0, 2.5)]
    path = tmp_path_factory.mktemp("auto") / "model_errors.csv"
    path.write_text(pd.DataFrame(rows).to_csv(index=False))  # hand-made study table
    return str(path)


def no_mesh_errors(table) -> str:
    """A mesh error table of no muscles beside ``table``: the FE meshes at the study table's
    recorded errors."""
    path = Path(table).with_name("no_mesh_errors.csv")
    path.write_text("muscle,mesh,shift_per_threshold,relative_error,fe_failed,D0_mm,t0_mm,"
                    "L0_mm\n")
    return str(path)


def auto(table, **params) -> AutoModel:
    """Auto on the hand-made study table; the FE meshes at its recorded errors (no mesh error
    table), unless ``mesh_errors`` is given."""
    params.setdefault("mesh_errors", no_mesh_errors(table))
    return AutoModel(table=table, build=fake_build, **params)


P = np.array([0.5, 1.5, 2.5])


def _bound_pct(spec: str, D0=35.0, t0=2.5, eps=0.05, **muscle) -> np.ndarray:
    """The bound of the module docstring, computed here from its definition."""
    ref = make_model("axisym", mesh="coarse", **muscle).predict(P, D0, t0, eps).force_N
    force = build_spec(spec, **muscle).predict(P, D0, t0, eps).force_N
    return 100 * (np.abs(force - ref) + STD_FACTOR * STD_N) / ref.max()


def test_the_cheapest_model_whose_bound_meets_the_tolerance_answers(table_path):
    thick = _bound_pct("thickwall").max()
    eq2 = _bound_pct("eq2:diameter=braid").max()
    assert thick < eq2  # the wall's work is what Equation 2 leaves out
    tol = (thick + eq2) / 2
    pred = auto(table_path, tolerance=tol / 100).predict(P, 35.0, 2.5, 0.05)
    assert set(pred.extras["model_used"]) == {"thickwall"}
    np.testing.assert_allclose(pred.extras["error_bound_pct"], _bound_pct("thickwall"))
    np.testing.assert_array_equal(pred.force_N,
                                  make_model("thickwall").predict(P, 35.0, 2.5, 0.05).force_N)
    assert "|thickwall - surrogate| + 3 x the surrogate's calibrated std" in explain(pred)
    # named as every table names it: the registry's label
    assert explain(pred, label=model_label).startswith(
        "auto: Thick-wall (Klute-Hannaford) for 3 of 3 points")
    # above Equation 2's bound, the cheaper one answers
    loose = auto(table_path, tolerance=min(0.99, 1.01 * eq2 / 100)).predict(P, 35.0, 2.5, 0.05)
    assert set(loose.extras["model_used"]) == {"eq2-braid"}


def test_below_every_closed_form_the_surrogate_then_the_mesh_answer(table_path):
    ref = make_model("axisym", mesh="coarse").predict(P, 35.0, 2.5, 0.05).force_N
    surrogate_bound = 100 * STD_FACTOR * STD_N / ref.max()
    pred = auto(table_path, tolerance=1.01 * surrogate_bound / 100).predict(P, 35.0, 2.5, 0.05)
    assert set(pred.extras["model_used"]) == {"surrogate-muscle-gp"}
    tight = auto(table_path, tolerance=0.9 * surrogate_bound / 100).predict(P, 35.0, 2.5, 0.05)
    # the coarse mesh's recorded 0.4 % x 1.5 = 0.6 % meets it only if it is above 0.6 %
    expected = "axisym-coarse" if 0.9 * surrogate_bound >= MESH_SAFETY * 0.4 else "axisym-fine"
    assert set(tight.extras["model_used"]) == {expected}


def test_every_muscle_parameter_reaches_the_candidates(table_path):
    tol = 1.01 * _bound_pct("thickwall", L0_mm=150.0, theta0_deg=30.0).max() / 100
    model = auto(table_path, tolerance=tol, L0_mm=150.0, theta0_deg=30.0)
    pred = model.predict(P, 35.0, 2.5, 0.05)
    assert set(pred.extras["model_used"]) == {"thickwall"}
    np.testing.assert_array_equal(pred.force_N, make_model(
        "thickwall", L0_mm=150.0, theta0_deg=30.0).predict(P, 35.0, 2.5, 0.05).force_N)
    assert pred.params["L0_mm"] == 150.0 and pred.params["theta0_deg"] == 30.0


def test_outside_the_surrogates_box_only_the_fe_answers(table_path):
    pred = auto(table_path, tolerance=0.5).predict(P, 55.0, 2.5, 0.05)  # D0 > 50: no reference
    assert set(pred.extras["model_used"]) == {"axisym-coarse"}  # 0.6 % <= 50 %: the mesh
    assert "mesh error" in explain(pred)
    strict = auto(table_path, tolerance=0.005).predict(P, 55.0, 2.5, 0.05)
    assert set(strict.extras["model_used"]) == {"axisym-fine"}
    assert "outside the surrogate's box" in explain(strict)


RANGE_STD_N = 1.0


def test_outside_the_default_box_the_range_surrogate_answers_and_never_inside(table_path):
    built = []

    def build(spec, **muscle):
        built.append(spec)
        if spec == RANGE_SPEC:  # the practical range's: valid up to D0 60 mm, its own std
            return FakeSurrogate(std_N=RANGE_STD_N, D0_max_mm=60.0, L0_mm=282.0, **muscle)
        return fake_build(spec, **muscle)

    def run(D0, tolerance):
        return AutoModel(table=table_path, build=build, tolerance=tolerance,
                         mesh_errors=no_mesh_errors(table_path)
                         ).predict(P, D0, 2.5, 0.05)

    ref = make_model("axisym", mesh="coarse").predict(P, 55.0, 2.5, 0.05).force_N
    # the range surrogate's std counts RANGE_STD_FACTOR times in the bounds where it is the
    # reference, its own and a closed form's: 3 of it were exceeded in 4 % of fresh calls of
    # the range, by up to 5.2 of it (benchmarks/bench_auto.py --range practical)
    assert RANGE_STD_FACTOR == 6.0 and STD_FACTOR == 3.0
    bound = 100 * RANGE_STD_FACTOR * RANGE_STD_N / ref.max()
    thick = 100 * (np.abs(make_model("thickwall").predict(P, 55.0, 2.5, 0.05).force_N - ref)
                   + RANGE_STD_FACTOR * RANGE_STD_N) / ref.max()
    assert bound < thick.max()  # a tolerance between them leaves the surrogate the cheapest
    pred = run(55.0, 1.01 * bound / 100)
    assert set(pred.extras["model_used"]) == {RANGE_PREDICTOR}
    np.testing.assert_allclose(pred.extras["error_bound_pct"], bound)
    np.testing.assert_array_equal(pred.force_N, ref)
    assert "practical range's surrogate" in explain(pred)
    assert spec_of(RANGE_PREDICTOR) == RANGE_SPEC
    # its bound is its calibrated std: below it, the mesh answers
    assert set(run(55.0, 0.9 * bound / 100).extras["model_used"]) != {RANGE_PREDICTOR}
    # inside the default's box the default answers and the range's is never built
    built.clear()
    inside = run(35.0, 0.05)
    assert RANGE_SPEC not in built
    assert RANGE_PREDICTOR not in set(inside.extras["model_used"])


def test_a_mesh_answering_where_the_range_surrogate_is_unsure_says_its_bound_and_where(
        table_path):
    # The practical range's surrogate missed fresh muscles by up to 100 % of their force
    # (surrogate_range_gp_pooled.json's worst muscles), each where its std was wide; auto's
    # 6 std kept it out, and the FE answered with no word of why (a user asking for 5 % on the
    # worst muscle, theta0 17 deg near the lock, got the coarse mesh and the mesh's bound only).
    def build(spec, **muscle):
        if spec == RANGE_SPEC:
            return FakeSurrogate(std_N=RANGE_STD_N, D0_max_mm=60.0, L0_mm=282.0, **muscle)
        return fake_build(spec, **muscle)

    ref = make_model("axisym", mesh="coarse").predict(P, 55.0, 2.5, 0.05).force_N
    own = 100 * RANGE_STD_FACTOR * RANGE_STD_N / ref.max()
    pred = AutoModel(table=table_path, build=build, tolerance=0.9 * own / 100,
                     mesh_errors=no_mesh_errors(table_path)).predict(P, 55.0, 2.5, 0.05)
    assert set(pred.extras["model_used"]) <= {"axisym-coarse", "axisym-medium", "axisym-fine"}
    said = explain(pred)
    assert (f"; the practical range's surrogate's own bound here is up to {own:.3g}% (6 x its "
            f"std), where it errs most: {RANGE_WORST})") in said
    assert STD_CAVEAT not in said  # the mesh's bound rests on its measured error
    assert "braid angle below 20 deg" in RANGE_WORST
    # where it answers, nothing is added
    answered = AutoModel(table=table_path, build=build, tolerance=1.01 * own / 100,
                         mesh_errors=no_mesh_errors(table_path)).predict(P, 55.0, 2.5, 0.05)
    assert "own bound" not in explain(answered)


def test_a_bound_from_a_surrogates_std_says_it_bounds_most_calls_not_every_one(table_path):
    # The range's surrogate answered a fresh call of the practical range (bench_auto.py --range
    # practical --seed 2026120602) 0.42 % off the fine mesh under a stated bound of 0.35 %
    # (7.17 of its std): asked for 0.4 %, auto answered beyond it. A bound from a surrogate's
    # std says what it is; a mesh's, from its measured error, does not.
    thick = _bound_pct("thickwall").max()
    pred = auto(table_path, tolerance=1.01 * thick / 100).predict(P, 35.0, 2.5, 0.05)
    assert set(pred.extras["model_used"]) == {"thickwall"}
    assert explain(pred).endswith(
        "(|thickwall - surrogate| + 3 x the surrogate's calibrated std); an estimate from a "
        "surrogate's std, which most calls' errors stay within, not every one's")
    # the coarse mesh's bound, 0.4 % x MESH_SAFETY, meets 0.65 %; the surrogate's 3 std do not
    mesh = auto(table_path, tolerance=0.65 / 100).predict(P, 35.0, 2.5, 0.05)
    assert set(mesh.extras["model_used"]) == {"axisym-coarse"}
    assert STD_CAVEAT not in explain(mesh)
    # it says the surrogate's own bound, which kept the surrogate and the closed forms out
    own = 100 * STD_FACTOR * STD_N / make_model("axisym", mesh="coarse").predict(
        P, 35.0, 2.5, 0.05).force_N.max()
    assert f"; the surrogate's own bound here is up to {own:.3g}% (3 x its std))" in explain(mesh)


def test_per_point_may_mix_models_a_sweep_never_does(table_path):
    bounds = _bound_pct("thickwall")
    tol = (bounds.min() + bounds.max()) / 2 / 100  # thickwall meets it at some points only
    sweep = auto(table_path, tolerance=tol).predict(P, 35.0, 2.5, 0.05)
    assert len(set(sweep.extras["model_used"])) == 1
    mixed = auto(table_path, tolerance=tol, per_point=True).predict(P, 35.0, 2.5, 0.05)
    used = mixed.extras["model_used"]
    assert "thickwall" in used and len(set(used)) == 2
    assert (mixed.extras["error_bound_pct"][used != "axisym-fine"] <= 100 * tol).all()


class RisingStdSurrogate(FakeSurrogate):
    """The fake surrogate with a std rising with the pressure, ``std_N`` at the call's top."""

    def _forces(self, P, D0, t0, eps):
        out = super()._forces(P, D0, t0, eps)
        return {**out, "force_std_N": self.std_N * np.asarray(P, dtype=float) / np.max(P)}


def test_per_point_a_point_takes_its_muscles_largest_std_of_the_call(table_path):
    # A fresh muscle of the practical range (seed 20263515, t0 0.3 D0, theta0 18 deg) whose
    # threshold the range surrogate put 15 of its std low: asked for 5 % per point, it answered
    # 6 bar by its std there (6 std, 4.9 % of the sweep's force) 8.9 % off the fine mesh, while
    # 6 of its largest std of the sweep, the quantity the factor is measured on, are 9.75 %.
    def build(spec, **muscle):
        if spec == RANGE_SPEC:
            return RisingStdSurrogate(std_N=RANGE_STD_N, D0_max_mm=60.0, L0_mm=282.0, **muscle)
        return fake_build(spec, **muscle)

    ref = make_model("axisym", mesh="coarse").predict(P, 55.0, 2.5, 0.05).force_N
    largest = 100 * RANGE_STD_FACTOR * RANGE_STD_N / ref.max()
    # between the bound at the lowest pressure, by its own std, and the call's largest
    tol = 0.9 * largest / 100
    assert 100 * RANGE_STD_FACTOR * RANGE_STD_N * P[0] / P[-1] / ref.max() < 100 * tol
    pred = AutoModel(table=table_path, build=build, tolerance=tol, per_point=True,
                     mesh_errors=no_mesh_errors(table_path)).predict(P, 55.0, 2.5, 0.05)
    used = pred.extras["model_used"]
    assert RANGE_PREDICTOR not in set(used) and "thickwall" not in set(used)
    assert set(used) <= {"axisym-coarse", "axisym-medium", "axisym-fine"}
    # above the call's largest, it answers every point, per point as for the call
    for per_point in (True, False):
        wide = AutoModel(table=table_path, build=build, tolerance=1.01 * largest / 100,
                         per_point=per_point, mesh_errors=no_mesh_errors(table_path)
                         ).predict(P, 55.0, 2.5, 0.05)
        assert set(wide.extras["model_used"]) == {RANGE_PREDICTOR}
        np.testing.assert_allclose(wide.extras["error_bound_pct"],
                                   largest * (P / P[-1] if not per_point else 1.0))


@pytest.fixture(scope="module")
def mesh_table(tmp_path_factory):
    """A hand-made mesh error table: the coarse mesh's threshold 0.2 % of it off and 0.1 % of
    the force beyond it (times SAFETY 1.5 in the bound)."""
    path = tmp_path_factory.mktemp("auto") / "mesh_errors.csv"
    path.write_text(pd.DataFrame([{"muscle": 0, "mesh": "coarse", "shift_per_threshold": 0.002,
                                   "relative_error": 0.001, "fe_failed": False,
                                   "D0_mm": 35.0, "t0_mm": 2.5, "L0_mm": 282.0}]).to_csv(
        index=False))
    return str(path)


def test_a_mesh_bound_is_on_the_scale_of_the_call(table_path, mesh_table):
    # D0 55 mm: outside the fake surrogate's box, only the FE answers. The coarse mesh's bound
    # is a P* A + b F (computed here from the mesh's own forces and threshold), relative to the
    # largest force of the call less its bound: over a sweep its largest force, at one point
    # just above the threshold the small force there. A tolerance between the two: the coarse
    # mesh answers the sweep, the fallback the single point.
    a, b = 1.5 * 0.002, 1.5 * 0.001
    coarse = make_model("axisym", mesh="coarse").predict(P, 55.0, 2.5, 0.05)
    F, P_star = coarse.force_N, float(coarse.extras["threshold_pressure_bar"][0])
    error = a * P_star * F / (P - P_star) + b * F
    sweep_bound = 100 * error / np.max(F - error)
    step = 0.001  # bar above the threshold: a force under 1 N, the scale's floor
    F1 = float(make_model("axisym", mesh="coarse").predict(P_star + step, 55.0, 2.5,
                                                           0.05).force_N)
    error1 = a * P_star * F1 / step + b * F1
    single_bound = 100 * error1 / max(F1 - error1, 1.0)
    tol = np.sqrt(sweep_bound.max() * single_bound) / 100
    sweep = auto(table_path, tolerance=tol, mesh_errors=mesh_table).predict(P, 55.0, 2.5, 0.05)
    assert set(sweep.extras["model_used"]) == {"axisym-coarse"}
    np.testing.assert_allclose(sweep.extras["error_bound_pct"], sweep_bound, rtol=1e-9)
    assert "mesh error at this call's scale: 0.300 % of P* x the slope + 0.150 %" in explain(
        sweep)
    near = auto(table_path, tolerance=tol, mesh_errors=mesh_table).predict(
        P_star + step, 55.0, 2.5, 0.05)
    assert set(np.ravel(near.extras["model_used"])) == {"axisym-fine"}
    chosen = AutoModel(table=table_path, build=fake_build, tolerance=0.99,
                       mesh_errors=mesh_table).choose(P_star + step, 55.0, 2.5, 0.05)
    assert chosen["model_used"][0] == "axisym-coarse"
    assert chosen["error_bound_pct"][0] == pytest.approx(single_bound, rel=1e-3)


def no_surrogate_build(spec: str, **muscle) -> ForceModel:
    """:func:`fake_build` with no muscle in the fake surrogate's box: only the FE answers."""
    if spec == "surrogate":
        return fake_build(spec, **muscle).__class__(D0_max_mm=0.0, **muscle)
    return fake_build(spec, **muscle)


@pytest.mark.parametrize("L0_mm, resolved", [(282.0, True), (1000.0, False)])
def test_a_mesh_answers_only_where_its_end_zone_bound_was_measured(table_path, mesh_table,
                                                                    L0_mm, resolved):
    # A thin tube (D0 6, t0 0.5 mm) 1 m long: the coarse mesh's element at the clamp spans 7.1
    # bending lengths sqrt(R t0), beyond the 4 its bound was measured to (the shipped table's
    # tube at 5.8 was 7.2 % off); 282 mm long, 2.0
    assert bool(mesh_errors.end_resolution(6.0, 0.5, L0_mm, "coarse")
                <= mesh_errors.MAX_END_RESOLUTION) is resolved
    chosen = AutoModel(table=table_path, build=no_surrogate_build, tolerance=0.99,
                       L0_mm=L0_mm, mesh_errors=mesh_table).choose(P, 6.0, 0.5, 0.05)
    assert set(chosen["model_used"]) == {"axisym-coarse" if resolved else "axisym-fine"}


@pytest.mark.parametrize("D0_mm, L0_mm, theta0_deg, measured", [
    (55.0, 282.0, 30.0, True), (62.0, 282.0, 30.0, False), (55.0, 1100.0, 30.0, False),
    (55.0, 282.0, 42.0, False)])
def test_a_mesh_answers_only_inside_the_range_its_bound_was_measured_over(
        table_path, mesh_table, D0_mm, L0_mm, theta0_deg, measured):
    # a tube of 62 mm (the practical range ends at 60) was answered by the coarse mesh with the
    # bound measured inside the range: a promise made where it was never tested
    chosen = AutoModel(table=table_path, build=no_surrogate_build, tolerance=0.99,
                       L0_mm=L0_mm, theta0_deg=theta0_deg, mesh_errors=mesh_table).choose(
        P, D0_mm, 2.5, 0.05)
    assert set(chosen["model_used"]) == {"axisym-coarse" if measured else "axisym-fine"}
    # per point: the points inside answered by the mesh, those beyond the range by the fine one
    mixed = AutoModel(table=table_path, build=no_surrogate_build, tolerance=0.99,
                      mesh_errors=mesh_table, per_point=True).choose(
        np.array([1.0, 1.0]), np.array([55.0, 62.0]), 2.5, 0.05)
    assert list(mixed["model_used"]) == ["axisym-coarse", "axisym-fine"]
    # the fine mesh answers beyond the range as the reference, whose own error is measured
    # only inside it: no bound there (it said 0 %), the reason given
    assert mixed["error_bound_pct"][0] > 0 and np.isnan(mixed["error_bound_pct"][1])
    assert mixed["bound_source"][1].endswith("the fine mesh's own error is not measured: no "
                                             "bound")


@pytest.mark.slow  # the default surrogate (GP training) and the fine mesh
def test_a_single_point_just_above_the_threshold_meets_the_tolerance():
    # Issue 34: at 0.5 % auto answered this single point (0.41 bar, just above P*) from the
    # coarse mesh with its sweep-scale bound, 0.08 %: 11.662 N, 0.77 % off the fine mesh's
    # 11.753 N. On the scale of the call the coarse mesh's bound is several %.
    muscle = {"L0_mm": 231.61, "theta0_deg": 28.864, "C10_MPa": 0.047421, "C01_MPa": 0.06696}
    point = (0.41, 35.405, 2.4931, 0.16289)
    chosen = build_spec("auto:tolerance=0.005", **muscle).choose(*point)
    fine = float(build_spec("axisym:mesh=fine", **muscle).predict(*point).force_N)
    assert fine == pytest.approx(11.753, abs=0.01)
    assert chosen["model_used"][0] != "axisym-coarse"
    pred = build_spec("auto:tolerance=0.005", **muscle).predict(*point)
    assert abs(float(pred.force_N) - fine) <= 0.005 * fine


def test_bad_tolerance_and_missing_table_are_clear_errors(table_path, tmp_path):
    with pytest.raises(ValueError, match=r"tolerance=1\.5 is invalid"):
        auto(table_path, tolerance=1.5).predict(1.0, 35.0, 2.5, 0.05)
    with pytest.raises(ValueError, match="run `mkm study`"):
        auto(str(tmp_path / "none.csv")).predict(1.0, 35.0, 2.5, 0.05)
    # a mesh error table named and absent: was ignored, the meshes bound by the study table's
    # recorded errors instead, and no word of it
    missing = tmp_path / "mesh_errors.csv"
    with pytest.raises(ValueError) as refused:
        auto(table_path, mesh_errors=str(missing))
    assert str(refused.value) == (f"mesh_errors={str(missing)!r} is invalid: no such file; "
                                  "expected a mesh error table written by `mkm study "
                                  "--mesh-muscles N` (mesh_errors.csv)")
    # tables that are not the study's: one line naming the file (were a KeyError traceback
    # and pandas' two lines)
    other = tmp_path / "other.csv"
    other.write_text("a,b\n1,2\n", encoding="utf-8")
    with pytest.raises(ValueError, match=re.escape(
            f"mesh error table {str(other)!r} lacks column(s) mesh, fe_failed, "
            "shift_per_threshold, relative_error, D0_mm, t0_mm, L0_mm: expected the table `mkm "
            "study --mesh-muscles N` writes (mesh_errors.csv)")):
        auto(table_path, mesh_errors=str(other), tolerance=0.005).predict(
            1.0, 35.0, 2.5, 0.05)
    ragged = tmp_path / "ragged.csv"
    ragged.write_text("a\nb\nc,d,e,f\n", encoding="utf-8")
    for text, said in ((ragged, "is no CSV table (Error tokenizing data."),
                       (other, "lacks column(s) predictor, spec")):
        with pytest.raises(ValueError, match=re.escape(f"study table {str(text)!r} {said}")):
            auto(str(text)).predict(1.0, 35.0, 2.5, 0.05)


@pytest.fixture(scope="module")
def fresh_muscles():
    """Three random muscles of the box (L0, theta0 and rubber included) and the fine FE's
    forces at 0.5, 1.5 and 2.5 bar, solved once for both tolerances below."""
    rng = np.random.default_rng(20261202)
    pressures = np.array([0.5, 1.5, 2.5])
    drawn = []
    for _ in range(3):
        muscle = {"L0_mm": rng.uniform(150, 400), "theta0_deg": rng.uniform(29, 37),
                  "C10_MPa": 0.0694 * (s := rng.uniform(0.7, 1.4)), "C01_MPa": 0.0628 * s}
        D0, t0, eps = rng.uniform(32, 48), rng.uniform(2.2, 3.8), rng.uniform(0.0, 0.18)
        fine = build_spec("axisym:mesh=fine", **muscle).predict(pressures, D0, t0, eps)
        drawn.append((muscle, (pressures, D0, t0, eps), fine.force_N))
    return drawn


@pytest.mark.slow  # the default surrogate (GP training) and the fine mesh
@pytest.mark.parametrize("tolerance", [0.01, 0.05])
def test_the_promise_at_fresh_random_muscles(fresh_muscles, tolerance):
    """The chosen model is within the tolerance of the fine FE at random muscles of the box
    (the benchmark benchmarks/bench_auto.py runs >= 200)."""
    for muscle, where, fine in fresh_muscles:
        pred = build_spec(f"auto:tolerance={tolerance}", **muscle).predict(*where)
        err = 100 * np.abs(pred.force_N - fine) / np.nanmax(fine)
        assert (err <= 100 * tolerance).all(), (muscle, *where[1:], err, explain(pred))


@pytest.mark.slow  # the default surrogate (GP training)
def test_cli_solve_auto_says_what_it_used(mkm_run):
    code, out, err = mkm_run(["fem", "solve", "--model", "auto", "--tolerance", "2%", "--D0",
                              "35", "--t0", "2.5", "--eps", "0.05", "--L0", "150"])
    assert code == 0
    from io import StringIO

    rows = pd.read_csv(StringIO(out))
    assert len(rows) == 11 and rows["valid"].all()
    assert set(rows["model_used"]) <= set(read_model_errors()["predictor"])
    assert len(set(rows["model_used"])) == 1
    chosen = rows[rows["model_used"] != "axisym-fine"]
    assert (chosen["error_bound_pct"] <= 2.0).all()
    assert err.startswith("auto: ") and " for 11 of 11 points" in err


def test_a_gap_never_reaches_the_surrogate(table_path):
    """gap_mm other than 0: the surrogate takes no gap, so nothing estimates the reference with
    one and no closed form's error is bounded there: only the FE meshes (at their mesh error),
    with the gap, may answer."""
    with_gap = make_model("axisym", mesh="coarse", gap_mm=0.5).predict(P, 35.0, 2.5, 0.05)
    gap_free = make_model("axisym", mesh="coarse").predict(P, 35.0, 2.5, 0.05)
    thick = _bound_pct("thickwall")
    # where the thick-wall form meets the tolerance without a gap, with one the FE answers
    tolerance = max(1.01 * thick.max() / 100, 0.01)
    assert set(auto(table_path, tolerance=tolerance).predict(P, 35.0, 2.5, 0.05)
               .extras["model_used"]) <= {"thickwall", "surrogate-muscle-gp", "eq2-inner"}
    pred = auto(table_path, tolerance=tolerance, gap_mm=0.5).predict(P, 35.0, 2.5, 0.05)
    assert set(pred.extras["model_used"]) == {"axisym-coarse"}
    np.testing.assert_array_equal(pred.force_N, with_gap.force_N)
    # the answer is the gapped muscle's (a higher threshold), not the gap-free one
    assert (with_gap.extras["threshold_pressure_bar"]
            > gap_free.extras["threshold_pressure_bar"]).all()
    assert not np.allclose(with_gap.force_N, gap_free.force_N, rtol=1e-3)
    assert explain(pred).splitlines()[0] == (
        "auto: gap_mm=0.5: the surrogate models no gap between tube and braid, so nothing "
        "bounds a closed form's error with one; the candidates are axisym, with the gap")
    assert pred.params["gap_mm"] == 0.5

    # where the surrogate alone meets the tolerance without a gap, with one the FE answers,
    # with the gap: the coarse mesh within its mesh bound, else the fallback (here coarse too)
    fe_gap = make_model("axisym", mesh="coarse", gap_mm=0.5).predict(P, 35.0, 2.5, 0.05)
    ref = make_model("axisym", mesh="coarse").predict(P, 35.0, 2.5, 0.05).force_N
    tol = 1.01 * STD_FACTOR * STD_N / ref.max()
    assert tol < thick.max() / 100  # the thick-wall form does not meet it
    assert set(auto(table_path, tolerance=tol).predict(P, 35.0, 2.5, 0.05)
               .extras["model_used"]) == {"surrogate-muscle-gp"}
    # (the coarse mesh's bound: 1.5 x its recorded 0.4 % = 0.6 %); the fallback is the real
    # fine mesh, with the gap: the coarse one's forces to 4e-4 (measured), 1e-3
    for tolerance, used, rtol in ((0.01, "axisym-coarse", 0.0), (0.005, "axisym-fine", 1e-3)):
        pred = auto(table_path, tolerance=tolerance, gap_mm=0.5).predict(P, 35.0, 2.5, 0.05)
        assert set(pred.extras["model_used"]) == {used}
        np.testing.assert_allclose(pred.force_N, fe_gap.force_N, rtol=rtol)
    # outside the surrogate's box the FE answers, with the gap
    outside = auto(table_path, tolerance=0.5, gap_mm=0.5).predict(P, 55.0, 2.5, 0.05)
    assert set(outside.extras["model_used"]) == {"axisym-coarse"}
    np.testing.assert_array_equal(outside.force_N, make_model(
        "axisym", mesh="coarse", gap_mm=0.5).predict(P, 55.0, 2.5, 0.05).force_N)


def test_a_zero_gap_changes_nothing(table_path):
    tol = 1.01 * _bound_pct("thickwall").max() / 100
    plain = auto(table_path, tolerance=tol).predict(P, 35.0, 2.5, 0.05)
    zero = auto(table_path, tolerance=tol, gap_mm=0.0).predict(P, 35.0, 2.5, 0.05)
    np.testing.assert_array_equal(zero.force_N, plain.force_N)
    for key in ("model_used", "error_bound_pct", "bound_source"):
        np.testing.assert_array_equal(zero.extras[key], plain.extras[key])


@pytest.mark.slow  # the fine mesh
def test_cli_solve_auto_with_a_gap_meets_its_tolerance_against_the_fine_mesh(mkm_run):
    # the thick-wall form answered a muscle with a gap at its gap-free bound, 0.44 %, and was
    # 0.58 % off the fine mesh with the gap (658.69 N against 654.88 N at 2.5 bar), over the
    # 0.5 % asked: now only the FE answers, within its mesh bound
    from io import StringIO

    muscle = ["--D0", "30", "--t0", "2", "--eps", "0.05"]
    code, out, err = mkm_run(["fem", "solve", "--model", "auto:gap_mm=0.5", "--tolerance",
                              "0.5%", *muscle])
    assert code == 0, err
    rows = pd.read_csv(StringIO(out))
    assert set(rows["model_used"]) <= {"axisym-medium", "axisym-coarse", "axisym-fine"}, err
    fine = make_model("axisym", mesh="fine", gap_mm=0.5).predict(
        rows["pressure_bar"], 30.0, 2.0, 0.05).force_N
    err_pct = 100 * np.abs(rows["force_N"] - fine) / fine.max()
    assert (err_pct <= rows["error_bound_pct"] + 1e-4).all() and err_pct.max() <= 0.5


def test_an_identified_gap_is_autos_default_as_the_thick_walls(tmp_path):
    from mkm.fem.calibration import Calibration

    shipped = Calibration.shipped()
    entries = {**shipped.entries, "thickwall": {**shipped.entry("thickwall"), "gap_mm": 0.7}}
    learnt = Calibration(tmp_path / "calibration.json", entries)
    assert build_spec("auto", learnt).resolved_gap_mm() == 0.7
    assert build_spec("auto:gap_mm=0", learnt).resolved_gap_mm() == 0.0  # asked: none
    assert build_spec("auto").resolved_gap_mm() == 0.0  # the shipped calibration has none


def test_a_gap_the_calibration_holds_keeps_the_surrogate_out_too(table_path, mesh_table,
                                                                 tmp_path):
    """A muscle identified with a gap (its calibration entry holds ``gap_mm``): auto answers
    with the gap as if it had been given, and says the surrogate cannot."""
    lab = tmp_path / "calibration.json"
    lab.write_text(json.dumps({"thickwall": {"theta0_deg": 30.0, "gap_mm": 0.5},
                               "axisym": {"theta0_deg": 30.0, "gap_mm": 0.5}}))
    calibration = Calibration.load(lab)

    def build(spec, **muscle):
        return fake_build(spec, **muscle) if spec == "surrogate" else build_spec(
            spec, calibration=calibration, **muscle)

    given = AutoModel(table=table_path, build=build, tolerance=0.01, gap_mm=0.5,
                      theta0_deg=30.0, mesh_errors=mesh_table)
    held = AutoModel(table=table_path, build=build, tolerance=0.01, theta0_deg=30.0,
                     mesh_errors=mesh_table)
    assert held.resolved_gap_mm() == 0.5
    a, b = (m.predict(P, 35.0, 2.5, 0.05) for m in (given, held))
    # the hand-made mesh table's coarse bound (0.17 % at most over this sweep) meets 1 %
    assert set(b.extras["model_used"]) == {"axisym-coarse"}
    np.testing.assert_array_equal(a.force_N, b.force_N)
    np.testing.assert_array_equal(b.force_N, make_model(
        "axisym", mesh="coarse", theta0_deg=30.0, gap_mm=0.5).predict(P, 35.0, 2.5, 0.05).force_N)
    assert explain(b).startswith("auto: gap_mm=0.5: the surrogate models no gap")
    # without the gap the surrogate, cheaper, meets the same tolerance and answers
    free = AutoModel(table=table_path, build=fake_build, tolerance=0.01, theta0_deg=30.0)
    assert set(free.predict(P, 35.0, 2.5, 0.05).extras["model_used"]) == {
        "surrogate-muscle-gp"}
    assert "gap_mm" not in explain(free.predict(P, 35.0, 2.5, 0.05))


def test_a_surrogate_about_to_train_is_announced_first(monkeypatch):
    """A first use outside the default's box trains the practical range's surrogate (a minute
    where its kernels are not shipped): auto says so before it starts, with the promise of how
    long, and not once cached."""
    import mkm.surrogate.train as train
    from mkm.auto import _announce_first_training
    from mkm.surrogate import kinds

    monkeypatch.setattr(train, "is_cached", lambda kind: False)
    with pytest.warns(UserWarning, match=f"training the surrogate {kinds.RANGE} on first use, "
                                         ".*; later calls load it"):
        _announce_first_training(kinds.RANGE)
    monkeypatch.setattr(train, "is_cached", lambda kind: True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        _announce_first_training(kinds.RANGE)


def test_past_the_braid_lock_auto_says_the_braid_locks_as_its_fallback_does(table_path):
    # eps 0.35 is past the lock at 32 deg (eps_max 0.319): no candidate is valid, the fallback
    # FE finds no state and names the physical limit, which auto passes on, so its points are
    # classified as the braid locking (mkm.fem.outcomes), not as a solve that failed
    from mkm.auto import FALLBACK_SPEC
    from mkm.fem.outcomes import BRAID_LOCKS, classify

    def build(spec, **muscle):  # the coarse mesh stands in for the fine one: fast
        return fake_build("axisym:mesh=coarse" if spec == FALLBACK_SPEC else spec, **muscle)

    pred = AutoModel(table=table_path, build=build, tolerance=0.02, theta0_deg=32.0,
                     mesh_errors=no_mesh_errors(table_path)
                     ).predict(P, 30.0, 2.0, 0.35)
    assert set(pred.extras["model_used"]) == {"axisym-fine"}
    assert not pred.converged.any() and np.isnan(pred.force_N).all()
    assert classify(pred).tolist() == [BRAID_LOCKS] * P.size
    # no force, no bound: it read 0 %, as if the reference had answered exactly
    assert np.isnan(pred.extras["error_bound_pct"]).all()


def test_a_fallback_that_does_not_converge_names_why(table_path):
    # a thick, stiff tube at 15 deg near the lock (a corner of the practical range): the FE's
    # threshold search inverts elements; auto answered `not converged` without the solver's
    # reason, which the FE model itself gives in its `failure` column
    from mkm.auto import FALLBACK_SPEC

    def build(spec, **muscle):  # the coarse mesh stands in for the fine one: fast
        return fake_build("axisym:mesh=coarse" if spec == FALLBACK_SPEC else spec, **muscle)

    pred = AutoModel(table=table_path, build=build, tolerance=0.02, theta0_deg=15.0,
                     L0_mm=180.0, C10_MPa=0.6, C01_MPa=0.55,
                     mesh_errors=no_mesh_errors(table_path)).predict(P, 60.0, 6.0, 0.3683)
    assert set(pred.extras["model_used"]) == {"axisym-fine"}
    assert not pred.converged.any() and np.isnan(pred.force_N).all()
    assert all("threshold search failed: element inversion" in f
               for f in np.ravel(pred.extras["failure"]))


def test_autos_nominal_angle_is_its_references(tmp_path):
    # a report's tolerance band asks every model its nominal muscle; auto's candidates each
    # take their own calibrated angle, bounded against the fine FE mesh, so auto's is the
    # reference's (it had none: `mkm report RUN --models auto` failed on every run)
    from mkm.uncertainty import nominal_parameters

    shipped = Calibration.shipped()
    assert nominal_parameters(build_spec("auto"), 30.0, 3.0, 0.1)["theta0_deg"] == \
        shipped.entry("axisym")["theta0_deg"]
    lab = Calibration(tmp_path / "calibration.json",
                      {**shipped.entries, "axisym": {**shipped.entry("axisym"),
                                                     "theta0_deg": 31.25}})
    assert nominal_parameters(build_spec("auto", lab), 30.0, 3.0, 0.1)["theta0_deg"] == 31.25


@pytest.mark.slow
def test_a_report_of_auto_runs(tmp_path):
    from mkm.cli import main

    run = Path(__file__).resolve().parents[2] / "data" / "experimental" / \
        "20261123T084037Z_paper-prototype"
    assert main(["report", str(run), "--models", "auto", "--no-cache", "--no-progress",
                 "--out", str(tmp_path / "report")]) == 0
    summary = pd.read_csv(tmp_path / "report" / "summary.csv")
    assert list(summary["model"]) == ["auto"] and summary["band_pct"].notna().all()
