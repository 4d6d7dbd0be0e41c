"""Material parameter sets and the incompressible Mooney-Rivlin strain energy.

Named parameter sets in the style of pvlib's ``TEMPERATURE_MODEL_PARAMETERS``: each carries its
source. Stresses in MPa (N/mm^2).
"""

from __future__ import annotations

from dataclasses import dataclass

from mkm.fem.limits import check_value


@dataclass(frozen=True)
class MooneyRivlin:
    """Two-parameter Mooney-Rivlin rubber, ``W = C10 (I1 - 3) + C01 (I2 - 3)`` [MPa]."""

    C10_MPa: float
    C01_MPa: float
    source: str = ""

    def energy(self, l1, l2, l3=None):
        """Strain energy density [MPa = mJ/mm^3] from principal stretches (``l3 = 1/(l1 l2)``)."""
        import numpy as np  # here: the command line reads MATERIALS without numpy

        l1 = np.asarray(l1, dtype=float)
        l2 = np.asarray(l2, dtype=float)
        l3 = 1.0 / (l1 * l2) if l3 is None else np.asarray(l3, dtype=float)
        I1 = l1**2 + l2**2 + l3**2
        I2 = (l1 * l2) ** 2 + (l2 * l3) ** 2 + (l3 * l1) ** 2
        return self.C10_MPa * (I1 - 3.0) + self.C01_MPa * (I2 - 3.0)


MATERIALS: dict[str, MooneyRivlin] = {
    "silastic_s": MooneyRivlin(
        0.0694, 0.0628,
        source="Antonelli et al., Actuators 2025, 14(3), 153, doi:10.3390/act14030153, Eq. 3",
    ),
}
SILASTIC_S = MATERIALS["silastic_s"]


def mooney_rivlin(C10_MPa: float | None = None, C01_MPa: float | None = None) -> MooneyRivlin:
    """The Mooney-Rivlin rubber with these constants [MPa]; a None is Silastic S's value.

    Every rubber a user names (a spec's ``C10_MPa=...``, a calibration, a design constraint)
    is made here, so the constants are checked against the limits: a negative or absurd one
    gave a force at 0 bar, or a negative one, marked valid."""
    if C10_MPa is None and C01_MPa is None:
        return SILASTIC_S
    return MooneyRivlin(SILASTIC_S.C10_MPa if C10_MPa is None else check_value("C10_MPa", C10_MPa),
                        SILASTIC_S.C01_MPa if C01_MPa is None else check_value("C01_MPa", C01_MPa))
