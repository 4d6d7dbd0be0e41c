"""Where the closed forms stop: a stability map over pressure and shortening

Equation 2 and the thick-wall model over P 0-4 bar x eps 0-35 % for the paper's muscle I. Both
flag every point past the braid's locking angle as invalid (`valid=False`) instead of clamping
it: there the braid cannot shorten any more, Equation 2 turns negative and the thick-wall
threshold pressure grows without bound. The lock is at

    eps_max = 1 - 1 / (sqrt(3) cos theta0)

(the braid angle reaches arccos(1/sqrt(3)) = 54.74 deg), so the boundary of each map is a
vertical line at the eps_max of the model's calibrated theta0, whatever the pressure. The FE
model's map (which also shows where Newton fails) is in `mkm study`'s report.

Writes `stability_map.png` into `mkm-out/examples/` (or `$MKM_OUT/examples/`).
"""

import numpy as np
from matplotlib.figure import Figure

from mkm.fem.paper import TEST_MUSCLES
from mkm.paths import default_out
from mkm.registry import build_spec

D0_mm, t0_mm, _ = TEST_MUSCLES["I"]
pressure_bar = np.linspace(0.0, 4.0, 41)
eps = np.linspace(0.0, 0.35, 351)  # steps of 0.001
P, E = np.meshgrid(pressure_bar, eps)

figure = Figure(figsize=(9, 3.6), layout="constrained")
axes = figure.subplots(1, 2, sharey=True)
for ax, spec in zip(axes, ["eq2", "thickwall"], strict=True):
    model = build_spec(spec)
    prediction = model.predict(P, D0_mm, t0_mm, E)
    theta0 = np.deg2rad(model.params()["theta0_deg"])
    eps_max = 1 - 1 / (np.sqrt(3) * np.cos(theta0))
    first_invalid = E[~prediction.valid].min()
    print(f"{spec:10s} theta0 {np.rad2deg(theta0):.3f} deg: eps_max {eps_max:.4f}, "
          f"first invalid eps on the map {first_invalid:.3f}")
    # the first invalid grid value is the first one at or past the lock
    assert eps_max <= first_invalid < eps_max + 0.001 + 1e-12
    assert prediction.valid[E < eps_max].all()
    ax.pcolormesh(E * 100, P, prediction.valid, cmap="RdYlGn", vmin=0, vmax=1, shading="auto")
    ax.axvline(eps_max * 100, color="k", ls="--", label=f"eps_max {100 * eps_max:.1f} %")
    ax.set(title=spec, xlabel="eps [%]")
    ax.legend(loc="upper left")
axes[0].set_ylabel("pressure [bar]")
out = default_out("examples")
out.mkdir(parents=True, exist_ok=True)
figure.savefig(out / "stability_map.png", dpi=100)
print(f"green: valid, red: flagged invalid; written {out / 'stability_map.png'}")
