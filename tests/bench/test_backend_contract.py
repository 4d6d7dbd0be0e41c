"""One contract, two backends: the simulated bench and the NI backend (driver faked) must give
the same run for the same physics, so the simulation cannot drift away from the real code path.
"""

import pandas as pd
import pytest

from mkm.bench.run import acquire
from mkm.bench.storage import load_run


@pytest.mark.mocked_hardware
def test_sim_and_ni_backends_record_the_same_run(config, fake_driver, tmp_path):
    # fake_driver feeds nidaqmx from a SimMuscleBench with the config's seed, like SimBackend
    sim = load_run(acquire(config, backend="sim", out_root=tmp_path / "sim").path)
    ni = load_run(acquire(config, backend="ni", out_root=tmp_path / "ni").path)
    assert sim.complete and ni.complete
    pd.testing.assert_frame_equal(sim.samples, ni.samples)
    pd.testing.assert_frame_equal(sim.steps, ni.steps)
    assert list(sim.commands["command_V"]) == list(ni.commands["command_V"])
    assert set(sim.meta["hardware"]) <= set(ni.meta["hardware"]) | {"clock", "sim"}
