"""The toolkit's plumbing, below the physics: every package of ``mkm`` may import it.

- :mod:`mkm.core.home`: the toolkit's name, version and folders on the user's machine;
- :mod:`mkm.core.records`: provenance, atomic writes, source versions, CSV sidecars;
- :mod:`mkm.core.ranges`: the parsers of numbers, fractions and ranges that the command line,
  the grids and the bench configuration share;
- :mod:`mkm.core.toml_text`: text files as Windows programs save them, and the one TOML reader
  (a bench configuration, a run folder's ``config.toml``, a dataset grid), whose messages say
  what a Windows user's line needs.
"""
