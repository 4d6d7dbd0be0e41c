"""Calibrate the braid angle from a bench run

The lab loop: record a run, fit the model's braid angle theta0 to it, predict other muscles with
the fitted angle. Here the run comes from the simulated bench (the paper's prototype, D0 30 mm,
t0 3 mm, held at eps 12.2 %), whose muscle is the FE model at a known theta0 with braid friction,
creep and load-cell noise added. A good fit must find that angle again.

Braid friction lowers the rising branch and raises the falling one by about the same amount, so
`check_reference` averages the two branches at every pressure measured both ways (and drops the
staircase's turning point, measured rising only). The command line does the same:

    mkm fem calibrate --model axisym --reference RUN_DIR --out lab.json
"""

import tempfile

import numpy as np

from mkm.bench import acquire, load_config, load_run
from mkm.fem import Axisym
from mkm.fem.calibration import check_reference, fit_theta0, line_above_threshold

with tempfile.TemporaryDirectory() as tmp:
    result = acquire(load_config(eps=0.122), backend="sim", clock="virtual", out_root=tmp,
                     progress=False)
    run = load_run(result.path)

physics = run.meta.hardware["sim"]["physics"]
true_theta0 = physics["force_model_params"]["theta0_deg"]
mesh = physics["force_model_params"]["mesh"]
print(f"simulated muscle: {physics['summary']}; theta0 {true_theta0} deg")

muscle = run.meta.muscle
steps = run.steps[run.steps["settled"]]
reference = check_reference(steps.assign(
    pressure_bar=steps["pressure_bar_mean"], force_N=steps["force_N_mean"],
    D0_mm=muscle.D0_mm, t0_mm=muscle.t0_mm, eps=muscle.eps), f"run {run.path.name}")
print(reference.round(3).to_string(index=False))



def model(theta0_deg):
    return Axisym(theta0_deg=theta0_deg, L0_mm=muscle.L0_mm, mesh=mesh)


fit = fit_theta0(model, reference)
print(f"fitted theta0 {fit['theta0_deg']:.3f} deg (slope residual "
      f"{fit['slope_residual_pct']:+.3f} %, {fit['evaluations']} FE sweeps); "
      f"the simulated muscle's: {true_theta0:.3f} deg")

# Creep relaxes up to `creep_fraction` of the force on both branches, so it can lower the
# measured slope by up to that fraction; the fit turns a slope error into an angle error through
# the slope's sensitivity to theta0, measured here by two FE sweeps half a degree apart.
P = reference["pressure_bar"].to_numpy()
slopes = [line_above_threshold(P, model(true_theta0 + d).predict(P, muscle.D0_mm, muscle.t0_mm,
                                                                  muscle.eps).force_N)[0]
          for d in (0.0, 0.5)]
sensitivity = abs(np.log(slopes[1] / slopes[0])) / 0.5  # relative slope change per degree
bound_deg = run.meta.hardware["sim"]["creep_fraction"] / sensitivity
error_deg = abs(fit["theta0_deg"] - true_theta0)
print(f"slope sensitivity {100 * sensitivity:.1f} % per degree: creep explains up to "
      f"{bound_deg:.3f} deg; the fit is {error_deg:.3f} deg off")
assert error_deg < bound_deg
