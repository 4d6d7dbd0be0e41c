"""The capabilities of the DAQ devices the backends drive, against which a configuration is
validated before anything is pressurised (:class:`mkm.bench.backend.DeviceCapabilities`).

Plain data, no driver: the backend registry (:mod:`mkm.bench.backends`) and the command line's
help read it without importing nidaqmx or numpy.
"""

from __future__ import annotations

from mkm.bench.backend import DeviceCapabilities

#: The NI USB-6001. NI USB-6001/6002/6003 User Guide (ni.com, "Pinout and Signal
#: Descriptions", "Analog Input"): AI 0-7 single-ended (RSE) or four differential channels AI 0-3
#: paired with AI 4-7 (AI <0,4>, <1,5>, <2,6>, <3,7>); no NRSE or pseudo-differential mode; one
#: +-10 V range; two analog outputs AO 0-1, +-10 V. NI USB-6001/6002/6003 Specifications: 14-bit
#: ADC, 20 kS/s aggregate maximum sample rate on the USB-6001.
USB6001 = DeviceCapabilities(
    product="USB-6001",
    ai_rse=tuple(f"ai{k}" for k in range(8)),
    ai_differential={f"ai{k}": f"ai{k + 4}" for k in range(4)},
    terminal_configs=("differential", "rse"),
    max_aggregate_rate_hz=20_000.0,
    ai_range_V=10.0,
    ao=("ao0", "ao1"),
    ao_range_V=10.0,
    ai_bits=14,
)
