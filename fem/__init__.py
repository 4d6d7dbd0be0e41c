"""Physics of the McKibben muscle: the force-model contract and the ladder of models.

``ForceModel.predict(pressure_bar, D0_mm, t0_mm, eps)`` is the one interface
(``mkm.fem.interface``);
the ladder climbs from Equation 2 (``Eq2``, ``mkm.fem.eq2``) through the thick-wall closed form
(``ThickWall``, ``mkm.fem.thickwall``) to the axisymmetric finite-element model (``Axisym``,
``mkm.fem.fe``). ``mkm.fem.calibration`` fits the braid angle, ``mkm.fem.dataset`` builds the FE
dataset,
``mkm.fem.paper`` holds the reference work's numbers, ``mkm.core.records`` the provenance plumbing.

Models are imported on first use, so ``import fem`` stays cheap (the FE model loads scikit-fem).
"""

from importlib import import_module

_LAZY = {
    "Domain": "mkm.fem.interface", "ForceModel": "mkm.fem.interface",
    "Prediction": "mkm.fem.interface", "validate_inputs": "mkm.fem.interface",
    "MODELS": "mkm.fem.ladder", "make_model": "mkm.fem.ladder",
    "Eq2": "mkm.fem.eq2", "chou_hannaford": "mkm.fem.eq2", "chou_hannaford_eps_max": "mkm.fem.eq2",
    "LOCKING_ANGLE_DEG": "mkm.fem.eq2",
    "ThickWall": "mkm.fem.thickwall", "klute_hannaford": "mkm.fem.thickwall",
    "klute_hannaford_threshold_pressure": "mkm.fem.thickwall",
    "Axisym": "mkm.fem.fe.model", "isometric_sweep": "mkm.fem.fe.model",
    "MooneyRivlin": "mkm.fem.materials", "SILASTIC_S": "mkm.fem.materials",
    "equation7_err_pct": "mkm.fem.paper", "TEST_MUSCLES": "mkm.fem.paper",
}

__all__ = list(_LAZY)


def __getattr__(name):
    if name in _LAZY:
        return getattr(import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'mkm.fem' has no attribute {name!r}")


def __dir__():
    return sorted(__all__)
