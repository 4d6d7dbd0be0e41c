"""The toolkit's identity and its folders on the user's machine: the one place every package
asks for them (below the physics in the layers: every package may import it).

- :data:`DISTRIBUTION`, :data:`PACKAGE` and :func:`package_version`: what the toolkit is called
  and which version runs;
- :func:`user_cache`: the caches of every package (FE predictions, dataset jobs, trained
  surrogates), ``$MKM_CACHE_DIR`` if set, else the operating system's user cache folder;
- :func:`user_state`: the bench's markers (runs that may pressurise the muscle, the owner of a
  bench), ``$MKM_STATE_DIR`` if set, else the user state folder.

Both folders are resolved at every call, never at import, so a test session or a lab can move
them with the environment.
"""

from __future__ import annotations

import os
from pathlib import Path

DISTRIBUTION = "mkm-bench"  # the name on the package index, and of the user folders
PACKAGE = "mkm"  # the one import root: fem, bench and surrogate live under it
CACHE_ENV = "MKM_CACHE_DIR"
STATE_ENV = "MKM_STATE_DIR"


def package_version() -> str:
    """The installed version of the toolkit (``0+unknown`` from a tree never installed)."""
    from importlib.metadata import PackageNotFoundError, version

    try:
        return version(DISTRIBUTION)
    except PackageNotFoundError:
        return "0+unknown"


def user_cache(*parts: str) -> Path:
    """``$MKM_CACHE_DIR / parts`` if that is set, else ``platformdirs.user_cache_dir("mkm-bench")
    / parts``: ``~/.cache/mkm-bench`` on Linux, ``%LOCALAPPDATA%\\mkm-bench\\mkm-bench\\Cache``
    on Windows (not created here)."""
    if os.environ.get(CACHE_ENV):
        return Path(os.environ[CACHE_ENV]).joinpath(*parts)
    import platformdirs

    return Path(platformdirs.user_cache_dir(DISTRIBUTION)).joinpath(*parts)


def user_state(*parts: str) -> Path:
    """``$MKM_STATE_DIR / parts`` if that is set, else the platform's user state folder
    (``~/.local/state/mkm-bench`` on Linux; not created here)."""
    if os.environ.get(STATE_ENV):
        return Path(os.environ[STATE_ENV]).joinpath(*parts)
    import platformdirs

    return Path(platformdirs.user_state_dir(DISTRIBUTION, appauthor=False)).joinpath(*parts)
