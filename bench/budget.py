"""The measurement uncertainty budget of a pressure step (GUM, JCGM 100:2008).

A step's force is the mean of the hold samples minus the tare; its pressure the mean of the
regulator monitor over the hold. Each standard uncertainty below is combined in quadrature
(uncorrelated inputs, sensitivity coefficients 1) and expanded to a coverage probability of
95.45 % (:data:`COVERAGE_PROBABILITY`, the probability of k = 2 for a normal distribution) with a
coverage factor ``k`` of its own per quantity (:func:`coverage_factor`): the quantile of the
terms' own distributions combined, rectangular bounds (type B data-sheet terms, an ADC step not
dithered) convolved with the normal remainder. ``k`` is 2 when the normal terms dominate and
falls to 1.65 (``0.9545 sqrt 3``) when one rectangular bound does: a k = 2 interval there covers
100 %, not 95 %. The type A terms' degrees of freedom (tens of samples each) are taken as
infinite. The budget table states each quantity's ``k``.

force [N]
    - load-cell sensitivity: ``loadcell.sensitivity_tolerance_fraction`` x ``abs(F)``, a rectangular
      bound (type B, divided by sqrt 3);
    - load-cell non-linearity and zero drift: ``loadcell.nonlinearity_fraction_fs`` and
      ``loadcell.zero_drift_fraction_fs`` x ``capacity_N``, rectangular (type B);
    - ADC resolution: one step of the device's ADC (the USB-6001: 14 bits over +-10 V, 1.22 mV,
      0.24 N on a 196 N/V cell) over sqrt 12, for the hold mean and for the tare mean; divided by
      sqrt n when the scatter is at least half a step (the noise dithers the rounding, which is
      then independent from sample to sample), not reduced otherwise (type B);
    - noise over the hold: the scatter about the hold's straight-line trend over sqrt n (type A);
    - tare spread: the tare's scatter over sqrt n (type A): the offset subtracted from every
      sample is a mean too.

    The drift within the hold (the trend's change from its first to its last sample, recorded
    as ``force_drift_N``) is removed from the scatter, so creep is not mistaken for noise, and is
    not a term: the hold's mean is the measurand, and a trend does not make its mean uncertain.
    The budget table shows it beside the terms.

pressure [bar]
    - the reading's error from the data sheet (type B, each rectangular: nothing more than a
      bound being known, GUM 4.3.7), as ``[regulator]`` declares it
      (:data:`mkm.bench.config.MONITOR_COMPONENTS`): either ``monitor_accuracy_bar``, one
      bound at every pressure; or its components, each its own term: the zero error
      ``monitor_zero_bar``, the span error ``monitor_span_fraction`` x the reading, the
      non-linearity ``monitor_nonlinearity_bar`` and half the hysteresis
      ``monitor_hysteresis_bar`` (a branch's reading is off by at most half the difference
      between the rising and falling ones);
    - ADC resolution of the monitor input, not reduced by averaging (the monitor's noise is below
      one step), electronic regulator only.

What the measurand is, and how friction and creep are treated: the measurand is the force the
muscle develops on the cell during the hold, braid friction and creep included: they are the
muscle's behaviour, not errors of the instrument, so no term of this budget stands for them.
The models of the ladder have neither; a model compared with a step therefore differs by the
friction of the branch (rising pressure reads low, falling high) and the creep so far, which the
consistency verdict of :mod:`mkm.scoring` shows rather than hides. On simulated runs whose truth
is known, with its instrument errors drawn within the data sheet (:mod:`mkm.bench.coverage`),
``benchmarks/bench_uncertainty.py`` measures how often the expanded interval covers the mean true
force and pressure of a step (:doc:`/guide/uncertainty`).

:func:`step_budget` computes a step's budget from what ``steps.csv`` records (so the report
recomputes the terms of a recorded step); :func:`expected_budget` the budget a configuration
allows before anything is pressurised, with the data terms at the settle and tare limits.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import fft, special

#: the coverage probability of the expanded uncertainties: a normal distribution's at k = 2
COVERAGE_PROBABILITY = math.erf(2.0 / math.sqrt(2.0))
SQRT3 = math.sqrt(3.0)
SQRT12 = math.sqrt(12.0)
#: grid points over the combined distribution's support when k is computed
_GRID = 4001


def _convolve_same(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``scipy.signal.fftconvolve(a, b, mode="same")`` of two 1-D float arrays, computed as it
    computes it (the same padded FFTs and centring: the same numbers to the bit) without
    importing scipy.signal, a second at the start of every command that records a step."""
    full = a.size + b.size - 1
    n = fft.next_fast_len(full, True)
    out = fft.irfftn(fft.rfftn(a, [n], axes=[0]) * fft.rfftn(b, [n], axes=[0]), [n], axes=[0])
    start = (full - a.size) // 2
    return out[start:start + a.size].copy()


@dataclass(frozen=True)
class Term:
    """One input of a budget: its standard uncertainty ``u`` [N or bar] and where it comes from."""

    name: str
    quantity: str  # "force" [N] | "pressure" [bar]
    u: float
    kind: str  # "A" (from the data) | "B" (data sheet, device)
    source: str
    distribution: str = "normal"  # "normal" | "rectangular" (a +- bound, u = half-width / sqrt 3)


def coverage_factor(terms, probability: float = COVERAGE_PROBABILITY) -> float:
    """``k`` such that ``+- k u`` covers ``probability`` of the sum of ``terms`` (each with its
    own distribution, independent): rectangular terms convolved on a grid with the normal
    remainder. 2 for normal terms alone at 95.45 %; ``probability * sqrt 3`` for one
    rectangular term alone; NaN when the combined ``u`` is not finite or zero."""
    terms = [t for t in terms if math.isfinite(t.u) and t.u > 0]
    u = math.sqrt(sum(t.u**2 for t in terms))
    if not terms or not math.isfinite(u):
        return math.nan
    halves = [SQRT3 * t.u for t in terms if t.distribution == "rectangular"]
    sigma = math.sqrt(sum(t.u**2 for t in terms if t.distribution != "rectangular"))
    if not halves:
        return math.sqrt(2.0) * float(special.erfinv(probability))
    if sigma == 0 and len(halves) == 1:
        return probability * SQRT3
    reach = sum(halves) + 8.0 * sigma
    x = np.linspace(-reach, reach, _GRID)
    h = x[1] - x[0]
    density = np.zeros_like(x)
    density[_GRID // 2] = 1.0 / h
    kernels = [(np.abs(x) <= a).astype(float) for a in halves]  # boxes of half-width a
    if sigma > 0:
        kernels.append(np.exp(-0.5 * (x / sigma) ** 2))
    for kernel in kernels:
        # a term narrower than the grid's step is a point there (an empty box or Gaussian
        # would divide by 0): nothing to spread
        if np.count_nonzero(kernel) > 1:
            density = _convolve_same(density, kernel / kernel.sum())
    cdf = np.cumsum(np.clip(density, 0.0, None)) * h
    cdf /= cdf[-1]
    half = x[_GRID // 2:]
    inside = cdf[_GRID // 2:] - cdf[_GRID // 2::-1][:half.size]  # P(|X| <= x), symmetric
    return float(np.interp(probability, inside, half) / u)


@dataclass(frozen=True)
class Budget:
    """The terms of one step, combined (root sum of squares) and expanded with ``k``."""

    terms: tuple[Term, ...]
    drift_N: float = math.nan  # the hold's trend, first to last sample: shown, not a term

    def u(self, quantity: str) -> float:
        """Combined standard uncertainty of ``quantity`` ("force" [N] or "pressure" [bar])."""
        return math.sqrt(sum(t.u**2 for t in self.terms if t.quantity == quantity))

    def k(self, quantity: str) -> float:
        """Coverage factor of ``quantity`` for :data:`COVERAGE_PROBABILITY`
        (:func:`coverage_factor`)."""
        return coverage_factor([t for t in self.terms if t.quantity == quantity])

    @property
    def force_u_N(self) -> float:
        return self.u("force")

    def U(self, quantity: str) -> float:
        """Expanded uncertainty of ``quantity``: ``k u``; 0 where no term has any (a table's
        quantity whose accuracy its lab did not declare)."""
        u = self.u(quantity)
        return 0.0 if u == 0 else self.k(quantity) * u

    @property
    def force_U_N(self) -> float:
        return self.U("force")

    @property
    def pressure_u_bar(self) -> float:
        return self.u("pressure")

    @property
    def pressure_U_bar(self) -> float:
        return self.U("pressure")

    def columns(self) -> dict[str, float]:
        """The four columns of ``steps.csv``."""
        return {"force_u_N": self.force_u_N, "force_U_N": self.force_U_N,
                "pressure_u_bar": self.pressure_u_bar, "pressure_U_bar": self.pressure_U_bar}

    def ranked(self, quantity: str) -> list[tuple[Term, float]]:
        """The terms of ``quantity``, largest first, each with its share of the variance."""
        terms = [t for t in self.terms if t.quantity == quantity]
        total = sum(t.u**2 for t in terms)
        shares = [(t, t.u**2 / total if total > 0 else 0.0) for t in terms]
        return sorted(shares, key=lambda pair: -pair[1])


@dataclass(frozen=True)
class Instrument:
    """What a budget needs of the bench: the load cell's calibration and data-sheet bounds, the
    pressure reading's accuracy, the ADC's step."""

    capacity_N: float
    sensitivity_N_per_V: float
    sensitivity_tolerance_fraction: float
    nonlinearity_fraction_fs: float
    zero_drift_fraction_fs: float
    lsb_V: float
    monitor_accuracy_bar: float
    monitor_bar_per_V: float  # nan with a manual regulator (no monitor input)
    #: the declared components of the reading's error (``Regulator.monitor_components``)
    monitor_components: dict[str, float] = field(default_factory=dict)

    @classmethod
    def from_config(cls, config) -> Instrument:
        """From a :class:`mkm.bench.config.BenchConfig` and its backend's device."""
        from mkm.bench import backends

        caps = backends.entry(config.daq.backend).capabilities
        return cls._make(config.loadcell, config.regulator, caps.ai_lsb_V)

    @classmethod
    def from_run(cls, meta) -> Instrument:
        """From a run's ``run.json`` (:class:`mkm.bench.storage.RunMeta`): the calibration it
        recorded, the defaults of :mod:`mkm.bench.config` where it predates a setting."""
        from mkm.bench.backends import BACKENDS
        from mkm.bench.config import LoadCell, Regulator, from_record
        from mkm.bench.devices import USB6001

        cell = from_record(LoadCell, meta.calibration.get("loadcell") or {})
        regulator = from_record(Regulator, meta.calibration.get("regulator") or {})
        name = str(meta.hardware.get("backend"))
        caps = BACKENDS.entry(name).capabilities if name in BACKENDS else USB6001
        return cls._make(cell, regulator, caps.ai_lsb_V)

    @classmethod
    def _make(cls, cell, regulator, lsb_V: float) -> Instrument:
        span_V = regulator.monitor_V_at_full_scale - regulator.monitor_V_at_zero
        per_V = regulator.full_scale_bar / span_V if regulator.electronic else math.nan
        return cls(cell.capacity_N, cell.sensitivity_N_per_V,
                   cell.sensitivity_tolerance_fraction, cell.nonlinearity_fraction_fs,
                   cell.zero_drift_fraction_fs, lsb_V, regulator.monitor_accuracy_bar, per_V,
                   regulator.monitor_components)

    @property
    def lsb_N(self) -> float:
        """One ADC step in newtons."""
        return self.lsb_V * self.sensitivity_N_per_V


def residual_std(std: float, n: int, drift: float) -> float:
    """Scatter about a straight-line trend from the plain scatter ``std`` of ``n`` equally spaced
    samples whose trend changes by ``drift`` from the first to the last (ddof 2).

    The trend explains ``drift^2 n (n + 1) / (12 (n - 1))`` of the ``(n - 1) std^2`` sum of
    squares (exact for equal spacing).
    """
    if n < 3 or not math.isfinite(std):
        return math.nan
    drift = drift if math.isfinite(drift) else 0.0
    explained = drift**2 * n * (n + 1) / (12.0 * (n - 1))
    return math.sqrt(max((n - 1) * std**2 - explained, 0.0) / (n - 2))


def _resolution(lsb: float, scatter: float, n: int) -> float:
    """Standard uncertainty [units of ``lsb``] a rounding to ``lsb`` leaves in a mean of ``n``."""
    u = lsb / SQRT12
    dithered = math.isfinite(scatter) and scatter >= lsb / 2
    return u / math.sqrt(n) if dithered and n > 0 else u


def reading_terms(instrument: Instrument, pressure_bar: float) -> list[Term]:
    """The data-sheet terms of a pressure reading of ``pressure_bar`` [bar]: one per declared
    component, else the one bound ``monitor_accuracy_bar`` (see the module docstring)."""
    components = instrument.monitor_components
    if not components:
        a = instrument.monitor_accuracy_bar
        return [Term("pressure reading accuracy", "pressure", a / SQRT3, "B",
                     f"regulator.monitor_accuracy_bar={a:g}", "rectangular")]
    from mkm.bench.config import MONITOR_COMPONENTS

    terms = []
    for name, bound in components.items():
        source = f"regulator.{name}={bound:g}"
        if name == "monitor_span_fraction":
            half, source = bound * abs(pressure_bar), f"{source} x {pressure_bar:.3g} bar"
        elif name == "monitor_hysteresis_bar":
            half, source = bound / 2, f"{source}, half on either branch"
        else:
            half = bound
        terms.append(Term(f"monitor {MONITOR_COMPONENTS[name][1]}", "pressure", half / SQRT3,
                          "B", source, "rectangular"))
    return terms


def step_budget(instrument: Instrument, force_N: float, force_N_std: float, n: int,
                force_drift_N: float, tare_std_N: float, tare_n: int, *,
                pressure_bar: float) -> Budget:
    """The uncertainty budget of one step (see the module docstring).

    Parameters
    ----------
    instrument : Instrument
        The bench's calibration and data-sheet bounds.
    force_N : float
        The hold's mean force [N].
    force_N_std : float
        The hold samples' standard deviation [N] (ddof 1).
    n : int
        Samples in the hold.
    force_drift_N : float
        Change of the hold's straight-line trend from its first to its last sample [N].
    tare_std_N, tare_n : float, int
        The tare's standard deviation [N] and its number of samples.
    pressure_bar : float
        The hold's mean pressure reading [bar] (the span error is a fraction of it).
    """
    i = instrument
    scatter = residual_std(force_N_std, n, force_drift_N)
    q_hold = _resolution(i.lsb_N, scatter, n)
    q_tare = _resolution(i.lsb_N, tare_std_N, tare_n)
    terms = [
        Term("load-cell sensitivity", "force",
             i.sensitivity_tolerance_fraction * abs(force_N) / SQRT3, "B",
             f"loadcell.sensitivity_tolerance_fraction={i.sensitivity_tolerance_fraction:g}",
             "rectangular"),
        Term("load-cell non-linearity", "force",
             i.nonlinearity_fraction_fs * i.capacity_N / SQRT3, "B",
             f"loadcell.nonlinearity_fraction_fs={i.nonlinearity_fraction_fs:g}", "rectangular"),
        Term("load-cell zero drift", "force", i.zero_drift_fraction_fs * i.capacity_N / SQRT3,
             "B", f"loadcell.zero_drift_fraction_fs={i.zero_drift_fraction_fs:g}", "rectangular"),
        Term("ADC resolution", "force", math.hypot(q_hold, q_tare), "B",
             f"1 step = {i.lsb_V * 1e3:.3g} mV = {i.lsb_N:.3g} N",
             "normal" if math.isfinite(scatter) and scatter >= i.lsb_N / 2 else "rectangular"),
        Term("noise over the hold", "force",
             scatter / math.sqrt(n) if n > 2 and math.isfinite(scatter) else math.nan, "A",
             f"scatter about the trend {scatter:.3g} N over {n} samples"),
        Term("tare spread", "force",
             tare_std_N / math.sqrt(tare_n) if tare_n > 0 else math.nan, "A",
             f"tare scatter {tare_std_N:.3g} N over {tare_n} samples"),
        *reading_terms(i, pressure_bar),
    ]
    if math.isfinite(i.monitor_bar_per_V):
        lsb_bar = i.lsb_V * i.monitor_bar_per_V
        terms.append(Term("ADC resolution (monitor)", "pressure", lsb_bar / SQRT12, "B",
                          f"1 step = {lsb_bar:.3g} bar", "rectangular"))
    return Budget(tuple(terms), drift_N=force_drift_N)


#: what a declared accuracy may bound (``mkm import --accuracy``): each quantity's unit
DECLARED_QUANTITIES = {"force": "N", "pressure": "bar"}


@dataclass(frozen=True)
class Declared:
    """The +- bound every value of one quantity keeps, as a data sheet or a lab states it for a
    table measured elsewhere: a part in the quantity's unit (``absolute``, N or bar) and a part
    proportional to the value (``fraction``); ``text`` as it was given."""

    absolute: float = 0.0
    fraction: float = 0.0
    text: str = ""

    def record(self) -> dict:
        return {"absolute": self.absolute, "fraction_of_value": self.fraction, "given": self.text}

    @classmethod
    def from_record(cls, record: dict) -> Declared:
        return cls(float(record.get("absolute", 0.0)),
                   float(record.get("fraction_of_value", 0.0)), str(record.get("given", "")))


def declared_budget(declared: dict[str, Declared], force_N: float, pressure_bar: float,
                    force_N_std: float = math.nan, n: int = 1,
                    force_drift_N: float = math.nan) -> Budget:
    """The budget of a step measured elsewhere, from the bounds its lab declares
    (``declared``: quantity -> :class:`Declared`): each part of a bound its own rectangular
    term (type B; a data sheet's "0.1 % FS + 0.5 % of reading" is two terms), and, for a
    plateau of a time series (``n`` > 2 samples), the noise over it as on the bench (type A).
    A quantity with no declared bound has none: its ``u`` is 0."""
    values = {"force": force_N, "pressure": pressure_bar}
    terms = []
    for quantity, bound in declared.items():
        unit, given = DECLARED_QUANTITIES[quantity], f"--accuracy {quantity}={bound.text}"
        if bound.absolute > 0:
            terms.append(Term(f"declared {quantity} accuracy", quantity,
                              bound.absolute / SQRT3, "B", f"{given}: +-{bound.absolute:g} "
                              f"{unit}", "rectangular"))
        if bound.fraction > 0:
            half = bound.fraction * abs(values[quantity])
            terms.append(Term(f"declared {quantity} accuracy (of the value)", quantity,
                              half / SQRT3, "B", f"{given}: {100 * bound.fraction:g} % x "
                              f"{abs(values[quantity]):.4g} {unit}", "rectangular"))
    scatter = residual_std(force_N_std, n, force_drift_N)
    if n > 2 and math.isfinite(scatter):
        terms.append(Term("noise over the hold", "force", scatter / math.sqrt(n), "A",
                          f"scatter about the trend {scatter:.3g} N over {n} samples"))
    return Budget(tuple(terms), drift_N=force_drift_N)


def declared_step_budget(declared: dict[str, Declared], step, plateau: bool) -> Budget:
    """:func:`declared_budget` of one imported step (a :class:`mkm.bench.storage.StepRecord`
    or a row of its ``steps.csv``); ``plateau``: the step is a time series' plateau, whose
    scatter is noise (a ramp's bin spreads over a rising force, a table row has one value)."""
    held = (float(step.force_N_std), int(step.n), float(step.force_drift_N)) if plateau else ()
    return declared_budget(declared, float(step.force_N_mean), float(step.pressure_bar_mean),
                           *held)


def expected_budget(config, force_N: float, pressure_bar: float) -> Budget:
    """The budget a step of ``config`` can have at the force ``force_N`` [N] and the pressure
    ``pressure_bar`` [bar], before any run.

    The data terms take the largest values a step can pass with: the hold's scatter at
    ``settle.max_force_std_N``, its drift at ``settle.max_force_slope_N_per_s`` over
    ``settle.hold_s``, the tare's scatter at ``safety.tare_max_std_N``; so the expanded
    uncertainty is an upper bound, and the data-sheet terms show what the load cell allows.
    """
    st, rate = config.settle, config.daq.sample_rate_hz
    n = max(int(round(st.hold_s * rate)), 3)
    tare_n = max(int(round(config.sequence.tare_s * rate)), 2)
    drift = st.max_force_slope_N_per_s * st.hold_s
    # the plain scatter of a hold with that trend and that scatter about it
    std = math.sqrt((st.max_force_std_N**2 * (n - 2) + drift**2 * n * (n + 1) / (12 * (n - 1)))
                    / (n - 1))
    return step_budget(Instrument.from_config(config), force_N, std, n, drift,
                       config.safety.tare_max_std_N, tare_n, pressure_bar=pressure_bar)


def budget_table(budget: Budget, quantity: str = "force") -> list[str]:
    """Lines of text: the terms of ``quantity`` ranked by their share of the variance."""
    unit = "N" if quantity == "force" else "bar"
    ranked = budget.ranked(quantity)
    width = max([len("combined")] + [len(term.name) for term, _ in ranked])
    lines = [f"  {'term':<{width}}  type  {'u [' + unit + ']':>8}  share [%]  source"]
    for term, share in ranked:
        lines.append(f"  {term.name:<{width}}  {term.kind:<4}  {term.u:>8.3g}  "
                     f"{100 * share:>9.1f}  {term.source}")
    u = budget.u(quantity)
    k = budget.k(quantity)
    lines.append(f"  {'combined':<{width}}  {'':<4}  {u:>8.3g}  {100:>9}  expanded U = "
                 f"{k:.3g} u = {k * u:.3g} {unit} (k for {100 * COVERAGE_PROBABILITY:.2f} % "
                 "of the terms' distributions combined)")
    if quantity == "force" and math.isfinite(budget.drift_N):
        lines.append(f"(drift within the hold: {budget.drift_N:+.3g} N; the hold mean is the "
                     "measurand, so not a term)")
    return lines
