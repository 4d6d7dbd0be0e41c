"""Tests of the dataset builder (fem/dataset/build.py): jobs, cache, resume, parallel runs."""

import json
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest

from mkm.cli import main
from mkm.core.records import package_file, source_version
from mkm.fem import batch
from mkm.fem.calibration import calibrated
from mkm.fem.dataset import build as dataset
from mkm.fem.dataset.build import Job, build_dataset, model_version, run_job
from mkm.fem.dataset.grid import parse_grid
from mkm.fem.eq2 import chou_hannaford
from mkm.fem.ladder import L0, THETA0, Entry, register, unregister

# 2 muscles x 2 eps = 4 jobs of 3 pressures: the smallest grid with more jobs than workers
TINY_GRID = """
pressure_bar = "0:2:1"
D0_mm = [30, 40]
t0_mm = 2.5
eps = [0.0, 0.1]
L0_mm = 282
"""
# seconds is the wall time of each job: the one column two runs may not share
SAME = [c for c in dataset.COLUMNS if c != "seconds"]


def tiny(model="eq2", mesh=None, **options):
    return build_dataset(parse_grid(TINY_GRID, "tiny"), model, mesh=mesh, progress=False,
                         **options)


def test_rows_are_the_models_forces(tmp_path):
    run = tiny(out=None, workers=1, cache_dir=tmp_path)
    theta0 = calibrated("eq2-inner")["theta0_deg"]
    rows = run.frame
    assert len(rows) == 12 and run.jobs_computed == 4
    # the builder must pass each muscle's inputs through unchanged: exact equality
    expected = chou_hannaford(rows.pressure_bar, rows.D0_mm, rows.eps, theta0)
    np.testing.assert_array_equal(rows.force_N, expected)
    assert (rows.theta0_deg == theta0).all() and (rows.L0_mm == 282.0).all()
    assert rows.converged.all() and rows.iterations.isna().all()


@pytest.mark.slow  # starts Dask
def test_serial_local_parallel_and_cluster_give_identical_rows(tmp_path):
    from dask.distributed import LocalCluster

    serial = tiny(out=None, workers=1, cache_dir=tmp_path / "serial")
    local = tiny(out=None, workers=2, cache_dir=tmp_path / "local")
    assert serial.workers == "1 worker (in-process)"
    assert local.workers == "2 local Dask workers"
    # and one tiny FE build: 2 jobs on the coarse mesh (theta0 fixed: no calibration needed)
    fe_grid = parse_grid(TINY_GRID.replace("[30, 40]", "30") + "theta0_deg = 30", "fe")
    fe_serial = build_dataset(fe_grid, "axisym", mesh="coarse", out=None, workers=1,
                              cache_dir=tmp_path / "fe-serial", progress=False)
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster:
        remote = tiny(out=None, scheduler=cluster.scheduler_address,
                      cache_dir=tmp_path / "cluster")
        fe_remote = build_dataset(fe_grid, "axisym", mesh="coarse", out=None,
                                  scheduler=cluster.scheduler_address,
                                  cache_dir=tmp_path / "fe-cluster", progress=False)
    for run in (serial, local, remote):
        assert (run.jobs_computed, run.jobs_cached) == (4, 0)
    # same code on the same inputs: the rows must be equal to the last bit
    pd.testing.assert_frame_equal(local.frame[SAME], serial.frame[SAME])
    pd.testing.assert_frame_equal(remote.frame[SAME], serial.frame[SAME])
    assert fe_remote.jobs_computed == 2 and len(fe_remote.frame) == 6
    assert fe_serial.frame.converged.all() and (fe_serial.frame.mesh == "coarse").all()
    pd.testing.assert_frame_equal(fe_remote.frame.drop(columns="seconds"),
                                  fe_serial.frame.drop(columns="seconds"))


def test_resume_after_interruption_computes_only_missing_jobs(tmp_path, monkeypatch):
    real_run_job = batch.run_job
    calls = []

    def interrupted_after_two(job):
        if len(calls) == 2:
            raise KeyboardInterrupt  # as Ctrl-C in the middle of the third job
        calls.append(job)
        return real_run_job(job)

    monkeypatch.setattr(batch, "run_job", interrupted_after_two)
    with pytest.raises(KeyboardInterrupt):
        tiny(out=tmp_path / "d.csv", workers=1, cache_dir=tmp_path / "cache")
    cached = list((tmp_path / "cache").iterdir())
    assert len(cached) == 2  # the two finished jobs, and no half-written temporary file
    assert not (tmp_path / "d.csv").exists()

    calls.clear()
    monkeypatch.setattr(batch, "run_job", lambda job: calls.append(job) or real_run_job(job))
    resumed = tiny(out=tmp_path / "d.csv", workers=1, cache_dir=tmp_path / "cache")
    assert (resumed.jobs_computed, resumed.jobs_cached, len(calls)) == (2, 2, 2)
    fresh = tiny(out=None, workers=1, cache_dir=tmp_path / "fresh")
    pd.testing.assert_frame_equal(resumed.frame[SAME], fresh.frame[SAME])

    again = tiny(out=tmp_path / "d.csv", workers=1, cache_dir=tmp_path / "cache")
    assert (again.jobs_computed, again.jobs_cached) == (0, 4)


def test_the_sidecar_names_the_cache_by_no_folder_of_the_machine(tmp_path, monkeypatch):
    # was: "cache": "/root/.cache/mkm-bench/dataset", a user's folder, in the shipped sidecar
    monkeypatch.chdir(tmp_path)
    tiny(out="d.csv", workers=1, cache_dir=tmp_path / "jobs")
    assert json.loads((tmp_path / "d.json").read_text())["cache"] == "jobs"
    tiny(out="d.csv", workers=1, cache_dir=dataset.default_cache_dir())
    assert json.loads((tmp_path / "d.json").read_text())["cache"] == "the user cache"


def test_damaged_cache_file_is_recomputed(tmp_path):
    tiny(out=None, workers=1, cache_dir=tmp_path)
    damaged = sorted(tmp_path.iterdir())[0]
    damaged.write_text(damaged.read_text()[:100])  # as left by a copy cut short
    run = tiny(out=None, workers=1, cache_dir=tmp_path)
    assert (run.jobs_computed, run.jobs_cached) == (1, 3)
    json.loads(damaged.read_text())


FAKE_MODEL = """
import numpy as np

from fakemkm.physics import stiffness_N_per_bar
from mkm.fem.interface import ForceModel


class Fake(ForceModel):
    name = "fake"

    def __init__(self, theta0_deg=30.0, L0_mm=282.0):
        self.theta0_deg, self.L0_mm = theta0_deg, L0_mm

    def params(self):
        return {"theta0_deg": self.theta0_deg, "L0_mm": self.L0_mm}

    def _forces(self, P, D0, t0, eps):
        # "fails to converge" above 1.5 bar when shortened, as an FE solve may
        failed = (P > 1.5) & (eps > 0)
        return {"force_N": np.where(failed, np.nan, stiffness_N_per_bar * P),
                "converged": ~failed, "iterations": np.where(failed, 20, 3),
                "cutbacks": np.where(failed, 6, 0),
                "failure": np.where(failed, "diverged", "")}
"""


@pytest.fixture
def fake_model(tmp_path, monkeypatch):
    """A model in its own package, "fakemkm", whose physics lives in a second module."""
    package = tmp_path / "fakemkm"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "model.py").write_text(FAKE_MODEL)
    (package / "physics.py").write_text("stiffness_N_per_bar = 100.0\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    register(Entry("fake", "fakemkm.model:Fake", "Fake", "a fake model", "test",
                   {"theta0_deg": THETA0, "L0_mm": L0}))
    source_version.cache_clear()
    yield package
    unregister("fake")
    source_version.cache_clear()


def test_editing_the_physics_changes_the_model_version(fake_model):
    before = model_version("fake")
    source_version.cache_clear()
    assert model_version("fake") == before
    (fake_model / "physics.py").write_text("stiffness_N_per_bar = 101.0\n")
    source_version.cache_clear()
    after = model_version("fake")
    assert after != before
    job = Job("fake", None, 30.0, 2.0, 0.1, 282.0, 30.0, (0.0, 1.0))
    assert job.key(before) != job.key(after)


def test_model_version_is_the_same_in_every_process():
    # workers compute it again and must agree with the client, whatever each has imported
    code = ("import mkm.fem.thickwall, mkm.cli\n"
            "from mkm.fem.dataset.build import model_version as v\nprint(v('eq2'))")
    other = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                           check=True).stdout.strip()
    assert other == model_version("eq2")


def test_non_converged_jobs_are_kept_and_flagged(fake_model, tmp_path, capsys):
    grid = tmp_path / "grid.toml"
    grid.write_text(TINY_GRID)
    out = tmp_path / "d.csv"
    code = main(["fem", "dataset", "--grid", str(grid), "--model", "fake", "--out", str(out),
                 "--cache", str(tmp_path / "cache"), "--workers", "1"])
    assert code == 0
    rows = pd.read_csv(out)
    assert len(rows) == 12  # nothing dropped
    failed = (rows.pressure_bar > 1.5) & (rows.eps > 0)
    assert failed.sum() == 2
    assert (~rows.converged == failed).all() and (~rows.valid == failed).all()
    assert rows.force_N[failed].isna().all()
    np.testing.assert_array_equal(rows.force_N[~failed], 100.0 * rows.pressure_bar[~failed])
    assert (rows.iterations[failed] == 20).all() and (rows.cutbacks[failed] == 6).all()
    assert (rows.failure[failed] == "diverged").all()  # the model's own extras are kept
    err = capsys.readouterr().err
    assert "2 of 12 points (2 of 4 jobs) did not converge" in err
    sidecar = json.loads(out.with_suffix(".json").read_text())
    assert (sidecar["points_not_converged"], sidecar["jobs_not_converged"]) == (2, 2)


def test_sidecar_records_provenance(tmp_path):
    run = tiny(out=tmp_path / "d.csv", workers=1, cache_dir=tmp_path / "cache")
    sidecar = json.loads(run.sidecar.read_text())
    assert sidecar["model"] == "eq2" and sidecar["model_version"] == model_version("eq2")
    assert sidecar["calibration"]["entry"] == calibrated("eq2-inner")
    assert sidecar["grid"]["D0_mm"] == [30.0, 40.0] and sidecar["rows"] == 12
    assert {"command", "date_utc", "versions"} <= set(sidecar)
    assert list(pd.read_csv(run.out).columns) == list(dataset.COLUMNS)


def test_workers_and_scheduler_together_are_refused(tmp_path):
    with pytest.raises(ValueError, match="workers=2 and scheduler='tcp://localhost:8786'"):
        tiny(out=None, workers=2, scheduler="tcp://localhost:8786", cache_dir=tmp_path)


@pytest.mark.slow  # starts Dask
def test_unreachable_scheduler_gives_clear_error(tmp_path):
    import dask

    # nothing listens on the discard port; 1 s instead of Dask's 30 s connect timeout
    with dask.config.set({"distributed.comm.timeouts.connect": "1s"}), \
            pytest.raises(ValueError, match="^scheduler='tcp://127.0.0.1:9': Timed out"):
        tiny(out=None, scheduler="tcp://127.0.0.1:9", cache_dir=tmp_path)


SHIPPED = package_file("mkm.surrogate", "data", "mkm_dataset.csv")


@pytest.mark.parametrize("D0_mm, t0_mm, eps", [(30.0, 2.0, 0.2), (50.0, 4.0, 0.1)])
def test_shipped_dataset_rebuilds(D0_mm, t0_mm, eps):
    rows = pd.read_csv(SHIPPED)
    info = json.loads(SHIPPED.with_suffix(".json").read_text())
    assert info["grid"]["source"] == "paper" and len(rows) == 162
    shipped = rows[(rows.D0_mm == D0_mm) & (rows.t0_mm == t0_mm) & (rows.eps == eps)]
    # built with today's calibration: a recalibrated theta0 means the data must be rebuilt
    assert (shipped.theta0_deg == calibrated(info["calibration"]["key"])["theta0_deg"]).all()
    job = Job(info["model"], info["mesh"], D0_mm, t0_mm, eps, float(shipped.L0_mm.iloc[0]),
              float(shipped.theta0_deg.iloc[0]), tuple(shipped.pressure_bar))
    rebuilt = pd.DataFrame(run_job(job)["rows"])
    np.testing.assert_array_equal(rebuilt.converged, shipped.converged)
    # Newton stops at a relative residual of 1e-9, so a rebuild on other hardware agrees to
    # about that; 1e-6 leaves margin yet catches any change of physics or mesh (coarse vs
    # medium mesh differ by 5e-4)
    np.testing.assert_allclose(rebuilt.force_N, shipped.force_N, rtol=1e-6, atol=1e-6)


@pytest.mark.parametrize("model", ["surrogate", "auto", "friction"])
def test_a_dataset_is_built_of_a_physics_model_only(model, tmp_path):
    # was: a 'dataset' of the surrogate (or of auto's pick) written as if the FE had made it
    with pytest.raises(ValueError) as caught:
        tiny(model, out=tmp_path / "d.csv", workers=1, cache_dir=tmp_path)
    assert str(caught.value) == (f"--model {model!r} is no physics model a dataset is built "
                                 "of: expected one of eq2, thickwall, axisym")
    assert not (tmp_path / "d.csv").exists()


@pytest.mark.parametrize("model", ["axisym:mesh=coarse", "eq2:diameter=braid"])
def test_a_predictor_spec_is_refused_saying_the_dataset_takes_a_name(model, tmp_path):
    # was "unknown model 'axisym:mesh=coarse': expected one of eq2, thickwall, axisym, friction,
    # surrogate, auto": axisym named unknown and listed, with three models no dataset takes
    with pytest.raises(ValueError) as caught:
        tiny(model, out=tmp_path / "d.csv", workers=1, cache_dir=tmp_path)
    name = model.partition(":")[0]
    assert str(caught.value) == (f"--model {model!r}: a dataset takes a model's name alone: "
                                 f"expected one of eq2, thickwall, axisym (--model {name}), the "
                                 "mesh given by --mesh, theta0_deg and L0_mm by the grid")
    assert not (tmp_path / "d.csv").exists()


def test_the_command_takes_no_progress(tmp_path, monkeypatch, capsys):
    # its help promised a progress bar, and every long command's --no-progress was refused here
    import mkm.fem.dataset

    asked = {}
    real = mkm.fem.dataset.build_dataset

    def recording(*args, **kwargs):
        asked.update(kwargs)
        return real(*args, **kwargs)

    monkeypatch.setattr(mkm.fem.dataset, "build_dataset", recording)
    grid = tmp_path / "grid.toml"
    grid.write_text(TINY_GRID)
    assert main(["fem", "dataset", "--grid", str(grid), "--model", "eq2", "--out",
                 str(tmp_path / "d.csv"), "--cache", str(tmp_path / "cache"), "--workers", "1",
                 "--no-progress"]) == 0
    assert asked["progress"] is False
    assert len(pd.read_csv(tmp_path / "d.csv")) == 12


def test_a_file_of_the_users_in_the_sidecars_place_is_said_before_any_job(tmp_path):
    # --out lab.csv beside the lab's calibration lab.json: refused before the FE runs, kept
    lab = tmp_path / "lab.json"
    lab.write_text('{"thickwall": {"theta0_deg": 31.0}}\n')
    with pytest.raises(ValueError, match=r"lab.json is not the metadata of an earlier lab.csv"):
        tiny(out=tmp_path / "lab.csv", workers=1, cache_dir=tmp_path / "cache")
    assert lab.read_text() == '{"thickwall": {"theta0_deg": 31.0}}\n'
    assert sorted(p.name for p in tmp_path.iterdir()) == ["lab.json"]  # no job was cached
