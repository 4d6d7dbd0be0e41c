"""How far each FE mesh is from the finest, at the scale of a call: the bound ``auto`` gives a
mesh at a single point as well as over a sweep.

A coarser mesh's force differs from the fine mesh's in two ways: its threshold ``P*`` is
shifted (by a small part of it) and the bend just above it differs, and its slope differs by a
small fraction (most for the coarse mesh on a slender tube near the lock). So at a point of force
``F`` (the mesh's) and slope ``A = F / (P - P*)``::

    |F - F_fine| <= a P* A + b F

with ``b`` the largest relative error from ``2 P*`` up (the slope's) and ``a`` the largest
error ``b`` leaves, in bar over ``P*`` (the threshold's shift, the bend), both
measured on fresh random muscles of the practical range, a share of them near the braid lock
(:func:`measure`, seeds recorded; ``mkm study --mesh-muscles N``). Near the lock the threshold
climbs steeply with the shortening, so there a mesh shifts it most (thin long walls most of
all), and a draw of the whole range puts about one muscle in ten there, half of which pull
nothing up to 8 bar: :data:`NEAR_LOCK_SHARE` of the muscles are drawn there.

Relative to the largest force of the call (Equation 7's scale) the bound is small over a sweep
and large just above ``P*``, where a shift of the threshold is a large part of a small force:
a single-point call answered from the coarse mesh is off by many times a bound taken at a
sweep's scale.

The table (``mkm/data/mesh_errors.csv`` + JSON sidecar) holds one row per muscle and mesh;
:func:`mesh_model` reads ``a`` and ``b`` per mesh (the largest over the muscles, times
:data:`SAFETY`) and :func:`point_bound_pct` applies them to a prediction.
"""

from __future__ import annotations

import dataclasses
from functools import cache
from pathlib import Path

import numpy as np

from mkm.core.records import package_file, provenance, read_csv_checked, write_csv_with_sidecar
from mkm.fem.limits import PRACTICAL_RANGE

MESH_ERRORS_FILE = package_file("mkm", "data", "mesh_errors.csv")
#: The meshes measured against the fine one.
MESHES = ("coarse", "medium")
#: The pressures of each sweep [bar]: the practical range every 0.5 bar.
PRESSURES_BAR = tuple(float(p) for p in np.round(np.arange(0.0, 8.001, 0.5), 2))
#: The largest shift and error over the measured muscles; another muscle may do a little worse.
SAFETY = 1.5
MIN_SCALE_N = 1.0  # a call that never pulls (all below threshold) is scored in newtons
#: The practical range near the braid lock: eps from 85 % of the lock up (to the draw's top,
#: :data:`mkm.fem.sampling.LOCK_FRACTION`), about the top tenth of the eps a draw of the range
#: spans.
NEAR_LOCK_RANGE = dataclasses.replace(PRACTICAL_RANGE, eps_per_lock=(0.85, 1.0))
#: The share of :func:`measure`'s muscles drawn from :data:`NEAR_LOCK_RANGE`.
NEAR_LOCK_SHARE = 0.5
#: The coarsest end zone a mesh's bound is measured and claimed for: its element at the clamped
#: cap at most this many bending lengths of the wall (:func:`end_resolution`). Beyond it a thin,
#: slender tube's bending at the cap falls between the nodes, and the coarse mesh was off by
#: several times its error on the muscles it resolves.
MAX_END_RESOLUTION = 4.0
#: A mesh's elements are about ``L0 / (2 n_z)`` long and ``t0 / n_r`` thick (graded towards the
#: caps): the longer and thinner the wall, the flatter they are and the further the mesh is from
#: the fine one. So a muscle's ``a`` and ``b`` are the largest over the measured muscles at most
#: this many times as slender (``L0/t0``) as it is (:meth:`MeshBound.coefficients`); a margin,
#: as slenderness is not all that sets the error.
SLENDERNESS_REACH = 1.5
#: The fewest measured muscles a bound is the largest over: below it the region extends to the
#: next more slender ones.
MIN_REGION_MUSCLES = 30


def end_resolution(D0_mm, t0_mm, L0_mm, mesh: str):
    """How coarsely ``mesh`` resolves the clamped end: the axial size of its element at the cap
    (the graded mesh's smallest, :func:`mkm.fem.fe.mesh.graded_spacing`) over the wall's bending
    length ``sqrt(R t0)`` (``R`` the mid-wall radius), the length over which a clamped thin wall
    bends. Arrays broadcast."""
    from mkm.fem.fe.mesh import graded_spacing
    from mkm.fem.options import MESH_LEVELS

    _, n_z, ratio = MESH_LEVELS[mesh]
    spacing = graded_spacing(1.0, n_z, ratio)
    clamp_mm = (spacing[-1] - spacing[-2]) * np.asarray(L0_mm, dtype=float) / 2.0
    D0, t0 = np.asarray(D0_mm, dtype=float), np.asarray(t0_mm, dtype=float)
    return clamp_mm / np.sqrt((D0 + t0) / 2.0 * t0)


def _muscle_rows(mesh: str, sweep, fine) -> dict:
    """Of one muscle's sweep at ``mesh`` against the ``fine`` one (rows of
    :func:`mkm.fem.batch.run_jobs`): ``b``, the largest relative error from twice the
    threshold up (the slope's), and ``a``, the error ``b`` leaves, in bar over ``P*`` at the
    mesh's slope (the threshold's shift, the bend just above it)."""
    P = sweep["pressure_bar"].to_numpy()
    F, F_fine = sweep["force_N"].to_numpy(), fine["force_N"].to_numpy()
    P_star = float(sweep["threshold_pressure_bar"].iloc[0])
    above = F > 0
    row = {"mesh": mesh, "threshold_bar": P_star,
           "threshold_shift_bar": abs(P_star - float(fine["threshold_pressure_bar"].iloc[0])),
           "largest_err_pct": float(100 * np.max(np.abs(F - F_fine))
                                    / max(np.max(F_fine), MIN_SCALE_N))}
    if not above.any():
        return {**row, "relative_error": 0.0, "shift_per_threshold": 0.0}
    # the slope's error where the threshold's is a small part of the force: P >= 2 P*
    far = above & (P >= 2.0 * P_star)
    relative = float(np.max(np.abs(F[far] - F_fine[far]) / F[far], initial=0.0))
    slope = np.max(F[above] / (P[above] - P_star))  # threshold-linear: one slope
    left = np.maximum(np.abs(F - F_fine) - relative * F, 0.0)
    shift = float(np.max(left) / slope / P_star) if P_star > 0 else 0.0
    return {**row, "relative_error": relative, "shift_per_threshold": shift}


def near_lock_seed(seed: int) -> int:
    """The seed of :func:`measure`'s near-lock draw, spawned from ``seed``: the two draws share
    no uniforms, nor does the near-lock draw with a practical draw of a nearby seed."""
    return int(np.random.SeedSequence(int(seed)).spawn(1)[0].generate_state(1)[0])


def measure(n_muscles: int, seed: int, out=MESH_ERRORS_FILE, workers: int | None = None,
            scheduler: str | None = None, cache_dir=None, progress: bool = True,
            near_lock_share: float = NEAR_LOCK_SHARE):
    """Solve ``n_muscles`` fresh random muscles at every mesh of :data:`MESHES` and the fine
    one (:data:`PRESSURES_BAR`; the batch runner: local workers or the Dask cluster at
    ``scheduler``) and write one row per muscle and mesh to ``out`` with its sidecar (both
    draws, their seeds). ``near_lock_share`` of them (rounded) come from :data:`NEAR_LOCK_RANGE`
    (:func:`mkm.fem.sampling.draw_muscles`, seed :func:`near_lock_seed`), the others from the
    practical range (``seed``); column ``draw`` says which. A muscle whose fine sweep fails
    anywhere is recorded with ``fe_failed`` and not scored."""
    import pandas as pd

    from mkm.fem.batch import Job, Runner
    from mkm.fem.sampling import draw_muscles

    if not 0.0 <= near_lock_share <= 1.0:
        raise ValueError(f"near_lock_share={near_lock_share!r} is invalid: expected in [0, 1]")
    n_near = round(near_lock_share * int(n_muscles))
    drawn = draw_muscles(int(n_muscles) - n_near, seed)
    near = draw_muscles(n_near, near_lock_seed(seed), box=NEAR_LOCK_RANGE)
    muscles = (*drawn.muscles, *near.muscles)
    origin = ["practical"] * len(drawn.muscles) + ["near lock"] * len(near.muscles)
    frames = {}
    with Runner(workers, scheduler) as runner:
        for mesh in (*MESHES, "fine"):
            jobs = [Job(model="axisym", mesh=mesh, D0_mm=m.D0_mm, t0_mm=m.t0_mm, eps=m.eps,
                        L0_mm=m.L0_mm, theta0_deg=m.theta0_deg, pressure_bar=PRESSURES_BAR,
                        C10_MPa=m.C10_MPa, C01_MPa=m.C01_MPa) for m in muscles]
            frame, done = runner.run(jobs, cache_dir=cache_dir, progress=progress,
                                     desc=f"FE {mesh} mesh, {n_muscles} "
                                     f"muscle{'' if n_muscles == 1 else 's'}")
            frame.insert(0, "muscle", np.repeat(np.arange(len(jobs)), len(PRESSURES_BAR)))
            frames[mesh] = frame
    rows = []
    for k, muscle in enumerate(muscles):
        fine = frames["fine"][frames["fine"]["muscle"] == k]
        base = {"muscle": k, "draw": origin[k], **{name: getattr(muscle, name) for name in
                                ("D0_mm", "t0_mm", "eps", "L0_mm", "theta0_deg", "C10_MPa",
                                 "C01_MPa")}}
        for mesh in MESHES:
            sweep = frames[mesh][frames[mesh]["muscle"] == k]
            if not (fine["converged"].all() and sweep["converged"].all()):
                rows.append({**base, "mesh": mesh, "fe_failed": True})
                continue
            rows.append({**base, **_muscle_rows(mesh, sweep, fine), "fe_failed": False})
    table = pd.DataFrame(rows)
    info = {**provenance(), "what": "FE mesh errors against the fine mesh (mkm.mesh_errors)",
            "draw": drawn.record(), "near_lock_draw": near.record(),
            "near_lock_share": float(near_lock_share), "pressure_bar": list(PRESSURES_BAR),
            "meshes": list(MESHES), "model_version": done["model_version"],
            "fe_failed_muscles": int(table.groupby("muscle")["fe_failed"].any().sum())}
    write_csv_with_sidecar(out, table.to_csv(index=False, lineterminator="\n"), info)
    return table, info


@dataclasses.dataclass(frozen=True)
class MeshBound:
    """A mesh's ``a`` and ``b`` by region (:func:`coefficients`), from the muscles it was
    measured on: their slenderness ``L0/t0`` (ascending), threshold shift over ``P*`` and
    relative error (:func:`_muscle_rows`)."""

    slenderness: np.ndarray
    shift_per_threshold: np.ndarray
    relative_error: np.ndarray

    def region_limit(self, L0_mm, t0_mm) -> np.ndarray:
        """The slenderness up to which measured muscles bound a muscle of ``L0_mm``,
        ``t0_mm``: :data:`SLENDERNESS_REACH` times its own, and at least the
        :data:`MIN_REGION_MUSCLES` least slender. Arrays broadcast."""
        own = np.asarray(L0_mm, dtype=float) / np.asarray(t0_mm, dtype=float)
        floor = self.slenderness[min(MIN_REGION_MUSCLES, len(self.slenderness)) - 1]
        return np.maximum(SLENDERNESS_REACH * own, floor)

    def coefficients(self, L0_mm, t0_mm) -> tuple[np.ndarray, np.ndarray]:
        """``(a, b)`` for muscles of ``L0_mm`` and ``t0_mm`` (arrays broadcast): the largest
        over the measured muscles up to :meth:`region_limit`, times :data:`SAFETY`."""
        limit = self.region_limit(L0_mm, t0_mm)
        # the largest over the first k muscles, k those within the limit
        k = np.searchsorted(self.slenderness, limit, side="right") - 1
        a = np.maximum.accumulate(self.shift_per_threshold)[k]
        b = np.maximum.accumulate(self.relative_error)[k]
        return SAFETY * a, SAFETY * b

    @property
    def largest(self) -> tuple[float, float]:
        """``(a, b)`` over every measured muscle (the most slender region's)."""
        return (SAFETY * float(self.shift_per_threshold.max()),
                SAFETY * float(self.relative_error.max()))


@cache
def mesh_model(path: Path | str = MESH_ERRORS_FILE) -> dict[str, MeshBound]:
    """Per mesh its :class:`MeshBound`: the measured muscles (:func:`_muscle_rows`) whose end
    zone it resolves (:data:`MAX_END_RESOLUTION`); empty without a table."""
    path = Path(path)
    if not path.is_file():
        return {}
    table = read_csv_checked(path, "mesh error table", "expected the table `mkm study "
                             "--mesh-muscles N` writes (mesh_errors.csv)",
                             ("mesh", "fe_failed", "shift_per_threshold", "relative_error",
                              "D0_mm", "t0_mm", "L0_mm"))
    model = {}
    for mesh, rows in table[~table["fe_failed"].astype(bool)].groupby("mesh"):
        rows = rows[end_resolution(rows["D0_mm"], rows["t0_mm"], rows["L0_mm"], str(mesh))
                    <= MAX_END_RESOLUTION]
        if len(rows):
            rows = rows.assign(slenderness=rows["L0_mm"] / rows["t0_mm"]).sort_values(
                "slenderness", kind="stable")
            model[str(mesh)] = MeshBound(*(rows[name].to_numpy(dtype=float) for name in (
                "slenderness", "shift_per_threshold", "relative_error")))
    return model


def point_bound_pct(force_N, pressure_bar, threshold_bar, geometry, a, b) -> np.ndarray:
    """Per point, the bound [%] of a mesh's force against the fine mesh's, ``a P* A + b F``
    relative to the largest force of its muscle in the call less its own bound (Equation 7's
    scale: a single point is its own; never below 1 N).

    ``force_N``, ``pressure_bar``, ``threshold_bar`` (the mesh's ``P*``) per point; ``geometry``
    ``(n, k)``: the points of one muscle share a row. A point at zero force within ``a P*`` of
    the threshold (the fine force may have started) takes the slope of its muscle's points
    above the threshold; with none, it has no bound (inf). ``a`` and ``b`` per point or one
    for all (:meth:`MeshBound.coefficients`).
    """
    F, P, P_star = (np.ravel(np.asarray(v, dtype=float)) for v in
                    (force_N, pressure_bar, threshold_bar))
    a, b = (np.broadcast_to(np.ravel(np.asarray(v, dtype=float)), F.shape) for v in (a, b))
    bound = np.full(F.shape, np.inf)
    _, which = np.unique(np.asarray(geometry), axis=0, return_inverse=True)
    which = which.ravel()
    for g in np.unique(which):
        here = np.flatnonzero(which == g)
        f, p, star = F[here], P[here], P_star[here]
        above = f > 0
        slope = np.where(above, f / np.maximum(p - star, 1e-12), np.nan)
        muscle_slope = np.nanmax(slope) if above.any() else np.nan
        slope = np.where(above, slope, np.where(p > star * (1 - a[here]), muscle_slope, 0.0))
        error_N = _error_N(f, slope, star, a[here], b[here])
        scale = max(np.max(f - error_N, initial=0.0), MIN_SCALE_N)
        bound[here] = np.where(np.isfinite(error_N), 100.0 * error_N / scale, np.inf)
    return bound


def _error_N(force_N, slope_N_per_bar, threshold_bar, a, b):
    """``a P* A + b F`` [N]: how far a mesh's force ``F`` of slope ``A`` above its threshold
    ``P*`` may lie from the fine mesh's."""
    return a * threshold_bar * slope_N_per_bar + b * force_N


def point_error_N(mesh: str, force_N: float, pressure_bar: float, threshold_bar: float,
                  D0_mm: float, t0_mm: float, L0_mm: float) -> float:
    """How far the force of ``mesh`` may lie from the fine mesh's [N] at one point of force
    ``force_N`` above the threshold (``A = F / (P - P*)``); 0 for the fine mesh itself, inf
    where no bound is measured (no table for the mesh, or an end zone it does not resolve:
    :data:`MAX_END_RESOLUTION`)."""
    if mesh == "fine":
        return 0.0
    model = mesh_model()
    if (mesh not in model or not np.isfinite(force_N)
            or end_resolution(D0_mm, t0_mm, L0_mm, mesh) > MAX_END_RESOLUTION):
        return np.inf
    star = threshold_bar if np.isfinite(threshold_bar) else 0.0
    slope = force_N / max(pressure_bar - star, 1e-12) if force_N > 0 else 0.0
    a, b = model[mesh].coefficients(L0_mm, t0_mm)
    return float(_error_N(force_N, slope, star, a, b))


def summary_line(path: Path | str = MESH_ERRORS_FILE) -> str:
    """The model in words, for ``auto``'s explanation: each mesh's bound on its least slender
    muscles and on all."""
    def words(a, b):
        return f"{100 * float(a):.3f} % of P* x the slope + {100 * float(b):.3f} % of the force"

    parts = []
    for mesh, bound in mesh_model(path).items():
        stout = bound.region_limit(bound.slenderness[0], 1.0)
        parts.append(f"{mesh}: {words(*bound.coefficients(bound.slenderness[0], 1.0))} up to "
                     f"L0/t0 {float(stout):.0f}, {words(*bound.largest)} over every muscle")
    return "; ".join(parts)
