"""The choices of a fit, each declared once: the ``--params`` groups (read by
:mod:`mkm.identify.fitting`) and the ``--search`` methods (read by
:mod:`mkm.identify.procedure`); ``mkm identify``'s parser reads them here without loading a
fitting library."""

#: ``--params`` groups and the fitted parameters each holds (internal names)
GROUPS = {"theta0": ("theta0_deg",), "rubber": ("rubber_scale",), "t0": ("t0_mm",),
          "D0": ("D0_mm",), "friction": ("hysteresis_fraction",),
          "creep": ("creep_fraction", "log_tau"), "gap": ("gap_mm",),
          "offset": ("pressure_offset_bar", "pressure_hysteresis_bar"), "L0": ("L0_mm",),
          "zero": ("force_zero_N",)}
#: what ``--params`` fits when not given: the wall, the diameter, a gap, the rest length and
#: the load cell's zero only when asked
DEFAULT_GROUPS = ("theta0", "rubber", "friction", "creep", "offset")
#: what searches the optimum: the surrogate (the FE model where its box ends) or --model itself
SEARCHES = ("surrogate", "model")
