"""The ladder of physics force models by name: Equation 2, thick-wall closed form, FE model.

Entries are ``"module:Class"`` strings so that a cheap model never imports the FE machinery. The
application's predictor registry (``mkm.registry``, ``mkm models``) builds on this table and adds
the surrogates and ``auto``; the dataset builder sends rung names to its workers.
"""

from __future__ import annotations

import inspect
from importlib import import_module

from mkm.fem.interface import ForceModel

LADDER: dict[str, str] = {
    "eq2": "mkm.fem.eq2:Eq2",
    "thickwall": "mkm.fem.thickwall:ThickWall",
    "axisym": "mkm.fem.fe.model:Axisym",
}


def model_names() -> list[str]:
    return list(LADDER)


def model_class(name: str) -> type[ForceModel]:
    if name not in LADDER:
        raise ValueError(f"unknown model {name!r}: expected one of {', '.join(LADDER)}")
    module, cls = LADDER[name].split(":")
    return getattr(import_module(module), cls)


def make_model(name: str, **params) -> ForceModel:
    """Instantiate rung ``name`` with ``params`` (None values mean "use the default")."""
    factory = model_class(name)
    given = {k: v for k, v in params.items() if v is not None}
    accepted = inspect.signature(factory).parameters
    unknown = sorted(set(given) - set(accepted))
    if unknown:
        raise ValueError(f"model {name!r} takes no parameter {', '.join(unknown)}: "
                         f"expected some of {', '.join(accepted) or 'none'}")
    return factory(**given)
