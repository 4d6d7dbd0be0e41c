"""The physics models' discrete choices: the FE model's mesh levels and braids.

Read without scikit-fem: the registry (:mod:`mkm.fem.ladder`), and through it every command's
choices, derive from these.
"""

#: level: (elements through the wall, elements along the half length, largest/smallest axial
#: size of the graded mesh)
MESH_LEVELS: dict[str, tuple[int, int, float]] = {
    "coarse": (2, 16, 8.0),
    "medium": (3, 32, 8.0),
    "fine": (6, 96, 8.0),
}

#: How the braid meets the rubber: ``bonded`` (fibres glued to the outer surface point by point,
#: inextensible everywhere) or ``sliding`` (a frictionless sleeve: one uniform fibre tension and
#: the sleeve's total length kept, see :func:`mkm.fem.fe.forms.sliding_sleeve_length`)
BRAIDS = ("bonded", "sliding")
