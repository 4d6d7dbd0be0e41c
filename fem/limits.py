"""The one set of limits of a muscle's numbers, the one check of them, and the practical range.

:data:`LIMITS` are the bounds beyond which a value is a typo, not a muscle (``--D0 1e9`` would
give 3e17 N; ``D0 1e-300`` a zero force). :func:`outside` is the check, for a number or an array
of them; the force-model interface (:func:`mkm.fem.interface.validate_inputs`), reference tables
(:mod:`mkm.fem.calibration`), tolerances and the muscle type (:class:`mkm.fem.muscle.Muscle`:
the bench configuration, the run folder, design) all ask it.

:data:`PRACTICAL_RANGE` is much narrower: every braided muscle a lab buys or makes (Festo-class
10-40 mm muscles at 6-8 bar as well as the paper's silicone tubes). Every physics model accepts
it, the stability map covers it and the default surrogate is trained over it;
:func:`range_text` is how it is stated to a user, and :func:`mkm.fem.sampling.draw_muscles`
draws fresh muscles from it.
"""

from __future__ import annotations

import dataclasses
import math
import re
from dataclasses import dataclass
from typing import Any, ClassVar

#: name -> (low, high, what the value is, unit); both bounds included except :data:`OPEN_ABOVE`
LIMITS: dict[str, tuple[float, float, str, str]] = {
    "pressure_bar": (0.0, 1000.0, "a gauge pressure", "bar"),
    "D0_mm": (1.0, 500.0, "an inner diameter", "mm"),
    "t0_mm": (0.05, 100.0, "a wall thickness", "mm"),
    "L0_mm": (10.0, 3000.0, "a length at rest", "mm"),
    "eps": (0.0, 1.0, "a shortening ratio", "(a fraction)"),
    "theta0_deg": (1.0, 89.0, "a braid angle at rest", "deg"),
    "C10_MPa": (1e-4, 100.0, "a Mooney-Rivlin C10", "MPa"),
    "C01_MPa": (0.0, 100.0, "a Mooney-Rivlin C01", "MPa"),
    "gap_mm": (0.0, 100.0, "a radial gap between tube and braid", "mm"),
}
#: the upper bound of these is excluded (eps = 1 is a muscle of zero length)
OPEN_ABOVE = frozenset({"eps"})
# A muscle id names the run folder and labels figures and reports: no path separators, no
# markup, no spreadsheet formula, no mathtext; no trailing dot, which Windows drops from a name.
MUSCLE_ID_PATTERN = r"[A-Za-z0-9](?:[A-Za-z0-9._+-]{0,62}[A-Za-z0-9_+-])?"


def limit_text(name: str) -> str:
    """``expected an inner diameter in [1, 500] mm``."""
    low, high, what, unit = LIMITS[name]
    close = ")" if name in OPEN_ABOVE else "]"
    return f"expected {what} in [{low:g}, {high:g}{close} {unit}"


def outside(name: str, values):
    """Where ``values`` (a number, or a numpy or pandas array) lie outside ``LIMITS[name]``:
    a bool of the same shape; NaN counts as outside."""
    low, high = LIMITS[name][:2]
    above = values >= high if name in OPEN_ABOVE else values > high
    return (values < low) | above | (values != values)  # the last: NaN


def check_value(name: str, value: Any, prefix: str = "") -> float:
    """``value`` as a float inside :data:`LIMITS`; ``ValueError`` names it and the range."""
    if isinstance(value, bool):
        raise ValueError(f"{prefix}{name}={value!r} is not a number: {limit_text(name)}")
    try:
        number = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{prefix}{name}={value!r} is not a number: {limit_text(name)}") from None
    if not math.isfinite(number) or outside(name, number):
        raise ValueError(f"{prefix}{name}={number:g} is invalid: {limit_text(name)}")
    return number


def check_wall(D0_mm: float, t0_mm: float, prefix: str = "") -> None:
    """A wall thinner than the tube's radius (``t0_mm < D0_mm / 2``)."""
    if not t0_mm < D0_mm / 2:
        raise ValueError(f"{prefix}t0_mm={t0_mm:g} is too thick for D0_mm={D0_mm:g}: expected "
                         f"t0_mm < D0_mm/2 = {D0_mm / 2:g}")


def check_gap(D0_mm: float, t0_mm: float, gap_mm: float, prefix: str = "") -> None:
    """A gap between tube and braid narrower than the tube's outer radius (``gap_mm < D0_mm / 2
    + t0_mm``): wider, the braid would be more than twice the tube's width and the tube would
    have to double its diameter before the braid pulls, which asks of the rubber a stretch no
    muscle's sleeve does (a tube in a sleeve it cannot fill is no muscle)."""
    outer_radius_mm = D0_mm / 2 + t0_mm
    if not gap_mm < outer_radius_mm:
        raise ValueError(f"{prefix}gap_mm={gap_mm:g} is too wide for D0_mm={D0_mm:g}, t0_mm="
                         f"{t0_mm:g}: expected gap_mm < D0_mm/2 + t0_mm = {outer_radius_mm:g} mm "
                         "(the tube's outer radius: a braid more than twice the tube's width "
                         "is no muscle's sleeve)")


def check_muscle_id(value: Any, where: str = "muscle.id") -> str:
    """``value`` if it is a valid muscle id (:data:`MUSCLE_ID_PATTERN`), else ``ValueError``."""
    if not isinstance(value, str) or not re.fullmatch(MUSCLE_ID_PATTERN, value):
        text = value if isinstance(value, str) else repr(value)
        shown = repr(text if len(text) <= 40 else text[:40] + "...")
        raise ValueError(f"{where}={shown} ({len(text)} characters) is invalid: expected 1 to "
                         "64 ASCII letters (no accents), digits or . _ + -, starting with a letter "
                         "or digit and not ending in '.' (it names the run folder and labels "
                         "figures)")
    return value


#: The braid's locking angle, arccos(1/sqrt(3)) = 54.7356 deg from the axis: at it the sleeve
#: encloses its largest volume and the muscle can shorten no further.
LOCKING_ANGLE_DEG = math.degrees(math.acos(1.0 / math.sqrt(3.0)))


def check_theta0(theta0_deg: float, prefix: str = "") -> float:
    """``theta0_deg`` as a float, or ``ValueError`` (naming it with ``prefix``) unless
    0 < theta0 < :data:`LOCKING_ANGLE_DEG`: at or above it the muscle cannot pull."""
    theta0 = float(theta0_deg)
    if not 0.0 < theta0 < LOCKING_ANGLE_DEG:
        raise ValueError(f"{prefix}theta0_deg={theta0:g} is invalid: expected 0 < theta0 < "
                         f"{LOCKING_ANGLE_DEG:.1f} deg (above the locking angle the muscle "
                         "cannot pull)")
    return theta0


def lock_eps(theta0_deg):
    """The shortening at which a braid of angle ``theta0_deg`` [deg] at rest locks [fraction]:
    ``1 - 1 / (sqrt(3) cos theta0)`` (the braid angle reaches :data:`LOCKING_ANGLE_DEG`); a
    number or an array."""
    if isinstance(theta0_deg, int | float):  # quick commands state the range without numpy
        cos = math.cos(math.radians(theta0_deg))
    else:
        import numpy as np

        cos = np.cos(np.deg2rad(theta0_deg))
    return 1.0 - 1.0 / (math.sqrt(3.0) * cos)


def past_lock_text(theta0_deg: float) -> str:
    """Why a point at or past the braid lock of ``theta0_deg`` [deg] has no force, as every
    table's reason column says it: ``past the braid lock: eps >= eps_max 0.2463 at theta0 40
    deg``."""
    return (f"past the braid lock: eps >= eps_max {lock_eps(float(theta0_deg)):.4g} at theta0 "
            f"{float(theta0_deg):g} deg")


@dataclass(frozen=True)
class PracticalRange:
    """A box of muscles: ``(low, high)`` per named quantity (both included) and the coupled
    constraints between them.

    Attributes
    ----------
    D0_mm, t0_mm, L0_mm : (float, float)
        Inner diameter, wall thickness and length at rest of the tube [mm].
    pressure_bar : (float, float)
        Gauge pressure [bar].
    theta0_deg : (float, float)
        Braid angle at rest [deg].
    C10_MPa : (float, float)
        Mooney-Rivlin C10 of the rubber [MPa].
    C01_per_C10 : (float, float)
        The rubber's C01 / C10 (a ratio).
    eps_per_lock : (float, float)
        The shortening ratio as a fraction of the braid lock's, ``eps / lock_eps(theta0)``.
    t0_per_D0_max : float
        The thickest wall: ``t0_mm <= t0_per_D0_max * D0_mm``.
    L0_per_D0_min : float
        The shortest muscle: ``L0_mm >= L0_per_D0_min * D0_mm``.
    """

    D0_mm: tuple[float, float] = (5.0, 60.0)
    t0_mm: tuple[float, float] = (0.5, 6.0)
    L0_mm: tuple[float, float] = (50.0, 1000.0)
    pressure_bar: tuple[float, float] = (0.0, 8.0)
    theta0_deg: tuple[float, float] = (15.0, 40.0)
    C10_MPa: tuple[float, float] = (0.03, 0.6)
    C01_per_C10: tuple[float, float] = (0.0, 1.5)
    eps_per_lock: tuple[float, float] = (0.0, 1.0)
    t0_per_D0_max: float = 0.3
    L0_per_D0_min: float = 3.0

    #: the quantities held as (low, high), in the order they are stated
    INTERVALS: ClassVar[tuple[str, ...]] = ("D0_mm", "t0_mm", "L0_mm", "pressure_bar",
                                            "theta0_deg", "C10_MPa", "C01_per_C10",
                                            "eps_per_lock")

    def __post_init__(self):
        for name in self.INTERVALS:
            low, high = (float(v) for v in getattr(self, name))
            if not low <= high:
                raise ValueError(f"{name}=({low:g}, {high:g}) is invalid: expected low <= high")
            if name in LIMITS and (outside(name, low) or outside(name, high)):
                raise ValueError(f"{name}=({low:g}, {high:g}) is invalid: {limit_text(name)}")
            object.__setattr__(self, name, (low, high))
        if not (0.0 <= self.eps_per_lock[0] and self.eps_per_lock[1] <= 1.0):
            raise ValueError(f"eps_per_lock={self.eps_per_lock} is invalid: expected within "
                             "[0, 1] (beyond 1 the braid is past its lock)")
        if not 0.0 < self.t0_per_D0_max < 0.5:
            raise ValueError(f"t0_per_D0_max={self.t0_per_D0_max:g} is invalid: expected in "
                             "(0, 0.5) (a wall thinner than the tube's radius)")

    def hull(self) -> dict[str, tuple[float, float]]:
        """The rectangular box around the range, per muscle number and pressure (the coupled
        constraints left out): ``eps`` up to the lock at the smallest angle, ``C01_MPa`` up to
        the largest ratio times the largest C10."""
        out = {name: getattr(self, name) for name in
               ("pressure_bar", "D0_mm", "t0_mm", "L0_mm", "theta0_deg", "C10_MPa")}
        out["t0_mm"] = (self.t0_mm[0], min(self.t0_mm[1], self.t0_per_D0_max * self.D0_mm[1]))
        out["eps"] = (self.eps_per_lock[0] * float(lock_eps(self.theta0_deg[1])),
                      self.eps_per_lock[1] * float(lock_eps(self.theta0_deg[0])))
        out["C01_MPa"] = (self.C01_per_C10[0] * self.C10_MPa[0],
                          self.C01_per_C10[1] * self.C10_MPa[1])
        return out

    def length_note(self, D0_mm: float, L0_mm: float) -> str | None:
        """A muscle shorter than ``L0_per_D0_min`` diameters, said with the rule and what the
        models do there (None for a longer one): a note, not an error, for a lab may have
        such a muscle."""
        if not L0_mm < self.L0_per_D0_min * D0_mm:
            return None
        k = self.L0_per_D0_min
        return (f"L0 {L0_mm:g} mm is below {k:g} D0 = {k * D0_mm:g} mm, outside the practical "
                f"range every model is validated over (L0 >= {k:g} D0, `mkm models`): the "
                "clamped ends, which Equation 2 and the thick-wall form leave out (they take "
                "a cylinder), are much of a muscle this short; every model still computes it, "
                "as an extrapolation")

    def lock_note(self, eps: float) -> str | None:
        """A shortening past the braid lock at the range's lowest angle, the largest lock of any
        braid in it (None below): held so short a muscle never pulls. A note, not an error (a
        slack length is a length), that names a percentage typed as a fraction."""
        theta0 = self.theta0_deg[0]
        lock = float(lock_eps(theta0))
        if not eps > lock:
            return None
        return (f"eps {eps:g} is past the braid lock of every muscle of the practical range "
                f"({lock:.3g} at {theta0:g} deg, its lowest braid angle): held so short, a "
                f"muscle never pulls (check the eps: {eps:g} is {100 * eps:g} %; for {eps:g} % "
                f"give --eps {eps:g}%)")

    def violations(self, **values) -> list[str]:
        """What of one muscle (``D0_mm=..., t0_mm=..., eps=..., C01_MPa=...``: any of the
        quantities, by their muscle names) lies outside the range, one phrase each; empty
        inside. ``eps`` is checked against the lock when ``theta0_deg`` is given, ``C01_MPa``
        when ``C10_MPa`` is."""
        out = []
        for name in ("D0_mm", "t0_mm", "L0_mm", "pressure_bar", "theta0_deg", "C10_MPa"):
            if values.get(name) is not None:
                low, high = getattr(self, name)
                if not low <= float(values[name]) <= high:
                    out.append(f"{name}={float(values[name]):g} outside [{low:g}, {high:g}]")
        D0, t0, L0 = (values.get(k) for k in ("D0_mm", "t0_mm", "L0_mm"))
        # a bound that is a product is itself rounded (1.5 x 0.6 = 0.8999999999999999): a value
        # typed at it is on it
        slack = 1.0 + 1e-12
        if D0 is not None and t0 is not None and t0 > self.t0_per_D0_max * D0 * slack:
            out.append(f"t0_mm={t0:g} above {self.t0_per_D0_max:g} D0_mm = "
                       f"{self.t0_per_D0_max * D0:g}")
        if D0 is not None and L0 is not None and L0 * slack < self.L0_per_D0_min * D0:
            out.append(f"L0_mm={L0:g} below {self.L0_per_D0_min:g} D0_mm = "
                       f"{self.L0_per_D0_min * D0:g}")
        C10, C01 = values.get("C10_MPa"), values.get("C01_MPa")
        if C10 is not None and C01 is not None:
            low, high = self.C01_per_C10
            if not low * C10 <= C01 * slack or C01 > high * C10 * slack:
                out.append(f"C01_MPa={C01:g} outside [{low:g}, {high:g}] x C10_MPa")
        theta0, eps = values.get("theta0_deg"), values.get("eps")
        if theta0 is not None and eps is not None:
            lock = float(lock_eps(theta0))
            low, high = (f * lock for f in self.eps_per_lock)
            if not low <= eps <= high:
                out.append(f"eps={eps:g} outside [{low:.4g}, {high:.4g}] (the braid lock at "
                           f"theta0_deg={theta0:g} is {lock:.4g})")
        return out

    def replace(self, **changes) -> PracticalRange:
        """A copy with some quantities changed (checked again)."""
        return dataclasses.replace(self, **changes)


#: Every braided muscle a lab buys or makes: see :func:`range_text`.
PRACTICAL_RANGE = PracticalRange()


def range_text(box: PracticalRange = PRACTICAL_RANGE) -> str:
    """The range stated for a user, numbers taken from ``box``."""
    def span(name: str) -> str:
        low, high = getattr(box, name)
        return f"{low:g}-{high:g}"

    theta_low, theta_high = box.theta0_deg
    lock_high, lock_low = (float(lock_eps(a)) for a in (theta_low, theta_high))
    if box.eps_per_lock == (0.0, 1.0):
        eps = "eps from 0 to the braid lock"
    else:
        eps = f"eps from {box.eps_per_lock[0]:g} to {box.eps_per_lock[1]:g} of the braid lock"
    return (f"inner diameter D0 {span('D0_mm')} mm, wall t0 {span('t0_mm')} mm with t0 <= "
            f"{box.t0_per_D0_max:g} D0, length L0 {span('L0_mm')} mm with L0 >= "
            f"{box.L0_per_D0_min:g} D0, pressure {span('pressure_bar')} bar, braid angle "
            f"theta0 {span('theta0_deg')} deg, rubber C10 {span('C10_MPa')} MPa with C01/C10 "
            f"{span('C01_per_C10')}, {eps} (eps_max = 1 - 1/(sqrt(3) cos theta0): "
            f"{lock_high:.3f} at {theta_low:g} deg, {lock_low:.3f} at {theta_high:g} deg)")
