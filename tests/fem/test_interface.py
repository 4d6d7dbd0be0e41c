"""The force-model contract (fem/interface.py): validation, broadcasting, validity flags."""

import numpy as np
import pytest

from mkm.fem.interface import Domain, ForceModel, validate_inputs


class Linear(ForceModel):
    """100 N per bar; "fails" (NaN) above 2 bar, out of range (kept, invalid) above eps 0.3."""

    name = "linear"

    def _forces(self, P, D0, t0, eps):
        return {"force_N": np.where(P > 2.0, np.nan, 100.0 * P), "valid": eps <= 0.3,
                "extra": D0 + t0}


def test_predict_broadcasts_and_flags():
    pred = Linear().predict(np.array([1.0, 3.0]), 35.0, 2.5, np.array([[0.1], [0.5]]))
    assert pred.force_N.shape == (2, 2)
    np.testing.assert_array_equal(pred.force_N[:, 0], [100.0, 100.0])
    assert np.isnan(pred.force_N[:, 1]).all()
    # NaN means "did not converge" unless the model says otherwise; out of range stays a number
    np.testing.assert_array_equal(pred.converged, [[True, False], [True, False]])
    np.testing.assert_array_equal(pred.valid, [[True, False], [False, False]])
    frame = pred.to_frame()
    assert len(frame) == 4 and (frame.extra == 37.5).all() and pred.seconds >= 0.0


@pytest.mark.parametrize(("args", "message"), [
    ((-1.0, 35.0, 2.5, 0.1),
     r"^pressure_bar=-1 is invalid: expected a gauge pressure in \[0, 1000\] bar$"),
    ((1e9, 35.0, 2.5, 0.1), r"^pressure_bar=1e\+09 is invalid: expected a gauge pressure in"),
    ((1.0, 1e9, 2.5, 0.1),
     r"^D0_mm=1e\+09 is invalid: expected an inner diameter in \[1, 500\] mm$"),
    ((1.0, 0.0, 2.5, 0.1), "^D0_mm=0 is invalid"),
    ((1.0, 35.0, 0.0, 0.1), "^t0_mm=0 is invalid"),
    ((1.0, 10.0, 5.0, 0.1), "^t0_mm=5 is too thick for D0_mm=10: expected t0_mm < D0_mm/2 = 5$"),
    ((1.0, 35.0, 2.5, 1.0), r"^eps=1 is invalid: expected a shortening ratio in \[0, 1\)"),
    ((np.nan, 35.0, 2.5, 0.1), "^pressure_bar=nan is not a finite number$"),
    (([1.0, 2.0], 35.0, 2.5, [0.1, 0.2, 0.3]), "^inputs do not broadcast"),
    (("a", 35.0, 2.5, 0.1), "^inputs must be numbers"),
])
def test_bad_inputs_are_named(args, message):
    with pytest.raises(ValueError, match=message):
        validate_inputs(*args)


def test_domain_is_a_closed_box_with_round_off_slack():
    box = Domain(pressure_bar=(0.0, 2.5), eps=(0.0, 0.2))
    inside = box.contains([2.5, 2.5 * (1 + 1e-12), 2.6], 35.0, 2.5, [0.2, 0.2, 0.1])
    np.testing.assert_array_equal(inside, [True, True, False])
    assert box.as_dict()["eps"] == [0.0, 0.2]
