"""The test bench: acquisition through nidaqmx at 10 Hz, a simulated bench, run records.

``backend`` (protocol and errors), ``ni`` (NI USB-6001), ``sim`` (simulated bench), ``config``
(TOML settings), ``run`` (the run lifecycle), ``storage`` (run folders and ``load_run``),
``procedures`` (tare, load-cell calibration, check), ``operator`` and ``liveplot``; ``commands``
holds the ``mkm acquire|tare|calibrate-loadcell|check`` subcommands.
"""
