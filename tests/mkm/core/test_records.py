"""Tests of mkm/core/records.py: atomic writes, source versions, package files, provenance."""

import json
import os
import shutil
import time

import pytest

from mkm.core import records
from mkm.core.home import package_version


def test_crash_while_writing_keeps_the_old_file(tmp_path, monkeypatch):
    target = tmp_path / "job.json"
    records.write_atomic(target, "old")
    umask = os.umask(0)
    os.umask(umask)
    assert target.stat().st_mode & 0o777 == 0o666 & ~umask  # as open() would, not mkstemp's 0600

    def crash(src, dst):
        raise KeyboardInterrupt  # killed between writing the temporary file and renaming it

    monkeypatch.setattr(records.os, "replace", crash)
    with pytest.raises(KeyboardInterrupt):
        records.write_atomic(target, "new")
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["job.json"]


def test_source_version_follows_imports_and_data(tmp_path):
    # thickwall imports materials: editing a material constant must change the version
    import mkm.fem.materials  # noqa: F401
    from mkm.core.records import source_version
    version = source_version("mkm.fem.thickwall")
    assert version.startswith(package_version() + "+")
    assert version == source_version("mkm.fem.thickwall")  # read from the files: stable
    assert version != source_version("mkm.fem.eq2")


def test_source_version_is_remembered_until_a_file_changes(tmp_path, monkeypatch):
    package = tmp_path / "memopkg"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "model.py").write_text("from memopkg import physics\n")
    (package / "physics.py").write_text("k = 100.0\n")
    old = time.time() - 60.0
    for path in (*package.iterdir(), package):
        os.utime(path, (old, old))
    monkeypatch.syspath_prepend(str(tmp_path))
    monkeypatch.setenv("MKM_CACHE_DIR", str(tmp_path / "cache"))
    records.source_version.cache_clear()
    first = records.source_version("memopkg.model")
    assert len(list((tmp_path / "cache" / "source-versions").iterdir())) == 1

    def no_reading(*args):
        raise AssertionError("the source was read again")

    records.source_version.cache_clear()
    with monkeypatch.context() as patch:
        patch.setattr(records, "_hash_sources", no_reading)
        assert records.source_version("memopkg.model") == first  # remembered
    # same size, another time: the edit is seen (and, just written, not remembered)
    (package / "physics.py").write_text("k = 101.0\n")
    records.source_version.cache_clear()
    second = records.source_version("memopkg.model")
    assert second != first
    records.source_version.cache_clear()
    assert records.source_version("memopkg.model") == second
    # the same module names found elsewhere (another sys.path): that code's version
    other = tmp_path / "elsewhere"
    shutil.copytree(package, other / "memopkg")
    (other / "memopkg" / "physics.py").write_text("k = 102.0\n")
    monkeypatch.syspath_prepend(str(other))
    records.source_version.cache_clear()
    assert records.source_version("memopkg.model") not in (first, second)
    records.source_version.cache_clear()


def test_package_files_exist():
    assert records.package_file("mkm.fem", "data", "paper_case_I.csv").is_file()
    assert records.package_file("mkm.surrogate", "data", "mkm_dataset.csv").is_file()
    assert records.package_file("mkm", "data", "model_errors.csv").is_file()


def test_a_recorded_path_names_no_folder_of_the_machine(tmp_path, monkeypatch):
    # was: the shipped results named /work/main/surrogate/data/mkm_design.csv and a dataset
    # /root/.cache/mkm-bench/dataset, folders of one machine and user
    monkeypatch.chdir(tmp_path)
    (tmp_path / "data").mkdir()
    assert records.recorded_path(tmp_path / "data" / "a.csv") == "data/a.csv"
    assert records.recorded_path(os.path.join("data", "a.csv")) == "data/a.csv"
    assert records.recorded_path(tmp_path.parent / "elsewhere" / "b.csv") == "b.csv"


def test_provenance_names_versions_and_command():
    info = records.provenance()
    assert {"date_utc", "command", "versions", "machine"} <= set(info)
    assert info["versions"]["numpy"] != "not installed"


def test_provenance_names_the_code_revision(tmp_path):
    # was: versions alone, whose mkm-bench 0.1.0 names every commit of a checkout alike
    root = records.CODE_ROOT
    if shutil.which("git") is None or not (root / ".git").exists():
        pytest.skip("not run from a git checkout")
    import subprocess

    described = subprocess.run(["git", "-C", str(root), "describe", "--always", "--dirty",
                                "--abbrev=12"], capture_output=True, text=True, check=True)
    assert records.provenance()["git"] == described.stdout.strip()
    (tmp_path / "pyproject.toml").write_text("")
    assert records.git_revision(tmp_path) is None  # no checkout there: a wheel's folder


@pytest.mark.parametrize("model, params, muscle", [
    ("eq2", {}, (35.0, 2.5, 0.05)),
    # past the braid lock: NaN forces and failure strings in the extras
    ("axisym", {"mesh": "coarse", "theta0_deg": 30.0}, (30.0, 2.0, 0.35))])
def test_prediction_csv_is_what_pandas_writes(model, params, muscle):
    import io
    import warnings

    import numpy as np

    from mkm.fem.ladder import make_model

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        pred = make_model(model, **params).predict(np.arange(0.0, 3.01, 0.25), *muscle)
    buf = io.StringIO()
    records.write_prediction_csv(pred, buf)
    assert buf.getvalue() == pred.to_frame().to_csv(index=False, float_format="%.6g",
                                                    lineterminator="\n")


def test_the_recorded_command_is_what_a_user_types():
    from mkm.core.records import command_line

    # `python -m mkm` puts the absolute path of mkm/__main__.py first: recorded as `mkm`
    assert command_line(["/home/lab/mkm-bench/mkm/__main__.py", "fem", "convergence"]) == \
        "mkm fem convergence"
    assert command_line(["C:\\venv\\Scripts\\mkm.exe", "demo"]) == "mkm demo"
    assert command_line(["/usr/local/bin/mkm", "report", "r1"]) == "mkm report r1"
    assert command_line(["benchmarks/bench_batch.py", "--json", "docs/measured/batch.json"]) \
        == "benchmarks/bench_batch.py --json docs/measured/batch.json"
    # a path with a space stays one argument (was: `mkm report C:\\Users\\Lab PC\\R`, two)
    assert command_line(["mkm", "report", r"C:\Users\Lab PC\R", "--muscle", ""]) == \
        r'mkm report "C:\Users\Lab PC\R" --muscle ""'


def test_a_memo_naming_files_outside_the_sources_is_not_trusted(tmp_path, monkeypatch):
    import json

    monkeypatch.setenv("MKM_CACHE_DIR", str(tmp_path / "cache"))
    records.source_version.cache_clear()
    true = records.source_version("mkm.fem.thickwall")
    (memo,) = (tmp_path / "cache" / "source-versions").iterdir()
    record = json.loads(memo.read_text())
    # whoever can write the cache adds a path of their choosing and another digest
    outside = tmp_path / "elsewhere.json"
    outside.write_text("{}")
    st = outside.stat()
    record["stat"][str(outside)] = [st.st_mtime_ns, st.st_size]
    record["digest"] = "forged000000"
    memo.write_text(json.dumps(record))
    records.source_version.cache_clear()
    assert records.source_version("mkm.fem.thickwall") == true  # hashed again, not the memo's
    records.source_version.cache_clear()


def test_a_sidecar_never_replaces_a_json_of_the_users(tmp_path):
    """``--out lab.csv`` beside the calibration ``lab.json`` used to overwrite the calibration
    with the CSV's metadata, and ``--out x.json`` wrote the CSV, then its metadata over it."""
    calibration = tmp_path / "lab.json"
    calibration.write_text('{"axisym-bonded": {"theta0_deg": 31.0}}', encoding="utf-8")
    with pytest.raises(ValueError, match=r"lab\.json is not the metadata of an earlier lab\.csv "
                       r"\(no mkm provenance in it\).* kept as it is"):
        records.write_csv_with_sidecar(tmp_path / "lab.csv", "a\n1\n", records.provenance())
    assert calibration.read_text(encoding="utf-8") == '{"axisym-bonded": {"theta0_deg": 31.0}}'
    assert not (tmp_path / "lab.csv").exists()
    with pytest.raises(ValueError, match=r"x\.json: its metadata goes to x\.json, the same "
                       "file"):
        records.write_csv_with_sidecar(tmp_path / "x.json", "a\n1\n", records.provenance())
    assert not (tmp_path / "x.json").exists()
    # the pair an earlier run wrote is rewritten when the same --out is asked again
    for value in ("1", "2"):
        records.write_csv_with_sidecar(tmp_path / "s.csv", f"a\n{value}\n",
                                       {**records.provenance(), "run": value})
    assert (tmp_path / "s.csv").read_text(encoding="utf-8") == "a\n2\n"
    assert '"run": "2"' in (tmp_path / "s.json").read_text(encoding="utf-8")


def test_a_sidecar_whose_provenance_is_nested_is_an_earlier_output(tmp_path):
    # designs.json keeps provenance() under provenance.software: a second `mkm design` into
    # the same (default) folder was refused as if designs.json were the user's
    for value in ("1", "2"):
        records.write_csv_with_sidecar(
            tmp_path / "designs.csv", f"a\n{value}\n",
            {"objective": value, "provenance": {"software": records.provenance()}})
    assert (tmp_path / "designs.csv").read_text(encoding="utf-8") == "a\n2\n"
    # a calibration file's entries each hold provenance: it is the user's file all the same
    (tmp_path / "lab.json").write_text(json.dumps({"axisym": {"theta0_deg": 31.0,
                                                              **records.provenance()}}),
                                       encoding="utf-8")
    with pytest.raises(ValueError, match=r"lab\.json is not the metadata"):
        records.write_csv_with_sidecar(tmp_path / "lab.csv", "a\n1\n", records.provenance())


def test_a_staged_folder_replaces_all_its_files_or_none(tmp_path, monkeypatch):
    # Windows cannot move a file another program holds open (a summary shown in Excel): the
    # old files already moved aside come back, none of the new ones stays, the error names it
    out = tmp_path / "report"
    out.mkdir()
    for name in ("a.csv", "b.csv", "mine.txt"):
        (out / name).write_text(f"old {name}")
    replace = os.replace

    def held_open(source, target):
        if os.fspath(out / "b.csv") in (os.fspath(source), os.fspath(target)):
            raise PermissionError(13, "Permission denied")
        replace(source, target)

    monkeypatch.setattr(records.os, "replace", held_open)
    with pytest.raises(PermissionError) as raised:
        with records.staged_folder(out, last="report.html") as stage:
            for name in ("a.csv", "b.csv", "report.html"):
                (stage / name).write_text(f"new {name}")
    assert raised.value.filename == str(out / "b.csv")
    assert {p.name: p.read_text() for p in out.iterdir()} == {
        "a.csv": "old a.csv", "b.csv": "old b.csv", "mine.txt": "old mine.txt"}
    assert [p.name for p in tmp_path.iterdir()] == ["report"]  # no staging folder left
    monkeypatch.setattr(records.os, "replace", replace)
    with records.staged_folder(out, last="report.html") as stage:
        for name in ("a.csv", "report.html"):
            (stage / name).write_text(f"new {name}")
    assert {p.name: p.read_text() for p in out.iterdir()} == {
        "a.csv": "new a.csv", "b.csv": "old b.csv", "mine.txt": "old mine.txt",
        "report.html": "new report.html"}


def test_a_file_windows_holds_open_is_named_with_what_to_do(tmp_path, monkeypatch):
    target = tmp_path / "summary.csv"
    target.write_text("old")

    def held_open(source, destination):
        raise PermissionError(13, "Permission denied", os.fspath(source), None,
                              os.fspath(destination))

    monkeypatch.setattr(records.os, "replace", held_open)
    monkeypatch.setattr(records.sys, "platform", "win32")
    with pytest.raises(PermissionError) as raised:
        records.write_atomic(target, "new")
    assert raised.value.filename == str(target)
    assert raised.value.strerror == "Permission denied"
    assert str(raised.value) == (
        f"{target} cannot be replaced (Permission denied): expected it closed in every other "
        "program (Excel holds a file it shows open) and writable by this user")
    assert target.read_text() == "old" and [p.name for p in tmp_path.iterdir()] == ["summary.csv"]


def test_a_staged_folder_removes_the_files_it_replaces_only_inside_out(tmp_path):
    out = tmp_path / "report"
    out.mkdir()
    for name in ("run1.csv", "run2.csv", "mine.txt"):
        (out / name).write_text(f"old {name}")
    (tmp_path / "outside.txt").write_text("kept")
    with records.staged_folder(out, replaces=["run1.csv", "run2.csv", "../outside.txt",
                                              str(tmp_path / "outside.txt"), ".."]) as stage:
        (stage / "run1.csv").write_text("new run1.csv")
    assert {p.name: p.read_text() for p in out.iterdir()} == {
        "run1.csv": "new run1.csv", "mine.txt": "old mine.txt"}
    assert (tmp_path / "outside.txt").read_text() == "kept"
