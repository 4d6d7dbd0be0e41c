"""The FE model inside the box of the stability map (benchmarks/bench_stability_map.py): the
cases that used to fail converge, with forces checked against physics.

Each case is a muscle the map found failing: just above the threshold (the held cap inherited
the threshold state's corner compression), on the fine mesh where the medium converged, and on
the coarse mesh with a sliding braid (a false "locking angle").
"""

import re

import numpy as np
import pytest

from mkm.fem.eq2 import BAR_TO_MPA, LOCKING_ANGLE_DEG
from mkm.fem.fe.model import LOCK_NEAR_DEG, HalfMuscle, isometric_sweep
from mkm.fem.fe.newton import OrderedLU
from mkm.fem.materials import SILASTIC_S, MooneyRivlin
from mkm.fem.outcomes import BRAID_LOCKS

#: the calibrated angle when the map was made (`mkm fem solve --model axisym` used it)
THETA0_MAP = 32.992
STIFFER = MooneyRivlin(1.5 * SILASTIC_S.C10_MPa, 1.5 * SILASTIC_S.C01_MPa,
                       source="Silastic S + 50 %, a rubber inside the box")
#: pressures above P* [bar]: the band the map found failing was 0.0006-0.008 bar wide
ABOVE = np.array([0.0005, 0.001, 0.002, 0.004, 0.008, 0.016, 0.032])

BAND_CASES = {
    # `mkm fem solve --model axisym --D0 35 --t0 2.5 --eps 0.05`: failed at 0.146, 0.147 bar
    "muscle I": ((35.0, 2.5, 0.05, THETA0_MAP), {}),
    # failed at 0.25 bar
    "short, stiff rubber": ((30.0, 2.0, 0.05, 28.0), {"L0_mm": 150.0, "material": STIFFER}),
}


@pytest.mark.parametrize("case", BAND_CASES)
def test_just_above_the_threshold_the_force_rises_from_zero(case):
    # Above P* the held cap's braid starts slack at the corner and is taut again a few mbar
    # later. The force is continuous at P* and rises from zero: F / (P - P*) tends to a finite
    # slope (measured 342 and 352 N/bar, flat to 0.1 % over the first 2 mbar), a little below
    # the slope once the corner is taut again (360-380 N/bar: the slack corner is softer)
    args, kwargs = BAND_CASES[case]
    threshold = isometric_sweep([0.0], *args, mesh="medium", **kwargs)["threshold_pressure_bar"][0]
    out = isometric_sweep(threshold + ABOVE, *args, mesh="medium", **kwargs)
    assert out["converged"].all(), out["failure"]
    assert np.all(out["min_tension_N_per_mm"] >= 0)
    force = out["force_N"]
    assert np.all(force > 0) and np.all(np.diff(force) > 0)
    secant = force / ABOVE
    np.testing.assert_allclose(secant[:3], secant[0], rtol=2e-3)
    taut = np.diff(force[-3:]) / np.diff(ABOVE[-3:])
    assert 0.85 * taut.min() < secant[0] < taut.min()


def test_the_slack_corner_is_shorter_along_the_fibres_and_carries_nothing():
    # the tension-only braid's complementarity at a held state in the band: the slack nodes
    # have zero tension and fibres shorter than at rest, the taut ones keep their length
    half = HalfMuscle(35.0, 2.5, 282.0, THETA0_MAP, SILASTIC_S, "medium")
    y, threshold_MPa, _ = half.free_path(-0.05 * half.H)
    [(y, report)] = half.held_path(y, threshold_MPa, [threshold_MPa + 0.001 * BAR_TO_MPA])
    assert report.converged
    tension, gap = half.tension(y), half.fibre_stretch_gap(y)
    slack = tension == 0
    assert 1 <= slack.sum() <= 3 and slack[-1]  # at the cap's corner (nodes sorted by Z)
    assert np.all(gap[slack] < 0) and np.all(tension[~slack] > 0)
    assert np.abs(gap[~slack]).max() < 1e-8


def test_coarse_sliding_braid_finds_the_inflated_threshold():
    # D0 40, t0 3.5, eps 0.1, theta0 20, L0 100, sliding braid: full Newton from the thick-wall
    # start lands on the free problem's other solution on the coarse mesh (a sucked tube at
    # -0.2 bar, slack sleeve); the threshold is the inflated one, reached by the path. Coarse
    # and medium agree as the mesh study says they do (P* within 0.1 %, forces within 3e-4 of
    # the largest)
    args = (40.0, 3.5, 0.1, 20.0)
    P = np.array([0.5, 1.0, 2.5])
    coarse, medium = (isometric_sweep(P, *args, L0_mm=100.0, mesh=m, braid="sliding")
                      for m in ("coarse", "medium"))
    assert coarse["converged"].all() and medium["converged"].all()
    assert coarse["threshold_pressure_bar"][0] == pytest.approx(
        medium["threshold_pressure_bar"][0], rel=1e-3)
    assert 0.3 < coarse["threshold_pressure_bar"][0] < 0.5
    np.testing.assert_allclose(coarse["force_N"], medium["force_N"], rtol=0,
                               atol=3e-4 * medium["force_N"].max())


def test_sliding_braid_factorises_like_the_bonded_one():
    # the sliding sleeve's single tension is a dense row of the held tangent; numbered after
    # the band it adds its own row and column only: the LU fill of the two braids agrees to
    # a few per cent (it was 11 times larger on the fine mesh)
    fills = {}
    for braid in ("bonded", "sliding"):
        half = HalfMuscle(35.0, 2.5, 282.0, THETA0_MAP, SILASTIC_S, "medium", sleeve=braid)
        y, threshold_MPa, _ = half.free_path(-0.05 * half.H)
        _, K, _ = half.assemble(y, threshold_MPa)
        lu = OrderedLU(leading=half.n - 1)(K)._lu
        fills[braid] = lu.L.nnz + lu.U.nnz
    assert fills["sliding"] < 1.1 * fills["bonded"]


@pytest.mark.slow
def test_fine_mesh_converges_where_the_medium_does():
    # D0 40, t0 3.5, eps 0.05, theta0 20, L0 250: the fine mesh's threshold search failed
    # ("Newton did not converge after 12 cut-backs") against the corner's compression. Fine
    # and medium agree within the mesh error the study measures: the threshold within 0.1 %,
    # the forces within 0.03 % of the sweep's largest
    args = (40.0, 3.5, 0.05, 20.0)
    P = np.array([0.31, 0.5, 1.0, 2.5])
    fine, medium = (isometric_sweep(P, *args, L0_mm=250.0, mesh=m) for m in ("fine", "medium"))
    assert fine["converged"].all() and medium["converged"].all()
    assert fine["threshold_pressure_bar"][0] == pytest.approx(
        medium["threshold_pressure_bar"][0], rel=1e-3)
    np.testing.assert_allclose(fine["force_N"], medium["force_N"], rtol=0,
                               atol=3e-4 * medium["force_N"].max())
    assert np.all(np.diff(fine["force_N"]) > 0)


def test_braid_angle_at_rest_is_theta0():
    half = HalfMuscle(40.0, 3.0, 200.0, 33.0, SILASTIC_S, "coarse")
    assert half.braid_angle_deg(half.rest_state()) == pytest.approx(33.0, abs=1e-9)


def test_a_short_wide_muscle_that_stalls_at_the_lock_says_so():
    # A muscle of the map (seed 20261201) whose free path inverted elements short of eps: its
    # widest section's braid angle was 54.24 deg and rising at eps 0.168, so it reaches the
    # locking angle (54.74 deg) before eps 0.1785, though the closed form's lock is 0.211. Its
    # ends, held narrow by the caps, make the middle shorten k_P ~ 1 / (1 - 0.38 D_braid / L0)
    # times eps (surrogate.muscle_gp): the lock at about eps_max / k_P (0.164 here; the middle's
    # share grows towards the lock, measured 0.176).
    from mkm.fem.eq2 import chou_hannaford_eps_max

    D0, t0, eps, theta0, L0 = 56.3016, 4.78701, 0.178513, 42.9768, 112.799
    out = isometric_sweep([0.0, 1.0], D0, t0, eps, theta0, L0, mesh="medium")
    assert not out["converged"].any()
    failure = str(out["failure"][0])
    match = re.match(r"threshold search failed: the braid locks before eps=0\.178513: its angle, "
                     r"([\d.]+) deg at eps=([\d.]+) and rising, reaches the locking angle "
                     r"54\.74 deg by eps=([\d.]+) \(the path stopped with: ", failure)
    assert match, failure
    angle, reached, lock = (float(g) for g in match.groups())
    assert theta0 < angle < LOCKING_ANGLE_DEG and reached < lock < eps
    k_P = 1.0 / (1.0 - 0.38 * (D0 + 2.0 * t0) / L0)
    assert lock == pytest.approx(chou_hannaford_eps_max(theta0) / k_P, rel=0.1)
    assert (out["limit"] == BRAID_LOCKS).all()  # a physical limit (mkm.fem.outcomes)


def test_a_stall_far_short_of_the_locking_angle_is_the_solvers_not_a_lock():
    # Muscle 150 of the stability map (seed 2857834494527622234, its CSV's rounded numbers),
    # sliding braid: the free path stalls at eps 0.0795 with the widest section at 28.75 deg,
    # 26 deg short of the locking angle, in a long muscle whose closed-form lock is eps 0.40
    # (L0 = 20 D0: its ends barely bring it closer). The rate of the last two steps, cut back
    # 12 times, extrapolated to a lock by eps 0.148: not a lock but the sliding braid's stall
    # at a low angle at rest (docs/guide/fe-model.md), so "not converged", with no limit named
    rubber = MooneyRivlin(0.265464, 0.000616, source="muscle 150 of the stability map")
    out = isometric_sweep([0.0, 1.0], 21.0759, 0.740377, 0.303659, 15.9583, 430.102,
                          mesh="medium", material=rubber, braid="sliding")
    assert not out["converged"].any() and np.isnan(out["force_N"]).all()
    assert (out["limit"] == "").all()
    assert out["failure"][0].startswith("threshold search failed: Newton did not converge")
    assert "locks" not in out["failure"][0]
    assert LOCKING_ANGLE_DEG - LOCK_NEAR_DEG > 28.75


#: the practical range's corner of a thin wide tube of the softest rubber at the lowest angle
CORNER = {"D0_mm": 60.0, "t0_mm": 0.5, "eps": 0.0239, "theta0_deg": 15.0,
          "material": MooneyRivlin(0.03, 0.0, source="the softest rubber of the practical range")}


def test_a_thin_soft_tube_at_a_low_angle_is_solved_above_its_threshold():
    # Just above P* (0.0054 bar) the held muscle barrels, its middle swelling and its ends
    # necking (du_r/dP 1350 mm/bar at the mid-plane on the held tangent at P*), and stiffens
    # within 0.01 bar (2.8 mm in all). Newton's first iterate of a ramp step from P* is that
    # slope times the step, which inverts the 0.5 mm wall's elements above 0.005 bar: the
    # 0:8:0.5 sweep needs 7 halvings of its first step (it failed with 6: "element inversion
    # (J <= 0) at 0.01315 bar after 6 cut-backs"), the 8 bar point asked alone 8 (coarse; 9
    # on the medium mesh)
    P = np.arange(0.0, 8.01, 0.5)
    out = isometric_sweep(P, L0_mm=180.0, mesh="coarse", **CORNER)
    assert out["converged"].all(), out["failure"]
    assert out["cutbacks"].max() > 6
    force = out["force_N"]
    assert force[0] == 0.0 and np.all(np.diff(force) > 0)
    # linear in P once the braid carries the pressure: equal steps to 1e-4 (measured 4e-6)
    np.testing.assert_allclose(np.diff(force[1:]), np.diff(force[1:]).mean(), rtol=1e-4)
    alone = isometric_sweep([8.0], L0_mm=180.0, mesh="coarse", **CORNER)
    assert alone["converged"][0] and alone["cutbacks"][0] > 6
    assert alone["force_N"][0] == pytest.approx(force[-1], rel=1e-9)


def test_the_corner_slope_tends_to_the_thick_wall_slope_with_length():
    # the clamped ends of the 3-diameter muscle cost it almost half the mid-section's slope
    # (thick wall: Equation 2 with the braid diameter, 7272 N/bar); at L0 = 1000 mm the gap is
    # 4.6 % (coarse mesh: 3921, 6935 N/bar), the slope rising towards the closed form's
    from mkm.fem.thickwall import klute_hannaford

    P = np.array([4.0, 8.0])
    rubber = CORNER["material"]
    closed = klute_hannaford(P, CORNER["D0_mm"], CORNER["t0_mm"], CORNER["eps"],
                             CORNER["theta0_deg"], rubber.C10_MPa, rubber.C01_MPa)
    slope_tw = np.diff(closed)[0] / 4.0
    slopes = []
    for L0 in (180.0, 1000.0):
        out = isometric_sweep(P, L0_mm=L0, mesh="coarse", **CORNER)
        assert out["converged"].all(), out["failure"]
        slopes.append(np.diff(out["force_N"])[0] / 4.0)
    assert 0.5 * slope_tw < slopes[0] < slopes[1] < slope_tw
    assert slopes[1] == pytest.approx(slope_tw, rel=0.06)


SLENDER = {"D0_mm": 5.0, "t0_mm": 0.5, "eps": 0.0145, "theta0_deg": 40.0, "L0_mm": 1000.0,
           "material": MooneyRivlin(0.6, 0.0, source="the stiffest rubber of the practical range")}


def test_the_mesh_zig_zag_of_a_slender_thin_wall_is_no_force():
    # The medium mesh's mid-plane elements of this muscle are 6.1 outer diameters long: its
    # threshold state zig-zags from node to node (the tension per node holds the fibres' mean
    # length, not their length between the nodes) with P* 0.2189 bar, 3.9 % below the fine
    # mesh's, and its held ramp pushed the cap (-0.0002 N at 0.219 bar, falling) to a fold at
    # 0.2217 bar. Those forces were answered as converged; each is now a failure that names
    # the zig-zag
    out = isometric_sweep([0.219, 0.2216, 0.2218], mesh="medium", **SLENDER)
    assert not out["converged"].any() and np.isnan(out["force_N"]).all()
    assert re.match(r"negative force \(-0\.000228 N at 0\.219 bar\): the wall zig-zags from "
                    r"node to node, its inextensible fibres stretched by [\d.]+ % between the "
                    r"nodes, on elements up to 6\.1 outer diameters long: a mode of the mesh, too "
                    r"coarse along this slender thin wall \(mesh=fine resolves it\)$",
                    out["failure"][0]), out["failure"][0]
    assert out["failure"][2].startswith("Newton did not converge in 20 iterations at 0.2217 bar")
    assert "(the wall zig-zags from node to node" in out["failure"][2]


def test_the_fine_mesh_resolves_the_slender_thin_wall():
    # elements up to 2.1 outer diameters: the fibres keep their length in the middle (7e-5
    # here, 0.075 on the medium mesh), P* is the closed form's mid-section within the end
    # zone's share (0.2277 against 0.2272 bar) and the force rises from zero
    from mkm.fem.thickwall import klute_hannaford_threshold_pressure

    half = HalfMuscle(5.0, 0.5, 1000.0, 40.0, SLENDER["material"], "fine")
    y, threshold_MPa, _ = half.free_path(-SLENDER["eps"] * half.H)
    assert half.zig_zag_strain(y) < 1e-4 and half.mesh_mode(y) == ""
    closed = klute_hannaford_threshold_pressure(5.0, 0.5, SLENDER["eps"], 40.0, 0.6, 0.0)
    assert threshold_MPa / BAR_TO_MPA == pytest.approx(closed, rel=5e-3)
    out = isometric_sweep([0.2269, 0.23, 0.5], mesh="fine", **SLENDER)
    assert out["converged"].all(), out["failure"]
    assert out["force_N"][0] == 0.0 and 0.0 < out["force_N"][1] < out["force_N"][2]


def test_a_threshold_search_that_stalls_on_the_zig_zag_says_so():
    # muscle 0 of a draw near the slender corner (draw_muscles(20, 2026120704) from D0 5-6 mm,
    # t0 0.5-0.7 mm, L0 800-1000 mm, eps up to 0.1 of the lock; its record's numbers): the
    # coarse mesh's free path stalls at a third of eps with its wall zig-zagging (fibres 0.6 %
    # long between the nodes, elements 9.3 outer diameters); the medium and fine meshes solve it
    rubber = MooneyRivlin(0.317501, 0.012141, source="a muscle drawn near the slender corner")
    out = isometric_sweep([1.0], 5.434522, 0.616841, 0.002652, 28.315829, 856.668683,
                          mesh="coarse", material=rubber)
    assert not out["converged"][0] and out["limit"][0] == ""
    assert re.match(r"threshold search failed: Newton did not converge in 20 iterations at cap "
                    r"displacement -0\.445 mm after 12 cut-backs \(the wall zig-zags from node to "
                    r"node, its inextensible fibres stretched by 0\.6 % between the nodes, on "
                    r"elements up to 9\.3 outer diameters long: .*\(mesh=fine resolves it\)\)$",
                    out["failure"][0]), out["failure"][0]
