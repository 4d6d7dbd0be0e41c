"""The muscle: one description of a McKibben muscle for every package.

A muscle is its tube (inner diameter ``D0_mm``, wall ``t0_mm``), its length at rest ``L0_mm``,
its braid angle at rest ``theta0_deg``, its rubber (Mooney-Rivlin ``C10_MPa``, ``C01_MPa``), the
radial gap between its tube and its braid at rest ``gap_mm``, the +- tolerances it is made to,
and, on a bench, its ``id``; the shortening ratio ``eps`` (a fraction) is where it is held.
``None`` for the angle, the rubber or the gap means "not known": the models' defaults (the
calibrated angle, Silastic S, the calibration's gap or none).

The bench configuration's ``[muscle]`` table, a run folder's ``run.json`` (read by report and
identify), the force models (:meth:`mkm.fem.interface.ForceModel.predict_muscle`, models built
for a muscle with ``make_model(..., muscle=...)``) and design's results use this one type,
checked when made against the one set of limits (:mod:`mkm.fem.limits`).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass, field
from typing import Any

from mkm.fem.limits import (
    LIMITS,
    check_gap,
    check_muscle_id,
    check_theta0,
    check_value,
    check_wall,
)
from mkm.fem.tolerances import Tolerances

#: the numbers of a muscle, in the order run.json and tables list them
NUMBERS = ("D0_mm", "t0_mm", "L0_mm", "eps", "theta0_deg", "C10_MPa", "C01_MPa", "gap_mm")
#: the numbers a force model is built with (its geometry and eps are what it predicts at; a
#: model takes those of them it has a parameter for, ``gap_mm`` only the models of a gap)
MODEL_PARAMETERS = ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa", "gap_mm")
#: the numbers a muscle always has (the others: None when not known)
REQUIRED = ("D0_mm", "t0_mm", "L0_mm", "eps")


def eps_at_rest_length(L0_mm: float, eps: float, rest_length_mm: float) -> float:
    """The shortening ratio of a muscle declared ``L0_mm`` long at rest and held at ``eps``
    (its held length ``L0_mm (1 - eps)``) when its rest length is ``rest_length_mm`` instead
    [mm, fraction]: a table's longest length already shortened, a rest length identified."""
    return 1.0 - L0_mm * (1.0 - eps) / rest_length_mm



def _said(check, *args) -> list[str]:
    """The line of ``check(*args)``'s ``ValueError``, none where it passes."""
    try:
        check(*args)
    except ValueError as exc:
        return [str(exc)]
    return []

@dataclass(frozen=True)
class Muscle:
    """A McKibben muscle (see the module docstring); checked when made.

    Parameters
    ----------
    D0_mm, t0_mm : float
        Inner diameter and wall thickness of the tube at rest [mm].
    L0_mm : float
        Length at rest [mm]; default 282 (the paper's prototype).
    eps : float
        Shortening ratio at which it is held (a fraction).
    theta0_deg : float or None
        Braid angle at rest [deg]; None: the model's calibrated angle.
    C10_MPa, C01_MPa : float or None
        Mooney-Rivlin constants of the rubber [MPa]; None: the calibration's, else Silastic S.
    gap_mm : float or None
        Radial gap between the tube's outer surface and the braid at rest [mm] (the braid is
        ``D0 + 2 t0 + 2 gap`` wide); None: the calibration's (an identified muscle), else 0.
        Only the models of a gap (``thickwall``, ``axisym``) take it.
    id : str
        What the muscle is called on a bench (names its run folders); empty for a muscle of a
        computation.
    tolerances : Tolerances
        The +- bounds it is made to (:class:`mkm.fem.tolerances.Tolerances`).
    """

    D0_mm: float
    t0_mm: float
    L0_mm: float = 282.0
    eps: float = 0.0
    theta0_deg: float | None = None
    C10_MPa: float | None = None
    C01_MPa: float | None = None
    gap_mm: float | None = None
    id: str = ""
    tolerances: Tolerances = field(default_factory=Tolerances)

    def __post_init__(self):
        for name in NUMBERS:
            value = getattr(self, name)
            if value is not None or name in REQUIRED:
                object.__setattr__(self, name, check_value(name, value))
        check_wall(self.D0_mm, self.t0_mm)
        if self.gap_mm is not None:
            check_gap(self.D0_mm, self.t0_mm, self.gap_mm)
        if self.theta0_deg is not None:
            check_theta0(self.theta0_deg)
        if self.id:
            check_muscle_id(self.id, "id")
        if not isinstance(self.tolerances, Tolerances):
            raise ValueError(f"tolerances={self.tolerances!r} is invalid: expected Tolerances")

    @classmethod
    def from_dict(cls, data: Any, where: str = "muscle", **extra) -> Muscle:
        """The muscle a table holds (a run.json's ``muscle``, a config's ``[muscle]``): the
        required numbers, the known ones and ``id``; ``extra`` (``tolerances=...``) added.
        ``ValueError`` names ``where`` and the bad or missing field."""
        if not isinstance(data, dict):
            raise ValueError(f"{where} is not a table: expected {', '.join(('id', *REQUIRED))}")
        # every bad value at once, a line each (a configuration's check names them all)
        known = {f.name for f in dataclasses.fields(cls)} - {"tolerances"}
        unknown = sorted(map(str, set(data) - known))
        lines = [f"{where}.{name[:40]} is not a field of a muscle: expected some of "
                 f"{', '.join(sorted(known))}" for name in unknown]
        if not unknown:  # a misspelt D0_mm is named as such, not as a D0_mm missing too
            lines += [f"{where}.{name} is missing: expected the muscle's "
                      f"{LIMITS[name][2].split(' ', 1)[1]}" for name in REQUIRED
                      if name not in data]
        if "id" in data:
            lines += _said(check_muscle_id, data["id"], f"{where}.id")
        for name in NUMBERS:
            value = data.get(name)
            if value is None:
                continue
            if isinstance(value, bool) or not isinstance(value, int | float):
                lines.append(f"{where}.{name}={str(value)[:40]!r} is invalid: expected a number")
            else:
                lines += _said(check_value, name, value, f"{where}.")
        if lines:
            raise ValueError("\n".join(lines))
        try:
            return cls(**{k: data[k] for k in data}, **extra)
        except ValueError as exc:
            raise ValueError(f"{where}.{exc}") from None

    def model_parameters(self) -> dict[str, float]:
        """What a force model of this muscle is built with: ``L0_mm``, and the angle and the
        rubber where known (the others stay the model's calibrated defaults)."""
        return {k: getattr(self, k) for k in MODEL_PARAMETERS if getattr(self, k) is not None}

    def record(self) -> dict[str, Any]:
        """What a run folder records of it: ``id``, the geometry and ``eps``, and the angle,
        rubber and gap when known (the tolerances go with the run's calibration)."""
        return {"id": self.id, **{k: getattr(self, k) for k in NUMBERS
                                  if getattr(self, k) is not None}}
