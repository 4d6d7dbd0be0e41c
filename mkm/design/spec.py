"""The specification of a design: requirements, constraints, objectives, the spec file."""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from mkm.core.ranges import parse_fraction, parse_number
from mkm.core.toml_text import read_toml_file
from mkm.fem.calibration import Calibration, calibrated
from mkm.fem.limits import check_value
from mkm.fem.materials import MATERIALS, MooneyRivlin, mooney_rivlin
from mkm.fem.muscle import Muscle
from mkm.flags import FLAG_OF, unit_of

#: each objective (the first is the default) and how it ranks the designs' table: the columns
#: sorted by, each ascending or not (ties on the first: the larger margin or the narrower muscle)
OBJECTIVES: dict[str, tuple[tuple[str, bool], ...]] = {
    "min-outer-diameter": (("outer_diameter_mm", True), ("min_margin_pct", False)),
    "min-rubber-volume": (("rubber_volume_cm3", True), ("min_margin_pct", False)),
    "max-margin": (("min_margin_pct", False), ("outer_diameter_mm", True)),
}
DEFAULT_OBJECTIVE = next(iter(OBJECTIVES))
#: the best designs of the search verified with the FE model unless a spec or ``top`` says
DEFAULT_TOP = 5
#: the probability each robust design (``--tolerance``) meets every requirement unless asked
DEFAULT_PROBABILITY = 0.95
#: the rubber of the calibration (a muscle ``mkm identify`` learnt), else Silastic S
CALIBRATED_RUBBER = "calibrated"
DEFAULT_RUBBER = CALIBRATED_RUBBER


def rubber_of(name: str, calibration: Calibration | None = None) -> MooneyRivlin:
    """The Mooney-Rivlin rubber a design's ``rubber`` names: a set of
    :data:`mkm.fem.materials.MATERIALS`, or :data:`CALIBRATED_RUBBER` (the FE model's entry in
    ``calibration``, default the shipped one)."""
    if name == CALIBRATED_RUBBER:
        try:
            entry = calibrated("axisym", calibration)
        except ValueError:
            entry = {}
        return mooney_rivlin(entry.get("C10_MPa"), entry.get("C01_MPa"))
    return MATERIALS[name]
def design_muscle(row, calibration: Calibration | None = None, eps: float = 0.0,
                  gap_mm: float | None = None) -> Muscle:
    """The muscle a design (a row of the designs' table) describes, held at ``eps``: its
    geometry, length, braid angle and rubber (``rubber`` named as in :func:`rubber_of`), and
    the gap between tube and braid it was designed with (``gap_mm`` [mm]; None or 0: none).
    Its id is :func:`design_id`'s."""
    rubber = rubber_of(str(row["rubber"]), calibration)
    return Muscle(D0_mm=float(row["D0_mm"]), t0_mm=float(row["t0_mm"]),
                  L0_mm=float(row["L0_mm"]), eps=eps, theta0_deg=float(row["theta0_deg"]),
                  C10_MPa=rubber.C10_MPa, C01_MPa=rubber.C01_MPa, gap_mm=gap_mm or None,
                  id=design_id(row))


def design_id(row) -> str:
    """A design's muscle id from its geometry, ``design-D31.25-t2.5-L282-th30`` (D0, t0 and L0
    [mm], theta0 [deg]): a valid id for a bench config's ``[muscle]`` and a run folder's name,
    and the same design always the same id."""
    return (f"design-D{float(row['D0_mm']):.4g}-t{float(row['t0_mm']):.4g}"
            f"-L{float(row['L0_mm']):.4g}-th{float(row['theta0_deg']):.4g}")


#: A requirement is near the braid lock from 75 % of Equation 2's eps_max on: the pressure term
#: of the force has fallen to about a fifth of its value at rest there (theta0 = 32 deg).
NEAR_LOCK_FRACTION = 0.75


# --- the specification --------------------------------------------------------------------------


@dataclass(frozen=True)
class Requirement:
    """One operating point: the muscle must develop at least ``force_N`` [N] at gauge pressure
    ``pressure_bar`` [bar], held at shortening ratio ``eps`` [fraction]."""

    force_N: float
    pressure_bar: float
    eps: float

    def __post_init__(self):
        if not self.force_N > 0:
            raise ValueError(f"requirement {self.label}: force {self.force_N:g} N is invalid: "
                             "expected a force > 0 N")
        if not self.pressure_bar > 0:
            raise ValueError(f"requirement {self.label}: pressure {self.pressure_bar:g} bar is "
                             "invalid: expected a gauge pressure > 0 bar")
        if not 0 <= self.eps < 1:
            raise ValueError(f"requirement {self.label}: eps={self.eps:g} is invalid: expected "
                             "a shortening ratio in [0, 1) (a fraction, or a percentage with %)")

    @property
    def label(self) -> str:
        return f"{self.force_N:g}N@{self.pressure_bar:g}bar,eps={self.eps:g}"


_REQUIREMENT = re.compile(r"^\s*([^@\s]+?)\s*N?\s*@\s*([^,\s]+?)\s*(?:bar)?\s*,\s*eps\s*=\s*"
                          r"(\S+)\s*$", re.IGNORECASE)


def parse_requirement(text: str, name: str = "--require") -> Requirement:
    """A :class:`Requirement` from ``"400N@2bar,eps=0.10"`` (eps also as ``10%``)."""
    match = _REQUIREMENT.match(str(text))
    if not match:
        raise ValueError(f"{name} {text!r} is malformed: expected FORCE N@PRESSURE bar,eps=EPS, "
                         "for example 400N@2bar,eps=0.10")
    force, pressure, eps = match.groups()
    # as typed, unit included: the pattern took the N and bar off ("300kN" would be "300k")
    typed_force, _, rest = str(text).partition("@")
    typed = {"force": (force, typed_force.strip(), "N", "newtons (N)", "0.4kN"),
             "pressure": (pressure, rest.split(",")[0].strip(), "bar", "bar", "200kPa")}
    numbers = {}
    for what, (number, shown, unit, unit_name, other) in typed.items():
        try:
            numbers[what] = parse_number(number, f"{name} {what}")
        except ValueError:
            try:  # another unit of its kind, converted as the CLI's options are (0.4kN, 200kPa)
                numbers[what] = parse_number(shown, f"{name} {what}", unit)
            except ValueError:
                raise ValueError(f"{name} {text!r}: {what} {shown!r}: expected a finite "
                                 f"number of {unit_name} (or with a unit of its kind, {other}),"
                                 " for example 400N@2bar,eps=0.10") from None
    return Requirement(numbers["force"], numbers["pressure"],
                       parse_fraction(eps, f"{name} {text!r}: eps"))


def parse_bounds(text, name: str, unit: str | None = None) -> tuple[float, float]:
    """``(low, high)`` from a value (``"37"``, fixed) or a range ``"30:50"``, above 0 (a size
    or an angle); numbers pass; with ``unit``, a number typed with a unit is converted
    (``"8mm:0.55in"``, :func:`mkm.core.ranges.parse_number`)."""
    if isinstance(text, int | float):
        value = parse_number(text, name, unit)
        return value, value
    if isinstance(text, list | tuple):
        parts = list(text)
    else:
        parts = str(text).split(":")
    if len(parts) == 1:
        parts = parts * 2
    if len(parts) != 2:
        raise ValueError(f"{name} {text!r} is malformed: expected a value or low:high "
                         "(for example 30:50)")
    low, high = (parse_number(p, name, unit) for p in parts)
    if low <= 0:  # a diameter, wall, length or angle: a sign typo, not a muscle
        raise ValueError(f"{name} {text!r} is invalid: expected values above 0")
    if low > high:
        raise ValueError(f"{name} {text!r} conflicts with itself: low {low:g} is above high "
                         f"{high:g}")
    return low, high


@dataclass(frozen=True)
class Constraints:
    """The design box and the housing. ``None`` means: D0 and t0 over the surrogate's training
    box, L0 the identified muscle's of a calibration identified on one length (``mkm
    identify``), else the surrogate's (the paper's 282 mm), theta0 the FE model's calibration
    (``fem/calibration.json`` or ``--calibration FILE``); rubber a name of
    :data:`mkm.fem.materials.MATERIALS` (or several).

    Parameters
    ----------
    D0_mm, t0_mm, L0_mm, theta0_deg : (low, high) or float or "low:high", optional
        Ranges or fixed values [mm, deg].
    rubber : str or tuple of str
        Wall material(s).
    max_outer_diameter_mm : float, optional
        Largest braid diameter of the muscle at the working pressure [mm] (its housing).
    max_pressure_bar : float, optional
        Largest working pressure [bar]; also the pressure the housing check uses.
    gap_mm : float, optional
        Radial gap between the tube and the braid at rest [mm] of the muscles as built (a
        fixed value, not searched). The surrogate has no gap: with one, the FE model (which
        takes it) searches and verifies.
    """

    D0_mm: tuple[float, float] | None = None
    t0_mm: tuple[float, float] | None = None
    L0_mm: tuple[float, float] | None = None
    theta0_deg: tuple[float, float] | None = None
    rubber: tuple[str, ...] = (DEFAULT_RUBBER,)
    max_outer_diameter_mm: float | None = None
    max_pressure_bar: float | None = None
    gap_mm: float | None = None

    def __post_init__(self):
        for key in ("D0_mm", "t0_mm", "L0_mm", "theta0_deg"):
            value = getattr(self, key)
            if value is not None:
                object.__setattr__(self, key, parse_bounds(value, key, unit_of(key)))
        rubber = (self.rubber,) if isinstance(self.rubber, str) else tuple(self.rubber)
        unknown = [r for r in rubber if r not in MATERIALS and r != CALIBRATED_RUBBER]
        if unknown or not rubber:
            raise ValueError(f"rubber {', '.join(unknown) or 'none'} is unknown: expected some "
                             f"of {CALIBRATED_RUBBER}, {', '.join(MATERIALS)}")
        object.__setattr__(self, "rubber", rubber)
        for key in ("max_outer_diameter_mm", "max_pressure_bar"):
            value = getattr(self, key)
            if value is not None:
                value = parse_number(value, key, unit_of(key))
                if not value > 0:
                    raise ValueError(f"{key}={value:g} is invalid: expected a value > 0")
                object.__setattr__(self, key, value)
        if self.gap_mm is not None:
            object.__setattr__(self, "gap_mm", check_value("gap_mm", self.gap_mm))


@dataclass(frozen=True)
class Hints:
    """How the user set the design's options, so that a hint is in the form they use: a
    ``--spec`` file's keys (``L0_mm = [60, 120] in spec.toml's [constraints]``) for an option
    the flags did not set over it, else the flag (``--L0 60:120``, :data:`mkm.flags.FLAG_OF`:
    a spec file's key is the option's name); and which options the user
    gave (the spec's or a flag's), whose ends are the user's own bounds.

    ``spec``: the spec file's name ("" without); ``flags``: the options a flag set (over the
    spec's); ``given``: every option the user set, by flag or in the spec."""

    spec: str = ""
    flags: frozenset = frozenset()
    given: frozenset = frozenset()

    def in_spec(self, key: str) -> bool:
        return bool(self.spec) and key not in self.flags

    def name(self, key: str) -> str:
        """``--L0``, or ``L0_mm in spec.toml's [constraints]`` (``top in spec.toml``)."""
        return f"{key} in {self._where(key)}" if self.in_spec(key) else FLAG_OF[key]

    def option(self, key: str, value: str) -> str:
        """``--L0 60:120``, or ``L0_mm = [60, 120] in spec.toml's [constraints]``; ``value``
        as the flag takes it (``MM``, ``A:B``, ``calibrated,silastic_s``)."""
        return self.options({key: value})

    def options(self, values: dict) -> str:
        """Several :meth:`option` s: the flags', then the spec's keys, each table named once."""
        flags = [f"{FLAG_OF[k]} {v}" for k, v in values.items() if not self.in_spec(k)]
        keys = [k for k in values if self.in_spec(k)]
        by_table: dict[str, list[str]] = {}
        for k in keys:
            by_table.setdefault(self._where(k), []).append(f"{k} = {_toml(k, values[k])}")
        spec = [f"{', '.join(pairs)} in {where}" for where, pairs in by_table.items()]
        return " and ".join(part for part in (" ".join(flags), *spec) if part)

    def own(self, key: str) -> str:
        """``your --L0`` or ``your L0_mm in spec.toml's [constraints]`` where the user gave
        ``key``, else ""."""
        return f"your {self.name(key)}" if key in self.given else ""

    def _where(self, key: str) -> str:
        return self.spec if key == "top" else f"{self.spec}'s [constraints]"


def _toml(key: str, value: str) -> str:
    """A flag's value as the spec file's TOML: ``60:120`` -> ``[60, 120]``, ``a,b`` ->
    ``["a", "b"]`` (a rubber), a number or a placeholder (``MM``) as it is."""
    if key == "rubber":
        return "[" + ", ".join(f'"{r}"' for r in value.split(",")) + "]"
    if ":" in value:
        return "[" + ", ".join(value.split(":")) + "]"
    return value


SPEC_KEYS = {"objective", "top", "requirement", "constraints"}


def load_spec(path) -> dict:
    """A TOML design spec as ``design`` keyword arguments.

    ``[[requirement]]`` tables (``force_N``, ``pressure_bar``, ``eps``), ``[constraints]`` (the
    fields of :class:`Constraints`), ``objective`` and ``top``. Unknown keys are errors.
    """
    path = Path(path)
    _, table = read_toml_file(path, "--spec ", "a design spec (a TOML file)")
    unknown = sorted(set(table) - SPEC_KEYS)
    if unknown:
        raise ValueError(f"--spec {path}: unknown key(s) {', '.join(unknown)}: expected some of "
                         f"{', '.join(sorted(SPEC_KEYS))}")
    out: dict = {k: table[k] for k in ("objective", "top") if k in table}
    requirements = []
    items = table.get("requirement", [])
    if not isinstance(items, list):
        raise ValueError(f"--spec {path}: requirement = {items!r} is invalid: expected "
                         "[[requirement]] tables of force_N, pressure_bar and eps")
    for i, item in enumerate(items, start=1):
        keys = {"force_N", "pressure_bar", "eps"}
        if not isinstance(item, dict) or set(item) != keys:
            extra = sorted(set(item) - keys) if isinstance(item, dict) else []
            # TOML puts every key after [[requirement]] into that requirement
            hint = (f" (it has {', '.join(extra)}: keys written below a [[requirement]] "
                    "belong to it; put them above the first)" if extra else "")
            raise ValueError(f"--spec {path}: requirement {i} must have exactly force_N, "
                             f"pressure_bar and eps{hint}")
        where = f"--spec {path}: requirement {i}"
        eps = item["eps"]
        eps = (parse_fraction(eps, f"{where} eps") if isinstance(eps, str)
               else parse_number(eps, f"{where} eps"))
        # "0.3kN", "250kPa" converted, as --require's and the constraints' are
        requirements.append(Requirement(parse_number(item["force_N"], f"{where} force_N", "N"),
                                        parse_number(item["pressure_bar"],
                                                     f"{where} pressure_bar", "bar"), eps))
    out["requirements"] = requirements
    constraints = table.get("constraints", {})
    fields = set(Constraints.__dataclass_fields__)
    unknown = sorted(set(constraints) - fields)
    if unknown:
        raise ValueError(f"--spec {path}: unknown constraint(s) {', '.join(unknown)}: expected "
                         f"some of {', '.join(sorted(fields))}")
    out["constraints"] = constraints
    return out
