"""The wheel runs anywhere: built from the sources, installed into a fresh virtual environment,
``mkm demo`` and ``mkm report`` work from an empty folder (no source tree, no editable install).

The fresh environment gets the wheel only; its dependencies (numpy, scikit-fem, ...) come from
the test's own environment through a ``.pth`` file, so the test needs no network and takes
seconds rather than the minutes a full dependency install would.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import sysconfig
import zipfile
from pathlib import Path

import pandas as pd
import pytest

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("bench", "fem", "surrogate", "mkm")


def _run(args, **kwargs):
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True, timeout=300,
                          check=False, **kwargs)
    assert done.returncode == 0, f"{args}: {done.stderr[-3000:]}"
    return done


@pytest.fixture(scope="module")
def wheel(tmp_path_factory):
    """The wheel of a copy of the sources (the work tree gets no build/ folder)."""
    tmp = tmp_path_factory.mktemp("wheel")
    src = tmp / "src"
    src.mkdir()
    for name in ("pyproject.toml", "README.md"):
        shutil.copy2(ROOT / name, src / name)
    for package in PACKAGES:
        shutil.copytree(ROOT / package, src / package,
                        ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "-w", tmp / "dist",
          src])
    (path,) = (tmp / "dist").glob("mkm_bench-*.whl")
    return path


def test_wheel_holds_the_packages_and_their_data_only(wheel):
    names = zipfile.ZipFile(wheel).namelist()
    top = {n.split("/")[0] for n in names if not n.split("/")[0].endswith(".dist-info")}
    assert top == set(PACKAGES)  # no stray top-level benchmarks/ (the old "bench*" pattern)
    data = {n for n in names if not n.endswith(".py") and ".dist-info/" not in n}
    shipped = {str(p.relative_to(ROOT).as_posix()) for package in PACKAGES
               for p in (ROOT / package).rglob("*")
               if p.is_file() and p.suffix in {".csv", ".json", ".toml"}}
    assert shipped and data == shipped  # every data file a command reads, and nothing else


@pytest.fixture(scope="module")
def fresh_env(wheel, tmp_path_factory):
    """A new virtual environment with the wheel installed (not editable); returns the folder
    of its scripts."""
    venv = tmp_path_factory.mktemp("venv") / "env"
    _run([sys.executable, "-m", "venv", "--without-pip", venv])
    bin_dir = venv / ("Scripts" if os.name == "nt" else "bin")
    python = next(p for p in (bin_dir / "python.exe", bin_dir / "python") if p.exists())
    site = Path(_run([python, "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"])
                .stdout.strip())
    # the dependencies of this environment, after the new one's own site-packages
    (site / "deps.pth").write_text(sysconfig.get_path("purelib") + "\n", encoding="utf-8")
    _run([sys.executable, "-m", "pip", "--python", python, "install", "--no-deps", "--no-index",
          "--quiet", wheel])
    return bin_dir, python


def test_demo_and_report_run_from_an_empty_folder(fresh_env, tmp_path):
    bin_dir, python = fresh_env
    work = tmp_path / "empty"
    work.mkdir()
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "MKM_OUT")}
    env |= {"XDG_CACHE_HOME": str(tmp_path / "cache"), "MPLBACKEND": "Agg",
            "OPENBLAS_NUM_THREADS": "1", "OMP_NUM_THREADS": "1"}
    where = _run([python, "-c", "import mkm; print(mkm.__file__)"], cwd=work, env=env)
    assert Path(where.stdout.strip()).is_relative_to(bin_dir.parent)  # the wheel, not the tree
    mkm = shutil.which("mkm", path=str(bin_dir))
    demo = _run([mkm, "demo", "--no-progress"], cwd=work, env=env)
    report = work / demo.stdout.strip().splitlines()[-1]  # the path is printed last
    assert report.name == "report.html" and report.is_file()
    assert report.resolve().is_relative_to(work.resolve())  # under ./mkm-out, nowhere else
    assert "mkm demo: 2 simulated runs" in demo.stderr
    runs = sorted((work / "mkm-out" / "demo" / "runs").iterdir())
    assert len(runs) == 2
    out = _run([mkm, "report", *runs, "--models", "eq2,thickwall,surrogate", "--out", "again",
                "--no-progress"], cwd=work, env=env)
    again = work / out.stdout.strip().splitlines()[-1]
    assert again == work / "again" / "report.html" and again.is_file()
    summary = pd.read_csv(work / "again" / "summary.csv")
    assert len(summary) == 2 * 3  # runs x models
    # the top step (measured 2.5001 bar at most) is in the surrogate's domain: every point valid
    assert (summary["valid_points"] == summary["points"]).all()


@pytest.mark.skipif(shutil.which("make") is None, reason="make is not installed")
def test_make_demo_runs_mkm_demo():
    """`make demo` is `mkm demo` (after the venv set-up), `make test` the checks of CI."""
    done = _run(["make", "-n", "-B", "demo", "test"], cwd=ROOT)
    lines = done.stdout.splitlines()
    assert ".venv/bin/mkm demo" in lines
    assert ".venv/bin/lint-imports" in lines
    assert any(line.endswith("-m pytest -q") for line in lines)
