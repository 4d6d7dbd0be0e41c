"""The surrogate of the practical range (``muscle-gp-range``): listed wherever the kinds are,
trained on its own shipped sets, and (slow) its calibrated std holding on muscles neither its fit
nor its calibration saw, which is what auto's bound outside the default's box rests on."""

from pathlib import Path

import numpy as np
import pytest

from mkm.cli import main
from mkm.surrogate import kinds
from mkm.surrogate.train import kind_files
from mkm.surrogate.training_data import load_training_data

CHECK_SET = Path(__file__).parent / "data" / "range_check.csv"


def test_the_range_kind_is_in_every_list_derived_from_the_registry(capsys):
    assert kinds.RANGE in kinds.names(include_families=False)
    assert kinds.RANGE in kinds.describe()
    assert any(line.startswith(f"{kinds.RANGE}: ") for line in kinds.describe_each())
    assert kinds.RANGE not in kinds.study_default()  # the study's box is the default's
    assert main(["models"]) == 0
    assert kinds.RANGE in capsys.readouterr().out  # the surrogate entry's kind choices
    with pytest.raises(SystemExit):
        main(["surrogate", "train", "--help"])
    assert kinds.RANGE in "".join(capsys.readouterr().out.split())


def test_its_sets_cover_the_practical_range_and_never_share_a_muscle():
    from mkm.fem.limits import PRACTICAL_RANGE

    design, calibration, holdout = (load_training_data(p) for p in kind_files(kinds.RANGE))
    assert kind_files("best")[0] != kind_files(kinds.RANGE)[0]
    assert design.inputs == calibration.inputs == holdout.inputs  # all eight vary
    assert len(design.inputs) == 8 and not design.fixed
    for name in ("pressure_bar", "D0_mm", "t0_mm", "L0_mm", "theta0_deg", "C10_MPa"):
        assert design.box[name] == pytest.approx(list(getattr(PRACTICAL_RANGE, name))), name
    muscles = [{tuple(row) for row in np.unique(d.X[:, 1:], axis=0)}
               for d in (design, calibration, holdout, load_training_data(CHECK_SET))]
    for i, a in enumerate(muscles):
        for b in muscles[i + 1:]:
            assert not a & b
    # 768, 80 and 60 drawn; a muscle the FE solved at no pressure has no row to learn from
    assert (design.n_muscles, calibration.n_muscles, holdout.n_muscles) == (765, 79, 59)
