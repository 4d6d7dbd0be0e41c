"""The surrogate kinds as the application imports them; :mod:`mkm.surrogate.kinds` holds the
registry itself."""

from __future__ import annotations

from mkm.surrogate.kinds import BEST, make_estimator, names

__all__ = ["BEST", "kind_names", "make_estimator"]


def kind_names(include_nets: bool = True) -> list[str]:
    """Every kind :func:`make_estimator` builds: the single ones, then the paper's nets."""
    return names(include_families=include_nets)
