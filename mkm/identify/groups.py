"""The ``--params`` groups of a fit: the one registry, read by :mod:`mkm.identify.fitting` and by
``mkm identify --help`` (which loads no fitting library for it)."""

#: ``--params`` groups and the fitted parameters each holds (internal names)
GROUPS = {"theta0": ("theta0_deg",), "rubber": ("rubber_scale",), "t0": ("t0_mm",),
          "D0": ("D0_mm",), "friction": ("hysteresis_fraction",),
          "creep": ("creep_fraction", "log_tau"), "gap": ("gap_mm",),
          "offset": ("pressure_offset_bar",), "L0": ("L0_mm",)}
#: what ``--params`` fits when not given: the wall, the diameter and a gap only when asked
DEFAULT_GROUPS = ("theta0", "rubber", "friction", "creep", "offset")
