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
   there), ``fe_not_converged`` (a solve that failed where the muscle has a state).

:func:`design` is the Python API (a DataFrame of the verified designs); :func:`run_design` also
writes ``designs.csv``, ``designs.json`` (provenance), ``design.html`` and its figures
(:mod:`mkm.design.page`).
"""

from mkm.design.page import write_design
from mkm.design.result import DesignResult, design, design_record, run_design
from mkm.design.search import Search, pick, search
from mkm.design.spec import (
    OBJECTIVES,
    Constraints,
    Requirement,
    load_spec,
    parse_bounds,
    parse_requirement,
)
from mkm.design.verify import verify

__all__ = ["OBJECTIVES", "Constraints", "DesignResult", "Requirement", "Search", "design",
           "design_record", "load_spec", "parse_bounds",
           "parse_requirement", "pick", "run_design", "search", "verify", "write_design"]
