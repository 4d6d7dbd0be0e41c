"""Gaussian-process helpers of the surrogates, on scikit-learn's public API only.

:func:`fit_gaussian_process` standardises the target itself and keeps its mean and scale in the
posterior it returns (:func:`posterior`), so nothing reads the regressor's private state;
:func:`posterior_mean_std` predicts from that posterior without scikit-learn's per-call checks;
:func:`leave_one_out` gives the closed-form leave-one-out posterior at the training points.
"""

from __future__ import annotations

import numpy as np

# A target scale below this is a constant target: scikit-learn's normalize_y divides by 1 then
TINY_SCALE = 10.0 * np.finfo(float).eps


def gaussian_process(n_features: int, random_state: int, restarts: int,
                     normalize_y: bool = True):
    """Matern 5/2 with one length scale per input, times an amplitude, plus a noise term (a
    ``GaussianProcessRegressor``; scikit-learn is imported here: predictions need only
    :func:`posterior_mean_std`)."""
    from sklearn.gaussian_process import GaussianProcessRegressor
    from sklearn.gaussian_process.kernels import ConstantKernel, Matern, WhiteKernel

    kernel = (ConstantKernel(1.0, (1e-3, 1e3))
              * Matern(length_scale=np.ones(n_features), length_scale_bounds=(1e-2, 1e3),
                       nu=2.5)
              + WhiteKernel(1e-4, (1e-10, 1e-1)))
    return GaussianProcessRegressor(kernel=kernel, normalize_y=normalize_y,
                                    n_restarts_optimizer=restarts, random_state=random_state)


def fit_gaussian_process(Z, y, random_state: int, restarts: int):
    """``(gp, posterior)``: :func:`gaussian_process` fitted to ``y`` standardised here (as
    ``normalize_y`` would), and its :func:`posterior` in the units of ``y``."""
    y = np.asarray(y, dtype=float)
    y_mean, y_std = float(np.mean(y)), float(np.std(y))
    y_std = y_std if y_std >= TINY_SCALE else 1.0
    gp = gaussian_process(Z.shape[1], random_state, restarts, normalize_y=False)
    gp.fit(Z, (y - y_mean) / y_std)
    return gp, posterior(gp, y_mean, y_std)


def posterior(gp, y_mean: float, y_std: float) -> dict[str, np.ndarray]:
    """What :func:`posterior_mean_std` needs of a fitted Matern + white-noise process on a target
    standardised with ``y_mean`` and ``y_std``: the training inputs in length-scale units,
    ``alpha``, the inverse Cholesky factor, the kernel's amplitude and noise, and the scaling."""
    product, white = gp.kernel_.k1, gp.kernel_.k2
    scale = np.asarray(product.k2.length_scale, dtype=float)
    return {"X_scaled": gp.X_train_ / scale, "length_scale": scale,
            "alpha": np.ravel(gp.alpha_), "L_inv": np.linalg.inv(gp.L_),
            "amplitude": np.array(product.k1.constant_value),
            "noise": np.array(white.noise_level),
            "y_mean": np.array(y_mean), "y_std": np.array(y_std)}


def posterior_mean_std(post, Z):
    """Mean and std of the process ``post`` (:func:`posterior`) at ``Z``, in the target's units:
    ``gp.predict(Z, return_std=True)`` without scikit-learn's per-call checks and kernel objects,
    which cost more than the arithmetic for a few points. The posterior of Rasmussen and
    Williams (2006), Algorithm 2.1, with the Matern 5/2 kernel ``a (1 + sqrt5 r + 5 r^2 / 3)
    exp(-sqrt5 r)``."""
    # Euclidean distances by broadcasting: scipy.spatial's import costs more than a sweep
    d = (np.asarray(Z, dtype=float) / post["length_scale"])[:, None, :] - post["X_scaled"][None]
    r = np.sqrt(5.0) * np.sqrt(np.einsum("ijk,ijk->ij", d, d))
    K = post["amplitude"] * (1.0 + r + r**2 / 3.0) * np.exp(-r)
    V = post["L_inv"] @ K.T
    var = np.clip(post["amplitude"] + post["noise"] - np.einsum("ij,ij->j", V, V), 0.0, None)
    return (post["y_std"] * (K @ post["alpha"]) + post["y_mean"],
            np.sqrt(var) * post["y_std"])


def predict_mean_std(gp, post, Z):
    """``gp.predict(Z, return_std=True)`` in the target's units (``post`` its scaling)."""
    mean, std = gp.predict(Z, return_std=True)
    return post["y_std"] * mean + post["y_mean"], std * post["y_std"]


def leave_one_out(gp, post):
    """Mean and std at each training point of the process fitted without it, at the fitted
    hyperparameters, in the target's units (Rasmussen and Williams 2006, eq. 5.12)."""
    from scipy.linalg import cho_solve

    Kinv_diag = np.diag(cho_solve((gp.L_, True), np.eye(len(gp.L_))))
    y_norm = gp.y_train_ if gp.y_train_.ndim == 1 else gp.y_train_[:, 0]
    mean = (y_norm - gp.alpha_ / Kinv_diag) * post["y_std"] + post["y_mean"]
    return mean, np.sqrt(1.0 / Kinv_diag) * post["y_std"]
