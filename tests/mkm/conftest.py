"""Fixtures shared by the tests of the ``mkm`` command line."""

from __future__ import annotations

import pytest

from mkm.cli import main


@pytest.fixture
def mkm_run(capsys):
    """``mkm_run(argv) -> (exit status, stdout, stderr)`` of ``mkm argv`` run in-process."""

    def run(argv):
        try:
            code = main(argv)
        except SystemExit as exc:  # argparse errors leave through parser.exit
            code = exc.code
        out, err = capsys.readouterr()
        return code, out, err

    return run
