"""The result of a design run and the Python API (:func:`design`, :func:`run_design`)."""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from mkm.design.box_search import (
    AXIS_RESOLUTION,
    AXIS_VALUES,
    BOX_NAMES,
    COARSE_STEPS,
    D0_STEP_MM,
    FE_SEARCH_STEPS,
    SEEDS,
    T0_STEP_MM,
    Search,
    box_text,
    geometry_text,
    larger_box,
    outside_practical_range,
    pick,
    range_limits,
    search,
)
from mkm.design.fe_verification import (
    BUILT_ANGLE_TOLERANCE_DEG,
    identified_ends_N,
    ordered,
    steeper_braid_N,
    verify,
)
from mkm.design.robust import (
    WORST_CORNER_UNSOLVED,
    below_target,
    check_designs,
    check_probability,
    monte_carlo_record,
)
from mkm.design.spec import (
    CALIBRATED_RUBBER,
    DEFAULT_OBJECTIVE,
    DEFAULT_PROBABILITY,
    DEFAULT_RUBBER,
    DEFAULT_TOP,
    NEAR_LOCK_FRACTION,
    Constraints,
    Hints,
    design_muscle,
    load_spec,
    parse_requirement,
)
from mkm.fem.calibration import Calibration
from mkm.fem.muscle import Muscle
from mkm.fem.options import MESH_LEVELS

# --- the API ------------------------------------------------------------------------------------


@dataclass
class DesignResult:
    """What :func:`run_design` found: the verified designs, their FE curves, the search."""

    designs: pd.DataFrame
    curves: pd.DataFrame
    search: Search
    mesh: str
    fe_seconds: float
    fe_models: dict
    fe_cached: int = 0
    files: dict = field(default_factory=dict)
    #: the probability a robust design is asked to meet every requirement with (None: nominal)
    probability: float | None = None
    #: per requirement, how far [N] the 95 % band of the chosen design's FE force from the
    #: identified muscle's own uncertainty reaches below it, the linearisation the probability
    #: takes (:func:`~mkm.design.fe_verification.identified_ends_N`; None where the calibration
    #: identified none, or a robust design, which carries its own)
    identified_band_N: list = field(default_factory=list)
    #: per requirement, how far [N] that band reaches above the force: the most a muscle of the
    #: identified parameters' 95 % ellipse pulls there, less the force (None as above)
    identified_above_N: list = field(default_factory=list)
    #: the ``--tolerance`` that carries the identified muscle's 95 % intervals ("" without)
    identified_tolerance: str = ""
    #: per requirement, the chosen design's FE force with its braid
    #: :data:`~mkm.design.fe_verification.BUILT_ANGLE_TOLERANCE_DEG` steeper [N], where no
    #: identified muscle's band or ``--tolerance`` says how sure its margin is (else empty)
    steeper_braid_N: list = field(default_factory=list)

    @property
    def chosen(self):
        """The best design the FE confirms (a row), or None."""
        ok = self.designs[self.designs["meets_all"]]
        return ok.iloc[0] if len(ok) else None

    def chosen_muscle(self, calibration: Calibration | None = None) -> Muscle | None:
        """The chosen design as a :class:`~mkm.fem.muscle.Muscle` (at rest, eps 0), ready for
        ``make_model(name, muscle=...)``; None when no design is confirmed. ``calibration``: where
        a ``calibrated`` rubber comes from. A design with a gap between tube and braid records
        it (``gap_mm``), so a model built for the muscle predicts with it."""
        best, gap = self.chosen, self.search.constraints.get("gap_mm")
        return None if best is None else design_muscle(best, calibration, gap_mm=gap)

    def summary(self) -> str:
        s = self.search
        cached = f" ({self.fe_cached} sweeps from the cache)" if self.fe_cached else ""
        ok = int(self.designs["meets_all"].sum())
        finer = self.designs["fe_mesh"] != self.mesh
        again = (f"; the best met a requirement by less than its error, verified again on "
                 f"the {' and '.join(_in_mesh_order(self.designs['fe_mesh'][finer]))} mesh"
                 if finer.any() else "")
        text = "".join(f"{why}; " for why in (s.fe_search, s.searcher_note) if why) + (
                f"{len(s.candidates)} candidate{'' if len(s.candidates) == 1 else 's'} "
                f"searched in {s.seconds:.2f} s, "
                f"{int(s.candidates['feasible'].sum())} feasible by the "
                f"{'FE search' if s.fe_search else s.searcher}; "
                f"{len(self.designs)} verified by the FE (axisym, {self.mesh} mesh{again}) in "
                f"{self.fe_seconds:.1f} s{cached}, {ok} meet{'s' if ok == 1 else ''} every "
                "requirement")
        best = self.chosen
        if best is None:
            return text + ": none confirmed, see the table's FE margins"
        return text + (f"; chosen: {geometry_text(best)}, outer diameter "
                       f"{best['outer_diameter_mm']:.1f} mm at {s.working_pressure_bar:g} bar")

    def notes(self) -> list[str]:
        """What a user must know of the box searched, one line each: the length searched
        where none was given and where from (:attr:`Search.length_note`), the box
        when it is not the surrogate's (:meth:`Search.box_note`), the chosen design on an end of a
        searched range (:meth:`~mkm.design.box_search.Search.edges`), where a larger box might hold
        a better design, and a searching margin of more than :data:`LARGE_MARGIN_SHARE` of a
        required force (the design then is larger than the requirement needs), a chosen
        design outside the practical range or on its limit (:func:`~mkm.design.box_search.
        range_limits`), one that meets a requirement by less than the mesh's error and was
        verified again on a finer one, a robust design below the probability asked (none
        verified holds it), one whose worst corner the FE did not solve, the chosen design's
        forces with the identified muscle's own uncertainty, the probability each holds
        (:meth:`identified_probability`) and the ``--tolerance`` where one is below the
        default probability, the most a muscle of that band pulls (what the load cell and
        the frame must take), and a chosen tube of the identified rubber other than the
        identified muscle's (:func:`_another_tube`), or, where no identified
        muscle says, by less than a braid 1 deg steeper takes away (:attr:`steeper_braid_N`).
        Empty when none."""
        s = self.search
        notes = [n for n in (s.length_note, s.box_note()) if n]
        best = self.chosen
        if best is not None:
            share = max(float(best[f"r{k}_uncertainty_N"]) / r.force_N
                        for k, r in enumerate(s.requirements, start=1))
            if share > LARGE_MARGIN_SHARE:
                notes.append(f"{s.searcher} searched with a margin of up to {100 * share:.0f} "
                             f"% of a required force ({s.uncertainty}): the chosen design pulls "
                             "about that much more than required (its FE margin); a surrogate "
                             "with a predictive std (the default) searches closer")
        if best is not None and (outside := outside_practical_range(best, s.requirements,
                                                                       s.calibration)):
            notes.append(f"the chosen design lies outside the practical range every model is "
                         f"validated over ({'; '.join(outside)}): its FE verification is an "
                         "extrapolation (`mkm models` states the range)")
        if best is not None and (edges := s.edges(best)):
            ranges = {k: v for k, v in s.constraints.items()
                      if k in BOX_NAMES and v[1] > v[0]}
            notes.append(f"the chosen design sits on the edge of the search box "
                         f"{box_text(ranges, s.constraints['D0_mm'][1])}: {', '.join(edges)}; "
                         + larger_box(best, s.constraints, s.calibration, hints=s.hints))
        if best is not None and (limits := range_limits(best, s.constraints)):
            beyond = any(", beyond its " in limit for limit in limits)
            notes.append(f"the chosen design sits on the practical range's limit"
                         f"{' or beyond it' if beyond else ''}: {'; '.join(limits)}; a design "
                         f"{'further out' if beyond else 'beyond it'} might do better, but no "
                         "model is validated there (`mkm models` states the range)")
        if best is not None and "all:probability_below_target" in str(best["flags"]):
            notes.append(f"no verified design holds every requirement with the "
                         f"{100 * self.probability:g} % asked (the chosen one: "
                         f"{100 * best['probability_all']:.1f} % of the Monte Carlo draws): "
                         f"verify more designs ({s.hints.name('top')}) or ask for a wider "
                         "margin")
        unsolved = [] if best is None else [
            flag.split(":")[0] for flag in str(best["flags"]).split(";")
            if flag.endswith(f":{WORST_CORNER_UNSOLVED}")]
        if unsolved:
            notes.append(f"the FE gave no force at the worst corner of the tolerances of the "
                         f"chosen design for {', '.join(unsolved)} ({best['fe_failure']}): "
                         "whether the muscle built to them meets it there is not verified")
        if best is not None and (held := self.identified_probability()):
            notes.append(self._band_note(best, held))
        if best is not None and str(best["rubber"]) == CALIBRATED_RUBBER:
            notes += _another_tube(best, s.calibration)
        short = [(k, force) for k, force in enumerate(self.steeper_braid_N, start=1)
                 if best is not None and force < s.requirements[k - 1].force_N]
        for k, force in short:
            margin = float(best[f"r{k}_fe_margin_N"])
            less = float(best[f"r{k}_fe_N"]) - force
            notes.append(f"the chosen design meets r{k} ({s.requirements[k - 1].label}) by "
                         f"{margin:.3g} N ({float(best[f'r{k}_fe_margin_pct']):.2g} %); a braid "
                         f"{BUILT_ANGLE_TOLERANCE_DEG:g} deg steeper than its "
                         f"{float(best['theta0_deg']):.4g} deg pulls {less:.3g} N "
                         f"({100 * less / float(best[f'r{k}_fe_N']):.2g} %) less there (the FE), "
                         "short of it: the braid angle of the muscle built is not known to that "
                         f"(no identified muscle): design for it (--tolerance theta0="
                         f"{BUILT_ANGLE_TOLERANCE_DEG:g}), or identify the built muscle "
                         "(mkm identify) and check it with its calibration")
        if best is not None and best["fe_mesh"] != self.mesh:
            notes.append(f"the {self.mesh} mesh's margin of the chosen design was within that "
                         f"mesh's error (mkm.mesh_errors): verified again on the "
                         f"{best['fe_mesh']} mesh, where it meets every requirement by "
                         f"{best['min_fe_margin_pct']:.2g} % or more")
        return notes

    def identified_probability(self) -> dict[int, float]:
        """Per requirement ``k`` with an identified band, the probability the chosen design
        meets it (:func:`held_with` of its FE margin and :attr:`identified_band_N`); empty
        without a band or a chosen design."""
        best = self.chosen
        return {} if best is None else {
            k: held_with(float(best[f"r{k}_fe_margin_N"]), band)
            for k, band in enumerate(self.identified_band_N, start=1) if band is not None}

    def identified_range_N(self) -> dict[int, tuple[float, float]]:
        """Per requirement ``k`` with an identified band, the forces [N] its 95 % band spans
        at the chosen design: from the FE force less :attr:`identified_band_N` (no muscle
        pulls less than nothing) to the FE force plus :attr:`identified_above_N`; empty
        without a band or a chosen design."""
        best = self.chosen
        return {} if best is None else {
            k: (max(0.0, float(best[f"r{k}_fe_N"]) - below),
                float(best[f"r{k}_fe_N"]) + self.identified_above_N[k - 1])
            for k, below in enumerate(self.identified_band_N, start=1) if below is not None}

    def _band_note(self, best, held: dict[int, float]) -> str:
        """The forces the chosen design pulls at each requirement within the identified
        muscle's band, its FE force and margin, the probability it holds, the most any
        requirement's band reaches (what the load cell and the frame must take), and what to do
        where one is below :data:`~mkm.design.spec.DEFAULT_PROBABILITY`."""
        target = 100 * DEFAULT_PROBABILITY
        ranges = self.identified_range_N()
        forces = "; ".join(
            f"r{k} ({self.search.requirements[k - 1].label}) pulls {ranges[k][0]:.1f}-"
            f"{ranges[k][1]:.1f} N ({float(best[f'r{k}_fe_N']):.4g} N at the calibration's "
            f"values, met by {float(best[f'r{k}_fe_margin_N']):.3g} N): {_chance(p)}"
            for k, p in held.items())
        most = max(ranges, key=lambda k: ranges[k][1])
        text = (f"the chosen design's forces with the identified muscle's own uncertainty (95 %, "
                f"its intervals carried through the FE model): {forces}; the load cell and the "
                f"frame must take {ranges[most][1]:.1f} N at these requirements (r{most}'s upper "
                "end)")
        short = [f"r{k}" for k, p in held.items() if p < DEFAULT_PROBABILITY]
        if not short:
            return text + f"; every requirement holds with {target:g} % or more"
        ask = (f"--tolerance {self.identified_tolerance} --probability {DEFAULT_PROBABILITY:g}"
               if self.identified_tolerance else "--tolerance")
        return (text + f"; {', '.join(short)} below {target:g} %: design for {target:g} % "
                f"({ask}: the intervals as build tolerances) or require more force")

    def table_text(self) -> str:
        """The verified designs, best first, as a plain text table for the terminal."""
        robust = ["probability_all"] if "probability_all" in self.designs else []
        shown = self.designs[["rank", "D0_mm", "t0_mm", "L0_mm", "theta0_deg", "rubber",
                              "outer_diameter_mm", "min_fe_margin_pct", "fe_mesh", *robust,
                              "meets_all"]]
        shown = shown.rename(columns={"outer_diameter_mm": "outer_mm",
                                      "min_fe_margin_pct": "FE_margin_%",
                                      "meets_all": "meets"})
        return shown.to_string(index=False, float_format=lambda v: f"{v:.4g}")


#: A searching margin above this share of a required force is said (:meth:`DesignResult.notes`)
LARGE_MARGIN_SHARE = 0.5

DESIGN_COLUMNS = ["rank", "D0_mm", "t0_mm", "L0_mm", "theta0_deg", "rubber",
                  "outer_diameter_mm", "rubber_volume_cm3"]


def run_design(requirements=(), constraints=None, objective=None, top=None, spec=None,
               mesh: str = "medium", surrogate: str = "surrogate",
               progress: bool = False, cache_dir=None, tolerances=None,
               probability: float = DEFAULT_PROBABILITY, workers: int | None = None,
               scheduler: str | None = None,
               calibration: Calibration | None = None) -> DesignResult:
    """Search and verify (:func:`mkm.design_page.write_design` writes the files).

    ``tolerances`` (:class:`mkm.fem.tolerances.Tolerances`): robust designs that meet every
    requirement with ``probability`` when built to them (:mod:`mkm.design.robust`).

    ``spec``: a TOML file (:func:`load_spec`); ``requirements`` are added to its requirements,
    ``constraints`` (a dict) override its constraints, ``objective``/``top`` its own.
    ``cache_dir``: FE prediction cache (None: solve every sweep). ``workers``/``scheduler``:
    where the FE sweeps run (:func:`mkm.design.fe_verification.verify`). ``calibration``: the
    default braid angle's and the ``calibrated`` rubber's (None: the shipped one).
    """
    base = load_spec(spec) if spec else {"requirements": [], "constraints": {}}
    requirements = list(base["requirements"]) + [
        parse_requirement(r) if isinstance(r, str) else r for r in requirements]
    merged = dict(base["constraints"])
    if isinstance(constraints, Constraints):
        flagged = {k: v for k, v in asdict(constraints).items()
                   if v is not None and not (k == "rubber" and v == (DEFAULT_RUBBER,))}
    else:
        flagged = {k: v for k, v in (constraints or {}).items() if v is not None}
    merged.update(flagged)
    # every hint in the form the user set the option in: the spec's key or the flag
    hints = Hints(Path(spec).name if spec else "",
                  frozenset(flagged) | ({"top"} if top is not None else set()),
                  frozenset(merged))
    objective = objective or base.get("objective", DEFAULT_OBJECTIVE)
    top = top if top is not None else base.get("top", DEFAULT_TOP)
    if isinstance(top, bool) or not isinstance(top, int) or top < 1:
        raise ValueError(f"top={top!r} is invalid: expected a whole number of designs >= 1")
    if tolerances is not None:
        probability = check_probability(probability)
        if merged.get("gap_mm"):
            raise ValueError(f"gap_mm={merged['gap_mm']} with --tolerance: a robust design "
                             "with a gap between tube and braid is not modelled (its Monte "
                             "Carlo runs on the surrogate, which has no gap)")
    if calibration is not None and "axisym" not in calibration.entries:
        # the search's defaults and the verification read the FE model's entry: refused before
        raise ValueError(f"--calibration {calibration.path} has no entry of the FE model "
                         "(axisym), whose angle and rubber mkm design searches and verifies "
                         f"with: {calibration.how_to_add('axisym', angle=None)}")
    found = search(requirements, merged, objective, surrogate, tolerances, probability,
                   calibration, hints)
    chosen = pick(found.feasible, top, found.constraints)
    chosen.insert(0, "rank", np.arange(1, len(chosen) + 1))
    demoted: frozenset = frozenset()
    if tolerances is not None:  # the probability first: the chosen design's verdict must hold it
        demoted = below_target(chosen, found.requirements, found.models, tolerances,
                               probability)
    designs, curves, seconds, fe_models, hits = verify(
        chosen, found.requirements, mesh, found.working_pressure_bar, progress, cache_dir,
        workers, scheduler, calibration, found.gap_mm, objective, demoted)
    robust: list[str] = []
    if tolerances is not None:
        designs = check_designs(designs, found.requirements, found.models, tolerances,
                                probability, mesh, cache_dir)
        robust = [c for k in range(1, len(found.requirements) + 1) for c in (
            f"probability_r{k}", f"probability_r{k}_search", f"r{k}_tolerance_u_N",
            f"r{k}_fe_worst_corner_N")] + ["probability_all"]
    designs = ordered(designs, objective, demoted)
    ok = designs[designs["meets_all"]]
    ends = ([] if tolerances is not None or ok.empty else
            identified_ends_N(ok.iloc[0], found.requirements, calibration, found.gap_mm,
                              cache_dir))
    band = [None if e is None else e[0] for e in ends]
    # how sure a nominal margin is where no identification says: the braid angle built
    steeper = ([] if tolerances is not None or ok.empty or any(b is not None for b in band)
               else steeper_braid_N(ok.iloc[0], found.requirements, calibration,
                                    found.gap_mm, cache_dir))
    n = len(found.requirements)
    columns = DESIGN_COLUMNS + [c for k in range(1, n + 1) for c in (
        f"r{k}_surrogate_N", f"r{k}_uncertainty_N", f"r{k}_fe_N", f"r{k}_fe_margin_N",
        f"r{k}_fe_margin_pct", f"r{k}_threshold_bar", f"r{k}_meets")] + robust + [
        "meets_all", "min_fe_margin_pct", "fe_mesh", "flags", "fe_failure"]
    result = DesignResult(designs[columns], curves, found, mesh, seconds, fe_models, hits,
                          probability=None if tolerances is None else probability,
                          identified_band_N=band,
                          identified_above_N=[None if e is None else e[1] for e in ends],
                          identified_tolerance=identified_tolerance(calibration),
                          steeper_braid_N=steeper)
    # the band's ends, solved for the chosen design alone: the other designs' are empty
    table = result.designs
    for k, span in result.identified_range_N().items():
        for column, value in zip((f"r{k}_fe_low95_N", f"r{k}_fe_high95_N"), span, strict=True):
            table.insert(table.columns.get_loc(f"r{k}_fe_margin_N"), column,
                         np.where(table.index == result.chosen.name, value, np.nan))
    return result


def design(requirements, constraints=None, objective: str = DEFAULT_OBJECTIVE, *,
           top: int = DEFAULT_TOP, mesh: str = "medium", surrogate: str = "surrogate",
           progress: bool = False, cache_dir=None,
           calibration: Calibration | None = None) -> pd.DataFrame:
    """Verified designs for force requirements, best first: the Python API of ``mkm design``.

    Parameters
    ----------
    requirements : list of Requirement or str
        Operating points, ``Requirement(force_N, pressure_bar, eps)`` or ``"400N@2bar,eps=0.10"``.
    constraints : Constraints or dict, optional
        Ranges or fixed values of ``D0_mm``, ``t0_mm``, ``L0_mm``, ``theta0_deg``; ``rubber``;
        ``max_outer_diameter_mm``, ``max_pressure_bar`` (see :class:`Constraints`).
    objective : {"min-outer-diameter", "min-rubber-volume", "max-margin"}
    top : int
        Designs verified with the FE model.
    mesh : {"coarse", "medium", "fine"}
        FE mesh; ``medium`` is the converged one (``coarse`` for quick checks only).
    surrogate : str
        Registry spec of the surrogate that searches the box.
    progress : bool
        Progress bar of the FE verification on stderr (when it is a terminal).
    cache_dir : path, optional
        FE prediction cache (:mod:`mkm.prediction_cache`); None solves every sweep.
    calibration : Calibration, optional
        The default braid angle's and the ``calibrated`` rubber's (None: the shipped
        ``fem/calibration.json``).

    Returns
    -------
    pandas.DataFrame
        One row per verified design: geometry, outer diameter at the working pressure [mm],
        rubber volume [cm^3], per requirement ``k`` the surrogate's force and uncertainty and the
        FE force, margin [N, %], threshold pressure [bar] and verdict ``r<k>_meets``;
        ``meets_all`` (the FE's verdict), ``flags``; with an identified muscle's
        ``calibration``, the chosen design's 95 % band at each requirement,
        ``r<k>_fe_low95_N`` to ``r<k>_fe_high95_N``. Sorted: designs the FE confirms first, in
        objective order. ``attrs`` holds the requirements, constraints and search summary.
    """
    result = run_design(requirements, constraints, objective, top, mesh=mesh,
                        surrogate=surrogate, progress=progress, cache_dir=cache_dir,
                        calibration=calibration)
    frame = result.designs.copy()
    frame.attrs.update(design_record(result))
    return frame


def held_with(margin_N: float, band_N: float) -> float:
    """The probability that a force ``margin_N`` above its requirement at the calibration's
    values still meets it, its error normal with the 95 % half-width ``band_N``."""
    from scipy import stats

    from mkm.identify.band import Z95

    if band_N <= 0.0:
        return 1.0 if margin_N >= 0.0 else 0.0
    return float(stats.norm.cdf(margin_N * Z95 / band_N))


def _chance(probability: float) -> str:
    """``holds with about 60 %``; ``over 99.9 %`` where rounding would say 100."""
    if probability >= 0.999:
        return "holds with over 99.9 %"
    return f"holds with about {100 * probability:.{0 if probability < 0.99 else 1}f} %"


def identified_tolerance(calibration: Calibration | None) -> str:
    """``--tolerance`` text of the identified muscle's 95 % intervals of its braid angle and
    rubber as identify printed them (``parameters``: the bootstrap's, widened by a misfit's
    Birge ratio and by each model-form term's shift, such as a creep the runs could not fit),
    the larger side of each (a build tolerance holds both); where they are not recorded, 1.96
    standard deviations of the calibration's band, whose covariance identify widened by the
    misfit as it widened the intervals. Uniform tolerances of that half-width are a little
    wider than the intervals' normal spread. "" without an identified muscle."""
    from mkm.identify.band import Z95, identified_entry

    found = identified_entry(calibration) if calibration is not None else None
    band = found[1]["identified"].get("band") if found is not None else None
    if not band:
        return ""
    names, values = band["parameters"], band["values"]
    sd = np.sqrt(np.clip(np.diag(np.asarray(band["covariance"], dtype=float)), 0.0, None))
    half = dict(zip(names, Z95 * sd, strict=True))
    for row in found[1]["identified"].get("parameters") or ():
        low, high = row.get("ci_low"), row.get("ci_high")
        if row.get("parameter") in half and low is not None and high is not None \
                and np.isfinite([low, high]).all():
            half[row["parameter"]] = max(row["value"] - low, high - row["value"])
    parts = []
    if "theta0_deg" in half:
        parts.append(f"theta0={half['theta0_deg']:.2g}")
    if "rubber_scale" in half:
        scale = values[names.index("rubber_scale")]
        parts.append(f"rubber={100 * half['rubber_scale'] / scale:.2g}%")
    return ",".join(parts)


#: A chosen tube further than this share from the identified one in D0 or t0 is another tube
#: (:func:`_another_tube`): the declared diameter's +-0.3 mm is 1.5 % of a 20 mm tube
ANOTHER_TUBE_SHARE = 0.02


def _another_tube(best, calibration: Calibration | None) -> list[str]:
    """The note of a chosen design of the identified rubber whose tube is not the identified
    muscle's (:func:`mkm.identify.band.identified_tube`): its band, or a robust design's
    probability, carries the identified parameters' uncertainty, not whether the rubber and
    braid fitted to one tube hold for another (the rubber identified may be an effective one:
    the Festo DMSP-20-300's membrane, fibres embedded, fits 4.6 x Silastic S); empty for the
    identified tube or a calibration that records none."""
    from mkm.identify.band import identified_tube

    tube = identified_tube(calibration)
    chosen = (float(best["D0_mm"]), float(best["t0_mm"]))
    if tube is None or np.allclose(chosen, tube, rtol=ANOTHER_TUBE_SHARE, atol=0.0):
        return []
    return [f"the chosen tube, {chosen[0]:.4g} x {chosen[1]:.4g} mm (D0 x t0), is not the "
            f"identified muscle's, {tube[0]:.4g} x {tube[1]:.4g} mm: its forces and the "
            "identified uncertainty stated take that muscle's rubber (and braid angle) to it, "
            "not whether they hold for another tube (a rubber fitted to one wall may be an "
            "effective one): build the chosen design, identify it (mkm identify) and check its "
            "margin with its own calibration"]


def _in_mesh_order(meshes) -> list[str]:
    """The distinct ``meshes``, coarsest first."""
    return sorted(set(meshes), key=list(MESH_LEVELS).index)


def _resolution(s) -> dict:
    """The steps the search of ``s`` tried: the FE search's grid of D0 x t0 has no fine one
    (the fine steps and seeds None)."""
    coarse, fine = (FE_SEARCH_STEPS, False) if s.fe_search else (COARSE_STEPS, True)
    return {"coarse_D0_mm": coarse[0], "coarse_t0_mm": coarse[1],
            "D0_mm": D0_STEP_MM if fine else None, "t0_mm": T0_STEP_MM if fine else None,
            "refined_seeds": SEEDS if fine else None,
            "L0_mm and theta0_deg values per range": AXIS_VALUES,
            "L0_mm and theta0_deg refined to": AXIS_RESOLUTION}


def design_record(result: DesignResult) -> dict:
    """What ``designs.json`` records besides provenance (also the ``attrs`` of :func:`design`)."""
    s = result.search
    ranges = result.identified_range_N()
    return {"requirements": [asdict(r) | {"label": f"r{k}: {r.label}"}
                             for k, r in enumerate(s.requirements, start=1)],
            "constraints": s.constraints, "objective": s.objective,
            "working_pressure_bar": s.working_pressure_bar,
            "surrogate_uncertainty": s.uncertainty,
            # the robust designs' probabilities are random draws: how many, from which seed
            "monte_carlo": (monte_carlo_record() if "probability_all" in result.designs
                            else None),
            "search": {"candidates": len(s.candidates),
                       "feasible": int(s.candidates["feasible"].sum()),
                       "searcher": (f"FE ({s.fe_search})" if s.fe_search else s.searcher),
                       "searcher_note": s.searcher_note,
                       "box": s.box, "surrogate_box": s.surrogate_box,
                       # "" when the box searched is the surrogate's
                       "box_note": s.box_note(),
                       "seconds": s.seconds,
                       "resolution": _resolution(s)},
            # the mesh asked for; a design met within its error has the finer one's forces
            "verification": {"model": "axisym", "mesh": result.mesh,
                             "meshes": _in_mesh_order(result.designs["fe_mesh"]),
                             "seconds": result.fe_seconds,
                             "sweeps_from_cache": result.fe_cached,
                             "near_lock_fraction_of_eps_max": NEAR_LOCK_FRACTION},
            # the searched ranges the chosen design sits on an end of (a larger box might
            # hold a better one); empty when none or nothing is confirmed
            "chosen_on_box_edge": ([] if result.chosen is None
                                   else s.edges(result.chosen)),
            # the lines the command prints besides its summary (the box, the edge)
            "notes": result.notes(),
            # per requirement, how far the chosen design's 95 % band reaches below and above
            # its FE force, and the forces it spans (null: none)
            "identified_band_N": result.identified_band_N,
            "identified_band_above_N": result.identified_above_N,
            "identified_range_N": [list(ranges[k]) if k in ranges else None for k in
                                   range(1, len(result.identified_band_N) + 1)],
            # per requirement, the chance the chosen design meets it by that band (null: none)
            "identified_probability": [result.identified_probability().get(k) for k in
                                       range(1, len(result.identified_band_N) + 1)],
            "steeper_braid_N": result.steeper_braid_N,
            # the chosen design as the muscle every other command reads (null: none confirmed)
            "chosen_muscle": chosen.record() if (chosen := result.chosen_muscle(
                s.calibration)) else None,
            "summary": result.summary()}
