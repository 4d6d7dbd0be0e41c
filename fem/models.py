"""Registry of the force models available by name (``mkm fem solve --model NAME``).

Entries are ``"module:Class"`` strings so that a cheap model never imports the FE machinery.
"""

from __future__ import annotations

import inspect
from importlib import import_module

from fem.interface import ForceModel

MODELS: dict[str, str] = {
    "eq2": "fem.closed_form:ChouHannaford",
    "thickwall": "fem.thickwall:ThickWall",
    "axisym": "fem.axisym:AxisymmetricFE",
    "auto": "fem.auto:AutoModel",
}


def model_names() -> list[str]:
    return list(MODELS)


def make_model(name: str, **params) -> ForceModel:
    """Instantiate model ``name`` with ``params`` (None values mean "use the default")."""
    if name not in MODELS:
        raise ValueError(f"unknown model {name!r}: expected one of {', '.join(MODELS)}")
    module, cls = MODELS[name].split(":")
    factory = getattr(import_module(module), cls)
    given = {k: v for k, v in params.items() if v is not None}
    accepted = inspect.signature(factory).parameters
    unknown = sorted(set(given) - set(accepted))
    if unknown:
        raise ValueError(f"model {name!r} takes no parameter {', '.join(unknown)}: "
                         f"expected some of {', '.join(accepted) or 'none'}")
    return factory(**given)
