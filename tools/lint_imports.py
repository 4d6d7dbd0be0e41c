"""Run import-linter on the installed layout of the ``mkm`` package.

The wheel maps the folders ``bench/``, ``fem/`` and ``surrogate/`` to ``mkm.bench``, ``mkm.fem``
and ``mkm.surrogate`` (``[tool.setuptools] package-dir``). import-linter finds modules by walking
the package's folder, which the editable install does not lay out, so this script copies the
sources into a temporary tree shaped as the wheel and runs ``lint-imports`` on it.

Usage: ``python tools/lint_imports.py`` from the repository root (``make test`` runs it).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def package_dirs(pyproject: Path = ROOT / "pyproject.toml") -> dict[str, str]:
    """The ``package-dir`` mapping of the project: import name -> folder."""
    config = tomllib.loads(pyproject.read_text(encoding="utf-8"))
    return config["tool"]["setuptools"]["package-dir"]


def lay_out(target: Path) -> None:
    """Copy every mapped folder's Python sources to ``target`` under its import name."""
    for name, folder in sorted(package_dirs().items(), key=lambda item: item[0].count(".")):
        destination = target.joinpath(*name.split("."))
        shutil.copytree(ROOT / folder, destination, dirs_exist_ok=True,
                        ignore=lambda _d, names: [n for n in names if n == "__pycache__"
                                                  or (Path(_d, n).is_file()
                                                      and not n.endswith(".py"))])


def main() -> int:
    with tempfile.TemporaryDirectory(prefix="mkm-lint-") as tmp:
        lay_out(Path(tmp))
        env = dict(os.environ, PYTHONPATH=tmp)
        exe = shutil.which("lint-imports", path=str(Path(sys.executable).parent)) or "lint-imports"
        return subprocess.call([exe, str(ROOT / "pyproject.toml")], env=env,
                               cwd=tmp)


if __name__ == "__main__":
    sys.exit(main())
