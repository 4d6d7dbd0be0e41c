"""Opt-in tests on a real NI USB-6001: set MKM_NI_DEVICE to its name (for example Dev1).

They need NI-DAQmx (Windows) and the bench wired as in the config; they vent and never
pressurise the muscle.
"""

import os

import pytest

from mkm.bench.config import load_config
from mkm.bench.ni import NIBackend
from mkm.bench.procedures import check, tare

DEVICE = os.environ.get("MKM_NI_DEVICE")
pytestmark = [pytest.mark.hardware,
              pytest.mark.skipif(not DEVICE, reason="set MKM_NI_DEVICE to a USB-6001's name")]


@pytest.fixture
def config():
    return load_config().replace(daq={"device": DEVICE})


def test_device_info_and_clock(config):
    backend = NIBackend(config)
    info = backend.open()
    try:
        assert info.product_type == "USB-6001"
        assert info.sample_rate_hz == pytest.approx(10.0, rel=1e-3)  # timebase divisor rounding
        backend.start()
        block = backend.read(5, timeout_s=2.0)
        assert block.volts.shape == (5, 2)
        assert (abs(block.volts) <= 10.0).all()
    finally:
        backend.close()


def test_tare_and_check(config):
    out = tare(config, backend="ni", seconds=2.0)
    assert out["n"] == 20
    # an unloaded cell reads within 1 % of its span of zero once the amplifier is adjusted
    assert abs(out["offset_V"]) < 0.1
    text, _warnings, _refusal = check(config, backend="ni")
    assert "USB-6001" in text
