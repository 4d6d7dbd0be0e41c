"""Design a muscle for required forces: surrogate search of the design box, FE verification.

The reference work's purpose is choosing a muscle's geometry "according to the required force"
(Antonelli et al. 2025); this module answers that question with the project's models:

1. **Search.** The candidates of the design box (``D0_mm`` x ``t0_mm``, coarse to fine, times
   the values of ``L0_mm``, ``theta0_deg`` and the rubber that the constraints allow) are
   predicted by the surrogate in vectorised calls, one per requirement and grid. A candidate is
   *feasible* when its predicted force minus the surrogate's uncertainty
   (:func:`surrogate_uncertainty`) meets every requirement, no requirement lies past its braid
   lock, and it fits the housing (outer diameter at the working pressure,
   :func:`mkm.fem.thickwall.outer_diameter_mm`). Feasible candidates are ranked by the objective.
2. **Verification.** The best ``top`` candidates (kept apart by :data:`MIN_SEPARATION` of the
   box so that they are alternatives, not neighbours) are solved with the axisymmetric FE model
   at the converged mesh over a pressure sweep at each requirement's eps. A design meets the
   requirements only when the FE says so; every margin reported is the FE's.
3. **Flags.** ``near_lock`` (eps at or past :data:`NEAR_LOCK_FRACTION` of Equation 2's
   ``eps_max``, or the FE's braid locks before eps: a physical limit,
   :data:`mkm.fem.outcomes.BRAID_LOCKS`), ``threshold_above_pressure`` (the FE threshold
   pressure of that eps is at or above the requirement's pressure: the muscle does not pull
   there), ``fe_not_converged`` (a solve that failed where the muscle has a state),
   ``margin_within_mesh_error`` (met by less than the mesh's force may lie from the fine
   mesh's: :func:`mkm.mesh_errors.point_error_N`).

:func:`design` is the Python API (a DataFrame of the verified designs); :func:`run_design` also
writes ``designs.csv``, ``designs.json`` (provenance), ``design.html`` and its figures
(:mod:`mkm.design.page`).
"""

import importlib
from typing import Any

# each public name and the module it lives in, loaded when first used: reading the objectives
# for `mkm design --help` (mkm.design.spec) need not load the FE, matplotlib and scipy.stats
_EXPORTS = {
    "write_design": "page",
    **dict.fromkeys(("DesignResult", "design", "design_record", "run_design"), "result"),
    **dict.fromkeys(("Search", "pick", "search"), "box_search"),
    **dict.fromkeys(("OBJECTIVES", "Constraints", "Requirement", "load_spec", "parse_bounds",
                     "parse_requirement"), "spec"),
    "verify": "fe_verification",
}
__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> Any:
    if name not in _EXPORTS:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(f"{__name__}.{_EXPORTS[name]}"), name)


def __dir__() -> list[str]:
    return __all__
