"""What became of each point of a prediction: one classification for every consumer.

:func:`classify` names, per point of a pressure sweep, the first failure that applies, or
``"ok"``. The study's stability maps, the stability map over the practical range
(``benchmarks/bench_stability_map.py``) and the warning of ``mkm fem solve`` all read it, so a
point counts the same everywhere.

A solve that stops at a physical limit of the muscle is not a numerical failure: where no state
of the muscle exists (the braid reaches its locking angle before the held shortening), the model
sets the per-point extra ``limit`` to the limit's name (:data:`BRAID_LOCKS`), its force is NaN
and ``converged`` is False (no state was found), and the point is classified by that name, not
as ``not converged``. ``not converged`` is left for what the solver failed at (Newton, element
inversion) where the muscle has a state.
"""

from __future__ import annotations

import numpy as np

#: A force falling with pressure by less than this, or negative by less, is noise [N]: a tenth
#: of a newton, below what the bench resolves, so not physics.
FORCE_NOISE_N = 0.1

#: The braid reaches its locking angle (arccos 1/sqrt(3), 54.74 deg: the largest volume, no
#: pressure shortens it further) before the held shortening: a physical limit of the muscle.
BRAID_LOCKS = "braid locks"

#: Every outcome :func:`classify` gives, from the good to the worst of each kind.
OUTCOMES = ("ok", "invalid (model's own limit)", BRAID_LOCKS, "not converged",
            "out of training domain", "negative force", "force falls with pressure")

#: The physical limits a model may name in its ``limit`` extra.
PHYSICAL_LIMITS = (BRAID_LOCKS,)


def classify(pred) -> np.ndarray:
    """Per point of one pressure sweep (a :class:`~mkm.fem.interface.Prediction`): the first
    failure that applies, or ``"ok"`` (one of :data:`OUTCOMES`).

    In order of precedence: a physical limit the model names (extra ``limit``), not converged,
    out of a surrogate's training domain (extra ``in_domain``), invalid by the model's own limit
    (``valid`` False), a negative force, a force that falls with pressure (both beyond
    :data:`FORCE_NOISE_N`).
    """
    force = np.ravel(pred.force_N)
    order = np.argsort(np.ravel(pred.pressure_bar), kind="stable")
    falls = np.zeros(force.size, dtype=bool)
    falls[order[1:]] = np.diff(force[order]) < -FORCE_NOISE_N
    status = np.full(force.size, "ok", dtype=object)
    status[falls] = "force falls with pressure"
    status[force < -FORCE_NOISE_N] = "negative force"
    in_domain = np.ravel(pred.extras.get("in_domain", np.ones(force.size, dtype=bool)))
    status[~np.ravel(pred.valid)] = "invalid (model's own limit)"
    status[~in_domain] = "out of training domain"
    status[~np.ravel(pred.converged)] = "not converged"
    # a table read back may hold a missing name as NaN: only a non-empty text names a limit
    limit = np.ravel(np.broadcast_to(np.asarray(pred.extras.get("limit", ""), dtype=object),
                                     force.shape))
    named = np.array([isinstance(v, str) and v != "" for v in limit], dtype=bool)
    unknown = set(limit[named]) - set(PHYSICAL_LIMITS)
    if unknown:
        raise ValueError(f"limit={sorted(unknown)[0]!r} is not a physical limit: expected one "
                         f"of {', '.join(PHYSICAL_LIMITS)}")
    status[named] = limit[named]
    return status
