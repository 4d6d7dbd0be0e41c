"""The paper's nets (its Table 2): ``mlp-paper``, its best (3 x 100 ReLU), and the family
``net-<layers>x<size>-<activation>[-standardised]`` of all 27, trained as MATLAB's ``fitrnet``.

The names are plain Python (:func:`net_kinds`); scikit-learn is imported when a net is built.
"""

from __future__ import annotations

ACTIVATIONS = {"relu": "relu", "tanh": "tanh", "sigmoid": "logistic"}  # paper name -> sklearn

# Table 2 of the paper, in its order (# 1..27): activation, then size, then layers.
PAPER_NETS = [(layers, size, act) for act in ACTIVATIONS for size in (25, 50, 100)
              for layers in (1, 2, 3)]


def paper_net(layers: int, size: int, activation: str, standardise_response: bool = False,
              random_state: int = 0):
    """One of the paper's Table 2 nets, trained as MATLAB's ``fitrnet`` in Regression Learner.

    fitrnet: L-BFGS on the mean squared error, ``Lambda = 0`` (no L2), ``IterationLimit = 1000``,
    ``Standardize = true`` (inputs only; the response stays in N), Glorot-initialised weights.
    Here: ``MLPRegressor(solver="lbfgs", alpha=0, max_iter=1000)`` after a ``StandardScaler``.
    Differences: scikit-learn minimises half the MSE (same minimiser), initialises biases
    randomly (fitrnet: zeros) and the logistic layers' weights in a narrower Glorot range,
    stops at a projected gradient of ``tol`` (set to fitrnet's ``GradientTolerance`` 1e-6) or
    at SciPy's relative loss change 2.2e-9 (fitrnet: ``LossTolerance`` 1e-6, ``StepTolerance``
    1e-6); both stop at 1000 iterations, fitrnet silently, scikit-learn with a warning.
    ``standardise_response=True`` also standardises the force (the fix of the tanh and
    sigmoid rows).
    """
    from sklearn.compose import TransformedTargetRegressor
    from sklearn.neural_network import MLPRegressor
    from sklearn.pipeline import Pipeline
    from sklearn.preprocessing import StandardScaler

    if activation not in ACTIVATIONS:
        raise ValueError(f"activation={activation!r} is invalid: expected one of "
                         f"{', '.join(ACTIVATIONS)}")
    net = Pipeline([
        ("scale", StandardScaler()),
        ("net", MLPRegressor(hidden_layer_sizes=(size,) * layers,
                             activation=ACTIVATIONS[activation], solver="lbfgs", alpha=0.0,
                             max_iter=1000, tol=1e-11 if standardise_response else 1e-6,
                             random_state=random_state)),
    ])
    if standardise_response:
        return TransformedTargetRegressor(regressor=net, transformer=StandardScaler())
    return net


def mlp_paper(random_state: int = 0):
    """The paper's best net, Table 2's # 9: 3 layers of 100 ReLU."""
    return paper_net(3, 100, "relu", random_state=random_state)


def net_kind(layers: int, size: int, activation: str, standardise_response=False) -> str:
    return f"net-{layers}x{size}-{activation}" + ("-standardised" if standardise_response else "")


def net_kinds() -> dict[str, dict]:
    """Every net of Table 2 by kind name (as printed, then standardised), with the
    :func:`paper_net` arguments that build it."""
    return {net_kind(*cfg, std): {"layers": cfg[0], "size": cfg[1], "activation": cfg[2],
                                  "standardise_response": std}
            for std in (False, True) for cfg in PAPER_NETS}
