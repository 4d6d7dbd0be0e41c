"""Design a muscle for a required force

The paper's aim: choose a muscle's geometry for the force an application needs. Here a
force-stroke requirement: at least 300 N at 2.5 bar held at 10 % shortening and still 250 N at
20 %, for a muscle that fits a housing 64 mm wide. `mkm.design.design`
searches the design box with the surrogate (fast, with its uncertainty), then verifies the best
designs with the FE model; a design counts only when the FE says it meets every requirement,
and every margin it reports is the FE's.

The same from the command line:

    mkm design --require 300N@2.5bar,eps=0.10 --require 250N@2.5bar,eps=0.20 \\
               --max-outer-diameter 64 --out mkm-out/design

The check below solves the chosen design again with the FE model built by hand, at the mesh the
verification used (`fe_mesh`: the medium one, or the fine one where the medium mesh met a
requirement by less than its error): the forces the design reports are the FE's, and they meet
the requirements.
The default surrogate is trained once, on first use, and cached.
"""

from mkm.design import design
from mkm.fem import Axisym

REQUIRED = [(300.0, 0.10), (250.0, 0.20)]  # (force [N], eps) at 2.5 bar
designs = design([f"{F:g}N@2.5bar,eps={eps:g}" for F, eps in REQUIRED],
                 {"max_outer_diameter_mm": 64})
columns = ["rank", "D0_mm", "t0_mm", "outer_diameter_mm", "r1_fe_N", "r2_surrogate_N",
           "r2_uncertainty_N", "r2_fe_N", "r2_fe_margin_N", "meets_all"]
print(designs[columns].round(3).to_string(index=False))

best = designs.iloc[0]
assert best["meets_all"], "no design the FE confirms"
fe = Axisym(theta0_deg=best["theta0_deg"], L0_mm=best["L0_mm"], mesh=best["fe_mesh"])
print(f"chosen: D0 {best['D0_mm']:.2f} mm, t0 {best['t0_mm']:.2f} mm, outer diameter "
      f"{best['outer_diameter_mm']:.1f} mm")
for k, (required_N, eps) in enumerate(REQUIRED, start=1):
    force_N = float(fe.predict(2.5, best["D0_mm"], best["t0_mm"], eps).force_N)
    print(f"requirement {k}: FE force again {force_N:.2f} N (reported {best[f'r{k}_fe_N']:.2f} N,"
          f" required {required_N:g} N)")
    assert force_N >= required_N and abs(force_N - best[f"r{k}_fe_N"]) <= 1e-6 * force_N
assert best["outer_diameter_mm"] <= 64.0
