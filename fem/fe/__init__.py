"""The axisymmetric finite-element model of the McKibben muscle (scikit-fem).

``model`` (the force model ``Axisym`` and the isometric sweep), ``assembly`` (the generic
vectorised total-Lagrangian assembler), ``forms`` (the energy terms as plain functions),
``newton`` (the load-path solver), ``mesh`` (the graded half-muscle mesh), ``convergence`` (the
mesh study).
"""

from mkm.fem.fe.model import Axisym, isometric_sweep

__all__ = ["Axisym", "isometric_sweep"]
