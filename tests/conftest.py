"""Fixtures of the whole suite: a hermetic home for every cache and state folder, and a small
dataset from the thick-wall model (exact, fast) for the surrogate tests."""

import itertools
import os

import numpy as np
import pandas as pd
import pytest
from hypothesis import settings

from mkm.fem.calibration import calibrated
from mkm.fem.ladder import make_model

# Property-based tests draw the same cases on every run (a suite that passes does not pass by
# luck, and a failure reproduces); explore afresh with HYPOTHESIS_PROFILE=explore
settings.register_profile("suite", derandomize=True, database=None)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "suite"))

# `make test` shares the modules out between two processes (pytest-xdist, ``--dist loadfile``:
# a module's fixtures are built once, in one process). These modules take the longest (the
# identifications on the FE bench, the site's build and the records it quotes, the imports of
# published tables: 311, 156 and 115 s of the suite's 1180 on an idle machine, then 62-41 s);
# handed out first, longest first, neither process is left running one of them alone at the end.
LONGEST_FIRST = ("tests/mkm/test_identify_terms.py", "tests/test_docs.py",
                 "tests/bench/test_import.py", "tests/mkm/test_report.py",
                 "tests/mkm/test_design.py", "tests/bench/test_safety.py",
                 "tests/bench/test_recorder.py", "tests/mkm/test_identify_params.py")


def pytest_configure(config):
    """A module of :data:`LONGEST_FIRST` renamed or removed is an error: the list would
    silently order nothing."""
    missing = [name for name in LONGEST_FIRST if not (config.rootpath / name).is_file()]
    if missing:
        raise pytest.UsageError(f"tests/conftest.py: LONGEST_FIRST names no module {missing}")


def pytest_collection_modifyitems(config, items):
    """Under pytest-xdist, :data:`LONGEST_FIRST` first (the same order in every process: each
    collects the suite and they must agree); a stable sort, so the rest keep their order."""
    if not os.environ.get("PYTEST_XDIST_WORKER"):
        return
    rank = {name: i for i, name in enumerate(LONGEST_FIRST)}
    items.sort(key=lambda item: rank.get(item.nodeid.split("::")[0], len(rank)))


@pytest.fixture(scope="session", autouse=True)
def _hermetic_folders(tmp_path_factory):
    """Every cache (FE predictions, dataset jobs, trained surrogates), the bench state folder and
    the default output root point into one temporary folder for the session: a run of the suite
    neither reads what an earlier run or the user left nor writes into the user's folders. The
    default surrogate is trained once there on first use and shared by every test."""
    home = tmp_path_factory.mktemp("mkm-home")
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("MKM_CACHE_DIR", str(home / "cache"))
        mp.setenv("MKM_STATE_DIR", str(home / "state"))
        mp.setenv("MKM_OUT", str(home / "out"))
        mp.setenv("MPLBACKEND", "Agg")
        yield home


class Symlinks:
    """Symbolic links where this platform lets the test make them: ``symlink(link, target)``
    makes one, or skips the test with the reason. Windows refuses them without developer mode
    or the SeCreateSymbolicLinkPrivilege (WinError 1314); whether it does is tried once, with
    ``os.symlink`` in ``folder``, when this is made."""

    def __init__(self, folder):
        probe = folder / "probe-link"
        try:
            os.symlink(folder / "probe-target", probe)
        except (OSError, NotImplementedError) as exc:
            self.reason = f"this platform cannot make symbolic links here ({exc})"
        else:
            probe.unlink()
            self.reason = None

    def __call__(self, link, target):
        if self.reason:
            pytest.skip(self.reason)
        os.symlink(target, link)
        return link


@pytest.fixture(scope="session")
def symlink(tmp_path_factory):
    """:class:`Symlinks`, tried once per session."""
    return Symlinks(tmp_path_factory.mktemp("symlink-probe"))


@pytest.fixture(scope="session")
def thickwall_dataset(tmp_path_factory):
    """The paper's Table 1 grid computed with ``thickwall``, as ``mkm fem dataset`` writes it,
    at the FE model's calibrated braid angle (a surrogate's default angle)."""
    model = make_model("thickwall", theta0_deg=calibrated("axisym")["theta0_deg"])
    frames = [model.predict(np.arange(0.0, 2.51, 0.5), D0, t0, eps).to_frame()
              for D0, t0, eps in itertools.product((30, 40, 50), (2, 3, 4), (0.0, 0.1, 0.2))]
    # the muscle parameters the FE would record (a surrogate checks them on every prediction)
    params = {k: model.params()[k] for k in ("L0_mm", "theta0_deg", "C10_MPa", "C01_MPa")}
    table = pd.concat(frames, ignore_index=True).assign(model="thickwall", **params)
    path = tmp_path_factory.mktemp("data") / "mkm_dataset.csv"
    with open(path, "w", encoding="utf-8") as f:
        f.write("# model: thickwall (test fixture)\n")
        table.to_csv(f, index=False)
    return path
