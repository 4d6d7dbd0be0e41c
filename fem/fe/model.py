"""Axisymmetric finite-element model of the McKibben muscle in scikit-fem (``--model axisym``).

The half muscle between the mid-plane (``Z = 0``, symmetry: ``u_z = 0``) and a rigid end cap
(``Z = L0/2``: ``u_r = 0``, ``u_z = U`` shared by the whole cap) in total-Lagrangian finite
strain:

* the silicone wall is a fully incompressible Mooney-Rivlin solid in a Taylor-Hood P2/P1 mixed
  displacement-pressure formulation: the pressure field enforces ``J = 1`` without a bulk
  modulus, so the wall does not lock (P1 displacement-only locked in a prototype, raising the
  threshold pressure) and it is the constitutive model of the paper's ANSYS runs (C10, C01, no
  D1);
* the braid is two inextensible fibre families at +-theta0 bonded to the outer surface,
  ``cos^2 theta0 l_s^2 + sin^2 theta0 l_t^2 = 1``, enforced with a Lagrange multiplier field
  (continuous P1 on the outer surface); the multiplier is the fibre membrane tension [N/mm].
  Fibres are threads: they cannot be stretched but carry no compression, so where the rubber
  under them would shorten along the fibres they go slack (buckle off the surface) instead of
  pushing. The braid is tension-only, ``g <= 0, lambda >= 0, lambda g = 0`` node by node
  (:meth:`HalfMuscle.slack_nodes`: a primal-dual active set inside Newton); it matters at the
  clamped cap's corner, where the free muscle near its threshold shortens the surface along
  the fibres. With a radial gap between tube and braid at rest (``gap_mm``) the same
  complementarity, with the braid's own rest radius in the fibre stretch, is the unilateral
  contact of tube and braid: the tube inflates freely until it reaches the braid, which acts
  only where they touch;
* the air pressure is the potential ``-P V`` of the closed cavity (inner surface and cap), a
  follower load with a symmetric tangent whose cap share lands in the cap reaction;
* the developed force is the reaction ``dPi/dU`` on the cap. For the half model this is already
  the muscle force: the force through any cross-section of the muscle is the same, and the
  whole muscle's energy ``2 Pi`` changes with its length ``2 U``.

The isometric lock of the paper (a muscle that shortens freely until ``eps`` and is then held)
is :func:`isometric_sweep`: phase 1 follows the free muscle by cap displacement with the pressure
as unknown up to ``U = -eps L0/2``, which gives the threshold pressure ``P*`` (force zero below
it); phase 2 holds the cap and ramps the pressure through the requested values.
"""

from __future__ import annotations

from dataclasses import replace
from functools import lru_cache, partial

import numpy as np
import scipy.sparse as sp
from skfem import Basis, ElementTriP1, ElementTriP2, ElementVector, FacetBasis

from mkm.fem.calibration import CalibratedTheta0, Calibration
from mkm.fem.eq2 import BAR_TO_MPA, LOCKING_ANGLE_DEG, check_theta0
from mkm.fem.fe.assembly import Assembler, Term, operator
from mkm.fem.fe.forms import (
    braid_inextensibility,
    cavity_volume,
    mooney_rivlin_incompressible,
    mooney_rivlin_incompressible_tangent,
    sliding_sleeve_length,
)
from mkm.fem.fe.mesh import half_muscle_mesh
from mkm.fem.fe.newton import Chord, NewtonReport, OrderedLU, load_path, newton
from mkm.fem.interface import ForceModel
from mkm.fem.limits import check_value
from mkm.fem.materials import SILASTIC_S, MooneyRivlin
from mkm.fem.options import BRAIDS, MESH_LEVELS
from mkm.fem.outcomes import BRAID_LOCKS
from mkm.fem.thickwall import klute_hannaford_threshold_pressure, mid_section_kinematics

# 6 points per triangle: exact for P2 x P2 products; the smooth R and 1/R factors of a wall
# away from the axis add an error far below the mesh's
INTORDER = 4
#: Halvings of a load step (free path and pressure ramp) before the solve gives up: from span/5,
#: 12 reach span/2e4. Near the braid lock the fine mesh's small cap elements need 7 on the free
#: path (a mesh graded 32:1 needs 9). Just above P* the held muscle of a thin soft tube at a low
#: braid angle is soft against barrelling (the middle swells, the ends neck: D0 60 mm, t0 0.5 mm,
#: theta0 15 deg, C10 0.03 MPa, L0 180 mm, eps 0.0239: du_r/dP 1350 mm/bar at the mid-plane)
#: and stiffens within a hundredth of a bar (2.8 mm in all), so Newton's first iterate of a
#: ramp step from P* is that slope times the step and inverts the wall's elements above
#: 0.005 bar: the 0:8:0.5 sweep needs 7 halvings, the 8 bar point alone 9.
MAX_CUTBACKS = 12
#: A pressure step of the held ramp is converged once the correction still to come, as the
#: factorisation at hand estimates it, would change the cap force by less than this fraction of
#: the force (or of the cap force at 1 bar, near the threshold). The chord iterations' estimate
#: is rougher than a fresh Newton step's, so the bar is set low: a point of a sweep and the same
#: point solved alone agree to 1e-9 (at 1e-8 they differed by up to 4e-7), at two or three
#: residuals more per step
FORCE_RTOL = 1e-10
#: A free path that stalls is said to stop at the braid lock (a physical limit) only where its
#: widest section's braid angle is within this of the locking angle [deg]: the rate of the last
#: two converged steps is extrapolated over a short way only. Stalls at the lock, coarse and
#: medium meshes, bonded braid (short wide muscles, L0 = 2-3 D0, theta0 30-43 deg): 0.16-1.71
#: deg short of it; stalls of the solver (the sliding braid at a low angle at rest) were 3.5-39
#: deg short, one at 26 deg with a rate, from steps cut back 12 times, that reached the lock by
#: eps 0.148 where the closed form's lock is at 0.40.
LOCK_NEAR_DEG = 2.5
#: A converged state whose bonded fibres are stretched by more than this between the nodes,
#: in the muscle's middle, is the mesh's zig-zag (:meth:`HalfMuscle.zig_zag_strain`): resolved
#: states stay below 1e-4, the zig-zags measured were 1.3e-3 to 0.075
ZIG_ZAG_STRAIN = 1e-3


class HalfMuscle:
    """Discretised half muscle of one geometry: operators, dof maps and the assembly.

    Unknowns (reduced, after the boundary conditions): the free displacement dofs, the P1 wall
    pressure, the P1 braid tension, and last the cap displacement ``U`` [mm].
    """

    def __init__(self, D0_mm, t0_mm, L0_mm, theta0_deg, material: MooneyRivlin, mesh: str,
                 braid: bool = True, cap: str = "clamped", sleeve: str = "bonded",
                 gap_mm: float = 0.0):
        if cap not in ("clamped", "sliding"):
            raise ValueError(f"cap={cap!r} is invalid: expected 'clamped' or 'sliding'")
        check_sleeve(sleeve)
        check_gap(gap_mm, sleeve)
        # the discretisation of a geometry (scikit-fem's bases: a quarter of a coarse sweep) is
        # shared by every muscle of that geometry; the work arrays and solver state are this one's
        self.__dict__.update(_discretised(float(D0_mm), float(t0_mm), float(L0_mm), mesh,
                                          bool(braid), cap, sleeve, float(gap_mm)))
        self.rubber, self.cavity = self.rubber.fresh(), self.cavity.fresh()
        self.braid = self.braid.fresh() if braid else None
        self.theta0_deg, self.material = theta0_deg, material
        if braid:
            self._membrane_N_per_mm = 3.0 * (material.C10_MPa + material.C01_MPa) * t0_mm
        self._reactions: dict[tuple[float, bytes], float] = {}
        self._last_rubber: tuple[np.ndarray, np.ndarray] | None = None
        self._held_lu = OrderedLU(leading=self.n - 1)
        self._free_lu = OrderedLU()

    def _discretise(self, D0_mm, t0_mm, L0_mm, mesh: str, braid: bool, cap: str, sleeve: str,
                    gap_mm: float) -> None:
        """Mesh, bases, operators, dof maps and sparsity patterns of one geometry: what
        :func:`_discretised` keeps (no material, no state)."""
        self.sleeve = sleeve
        self.Ri, self.Ro, self.H = D0_mm / 2.0, D0_mm / 2.0 + t0_mm, L0_mm / 2.0
        # the braid's rest radius: a gap puts it outside the tube (bonded braid only)
        self.gap_mm = float(gap_mm)
        self.Rb = self.Ro + self.gap_mm
        self._constraint = (sliding_sleeve_length if sleeve == "sliding" else
                            partial(braid_inextensibility,
                                    braid_radius_mm=self.Rb if self.gap_mm else None))
        m = half_muscle_mesh(D0_mm, t0_mm, L0_mm, mesh)
        eu = ElementVector(ElementTriP2())
        ub = Basis(m, eu, intorder=INTORDER)
        pb = Basis(m, ElementTriP1(), intorder=INTORDER)
        inner = m.facets_satisfying(lambda x: np.isclose(x[0], self.Ri))
        outer = m.facets_satisfying(lambda x: np.isclose(x[0], self.Ro))
        ib = FacetBasis(m, eu, facets=inner, intorder=INTORDER)
        ob = FacetBasis(m, eu, facets=outer, intorder=INTORDER)
        nu, npr = ub.N, pb.N
        tension_nodes = np.unique(m.facets[:, outer]) if braid else np.array([], dtype=int)
        # bonded: a tension per outer node; sliding: one uniform tension
        nl = len(tension_nodes) if sleeve == "bonded" else int(braid)

        # rubber: y = (F_rr, F_rz, F_zr, F_zz, F_tt, p)
        R = ub.global_coordinates()[0]
        Bu = operator(ub, lambda v, g: (g[0, 0], g[0, 1], g[1, 0], g[1, 1], v[0] / R, 0 * R))
        Bp = operator(pb, lambda v, g: (0 * v,) * 5 + (v,))
        rubber_term = (np.concatenate([Bu, Bp], axis=2), np.array([1, 0, 0, 1, 1, 0.0]),
                       np.vstack([ub.element_dofs, nu + pb.element_dofs]), 2 * np.pi * R * ub.dx)
        # cavity: y = (r, dz/dZ) on the inner surface; dZ is the facet measure (vertical facets)
        cavity_term = (operator(ib, lambda v, g: (v[0], g[1, 1])),
                       np.stack([ib.global_coordinates()[0], np.ones_like(ib.dx)], axis=-1),
                       ib.element_dofs, ib.dx)
        # braid: y = (u_r, du_r/dZ, du_z/dZ, tension) on the outer surface
        Z = ob.global_coordinates()[1]
        za, zb = (m.p[1, m.facets[k, ob.find]][:, None] for k in (0, 1))
        shape_a = (zb - Z) / (zb - za)
        Bb = operator(ob, lambda v, g: (v[0], g[0, 1], g[1, 1], 0 * Z))
        Bl = np.zeros(Bb.shape[:2] + (2, 4))
        Bl[..., 0, 3], Bl[..., 1, 3] = shape_a, 1.0 - shape_a
        lam_dofs = nu + npr + (np.searchsorted(tension_nodes, m.facets[:, ob.find])
                               if sleeve == "bonded" else np.zeros((2, ob.find.size), int))
        # the braid's quadrature points more than two outer diameters from the cap: the
        # muscle's middle, where a converged bonded braid keeps its length (zig_zag_strain)
        self._braid_middle = Z < self.H - 4.0 * self.Ro
        braid_term = (np.concatenate([Bb, Bl], axis=2), np.zeros(4),
                      np.vstack([ob.element_dofs, lam_dofs]), 2 * np.pi * self.Ro * ob.dx)

        # boundary conditions as a map full dof -> reduced dof (-1: fixed at zero)
        ir, iz = ub.split_indices()
        Zdof = ub.doflocs[1]
        fixed = np.zeros(nu + npr + nl, dtype=bool)
        fixed[iz[np.isclose(Zdof[iz], 0.0)]] = True
        cap_r = ir[np.isclose(Zdof[ir], self.H)]
        cap_z = iz[np.isclose(Zdof[iz], self.H)]
        fixed[cap_z] = True
        fixed[cap_r] = cap == "clamped"  # "sliding" (a verification case): u_r free at the cap
        red = np.full(fixed.size, -1)
        red[~fixed] = np.arange((~fixed).sum())
        self.n = int((~fixed).sum()) + 1
        red[cap_z] = self.n - 1
        self.red = red
        # where the free displacement dofs sit at rest (R, Z), for the thick-wall start
        R_dof = ub.doflocs[0]
        self._free_r = ir[red[ir] >= 0]
        self._free_z = iz[(red[iz] >= 0) & (red[iz] < self.n - 1)]
        self._dof_RZ = R_dof, Zdof
        self.p_slice = slice(red[nu], red[nu] + npr)
        self.tension_slice = slice(red[nu] + npr, red[nu] + npr + nl)
        self.rubber, self.cavity = Term(*rubber_term, red), Term(*cavity_term, red)
        self.braid = Term(*braid_term, red) if braid else None
        terms = [t for t in (self.rubber, self.cavity, self.braid) if t is not None]
        self.assembler = Assembler(terms, self.n)
        if braid:
            # tension-only braid (slack_nodes): a tension dof's constraint residual over its
            # weight int phi_i dA is the mean of g = l_f^2 - 1 ~ 2 x fibre strain around it;
            # the wall's membrane stiffness E t0 / 2 = 3 (C10 + C01) t0 [N/mm] turns that into
            # the tension it would take to hold it, which the active set compares with lambda
            self._tension_weight_mm2 = self._tension_rows(np.ones(Bb.shape[:2]))
            rows, cols = self.assembler.entries()
            in_tension = ((rows >= self.tension_slice.start) & (rows < self.tension_slice.stop)
                          | (cols >= self.tension_slice.start) & (cols < self.tension_slice.stop))
            # the entries in a tension dof's row or column: the only ones _release touches
            self._tension_entries = np.flatnonzero(in_tension)
            self._entry_rows, self._entry_cols = (rows[self._tension_entries],
                                                  cols[self._tension_entries])
            self._tension_diagonal = np.flatnonzero(
                (rows == cols) & (rows >= self.tension_slice.start)
                & (rows < self.tension_slice.stop))
        # the ramp's tangents (the leading block: without the cap) keep one ordering, and so do
        # the free path's (the pressure's column -dV/dy, dense along the inner surface, is
        # numbered last); the free tangent's pattern: K's without the cap column, plus dV's
        self._free_pattern()

    def rest_state(self) -> np.ndarray:
        """Reduced unknowns at rest: no displacement, no tension, and the wall pressure that
        balances the non-isochoric Mooney-Rivlin stress at F = I (p = 2 C10 + 4 C01)."""
        y = np.zeros(self.n)
        y[self.p_slice] = 2 * self.material.C10_MPa + 4 * self.material.C01_MPa
        return y

    def assemble(self, y, pressure_MPa, tangent: bool = True):
        """Residual ``dPi/dy``, tangent ``d2Pi/dy2`` (CSR) and ``dV/dy`` at the reduced state.

        ``tangent=False`` leaves the tangent out (``None``): a chord iteration, which reuses a
        factorised tangent, needs the residual only, at a fraction of the cost. The cap
        reaction (the last residual entry) of every state assembled is kept, so the force of a
        converged state is read from the assembly Newton made to check it.
        """
        result = self._assemble(y, pressure_MPa, tangent)
        if len(self._reactions) > 256:  # a sweep needs a few dozen; bound the memory
            self._reactions.clear()
        self._reactions[pressure_MPa, np.asarray(y, dtype=float).tobytes()] = float(result[0][-1])
        return result

    def _assemble(self, y, pressure_MPa, tangent=True):
        y = np.asarray(y, dtype=float)
        yr = self._rubber_values(y)
        h = mooney_rivlin_incompressible_tangent(yr, self.material) if tangent else None
        r, K_rub = self.rubber.arrays(mooney_rivlin_incompressible(yr, self.material), h)
        _, g, h = cavity_volume(self.cavity.values(y))
        dV, K_cav = self.cavity.arrays(g, -pressure_MPa * h if tangent else None)
        r -= pressure_MPa * dV
        blocks = [K_rub, K_cav]
        slack = None
        if self.braid is not None:
            yb = self.braid.values(y)
            gb, dgb, hgb = self._constraint(yb[..., :3], self.theta0_deg, self.Ro)
            r_br, K_br = self._braid_arrays(gb, dgb, hgb, yb[..., 3], tangent)
            # the constraint rows do not depend on the tension: the gaps of this state
            gap = r_br[self.tension_slice]
            slack = self.slack_nodes(y[self.tension_slice], gap)
            if slack.any():  # slack fibres carry nothing: the braid term without their tension
                y_taut = y.copy()
                y_taut[self.tension_slice][slack] = 0.0
                r_br, K_br = self._braid_arrays(gb, dgb, hgb, self.braid.values(y_taut)[..., 3],
                                                tangent)
            r += r_br
            blocks.append(K_br)
        K = self.assembler.matrix(blocks) if tangent else None
        if slack is not None and slack.any():
            self._release(r, K, y, slack)
        return r, K, dV

    def _rubber_values(self, y) -> np.ndarray:
        """The rubber's variables at ``y`` (read-only), the last state's kept: Newton checks
        a state (:meth:`inverted`) and then assembles it."""
        if self._last_rubber is not None and np.array_equal(self._last_rubber[0], y):
            return self._last_rubber[1]
        values = self.rubber.values(y)
        values.flags.writeable = False
        self._last_rubber = (np.array(y, dtype=float), values)  # a copy: y may change after
        return values

    def _tension_rows(self, density) -> np.ndarray:
        """``int phi_i density dA`` over the outer surface for each tension dof ``i``."""
        grad = np.zeros(density.shape + (4,))
        grad[..., 3] = density
        return self.braid.residual(grad)[self.tension_slice]

    def fibre_stretch_gap(self, y) -> np.ndarray:
        """Mean of ``l_f^2 - 1`` around each tension dof: < 0 where the fibres are slack."""
        yb = self.braid.values(y)
        g, _, _ = self._constraint(yb[..., :3], self.theta0_deg, self.Ro)
        return self._tension_rows(g) / self._tension_weight_mm2

    def _braid_arrays(self, g, dg, hg, tension, tangent=True):
        """Element vectors and matrices (None without ``tangent``) of the braid term
        ``int tension g dA``."""
        grad = np.concatenate([tension[..., None] * dg, g[..., None]], axis=-1)
        if not tangent:
            return self.braid.arrays(grad, None)
        hess = np.zeros(grad.shape + (4,))
        hess[..., :3, :3] = tension[..., None, None] * hg
        hess[..., :3, 3] = hess[..., 3, :3] = dg
        return self.braid.arrays(grad, hess)

    def slack_nodes(self, tension, gap) -> np.ndarray:
        r"""Tension dofs whose fibres are slack: True where ``lambda + k g_i <= 0``.

        The tension-only braid is the complementarity ``g_i <= 0, lambda_i >= 0,
        lambda_i g_i = 0`` at each tension dof ``i`` (``g_i`` the weighted mean of
        ``l_f^2 - 1`` around it, ``gap / weight``): a thread can be shortened (it goes slack)
        but not stretched, and pulls only. It is solved as a primal-dual active set
        (semi-smooth Newton on ``lambda - max(0, lambda + k g)``): at each iterate a fibre is
        taut when its tension plus the tension the wall would need to hold its strain
        (``k`` its membrane stiffness) is positive; a taut fibre keeps ``g_i = 0``, a slack
        one gets ``lambda_i = 0`` and drops out of the equilibrium. At a converged state that
        is exactly the complementarity, whatever ``k``; ``k`` only sets how an iterate far from
        it is read.

        Parameters
        ----------
        tension : numpy.ndarray
            Braid tension at the tension dofs [N/mm].
        gap : numpy.ndarray
            Constraint residuals ``int phi_i (l_f^2 - 1) dA`` there [mm^2].
        """
        return tension + self._membrane_N_per_mm * gap / self._tension_weight_mm2 < 0.0

    def _release(self, r, K, y, slack) -> None:
        """Make the slack tension dofs' rows ``lambda_i = 0`` in ``r`` and ``K`` (in place;
        ``K`` None: the residual only).

        Row and column of each are emptied (the rest of the system no longer sees it: its
        tension was left out of the assembly) and the diagonal is ``-weight / k``, so the
        Newton step sets the tension to zero and the tangent stays symmetric.
        """
        scale = -self._tension_weight_mm2[slack] / self._membrane_N_per_mm
        dofs = np.flatnonzero(slack) + self.tension_slice.start
        r[dofs] = scale * y[dofs]
        if K is None:
            return
        released = np.zeros(self.n, dtype=bool)
        released[dofs] = True
        K.data[self._tension_entries[released[self._entry_rows]
                                     | released[self._entry_cols]]] = 0.0
        K.data[self._tension_diagonal[slack]] = scale

    def inverted(self, y) -> str | None:
        """Reason to reject a state at once: an element turned inside out (J <= 0)."""
        f = self._rubber_values(y)
        if not np.all(np.isfinite(f)):
            return "non-finite displacement"
        if np.any(f[..., 4] <= 0) or np.any(f[..., 0] * f[..., 3] - f[..., 1] * f[..., 2] <= 0):
            return "element inversion (J <= 0)"
        return None

    def braid_angle_deg(self, y) -> float:
        """Largest braid angle along the muscle [deg from the axis] in the state ``y``.

        An inextensible fibre at ``theta0`` on a surface whose hoop stretch is ``l_t`` makes
        ``sin theta = l_t sin theta0`` (its length around the axis grows with the radius, its
        length is fixed), for a bonded braid and a sliding sleeve alike (the sleeve's radius is
        the rubber's); the widest section has the largest (with a gap the braid's hoop
        stretch is the tube's radius over the braid's rest radius, where they touch). NaN
        without a braid.
        """
        if self.braid is None:
            return np.nan
        u_r = self.braid.values(y)[..., 0]
        l_t = (1.0 + u_r / self.Ro) * (self.Ro / self.Rb)
        sine = float(np.max(l_t)) * np.sin(np.deg2rad(self.theta0_deg))
        return float(np.rad2deg(np.arcsin(min(sine, 1.0))))

    def tension(self, y) -> np.ndarray:
        """Braid membrane tension at the outer-surface nodes [N/mm]."""
        return y[self.tension_slice]

    def slack_everywhere(self, y) -> bool:
        """Whether the braid carries no tension at all (a bare rubber tube)."""
        lam = self.tension(y)
        return bool(lam.size) and bool(np.all(lam <= 0))

    def compression(self, y) -> str:
        """Why a state is unphysical for a tension-only braid (empty if it is not)."""
        lam = self.tension(y)
        if lam.size and lam.min() < -1e-6 * max(np.abs(lam).max(), 1e-12):
            return f"fibre compression (braid tension {lam.min():.3g} N/mm < 0)"
        return ""

    def zig_zag_strain(self, y) -> float:
        """Largest fibre strain ``l_f - 1`` of a bonded braid in the muscle's middle (more than
        two outer diameters from the cap), between the nodes where its length is enforced; 0
        without a bonded braid or a middle.

        The tension per outer node holds the weighted mean of ``l_f^2 - 1`` around the node to
        zero, not its value at every point: on a mesh too coarse along a slender thin wall the
        wall can zig-zag from node to node with its fibres stretched between the nodes and
        shortened at them, a mode of the mesh, not of the muscle. Resolved states keep it below
        1e-4 (muscle I's threshold on every mesh 5e-7, the fine mesh's D0 5 mm, t0 0.5 mm,
        L0 1000 mm muscle at theta0 40 deg, eps 0.0145, 7e-5); the medium mesh's zig-zag of that
        muscle at its threshold reaches 0.075.
        """
        if self.braid is None or self.sleeve != "bonded" or not self._braid_middle.any():
            return 0.0
        g, _, _ = self._constraint(self.braid.values(y)[..., :3], self.theta0_deg, self.Ro)
        return max(float(np.max(g[self._braid_middle])) / 2.0, 0.0)

    def mesh_mode(self, y) -> str:
        """Why ``y`` is the mesh's zig-zag rather than the muscle's state (empty if it is not):
        its fibres stretched by more than :data:`ZIG_ZAG_STRAIN` between the nodes."""
        strain = self.zig_zag_strain(y)
        if strain <= ZIG_ZAG_STRAIN:
            return ""
        longest = float(np.max(np.diff(np.unique(self._dof_RZ[1]))) * 2.0)  # P2: mid-side nodes
        return (f"the wall zig-zags from node to node, its inextensible fibres stretched by "
                f"{100 * strain:.2g} % between the nodes, on elements up to "
                f"{longest / (2.0 * self.Ro):.2g} outer diameters long: a mode of the mesh, too "
                "coarse along this slender thin wall (mesh=fine resolves it)")

    @property
    def force_scale_N(self) -> float:
        """The pressure's force on the cap at 1 bar [N]: the scale of the forces' tolerances."""
        return 0.1 * np.pi * self.Ro**2

    def _newton_options(self):
        return {"residual_floor": 1e-10 * self.force_scale_N}

    def thick_wall_start(self, U_mm: float):
        """A start for the free muscle at cap displacement ``U_mm``: ``(x, pressure_MPa)`` or
        None where the closed form has no solution (at and beyond the braid lock).

        The mid-section of a long free muscle is the thick-wall closed form
        (:func:`mkm.fem.thickwall.mid_section_kinematics`): uniform axial stretch ``1 - eps``,
        ``r^2 = k + R^2 / (1 - eps)``, at the thick-wall threshold pressure. Towards the clamped
        cap the radial displacement is faded out over half a diameter (the end zone); the wall
        pressure starts at rest and the braid tension at :meth:`taut_tension` of that pressure,
        Newton finds them with the rest. With a gap, the closed form's tube in contact with the
        braid (the same kinematics with the braid's radius).
        """
        eps = -U_mm / self.H
        D0, t0 = 2.0 * self.Ri, self.Ro - self.Ri
        _, _, lz, k, ri2, _, _, _ = mid_section_kinematics(D0, t0, eps, self.theta0_deg,
                                                           self.gap_mm)
        threshold_bar = klute_hannaford_threshold_pressure(
            D0, t0, eps, self.theta0_deg, self.material.C10_MPa, self.material.C01_MPa,
            self.gap_mm)
        if not (ri2 > 0 and np.isfinite(threshold_bar)):
            return None
        R, Z = self._dof_RZ
        y = self.rest_state()
        Rr, Zr = R[self._free_r], Z[self._free_r]
        fade = -np.expm1(-(self.H - Zr) / self.Ri)
        y[self.red[self._free_r]] = (np.sqrt(k + Rr**2 / lz) - Rr) * fade
        y[self.red[self._free_z]] = U_mm * Z[self._free_z] / self.H
        y[self.tension_slice] = self.taut_tension(float(threshold_bar) * BAR_TO_MPA)
        return np.append(y[:-1], float(threshold_bar) * BAR_TO_MPA)

    def taut_tension(self, pressure_MPa: float) -> float:
        """Braid tension [N/mm] of the undeformed muscle at ``pressure_MPa``: the braid's hoop
        force ``lambda dg/dl_t`` carries ``P R_o`` (exact at eps = 0).

        A start for the free muscle's tension-only braid: from a start whose tension is zero
        every fibre that the start shortens reads as slack, and the free problem (pressure
        unknown) has a second solution with a slack braid at a negative pressure, a tube
        sucked shorter, where Newton then goes. A taut start keeps it on the inflated branch.
        """
        if self.braid is None:
            return 0.0
        _, dg, _ = self._constraint(np.zeros(3), self.theta0_deg, self.Ro)
        return pressure_MPa / dg[0]  # dg/du_r = (dg/dl_t) / R_o

    def free_path(self, U_mm: float):
        """Free shortening of the muscle (no force) to cap displacement ``U_mm`` < 0.

        The cap is put at ``U_mm`` with the pressure as unknown (the cap equation says the
        reaction is zero). First one Newton solve from the thick-wall start
        (:meth:`thick_wall_start`: 5-6 iterations on every mesh); where it fails (near the
        braid lock) or lands off the inflated branch (a pressure <= 0 or a braid slack
        everywhere: full Newton from a far start can jump there) the path is followed by cap
        displacement from the thick-wall solution at a fifth of the shortening (or from rest
        where there is none), with up to :data:`MAX_CUTBACKS` halvings (the small cap
        elements of a fine mesh need short steps near the lock). Returns the state, the
        pressure [MPa] and the report (iterations of all attempts). With a gap, ``U_mm = 0``
        too (the threshold at rest length): there is no path to follow, and a failed solve
        from the thick-wall start is reported as such. A path that ends off the inflated branch
        is reported too, never returned.
        """
        def free(x, U):
            r, K, dV = self.assemble(np.append(x[:-1], U), x[-1])
            return r, self._free_tangent(K, dV)

        def free_residual(x, U):
            return self.assemble(np.append(x[:-1], U), x[-1], tangent=False)[0]

        def check(x, U):
            return self.inverted(np.append(x[:-1], U))

        def from_thick_wall(U):
            start = self.thick_wall_start(U)
            if start is None:
                return None, None
            x, report = newton(lambda x: free(x, U), start, check=lambda x: check(x, U),
                               residual=lambda x: free_residual(x, U), chord=Chord(),
                               factorize=self._free_lu, **self._newton_options())
            inflated = x[-1] > 0 and not self.slack_everywhere(np.append(x[:-1], U))
            return (x if report.converged and inflated else None), report

        x, report = from_thick_wall(U_mm)
        if x is not None:
            return np.append(x[:-1], U_mm), float(x[-1]), report
        spent = 0 if report is None else report.iterations
        # a start on the inflated branch: from rest (no tension) the first step's fibres,
        # shortened by the cap alone, read as slack and Newton may take the sucked branch
        U_start = U_mm / 5
        x0, first = from_thick_wall(U_start)
        spent += 0 if first is None else first.iterations
        if x0 is None:
            U_start, x0 = 0.0, np.append(self.rest_state()[:-1], 0.0)
        if U_start == U_mm:  # eps = 0 with a gap: no path to follow, the one solve failed
            reason = "" if report is None else report.reason
            return None, np.nan, replace(report or NewtonReport(False), converged=False, reason=(
                f"the tube in contact with the braid at eps=0 was not found from the thick-wall "
                f"start ({reason or 'it landed off the inflated branch'})"))
        # full Newton on this path near the lock: chord iterations there would spend their
        # iterations where Newton finds the inversion that names the reason at once
        [(x, report)] = load_path(free, x0, U_start, [U_mm], check=check,
                                  max_cutbacks=MAX_CUTBACKS,
                                  label=lambda U: f"cap displacement {U:.3g} mm",
                                  factorize=self._free_lu, **self._newton_options())
        report.iterations += spent
        if x is not None and (x[-1] <= 0 or self.slack_everywhere(np.append(x[:-1], U_mm))):
            # a bare tube sucked shorter, not the muscle: say so rather than return it
            report.converged = False
            x, report.reason = None, (f"the free path ended off the inflated branch (at "
                                      f"{x[-1] / BAR_TO_MPA:.3g} bar, or with the braid slack "
                                      "everywhere)")
        if x is None:
            if self.thick_wall_start(U_mm) is None:
                # the closed form's mid-section is past the lock, and the muscle's narrow ends
                # make its mid-section shorten more than eps: the muscle is past it too
                report.reason = (f"the braid passes its locking angle before eps={-U_mm / self.H:g}"
                                 f" (the thick-wall mid-section locks first; the path "
                                 f"stopped with: {report.reason})")
                report.limit = BRAID_LOCKS
            elif lock := self._locks_before(report.reached, U_mm):
                report.reason = f"{lock} (the path stopped with: {report.reason})"
                report.limit = BRAID_LOCKS
            elif report.reached and (mode := self.mesh_mode(
                    np.append(report.reached[-1][1][:-1], report.reached[-1][0]))):
                report.reason = f"{report.reason} ({mode})"
            return None, np.nan, report
        return np.append(x[:-1], U_mm), float(x[-1]), report

    def _free_pattern(self) -> None:
        """The free tangent's CSR pattern from K's (sorted columns, the cap's last): in each row
        K's entries left of the cap column, then the pressure column where dV has a row."""
        rows, cols = self.assembler.entries()
        K_indptr = np.append(np.searchsorted(rows, np.arange(self.n)), rows.size)
        self._K_inner = np.flatnonzero(cols < self.n - 1)
        self._dV_rows = np.unique(self.cavity.dofs[self.cavity.dofs >= 0])
        counts = np.bincount(rows[self._K_inner], minlength=self.n)
        counts[self._dV_rows] += 1
        indptr = np.concatenate([[0], np.cumsum(counts)])
        inner_rows = rows[self._K_inner]
        inner_slots = indptr[inner_rows] + self._K_inner - K_indptr[inner_rows]
        dV_slots = indptr[self._dV_rows + 1] - 1
        self._free_slots = np.concatenate([inner_slots, dV_slots])
        self._free_indices = np.empty(indptr[-1], dtype=cols.dtype)
        self._free_indices[self._free_slots] = np.concatenate(
            [cols[self._K_inner], np.full(self._dV_rows.size, self.n - 1)])
        self._free_indptr = indptr

    def _free_tangent(self, K, dV) -> sp.csr_matrix:
        """The free muscle's tangent: ``K`` with its cap column replaced by ``-dV`` (the
        pressure is the unknown there), gathered into the pattern found once."""
        data = np.empty(self._free_indices.size)
        data[self._free_slots] = np.concatenate([K.data[self._K_inner], -dV[self._dV_rows]])
        return sp.csr_matrix((data, self._free_indices, self._free_indptr), shape=K.shape)

    def _locks_before(self, reached, U_mm: float) -> str:
        """Why a free path that stalled short of ``U_mm`` stopped at the braid lock, or "".

        The braid locks where its angle reaches :data:`~mkm.fem.eq2.LOCKING_ANGLE_DEG` (the
        largest volume: no pressure shortens it further); with the ends held narrow by the caps
        the widest section gets there before the closed form's lock shortening. The path's last
        two converged states (``reached``: cap displacement, unknowns) give the rate at which
        ``cos theta`` of the widest section falls with the shortening; it locks before the
        target when that line reaches ``1 / sqrt(3)`` by ``U_mm`` (the rate only grows towards
        the lock, as the middle takes a growing share of the shortening) and the path stalled
        within :data:`LOCK_NEAR_DEG` of the locking angle (further short of it, the stall is
        the solver's, whatever the rate of its cut-back steps says).
        """
        if len(reached) < 2 or self.braid is None:
            return ""
        (U0, x0), (U1, x1) = reached
        angle = self.braid_angle_deg(np.append(x1[:-1], U1))
        if angle < LOCKING_ANGLE_DEG - LOCK_NEAR_DEG:  # stalled short of it: the solver's
            return ""
        c0, c1 = (np.cos(np.deg2rad(self.braid_angle_deg(np.append(x[:-1], U))))
                  for U, x in reached)
        e0, e1, target = -U0 / self.H, -U1 / self.H, -U_mm / self.H
        if not (e1 > e0 and c1 < c0):
            return ""
        predicted = c1 + (c1 - c0) / (e1 - e0) * (target - e1)
        if predicted > 1.0 / np.sqrt(3.0):
            return ""
        return (f"the braid locks before eps={target:g}: its angle, {angle:.2f} deg at "
                f"eps={e1:.4g} and rising, reaches the locking angle {LOCKING_ANGLE_DEG:.2f} deg "
                f"by eps={e1 + (c1 - 1.0 / np.sqrt(3.0)) / (c0 - c1) * (e1 - e0):.4g}")

    def held_path(self, y, P_start_MPa: float, pressures_MPa):
        """Pressure ramp with the cap held where ``y`` has it, from the state ``y`` at
        ``P_start_MPa`` through the sorted ``pressures_MPa``: a list of (state or None, report).
        A step that fails is halved, up to :data:`MAX_CUTBACKS` times.
        """
        U = y[-1]
        last = {}

        def held(x, P):  # K's leading block is the held tangent: self._held_lu reads only it
            r, K, _ = self.assemble(np.append(x, U), P)
            last["K"], last["force"] = K, r[-1]
            return r[:-1], K

        def held_residual(x, P):  # for chord iterations: the tangent of the last Newton step
            r, _, _ = self.assemble(np.append(x, U), P, tangent=False)
            last["force"] = r[-1]
            return r[:-1]

        def force_converged(x, step):
            # the force is the cap reaction r[-1]: the next Newton step changes it by the cap
            # row of the tangent times that step (first order; Newton's error after this
            # iterate is second order), so the force is converged to FORCE_RTOL when that is
            # small, however far the other unknowns still are from the strict tolerance
            K = last["K"]
            lo, hi = K.indptr[-2], K.indptr[-1]
            columns, values = K.indices[lo:hi], K.data[lo:hi]
            inner = columns < self.n - 1
            change = values[inner] @ step[columns[inner]]
            return abs(change) <= FORCE_RTOL * max(abs(last["force"]), self.force_scale_N)

        path = load_path(held, y[:-1], P_start_MPa, pressures_MPa,
                         check=lambda x, P: self.inverted(np.append(x, U)),
                         label=lambda P: f"{P / BAR_TO_MPA:.4g} bar", factorize=self._held_lu,
                         accept=force_converged, residual=held_residual,
                         max_cutbacks=MAX_CUTBACKS, **self._newton_options())
        return [(None if x is None else np.append(x, U), report) for x, report in path]

    def cavity_volume(self, y) -> float:
        """Volume of the half muscle's cavity [mm^3] (inside the rubber, up to the cap)."""
        v, _, _ = cavity_volume(self.cavity.values(y))
        return float(np.sum(v * self.cavity.w))

    def cap_force(self, y, pressure_MPa: float) -> float:
        """Reaction on the cap, ``dPi/dU`` [N]: the muscle's pulling force (see module doc)."""
        key = (pressure_MPa, np.asarray(y, dtype=float).tobytes())
        if key not in self._reactions:
            self.assemble(y, pressure_MPa)
        return self._reactions[key]


@lru_cache(maxsize=8)
def _discretised(D0_mm: float, t0_mm: float, L0_mm: float, mesh: str, braid: bool, cap: str,
                 sleeve: str, gap_mm: float) -> dict:
    """The attributes :meth:`HalfMuscle._discretise` sets for one geometry, built once for the
    muscles of that geometry (a fit varies the angle and the rubber, not the tube). Read only:
    each :class:`HalfMuscle` takes fresh work arrays of its terms (:meth:`Term.fresh`)."""
    bare = HalfMuscle.__new__(HalfMuscle)
    bare._discretise(D0_mm, t0_mm, L0_mm, mesh, braid, cap, sleeve, gap_mm)
    return dict(vars(bare))


def check_sleeve(braid: str) -> str:
    """``braid`` if it is one of :data:`mkm.fem.options.BRAIDS`, else ``ValueError``."""
    if braid not in BRAIDS:
        raise ValueError(f"braid={braid!r} is invalid: expected one of {', '.join(BRAIDS)}")
    return braid


def check_gap(gap_mm: float, braid: str = "bonded") -> float:
    """``gap_mm`` if it is in its range (:data:`mkm.fem.limits.LIMITS`) and the braid takes it,
    else ``ValueError``: a sliding sleeve has one uniform tension, so it cannot lie on the tube
    in the middle and off it near the caps, as a braid with a gap does."""
    gap_mm = check_value("gap_mm", gap_mm)
    if gap_mm and braid != "bonded":
        raise ValueError(f"gap_mm={gap_mm:g} is invalid with braid={braid!r}: a gap is "
                         "modelled with the bonded braid only")
    return gap_mm


def check_parameters(theta0_deg: float, L0_mm: float, mesh: str, braid: str = "bonded",
                     gap_mm: float = 0.0) -> None:
    """Raise ``ValueError`` naming a model parameter outside its physical range."""
    check_sleeve(braid)
    check_gap(gap_mm, braid)
    check_theta0(theta0_deg)
    if not L0_mm > 0:
        raise ValueError(f"L0_mm={L0_mm:g} is invalid: expected a length > 0 mm")
    if mesh not in MESH_LEVELS:
        raise ValueError(f"mesh={mesh!r} is invalid: expected one of {', '.join(MESH_LEVELS)}")


def isometric_sweep(pressure_bar, D0_mm: float, t0_mm: float, eps: float, theta0_deg: float,
                    L0_mm: float = 282.0, mesh: str = "medium",
                    material: MooneyRivlin = SILASTIC_S,
                    braid: str = "bonded", gap_mm: float = 0.0) -> dict[str, np.ndarray]:
    """Isometric force of one muscle over a pressure sweep, by the axisymmetric FE model.

    Parameters
    ----------
    pressure_bar : array_like
        Gauge pressures [bar], any order, repeats allowed.
    D0_mm, t0_mm : float
        Inner diameter and wall thickness at rest [mm].
    eps : float
        Shortening ratio at which the cap is locked [fraction].
    theta0_deg : float
        Braid angle at rest, from the axis [deg].
    L0_mm : float
        Length at rest [mm] (282 in the paper).
    mesh : {"coarse", "medium", "fine"}
        Mesh level (:data:`mkm.fem.options.MESH_LEVELS`).
    material : MooneyRivlin
        Wall material (default Silastic S, the paper's Equation 3).
    braid : {"bonded", "sliding"}
        How the braid meets the rubber (:data:`mkm.fem.options.BRAIDS`); ``bonded`` as the
        paper's figure suggests (the paper does not say), ``sliding`` the frictionless-sleeve
        limit.
    gap_mm : float
        Radial gap between the tube's outer surface and the braid at rest [mm] (bonded braid
        only). The tube inflates freely until it reaches the braid, which carries load only
        where they touch (a unilateral contact: the tension-only braid's complementarity, see
        :func:`mkm.fem.fe.forms.braid_inextensibility`); then even at ``eps = 0`` the force
        starts above a threshold pressure, found as at ``eps > 0`` (the muscle held at its
        length, the pressure unknown). 0 (default): no gap, today's model.

    Returns
    -------
    dict
        Per pressure (in the order given): ``force_N`` (NaN where not converged),
        ``converged``, ``iterations``, ``cutbacks``, ``residual`` (last Newton residual relative
        to the step's first), ``min_tension_N_per_mm`` (braid), ``failure`` (empty when
        converged), ``limit`` (:data:`mkm.fem.outcomes.BRAID_LOCKS` where the braid locks before
        ``eps``: a physical limit, no state of the muscle there, not a solver failure; empty
        elsewhere); per sweep: ``threshold_pressure_bar`` (P*, force zero up to it) and ``dofs``.
    """
    check_parameters(theta0_deg, L0_mm, mesh, braid, gap_mm)
    P_bar = np.atleast_1d(np.asarray(pressure_bar, dtype=float))
    half = HalfMuscle(D0_mm, t0_mm, L0_mm, theta0_deg, material, mesh, sleeve=braid,
                      gap_mm=gap_mm)
    levels = np.unique(P_bar)
    out = {k: np.zeros(levels.size) for k in ("force_N", "iterations", "cutbacks", "residual",
                                              "min_tension_N_per_mm")}
    out["converged"] = np.zeros(levels.size, dtype=bool)
    out["failure"] = np.full(levels.size, "", dtype=object)
    out["limit"] = np.full(levels.size, "", dtype=object)

    # phase 1: free shortening to U* = -eps L0/2 gives the threshold pressure P* (with a gap
    # also at eps = 0: the braid carries nothing until the tube reaches it)
    y, threshold_MPa, report = half.rest_state(), 0.0, None
    if eps > 0 or half.gap_mm:
        y, threshold_MPa, report = half.free_path(-eps * half.H)
        failure = report.reason
        limit = report.limit
        if threshold_MPa < 0:
            failure = (f"the braid passes its locking angle before eps={eps:g}: the free "
                       f"muscle would need {threshold_MPa / BAR_TO_MPA:.3g} bar to shorten so far")
            limit = BRAID_LOCKS
        if failure:
            out["force_N"][:] = np.nan
            out["failure"][:] = f"threshold search failed: {failure}"
            out["limit"][:] = limit
            out["iterations"][:], out["cutbacks"][:] = report.iterations, report.cutbacks
            out["residual"][:] = report.residual
            return _per_point(out, levels, P_bar, np.nan, half.n)
    below = levels * BAR_TO_MPA <= threshold_MPa
    out["converged"][below] = True
    if report is not None:
        out["iterations"][below], out["residual"][below] = report.iterations, report.residual
        out["cutbacks"][below] = report.cutbacks
    # the threshold state's braid is often slack at the clamped cap's corner (zero tension)
    out["min_tension_N_per_mm"][below] = half.tension(y).min()

    # phase 2: cap held at U*, pressure ramped from P* through the levels above it
    above = np.flatnonzero(~below)
    if above.size:
        path = half.held_path(y, threshold_MPa, levels[above] * BAR_TO_MPA)
        for i, (yy, report) in zip(above, path, strict=True):
            out["iterations"][i], out["cutbacks"][i] = report.iterations, report.cutbacks
            out["residual"][i] = report.residual
            failure = report.reason
            force = np.nan
            if yy is not None:
                force = half.cap_force(yy, levels[i] * BAR_TO_MPA)
                failure = half.compression(yy) or _pushing(half, yy, force, levels[i])
                out["min_tension_N_per_mm"][i] = half.tension(yy).min()
            elif report.reached and (mode := half.mesh_mode(np.append(report.reached[-1][1],
                                                                      y[-1]))):
                failure = f"{failure} ({mode})"
            out["converged"][i] = not failure
            out["force_N"][i] = np.nan if failure else force
            out["failure"][i] = failure
    return _per_point(out, levels, P_bar, threshold_MPa / BAR_TO_MPA, half.n)


def _pushing(half: HalfMuscle, y, force_N: float, pressure_bar: float) -> str:
    """Why a held state above P* is not the muscle's (empty if it is): a force below zero by
    more than the solver's error (1e-6 of the cap force at 1 bar; a muscle held above its
    threshold pulls), said with the mesh's zig-zag where that is the cause."""
    if force_N >= -1e-6 * half.force_scale_N:
        return ""
    why = half.mesh_mode(y) or "no state of a muscle held above its threshold pushes its cap"
    return f"negative force ({force_N:.3g} N at {pressure_bar:.4g} bar): {why}"


def _per_point(out, levels, P_bar, threshold_bar, dofs):
    index = np.searchsorted(levels, P_bar)
    result = {k: v[index] for k, v in out.items()}
    result["threshold_pressure_bar"] = np.full(P_bar.size, threshold_bar)
    result["dofs"] = np.full(P_bar.size, dofs)
    return result


class Axisym(CalibratedTheta0, ForceModel):
    """Axisymmetric Taylor-Hood FE model of the whole muscle with isometric lock (``axisym``).

    Parameters
    ----------
    theta0_deg : float, optional
        Braid angle at rest [deg]. Default: the calibrated value in ``fem/calibration.json``.
    L0_mm : float
        Length at rest [mm]; 282 as in the paper.
    mesh : {"coarse", "medium", "fine"}
        Mesh level; how close each is to ``fine``: ``mkm fem convergence``
        (docs/measured/mesh_convergence.csv).
    C10_MPa, C01_MPa : float, optional
        Mooney-Rivlin constants of the wall [MPa]; default Silastic S (C10 = 0.0694 MPa,
        C01 = 0.0628 MPa).
    braid : {"bonded", "sliding"}
        ``bonded`` (default): the fibres are glued to the rubber's outer surface and
        inextensible at every point. ``sliding``: a frictionless sleeve, one uniform fibre
        tension, only the fibres' total length is kept; its theta0 is calibrated on its own
        (calibration key ``axisym-sliding``).
    gap_mm : float, optional
        Radial gap between the tube and the (bonded) braid at rest [mm]: the tube inflates
        freely until it meets the braid, a unilateral contact (:func:`isometric_sweep`).
        Default: the calibration entry's ``gap_mm`` where a muscle was identified with one,
        else 0 (no gap: the model without contact, unchanged).
    calibration : Calibration, optional
        Where the default angle (and an identified rubber) comes from; default the shipped
        ``fem/calibration.json`` (:class:`mkm.fem.calibration.Calibration`).
    """

    name = "axisym"
    has_threshold = True

    def __init__(self, theta0_deg: float | None = None, L0_mm: float = 282.0,
                 mesh: str = "medium", C10_MPa: float | None = None,
                 C01_MPa: float | None = None, braid: str = "bonded",
                 gap_mm: float | None = None, calibration: Calibration | None = None):
        if gap_mm is not None:
            gap_mm = check_gap(gap_mm, braid)
        self.theta0_deg = theta0_deg
        self.calibration = calibration
        self.L0_mm = L0_mm
        self.mesh = mesh
        self.C10_MPa = C10_MPa
        self.C01_MPa = C01_MPa
        self.braid = braid
        self.gap_mm = gap_mm

    @property
    def material(self) -> MooneyRivlin:
        return self._rubber()

    @property
    def calibration_key(self) -> str:
        return "axisym" if self.braid == "bonded" else f"axisym-{self.braid}"

    def params(self):
        params = {"theta0_deg": self._theta0(), "L0_mm": self.L0_mm, "mesh": self.mesh,
                  "C10_MPa": self.material.C10_MPa, "C01_MPa": self.material.C01_MPa}
        if self.braid != "bonded":  # the default stays out: older records keep their keys
            params["braid"] = self.braid
        if gap := self._gap():  # likewise: a gap-free muscle's records and cache keys unchanged
            params["gap_mm"] = gap
        return params

    def _forces(self, P, D0, t0, eps):
        check_sleeve(self.braid)
        theta0 = self._theta0()
        gap = self._gap()
        check_parameters(theta0, self.L0_mm, self.mesh, self.braid, gap)
        geometry = np.stack([D0.ravel(), t0.ravel(), eps.ravel()], axis=1)
        groups, which = np.unique(geometry, axis=0, return_inverse=True)
        which = which.ravel()
        out = {}
        for g, (d, t, e) in enumerate(groups):
            points = np.flatnonzero(which == g)
            sweep = isometric_sweep(P.ravel()[points], d, t, e, theta0, self.L0_mm, self.mesh,
                                    self.material, self.braid, gap)
            for key, values in sweep.items():
                if key not in out:
                    out[key] = np.empty(P.size, dtype=values.dtype)
                out[key][points] = values
        return {k: v.reshape(P.shape) for k, v in out.items()}
