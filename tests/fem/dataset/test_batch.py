"""Tests of the FE batch runner (fem/batch.py): task sizing, failures, bit-identical results on
any number of workers, a killed worker, a real scheduler/worker pair, a worker with other code."""

import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from mkm.cli import main
from mkm.fem import batch
from mkm.fem.batch import (
    CHUNKS_PER_WORKER,
    TASK_SECONDS,
    Job,
    Runner,
    chunk_size,
    model_version,
    run_job,
    run_jobs,
)

PRESSURES = (0.0, 1.0, 2.0)
# 16 coarse-mesh FE muscles (theta0 given: no calibration read), about 0.1 s each
FE_JOBS = [Job("axisym", "coarse", D0, 2.5, eps, 282.0, 30.0, PRESSURES)
           for D0 in (30.0, 35.0, 40.0, 45.0) for eps in (0.0, 0.05, 0.1, 0.15)]
SAME = [c for c in batch.COLUMNS if c != "seconds"]  # seconds: the one column runs may not share


def eq2_jobs(n):
    return [Job("eq2", None, 30.0 + k, 2.5, 0.05, 282.0, 30.0, PRESSURES) for k in range(n)]


def test_chunks_hide_the_task_overhead_and_still_balance():
    # a 5 ms job: TASK_SECONDS / 5 ms jobs per task, unless that leaves a worker few chunks
    assert chunk_size(0.005, 10_000, 2) == int(TASK_SECONDS / 0.005)
    assert chunk_size(0.005, 200, 2) == 200 // (CHUNKS_PER_WORKER * 2)
    # an FE job longer than the target: one per task
    assert chunk_size(2 * TASK_SECONDS, 10_000, 100) == 1
    assert chunk_size(0.0, 7, 1) == 2  # nothing measured: balance alone decides
    assert chunk_size(0.01, 1, 4) == 1


def test_a_job_listed_twice_is_computed_once(tmp_path):
    jobs = eq2_jobs(3)
    frame, done = run_jobs(jobs + jobs[:1], workers=1, cache_dir=tmp_path, progress=False)
    assert (done["computed"], done["cached"], len(list(tmp_path.iterdir()))) == (3, 0, 3)
    assert len(frame) == 4 * len(PRESSURES)  # every job listed gets its rows, in order
    np.testing.assert_array_equal(frame.force_N.iloc[9:], frame.force_N.iloc[:3])


def test_a_failing_job_is_named_and_the_others_are_cached(tmp_path, monkeypatch):
    real = batch.run_job

    def fails_at_32(job):
        if job.D0_mm == 32.0:
            raise ArithmeticError("boom")
        return real(job)

    monkeypatch.setattr(batch, "run_job", fails_at_32)
    with pytest.raises(RuntimeError, match=r"^1 of 4 jobs failed .*D0_mm=32 .*"
                                           r"ArithmeticError: boom"):
        run_jobs(eq2_jobs(4), workers=1, cache_dir=tmp_path, progress=False)
    assert len(list(tmp_path.iterdir())) == 3


def test_runner_and_workers_together_are_refused(tmp_path):
    with pytest.raises(ValueError, match="runner and workers/scheduler given"):
        run_jobs(eq2_jobs(1), workers=1, runner=Runner(1), cache_dir=tmp_path)
    with pytest.raises(ValueError, match="workers=0 is invalid"):
        Runner(0)


@pytest.fixture(scope="module")
def serial(tmp_path_factory):
    """The FE jobs solved in this process, once for the tests that compare Dask's rows to
    them."""
    frame, done = run_jobs(FE_JOBS, workers=1, cache_dir=tmp_path_factory.mktemp("serial"),
                           progress=False)
    assert done["workers"] == "1 worker (in-process)" and frame.converged.all()
    return frame


@pytest.mark.slow  # starts Dask
def test_chunked_runs_on_two_workers_are_bit_identical_and_reuse_the_cluster(serial, tmp_path,
                                                                          monkeypatch):
    # a long task target: the balance rule alone sizes the chunks, 12 jobs left after the
    # first 4 single-job tasks (2 queued per worker) -> ceil(12 / (4 x 2)) = 2
    monkeypatch.setattr(batch, "TASK_SECONDS", 1e3)
    monkeypatch.setattr(batch, "COMPUTE_WHILE_STARTING", False)  # every job to the cluster
    with Runner(workers=2) as runner:
        frame, done = run_jobs(FE_JOBS, runner=runner, cache_dir=tmp_path / "two",
                               progress=False)
        cluster = runner._cluster
        # a second batch of the same command on the same workers
        again, done_again = run_jobs(eq2_jobs(4), runner=runner, cache_dir=tmp_path / "eq2",
                                     progress=False)
        assert runner._cluster is cluster and done_again["computed"] == 4
    assert runner._cluster is None  # closed with the block
    assert done["workers"] == "2 local Dask workers"
    assert done["chunk_jobs"] == -(-12 // (CHUNKS_PER_WORKER * 2)) == 2
    pd.testing.assert_frame_equal(frame[SAME], serial[SAME])  # to the last bit


@pytest.mark.slow  # starts Dask
def test_this_process_computes_while_the_cluster_starts(serial, tmp_path):
    frame, done = run_jobs(FE_JOBS, workers=2, cache_dir=tmp_path / "two", progress=False)
    # a coarse job takes about 0.1 s, starting two worker processes seconds
    assert done["computed_while_starting"] >= 1 and done["computed"] == len(FE_JOBS)
    pd.testing.assert_frame_equal(frame[SAME], serial[SAME])  # to the last bit


@pytest.mark.slow  # starts Dask, kills a worker process
@pytest.mark.skipif(not hasattr(signal, "SIGKILL"), reason="SIGKILL is POSIX")
def test_a_killed_worker_loses_only_its_task(serial, tmp_path):
    from dask.distributed import Client, LocalCluster

    cache = tmp_path / "cluster"
    killed = []

    def kill_one_worker_after_two_jobs(pid):
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline:
            if cache.is_dir() and len(list(cache.glob("*.json"))) >= 2:
                os.kill(pid, signal.SIGKILL)
                killed.append(len(list(cache.glob("*.json"))))
                return
            time.sleep(0.01)

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        pids = client.run(os.getpid)
        killer = threading.Thread(target=kill_one_worker_after_two_jobs,
                                  args=(sorted(pids.values())[0],))
        killer.start()
        frame, done = run_jobs(FE_JOBS, scheduler=cluster.scheduler_address, cache_dir=cache,
                               progress=False)
        killer.join()
    assert killed and killed[0] < len(FE_JOBS)  # killed mid-batch
    assert done["computed"] == len(FE_JOBS) and len(list(cache.glob("*.json"))) == len(FE_JOBS)
    pd.testing.assert_frame_equal(frame[SAME], serial[SAME])


class AnsweringClient:
    """What ``Client.run(..., on_error="return")`` gives: each worker's answer or exception."""

    def __init__(self, answers):
        self.answers = answers

    def run(self, function, *args, on_error):
        assert on_error == "return"
        return self.answers


def test_the_version_check_names_missing_code_and_skips_a_worker_that_died():
    mine = model_version("eq2")
    runner = Runner(scheduler="tcp://lab:8786")
    # a worker killed mid-check computes nothing: the others decide
    runner.check_versions(AnsweringClient({"tcp://a": mine, "tcp://b": OSError("closed")}),
                          "eq2", mine)
    with pytest.raises(ValueError, match=r"cannot import the model \(No module named 'mkm'\): "
                                         "install mkm-bench on them"):
        runner.check_versions(AnsweringClient({"tcp://a": ModuleNotFoundError(
            "No module named 'mkm'")}), "eq2", mine)
    with pytest.raises(ValueError, match="worker tcp://b has eq2 model version 0.0.9"):
        runner.check_versions(AnsweringClient({"tcp://a": mine, "tcp://b": "0.0.9"}), "eq2",
                              mine)


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def dask_command() -> str:
    """The ``dask`` command of this environment (installed with ``distributed``)."""
    found = shutil.which("dask", path=str(Path(sys.executable).parent))
    assert found, "the dask command comes with distributed"
    return found


def start(args, env=None, cwd=None) -> subprocess.Popen:
    return subprocess.Popen([dask_command(), *args], env=env, cwd=cwd,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def stop(processes) -> None:
    for p in processes:
        p.terminate()
    for p in processes:
        try:
            p.wait(timeout=20)
        except subprocess.TimeoutExpired:
            p.kill()
            p.wait()


def copy_with_other_physics(root: Path) -> Path:
    """The installed package laid out under ``root`` (mkm with fem, bench, surrogate inside),
    with one line of the Equation 2 model changed: a worker running other code."""
    import mkm
    import mkm.bench
    import mkm.fem
    import mkm.surrogate

    skip = shutil.ignore_patterns("__pycache__")
    shutil.copytree(Path(mkm.__file__).parent, root / "mkm", ignore=skip)
    for sub in (mkm.fem, mkm.bench, mkm.surrogate):
        target = root / "mkm" / sub.__name__.split(".")[1]
        shutil.rmtree(target, ignore_errors=True)
        shutil.copytree(Path(sub.__file__).parent, target, ignore=skip)
    eq2 = root / "mkm" / "fem" / "eq2.py"
    eq2.write_text(eq2.read_text() + "\n# edited on this worker only\n")
    return root


@pytest.mark.slow  # starts a Dask scheduler and workers as a lab would
def test_a_scheduler_and_workers_started_with_the_dask_command(tmp_path, capsys):
    address = f"tcp://127.0.0.1:{free_port()}"
    env = {**os.environ, "OMP_NUM_THREADS": "1", "OPENBLAS_NUM_THREADS": "1"}
    processes = [start(["scheduler", "--host", "127.0.0.1", "--port", address.rsplit(":")[-1],
                        "--no-dashboard"], env)]
    try:
        # one worker process is a cluster as a lab's; test_chunked_runs_on_two_workers_... and
        # the identification's test on two workers split the work
        processes.append(start(["worker", address, "--nworkers", "1", "--nthreads", "1",
                                "--no-dashboard"], env))
        grid = tmp_path / "grid.toml"
        grid.write_text('pressure_bar = "0:2:1"\nD0_mm = [30, 40]\nt0_mm = 2.5\n'
                        'eps = [0.0, 0.1]\nL0_mm = 282\ntheta0_deg = 30\n')
        out = tmp_path / "d.csv"
        args = ["fem", "dataset", "--grid", str(grid), "--model", "axisym", "--mesh", "coarse",
                "--cache", str(tmp_path / "cache")]
        assert main([*args, "--out", str(out), "--scheduler", address]) == 0
        assert f"on the Dask cluster at {address}" in capsys.readouterr().err
        assert main([*args, "--out", str(tmp_path / "serial.csv"), "--cache",
                     str(tmp_path / "serial"), "--workers", "1"]) == 0
        remote, serial = pd.read_csv(out), pd.read_csv(tmp_path / "serial.csv")
        assert len(remote) == 12 and remote.converged.all()
        pd.testing.assert_frame_equal(remote[SAME], serial[SAME])
        # another FE batch command on the same cluster: the surrogate's design
        assert main(["surrogate", "design", "--muscles", "2", "--mesh", "coarse", "--out",
                     str(tmp_path / "design.csv"), "--cache", str(tmp_path / "design"),
                     "--scheduler", address]) == 0
        design = pd.read_csv(tmp_path / "design.csv")
        assert design.muscle.nunique() == 2 and design.converged.all()
        assert json.loads((tmp_path / "design.json").read_text())["workers"] == (
            f"the Dask cluster at {address}")
        # and the identification's FE search, from a simulated run
        assert main(["acquire", "--backend", "sim", "--eps", "0.1", "--out",
                     str(tmp_path / "runs")]) == 0
        run = capsys.readouterr().out.strip().splitlines()[-1]
        assert main(["identify", run, "--params", "theta0", "--search", "model", "--model",
                     "axisym:mesh=coarse", "--out", str(tmp_path / "identified"),
                     "--scheduler", address]) == 0
        record = json.loads((tmp_path / "identified" / "identification.json").read_text())
        assert record["fe_workers"] == f"the Dask cluster at {address}"

        # a worker with other code joins: the next batch is refused, naming both versions
        other = copy_with_other_physics(tmp_path / "other")
        other_env = {**env, "PYTHONPATH": str(other)}
        theirs = subprocess.run([sys.executable, "-c", "from mkm.fem.batch import "
                                 "model_version as v; print(v('eq2'))"], env=other_env,
                                cwd=other, capture_output=True, text=True,
                                check=True).stdout.strip()
        assert theirs != model_version("eq2")
        processes.append(start(["worker", address, "--nthreads", "1", "--no-dashboard",
                                "--name", "other-code"], other_env, cwd=other))
        from dask.distributed import Client

        with Client(address) as client:
            client.wait_for_workers(2, timeout=60)
        capsys.readouterr()
        code = main(["fem", "dataset", "--grid", str(grid), "--model", "eq2", "--cache",
                     str(tmp_path / "eq2"), "--out", str(tmp_path / "eq2.csv"), "--scheduler",
                     address])
        err = capsys.readouterr().err
        assert code == 2 and len(err.splitlines()) == 1
        assert f"has eq2 model version {theirs}, this client has {model_version('eq2')}" in err
        assert not (tmp_path / "eq2.csv").exists()
        # what this process computed while it checked the workers is kept: its own code's
        kept = [json.loads(f.read_text()) for f in (tmp_path / "eq2").rglob("*.json")]
        assert all(job["model_version"] == model_version("eq2") for job in kept)
    finally:
        stop(processes)


def test_every_job_is_computed_from_its_inputs_alone():
    # the same job after others in the same process (models reused per process): same bits
    first = run_job(FE_JOBS[5])["rows"]
    for job in FE_JOBS[:3]:
        run_job(job)
    again = run_job(FE_JOBS[5])["rows"]
    assert np.array_equal(first["force_N"], again["force_N"])


def test_by_default_a_short_batch_stays_in_process(tmp_path):
    _, done = run_jobs(eq2_jobs(6), cache_dir=tmp_path, progress=False)
    assert done["workers"] == "1 worker (in-process)" and done["computed"] == 6
    # the rule: a cluster only when the jobs would take AUTO_CLUSTER_SECONDS in-process
    runner = Runner()
    assert runner.in_process(10, 0.9 * batch.AUTO_CLUSTER_SECONDS / 10)
    assert not runner.in_process(10, 1.1 * batch.AUTO_CLUSTER_SECONDS / 10)
    assert not Runner(workers=2).in_process(10, 0.001)  # asked for: always a cluster
