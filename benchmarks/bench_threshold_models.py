"""Which physics makes a muscle's force start above a threshold pressure at its rest length.

A model-selection study. Every candidate is the thick-wall closed form (Klute-Hannaford,
:mod:`mkm.fem.thickwall`) with the braid angle ``theta0`` and one rubber scale (Silastic S's
C10 and C01 times ``s``) fitted, plus the physics it adds:

- ``gap``: a radial gap between tube and braid at rest: the thick Mooney-Rivlin tube inflates
  freely until it meets the sleeve, a threshold even at eps 0. Read two ways, since a
  catalogue muscle gives one nominal diameter: ``gap, tube nominal`` (``gap_mm``: the tube is
  D0, t0 and the braid ``g`` wider, as :mod:`mkm.fem.thickwall` takes it) and ``gap, braid
  nominal`` (``gap_inside_mm``: the braid is D0 + 2 t0 and the tube ``g`` narrower, D0 - 2 g);
- ``slack``: braid threads longer than the rest geometry needs (crimp straightened, ``slack`` a
  fraction). Derivation: taut threads of length ``b (1 + slack)`` have ``cos theta = lz cos
  theta0 / (1 + slack)`` and radius ``Rb (1 + slack) sin theta / sin theta0``: a gap model with
  another angle, so with theta0 fitted it is the gap model reparametrised (the study shows it);
- ``extensibility``: fibres that stretch with the load, thread stretch ``1 + c P`` (``c`` per
  bar; linear fibres under a tension that grows with P). The force at fixed thread stretch is the
  slack model's (the envelope theorem: the fibres' energy depends on their stretch only);
- ``Gent``: the rubber's I1 term stiffening at large stretch, ``W = -(C10 / j) ln(1 - j (I1 -
  3)) + C01 (I2 - 3)`` (Gent 1996 with the Mooney-Rivlin I2 term; ``j = 1 / Jm``, 0 is
  Mooney-Rivlin), its wall force by Gauss-Legendre quadrature through the wall;
- ``Yeoh``: the rubber's I1 term as Yeoh's cubic, ``W = C10 (I1 - 3) + C20 (I1 - 3)^2 + C30 (I1
  - 3)^3 + C01 (I2 - 3)`` (Yeoh 1993 with the Mooney-Rivlin I2 term, so that C20 = C30 = 0 is
  today's rubber; ``yeoh_c20``, ``yeoh_c30`` are C20 / C10 and C30 / C10): a filled rubber's
  stiff start that softens (C20 < 0) and stiffens again at large stretch, by the same quadrature;
- ``ends``: the clamped ends' share, by Tondu and Lopez's factor (the mid-section held at ``k
  eps``); the ladder's FE models the ends themselves, this is their closed-form stand-in;
- ``rest length``: the rest length fitted (``rest_offset``, the shortening of the table's longest
  length): not physics of the muscle but of the data's reading;

alone and in pairs (a pair's gap is the braid-nominal one). The maps are isometric ramps read
once (one force per length and pressure, no loading and unloading branch): friction or
hysteresis, which only the difference between the branches shows, cannot be fitted to them.
Data: the Martens and Boblan force maps of two Festo muscles (``mkm/data/published/``; D0 the
nominal diameter, t0 1.8 mm as the third party assumed). Each candidate is fitted
(``scipy.optimize.least_squares``, bounds, several starts; a fit that does not converge is reported
as such) on two held lengths other than the rest length, and scored on the rest-length curve and
the other held lengths (where starts tie on the training cost with other parameters, the worst of
those equal fits, counted in ``equal fits``: :func:`scored`): the largest error as % of the
muscle's largest measured force (100 % at a point where the fitted law has no wall state), the
threshold pressure at eps 0 against the measured one, and AIC/BIC of the training fit. The table's
``zero_entry`` rows (0 N where the muscle is slack) are kept as one-sided constraints: the model's
isometric force there (zero below its threshold) is the residual, so a model is charged only for
predicting a pull where the muscle was slack. Every pair of held lengths is tried; the default pair
is the two longest below the rest length. Pairs that include the rest length are tried too and
summarised apart: they say whether a model can hold the whole map when the rest-length curve is
known, not whether it predicts it.

Each map is read with the table's longest length as the rest length (the data file's reading)
and, where it differs, with Festo's nominal length (:data:`NOMINAL_LENGTH_MM`): the DMSP-20-300's
table starts at 296 mm, its type code says 300 mm.

The same study then runs on simulated maps whose truth is one physics each (:data:`TRUTHS`, on
the baseline's fit to the DMSP-20-300 and that muscle's grid, with Gaussian noise of 0.5 % of the
largest force, seeded): does the selection find the physics that made the data, and the gap its
size?

    .venv/bin/python benchmarks/bench_threshold_models.py [--out FILE.json] [--seed 0]

writes FILE.json (rows: the model-selection table; also the before/after, simulated and fitted
rest-length tables, every fit, provenance) and FILE.png (the fitted curves). ``make bench-docs``
runs it into docs/measured/.
"""

from __future__ import annotations

import argparse
import io
import itertools
import json
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pandas as pd
from scipy.optimize import brentq, least_squares

from mkm.core.records import provenance, write_atomic, write_json_atomic
from mkm.fem.eq2 import chou_hannaford, chou_hannaford_eps_max
from mkm.fem.materials import SILASTIC_S
from mkm.fem.thickwall import braided_tube_elastic_force, klute_hannaford, mid_section_kinematics

ROOT = Path(__file__).resolve().parents[1]
MAP_FILE = ROOT / "mkm" / "data" / "published" / "martens_boblan_2017_forcemaps.csv"
DEFAULT_OUT = ROOT / "docs" / "measured" / "threshold_models.json"
GAUSS_X, GAUSS_W = np.polynomial.legendre.leggauss(24)  # smooth integrand: 24 nodes to ~1e-12
SIM_NOISE_FRACTION = 0.005  # of the largest force: about a good load cell's share of a map

#: extra parameter -> (start, lower bound, upper bound, meaning)
EXTRAS = {
    "gap_mm": (0.3, 0.0, 3.0, "radial gap between tube and braid at rest [mm]"),
    "gap_inside_mm": (0.3, 0.0, 3.0, "radial gap inside the nominal braid [mm]"),
    "slack": (0.01, 0.0, 0.2, "braid thread slack [fraction]"),
    "stretch_per_bar": (0.002, 0.0, 0.05, "fibre stretch per bar [1/bar]"),
    "gent_inv_Jm": (0.05, 0.0, 2.0, "Gent 1/Jm [-]"),
    # W1 = C10 (1 + 2 c20 x + 3 c30 x^2) > 0 for every x = I1 - 3 >= 0 needs c20 > -sqrt(3 c30):
    # a start that softens a little and stiffens a little
    "yeoh_c20": (-0.1, -2.0, 2.0, "Yeoh C20 / C10 [-]"),
    "yeoh_c30": (0.05, 0.0, 5.0, "Yeoh C30 / C10 [-]"),
    "end_factor": (1.1, 1.0, 2.0, "Tondu-Lopez end factor k [-]"),
    "rest_offset": (0.005, -0.05, 0.05, "shortening of the table's longest length [fraction]"),
}
BASE = {"theta0_deg": ((24.0, 28.0, 32.0), 15.0, 45.0), "rubber_scale": ((1.0, 5.0), 0.1, 50.0)}
#: starts whose training cost is within this fraction of the best fit the data equally; their
#: parameters differ when they differ by more than SAME_PARAMS_RELATIVE (the fit's own xtol is
#: 1e-10, so one optimum reached from two starts agrees far closer)
TIE_RELATIVE_COST, SAME_PARAMS_RELATIVE = 1e-8, 1e-4


@dataclass(frozen=True)
class Candidate:
    name: str
    extras: tuple[str, ...] = ()

    @property
    def n_params(self) -> int:
        return 2 + len(self.extras)


CANDIDATES = (
    Candidate("thick-wall (baseline)"),
    Candidate("gap, tube nominal", ("gap_mm",)),
    Candidate("gap, braid nominal", ("gap_inside_mm",)),
    Candidate("slack", ("slack",)),
    Candidate("extensibility", ("stretch_per_bar",)),
    Candidate("Gent", ("gent_inv_Jm",)),
    Candidate("Yeoh", ("yeoh_c20", "yeoh_c30")),
    Candidate("ends", ("end_factor",)),
    Candidate("rest length", ("rest_offset",)),
    Candidate("gap + extensibility", ("gap_inside_mm", "stretch_per_bar")),
    Candidate("gap + Gent", ("gap_inside_mm", "gent_inv_Jm")),
    Candidate("gap + Yeoh", ("gap_inside_mm", "yeoh_c20", "yeoh_c30")),
    Candidate("gap + ends", ("gap_inside_mm", "end_factor")),
    Candidate("gap + rest length", ("gap_inside_mm", "rest_offset")),
    Candidate("extensibility + Gent", ("stretch_per_bar", "gent_inv_Jm")),
    Candidate("rest length + extensibility", ("rest_offset", "stretch_per_bar")),
    Candidate("rest length + Gent", ("rest_offset", "gent_inv_Jm")),
    Candidate("rest length + Yeoh", ("rest_offset", "yeoh_c20", "yeoh_c30")),
    Candidate("rest length + ends", ("rest_offset", "end_factor")),
)
BASELINE, KEPT = "thick-wall (baseline)", "gap, braid nominal"
#: the simulated truths: one physics each, at a size that matters (on the baseline's theta0 and
#: rubber fitted to the DMSP-20-300)
TRUTHS = {"thick-wall (baseline)": {}, "gap, braid nominal": {"gap_inside_mm": 0.9},
          "extensibility": {"stretch_per_bar": 0.01}, "Gent": {"gent_inv_Jm": 0.3},
          # W1 = C10 (1 - 0.6 x + 0.3 x^2): softens by a fifth at I1 - 3 = 0.5, never to zero
          "Yeoh": {"yeoh_c20": -0.3, "yeoh_c30": 0.1},
          "ends": {"end_factor": 1.15}}


# --- the candidates' physics ------------------------------------------------------------------

def i1_law_elastic_force(D0_mm, t0_mm, eps, theta0_deg, gap_mm, C10_MPa, C01_MPa, w1_factor):
    """``dE/dlz`` [N] of the braided tube whose rubber has ``W1 = dW/dI1 = C10 w1_factor(I1 -
    3)`` and ``dW/dI2 = C01``, by quadrature through the wall.

    ``E = pi * integral of W dx`` over ``x = R^2`` through the wall, differentiated under the
    integral: ``W1 dI1/dlz + C01 dI2/dlz``. The kinematics are
    :func:`mkm.fem.thickwall.mid_section_kinematics`'. NaN where ``w1_factor`` is NaN or not
    positive (no stable wall state: past the Gent limit, a Yeoh law that softens to nothing).
    """
    Ri2, Ro2, lz, k, _, ro2, _, cot2 = mid_section_kinematics(D0_mm, t0_mm, eps, theta0_deg,
                                                              gap_mm)
    Rb2 = (np.asarray(D0_mm) / 2.0 + np.asarray(t0_mm) + np.asarray(gap_mm)) ** 2
    dk = -2.0 * Rb2 * lz * cot2 + Ro2 / lz**2
    half = (Ro2 - Ri2) / 2.0
    x = (Ri2 + half)[..., None] + np.multiply.outer(half, GAUSS_X)
    lz_, k_, dk_ = (np.asarray(v, dtype=float)[..., None] for v in (lz, k, dk))
    a = k_ / x + 1.0 / lz_
    da = dk_ / x - 1.0 / lz_**2
    I1 = lz_**2 + a + 1.0 / (a * lz_**2)
    dI1 = 2.0 * lz_ + da - da / (a**2 * lz_**2) - 2.0 / (a * lz_**3)
    dI2 = da * lz_**2 + 2.0 * a * lz_ - 2.0 / lz_**3 - da / a**2
    with np.errstate(divide="ignore", invalid="ignore"):
        factor = w1_factor(I1 - 3.0)
        W1 = np.where(factor > 0, C10_MPa * factor, np.nan)
    return np.pi * np.sum((W1 * dI1 + C01_MPa * dI2) * GAUSS_W, axis=-1) * half


def gent_elastic_force(D0_mm, t0_mm, eps, theta0_deg, gap_mm, C10_MPa, C01_MPa, inv_Jm):
    """``dE/dlz`` [N] with the Gent-Mooney-Rivlin energy (``W1 = C10 / (1 - j (I1 - 3))``)."""
    j = np.asarray(inv_Jm, dtype=float)[..., None]
    return i1_law_elastic_force(D0_mm, t0_mm, eps, theta0_deg, gap_mm, C10_MPa, C01_MPa,
                                lambda x: 1.0 / (1.0 - j * x))


def yeoh_elastic_force(D0_mm, t0_mm, eps, theta0_deg, gap_mm, C10_MPa, C01_MPa, c20, c30):
    """``dE/dlz`` [N] with the Yeoh-Mooney-Rivlin energy (``W1 = C10 (1 + 2 c20 x + 3 c30
    x^2)``, ``x = I1 - 3``)."""
    c20, c30 = (np.asarray(c, dtype=float)[..., None] for c in (c20, c30))
    return i1_law_elastic_force(D0_mm, t0_mm, eps, theta0_deg, gap_mm, C10_MPa, C01_MPa,
                                lambda x: 1.0 + 2.0 * c20 * x + 3.0 * c30 * x**2)


def candidate_force(P, eps, D0_mm, t0_mm, theta0_deg, rubber_scale, gap_mm=0.0,
                    gap_inside_mm=0.0, slack=0.0, stretch_per_bar=0.0, gent_inv_Jm=0.0,
                    end_factor=1.0, rest_offset=0.0, yeoh_c20=0.0, yeoh_c30=0.0, raw=False):
    """Isometric force [N] of a candidate (see the module docstring); 0 where the muscle is
    slack (below its threshold, or held beyond its braid lock), NaN where the wall has no state
    (past the Gent limit). ``raw``: the force before the slack is taken out (negative below
    the threshold)."""
    P = np.asarray(P, dtype=float)
    eps = end_factor * (rest_offset + (1.0 - rest_offset) * np.asarray(eps, dtype=float))
    D0_mm, gap_mm = D0_mm - 2.0 * gap_inside_mm, gap_mm + gap_inside_mm
    stretch = 1.0 + slack + stretch_per_bar * P  # thread stretch
    theta = np.arccos(np.cos(np.deg2rad(theta0_deg)) / stretch)
    theta_deg = np.rad2deg(theta)
    Ro = D0_mm / 2.0 + t0_mm
    braid_radius = (Ro + gap_mm) * stretch * np.sin(theta) / np.sin(np.deg2rad(theta0_deg))
    gap = braid_radius - Ro  # the equivalent gap of a taut braid of that angle
    C10, C01 = rubber_scale * SILASTIC_S.C10_MPa, rubber_scale * SILASTIC_S.C01_MPa
    if gent_inv_Jm:
        force = (chou_hannaford(P, 2.0 * braid_radius, eps, theta_deg)
                 + gent_elastic_force(D0_mm, t0_mm, eps, theta_deg, gap, C10, C01, gent_inv_Jm))
    elif yeoh_c20 or yeoh_c30:
        force = (chou_hannaford(P, 2.0 * braid_radius, eps, theta_deg)
                 + yeoh_elastic_force(D0_mm, t0_mm, eps, theta_deg, gap, C10, C01, yeoh_c20,
                                      yeoh_c30))
    else:
        force = klute_hannaford(P, D0_mm, t0_mm, eps, theta_deg, C10, C01, gap)
    if raw:
        return force
    reachable = eps < chou_hannaford_eps_max(theta_deg)
    return np.where(reachable, np.where(force > 0, force, np.where(np.isnan(force), np.nan, 0.0)),
                    0.0)


def threshold_at_rest_bar(D0_mm, t0_mm, params: dict, eps: float = 0.0) -> float:
    """The pressure [bar] at which the candidate's force at ``eps`` (the table's longest length)
    turns positive (Brent's root of the raw force between 0 and 10 bar); NaN where it has none
    there."""
    def force(p):
        return float(candidate_force(p, eps, D0_mm, t0_mm, raw=True, **params))

    if not force(10.0) > 0:
        return float("nan")
    if force(0.0) >= 0:  # eps 0 without a threshold: F = A P
        return 0.0
    return brentq(force, 0.0, 10.0, xtol=1e-6)


@dataclass(frozen=True)
class Physics:
    """How a candidate's force and threshold are computed: ``force(P, eps, D0_mm, t0_mm,
    **params)`` as :func:`candidate_force`, ``threshold(D0_mm, t0_mm, params, eps)`` as
    :func:`threshold_at_rest_bar`. The closed forms by default; another script may fit the same
    candidates with the FE model."""

    force: object = candidate_force
    threshold: object = threshold_at_rest_bar


CLOSED_FORM = Physics()


# --- data -------------------------------------------------------------------------------------

#: Festo's type code is DMSP-<diameter>-<nominal length in mm>: the rest length a second reading
#: of the maps takes (the table's longest length is 296 mm for the DMSP-20-300)
NOMINAL_LENGTH_MM = {"Festo DMSP-20-300": 300.0, "Festo DMSP-10-250": 250.0}


@dataclass(frozen=True)
class ForceMap:
    """One muscle's isometric map: rows ``eps, pressure_bar, force_N, zero_entry`` with ``eps``
    the table's (0 at its longest length ``table_L0_mm``); the model is held at the shortening
    from ``rest_length_mm`` (:meth:`model_eps`)."""

    muscle: str
    D0_mm: float
    t0_mm: float
    rows: pd.DataFrame
    table_L0_mm: float
    rest_length_mm: float

    @property
    def reading(self) -> str:
        """Which rest length the model takes: the table's longest or the nominal one."""
        which = "table" if self.rest_length_mm == self.table_L0_mm else "nominal"
        return f"{self.rest_length_mm:g} mm ({which})"

    def model_eps(self, eps):
        """The shortening from the rest length of a table shortening ``eps`` [fraction]."""
        return 1.0 - (1.0 - np.asarray(eps, dtype=float)) * self.table_L0_mm / self.rest_length_mm

    def at_nominal_length(self) -> ForceMap:
        return ForceMap(self.muscle, self.D0_mm, self.t0_mm, self.rows, self.table_L0_mm,
                        NOMINAL_LENGTH_MM[self.muscle])

    @property
    def largest_force_N(self) -> float:
        return float(self.rows["force_N"].max())

    @property
    def held(self) -> list[float]:
        """The held shortenings other than the rest length with at least one measured force."""
        loaded = self.rows[self.rows["zero_entry"] == 0]
        return sorted(e for e in loaded["eps"].unique() if e > 0)

    def measured_threshold_bar(self) -> dict:
        """The threshold at eps 0: the bracket between the table's last slack pressure and its
        first measured force, and the zero of the line through the two lowest measured forces
        held into that bracket (the estimate scored)."""
        rest = self.rows[self.rows["eps"] == 0].sort_values("pressure_bar")
        loaded = rest[rest["zero_entry"] == 0]
        first = loaded["pressure_bar"].min()
        slack = rest[(rest["zero_entry"] == 1) & (rest["pressure_bar"] < first)]
        low = float(slack["pressure_bar"].max()) if len(slack) else 0.0
        high = float(loaded["pressure_bar"].iloc[0])
        (p1, f1), (p2, f2) = loaded[["pressure_bar", "force_N"]].to_numpy()[:2]
        line = p1 - f1 * (p2 - p1) / (f2 - f1)
        return {"low_bar": low, "high_bar": high, "line_bar": float(line),
                "estimate_bar": float(np.clip(line, low, high))}


def read_maps(path: Path = MAP_FILE) -> list[ForceMap]:
    frame = pd.read_csv(path, comment="#")
    maps = []
    for muscle, rows in frame.groupby("muscle", sort=False):
        L0_mm = float(rows["L0_mm"].iloc[0])
        maps.append(ForceMap(muscle, float(rows["D0_nominal_mm"].iloc[0]),
                             float(rows["t0_mm_third_party"].iloc[0]),
                             rows.rename(columns={"P_bar": "pressure_bar"})[
                                 ["eps", "pressure_bar", "force_N", "zero_entry"]]
                             .reset_index(drop=True), L0_mm, L0_mm))
    return maps


# --- fitting and scoring ----------------------------------------------------------------------

@dataclass
class Fit:
    candidate: Candidate
    converged: bool
    params: dict
    rss_N2: float
    n_train: int
    message: str
    #: every distinct parameter set whose training cost ties the best (``params`` among them)
    tied: tuple[dict, ...] = ()

    def criteria(self) -> tuple[float, float]:
        """AIC and BIC of the training fit (Gaussian residuals of unknown variance)."""
        n, k = self.n_train, self.candidate.n_params
        base = n * np.log(max(self.rss_N2, 1e-300) / n)
        return base + 2 * k, base + k * np.log(n)


def _residuals(force_map: ForceMap, rows: pd.DataFrame, params: dict,
               physics: Physics = CLOSED_FORM) -> np.ndarray:
    """Model minus table [N]; a zero entry's residual is the model's pull there (0 if slack)."""
    model = physics.force(rows["pressure_bar"].to_numpy(), force_map.model_eps(rows["eps"]),
                          force_map.D0_mm, force_map.t0_mm, **params)
    return model - rows["force_N"].to_numpy()


def fit_candidate(candidate: Candidate, force_map: ForceMap, train: pd.DataFrame,
                  physics: Physics = CLOSED_FORM, starts=None) -> Fit:
    """Least squares with bounds from every start (default: every pair of :data:`BASE`'s
    starts, the extras at theirs); the best converged fit, or a failed one."""
    names = ["theta0_deg", "rubber_scale", *candidate.extras]
    lower = [BASE[n][1] for n in names[:2]] + [EXTRAS[e][1] for e in candidate.extras]
    upper = [BASE[n][2] for n in names[:2]] + [EXTRAS[e][2] for e in candidate.extras]
    scale = force_map.largest_force_N

    def residuals(x):
        r = _residuals(force_map, train, dict(zip(names, x, strict=True)), physics) / scale
        return np.nan_to_num(r, nan=1.0)  # no wall state (Gent limit): a whole largest force off

    best, messages, done = None, set(), []
    if starts is None:
        starts = [[theta0, rubber] + [EXTRAS[e][0] for e in candidate.extras]
                  for theta0, rubber in itertools.product(
                      *(BASE[n][0] for n in ("theta0_deg", "rubber_scale")))]
    for x0 in starts:
        result = least_squares(residuals, x0, bounds=(lower, upper), x_scale="jac",
                               xtol=1e-10, ftol=1e-12, max_nfev=2000)
        messages.add(result.message)
        finite = np.all(np.isfinite(_residuals(force_map, train,
                                               dict(zip(names, result.x, strict=True)),
                                               physics)))
        if result.status > 0 and finite:
            done.append(result)
            if best is None or result.cost < best.cost:
                best = result
    if best is None:
        return Fit(candidate, False, {}, float("nan"), len(train), "; ".join(sorted(messages)))
    params = dict(zip(names, (float(v) for v in best.x), strict=True))
    rss = float(np.sum(_residuals(force_map, train, params, physics) ** 2))
    tied: list[np.ndarray] = []
    for result in done:
        if result.cost <= best.cost * (1 + TIE_RELATIVE_COST) and not any(
                np.allclose(result.x, x, rtol=SAME_PARAMS_RELATIVE, atol=1e-6) for x in tied):
            tied.append(result.x)
    return Fit(candidate, True, params, rss, len(train), best.message,
               tuple(dict(zip(names, (float(v) for v in x), strict=True)) for x in tied))


def score(fit: Fit, force_map: ForceMap, train_eps, physics: Physics = CLOSED_FORM) -> dict:
    """Held-out errors as % of the muscle's largest force, and the threshold at eps 0."""
    if not fit.converged:
        return {"converged": False, "message": fit.message}
    rows = force_map.rows
    scale = force_map.largest_force_N / 100.0
    # a point where the fitted law has no wall state (a Yeoh law softened to nothing, past the
    # Gent limit) counts as a whole largest force off, as in the fit
    err = np.nan_to_num(_residuals(force_map, rows, fit.params, physics) / scale, nan=100.0)
    measured = rows["zero_entry"].to_numpy() == 0
    rest = rows["eps"].to_numpy() == 0
    held_out = ~np.isin(rows["eps"].to_numpy(), train_eps)
    aic, bic = fit.criteria()
    threshold = physics.threshold(force_map.D0_mm, force_map.t0_mm, fit.params,
                                  float(force_map.model_eps(0.0)))
    rest_held_out = 0.0 not in train_eps
    return {"converged": True, **fit.params,
            "rest_max_err_pct": (float(np.max(np.abs(err[measured & rest])))
                                 if rest_held_out else float("nan")),
            "other_max_err_pct": float(np.max(np.abs(err[measured & held_out & ~rest]),
                                              initial=0.0)),
            "held_out_max_err_pct": float(np.max(np.abs(err[measured & held_out]))),
            "held_out_rms_pct": float(np.sqrt(np.mean(err[measured & held_out] ** 2))),
            "slack_pull_pct": float(np.max(err[~measured & held_out], initial=0.0)),
            "threshold_eps0_bar": threshold,
            "threshold_eps0_err_bar": (threshold
                                       - force_map.measured_threshold_bar()["estimate_bar"]),
            "train_rmse_N": float(np.sqrt(fit.rss_N2 / fit.n_train)),
            "aic": float(aic), "bic": float(bic)}


def scored(candidate: Candidate, force_map: ForceMap, train: pd.DataFrame, train_eps) -> dict:
    """The candidate fitted on ``train`` and scored (:func:`score`). Where starts reach the
    same training cost with other parameters (two lengths do not fix a candidate acting twice on
    the offsets), the data cannot choose between those fits, and which start wins is decided by
    rounding: the worst of them on the lengths held out is scored, and ``equal_fits`` counts
    them."""
    fit = fit_candidate(candidate, force_map, train)
    if not fit.converged:
        return score(fit, force_map, train_eps)
    scores = [score(replace(fit, params=p), force_map, train_eps) for p in fit.tied]
    worst = max(scores, key=lambda s: s["held_out_max_err_pct"])
    return {**worst, "equal_fits": len(scores)}


def study_map(force_map: ForceMap) -> pd.DataFrame:
    """Every candidate on every pair of held lengths: one row per (pair, candidate)."""
    records = []
    for pair in itertools.combinations([0.0, *force_map.held], 2):
        train = force_map.rows[np.isin(force_map.rows["eps"], pair)]
        for candidate in CANDIDATES:
            records.append({"muscle": force_map.muscle, "rest length": force_map.reading,
                            "train_eps": list(pair),
                            "default_pair": list(pair) == force_map.held[:2],
                            "rest_fitted": 0.0 in pair,
                            "model": candidate.name, "n_params": candidate.n_params,
                            **scored(candidate, force_map, train, pair)})
    frame = pd.DataFrame(records)
    # information criteria are comparable only on the same training rows
    for column in ("aic", "bic"):
        frame[f"d{column}"] = frame[column] - frame.groupby(
            frame["train_eps"].map(tuple))[column].transform("min")
    return frame


def selection_table(study: pd.DataFrame) -> pd.DataFrame:
    """One row per muscle, rest length and candidate: the default pair's scores and the spread
    over pairs."""
    rows = []
    for (muscle, reading, model), group in study.groupby(["muscle", "rest length", "model"],
                                                         sort=False):
        default = group[group["default_pair"]].iloc[0]
        done = group[group["converged"] & ~group["rest_fitted"]]
        rest_fitted = group[group["converged"] & group["rest_fitted"]]
        rows.append({
            "muscle": muscle, "rest length": reading, "model": model,
            "params": int(default["n_params"]),
            "converged": f"{int(group['converged'].sum())}/{len(group)}",
            "rest curve max err %": default.get("rest_max_err_pct"),
            "other lengths max err %": default.get("other_max_err_pct"),
            "slack pull %": default.get("slack_pull_pct"),
            "P* at the longest length bar": default.get("threshold_eps0_bar"),
            "dAIC": default.get("daic"), "dBIC": default.get("dbic"),
            "equal fits": default.get("equal_fits"),
            "held-out max err % (median over pairs)": float(done["held_out_max_err_pct"].median()),
            "held-out max err % (worst pair)": float(done["held_out_max_err_pct"].max()),
            "dBIC (median over pairs)": float(done["dbic"].median()),
            "rest fitted: other lengths max err % (median)": float(
                rest_fitted["other_max_err_pct"].median()),
            "rest fitted: other lengths max err % (worst pair)": float(
                rest_fitted["other_max_err_pct"].max()),
        })
    return pd.DataFrame(rows)


def _default_fit(study: pd.DataFrame, force_map: ForceMap, model: str) -> pd.Series:
    return study[(study["muscle"] == force_map.muscle) & (study["model"] == model)
                 & (study["rest length"] == force_map.reading) & study["default_pair"]].iloc[0]


def before_after(study: pd.DataFrame, readings: list[ForceMap]) -> pd.DataFrame:
    """Baseline against the kept model on each muscle's default pair, per rest length, with the
    measured threshold at the table's longest length."""
    rows = []
    for force_map in readings:
        measured = force_map.measured_threshold_bar()
        for model in (BASELINE, KEPT):
            r = _default_fit(study, force_map, model)
            rows.append({"muscle": force_map.muscle, "rest length": force_map.reading,
                         "model": model,
                         "trained on eps": ", ".join(f"{e:g}" for e in r["train_eps"]),
                         "theta0 deg": r.get("theta0_deg"), "rubber x Silastic S":
                         r.get("rubber_scale"), "gap mm": r.get("gap_inside_mm", 0.0),
                         "rest curve max err %": r.get("rest_max_err_pct"),
                         "other lengths max err %": r.get("other_max_err_pct"),
                         "P* at the longest length bar": r.get("threshold_eps0_bar"),
                         "measured P* bar": measured["estimate_bar"],
                         "measured bracket bar":
                             f"{measured['low_bar']:g}-{measured['high_bar']:g}"})
    return pd.DataFrame(rows)


def fitted_rest_lengths(study: pd.DataFrame, maps: list[ForceMap]) -> pd.DataFrame:
    """The rest length [mm] the ``rest length`` candidate finds on each pair that includes the
    table's longest length (where the threshold there is measured, not extrapolated)."""
    rows = []
    for force_map in maps:
        fits = study[(study["muscle"] == force_map.muscle) & (study["model"] == "rest length")
                     & (study["rest length"] == force_map.reading) & study["rest_fitted"]
                     & study["converged"]]
        for _, fit in fits.iterrows():
            rows.append({"muscle": force_map.muscle, "table's longest length mm":
                         force_map.table_L0_mm, "nominal length mm":
                         NOMINAL_LENGTH_MM[force_map.muscle],
                         "fitted on eps": ", ".join(f"{e:g}" for e in fit["train_eps"]),
                         "fitted rest length mm": force_map.table_L0_mm
                         / (1.0 - fit["rest_offset"]),
                         "other lengths max err %": fit["other_max_err_pct"]})
    return pd.DataFrame(rows)


def measured_lines(maps: list[ForceMap]) -> pd.DataFrame:
    """Per muscle and held length: the least-squares line through its measured forces (slope
    and zero, the threshold the data themselves give) and the largest deviation from it, as %
    of the muscle's largest force; the model-free picture of how the threshold grows with the
    shortening."""
    rows = []
    for force_map in maps:
        for eps, group in force_map.rows.groupby("eps"):
            loaded = group[group["zero_entry"] == 0]
            if len(loaded) < 3:
                continue
            slope, intercept = np.polyfit(loaded["pressure_bar"], loaded["force_N"], 1)
            deviation = np.polyval([slope, intercept], loaded["pressure_bar"]) - loaded["force_N"]
            slack = group[(group["zero_entry"] == 1)
                          & (group["pressure_bar"] < loaded["pressure_bar"].min())]
            rows.append({"muscle": force_map.muscle, "eps (table)": float(eps),
                         "points": len(loaded), "slope N/bar": float(slope),
                         "line's zero bar": float(-intercept / slope),
                         "last slack entry bar": (float(slack["pressure_bar"].max())
                                                  if len(slack) else float("nan")),
                         "largest deviation %": float(100.0 * np.max(np.abs(deviation))
                                                      / force_map.largest_force_N)})
    return pd.DataFrame(rows)


# --- simulated maps ---------------------------------------------------------------------------

def simulated_map(truth_params: dict, like: ForceMap, rng) -> ForceMap:
    """``like``'s grid with the truth's forces plus Gaussian noise; slack where the truth pulls
    nothing (a zero entry, as the published tables mark it)."""
    rows = like.rows[["eps", "pressure_bar"]].copy()
    force = candidate_force(rows["pressure_bar"].to_numpy(), like.model_eps(rows["eps"]),
                            like.D0_mm, like.t0_mm, **truth_params)
    noise = rng.normal(0.0, SIM_NOISE_FRACTION * np.nanmax(force), force.shape)
    slack = ~(force > 0)
    rows["force_N"] = np.where(slack, 0.0, np.maximum(force + noise, 0.0))
    rows["zero_entry"] = slack.astype(int)
    return ForceMap(f"simulated {like.muscle}", like.D0_mm, like.t0_mm, rows,
                    like.table_L0_mm, like.rest_length_mm)


def simulated_study(study: pd.DataFrame, like: ForceMap, seed: int) -> pd.DataFrame:
    """A simulated map of ``like``'s grid per truth (:data:`TRUTHS`); every candidate fitted to
    it on ``like``'s default pair."""
    rng = np.random.default_rng(seed)
    baseline = _default_fit(study, like, BASELINE)
    rows = []
    for truth, extras in TRUTHS.items():
        truth_params = {"theta0_deg": float(baseline["theta0_deg"]),
                        "rubber_scale": float(baseline["rubber_scale"]), **extras}
        simulated = simulated_map(truth_params, like, rng)
        pair = like.held[:2]
        train = simulated.rows[np.isin(simulated.rows["eps"], pair)]
        for candidate in CANDIDATES:
            s = scored(candidate, simulated, train, pair)
            rows.append({"truth": truth, **{f"truth {n}": v for n, v in
                                                 truth_params.items()},
                         "model": candidate.name, **s})
    frame = pd.DataFrame(rows)
    frame["dbic"] = frame["bic"] - frame.groupby("truth")["bic"].transform("min")
    return frame


def simulated_table(simulated: pd.DataFrame) -> pd.DataFrame:
    """Per truth: the candidate BIC picks, the one with the smallest held-out error, and the
    kept model's recovered gap."""
    rows = []
    for truth, group in simulated.groupby("truth", sort=False):
        done = group[group["converged"]]
        by_bic = done.loc[done["bic"].idxmin()]
        by_err = done.loc[done["held_out_max_err_pct"].idxmin()]
        true_row = done[done["model"] == truth].iloc[0]
        kept = done[done["model"] == KEPT].iloc[0]
        rows.append({"truth": truth, "BIC picks": by_bic["model"],
                     "smallest held-out error": by_err["model"],
                     "truth's own model: held-out max err %": true_row["held_out_max_err_pct"],
                     "baseline: held-out max err %": done[done["model"] == BASELINE].iloc[0][
                         "held_out_max_err_pct"],
                     "gap model: held-out max err %": kept["held_out_max_err_pct"],
                     "true gap mm": float(np.nan_to_num(group.iloc[0].get(
                         "truth gap_inside_mm", 0.0))),
                     "fitted gap mm": kept["gap_inside_mm"]})
    return pd.DataFrame(rows)


# --- figure -----------------------------------------------------------------------------------

def curves_figure(study: pd.DataFrame, maps: list[ForceMap]):
    """Per muscle (table reading): the map, the baseline (dashed) and the kept model (solid)
    fitted on the default pair, and the baseline with the nominal rest length (dotted)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(2, len(maps), figsize=(6.2 * len(maps), 9.0))
    for column, force_map in enumerate(maps):
        nominal = force_map.at_nominal_length()
        lines = [(force_map, BASELINE, "--"), (force_map, KEPT, "-")]
        if nominal.reading != force_map.reading:
            lines.append((nominal, BASELINE, ":"))
        train = _default_fit(study, force_map, KEPT)["train_eps"]
        for row, top in enumerate((None, 2.0)):
            ax = axes[row, column]
            lengths = sorted(force_map.rows["eps"].unique()) if top is None else [0.0]
            colours = plt.cm.viridis(np.linspace(0, 0.9, len(lengths)))
            for eps, colour in zip(lengths, colours, strict=True):
                rows = force_map.rows[force_map.rows["eps"] == eps]
                loaded = rows["zero_entry"] == 0
                label = f"eps {eps:g}" + (" (fitted)" if eps in train else "")
                ax.plot(rows["pressure_bar"][loaded], rows["force_N"][loaded], "o",
                        color=colour, ms=4, label=label)
                ax.plot(rows["pressure_bar"][~loaded], rows["force_N"][~loaded], "o",
                        mfc="none", color=colour, ms=4)
                pressures = np.linspace(0.0, top or rows["pressure_bar"].max(), 300)
                for reading, model, style in lines:
                    fit = _default_fit(study, reading, model)
                    params = {k: fit[k] for k in ["theta0_deg", "rubber_scale", *next(
                        c.extras for c in CANDIDATES if c.name == model)]}
                    ax.plot(pressures, candidate_force(pressures, reading.model_eps(eps),
                                                       reading.D0_mm, reading.t0_mm, **params),
                            style, color=colour, lw=1.2)
            ax.set_xlabel("pressure [bar]")
            ax.set_ylabel("force [N]")
            ax.set_title(force_map.muscle + ("" if top is None else
                                             ": longest length, low pressure"))
            if top is not None:
                ax.set_xlim(0, top)
                ax.set_ylim(-5, float(force_map.rows[(force_map.rows["eps"] == 0)
                                                     & (force_map.rows["pressure_bar"] <= top)]
                                      ["force_N"].max()) * 1.15)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7, loc="upper left")
    fig.suptitle(f"dashed: {BASELINE}; solid: {KEPT}; dotted: {BASELINE} with the nominal "
                 "rest length; hollow: slack entries", fontsize=9)
    fig.tight_layout()
    return fig


# --- main -------------------------------------------------------------------------------------

def check_quadrature() -> float:
    """The Gent wall force with ``1/Jm = 0`` against the closed Mooney-Rivlin form: the
    quadrature's error, relative (raises past 1e-9)."""
    eps = np.linspace(0.0, 0.25, 11)
    closed = braided_tube_elastic_force(20.0, 1.8, eps, 28.0, 0.4, 0.35, 0.7)
    quad = gent_elastic_force(20.0, 1.8, eps, 28.0, 0.7, 0.4, 0.35, 0.0)
    error = float(np.max(np.abs(quad - closed)) / np.max(np.abs(closed)))
    if error > 1e-9:
        raise RuntimeError(f"Gent quadrature off the closed form by {error:.2e} (relative)")
    return error


def jsonable_frame(frame: pd.DataFrame) -> list[dict]:
    return json.loads(frame.to_json(orient="records", double_precision=6))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()

    quadrature_error = check_quadrature()
    maps = read_maps()
    readings = [*maps, *(m.at_nominal_length() for m in maps
                         if NOMINAL_LENGTH_MM[m.muscle] != m.table_L0_mm)]
    study = pd.concat([study_map(m) for m in readings], ignore_index=True)
    selection = selection_table(study)
    simulated = simulated_study(study, maps[0], args.seed)
    record = {**provenance(), "seed": args.seed, "data": str(MAP_FILE.relative_to(ROOT)),
              "sim_noise_fraction_of_largest_force": SIM_NOISE_FRACTION,
              "gent_quadrature_relative_error": quadrature_error,
              "measured_threshold_eps0": {m.muscle: m.measured_threshold_bar() for m in maps},
              "rows": jsonable_frame(selection),
              "before_after": jsonable_frame(before_after(study, readings)),
              "simulated": jsonable_frame(simulated_table(simulated)),
              "rest_length": jsonable_frame(fitted_rest_lengths(study, maps)),
              "lines": jsonable_frame(measured_lines(maps)),
              "fits": jsonable_frame(study)}
    write_json_atomic(args.out, record)
    buffer = io.BytesIO()
    curves_figure(study, maps).savefig(buffer, format="png", dpi=100, metadata={
        "Description": json.dumps(provenance()), "Software": "mkm-bench"})
    write_atomic(args.out.with_suffix(".png"), buffer.getvalue())
    with pd.option_context("display.width", 200, "display.max_columns", 20):
        print(selection.round(3).to_string(index=False))
        print(pd.DataFrame(record["before_after"]).round(3).to_string(index=False))
        print(pd.DataFrame(record["simulated"]).round(3).to_string(index=False))
    print(args.out)


if __name__ == "__main__":
    main()
