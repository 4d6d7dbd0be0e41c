"""Warnings every surrogate fit would repeat, silenced where fits run."""

from __future__ import annotations

import warnings
from contextlib import contextmanager


@contextmanager
def quiet_fits():
    """Silence the warnings every fit here would repeat, expected and not worth a line each."""
    from sklearn.exceptions import ConvergenceWarning

    with warnings.catch_warnings():
        # A Gaussian process length scale at its bound means an input it finds irrelevant, a
        # noise level at its bound noise-free FE data.
        warnings.filterwarnings("ignore", message="The optimal value found for dimension",
                                category=ConvergenceWarning)
        # fitrnet, which the nets copy, also stops at its IterationLimit without a warning
        warnings.filterwarnings("ignore", message="lbfgs failed to converge",
                                category=ConvergenceWarning)
        yield
