"""Verification of the axisymmetric FE model (coarse meshes: the whole file runs in well under
a minute).

The tests check physics with a fixed theta0 (32 deg, near the calibrated value), never the
calibration: closed-form limits (eps = 0, a free tube), the mid-section closed form of a long
muscle, the isometric lock's structure, mesh convergence and the failure reports.
"""

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.integrate import quad

from mkm.fem.eq2 import BAR_TO_MPA, chou_hannaford
from mkm.fem.fe.forms import braid_inextensibility
from mkm.fem.fe.model import Axisym, HalfMuscle, isometric_sweep
from mkm.fem.fe.newton import load_path
from mkm.fem.materials import SILASTIC_S, MooneyRivlin
from mkm.fem.thickwall import ThickWall

THETA0 = 32.0
SOFT = MooneyRivlin(1e-5, 1e-5, source="a nearly massless membrane for the braid limit")


@pytest.mark.parametrize(("D0", "t0", "material", "braid"), [
    (35.0, 2.5, SILASTIC_S, "bonded"), (30.0, 4.0, SILASTIC_S, "bonded"),
    (35.0, 0.1, SOFT, "bonded"), (35.0, 2.5, SILASTIC_S, "sliding")])
def test_eps0_force_is_equation2_with_braid_diameter(D0, t0, material, braid):
    # At eps = 0 an inextensible braid and an incompressible wall admit no deformation: the
    # wall carries a uniform hydrostatic stress -P, the braid hoop tension P Ro and axial
    # tension P Ro cot^2(theta0), so the cap force is P pi Ro^2 (2 cot^2 - 1) = Equation 2 with
    # the braid diameter D0 + 2 t0, for any wall (the thin, soft tube is the braid limit of the
    # issue). The discrete problem has that state as its exact solution: only round-off and the
    # Newton tolerance (1e-9 relative) remain, so 1e-7 is a safe bound.
    P = np.array([0.0, 0.5, 2.5])
    out = isometric_sweep(P, D0, t0, 0.0, THETA0, mesh="coarse", material=material,
                          braid=braid)
    assert out["converged"].all()
    np.testing.assert_allclose(out["force_N"], chou_hannaford(P, D0 + 2 * t0, 0.0, THETA0),
                               rtol=1e-7, atol=1e-9)


def plane_strain_inflation_pressure_MPa(ri_mm, Ri_mm, Ro_mm, C10, C01):
    """Pressure that inflates a free incompressible Mooney-Rivlin tube in plane strain to an
    inner radius ``ri_mm``.

    Plane strain (l_z = 1) and incompressibility give r^2 = R^2 + c with c = ri^2 - Ri^2, the
    hoop stretch l = r/R and radial stretch 1/l. Then I1 = I2 = l^2 + l^-2 + 1, so
    W = (C10 + C01)(l^2 + l^-2 - 2) and sigma_tt - sigma_rr = l dW/dl = 2 (C10 + C01)(l^2 - l^-2).
    Radial equilibrium d(sigma_rr)/dr = (sigma_tt - sigma_rr)/r with sigma_rr(ri) = -P and
    sigma_rr(ro) = 0 gives P = integral over [ri, ro] of (sigma_tt - sigma_rr)/r dr.
    """
    c = ri_mm**2 - Ri_mm**2
    ro = np.sqrt(Ro_mm**2 + c)

    def integrand(r):
        l2 = r**2 / (r**2 - c)
        return 2.0 * (C10 + C01) * (l2 - 1.0 / l2) / r

    return quad(integrand, ri_mm, ro, epsabs=1e-14, epsrel=1e-12)[0]


@pytest.mark.parametrize("pressure_bar", [0.1, 0.3])
def test_free_tube_inflation_matches_closed_form(pressure_bar):
    # No braid and the cap sliding radially at U = 0: a thick tube inflated in plane strain.
    D0, t0 = 35.0, 2.5
    half = HalfMuscle(D0, t0, 20.0, THETA0, SILASTIC_S, "coarse", braid=False, cap="sliding")
    [(y, report)] = half.held_path(half.rest_state(), 0.0, [pressure_bar * BAR_TO_MPA])
    assert report.converged
    ri = np.sqrt(half.cavity_volume(y) / (np.pi * half.H))  # uniform radius in plane strain
    assert ri > D0 / 2 * 1.05  # a large deformation, not a linear check
    expected = plane_strain_inflation_pressure_MPa(ri, D0 / 2, D0 / 2 + t0,
                                                   SILASTIC_S.C10_MPa, SILASTIC_S.C01_MPa)
    # P2 displacements interpolate r(R) = sqrt(R^2 + c) on two elements through the wall to
    # ~1e-5 (measured 2e-6); 1e-4 leaves room and would still catch a wrong law or load (>1e-2)
    assert expected == pytest.approx(pressure_bar * BAR_TO_MPA, rel=1e-4)


def test_isometric_lock_zero_below_threshold_and_linear_above():
    P = np.arange(0.0, 2.51, 0.25)
    out = isometric_sweep(P, 35.0, 2.5, 0.1, THETA0, mesh="coarse")
    assert out["converged"].all()
    Pstar = out["threshold_pressure_bar"][0]
    assert 0.1 < Pstar < 0.5  # eps = 10 % needs a fraction of a bar to shorten freely
    below = P <= Pstar
    assert np.all(out["force_N"][below] == 0.0)
    # above P* the force is affine in P (the braid fixes the kinematics; the wall's share is
    # nearly constant): a straight-line fit leaves < 0.5 % of the largest force, and it
    # crosses zero at P* (the force is continuous at the lock) within 0.02 bar
    Pa, Fa = P[~below], out["force_N"][~below]
    slope, intercept = np.polyfit(Pa, Fa, 1)
    assert np.max(np.abs(slope * Pa + intercept - Fa)) < 0.005 * Fa.max()
    assert -intercept / slope == pytest.approx(Pstar, abs=0.02)
    assert np.all(np.diff(Fa) > 0)


def test_threshold_grows_with_eps_and_wall_thickness():
    # the paper's observation: a thicker wall and a larger eps need more pressure to shorten
    thresholds = {(t0, eps): isometric_sweep([0.0], 35.0, t0, eps, THETA0, mesh="coarse")
                  ["threshold_pressure_bar"][0] for t0 in (2.0, 3.0) for eps in (0.05, 0.15)}
    assert thresholds[2.0, 0.05] < thresholds[2.0, 0.15]
    assert thresholds[2.0, 0.05] < thresholds[3.0, 0.05]


def test_long_muscle_tends_to_thickwall_like_one_over_length():
    # The mid-section of a long muscle is the thickwall closed form; the clamped caps keep the
    # ends narrow over about one diameter, so the FE slope dF/dP falls below thickwall's and
    # the FE threshold rises above it by amounts that shrink like 1/L0 (first order in the end
    # zone's share of the length). Measured gaps at L0 564, 1128, 2256 mm: slope 4.2, 2.0,
    # 1.0 %, threshold 2.6, 1.3, 0.68 %; each doubling halves them to within 7 %.
    D0, t0, eps, P = 35.0, 2.5, 0.1, np.array([1.5, 2.5])
    tw = ThickWall(theta0_deg=THETA0).predict(P, D0, t0, eps)
    slope_tw = np.diff(tw.force_N)[0] / np.diff(P)[0]
    threshold_tw = tw.extras["threshold_pressure_bar"][0]
    gaps = {}
    for L0 in (564.0, 1128.0, 2256.0):
        out = isometric_sweep(P, D0, t0, eps, THETA0, L0_mm=L0, mesh="medium")
        slope = np.diff(out["force_N"])[0] / np.diff(P)[0]
        gaps[L0] = ((slope_tw - slope) / slope_tw,
                    (out["threshold_pressure_bar"][0] - threshold_tw) / threshold_tw)
    for short, long in ((564.0, 1128.0), (1128.0, 2256.0)):
        for k in (0, 1):
            assert 0 < gaps[long][k] < gaps[short][k] < 0.05
            assert gaps[short][k] / gaps[long][k] == pytest.approx(2.0, rel=0.1)


def test_mesh_convergence_coarse_to_medium():
    # The study (`mkm fem convergence`) finds coarse within 0.1 % of fine; coarse and medium
    # within 0.5 % here would still flag a broken mesh level
    F = [isometric_sweep([2.5], 35.0, 2.5, 0.05, THETA0, mesh=m)["force_N"][0]
         for m in ("coarse", "medium")]
    assert F[0] == pytest.approx(F[1], rel=5e-3)


def test_beyond_the_braid_lock_the_braid_locks_a_physical_limit_not_a_solver_failure():
    # eps = 35 % is past the shortening where the braid reaches its locking angle (eps_max
    # 0.319 at 32 deg): the free muscle cannot get there with a positive pressure. No state is
    # found (converged False, force NaN), and the model names the limit: its outcome is the
    # braid locking, not "not converged"
    from mkm.fem.outcomes import BRAID_LOCKS, classify

    out = isometric_sweep([0.0, 1.0], 30.0, 2.0, 0.35, THETA0, mesh="coarse")
    assert not out["converged"].any()
    assert np.isnan(out["force_N"]).all()
    assert "braid passes its locking angle" in out["failure"][0]
    assert out["limit"].tolist() == [BRAID_LOCKS, BRAID_LOCKS]
    pred = Axisym(theta0_deg=THETA0, mesh="coarse").predict([0.0, 1.0], 30.0, 2.0, 0.35)
    assert classify(pred).tolist() == [BRAID_LOCKS, BRAID_LOCKS]
    # short of the lock nothing is named
    assert isometric_sweep([1.0], 30.0, 2.0, 0.1, THETA0, mesh="coarse")["limit"][0] == ""


def test_model_groups_points_and_reports_extras():
    model = Axisym(theta0_deg=THETA0, mesh="coarse")
    P = np.array([0.0, 1.0, 2.0])
    pred = model.predict(P, 35.0, 2.5, np.array([[0.0], [0.1]]))
    assert pred.force_N.shape == (2, 3)
    assert pred.valid.all() and pred.converged.all()
    for key in ("iterations", "cutbacks", "residual", "threshold_pressure_bar", "failure"):
        assert pred.extras[key].shape == (2, 3)
    single = isometric_sweep(P, 35.0, 2.5, 0.1, THETA0, mesh="coarse")
    np.testing.assert_allclose(pred.force_N[1], single["force_N"], rtol=1e-12)
    assert pred.params["mesh"] == "coarse" and pred.params["theta0_deg"] == THETA0


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"theta0_deg": 60.0}, "theta0_deg=60 is invalid"),
    ({"theta0_deg": 30.0, "mesh": "huge"}, "mesh='huge' is invalid"),
    ({"theta0_deg": 30.0, "L0_mm": -1.0}, "L0_mm=-1 is invalid"),
    ({"theta0_deg": 30.0, "braid": "glued"},
     "braid='glued' is invalid: expected one of bonded, sliding"),
])
def test_bad_parameters_raise_one_line_errors(kwargs, message):
    with pytest.raises(ValueError, match=message):
        Axisym(**kwargs).predict(1.0, 35.0, 2.5, 0.05)


def test_braid_goes_slack_at_the_cap_at_the_threshold_only():
    # At the threshold of muscle I the free muscle's surface shortens along the fibres right at
    # the clamped cap's corner: the tension-only braid goes slack there (zero tension, fibres
    # shorter than at rest) and is taut with g = 0 elsewhere (the complementarity
    # g <= 0, lambda >= 0, lambda g = 0). Once the cap is held and the pressure rises the braid
    # is taut everywhere again.
    half = HalfMuscle(35.0, 2.5, 282.0, THETA0, SILASTIC_S, "coarse")
    y, threshold_MPa, report = half.free_path(-0.05 * half.H)
    assert report.converged and threshold_MPa > 0
    tension, gap = half.tension(y), half.fibre_stretch_gap(y)
    slack = tension == 0
    assert slack[-1] and slack.sum() == 1  # the corner node only (nodes sorted by Z)
    # the slack corner's fibres are 1 % shorter than at rest (mean l_f^2 - 1 around it); a
    # taut node's is the constraint residual, round-off (1e-9 Newton tolerance) below that
    assert gap[-1] < -1e-3
    assert np.all(tension[~slack] > 0) and np.abs(gap[~slack]).max() < 1e-8
    assert half.compression(y) == ""
    [(y2, _)] = half.held_path(y, threshold_MPa, [2.5 * BAR_TO_MPA])
    assert half.tension(y2).min() > 0 and half.compression(y2) == ""


def test_free_tangent_is_the_tangent_with_the_pressure_column():
    # The free muscle's unknowns are the state without the cap displacement, and the pressure:
    # its tangent is K with the cap column replaced by dr/dP = -dV, gathered into a pattern
    # found once. At the threshold state (the cap corner's fibres slack: a released row) it
    # is that matrix entry for entry (the same numbers moved, nothing summed).
    half = HalfMuscle(35.0, 2.5, 282.0, THETA0, SILASTIC_S, "coarse")
    y, P, _ = half.free_path(-0.05 * half.H)
    _, K, dV = half.assemble(y, P)
    assert (half.tension(y) == 0).any()
    expected = sp.hstack([K[:, :-1], -dV[:, None]], format="csr")
    assert abs(half._free_tangent(K, dV) - expected).max() == 0.0
    # the rubber's variables kept from the check of a state are that state's, also after the
    # caller changed it in place
    z = y.copy()
    assert half.inverted(z) is None
    z[: half.n // 2] *= 1.001
    np.testing.assert_array_equal(half._rubber_values(z), half.rubber.values(z))


@pytest.mark.slow  # solves the fine mesh
def test_threshold_search_on_the_graded_fine_mesh_near_the_lock():
    # D0 30, t0 2, eps 30 % at theta0 32.109 deg is a step from the braid lock: P* = 19.13
    # (coarse) and 19.12 bar (medium); the fine mesh's small cap elements must not invert
    # "at the lock" on the way (an artefact of too few halvings of the free path's steps).
    pred = Axisym(theta0_deg=32.109, mesh="fine").predict([0.0, 20.0, 25.0], 30.0, 2.0, 0.3)
    assert pred.converged.all() and pred.valid.all()
    assert pred.extras["threshold_pressure_bar"][0] == pytest.approx(19.12, abs=0.01)
    assert pred.force_N[0] == 0.0 and 0 < pred.force_N[1] < pred.force_N[2]
    # the force is continuous at the lock and affine above it: 3.9 N at 20 bar and 26.2 N at
    # 25 bar, the medium mesh's to 0.5 %
    medium = Axisym(theta0_deg=32.109, mesh="medium").predict([20.0, 25.0], 30.0, 2.0, 0.3)
    np.testing.assert_allclose(pred.force_N[1:], medium.force_N, rtol=5e-3)


def test_thick_wall_start_reaches_the_state_the_path_reaches():
    # The threshold state is solved at once from the thick-wall kinematics; following the path
    # from rest by cap displacement must find the same equilibrium (no other branch).
    half = HalfMuscle(40.0, 3.0, 282.0, THETA0, SILASTIC_S, "coarse")
    U = -0.15 * half.H
    y, P_MPa, report = half.free_path(U)
    assert report.converged and report.iterations <= 8 and report.cutbacks == 0

    def free(x, U):
        r, K, dV = half.assemble(np.append(x[:-1], U), x[-1])
        return r, sp.hstack([K[:, :-1], -dV[:, None]], format="csr")

    [(x, path)] = load_path(free, np.append(half.rest_state()[:-1], 0.0), 0.0, [U],
                            **half._newton_options())
    assert path.converged and path.iterations > 3 * report.iterations
    assert x[-1] == pytest.approx(P_MPa, rel=1e-9)
    np.testing.assert_allclose(x[:-1], y[:-1], rtol=0, atol=1e-7 * np.abs(y).max())


def test_large_strain_terms_at_a_deformed_state():
    # The assembled residual is the gradient of the total potential and the tangent its
    # Hessian, checked by central differences at a deformed state (muscle II held at eps 15 %
    # and 2 bar: stretches of 10-20 %, an active braid and wall pressure), where every
    # geometric term of the large-strain forms counts (at rest most of them vanish).
    half = HalfMuscle(40.0, 3.0, 282.0, THETA0, SILASTIC_S, "coarse")
    y, P_MPa, _ = half.free_path(-0.15 * half.H)
    [(y, _)] = half.held_path(y, P_MPa, [2.0 * BAR_TO_MPA])
    P = 2.0 * BAR_TO_MPA
    F = half.rubber.values(np.append(y, 0.0))
    assert np.abs(F[..., :5] - [1, 0, 0, 1, 1]).max() > 0.1  # a large deformation

    def potential(z):
        z_ext = np.append(z, 0.0)
        a, b, c, d, t, p = np.moveaxis(half.rubber.values(z_ext), -1, 0)
        s2, j = a * a + b * b + c * c + d * d, a * d - b * c
        psi = (SILASTIC_S.C10_MPa * (s2 + t * t - 3) + SILASTIC_S.C01_MPa * (t * t * s2 + j * j - 3)
               - p * (t * j - 1))
        yb = half.braid.values(z_ext)
        g, _, _ = braid_inextensibility(yb[..., :3], THETA0, half.Ro)
        return (np.sum(psi * half.rubber.w) + np.sum(yb[..., 3] * g * half.braid.w)
                - P * half.cavity_volume(z))

    r, K, _ = half.assemble(y, P)
    rng = np.random.default_rng(0)
    for _ in range(3):
        v = rng.standard_normal(half.n)
        v *= 1e-3 * np.abs(y).max() / np.abs(v).max()
        h = 1e-3  # a step of 1e-6 of the state: truncation 1e-12, round-off 1e-10 relative
        dPi = (potential(y + h * v) - potential(y - h * v)) / (2 * h)
        assert dPi == pytest.approx(r @ v, rel=1e-6, abs=1e-9 * np.abs(r).max())
        dr = (half.assemble(y + h * v, P)[0] - half.assemble(y - h * v, P)[0]) / (2 * h)
        np.testing.assert_allclose(K @ v, dr, rtol=0, atol=1e-6 * np.abs(dr).max())


def test_sliding_sleeve_differs_from_bonded_in_the_end_zone_only():
    # Both sleeves give the same mid-section (the uniform braided state satisfies both), so
    # they differ by what happens near the caps, where the sliding sleeve lets the tube widen
    # without stretching its threads locally: a little more force and a lower threshold, by
    # amounts that shrink like 1/L0 (muscle II at 2.5 bar: 0.78 %, 0.35 %, 0.17 % at L0 282,
    # 564, 1128 mm). Its theta0 has its own calibration entry.
    gaps = {}
    for L0 in (564.0, 1128.0):
        bonded, sliding = (isometric_sweep([2.5], 40.0, 3.0, 0.15, THETA0, L0_mm=L0,
                                           mesh="medium", braid=b) for b in ("bonded", "sliding"))
        assert sliding["converged"].all()
        assert sliding["threshold_pressure_bar"][0] < bonded["threshold_pressure_bar"][0]
        gaps[L0] = (sliding["force_N"][0] - bonded["force_N"][0]) / bonded["force_N"][0]
    assert 0 < gaps[1128.0] < gaps[564.0] < 0.01
    assert gaps[564.0] / gaps[1128.0] == pytest.approx(2.0, rel=0.15)
    model = Axisym(braid="sliding")
    assert model.calibration_key == "axisym-sliding" and model.params()["braid"] == "sliding"
    assert "braid" not in Axisym().params()  # the default keeps older records' keys


def test_muscles_of_one_geometry_share_its_discretisation_not_their_work():
    """A fit solves many muscles of one tube (angle and rubber vary): they share the mesh,
    bases and operators, each assembles in work arrays of its own, so muscles of one geometry
    solved at once in two threads (a Dask worker's) give the forces solved one after the
    other."""
    from concurrent.futures import ThreadPoolExecutor

    a = HalfMuscle(35.0, 3.0, 282.0, 30.0, SILASTIC_S, "coarse")
    b = HalfMuscle(35.0, 3.0, 282.0, 36.0, SILASTIC_S, "coarse")
    assert a.assembler is b.assembler and a.rubber.G is b.rubber.G
    assert a.rubber._Ke is not b.rubber._Ke and a._held_lu is not b._held_lu
    assert HalfMuscle(35.0, 3.1, 282.0, 30.0, SILASTIC_S, "coarse").rubber.G is not a.rubber.G
    P = np.arange(0.5, 2.51, 0.5)
    cases = [(theta0, material) for theta0 in (28.0, 33.0, 38.0)
             for material in (SILASTIC_S, MooneyRivlin(0.1, 0.02))]
    serial = [isometric_sweep(P, 35.0, 3.0, 0.1, theta0, mesh="coarse", material=material)
              ["force_N"] for theta0, material in cases]
    with ThreadPoolExecutor(2) as pool:
        threaded = list(pool.map(lambda c: isometric_sweep(
            P, 35.0, 3.0, 0.1, c[0], mesh="coarse", material=c[1])["force_N"], cases * 3))
    for k, force in enumerate(threaded):
        np.testing.assert_array_equal(force, serial[k % len(cases)])


def test_mesh_convergence_studies_the_calibrated_muscle(tmp_path):
    # `mkm fem convergence --calibration FILE` of an identified muscle (its rubber in the
    # entry) must study that muscle, the one `mkm fem solve --model axisym --calibration FILE`
    # solves: it solved Silastic S instead (863.5 N against 792.8 N at 2.5 bar, medium mesh)
    import json

    from mkm.fem.calibration import CALIBRATION_FILE, Calibration
    from mkm.fem.fe.convergence import mesh_convergence

    entries = json.loads(CALIBRATION_FILE.read_text())
    entries["axisym"].update(C10_MPa=0.2, C01_MPa=0.1)
    path = tmp_path / "identified.json"
    path.write_text(json.dumps(entries))
    calibration = Calibration.load(path)
    frame = mesh_convergence(levels=("coarse",), calibration=calibration)
    model = Axisym(mesh="coarse", calibration=calibration)
    expected = float(model.predict([2.5], 35.0, 2.5, 0.05).force_N[0])
    assert frame["force_N"].iloc[0] == pytest.approx(expected, rel=1e-9)
    # a stiffer wall costs force: below Silastic S's, by more than the mesh could explain
    silastic = float(Axisym(mesh="coarse").predict([2.5], 35.0, 2.5, 0.05).force_N[0])
    assert frame["force_N"].iloc[0] < 0.95 * silastic
    assert (frame.attrs["C10_MPa"], frame.attrs["C01_MPa"]) == (0.2, 0.1)
