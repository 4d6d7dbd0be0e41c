"""Physics of the McKibben muscle: the force-model contract and the ladder of models.

``ForceModel.predict(pressure_bar, D0_mm, t0_mm, eps)`` is the one interface (``fem.interface``);
the ladder climbs from Equation 2 (``Eq2``, ``fem.eq2``) through the thick-wall closed form
(``ThickWall``, ``fem.thickwall``) to the axisymmetric finite-element model (``Axisym``,
``fem.fe``). ``fem.calibration`` fits the braid angle, ``fem.dataset`` builds the FE dataset,
``fem.paper`` holds the reference work's numbers, ``fem.records`` the provenance plumbing.

Models are imported on first use, so ``import fem`` stays cheap (the FE model loads scikit-fem).
"""

from importlib import import_module

from fem.interface import Domain, ForceModel, Prediction, validate_inputs
from fem.ladder import LADDER, make_model, model_names

_LAZY = {
    "Eq2": "fem.eq2", "chou_hannaford": "fem.eq2", "chou_hannaford_eps_max": "fem.eq2",
    "LOCKING_ANGLE_DEG": "fem.eq2",
    "ThickWall": "fem.thickwall", "klute_hannaford": "fem.thickwall",
    "klute_hannaford_threshold_pressure": "fem.thickwall",
    "Axisym": "fem.fe.model", "isometric_sweep": "fem.fe.model",
    "MooneyRivlin": "fem.materials", "SILASTIC_S": "fem.materials",
    "equation7_err_pct": "fem.paper", "TEST_MUSCLES": "fem.paper",
}

__all__ = ["LADDER", "Domain", "ForceModel", "Prediction", "make_model", "model_names",
           "validate_inputs", *_LAZY]


def __getattr__(name):
    if name in _LAZY:
        return getattr(import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'fem' has no attribute {name!r}")


def __dir__():
    return sorted(__all__)
