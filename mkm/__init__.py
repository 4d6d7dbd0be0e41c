"""The ``mkm`` application: the command line, the predictor registry, ``auto``, the validation
report, the speed-accuracy study, figures and HTML.

It sits above the three libraries: ``bench`` (acquisition), ``fem`` (physics) and ``surrogate``
(learned models); the layers are checked by import-linter (``lint-imports``, see
``pyproject.toml``).
"""



def __getattr__(name):
    if name == "__version__":  # read from the installed metadata when asked, not at import
        from mkm.core.home import package_version

        return package_version()
    raise AttributeError(f"module 'mkm' has no attribute {name!r}")
