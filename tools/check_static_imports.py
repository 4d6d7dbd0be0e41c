"""Check that a static reader resolves every import of the project's own modules.

The folders ``bench/``, ``fem/`` and ``surrogate/`` are installed as ``mkm.bench``, ``mkm.fem``
and ``mkm.surrogate``; ``make`` installs the project in setuptools' strict editable mode, whose
tree of links under ``build/`` is what type checkers, IDEs and import-graph readers find. This
script runs mypy (a type checker's import resolution, not its type check) over the installed
package and fails on any import of ``mkm`` it cannot resolve: a module that does not exist, or a
name a module does not define.

Usage: ``python tools/check_static_imports.py`` from the repository root (``make test`` runs it).
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
UNRESOLVED = re.compile(r'\[import-not-found\]|Module "mkm[\w.]*" has no attribute|'
                        r'Cannot find implementation or library stub for module named "mkm')


def main() -> int:
    done = subprocess.run(
        [sys.executable, "-m", "mypy", "-p", "mkm", "--follow-imports=silent",
         "--show-error-codes", "--no-error-summary", "--cache-dir", str(ROOT / ".mypy_cache")],
        capture_output=True, text=True, cwd=ROOT.parent, check=False)
    if done.returncode not in (0, 1):  # 2: mypy itself failed (no package mkm found, ...)
        print(done.stdout + done.stderr, file=sys.stderr)
        print("static imports: mypy could not read the installed package mkm (is the project "
              "installed with `make`?)", file=sys.stderr)
        return 1
    unresolved = [line for line in done.stdout.splitlines() if UNRESOLVED.search(line)]
    for line in unresolved:
        print(line, file=sys.stderr)
    modules = len(set(re.findall(r"^(\S+\.py):", done.stdout, re.M)))
    print(f"static imports: {len(unresolved)} unresolved import(s) of mkm "
          f"(mypy read the installed package; {modules} file(s) have type notes, not checked "
          "here)")
    return 1 if unresolved else 0


if __name__ == "__main__":
    sys.exit(main())
