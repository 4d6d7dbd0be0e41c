"""The command-line flag of each option: the one table that the command line and the library
read, so that a message or a hint names the flag the user types.

The command line (:mod:`mkm.cli`) says a library's ``D0_mm=-1 is invalid: ...`` about a value
typed as ``--D0 -1`` as ``--D0 -1: ...`` (:func:`mkm.cli.common.name_the_flag`), and declares
``mkm design``'s constraints by these flags; ``mkm design``'s hints name the flag of an option
(``widen it, e.g. --D0 20:50``, :class:`mkm.design.spec.Hints`), which mkm.design, below the
command line, cannot ask it for. It imports nothing of the project.
"""

from __future__ import annotations

#: option (a library's quantity, a design spec's key, a configuration's key) -> its flag
FLAG_OF: dict[str, str] = {
    "D0_mm": "--D0", "t0_mm": "--t0", "L0_mm": "--L0", "theta0_deg": "--theta0",
    "eps": "--eps", "muscle.eps": "--eps", "tolerance": "--tolerance",
    # mkm design's constraints and options
    "rubber": "--rubber", "max_outer_diameter_mm": "--max-outer-diameter",
    "max_pressure_bar": "--max-pressure", "gap_mm": "--gap", "top": "--top",
    # mkm surrogate's
    "splits": "--splits", "seeds": "--seeds", "jobs": "--jobs",
}


def dests(option: str) -> tuple[str, ...]:
    """Where a parsed command line may hold ``option``'s value: the option's own name (the
    ``dest`` of ``mkm design``'s constraints, ``max_pressure_bar``) and the flag's default
    ``dest`` (``--D0`` -> ``D0``, ``--max-pressure`` -> ``max_pressure``)."""
    return option, FLAG_OF[option].lstrip("-").replace("-", "_")


def unit_of(option: str) -> str:
    """The unit an option's name ends in, as its flag takes it: ``D0_mm`` -> ``mm``."""
    return option.rsplit("_", 1)[1]
