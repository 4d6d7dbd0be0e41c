"""The reference work's constants: its Equation 7, its test muscles, its data and Table 1's grid.

M. G. Antonelli, P. Beomonte Zobel, M. A. Sarwar, N. Stampone, "Mechanical Design of McKibben
Muscles Predicting Developed Force by Artificial Neural Networks", Actuators 2025, 14(3), 153,
doi:10.3390/act14030153. Every number of the paper the project uses is read from here.
"""

from __future__ import annotations

import numpy as np

from mkm.core.records import package_file

CITATION = ("Antonelli, Beomonte Zobel, Sarwar, Stampone, Actuators 2025, 14(3), 153, "
            "doi:10.3390/act14030153")

#: The paper's test muscles (section 3.3): name -> (D0_mm, t0_mm, eps); L0 282 mm.
TEST_MUSCLES = {
    "I": (35.0, 2.5, 0.05),
    "II": (40.0, 3.0, 0.15),
    "III": (45.0, 3.5, 0.20),
}
#: The pressures of the paper's test sweep [bar]: 0 to 2.5 in steps of 0.25 (11 per muscle).
TEST_PRESSURES_BAR = np.round(np.arange(0.0, 2.5 + 1e-9, 0.25), 2)
#: Rest length of every FE run of the paper [mm].
L0_MM = 282.0
#: The bench prototype (section 3.4): D0 30 mm, t0 3 mm, tested at eps 0 and 12.2 %.
PROTOTYPE = {"D0_mm": 30.0, "t0_mm": 3.0, "eps": (0.0, 0.122)}

#: The paper's FE forces of muscle I (section 3.3), CSV.
CASE_I_CSV = package_file("mkm.fem", "data", "paper_case_I.csv")
#: Table 2 (train and validation RMSE of the 27 nets), CSV.
TABLE2_CSV = package_file("mkm.fem", "data", "paper_table2.csv")
#: Table 3 (largest |Err%| of the best net on muscles I-III), CSV.
TABLE3_CSV = package_file("mkm.fem", "data", "paper_table3.csv")
#: Table 1: the dataset's grid (6 pressures x 3 D0 x 3 t0 x 3 eps = 162 points), TOML.
TABLE1_GRID = package_file("mkm.fem", "dataset", "grids", "paper.toml")


def equation7_err_pct(force_reference_N, force_N, scale_N=None) -> np.ndarray:
    """The paper's Equation 7, in %: ``(F_ref - F) / max(F_ref)``.

    Parameters
    ----------
    force_reference_N : array_like
        Reference forces of one sweep [N] (the FE's, or the bench's measurement).
    force_N : array_like
        Predicted forces at the same points [N]; NaN stays NaN (a point without a prediction has
        no error, it is never counted as 0 %).
    scale_N : float, optional
        The normaliser [N]; default the largest finite reference force of the sweep.

    Raises ``ValueError`` when the normaliser is not a positive finite force: a sweep without
    force cannot normalise Equation 7.
    """
    reference = np.asarray(force_reference_N, dtype=float)
    if scale_N is None:
        finite = reference[np.isfinite(reference)]
        scale_N = float(finite.max()) if finite.size else np.nan
    if not np.isfinite(scale_N) or scale_N <= 0:
        raise ValueError(f"max reference force {scale_N!r} N is invalid: expected > 0 N "
                         "(a sweep without force cannot normalise Equation 7)")
    return 100.0 * (reference - np.asarray(force_N, dtype=float)) / scale_N
