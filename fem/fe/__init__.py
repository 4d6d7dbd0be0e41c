"""The axisymmetric finite-element model of the McKibben muscle (scikit-fem).

``model`` (the force model ``Axisym`` and the isometric sweep), ``assembly`` (the generic
vectorised total-Lagrangian assembler), ``forms`` (the energy terms as plain functions),
``newton`` (the load-path solver), ``mesh`` (the graded half-muscle mesh), ``options`` (the mesh
levels and braids, read without scikit-fem), ``convergence`` (the mesh study).

The model is imported on first use, so reading :mod:`mkm.fem.fe.options` loads no scikit-fem.
"""

from importlib import import_module

__all__ = ["Axisym", "isometric_sweep"]


def __getattr__(name):
    if name in __all__:
        return getattr(import_module("mkm.fem.fe.model"), name)
    raise AttributeError(f"module 'mkm.fem.fe' has no attribute {name!r}")


def __dir__():
    return sorted(__all__)
