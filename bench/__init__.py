"""The test bench: acquisition through nidaqmx at 10 Hz, a simulated bench, run records.

``backend`` (protocol and errors), ``ni`` (NI USB-6001), ``sim`` (simulated bench), ``config``
(TOML settings validated against the USB-6001's capabilities), ``run`` (the run lifecycle, which
joins the procedure ``sequence``, the worker ``worker`` and the recorder ``recorder``),
``signals`` (every stop signal vents), ``unvented`` (runs that died pressurised), ``storage``
(the run-folder contract: ``RunMeta``, ``RunStatus``, ``Sample``, ``load_run``), ``procedures``
(tare, load-cell calibration, check, vent), ``reprocess`` (new calibration, same raw volts),
``operator`` and ``liveplot``. The ``mkm`` subcommands are in ``mkm.cli.bench``.
"""

from importlib import import_module

# imported on first use: the command line reads mkm.bench.backends without pandas
_LAZY = {
    "BenchConfig": "mkm.bench.config", "load_config": "mkm.bench.config",
    "parse_config": "mkm.bench.config",
    "BenchRun": "mkm.bench.run", "RunResult": "mkm.bench.run", "acquire": "mkm.bench.run",
    "RunMeta": "mkm.bench.storage", "RunStatus": "mkm.bench.storage",
    "Sample": "mkm.bench.storage", "aggregate_samples": "mkm.bench.storage",
    "load_run": "mkm.bench.storage",
}

__all__ = sorted(_LAZY)


def __getattr__(name):
    if name in _LAZY:
        return getattr(import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'mkm.bench' has no attribute {name!r}")


def __dir__():
    return sorted(__all__)
