"""One contract for every backend of the registry (mkm.bench.backends): simulated ones always,
the NI backend through the mocked driver. A backend added to the registry is tested here, offered
by `mkm acquire --backend` and accepted by `mkm check` the moment it exists.
"""

import pandas as pd
import pytest

from mkm.bench.backends import BACKENDS, BackendEntry, register, unregister
from mkm.bench.run import acquire
from mkm.bench.sim import SimBackend
from mkm.bench.storage import load_run


def check_contract(config, name, out_root):
    """A short staircase on backend ``name``: complete, every sample once in order, vented last
    and the vent verified, marked simulated exactly when the registry says so."""
    entry = BACKENDS.entry(name)
    result = acquire(config, backend=name, out_root=out_root, notify=lambda m: None)
    run = load_run(result.path)
    assert result.status == "complete" and result.exit_code == 0, result.reason
    assert list(run.samples["sample"]) == list(range(len(run.samples)))
    assert list(run.steps["set_pressure_bar"]) == [0.5, 1.0, 0.5]
    last = run.commands.iloc[-1]
    assert last["purpose"] == "vent" and last["ok"] and last["command_bar"] == 0.0
    assert run.meta.vent_check["verified"]
    assert run.meta.vent_check["pressure_bar"] < config.safety.vent_below_bar
    assert run.meta.simulated is entry.simulated
    assert run.path.name.endswith("-SIMULATED") is entry.simulated
    return run


@pytest.mark.parametrize("name", list(BACKENDS))
def test_every_registered_backend_meets_the_contract(name, config, tmp_path, request):
    if not BACKENDS.entry(name).simulated:
        request.getfixturevalue("fake_driver")  # NI: nidaqmx's own code, the driver faked
    check_contract(config, name, tmp_path)


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


class ToyBackend(SimBackend):
    """A backend built from the simulated one, on a bench of its own."""

    def __init__(self, config, clock="virtual"):
        super().__init__(config, clock)
        self.bench_key = f"toy-{config.daq.device}"


def test_a_registered_backend_is_offered_checked_and_tested(config, tmp_path, mkm_cli):
    from mkm.bench.devices import USB6001

    register(BackendEntry("toy", ToyBackend, USB6001, "toy bench of the tests", simulated=True))
    try:
        code, out, _ = mkm_cli(["acquire", "--help"])
        assert code == 0 and "{sim,ni,toy}" in out and "toy: toy bench of the tests" in out
        code, out, _ = mkm_cli(["check", "--backend", "toy"])
        assert code == 0 and "backend: toy (SIMULATED" in out
        run = check_contract(config, "toy", tmp_path)
        assert run.meta.hardware["backend"] == "sim"  # what the device reported
    finally:
        unregister("toy")
    assert "toy" not in BACKENDS
    code, _, err = mkm_cli(["check", "--backend", "toy"])
    assert code == 2 and "invalid choice: 'toy'" in err
