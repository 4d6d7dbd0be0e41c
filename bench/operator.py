"""The person at the bench: sets a hand regulator, reads the manometer, hangs masses.

With the paper's manual precision regulator the program cannot set the pressure: at each step it
asks the operator to set it and to type the manometer reading. :class:`ConsoleOperator` asks on
the terminal; :class:`SimOperator` does the same actions on the simulated bench.
"""

from __future__ import annotations

from typing import Protocol

from mkm.core.ranges import parse_number


class Operator(Protocol):
    def set_pressure(self, pressure_bar: float) -> float:
        """Set the hand regulator to ``pressure_bar``; return the manometer reading [bar]."""

    def vent(self) -> float:
        """Vent the muscle (turn the hand regulator to zero); return the manometer reading
        [bar] that confirms it."""

    def hang_mass(self, mass_kg: float) -> None:
        """Hang a known mass on the load cell (``mass_kg`` 0 means unload it)."""


class ConsoleOperator:
    """Asks on the terminal; ``ask`` is ``input`` (replaceable for tests)."""

    def __init__(self, ask=input):
        self.ask = ask

    def _reading(self, prompt: str) -> float:
        while True:
            text = self.ask(prompt)
            try:
                reading = parse_number(text, "manometer reading")
            except ValueError as exc:
                print(exc)
                continue
            if reading < 0:
                print(f"manometer reading {reading:g} bar is negative: type a gauge pressure")
                continue
            return reading

    def set_pressure(self, pressure_bar: float) -> float:
        return self._reading(f"Set the regulator to {pressure_bar:g} bar, wait for the "
                             "manometer to settle and type its reading [bar]: ")

    def vent(self) -> float:
        return self._reading("VENT the muscle now (regulator to zero), wait for the manometer "
                             "and type its reading [bar]: ")

    def hang_mass(self, mass_kg: float) -> None:
        what = "Unload the load cell" if mass_kg == 0 else f"Hang {mass_kg:g} kg on the load cell"
        self.ask(f"{what}, let it settle, then press Enter: ")


class SimOperator:
    """The operator's actions on a :class:`mkm.bench.sim.SimBackend`."""

    def __init__(self, backend):
        self.backend = backend

    def set_pressure(self, pressure_bar: float) -> float:
        return self.backend.set_manual_pressure(pressure_bar)

    def vent(self) -> float:
        return self.backend.set_manual_pressure(0.0)

    def hang_mass(self, mass_kg: float) -> None:
        self.backend.hang_mass(mass_kg)
