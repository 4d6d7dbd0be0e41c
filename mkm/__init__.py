"""The ``mkm`` application: the command line, the predictor registry, ``auto``, the validation
report, the speed-accuracy study, figures and HTML.

It sits above the three libraries: ``bench`` (acquisition), ``fem`` (physics) and ``surrogate``
(learned models); the layers are checked by import-linter (``lint-imports``, see
``pyproject.toml``).
"""

from mkm.fem.records import package_version

__version__ = package_version()
