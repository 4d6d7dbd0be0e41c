"""The 95 % prediction band of a force predicted with an identified muscle's calibration.

``mkm fem solve --calibration DIR/calibration.json`` (a file ``mkm identify`` wrote) prints
``band95_N`` beside the force: 1.96 standard deviations of

- the identified parameters' uncertainty: the model's sensitivity to each static parameter
  (braid angle, rubber scale, C01's share where fitted, the wall and diameter where fitted,
  the gap; forward differences of a tenth of a standard deviation) through their bootstrap
  covariance, which already holds the pressure monitor's offset and the load cell's tolerance
  as the runs could not see them;
- the load cell's sensitivity tolerance again, on the predicted force itself (uniform within
  the declared +- tolerance: every force the runs measured, so every force the calibration
  predicts, carries the cell's unknown gain);
- the misfit, where calibration.json records one (``band.misfit_rms_N``: the residual the
  model could not explain).

A fitted wall or diameter enters only as the solve's own ``--t0``/``--D0``: the band assumes
the identified muscle's geometry is what is solved (parameters.csv gives the fitted values).
"""

from __future__ import annotations

import numpy as np

from mkm.identify import fitting

#: the two-sided 95 % normal quantile
Z95 = 1.959964
#: the finite-difference step, in standard deviations of the parameter
STEP_SD = 0.1


def identified_entry(calibration) -> tuple[str, dict] | None:
    """``(key, entry)`` of the identified muscle in ``calibration`` (the entry of the static
    model identify confirmed with), or None."""
    return next(((key, entry) for key, entry in calibration.entries.items()
                 if "identified" in entry), None)


def prediction_band(spec, calibration, force_N, pressure_bar, D0_mm, t0_mm, eps):
    """The 95 % half-width [N] of each force ``force_N`` the model of ``spec`` (a
    :class:`mkm.registry.Spec`) predicted with ``calibration`` at the inputs; None where the
    calibration holds no identified muscle of this model, or the spec overrides the identified
    angle or rubber."""
    found = identified_entry(calibration) if calibration is not None else None
    if found is None or "band" not in found[1]["identified"]:
        return None
    key, entry = found
    if spec.build(calibration).calibration_key != key or {
            "theta0_deg", "C10_MPa", "C01_MPa"} & set(dict(spec.params)):
        return None
    band = entry["identified"]["band"]
    names, covariance = band["parameters"], np.asarray(band["covariance"], dtype=float)
    values = {**fitting.nominal_values(entry["theta0_deg"]),
              **dict(zip(names, band["values"], strict=True))}
    inputs = {"D0_mm": D0_mm, "t0_mm": t0_mm}
    # the force at the band's own (unrounded) values: the differences are taken from it
    base = _force(spec, calibration, values, pressure_bar, D0_mm, t0_mm, eps)
    gradient = []
    for k, name in enumerate(names):
        step = STEP_SD * np.sqrt(max(covariance[k, k], 0.0)) or 1e-6
        moved = {**values, name: values[name] + step}
        geometry = {g: (moved[g] if g in names else inputs[g]) for g in fitting.GEOMETRY}
        force = _force(spec, calibration, moved, pressure_bar, geometry["D0_mm"],
                       geometry["t0_mm"], eps)
        gradient.append((force - base) / step)
    G = np.array(gradient).reshape(len(names), -1)
    variance = np.einsum("in,ij,jn->n", G, covariance, G) if names else np.zeros(base.size)
    tolerance = float(band.get("sensitivity_tolerance", 0.0))
    variance = variance + (tolerance / np.sqrt(3.0) * np.ravel(force_N)) ** 2
    variance = variance + float(band.get("misfit_rms_N", 0.0)) ** 2
    return Z95 * np.sqrt(variance).reshape(np.shape(force_N))


def _force(spec, calibration, values, pressure_bar, D0_mm, t0_mm, eps):
    C10, C01 = fitting.rubber(values)
    gap = {"gap_mm": values["gap_mm"]} if "gap_mm" in values else {}
    model = spec.with_params(theta0_deg=float(values["theta0_deg"]), C10_MPa=C10,
                             C01_MPa=C01, **gap).build(calibration)
    return np.asarray(model.predict(pressure_bar, D0_mm, t0_mm, eps).force_N, dtype=float)
