"""Goodness of fit of an identification: do the settled steps agree with the model within their
own noise?

Each settled step's mean residual (model minus measured, over its hold) is judged against the
noise of that mean, measured on the step itself:

- the scatter of the hold's residuals about their mean over root n (the load cell's noise and
  quantisation; a creep trend the model follows is not in it, one it misses is);
- the monitor's noise in the hold's mean pressure times the force's slope there (the model is
  evaluated at that mean, so its noise moves the residual);
- the run's tare, shared by every step of the run (a correlated term: its standard error on
  every element of the run's covariance).

Per run and branch (rising, falling): ``chi2 = r' C^-1 r`` over the branch's ``n`` steps, with
``nu = n`` degrees of freedom: the fit minimises the residuals of every hold sample, not this
chi-square (the within-hold creep and the ramps inform it too), so its parameters do not take
``p`` degrees of freedom from it (on in-family simulated runs the fitted chi-square exceeds the
truth's more often than not); and a Wald-Wolfowitz runs test on the signs of the residuals in
pressure order (too few runs: the residuals have structure, a curve the model does not follow).
The fit does not fit within its noise when all steps' ``chi2`` together is that large with a
probability below :data:`MISFIT_P`, or one branch's is below :data:`MISFIT_P` over the number
of branches (were the steps' noise exactly what they show, a fit that fits would be called a
misfit in 0.2 % of identifications; ``benchmarks/bench_identify_coverage.py --departures
in-family`` measures it on simulated runs); then the intervals are widened by the Birge ratio
``sqrt(chi2 / nu)`` of all steps together (where it exceeds 1), the usual remedy when the spread
of the data exceeds their stated noise (Birge 1932; the Particle Data Group's scale factor), so
the intervals are at least as wide as the misfit says the model's errors are. It is a
widening, not a model of the discrepancy: a systematic error (a monitor offset, a braid the
model does not have) biases the estimate as well, which the warning line says.

A step table without a declared accuracy has one value per step; where its sweeps repeat its
pressures, the scatter of the repeats' residuals is its noise (:func:`repeat_noise`), estimated,
so its branches are judged by an F test (:func:`_from_repeats`); its steps are what the fit
minimised, one value each, so there the parameters take their degrees of freedom. Its rising and
falling branches share that one estimate, so their F tests are not independent (a scatter
drawn low raises both): all steps' p-value takes the table whole, one F test of its branches'
chi-squares together (:meth:`Goodness.table_tests`).

The bench's instrument tolerances (the load cell's gain, the monitor's accuracy) are not noise
here: they are errors the data share, and a fit that cannot absorb them shows them as misfit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize, special, stats

from mkm.bench.series import PLATEAU_TOLERANCE_BAR
from mkm.fem.calibration import THRESHOLD_FLOOR_FRACTION, line_above_threshold
from mkm.fem.thickwall import klute_hannaford_threshold_pressure
from mkm.identify import fitting
from mkm.identify.groups import GROUPS
from mkm.identify.runs import shown_effects, step_slopes

#: a misfit: all steps' chi-square this improbable under their noise alone (a branch's: this
#: over the number of branches)
MISFIT_P = 1e-3
#: a slack step's mean force called a zero error beyond this many standard errors and this
#: many of the run's load cell's ADC steps (a quantised zero), or this force [N] for a table
#: (no cell recorded)
ZERO_SIGMAS, ZERO_FLOOR_STEPS, ZERO_FLOOR_N = 5.0, 2.0, 0.5
#: a step whose fitted force is below this [N] is slack
SLACK_N = 1e-6
#: runs-test probability below which the residuals are said to have structure
STRUCTURE_P = 0.01
BRANCHES = {"up": "loading", "down": "unloading"}


@dataclass
class Branch:
    """One run's branch: its steps' mean residuals, their noise and the statistics."""

    run: str
    branch: str  # "loading" | "unloading"
    steps: int
    chi2: float
    nu: float
    p_value: float  # P(chi2 >= observed | the noise alone)
    runs: int  # sign runs of the residuals in pressure order
    runs_p: float  # one-sided: P(this few runs | independent signs)
    rms_residual_N: float
    rms_noise_N: float
    #: each step's mean residual and its noise [N] (the discrepancy's estimate takes them)
    residual_N: np.ndarray = field(default_factory=lambda: np.zeros(0), repr=False)
    noise_N: np.ndarray = field(default_factory=lambda: np.zeros(0), repr=False)

    @property
    def reduced(self) -> float:
        return self.chi2 / self.nu if self.nu > 0 else math.nan

    def record(self) -> dict:
        return {"run": self.run, "branch": self.branch, "steps": self.steps,
                "chi2": round(self.chi2, 3), "nu": round(self.nu, 3),
                "chi2_per_nu": round(self.reduced, 3), "p_value": float(f"{self.p_value:.3g}"),
                "sign_runs": self.runs, "runs_test_p": float(f"{self.runs_p:.3g}"),
                "rms_residual_N": round(self.rms_residual_N, 4),
                "rms_noise_N": round(self.rms_noise_N, 4)}


@dataclass
class Goodness:
    """The judgement of one fit: per run and branch, and the widening it calls for."""

    branches: list[Branch]
    chi2: float
    nu: float
    judged: bool = True
    why_not: str = ""
    left_out: list[str] = field(default_factory=list)  # runs whose steps show no noise
    widened: dict = field(default_factory=dict)  # parameter: factor applied
    fitted: tuple[str, ...] = ()  # the fit's parameters: a misfit names what it did not fit
    shown: tuple[str, ...] = ()  # the --params groups of what the runs show (SHOWN)
    #: per run, the settled steps where the fitted muscle is slack: (run, steps, their mean
    #: measured force [N], its standard error [N], the smallest force called a zero error [N])
    slack: list[tuple[str, int, float, float, float]] = field(default_factory=list)
    #: the fit with the rubber's C01/C10 free where one scale at the assumed ratio is kept
    #: though freeing it lowers chi2 beyond chance (:func:`mkm.identify.procedure.ratio_freed`:
    #: ``assumed``, ``ratio``, ``chi2_improvement``, ``chi2_per_nu``, ``within_noise``)
    ratio_freed: dict | None = None
    #: a run declared at its rest length pulls later than the fitted model
    #: (:func:`mkm.identify.procedure._rest_length_hint`): a length or a gap, not an instrument
    pulls_late: bool = False
    #: a frame yielding under the muscle's pull explains the misfit
    #: (:func:`mkm.identify.procedure.frame_hint`: its stiffness, what it lowers chi2 by, the note,
    #: the refit's shift that the intervals hold)
    frame: dict | None = None
    #: a braid whose fibres stretch under their tension explains the misfit better than a frame
    #: (:func:`mkm.identify.procedure.frame_hint`: their strain at the largest tension, E A, what
    #: it lowers chi2 by, the note, the refit's shift)
    fibres: dict | None = None
    #: the frame check where it ran (a judged misfit): the model it swept the runs with once more,
    #: at the shorter held length, and how many sweeps (one per run); the stiffness it fits and
    #: how far it and a rest length lower chi2, named or not
    frame_check: dict | None = None
    #: the step tables judged against the scatter of their repeats (no accuracy declared)
    repeats: list[Repeats] = field(default_factory=list)

    @property
    def reduced(self) -> float:
        return self.chi2 / self.nu if self.nu > 0 else math.nan

    @property
    def p_value(self) -> float:
        """P(chi2 of all steps >= observed | the noise alone): the branches' chi-squares added,
        a table judged by its repeats as the chi-square as probable as its F test
        (:meth:`table_tests`)."""
        if not self.nu > 0:
            return math.nan
        tables = self.table_tests()
        total = sum(b.chi2 for b in self.branches if b.run not in tables)
        total += sum(test["p_chi2"] for test in tables.values())
        return float(special.chdtrc(self.nu, total))

    def table_tests(self) -> dict[str, dict]:
        """Per step table judged by its repeats: the F test of its branches together against
        the one noise they share (its rising and falling branches' F tests are not
        independent, and added as if they were, a fitting model is called a misfit too often:
        :func:`f_test`)."""
        tests = {}
        for found in self.repeats:
            mine = [b for b in self.branches if b.run == found.run]
            chi2, nu = sum(b.chi2 for b in mine), sum(b.nu for b in mine)
            if nu > 0:
                p, p_chi2 = f_test(chi2, nu, found.dof)
                tests[found.run] = {"chi2": chi2, "nu": nu, "p_value": p, "p_chi2": p_chi2}
        return tests

    @property
    def misfit(self) -> list[Branch]:
        """The branches to name when the fit is a misfit (see the module docstring): those
        beyond their noise at :data:`MISFIT_P`, else the worst one; empty when it fits."""
        if not self.branches:
            return []
        alone = [b for b in self.branches if b.p_value < MISFIT_P / len(self.branches)]
        if not alone and not self.p_value < MISFIT_P:
            return []
        return [b for b in self.branches if b.p_value < MISFIT_P] or [
            max(self.branches, key=lambda b: b.reduced)]

    @property
    def birge_ratio(self) -> float:
        """The factor the intervals are widened by: ``sqrt(chi2 / nu)`` of all steps when a
        branch misfits and that exceeds 1, else 1."""
        if not self.misfit or not self.reduced > 1:
            return 1.0
        return math.sqrt(self.reduced)

    @property
    def discrepancy_rms_N(self) -> float:
        """The residual the noise does not explain: the standard deviation ``d`` [N] of a
        discrepancy that, added to every step's own noise ``s``, brings the steps' residuals
        ``r`` to their noise (``sum r^2 / (s^2 + d^2)`` = the number of steps: each step
        weighed by its own noise, so a slack step's small residual far beyond its small noise
        counts as the chi-square counts it, not under a loaded step's larger noise); 0 when
        the model fits within the noise."""
        r = np.concatenate([b.residual_N for b in self.branches] or [np.zeros(0)])
        s = np.concatenate([b.noise_N for b in self.branches] or [np.zeros(0)])
        if not self.misfit or r.size == 0:
            return 0.0

        def excess(d2: float) -> float:
            return float(np.sum(r**2 / (s**2 + d2))) - r.size

        if excess(0.0) <= 0.0:
            return 0.0
        return math.sqrt(optimize.brentq(excess, 0.0, float(np.sum(r**2)), xtol=1e-12))

    def line(self) -> str | None:
        """One line when the model does not fit within the noise (None when it does)."""
        bad = sorted(self.misfit, key=lambda b: -b.reduced)
        if not bad:
            return None
        shown = "; ".join(
            f"run {b.run} {b.branch} chi2/nu={b.reduced:.3g}"
            + (f" structured (runs test p={b.runs_p:.2g})" if b.runs_p < STRUCTURE_P else "")
            for b in bad[:4])
        more = f"; and {len(bad) - 4} more" if len(bad) > 4 else ""
        return (f"misfit: {shown}{more}: the model does not follow these steps within their "
                f"noise, intervals widened by x{self.birge_ratio:.3g} ({self._left_out()}"
                f"{self._ratio_said()}the estimates may be biased too: {self.checks()})")

    def checks(self) -> str:
        """What to check on a misfit no term of the fit explains: the instruments, the
        muscle's wall and braid, and a rest length or a gap not fitted."""
        # a rest length or a gap the runs do not declare misfits as an instrument does, and
        # identify can fit both
        unfitted = [what for name, what in UNDECLARED.items() if name not in self.fitted]
        fit_them = f"; or fit {' or '.join(unfitted)}" if unfitted else ""
        return ("check the monitor's zero, the load cell's calibration, the muscle's wall and "
                f"braid{fit_them}")

    def _ratio_said(self) -> str:
        """The rubber's ratio as what the fit lacks, where freeing it lowers chi2 beyond
        chance (:attr:`ratio_freed`): whether the model then follows the steps within their
        noise; or ''."""
        freed = self.ratio_freed
        if not freed:
            return ""
        fits = (f"the model follows these steps within their noise (chi2/nu "
                f"{freed['chi2_per_nu']:.3g})" if freed["within_noise"] else
                f"chi2 is lowered by {freed['chi2_improvement']:.3g}"
                + (f" (chi2/nu {freed['chi2_per_nu']:.3g}), not to within the noise"
                   if freed["chi2_per_nu"] is not None else ""))
        return (f"the rubber's C01/C10, held at {freed['assumed_from']} {freed['assumed']:.3g}: "
                "freed "
                f"(to {freed['ratio']:.3g}) {fits}, so the rubber may be what the fit lacks; ")

    def _left_out(self) -> str:
        """What the runs show and the fit left out, with the ``--params`` that fits it too
        (first: the likeliest misfit), or ''."""
        missing = [g for g in self.shown if not set(GROUPS[g]) <= set(self.fitted)]
        if not missing:
            return ""
        fitted = [g for g, names in GROUPS.items() if names and set(names) <= set(self.fitted)]
        return (f"{' and '.join(missing)} not fitted, though the runs "
                f"{' and '.join(SHOWN[g] for g in missing)}: --params "
                f"{','.join(fitted + missing)} fits {'them' if len(missing) > 1 else 'it'} too; ")

    def zero_line(self) -> str | None:
        """One line when the fit misfits and a run's steps where the fitted muscle is slack
        read a force beyond :data:`ZERO_SIGMAS` standard errors and :data:`ZERO_FLOOR_STEPS`
        of the cell's ADC steps (:data:`ZERO_FLOOR_N` for a table): a
        slack muscle pulls nothing, so what they read is the load cell's zero (a tare left
        out, a drift) or a preload the model does not have."""
        if not self.misfit:
            return None
        off = [(run, n, F) for run, n, F, se, floor in self.slack
               if abs(F) > max(ZERO_SIGMAS * se, floor)]
        if not off:
            return None
        shown = "; ".join(f"run {run} {F:+.3g} N over {n} step{'s' if n > 1 else ''}"
                          for run, n, F in off)
        beyond = " beyond the fitted zero" if "force_zero_N" in self.fitted else ""
        return (f"the steps where the identified muscle is slack read a force{beyond} ({shown}): a "
                "slack muscle pulls nothing, so the load cell's zero is off by that (a tare "
                "left out, a drift) or the muscle is mounted with a preload: "
                + ("" if "force_zero_N" in self.fitted else
                   "fit it (--params ...,zero: one zero for every run) or, ")
                + "for an imported table, import it again with --tare at that force; for a "
                "bench run, check the cell's zero (mkm tare) and the mounting, and record again")

    def record(self) -> dict:
        return {"method": "chi-square of the settled steps' mean residuals against their own "
                          f"noise (hold scatter, monitor noise x slope, tare), per run and "
                          f"branch; misfit when all steps' p < {MISFIT_P:g} or a branch's < "
                          f"{MISFIT_P:g} / branches; Wald-Wolfowitz runs test on "
                          "the residuals' signs in pressure order; intervals widened by the "
                          "Birge ratio sqrt(chi2/nu) on a misfit",
                "judged": self.judged, **({"why_not": self.why_not} if not self.judged else {}),
                **({"runs_not_judged": self.left_out,
                    "why_runs_not_judged": NO_NOISE} if self.left_out and self.judged else {}),
                "chi2": round(self.chi2, 3), "nu": round(self.nu, 3),
                "chi2_per_nu": round(self.reduced, 3) if self.nu > 0 else None,
                "p_value": float(f"{self.p_value:.3g}") if self.nu > 0 else None,
                "misfit_branches": [f"{b.run} {b.branch}" for b in self.misfit],
                "birge_ratio": round(self.birge_ratio, 4),
                "misfit_line": self.line(), "widened": self.widened,
                **({"ratio_freed": self.ratio_freed} if self.ratio_freed else {}),
                **({"pulls_late": True} if self.pulls_late else {}),
                **({"frame": {k: v for k, v in self.frame.items() if k not in ("said", "shift")}}
                   if self.frame else {}),
                **({"fibres": {k: v for k, v in self.fibres.items() if k not in ("said", "shift")}}
                   if self.fibres else {}),
                **({"frame_check": self.frame_check} if self.frame_check else {}),
                **({"noise_from_repeats": [self._repeats_record(r) for r in self.repeats],
                    "repeats_method": "a step table without a declared accuracy: one step's "
                                      "noise the pooled standard deviation of the residuals "
                                      "of its steps repeated on one branch within "
                                      f"{REPEAT_BAND_BAR:g} bar, judged by an F test of the "
                                      "repeats' means against it (at least "
                                      f"{REPEAT_MIN_DOF} degrees of freedom), the means' "
                                      "degrees of freedom their number less the fit's "
                                      "leverage on them; each branch alone, and the table "
                                      "whole (its branches share the noise) in all steps' "
                                      "p-value"}
                   if self.repeats else {}),
                "branches": [b.record() for b in self.branches]}

    def _repeats_record(self, found: Repeats) -> dict:
        """A table's noise from its repeats and its F test whole (:meth:`table_tests`)."""
        test = self.table_tests().get(found.run)
        return {**found.record(), **({
            "chi2": round(test["chi2"], 3), "nu": round(test["nu"], 3),
            "p_value": float(f"{test['p_value']:.3g}")} if test else {})}


def runs_test(values) -> tuple[int, float]:
    """Wald-Wolfowitz runs test on the signs of ``values`` (zeros left out): the number of runs
    and the one-sided mid-p of so few under independent signs, from the exact distribution of
    the runs given the counts of each sign (mid-p: ``P(R < r) + P(R = r) / 2``, near uniform on
    noise where the plain exact p is conservative); 1 when one sign is missing."""
    signs = np.sign(np.asarray(values, dtype=float))
    signs = signs[signs != 0]
    n1, n2 = int(np.sum(signs > 0)), int(np.sum(signs < 0))
    if n1 == 0 or n2 == 0:
        return (1 if signs.size else 0), 1.0
    runs = int(1 + np.sum(signs[1:] != signs[:-1]))
    total = math.comb(n1 + n2, n1)

    def probability(r: int) -> float:
        k, odd = divmod(r, 2)
        if odd:
            ways = (math.comb(n1 - 1, k) * math.comb(n2 - 1, k - 1)
                    + math.comb(n1 - 1, k - 1) * math.comb(n2 - 1, k)) if k >= 1 else 0
        else:
            ways = 2 * math.comb(n1 - 1, k - 1) * math.comb(n2 - 1, k - 1) if k >= 1 else 0
        return ways / total

    below = sum(probability(r) for r in range(2, runs))
    return runs, float(below + probability(runs) / 2)


def chi_square(residual, noise, shared: float = 0.0) -> float:
    """``r' C^-1 r`` with ``C = diag(noise^2) + shared^2`` (a term every element shares)."""
    r, var = np.asarray(residual, dtype=float), np.asarray(noise, dtype=float) ** 2
    if shared > 0:  # Sherman-Morrison: (D + s^2 11')^-1
        w = r / var
        return float(r @ w - shared**2 * np.sum(w) ** 2 / (1.0 + shared**2 * np.sum(1 / var)))
    return float(np.sum(r**2 / var))


def assess(runs, fit) -> Goodness:
    """The goodness of ``fit`` (:class:`mkm.identify.fitting.Fit`) to ``runs``: each run's steps
    against their noise (:func:`_step_noise`); a run that shows none is left out, and with
    none left the fit is not judged."""
    n_steps = fit.run_of_cluster.size
    sums = np.bincount(fit.cluster, fit.residual_N, minlength=n_steps)
    counts = np.bincount(fit.cluster, minlength=n_steps)
    mean = sums / np.maximum(counts, 1)
    squares = np.bincount(fit.cluster, (fit.residual_N - mean[fit.cluster]) ** 2,
                          minlength=n_steps)
    scatter2 = squares / np.maximum(counts - 1, 1) / np.maximum(counts, 1)
    measured = np.bincount(fit.cluster, fit.measured_N, minlength=n_steps) / np.maximum(counts, 1)
    taken = None  # each step's leverage in the fit, where a table's repeats judge it
    branches, offset, left_out, slack, repeats, too_few = [], 0, [], [], [], []
    zero_N = fit.values.get("force_zero_N", 0.0)
    for k, run in enumerate(runs):
        steps = run.steps.reset_index(drop=True)
        here = slice(offset, offset + len(steps))
        offset += len(steps)
        noise, usable = _step_noise(run, steps, scatter2[here], counts[here])
        repeated = None
        if noise is None and not run.timed and not run.binned:  # a step table's repeats
            found = repeat_noise(run.name, steps, mean[here], counts[here] > 0)
            if found.dof >= REPEAT_MIN_DOF:
                repeated, usable = found, counts[here] > 0
                noise = np.full(len(steps), found.noise_N)
                repeats.append(found)
            else:
                too_few.append(found)
        if noise is None:
            left_out.append(run.name)
            continue
        tare = float(fit.tare_se_N[k]) if fit.tare_se_N.size else 0.0
        # the model's step mean is the measured one plus the residual (model minus measured),
        # the muscle's force that less the cell's fitted zero
        idle = usable & (np.abs(measured[here] + mean[here] - zero_N) < SLACK_N)
        if idle.any():
            se = math.sqrt(float(np.sum(noise[idle] ** 2)) / idle.sum() ** 2 + tare**2)
            slack.append((run.name, int(idle.sum()),
                          float(np.mean(measured[here][idle])) - zero_N, se,
                          ZERO_FLOOR_N if run.force_step_N is None else
                          ZERO_FLOOR_STEPS * run.force_step_N))
        for direction, branch in BRANCHES.items():
            pick = (steps["direction"].to_numpy() == direction) & usable
            if not pick.any():
                continue
            r, s = mean[here][pick], noise[pick]
            s = np.maximum(s, 1e-12)
            if repeated is None:
                chi2, nu = chi_square(r, s, tare), float(pick.sum())
                p = float(stats.chi2.sf(chi2, nu))
            else:
                if taken is None:
                    taken = np.bincount(fit.cluster, leverages(fit), minlength=n_steps)
                chi2, nu, p = _from_repeats(mean[here], repeated, [
                    g for g in repeat_groups(steps, usable)
                    if steps["direction"].iloc[int(g[0])] == direction], tare, taken[here])
            order = np.argsort(steps["pressure_bar_mean"].to_numpy()[pick], kind="stable")
            n_runs, runs_p = runs_test(r[order])
            branches.append(Branch(
                run.name, branch, int(pick.sum()), chi2, nu, p if nu > 0 else math.nan,
                n_runs, runs_p, float(np.sqrt(np.mean(r**2))), float(np.sqrt(np.mean(s**2))),
                r, np.hypot(s, tare)))
    if not branches:
        return Goodness([], 0.0, 0.0, judged=False, why_not=NO_NOISE + "".join(
            "; too few repeats in a table to judge it by: "
            f"{'; '.join(f.too_few() for f in too_few)}; {REPEAT_MIN_DOF} needed"
            for _ in too_few[:1]), left_out=left_out)
    chi2 = sum(b.chi2 for b in branches)
    nu = sum(b.nu for b in branches)
    return Goodness(branches, chi2, nu, left_out=left_out, fitted=tuple(fit.names),
                    shown=shown_effects(runs), slack=slack, repeats=repeats)


#: a step table's steps of one branch whose pressures lie within a staircase's plateau band
#: of the lowest of them are repeats of one step (:data:`mkm.bench.series.PLATEAU_TOLERANCE_BAR`)
REPEAT_BAND_BAR = PLATEAU_TOLERANCE_BAR
#: the fewest degrees of freedom of the repeats' scatter that judge a table without a declared
#: accuracy: the scatter's own standard error is then at most 22 % (1 / sqrt(2 * 10)), and the
#: judgement takes the scatter's uncertainty in (an F test, :func:`_from_repeats`)
REPEAT_MIN_DOF = 10


@dataclass
class Repeats:
    """A step table's noise judged from its repeats (:func:`repeat_noise`)."""

    run: str
    noise_N: float  # one step's: the pooled standard deviation of the repeats' residuals
    dof: int  # its degrees of freedom: the repeats less one per repeated step
    steps: int  # the steps that repeat another
    pressures: int  # the branch and pressure pairs repeated

    def record(self) -> dict:
        return {"run": self.run, "noise_N": round(self.noise_N, 4), "dof": self.dof,
                "steps": self.steps, "repeated_pressures": self.pressures}

    def said(self) -> str:
        return (f"run {self.run}: {self.noise_N:.3g} N from {self.steps} steps repeated at "
                f"{self.pressures} pressures, {self.dof} degrees of freedom")

    def too_few(self) -> str:
        return (f"run {self.run}: {self.dof} degrees of freedom ({self.steps} steps repeated at "
                f"{self.pressures} pressures)")


def repeat_groups(steps, usable: np.ndarray) -> list[np.ndarray]:
    """The usable steps of ``steps`` grouped as repeats: per branch, in pressure order, a group
    holding the steps within :data:`REPEAT_BAND_BAR` of its lowest pressure."""
    groups = []
    pressure = steps["pressure_bar_mean"].to_numpy(dtype=float)
    for direction in BRANCHES:
        pick = np.flatnonzero((steps["direction"].to_numpy() == direction) & usable)
        order = pick[np.argsort(pressure[pick], kind="stable")]
        start = 0
        for k in range(1, order.size + 1):
            if k == order.size or pressure[order[k]] - pressure[order[start]] > REPEAT_BAND_BAR:
                groups.append(order[start:k])
                start = k
    return groups


def repeat_noise(name: str, steps, residual: np.ndarray, usable: np.ndarray) -> Repeats:
    """The noise of one step of a step table without a declared accuracy, from its repeats: the
    pooled standard deviation of the steps' mean residuals about their repeats' mean (model
    minus measured: the model takes up the repeats' pressures' differences, and a misfit the
    repeats share cancels), each branch and pressure apart (:func:`repeat_groups`)."""
    groups = [g for g in repeat_groups(steps, usable) if g.size > 1]
    dof = sum(g.size - 1 for g in groups)
    squares = sum(float(np.sum((residual[g] - residual[g].mean()) ** 2)) for g in groups)
    return Repeats(name, math.sqrt(squares / dof) if dof else math.nan, dof,
                   sum(g.size for g in groups), len(groups))


def leverages(fit) -> np.ndarray:
    """Each residual's leverage in ``fit``: the diagonal of the weighted least-squares hat matrix
    of its Jacobian (the share of a residual's own noise the fitted parameters take up; they
    sum to the parameters' number, the Jacobian's rank)."""
    jacobian = fit.weighted_jacobian
    if jacobian.size == 0:
        return np.zeros(fit.n)
    u, singular, _ = np.linalg.svd(jacobian, full_matrices=False)
    rank = int(np.sum(singular > singular.max(initial=0.0) * max(jacobian.shape) *
                      np.finfo(float).eps))
    return np.sum(u[:, :rank] ** 2, axis=1)


def _from_repeats(residual, repeats: Repeats, groups, tare: float, taken: np.ndarray):
    """A branch's chi-square, degrees of freedom and p-value, judged against a noise its
    repeats measured: the groups' mean residuals against the repeats' noise over root n (and
    the tare every step shares), a chi-square of ``G`` groups less what the fit took of them
    (``taken``: each step's leverage, :func:`leverages`; the fit minimised these very steps'
    residuals, so its parameters take their degrees of freedom, shared out among the branches
    by their leverages), ``nu`` F(nu, dof) distributed where the model fits (the noise
    estimated, not known): :func:`f_test`. The chi-square itself measures the misfit (the Birge
    ratio widens by it)."""
    means = np.array([residual[g].mean() for g in groups])
    spread = max(repeats.noise_N, 1e-12) / np.sqrt([g.size for g in groups])
    chi2 = chi_square(means, spread, tare)
    # a floor of a tenth of a group: a branch whose every step the fit follows exactly
    nu = max(len(groups) - float(sum(np.sum(taken[g]) for g in groups)), 0.1)
    return chi2, nu, f_test(chi2, nu, repeats.dof)[0]


def f_test(chi2: float, nu: float, dof: float) -> tuple[float, float]:
    """The p-value of ``chi2`` of ``nu`` degrees of freedom measured against a noise estimated
    on ``dof`` (``chi2 / nu`` F(nu, dof) distributed where the model fits), and the chi-square
    of ``nu`` degrees of freedom as probable, which all steps' p-value adds."""
    # scipy.stats' f.sf and chi2.isf are these functions behind a check of their arguments
    # that costs a hundred times the value (the size's test and benchmark call it thousands
    # of times)
    p = float(special.fdtrc(nu, dof, chi2 / nu))
    # beyond the F tail's floating point the chi-square itself, larger still
    return p, (float(special.chdtri(nu, p)) if p > 0 else chi2)


#: what runs show that a fit may leave out, by the ``--params`` group that fits it
SHOWN = {"friction": "rise and fall", "creep": "hold their steps"}
#: what a muscle may have that its runs do not declare, and the ``--params`` group fitting it
UNDECLARED = {"L0_mm": "its rest length (--params ...,L0: a first length already shortened)",
              "gap_mm": "a gap between tube and braid (--params ...,gap)"}


#: why a run's steps show no noise, and what gives them one
NO_NOISE = ("a step table has one value per step, no samples to measure its noise from, and "
            "a ramp's bins stand for a moving sweep at their mean pressures, which no model "
            "follows to within their samples' scatter where the sweep turns or the muscle "
            "starts to pull; import it with the instruments' accuracy (mkm import --accuracy "
            "force=...,pressure=...) to judge it")


def _step_noise(run, steps, scatter2, counts) -> tuple[np.ndarray | None, np.ndarray]:
    """The noise [N] of each step's mean residual and which steps have one: a held step's from
    its hold (the scatter and the monitor's noise times the slope); an imported table's or
    ramp's from the bounds its lab declared (:meth:`~mkm.identify.runs.RunData.declared_noise_N`,
    taken as independent from value to value); ``None`` for a run with neither."""
    if run.timed:
        pressure_se = steps.get("pressure_se_bar")
        pressure_se = (np.nan_to_num(pressure_se.to_numpy(dtype=float)) if pressure_se is
                       not None else np.zeros(len(steps)))
        return np.sqrt(scatter2 + (step_slopes(steps) * pressure_se) ** 2), counts > 1
    noise = run.declared_noise_N()
    if noise is None:
        return None, np.zeros(len(steps), bool)
    return noise, counts > 0


def widen(boot: dict, fit, goodness: Goodness) -> dict:
    """``boot`` (:func:`mkm.identify.intervals.bootstrap`) with every interval of an identifiable
    parameter widened about the estimate by the Birge ratio (clipped to the parameter's bounds);
    unchanged when the fit is within the noise."""
    factor = goodness.birge_ratio
    if factor <= 1.0:
        return boot
    interval = dict(boot["interval"])
    for name, (low, high) in boot["interval"].items():
        if not boot["identifiable"].get(name, True):
            continue
        value = fit.values[name]
        lo_b, hi_b = fit.bounds[name]
        interval[name] = (max(value - factor * (value - low), lo_b),
                          min(value + factor * (high - value), hi_b))
        goodness.widened[name] = round(factor, 4)
    return {**boot, "interval": interval, "unwidened_interval": boot["interval"]}


def threshold_row(run, static, values: dict) -> dict:
    """The identified threshold pressure [bar] at the run's eps against the measured one.

    Fitted: the ``threshold_pressure_bar`` of the identified static model where it reports one
    (the thick-wall form, the FE, both with the gap), else the thick-wall form's
    (:func:`mkm.fem.thickwall.klute_hannaford_threshold_pressure`) at the identified angle,
    rubber and gap. Measured: the zero of the least-squares line through the settled steps,
    rising and falling (friction and creep scale the force, so they leave the zero where it is),
    whose force is above the noise floor: the larger of 2 % of the run's largest step force
    (:data:`mkm.fem.calibration.THRESHOLD_FLOOR_FRACTION`, the calibration's floor for the same
    line) and three standard errors of the run's zero (its tare), below which a step may be a
    muscle not yet pulling.
    """
    D0_mm, t0_mm, eps = fitting.geometry(run, values)
    gap_mm = values.get("gap_mm", 0.0)
    model = static.model(values, float(run.muscle["L0_mm"]))
    if model.has_threshold:
        fitted = float(model.predict(0.0, D0_mm, t0_mm, eps).extras["threshold_pressure_bar"])
    else:
        rubber = model.material
        fitted = float(klute_hannaford_threshold_pressure(
            D0_mm, t0_mm, eps, values["theta0_deg"], rubber.C10_MPa, rubber.C01_MPa, gap_mm))
    fitted += values.get("pressure_offset_bar", 0.0)  # as the monitor reads it
    force = run.steps["force_N_mean"].to_numpy(dtype=float) - values.get("force_zero_N", 0.0)
    floor = max(THRESHOLD_FLOOR_FRACTION * np.max(force, initial=0.0), 3.0 * run.tare_se_N)
    _, measured = line_above_threshold(run.steps["pressure_bar_mean"], force, floor)
    return {"run": run.name, "eps": eps, "fitted threshold [bar]": fitted,
            "measured threshold [bar]": measured, "fitted - measured [bar]": fitted - measured}
