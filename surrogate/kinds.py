"""The registry of surrogate kinds: every kind the project trains, declared once.

A :class:`Kind` carries its factory, a label and a description (``mkm models``, the CLI), whether
the study scores it by default, and what its model files need: the types skops must trust to
load them (beyond scikit-learn's estimators and numpy arrays, which skops trusts itself) and the
project modules whose code a loaded estimator runs (the model's code version). A factory is
named ``"module:function"`` and imported when a kind is built: this module imports nothing but
the standard library, so the registry and the CLI can list the kinds without loading
scikit-learn. A kind's parameters are its factory's keyword arguments beyond ``inputs``,
``fixed`` and ``random_state``, declared once in its signature next to the estimator, whose
``_parameter_constraints`` check their values at fit. A family (the paper's nets) is one entry
whose ``members`` name each of its kinds with the factory's arguments.

``best`` names :data:`BEST`, the kind chosen by the numbers (muscle-held-out and off-grid errors,
see the README's surrogate section). :data:`KINDS` is a :class:`mkm.core.registry.Registry`:
:func:`register` adds a kind (a plugin's, a test's), :func:`unregister` removes it,
:func:`entry` finds the entry that builds a kind and :func:`names` lists them.
"""

from __future__ import annotations

import importlib
import inspect
from collections.abc import Callable
from dataclasses import dataclass

from mkm.core.registry import Registry

BEST = "muscle-gp"
#: The kind auto takes as the reference where :data:`BEST`'s box does not cover a call.
RANGE = "muscle-gp-range"
#: The muscle ranges a design or a benchmark draws from, by name, and the kind each trains.
RANGES = {"box": BEST, "practical": RANGE}
CALL_INPUTS = ("pressure_bar", "D0_mm", "t0_mm", "eps")
#: Arguments every factory may take; the others are the kind's parameters.
COMMON_ARGUMENTS = ("inputs", "fixed", "random_state")
#: The modules of every surrogate: the physics features and the force model around it.
BASE_MODULES = ("mkm.surrogate.features", "mkm.surrogate.model")
KERNEL_TYPES = tuple(f"sklearn.gaussian_process.kernels.{name}" for name in
                     ("ConstantKernel", "Matern", "Product", "Sum", "WhiteKernel"))
FEATURES_TYPE = "mkm.surrogate.features.physics_features"


def _resolve(target):
    """A callable, or the object ``"module:attribute"`` names (imported now)."""
    if callable(target):
        return target
    module, _, attribute = target.partition(":")
    return getattr(importlib.import_module(module), attribute)


@dataclass(frozen=True)
class Kind:
    """A surrogate kind (see the module docstring).

    Parameters
    ----------
    name : str
        The kind's name (``--kind``, ``surrogate:kind=``); for a family, its pattern.
    factory : str or callable
        ``"module:function"`` or the callable that returns a fresh, unfitted estimator; it may
        take ``inputs`` (column names of ``X``), ``fixed`` (values of the muscle parameters
        that are not columns) and ``random_state``.
    label : str
        Short name in tables and figures.
    description : str
        One line: what the kind is.
    study_default : bool, default False
        Scored by ``mkm study`` unless other kinds are asked for.
    trusted_types : tuple of str
        Types its model files hold beyond those skops trusts itself.
    modules : tuple of str
        Project modules whose code a loaded estimator of the kind runs.
    members : str or callable, optional
        A family's ``() -> {name: factory arguments}``; None for a single kind.
    predictor : str or callable, optional
        A class whose ``from_arrays(arrays, inputs, fixed)`` predicts from the arrays of the
        fitted estimator's ``predictor().arrays()`` without scikit-learn; saved beside the
        estimator, it makes loading fast. None: the estimator file is loaded.
    dataset : str, optional
        The FE dataset it trains on when none is given: a file of ``mkm.surrogate``'s data
        folder. None: the default design (:data:`mkm.surrogate.training_data.DEFAULT_DATASET`).
    std_sets : (str, str), optional
        The random muscles that calibrate its std and the held-out ones that rescale it
        (files of the same folder). None: the default surrogate's.
    splits : int, optional
        Muscle-held-out refits whose errors a training records (None: the default number);
        a kind that takes minutes to fit records fewer, so its first use stays short.
    """

    name: str
    factory: str | Callable
    label: str
    description: str
    study_default: bool = False
    trusted_types: tuple[str, ...] = ()
    modules: tuple[str, ...] = ()
    members: str | Callable | None = None
    predictor: str | Callable | None = None
    dataset: str | None = None
    std_sets: tuple[str, str] | None = None
    splits: int | None = None

    def names(self) -> list[str]:
        """The kind names this entry builds: its own, or every member of the family."""
        return [self.name] if self.members is None else list(_resolve(self.members)())

    def parameters(self) -> tuple[str, ...]:
        """The factory's keyword parameters beyond :data:`COMMON_ARGUMENTS` (a family's
        members fix theirs)."""
        signature = inspect.signature(_resolve(self.factory))
        return tuple(p for p in signature.parameters if p not in COMMON_ARGUMENTS)

    def build(self, inputs=CALL_INPUTS, fixed=None, random_state: int = 0, **arguments):
        """A fresh, unfitted estimator (``arguments``: the kind's parameters)."""
        factory = _resolve(self.factory)
        accepted = inspect.signature(factory).parameters
        common = {"inputs": tuple(inputs), "fixed": dict(fixed or {}),
                  "random_state": random_state}
        return factory(**{k: v for k, v in common.items() if k in accepted}, **arguments)


KINDS: Registry[Kind] = Registry("surrogate kind")


def register(kind: Kind) -> Kind:
    """Add ``kind``; ``ValueError`` if its name is taken (``best`` is)."""
    if kind.name == "best":
        raise ValueError("surrogate kind 'best' is already registered: expected a new name")
    return KINDS.register(kind)


def unregister(name: str) -> None:
    """Remove the kind ``name``; ``ValueError`` if it is not registered."""
    KINDS.unregister(name)


def registered() -> tuple[Kind, ...]:
    """Every registered entry, in registration order."""
    return KINDS.entries()


def named(name: str) -> str:
    """The kind ``name`` stands for: :data:`BEST` for ``best``, else itself."""
    return BEST if name == "best" else name


def _find(name: str) -> tuple[Kind, dict]:
    """The entry that builds kind ``name`` (``best``: :data:`BEST`) and the factory arguments
    it fixes; a one-line ``ValueError`` naming the known kinds if none does."""
    name = named(name)
    if name in KINDS and KINDS.entry(name).members is None:
        return KINDS.entry(name), {}
    near = ""
    for kind in KINDS.entries():
        if kind.members is not None:
            members = _resolve(kind.members)()
            if name in members:
                return kind, dict(members[name])
            if name.startswith(kind.name.partition("<")[0]):  # a family's pattern, other values
                near = f" ({kind.label}: {_member_values(members)}; e.g. {next(iter(members))})"
    raise ValueError(f"unknown surrogate kind {name!r}{near}: expected {describe()}")


def _member_values(members: dict[str, dict]) -> str:
    """The values a family's members take, per argument: ``layers 1, 2 or 3, size 25, 50 or
    100, ...`` (a pattern such as ``net-<layers>x<size>`` does not say which)."""
    parts = []
    for key in next(iter(members.values())):
        values = list(dict.fromkeys(str(m[key]).lower() for m in members.values()))
        parts.append(f"{key} " + (", ".join(values[:-1]) + " or " + values[-1]
                                  if len(values) > 1 else values[0]))
    return ", ".join(parts)


def entry(name: str) -> Kind:
    """The entry that builds kind ``name``: its own, its family's (a paper net), or
    :data:`BEST`'s for ``best``; a one-line ``ValueError`` naming the known kinds otherwise."""
    return _find(name)[0]


def names(include_families: bool = True) -> list[str]:
    """Every kind name: the single kinds, then (``include_families``) each family's members."""
    singles = list(KINDS.names(lambda k: k.members is None))
    if not include_families:
        return singles
    return singles + [n for k in KINDS.entries() if k.members is not None for n in k.names()]


def make_estimator(kind: str, inputs=CALL_INPUTS, fixed=None, random_state: int = 0,
                   **parameters):
    """A fresh, unfitted estimator of ``kind`` on ``X`` of columns ``inputs``, with ``fixed``
    the values of the muscle parameters that are not; ``parameters``: the kind's own (see
    :meth:`Kind.parameters`), a one-line ``ValueError`` for any other."""
    found, arguments = _find(kind)
    allowed = [p for p in found.parameters() if p not in arguments]  # a member fixes its own
    unknown = sorted(set(parameters) - set(allowed))
    if unknown:
        raise ValueError(f"surrogate kind {kind!r} takes no parameter {', '.join(unknown)}: "
                         f"expected some of {', '.join(allowed) or 'none'}")
    return found.build(inputs, fixed, random_state, **arguments, **parameters)


def describe() -> str:
    """The kinds in one line, for help texts: ``best (muscle-gp), muscle-gp, physics, ... or
    net-<layers>x<size>-...``."""
    listed = [k.name for k in registered()]
    return f"best ({BEST}), " + ", ".join(listed[:-1]) + f" or {listed[-1]}"


def describe_each() -> list[str]:
    """One line per registered entry: name, label, description (and the study default)."""
    return [f"{k.name}: {k.label}, {k.description}" + (" (scored by `mkm study`)"
                                                         if k.study_default else "")
            for k in registered()]


def study_default() -> tuple[str, ...]:
    """The kinds ``mkm study`` scores unless asked for others."""
    return tuple(n for k in registered() if k.study_default for n in k.names())


def trusted_types(kind: str) -> tuple[str, ...]:
    """The types a model file of ``kind`` may hold beyond those skops trusts itself."""
    return entry(kind).trusted_types


def predictor_class(kind: str):
    """The class that predicts ``kind`` from its saved arrays, or None (see :class:`Kind`)."""
    found = entry(kind)
    return None if found.predictor is None else _resolve(found.predictor)


def model_modules(kind: str) -> tuple[str, ...]:
    """The project modules whose code a loaded estimator of ``kind`` runs."""
    return (*BASE_MODULES, *entry(kind).modules)


for _kind in (
    Kind("muscle-gp", "mkm.surrogate.muscle_gp:MuscleThresholdGP", "muscle GP",
         "per muscle F = A max(0, P - P*), slope and threshold of the thick-wall closed form "
         "at shortenings two Gaussian processes learn over the muscle parameters; non-negative "
         "and monotone in pressure, with a calibrated predictive std",
         study_default=True,
         trusted_types=("mkm.surrogate.muscle_gp.MuscleThresholdGP", *KERNEL_TYPES),
         modules=("mkm.surrogate.muscle_gp",),
         predictor="mkm.surrogate.muscle_predictor:MusclePredictor"),
    Kind("muscle-gp-range", "mkm.surrogate.range_gp:RangeThresholdGP", "muscle GP (range)",
         "the muscle GP over the practical range (D0 5-60 mm, P 0-8 bar, rubber C10 "
         "0.03-0.6 MPa), its processes on log-scaled sizes and rubber; auto's reference "
         "outside the default surrogate's box",
         trusted_types=("mkm.surrogate.range_gp.RangeThresholdGP", *KERNEL_TYPES),
         modules=("mkm.surrogate.muscle_gp", "mkm.surrogate.range_gp"),
         predictor="mkm.surrogate.range_gp:RangePredictor",
         dataset="mkm_range_design.csv",
         std_sets=("mkm_range_std_calibration.csv", "mkm_range_std_holdout.csv"), splits=0),
    Kind("physics", "mkm.surrogate.feature_models:physics_model", "physics ridge",
         "F = A max(0, P - P*) with the closed form's slope and threshold corrected by "
         "ridge-penalised polynomials of the geometry (no std)",
         study_default=True,
         trusted_types=("mkm.surrogate.threshold_linear.ThresholdLinearRegressor",
                        FEATURES_TYPE),
         modules=("mkm.surrogate.feature_models",)),
    Kind("gp", "mkm.surrogate.feature_models:gp_model", "GP",
         "Gaussian process (Matern 5/2, one length scale per input, noise) on physics "
         "features, row by row, with a predictive std",
         trusted_types=(FEATURES_TYPE, *KERNEL_TYPES),
         modules=("mkm.surrogate.feature_models",)),
    Kind("mlp-paper", "mkm.surrogate.paper_nets:mlp_paper", "paper net (3 x 100 ReLU)",
         "the paper's best net (3 x 100 ReLU) trained as MATLAB's fitrnet",
         study_default=True, modules=("mkm.surrogate.paper_nets",)),
    Kind("net-<layers>x<size>-<relu|tanh|sigmoid>[-standardised]",
         "mkm.surrogate.paper_nets:paper_net", "paper net",
         "the 27 nets of the paper's Table 2, the force in N as fitrnet or standardised",
         modules=("mkm.surrogate.paper_nets",),
         members="mkm.surrogate.paper_nets:net_kinds"),
):
    register(_kind)
