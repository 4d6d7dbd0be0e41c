"""Surrogates of the FE force model: scikit-learn estimators trained on FE datasets.

``mkm.surrogate.default_model(L0_mm=..., theta0_deg=..., C10_MPa=..., C01_MPa=...)`` is the default
(``best``) surrogate as a fitted ``mkm.fem.interface.ForceModel``, trained on the shipped
space-filling FE design (``data/mkm_design.csv``, :mod:`mkm.surrogate.design`) on first use and
cached in the user's cache folder; ``mkm.surrogate.io.load_model(path)`` loads one saved by ``mkm
surrogate train`` (JSON and arrays: loading runs no code from the file).
"""


def default_model(*args, **kwargs):
    """See :func:`mkm.surrogate.train.default_model` (imported lazily: scikit-learn is slow to
    load)."""
    from mkm.surrogate.train import default_model as _default_model

    return _default_model(*args, **kwargs)
