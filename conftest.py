"""Loaded by pytest before the suite: the interpreter must find the installed package.

``make`` installs the project in setuptools' strict editable mode (a tree of links under
``build/``), where ``mkm.fem`` is ``fem/``; the repository's own ``mkm/`` folder holds the
application only. ``python -m pytest`` (and ``python -c`` in a test's subprocess) put the
working directory first on ``sys.path``, where that folder would shadow the package: it is left
out here, and ``PYTHONSAFEPATH`` tells the interpreters the tests start to leave it out too.
"""

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent
sys.path[:] = [p for p in sys.path if Path(p or os.getcwd()).resolve() != ROOT]
os.environ["PYTHONSAFEPATH"] = "1"
