"""Commands write only under their --out (default ./mkm-out) and the user's cache, never over
the files that ship with the project (mkm.paths)."""

from __future__ import annotations

import argparse
import contextlib
import hashlib
import io
import json
import re
import subprocess
from pathlib import Path

import pytest

from mkm.cli import build_parser, main
from mkm.paths import cache_root, default_out, output_root

ROOT = Path(__file__).resolve().parents[2]


def _subparsers(parser, prefix=()):
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield (*prefix, name), sub
                yield from _subparsers(sub, (*prefix, name))


def test_every_default_output_is_under_mkm_out_or_the_user_cache():
    checked = 0
    for name, sub in _subparsers(build_parser()):
        for action in sub._actions:
            if action.dest in ("out", "cache") and action.default is not None:
                path = Path(action.default)
                assert (path.is_relative_to(output_root()) or path.is_relative_to(cache_root())), \
                    f"mkm {' '.join(name)} {action.option_strings[0]} defaults to {path}"
                checked += 1
    assert checked >= 6  # acquire, dataset, convergence, surrogate grid/test/reference, ...


def test_default_out_follows_mkm_out(monkeypatch, tmp_path):
    monkeypatch.setenv("MKM_OUT", str(tmp_path))
    assert default_out("report", "x") == tmp_path / "report" / "x"
    monkeypatch.delenv("MKM_OUT")
    assert default_out("study") == Path("mkm-out") / "study"


def _shipped_hashes() -> dict[str, str]:
    """SHA-256 of every tracked file that is data (what a command could rewrite)."""
    files = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True,
                           check=True).stdout.decode().split("\0")
    data = [f for f in files if f and Path(f).suffix in {".csv", ".json", ".toml"}]
    return {f: hashlib.sha256((ROOT / f).read_bytes()).hexdigest() for f in data
            if (ROOT / f).exists()}


@pytest.fixture(scope="module")
def first_demo(tmp_path_factory):
    """``mkm demo`` run once from an empty folder with the default output root, for the tests
    below: the folder, the shipped files' hashes before it (None outside a git work tree) and
    the last line it printed."""
    folder = tmp_path_factory.mktemp("cwd")
    before = _shipped_hashes() if (ROOT / ".git").exists() else None
    out = io.StringIO()
    with pytest.MonkeyPatch.context() as mp, contextlib.redirect_stdout(out):
        mp.chdir(folder)
        mp.delenv("MKM_OUT", raising=False)
        mp.setenv("XDG_CACHE_HOME", str(folder / "cache"))
        assert main(["demo", "--no-progress"]) == 0
    return folder, before, Path(out.getvalue().splitlines()[-1])


@pytest.mark.slow  # the demo trains the default surrogate
@pytest.mark.skipif(not (ROOT / ".git").exists(), reason="not a git work tree")
def test_demo_and_report_leave_the_shipped_files_alone(first_demo, monkeypatch, capsys):
    folder, before, report = first_demo
    monkeypatch.chdir(folder)
    monkeypatch.delenv("MKM_OUT", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(folder / "cache"))
    runs = sorted((folder / "mkm-out" / "demo" / "runs").iterdir())
    assert main(["report", *map(str, runs), "--models", "eq2,thickwall", "--no-progress"]) == 0
    again = Path(capsys.readouterr().out.splitlines()[-1])
    # defaults: ./mkm-out/demo/report and ./mkm-out/report/<first run>
    assert report == Path("mkm-out") / "demo" / "report" / "report.html"
    assert again == Path("mkm-out") / "report" / runs[0].name / "report.html"
    assert (folder / again).is_file()
    assert _shipped_hashes() == before


def test_one_cache_folder_for_predictions_surrogates_and_dataset_jobs(tmp_path, monkeypatch):
    from mkm.fem.dataset.build import default_cache_dir as dataset_cache
    from mkm.prediction_cache import DEFAULT_CACHE_DIR
    from mkm.surrogate.train import default_cache_dir as surrogate_cache

    # resolved at each use: MKM_CACHE_DIR set after import moves all three
    monkeypatch.setenv("MKM_CACHE_DIR", str(tmp_path / "elsewhere"))
    folders = {Path(DEFAULT_CACHE_DIR).parent, surrogate_cache().parent, dataset_cache().parent}
    assert folders == {tmp_path / "elsewhere"}
    monkeypatch.delenv("MKM_CACHE_DIR")
    folders = {Path(DEFAULT_CACHE_DIR).parent, surrogate_cache().parent, dataset_cache().parent}
    assert len(folders) == 1 and folders.pop().is_absolute()


@pytest.mark.slow  # a second whole demo
def test_a_demo_replaces_the_runs_of_the_demo_before_it(first_demo):
    from mkm.demo import run_demo

    demo = first_demo[0] / "mkm-out" / "demo"
    keep = demo / "runs" / "my-own-folder"
    keep.mkdir(parents=True, exist_ok=True)  # not the demo's: never touched
    first = sorted(p.name for p in (demo / "runs").iterdir())
    run_demo(demo, progress=False, models=["eq2"], tolerance=None, surrogate_section=False,
             cache_dir=None)
    second = sorted(p.name for p in (demo / "runs").iterdir())
    assert len(first) == len(second) == 3 and "my-own-folder" in second
    assert all(name.endswith("-SIMULATED") for name in second if name != "my-own-folder")
    # its record says which runs, and, as every file written, by which command, code and when
    from mkm.core.records import holds_provenance

    record = json.loads((demo / "demo.json").read_text(encoding="utf-8"))
    assert sorted(record["runs"]) == [name for name in second if name != "my-own-folder"]
    assert holds_provenance(demo / "demo.json") and "versions" in record and "git" in record


# what a user runs, as the documentation shows it (the developer guide's commands are run in a
# checkout and may name its files)
USER_DOCS = [ROOT / "README.md", ROOT / "docs" / "getting-started.md",
             ROOT / "docs" / "published.md", *sorted((ROOT / "docs" / "guide").glob("*.md"))]


def test_every_documented_import_reads_a_table_a_wheel_user_has():
    """``mkm import FILE`` as the docs show it names the user's own table or a shipped one that
    ``mkm data copy`` wrote into the working folder before it (was: the source tree's
    ``data/published/...``, which a wheel does not hold)."""
    from mkm.paths import published_tables

    shipped = published_tables()
    assert "martens_boblan_2017_forcemaps.csv" in shipped
    seen = 0
    for doc in USER_DOCS:
        text = doc.read_text("utf-8")
        for found in re.finditer(r"^\s*mkm import (\S+)", text, re.MULTILINE):
            table = found.group(1)
            seen += 1
            assert "/" not in table and "\\" not in table, f"{doc.name}: mkm import {table}"
            if table in shipped:
                assert f"mkm data copy {table}" in text[:found.start()], \
                    f"{doc.name}: mkm import {table} without mkm data copy {table} before it"
    assert seen >= 3


def test_data_copy_writes_the_shipped_table_byte_for_byte(tmp_path, monkeypatch, capsys):
    """``mkm data copy NAME`` writes the published table into the working folder (a path with a
    space and a non-ASCII letter here), its SHA-256 the one its README records, is that copy
    again when run twice, and keeps an existing file of other bytes; ``mkm data path`` and
    ``list`` name the installed file."""
    name = "martens_boblan_2017_forcemaps.csv"
    work = tmp_path / "Prüfstand 1"
    work.mkdir()
    monkeypatch.chdir(work)
    assert main(["data", "copy", name]) == 0
    copied = capsys.readouterr()
    assert copied.out.strip() == name
    # the path alone said nothing of what to do with it
    assert copied.err == (f"mkm data copy: note: import it with mkm import {name} --id ID --D0 "
                          "MM --t0 MM --muscle NAME (its # header names its muscles and their "
                          "geometry; the guide's run folders page gives the lines for each)\n")
    digest = hashlib.sha256((work / name).read_bytes()).hexdigest()
    readme = (ROOT / "mkm" / "data" / "published" / "README.md").read_text("utf-8")
    assert f"SHA-256 `{digest}`" in readme
    # the same copy again (a script run twice, `set -e`): that copy, not an error
    assert main(["data", "copy", name]) == 0
    assert capsys.readouterr().out.strip() == name
    shipped = (work / name).read_bytes()
    (work / name).write_bytes(shipped + b"# edited\n")
    assert main(["data", "copy", name]) == 2  # another file: kept, said in one line
    assert "exists: kept as it is" in capsys.readouterr().err
    assert (work / name).read_bytes() == shipped + b"# edited\n"
    (work / name).write_bytes(shipped)
    # was "sub: no such folder", naming neither the argument nor what was expected
    assert main(["data", "copy", name, "sub/maps.csv"]) == 2
    assert capsys.readouterr().err == ("mkm data copy: error: TO 'sub/maps.csv': no such folder "
                                       "'sub': expected the file in an existing folder (make it "
                                       "first)\n")
    # was: a file named 'sub' (the slash dropped) and one named 'maps', neither a table that
    # mkm import reads ("unknown table format ''")
    assert main(["data", "copy", name, "sub/"]) == 2
    assert capsys.readouterr().err == ("mkm data copy: error: TO 'sub/': no such folder: "
                                       "expected an existing folder (make it first) or a file "
                                       "name ending in .csv\n")
    assert main(["data", "copy", name, "maps"]) == 2
    assert capsys.readouterr().err == ("mkm data copy: error: TO 'maps' is neither an existing "
                                       "folder nor a file name ending in .csv: expected one of "
                                       "them (mkm import reads the table by its suffix)\n")
    assert sorted(p.name for p in work.iterdir()) == [name]
    # into a folder with a space: the command said was two arguments where one was meant
    (work / "Lab Data").mkdir()
    assert main(["data", "copy", name, "Lab Data"]) == 0
    assert capsys.readouterr().err.startswith(
        f'mkm data copy: note: import it with mkm import "{Path("Lab Data") / name}" --id ID ')
    (work / "sub").mkdir()
    assert main(["data", "copy", name, "sub/"]) == 0
    assert capsys.readouterr().out.strip() == str(Path("sub") / name)
    (work / "sub" / name).unlink()
    assert main(["data", "copy", name, "sub"]) == 0
    assert capsys.readouterr().out.strip() == str(Path("sub") / name)
    assert main(["data", "path", name]) == 0
    path = Path(capsys.readouterr().out.strip())
    assert not path.is_symlink()  # mkm import refuses links (a strict editable install's)
    assert path.read_bytes() == (work / name).read_bytes()
    assert main(["data", "list"]) == 0
    assert capsys.readouterr().out.split("\t")[0] == name
    assert main(["data", "path", "nope.csv"]) == 2
    assert capsys.readouterr().err.startswith("mkm data path: error: 'nope.csv' is not a shipped")
    # the copy imports as the documentation shows it
    assert main(["import", name, "--id", "dmsp-20", "--D0", "20", "--t0", "1.8", "--muscle",
                 "Festo DMSP-20-300", "--out", "runs"]) == 0
    assert len(capsys.readouterr().out.split()) == 6  # one run per length


SOURCE_TREE_ONLY = ("data/", "examples/", "benchmarks/", "tests/", "docs/", "tools/")


def test_the_documented_python_reads_no_file_of_the_source_tree():
    """The Python the user docs show runs from a wheel: no path into the checkout (was:
    ``load_run("data/experimental/...")`` in the README and the run-folder page, a folder the
    wheel does not hold)."""
    checked = 0
    for doc in USER_DOCS:
        for block in re.findall(r"```python\n(.*?)```", doc.read_text("utf-8"), re.DOTALL):
            checked += 1
            for literal in re.findall(r"[\"']([^\"'\n]+)[\"']", block):
                assert not literal.replace("\\", "/").startswith(SOURCE_TREE_ONLY), \
                    f"{doc.name}: {literal!r} is a path of the source tree"
    assert checked >= 2


def test_every_documented_out_is_in_the_working_folder():
    """``--out`` in a command the user docs show names no folder of the installed package's
    sources (was: ``mkm fem dataset ... --out surrogate/data/mkm_dataset.csv``, the checkout's
    shipped file; from a wheel a stray ./surrogate/data/ folder)."""
    packages = ("mkm/", "bench/", "fem/", "surrogate/")
    seen = 0
    for doc in USER_DOCS:
        for line in doc.read_text("utf-8").splitlines():
            command = line.strip()
            if not command.startswith("mkm "):
                continue
            for out in re.findall(r"--out\s+(\S+)", command):
                seen += 1
                assert not out.replace("\\", "/").startswith(packages), f"{doc.name}: {command}"
    assert seen >= 10
