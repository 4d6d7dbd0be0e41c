"""The one list of bench backends: each entry carries its factory, its device's capabilities, a
label and whether it is simulated.

``mkm.bench.run.make_backend``, the ``--backend`` choices of the ``mkm`` bench commands, the
configuration's ``[daq] backend`` check and the backend contract test all read
:data:`BACKENDS` (a :class:`mkm.core.registry.Registry`); a backend added with :func:`register`
is offered, validated and tested by all of them at once (scikit-learn's ``all_estimators``
idea).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from mkm.bench.backend import Backend, DeviceCapabilities
from mkm.bench.devices import USB6001
from mkm.core.registry import Registry


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


BACKENDS: Registry[BackendEntry] = Registry("backend", shown=lambda e: f"{e.name!r} ({e.label})")


def register(entry: BackendEntry) -> BackendEntry:
    """Add ``entry`` (its name must be new)."""
    return BACKENDS.register(entry)


def unregister(name: str) -> None:
    """Remove the backend ``name`` (an unknown name is refused)."""
    BACKENDS.unregister(name)


def names() -> tuple[str, ...]:
    return BACKENDS.names()


def entry(name: str) -> BackendEntry:
    """The entry of ``name``, or a one-line ``ValueError`` naming the choices."""
    return BACKENDS.entry(name)


# the backends' modules are imported when a run opens one, not when the list is read
def _sim(config, clock="virtual") -> Backend:
    from mkm.bench.sim import SimBackend

    return SimBackend(config, clock=clock)


def _ni(config, clock="virtual") -> Backend:
    from mkm.bench.ni import NIBackend

    return NIBackend(config)


register(BackendEntry("sim", _sim, USB6001, "simulated NI USB-6001 bench", simulated=True))
register(BackendEntry("ni", _ni, USB6001, "NI USB-6001 through nidaqmx", simulated=False))
