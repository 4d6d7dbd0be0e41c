"""95 % confidence intervals, correlation and identifiability of a fit, by a bootstrap over steps.

Each bootstrap replicate draws every run's settled steps with replacement (a step's hold
samples travel together: their noise and any model error they share stay correlated; the few
steps that alone fix the load cell's zero are drawn among themselves, :func:`strata`) and
refits. The refit is the Gauss-Newton step from the optimum on the resampled residuals, with
the Jacobian of the optimum (the linearised bootstrap): exact for a model linear in its
parameters near the optimum, as this one is over an interval's width, and thousands of
replicates cost milliseconds instead of thousands of fits.

Errors every step of a run shares are drawn with each replicate, since resampling steps
cannot show them: the run's zero (its tare's standard error, normal), the load cell's
sensitivity (uniform within the tolerance the runs declare: the data cannot see it, so the
interval must carry it) and the tube's declared wall and diameter where they are not fitted
(uniform within their declared tolerances, through the residuals' sensitivity to each). A
nuisance parameter with a prior (the pressure monitor's offset,
within its declared accuracy) adds the prior's information to the normal equations and a draw
of the prior's centre to each replicate. Intervals are the replicates' 2.5 and 97.5
percentiles, clipped to the parameter's bounds.
"""

from __future__ import annotations

import numpy as np

from mkm.identify.fitting import Fit, at_edge

REPLICATES = 4000
LEVEL = 0.95
#: correlation above which two parameters are said to be confounded by these runs
CONFOUNDED = 0.95
#: load-cell sensitivity tolerance where none is declared (AEP TCA10 data sheet: <= +-0.1 %)
SENSITIVITY_TOLERANCE = 0.001


def bootstrap(result: Fit, replicates: int = REPLICATES, seed: int = 0,
              sensitivity_tolerance: float = SENSITIVITY_TOLERANCE,
              prior_sd: dict[str, float] | None = None,
              uniform_terms: dict[str, tuple[np.ndarray, float]] | None = None,
              step_u_N: np.ndarray | None = None) -> dict:
    """Replicates of the fitted parameters (internal names), their intervals and correlation.

    Returns ``{"draws": array (replicates, p), "interval": {name: (low, high)}, "correlation":
    array (p, p), "covariance": array (p, p), "identifiable": {name: bool}, "stretched":
    [name], "seed", "replicates"}`` (the covariance is :func:`robust_covariance`'s; an interval
    the replicates' 95 % range would give without its estimate is stretched to hold it, and
    its name listed in ``stretched``). A parameter whose column of
    the Jacobian is (numerically) zero is not identifiable: the runs do not inform it, its
    interval is its whole bound and its variance a uniform's over it. ``sensitivity_tolerance``:
    the load cell's (a fraction, uniform); ``prior_sd``: a normal prior's standard deviation per
    parameter, weighed against the residuals' variance; ``uniform_terms``: an input every run
    shares and the fit takes as given (the tube's declared wall and diameter), as the residuals'
    sensitivity to it (one value per residual) and its +- tolerance (uniform); ``step_u_N``:
    a standard uncertainty of each step's measured value that its residuals cannot show (an
    imported table's declared accuracy, 0 elsewhere), drawn normal and independent per step.
    """
    # in the weighted fit's space (every weight 1 for bench runs): the Gauss-Newton step of a
    # replicate and the measured force's and zero's errors, each times the residual's weight
    names, J, r, w = result.names, result.weighted_jacobian, result.weighted_residual, result.w
    p = len(names)
    rng = np.random.default_rng(seed)
    if p == 0:
        return {"draws": np.zeros((replicates, 0)), "interval": {}, "correlation": np.zeros((0, 0)),
                "covariance": np.zeros((0, 0)),
                "identifiable": {}, "stretched": [], "slack_steps": 0, "seed": seed,
                "replicates": replicates}
    column = np.sqrt(np.sum(J**2, axis=0))
    identifiable = column > 1e-9 * max(column.max(), 1e-300)
    use = np.flatnonzero(identifiable)
    J = J[:, use]
    n_clusters = result.run_of_cluster.size
    # per step: J'J, J'r, J'F (a sensitivity error) and J'1 (a zero error)
    JtJ = np.zeros((n_clusters, use.size, use.size))
    Jtr, JtF, Jt1 = (np.zeros((n_clusters, use.size)) for _ in range(3))
    np.add.at(JtJ, result.cluster, J[:, :, None] * J[:, None, :])
    np.add.at(Jtr, result.cluster, J * r[:, None])
    np.add.at(JtF, result.cluster, J * (w * result.measured_N)[:, None])
    np.add.at(Jt1, result.cluster, J * w[:, None])
    counts = np.zeros((replicates, n_clusters))
    slack = slack_steps(result, J, [names[i] for i in use])
    for members, size in strata(result, slack):
        picks = rng.choice(members, size=(replicates, size), replace=True)
        for b in range(replicates):
            counts[b] += members.size / size * np.bincount(picks[b], minlength=n_clusters)
    # a measured force F' = (1 + s) F + z moves the residual model - F' by -(s F + z)
    s = rng.uniform(-sensitivity_tolerance, sensitivity_tolerance, size=replicates)
    tare = result.tare_se_N if result.tare_se_N.size else np.zeros(n_clusters)
    z = rng.standard_normal((replicates, tare.size)) * tare
    A = np.einsum("bc,cij->bij", counts, JtJ)
    g = (np.einsum("bc,ci->bi", counts, Jtr) - s[:, None] * np.einsum("bc,ci->bi", counts, JtF)
         - np.einsum("bc,ci->bi", counts * z[:, result.run_of_cluster], Jt1))
    if step_u_N is not None:
        # each step's value off by e moves its residuals by -e: once per step, as measured
        # once (a step resampled twice would count its one error twice)
        e = rng.standard_normal((replicates, n_clusters)) * np.asarray(step_u_N, dtype=float)
        g -= np.einsum("bc,ci->bi", e, Jt1)
    for column, half in (uniform_terms or {}).values():  # r moves by u column
        Jtc = np.zeros((n_clusters, use.size))
        np.add.at(Jtc, result.cluster, J * (w * np.asarray(column, dtype=float))[:, None])
        u = rng.uniform(-half, half, size=replicates)
        g += u[:, None] * np.einsum("bc,ci->bi", counts, Jtc)
    x = np.array([result.values[n] for n in names])
    # a prior sd_p on a parameter: the residual r_p = (sigma / sd_p)(x - c), c drawn about
    # the optimum per replicate (the fit itself stays within hard bounds)
    sigma2 = result.rss / max(result.n, 1)
    for name, sd in (prior_sd or {}).items():
        if name in names and identifiable[names.index(name)]:
            k = int(np.flatnonzero(use == names.index(name))[0])
            weight = sigma2 / sd**2
            A[:, k, k] += weight
            g[:, k] -= weight * rng.standard_normal(replicates) * sd
    draws = np.tile(x, (replicates, 1))
    # the Gauss-Newton step of each replicate from the optimum: -(J'WJ)^-1 J'W r
    try:
        step = np.linalg.solve(A, g[..., None])[..., 0]
    except np.linalg.LinAlgError:  # a replicate without the steps that inform a parameter
        step = (np.linalg.pinv(A) @ g[..., None])[..., 0]
    draws[:, use] -= step
    low_q, high_q = 100 * (1 - LEVEL) / 2, 100 * (1 + LEVEL) / 2
    interval, stretched = {}, []
    for i, name in enumerate(names):
        lo_b, hi_b = result.bounds[name]
        if not identifiable[i]:
            interval[name] = (lo_b, hi_b)
            continue
        column_draws = np.clip(draws[:, i], lo_b, hi_b)
        low, high = (float(np.percentile(column_draws, q)) for q in (low_q, high_q))
        # the replicates step from the optimum as if it were free: where a parameter rests on a
        # bound the residuals still push against it, and the push moves the others' steps
        # with it, so that their range can leave the estimate out; stretched, and said
        if not low <= x[i] <= high:
            stretched.append(name)
            low, high = min(low, float(x[i])), max(high, float(x[i]))
        interval[name] = (low, high)
    covariance = robust_covariance(draws)
    for i in np.flatnonzero(~identifiable):  # the runs say nothing: uniform over its bound
        lo_b, hi_b = result.bounds[names[i]]
        covariance[i, :] = covariance[:, i] = 0.0
        covariance[i, i] = (hi_b - lo_b) ** 2 / 12.0
    with np.errstate(invalid="ignore", divide="ignore"):
        sd = np.sqrt(np.diag(covariance))
        correlation = covariance / np.outer(sd, sd) if p > 1 else np.ones((1, 1))
    correlation = np.where(np.isfinite(correlation), correlation, 0.0)
    return {"draws": draws, "interval": interval, "correlation": np.atleast_2d(correlation),
            "covariance": covariance,
            "identifiable": dict(zip(names, map(bool, identifiable), strict=True)),
            "stretched": stretched, "slack_steps": int(slack.sum()), "seed": seed,
            "replicates": replicates}


def slack_steps(result: Fit, J: np.ndarray, names) -> np.ndarray:
    """Per step: whether only the load cell's zero moves its residuals (the fitted muscle
    slack there), of ``J``'s columns ``names``; none where the zero is not fitted."""
    n_clusters = result.run_of_cluster.size
    if "force_zero_N" not in names:
        return np.zeros(n_clusters, dtype=bool)
    zero = np.array([n == "force_zero_N" for n in names])
    moved = np.zeros((n_clusters, 2))
    np.add.at(moved, result.cluster, np.c_[np.abs(J[:, zero]).sum(axis=1),
                                           np.abs(J[:, ~zero]).sum(axis=1)])
    return (moved[:, 0] > 0) & (moved[:, 1] == 0)


def strata(result: Fit, slack: np.ndarray) -> list[tuple[np.ndarray, int]]:
    """The steps each bootstrap replicate draws among, and how many it draws: each run's steps,
    as many as it has, except the ``slack`` ones (:func:`slack_steps`), drawn among themselves
    over every run. Those are few (the first and last step of a run whose threshold is above
    its lowest pressure) and alone tell the zero from the muscle's force: a replicate that left
    them all out would see the zero only through the threshold's line and land tens of newtons
    off. Of ``n`` of them a replicate draws ``n - 1``, each counted ``n / (n - 1)`` times
    (McCarthy and Snowden's bootstrap of a small stratum): drawn ``n`` times their spread would
    be ``(n - 1) / n`` of theirs, half of it for two. A single one stays among its run's steps:
    no other step shows its noise."""
    apart = slack if slack.sum() > 1 else np.zeros_like(slack)
    out = [np.flatnonzero((result.run_of_cluster == run) & ~apart)
           for run in np.unique(result.run_of_cluster)]
    return ([(m, m.size) for m in out if m.size]
            + ([(np.flatnonzero(apart), int(apart.sum()) - 1)] if apart.any() else []))


def robust_covariance(draws: np.ndarray) -> np.ndarray:
    """The replicates' covariance as their percentile intervals see it: each standard deviation
    the 95 % interval's half-width over 1.96, each correlation from the ranks (Spearman's rho,
    as the normal's correlation ``2 sin(pi rho / 6)``). A replicate whose resampled steps lack
    what fixes a parameter can land far off; a handful of those in thousands leave the
    percentiles where they are but would rule a plain covariance."""
    from scipy.stats import rankdata

    draws = np.atleast_2d(np.asarray(draws, dtype=float).T).T
    low, high = np.percentile(draws, [100 * (1 - LEVEL) / 2, 100 * (1 + LEVEL) / 2], axis=0)
    sd = (high - low) / (2 * 1.959964)
    with np.errstate(invalid="ignore", divide="ignore"):
        rho = np.corrcoef(rankdata(draws, axis=0), rowvar=False)
    rho = np.where(np.isfinite(rho), np.atleast_2d(rho), 0.0)
    R = 2 * np.sin(np.pi / 6 * rho)
    np.fill_diagonal(R, 1.0)
    return R * np.outer(sd, sd)


def extend(boot: dict, result: Fit, terms: dict) -> dict:
    """``boot`` with each interval of an identifiable parameter extended by the model-form
    ``terms`` (:func:`mkm.identify.procedure.model_form_terms`): a ``one-sided`` term's shift
    ``d`` extends it to hold the interval moved by ``d`` too, a ``symmetric`` one by ``|d|``
    on both sides; clipped to the parameter's bounds. The intervals before are kept as
    ``before_model_form``."""
    applied = [t for t in terms.values() if "shift" in t]
    if not applied:
        return boot
    interval = dict(boot["interval"])
    for name, (low, high) in boot["interval"].items():
        if not boot["identifiable"].get(name, True):
            continue
        for term in applied:
            d = term["shift"].get(name, 0.0)
            if term["kind"] == "one-sided":
                low, high = min(low, low + d), max(high, high + d)
            else:
                low, high = low - abs(d), high + abs(d)
        lo_b, hi_b = result.bounds[name]
        interval[name] = (max(low, lo_b), min(high, hi_b))
    return {**boot, "interval": interval, "before_model_form": boot["interval"]}


#: the parameters whose interval is profiled where it meets a bound of their search
#: (:func:`profile_at_bounds`): the static force's; a friction or creep term at its zero bound is
#: no force at all, its clipped interval one-sided already, and each refit would cost a fit
PROFILED = ("theta0_deg", "rubber_scale", "c01_fraction", "t0_mm", "D0_mm", "L0_mm", "gap_mm")
#: each end of a profile interval where chi2 (in the bootstrap's scale) has risen by this: the
#: square of the normal's 97.5 % point, as each end of a percentile interval is
PROFILE_RISE = 1.959964 ** 2
#: a profile's first step from the estimate, as the fraction of the way to the bound, at the
#: least; doubled until chi2 rises past :data:`PROFILE_RISE`, then bisected this many times
PROFILE_FIRST, PROFILE_BISECTIONS = 2.0 ** -6, 5


def meets_bound(value: float, bounds: tuple[float, float],
                linear: tuple[float, float]) -> bool:
    """Whether a parameter ``value`` rests on a bound of its search (within
    :data:`mkm.identify.fitting.EDGE_FRACTION` of its width) or its linearised 95 % interval
    ``linear`` (unclipped) reaches one."""
    return at_edge(value, bounds) or linear[0] <= bounds[0] or linear[1] >= bounds[1]


def linear_scale(result: Fit, boot: dict, name: str) -> float:
    """The residuals' variance in which ``boot``'s linearised spread of ``name`` is a chi2 rise
    of :data:`PROFILE_RISE` at each end: its replicates' variance (the 95 % range over
    2 x 1.96, unclipped) over its diagonal element of ``(J'J)^-1``. A profile on that scale
    gives the bootstrap's interval where the model is linear in the parameter, and carries
    what the bootstrap draws besides the steps' noise (the hold samples' shared errors, the
    instrument's tolerances: the declared wall alone makes theta0's variance 5e5 times the
    samples' scatter's); at a bound it follows chi2 where the linearisation collapses."""
    names = result.names
    use = [i for i, n in enumerate(names) if boot["identifiable"][n]]
    J = result.weighted_jacobian[:, use]
    k = use.index(names.index(name))
    low, high = np.percentile(boot["draws"][:, names.index(name)],
                              [100 * (1 - LEVEL) / 2, 100 * (1 + LEVEL) / 2])
    sd = (high - low) / (2 * 1.959964)
    return float(sd**2 / np.linalg.pinv(J.T @ J)[k, k])


def profile(refit, result: Fit, name: str, side: str, scale: float,
            linear_end: float) -> tuple[float, int]:
    """The end of ``name``'s interval towards its ``side`` bound, profiled: ``name`` held at
    values from its estimate towards that bound, the others refitted (``refit(value, start)``:
    the fit with ``name`` held at ``value``, started from the values ``start``), the end where
    the sum of squares has risen by :data:`PROFILE_RISE` times ``scale``
    (:func:`linear_scale`), or the bound where it does not rise so far; never inside the
    bootstrap's end ``linear_end``, which carries the instrument's tolerances as well. The
    first value held is that end (:data:`PROFILE_FIRST` of the way to the bound where it is
    the estimate): where chi2 has risen so far there the bootstrap's end stands, one refit;
    else the distance doubles (from that first fraction at the least) until it has.
    Returns the end and the number of refits."""
    x0 = result.values[name]
    bound = result.bounds[name][0 if side == "low" else 1]
    reach = PROFILE_RISE * scale
    refits, start = 0, result.values
    # fractions of the way to the bound
    linear = min(max((linear_end - x0) / (bound - x0), 0.0), 1.0) if bound != x0 else 1.0
    inside, beyond, fraction = 0.0, None, linear if linear > 0 else PROFILE_FIRST
    while beyond is None:
        fitted = refit(x0 + fraction * (bound - x0), start)
        refits += 1
        if fitted.rss - result.rss >= reach:
            beyond = fraction
        elif fraction >= 1.0:
            return bound, refits
        else:
            inside, start = fraction, fitted.values
            fraction = min(max(2.0 * fraction, PROFILE_FIRST), 1.0)
    if beyond <= linear:  # risen by the bootstrap's end: it stands
        return linear_end, refits
    for _ in range(PROFILE_BISECTIONS):
        middle = (inside + beyond) / 2
        fitted = refit(x0 + middle * (bound - x0), start)
        refits += 1
        if fitted.rss - result.rss >= reach:
            beyond = middle
        else:
            inside, start = middle, fitted.values
    return x0 + max((inside + beyond) / 2, linear) * (bound - x0), refits
