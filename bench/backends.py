"""The one list of bench backends: each entry carries its factory, its device's capabilities, a
label and whether it is simulated.

``mkm.bench.run.make_backend``, the ``--backend`` choices of the ``mkm`` bench commands, the
configuration's ``[daq] backend`` check and the backend contract test all read
:data:`BACKENDS`; a backend added with :func:`register` is offered, validated and tested by all
of them at once (scikit-learn's ``all_estimators`` idea).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from mkm.bench.backend import Backend, DeviceCapabilities
from mkm.bench.devices import USB6001


@dataclass(frozen=True)
class BackendEntry:
    """One backend.

    Parameters
    ----------
    name : str
        What ``[daq] backend`` and ``--backend`` say (``sim``, ``ni``).
    factory : callable
        ``factory(config, clock)`` returns the (unopened) backend; ``clock`` is ``virtual`` or
        ``real`` and matters to simulated backends only.
    capabilities : DeviceCapabilities
        What its device can do; a configuration is validated against it.
    label : str
        One line for help texts.
    simulated : bool
        True when no hardware is driven: its runs are marked SIMULATED everywhere.
    """

    name: str
    factory: Callable[..., Backend]
    capabilities: DeviceCapabilities
    label: str
    simulated: bool


BACKENDS: dict[str, BackendEntry] = {}


def register(entry: BackendEntry) -> None:
    """Add ``entry`` (its name must be new)."""
    if entry.name in BACKENDS:
        raise ValueError(f"backend {entry.name!r} is already registered")
    BACKENDS[entry.name] = entry


def unregister(name: str) -> None:
    """Remove the backend ``name``."""
    BACKENDS.pop(name, None)


def backend_names() -> tuple[str, ...]:
    return tuple(BACKENDS)


def backend_entry(name: str) -> BackendEntry:
    """The entry of ``name``, or ``ValueError`` naming the choices."""
    try:
        return BACKENDS[name]
    except (KeyError, TypeError):
        choices = ", ".join(f"{e.name!r} ({e.label})" for e in BACKENDS.values())
        shown = name if not isinstance(name, str) or len(name) <= 40 else name[:40] + "..."
        raise ValueError(f"backend={shown!r} is invalid: expected one of {choices}") from None


# the backends' modules are imported when a run opens one, not when the list is read
def _sim(config, clock="virtual") -> Backend:
    from mkm.bench.sim import SimBackend

    return SimBackend(config, clock=clock)


def _ni(config, clock="virtual") -> Backend:
    from mkm.bench.ni import NIBackend

    return NIBackend(config)


register(BackendEntry("sim", _sim, USB6001, "simulated NI USB-6001 bench", simulated=True))
register(BackendEntry("ni", _ni, USB6001, "NI USB-6001 through nidaqmx", simulated=False))
