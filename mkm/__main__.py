"""``python -m mkm``: the same as the ``mkm`` command."""

import sys

from mkm.cli import main

sys.exit(main())
