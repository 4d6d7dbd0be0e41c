"""Surrogates of the FE force model: scikit-learn estimators trained on the FE dataset.

``surrogate.default_model()`` is the default (``best``) surrogate as a fitted
``fem.interface.ForceModel``, trained on ``data/mkm_dataset.csv`` on first use and cached;
``surrogate.io.load_model(path)`` loads one saved by ``mkm surrogate train``.
"""


def default_model(*args, **kwargs):
    """See :func:`surrogate.train.default_model` (imported lazily: scikit-learn is slow to load)."""
    from surrogate.train import default_model as _default_model

    return _default_model(*args, **kwargs)
