"""The test bench: acquisition through nidaqmx at 10 Hz, a simulated bench, run records.

``backend`` (protocol and errors), ``ni`` (NI USB-6001), ``sim`` (simulated bench), ``config``
(TOML settings validated against the USB-6001's capabilities), ``run`` (the run lifecycle, which
joins the procedure ``sequence``, the worker ``worker`` and the recorder ``recorder``),
``signals`` (every stop signal vents), ``unvented`` (runs that died pressurised), ``storage``
(the run-folder contract: ``RunMeta``, ``RunStatus``, ``Sample``, ``load_run``), ``procedures``
(tare, load-cell calibration, check, vent), ``reprocess`` (new calibration, same raw volts),
``operator`` and ``liveplot``. The ``mkm`` subcommands are in ``mkm.cli.bench``.
"""

from mkm.bench.config import BenchConfig, load_config, parse_config
from mkm.bench.run import BenchRun, RunResult, acquire
from mkm.bench.storage import RunMeta, RunStatus, Sample, aggregate_samples, load_run

__all__ = ["BenchConfig", "BenchRun", "RunMeta", "RunResult", "RunStatus", "Sample", "acquire",
           "aggregate_samples", "load_config", "load_run", "parse_config"]
