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

pytestmark = pytest.mark.slow  # builds a wheel and a virtual environment

ROOT = Path(__file__).resolve().parents[2]
# source folder -> where the wheel installs it (pyproject's package-dir: one import root)
PACKAGES = {"mkm": "mkm", "bench": "mkm/bench", "fem": "mkm/fem", "surrogate": "mkm/surrogate"}


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
    for package in PACKAGES:  # the source folders
        shutil.copytree(ROOT / package, src / package,
                        ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "-w", tmp / "dist",
          src])
    (path,) = (tmp / "dist").glob("mkm_bench-*.whl")
    return path


def test_wheel_holds_one_import_package_with_its_data_only(wheel):
    names = zipfile.ZipFile(wheel).namelist()
    top = {n.split("/")[0] for n in names if not n.split("/")[0].endswith(".dist-info")}
    assert top == {"mkm"}  # fem, bench and surrogate live under it: nothing generic on top
    modules = {n for n in names if n.endswith(".py")}
    sources = {f"{PACKAGES[folder]}/{p.relative_to(ROOT / folder).as_posix()}"
               for folder in PACKAGES for p in (ROOT / folder).rglob("*.py")}
    assert modules == sources  # every module of every folder, under its import name
    data = {n for n in names if not n.endswith(".py") and ".dist-info/" not in n}
    shipped = {f"{PACKAGES[folder]}/{p.relative_to(ROOT / folder).as_posix()}"
               for folder in PACKAGES for p in (ROOT / folder).rglob("*")
               if p.is_file() and p.suffix in {".csv", ".json", ".toml"}}
    # every data file a command reads and the type checkers' marker (PEP 561), nothing else
    assert shipped and data == shipped | {"mkm/py.typed"}


GENERIC_NAMES = ("fem", "bench", "surrogate")


def _dummy_wheel(folder: Path) -> Path:
    """A wheel of another distribution owning the generic top-level names ``fem``, ``bench`` and
    ``surrogate`` (as distributions on the package index do), written by hand: a wheel is a zip
    with its metadata."""
    name = "dummy_generic-1.0"
    files = {f"{pkg}/__init__.py": f"OWNER = 'dummy-generic'  # not mkm's {pkg}\n"
             for pkg in GENERIC_NAMES}
    files[f"{name}.dist-info/METADATA"] = ("Metadata-Version: 2.1\nName: dummy-generic\n"
                                           "Version: 1.0\n")
    files[f"{name}.dist-info/WHEEL"] = ("Wheel-Version: 1.0\nGenerator: test\n"
                                        "Root-Is-Purelib: true\nTag: py3-none-any\n")
    record = f"{name}.dist-info/RECORD"
    files[record] = "".join(f"{n},,\n" for n in [*files, record])
    path = folder / f"{name}-py3-none-any.whl"
    with zipfile.ZipFile(path, "w") as z:
        for n, text in files.items():
            z.writestr(n, text)
    return path


@pytest.fixture(scope="module")
def fresh_env(wheel, tmp_path_factory):
    """A new virtual environment with the wheel installed (not editable), next to a distribution
    that owns top-level ``fem``, ``bench`` and ``surrogate``; returns the folder of its
    scripts."""
    venv = tmp_path_factory.mktemp("venv") / "env"
    _run([sys.executable, "-m", "venv", "--without-pip", venv])
    bin_dir = venv / ("Scripts" if os.name == "nt" else "bin")
    python = next(p for p in (bin_dir / "python.exe", bin_dir / "python") if p.exists())
    site = Path(_run([python, "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"])
                .stdout.strip())
    # the dependencies of this environment, after the new one's own site-packages
    (site / "deps.pth").write_text(sysconfig.get_path("purelib") + "\n", encoding="utf-8")
    dummy = _dummy_wheel(tmp_path_factory.mktemp("dummy"))
    _run([sys.executable, "-m", "pip", "--python", python, "install", "--no-deps", "--no-index",
          "--quiet", dummy, wheel])
    return bin_dir, python


def test_installs_beside_a_distribution_owning_the_generic_names(fresh_env, tmp_path):
    _, python = fresh_env
    probe = ("import bench, fem, surrogate, mkm.bench, mkm.fem, mkm.surrogate\n"
             "print(bench.OWNER, fem.OWNER, surrogate.OWNER)\n"
             "from mkm.fem import Eq2\n"
             "print(round(float(Eq2(theta0_deg=30).predict(2.0, 40, 3, 0.1).force_N), 3))\n")
    out = _run([python, "-c", probe], cwd=tmp_path).stdout.split("\n")
    assert out[0] == "dummy-generic dummy-generic dummy-generic"  # both kept their files
    # Equation 2 at 2 bar, D0 40 mm, eps 0.1, theta0 30 deg: pi D0^2 P / 4 (3 (1-eps)^2 / tan^2
    # - 1 / sin^2) = 1256.6 mm^2 x 0.2 MPa x (3 x 0.81 x 3 - 4) = 251.33 N x 3.29 = 826.9 N
    assert float(out[1]) == pytest.approx(826.87, abs=0.01)


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
    assert ".venv/bin/python tools/lint_imports.py" in lines
    assert any(line.endswith("-m pytest -q --durations=15 -n 2 --dist loadfile "
                             "--no-loadscope-reorder") for line in lines)
