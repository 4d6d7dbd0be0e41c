"""Records every generated file carries: provenance, atomic writes, source-code versions.

One place for the plumbing that datasets, calibrations, run folders, caches, model files and
reports share, so they cannot drift apart:

- :func:`provenance`: library versions, the code's git revision, command, machine and UTC
  date;
- :func:`write_atomic` / :func:`write_json_atomic`: a reader (or a resumed job after a crash)
  sees the old file or the new one, never half of one; files get the permissions of the user's
  umask, like any file the user makes;
- :func:`source_version`: package version plus a hash of the source of modules and of every
  project module they import, read from the files (the same code gives the same version in every
  process and on every Dask worker), and of the package data files they read;
- :func:`package_file`: a data file shipped inside a package, found through
  ``importlib.resources`` (works from a wheel, from any working directory);
- :func:`recorded_path`: a path as a record names it, with no folder of one machine.

The toolkit's own folders (the user cache, the state folder) are :mod:`mkm.core.home`'s.
"""

from __future__ import annotations

import ast
import datetime
import hashlib
import io
import json
import math
import os
import platform
import sys
import time
from collections.abc import Iterable, Iterator, Sequence
from contextlib import contextmanager
from functools import cache
from importlib.util import resolve_name
from pathlib import Path, PureWindowsPath
from typing import Any

from mkm.core.home import DISTRIBUTION, PACKAGE, package_version, user_cache

RACY_NS = 2_000_000_000  # file systems stamp times to 2 s (FAT) or finer
RECORDED_LIBRARIES = (DISTRIBUTION, "numpy", "scipy", "scikit-fem", "scikit-learn", "pandas")


# importlib.metadata, importlib.resources and tempfile are imported where used: the command line
# imports this module and starts in well under a second only without them


def command_line(argv: list[str] | None = None) -> str:
    """The command as a user types it: ``mkm fem convergence --out docs/measured`` whether it ran
    as the console script (``mkm``, ``mkm.exe``) or as ``python -m mkm`` (whose ``argv[0]`` is the
    absolute path of ``mkm/__main__.py`` on the machine that ran it)."""
    argv = list(sys.argv if argv is None else argv)
    if argv:
        first = PureWindowsPath(argv[0])  # either separator, on any system
        if first.name == "__main__.py":
            argv[0] = first.parent.name
        elif first.stem == "mkm":
            argv[0] = "mkm"
    return " ".join(map(one_argument, argv))


def one_argument(text) -> str:
    """``text`` as one argument of a command line a user copies back: in double quotes where it
    is empty or holds a space (a Windows user folder), else as it is."""
    text = str(text)
    return f'"{text}"' if not text or any(c.isspace() for c in text) else text


def provenance() -> dict[str, Any]:
    """Library versions, the code's revision (:func:`git_revision`), command line, machine and
    UTC date, recorded with every generated file."""
    return {"date_utc": datetime.datetime.now(datetime.UTC).isoformat(timespec="seconds"),
            "command": command_line(), "machine": platform.machine(),
            "versions": dict(_library_versions()), "git": git_revision()}


#: The checkout the running code lies in, if it runs from one (``mkm/core/`` is two folders
#: below it); from a wheel, the folder holding the installed package.
CODE_ROOT = Path(__file__).resolve().parents[2]


@cache
def git_revision(root: Path = CODE_ROOT) -> str | None:
    """``git describe --always --dirty`` of the checkout ``root`` (``83e6ee1a2b3c-dirty`` for
    edited files): the code itself, where the version of a checkout (``0.1.0``) names every
    commit alike. None when the code is no checkout's (a wheel: its installed version, in
    ``versions``, names it) or git cannot tell (not installed, as on a bench PC)."""
    import subprocess

    if not ((root / ".git").exists() and (root / "pyproject.toml").is_file()):
        return None
    try:
        done = subprocess.run(["git", "-C", str(root), "describe", "--always", "--dirty",
                               "--abbrev=12"], capture_output=True, text=True, timeout=10,
                              check=True)
    except (OSError, subprocess.SubprocessError):
        return None
    return done.stdout.strip() or None


@cache
def _library_versions() -> tuple[tuple[str, str], ...]:
    """Python's and :data:`RECORDED_LIBRARIES`' versions, read once per process (each is a
    metadata file parsed)."""
    from importlib.metadata import PackageNotFoundError, version

    versions = [("python", platform.python_version())]
    for pkg in RECORDED_LIBRARIES:
        try:
            versions.append((pkg, version(pkg)))
        except PackageNotFoundError:
            versions.append((pkg, "not installed"))
    return tuple(versions)


def package_file(package: str, *parts: str) -> Path:
    """Path of a data file shipped inside ``package`` (``package_file("mkm.fem", "data",
    "x.csv")``): the file itself, not a link to it (a strict editable install links each file
    of the source tree, and ``--update-shipped`` must write the source's)."""
    from importlib.resources import files

    return Path(str(files(package).joinpath(*parts))).resolve()


def write_atomic(path: str | os.PathLike, data: str | bytes, *, sync: bool = True) -> Path:
    """Write ``data`` (text as UTF-8) to ``path`` through a temporary file and ``os.replace``.

    The file is synced before the rename (``sync``), so a power loss leaves the old file or the
    new one; its permissions follow the umask (``mkstemp`` alone would make it private to its
    writer). A cache whose reader takes a damaged entry for a miss needs no sync: a sync costs
    milliseconds on a disk, more than a cheap model's whole sweep.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    import tempfile

    try:
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    except OSError as exc:  # named by the file asked for, not by its temporary
        raise type(exc)(exc.errno, exc.strerror, str(path)) from None
    try:
        follow_umask(tmp, 0o666)
        with os.fdopen(fd, "wb") as f:
            f.write(data.encode("utf-8") if isinstance(data, str) else data)
            f.flush()
            if sync:
                os.fsync(f.fileno())
        _move(Path(tmp), path, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def follow_umask(path: str | os.PathLike, mode: int) -> None:
    """Give ``path`` the permissions ``mode`` less the umask, as any file or folder the user
    makes: ``mkstemp`` and ``mkdtemp`` make theirs private to their writer."""
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(path, mode & ~umask)


@contextmanager
def staged_folder(out: str | os.PathLike, last: str | None = None,
                  record: str | None = None, replaces: Iterable[str] = ()) -> Iterator[Path]:
    """Write a folder's files whole or not at all: yields a temporary folder beside ``out``
    (same file system); when the block ends normally each file is moved into ``out`` (made if
    needed; ``last`` moved last, so its presence means the rest is there), and the temporary
    folder removed. On any error or interrupt the temporary folder is removed and ``out`` is left
    as it was: a full disk or a Ctrl-C leaves no partial output. ``replaces`` names the files
    the previous output wrote there: those the block did not write again go too (a report of
    six runs replaced by one of two leaves no run3_errors.csv behind); other files of ``out``
    (a user's) are left alone.

    The files it replaces are moved aside first, all of them before any new one comes in: on
    Windows a file another program holds open (a summary.csv shown in Excel) cannot be moved,
    and the old ones already moved go back, so ``out`` never mixes this run's files with the
    last one's.

    With ``record`` (the name of the JSON file among them that holds mkm's provenance), a file
    of ``out`` is replaced only when ``out`` is a folder the command wrote before: else
    ``ValueError`` names the first file in the way and ``out`` is left as it was
    (:func:`check_output_folder`)."""
    import shutil
    import tempfile

    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    try:
        stage = Path(tempfile.mkdtemp(prefix=f".{out.name}.", suffix=".partial", dir=out.parent))
    except OSError as exc:  # named by the folder asked for, not by its temporary
        raise type(exc)(exc.errno, exc.strerror, str(out)) from None
    try:
        yield stage
        names = sorted(p.name for p in stage.iterdir())
        if record is not None:
            check_output_folder(out, names, record)
        out.mkdir(exist_ok=True)
        if last in names:
            names.remove(last)
            names.append(last)
        # a plain name only: a manifest read from out must not reach outside it
        stale = sorted({n for n in replaces if Path(n).name == n and n not in ("", ".", "..")
                        and n not in names and (out / n).is_file()})
        _swap_in(stage, out, names, stale)
    finally:
        shutil.rmtree(stage, ignore_errors=True)


def _swap_in(stage: Path, out: Path, names: list[str], stale: Sequence[str] = ()) -> None:
    """Move ``names`` from ``stage`` into ``out``, the files they replace and the ``stale``
    ones moved aside into ``stage``'s ``.old`` first; an error restores ``out`` as it was and is
    raised naming the file in ``out``."""
    aside = stage / ".old"
    aside.mkdir()
    moved_aside: list[str] = []
    moved_in: list[str] = []
    try:
        for name in [*names, *stale]:
            if (out / name).exists() or (out / name).is_symlink():
                _move(out / name, aside / name, out / name)
                moved_aside.append(name)
        for name in names:
            _move(stage / name, out / name, out / name)
            moved_in.append(name)
    except BaseException:
        for name in moved_in:
            (out / name).unlink(missing_ok=True)
        for name in moved_aside:
            os.replace(aside / name, out / name)
        raise


class HeldOpen(PermissionError):
    """A file Windows would not replace: mostly one another program holds open (a summary.csv
    shown in Excel), else a read-only one. ``strerror`` is the system's words; the message
    says both causes in one line (a command adds that its files are as they were)."""

    def __str__(self) -> str:
        return (f"{self.filename} cannot be replaced ({self.strerror}): expected it closed in "
                "every other program (Excel holds a file it shows open) and writable by this "
                "user")


def _move(source: Path, target: Path, named: Path) -> None:
    try:
        os.replace(source, target)
    except OSError as exc:  # named by the user's file; on Windows mostly one held open
        kind = HeldOpen if sys.platform == "win32" and isinstance(exc, PermissionError) else \
            type(exc)
        raise kind(exc.errno, exc.strerror or str(exc), str(named)) from None


def write_json_atomic(path: str | os.PathLike, data: Any) -> Path:
    """:func:`write_atomic` of ``data`` as indented JSON (numpy values as lists or text)."""
    return write_atomic(path, json.dumps(data, indent=2, default=jsonable) + "\n")


def finite_or_null(data: Any) -> Any:
    """``data`` with every NaN or infinity as None, so ``json.dumps`` writes ``null`` (JSON has
    no NaN: jq, browsers and strict parsers refuse a file holding one); dicts, lists, tuples
    and numpy values followed."""
    if isinstance(data, dict):
        return {k: finite_or_null(v) for k, v in data.items()}
    if isinstance(data, (list, tuple)):
        return [finite_or_null(v) for v in data]
    if hasattr(data, "tolist") and not isinstance(data, (str, bytes)):
        return finite_or_null(data.tolist())
    if isinstance(data, float) and not math.isfinite(data):
        return None
    return data


def jsonable(value):
    """``json.dumps`` default: numpy arrays and scalars as lists and numbers, else ``str``."""
    if hasattr(value, "tolist"):
        return value.tolist()
    return str(value)


@cache
def source_version(*modules: str, data: bool = True) -> str:
    """``<package version>+<hash>`` of ``modules``, every project module they import at any depth
    (read from the source, not from ``sys.modules``), and the ``*.json`` data files of each
    package directory involved (the calibration): editing the physics, a material constant or the
    calibration changes the version; editing a report does not. ``data=False`` hashes the source
    only (the version a calibration records of the code that made it).

    The result is remembered in the user cache with the file each module was found in and the
    size and modification time of every file and folder it read (Python's own test for a stale
    bytecode file), so a command that checks a cached model does not re-read the project's
    source each time it starts.
    """
    memo = user_cache("source-versions", _memo_name(modules, data))
    digest = _read_memo(memo, {PACKAGE} | {m.split(".")[0] for m in modules})
    if digest is None:
        digest, origins, paths = _hash_sources(modules, data)
        stats = {p: _stat(p) for p in paths}
        # a file changed within the clock's granularity of now could change again unseen
        # (git's "racy" files): remembered only once every file is older than that
        settled = time.time_ns() - RACY_NS
        try:
            if all(mtime_ns < settled for mtime_ns, _ in stats.values()):
                write_json_atomic(memo, {"digest": digest, "modules": origins, "stat": stats})
        except OSError:  # a read-only cache costs time, never a wrong version
            pass
    return f"{package_version()}+{digest}"


def _memo_name(modules, data: bool) -> str:
    key = json.dumps([sorted(modules), data, sys.prefix])
    return hashlib.sha256(key.encode()).hexdigest()[:20] + ".json"


def _stat(path: str) -> list[int]:
    st = os.stat(path)
    return [st.st_mtime_ns, st.st_size]


def _read_memo(memo: Path, packages: set[str]) -> str | None:
    """The remembered digest if every module still comes from the file it was read from (another
    ``sys.path`` may find other code) and every file and folder is unchanged."""
    try:
        record = json.loads(memo.read_text(encoding="utf-8"))
        if (all(getattr(_spec(name), "origin", None) == origin
                for name, origin in record["modules"].items())
                and _only_sources(record["modules"], record["stat"], packages)
                and all(_stat(path) == list(known) for path, known in record["stat"].items())):
            return str(record["digest"])
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        pass
    return None


def _only_sources(origins: dict[str, str], stats: dict[str, Any], packages: set[str]) -> bool:
    """Whether a memo's paths are the ones :func:`_hash_sources` lists for its modules (their
    files, their folders, the data files in those folders) and its modules of ``packages``: a
    memo made up by whoever can write the cache names nothing else."""
    if not all(name.split(".")[0] in packages for name in origins):
        return False
    files = {Path(o) for o in origins.values()}
    folders = {f.parent for f in files}
    return all(p in files or p in folders or (p.suffix == ".json" and p.parent in folders)
               for p in map(Path, stats))


def _hash_sources(modules, data: bool) -> tuple[str, dict[str, str], list[str]]:
    """The digest of :func:`source_version`, the file each module was read from, and every path
    the digest depends on (source files, data files, the folders whose data files were listed)."""
    packages = {PACKAGE} | {m.split(".")[0] for m in modules}
    sources: dict[str, bytes] = {}
    origins: dict[str, str] = {}
    stack = list(modules)
    while stack:
        module = stack.pop()
        if module in sources:
            continue
        spec = _spec(module)
        if spec is None or not spec.origin or not spec.origin.endswith(".py"):
            continue
        origins[module] = spec.origin
        sources[module] = Path(spec.origin).read_bytes()
        package = spec.name if spec.submodule_search_locations else spec.parent
        for node in ast.walk(ast.parse(sources[module])):
            if isinstance(node, ast.Import):
                names = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = resolve_name("." * node.level + (node.module or ""), package)
                names = [base] + [f"{base}.{alias.name}" for alias in node.names]
            else:
                continue
            stack.extend(n for n in names if n.split(".")[0] in packages
                         and n not in sources and _is_module(n))
    # a module or data file added to a folder changes the folder's time
    folders = {Path(origin).parent for origin in origins.values()}
    data_files = {path for folder in folders for path in folder.glob("*.json")} if data else set()
    digest = hashlib.sha256()
    for module in sorted(sources):
        digest.update(module.encode() + b"\0" + sources[module])
    for path in sorted(data_files):
        digest.update(path.name.encode() + b"\0" + path.read_bytes())
    paths = [str(p) for p in (*origins.values(), *folders, *data_files)]
    return digest.hexdigest()[:12], origins, paths


def _is_module(name: str) -> bool:
    return _spec(name) is not None  # "mkm.fem.calibration.calibrated": a name, not a module


def _spec(name: str):
    """The spec of module ``name`` as the import system finds it, or None, without executing any
    module (``importlib.util.find_spec`` imports the parent packages: the whole model stack)."""
    if name in sys.modules:
        return getattr(sys.modules[name], "__spec__", None)
    parent, _, _ = name.rpartition(".")
    path = None
    if parent:
        parent_spec = _spec(parent)
        if parent_spec is None or parent_spec.submodule_search_locations is None:
            return None
        path = list(parent_spec.submodule_search_locations)
    for finder in sys.meta_path:
        find = getattr(finder, "find_spec", None)
        spec = find(name, path) if find is not None else None
        if spec is not None:
            return spec
    return None


def file_sha256(path: str | os.PathLike) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def recorded_path(path: str | os.PathLike) -> str:
    """``path`` as a record others read names it, naming no folder of the machine that wrote it
    (a user's name, a temporary folder, a checkout): relative to the working directory, parts
    joined by ``/``, where it lies in it (as the command was typed there); else its name alone,
    which the sha256 recorded beside it identifies."""
    path = Path(os.path.abspath(path))
    try:
        return path.relative_to(os.path.abspath(os.getcwd())).as_posix()
    except ValueError:  # elsewhere, or on another drive
        return path.name


#: What makes a spreadsheet read a text cell as a formula (or a DDE command): OWASP's list.
FORMULA_LEAD = ("=", "+", "-", "@", "\t", "\r")


def spreadsheet_safe_text(text: str) -> str:
    """``text`` with a leading ``'`` if it starts like a formula (:data:`FORMULA_LEAD`), so
    Excel, LibreOffice and Sheets show it as text instead of evaluating it. Judged on the cell
    as a spreadsheet reads it: leading spaces and line breaks stripped, and full-width forms
    (``＝``, ``＋``) folded to ASCII (NFKC), since some spreadsheets accept those too."""
    import unicodedata

    lead = unicodedata.normalize("NFKC", text[:64]).lstrip(" \n\v\f\u00a0\u3000")
    return "'" + text if lead.startswith(FORMULA_LEAD) or text.startswith(FORMULA_LEAD) \
        else text


def spreadsheet_safe(frame):
    """A copy of the DataFrame ``frame`` whose text cells cannot run as spreadsheet formulas
    (:func:`spreadsheet_safe_text`); numbers are left alone."""
    out = frame.copy()
    for column in out.columns:
        values = out[column]
        if values.dtype == object or "str" in str(values.dtype):
            out[column] = values.map(lambda v: spreadsheet_safe_text(v) if isinstance(v, str)
                                     else v)
    return out


def sidecar_path(path: str | os.PathLike) -> Path:
    """The JSON file that holds a CSV's metadata: ``sweep.csv`` -> ``sweep.json``."""
    return Path(path).with_suffix(".json")


def holds_provenance(path: Path) -> bool:
    """Whether ``path`` is a record written by mkm: an object holding :func:`provenance` at its
    top, as its ``software`` (a dataset's), its ``provenance`` (identification.json) or its
    ``provenance.software`` (designs.json). Nowhere else: a calibration file's entries each
    hold one, and it is the user's file, never a record of an output."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    if not isinstance(data, dict):
        return False
    nested = data.get("provenance")
    places = (data, data.get("software"), nested,
              nested.get("software") if isinstance(nested, dict) else None)
    return any(isinstance(d, dict) and {"date_utc", "command"} <= d.keys() for d in places)


#: the names of workbooks: CSV text in such a file is a file Excel refuses to open
WORKBOOK_SUFFIXES = (".xlsx", ".xlsm", ".xls", ".ods")


def check_csv_with_sidecar(path: str | os.PathLike, workbook: bool = False) -> Path:
    """``path`` if a CSV (``workbook``: an ``.xlsx`` workbook) and its sidecar
    (:func:`sidecar_path`) may be written there, else ``ValueError`` naming the file in the way
    or, for a CSV, a workbook's name (CSV text in it is a file Excel refuses to open). The
    sidecar's name comes from the CSV's, so the user never named it: ``--out lab.csv`` must not
    replace the lab's calibration ``lab.json``, nor ``--out sweep.json`` the CSV by its own
    metadata. Each file must be new or an earlier output (its sidecar holding mkm's
    provenance)."""
    path = Path(path)
    if not workbook and path.suffix.lower() in WORKBOOK_SUFFIXES:
        raise ValueError(f"{path}: a workbook's name, and this table is written as CSV: "
                         f"expected a .csv name ({path.with_suffix('.csv').name})")
    sidecar = sidecar_path(path)
    if sidecar == path:
        raise ValueError(f"{path}: its metadata goes to {sidecar.name}, the same file: expected "
                         "a .csv name")
    if sidecar.exists() and not holds_provenance(sidecar):
        raise ValueError(f"{sidecar} is not the metadata of an earlier {path.name} (no mkm "
                         f"provenance in it), and {path.name}'s would replace it: kept as it is; "
                         "expected another name for the CSV")
    if path.is_file() and not sidecar.exists():
        raise ValueError(f"{path} exists and was not written by mkm (no {sidecar.name} beside "
                         "it): kept as it is; expected a new name for the CSV")
    return path


def check_output_folder(out: str | os.PathLike, names, record: str) -> Path:
    """``out`` if a command may write the files ``names`` into it: each is new there, or ``out``
    is a folder the command wrote before (its ``record``, one of ``names``, a JSON file holding
    mkm's provenance: :func:`holds_provenance`); else ``ValueError`` naming the file in the way.
    A run folder or a lab's own folder holds ``steps.csv`` and ``calibration.json`` too."""
    out = Path(out)
    if holds_provenance(out / record):
        return out
    for name in names:
        if (out / name).exists():
            raise ValueError(f"{out / name} exists and {out} is not a folder this command wrote "
                             f"(no {record} of mkm's in it): kept as it is; expected --out to "
                             "name a new folder or an earlier output of the same command")
    return out


def png_metadata() -> dict[str, str]:
    """The provenance a PNG carries in its text chunks (any image viewer's properties list
    them), since a figure is often copied away from the folder whose JSON records it: the
    code's version, the command, the UTC date and the whole :func:`~mkm.core.records.provenance`
    as JSON."""
    record = provenance()
    return {"Software": f"{DISTRIBUTION} {record['versions'][DISTRIBUTION]}",
            "Command": record["command"], "Creation Time": record["date_utc"],
            "Provenance": json.dumps(record, default=str)}


def save_figure(fig, path: Path) -> Path:
    """``fig`` as a PNG at ``path``, its provenance inside (:func:`png_metadata`)."""
    fig.savefig(path, dpi=110, metadata=png_metadata())
    return path


#: The encoding of the CSV files written for people to open in a spreadsheet (those made
#: :func:`spreadsheet_safe`: an export's steps, samples and metadata, a report's summary and
#: per-run errors, an identification's parameters and steps): UTF-8 with a byte-order mark,
#: without which Excel on Windows reads UTF-8 as its ANSI code page and shows 'Müller' as
#: 'MÃ¼ller' and 'µm' as 'Âµm'. Every reader of the toolkit reads UTF-8 with or without the
#: mark (pandas and :func:`read_csv_checked` skip it, text is opened as ``utf-8-sig``). A run
#: folder's own files, appended to while the bench records, stay plain UTF-8.
SPREADSHEET_CSV_ENCODING = "utf-8-sig"

#: The forms ``mkm export`` writes a run in: each name and what it makes at ``--out``.
EXPORT_FORMATS = {"xlsx": "one .xlsx workbook of three sheets",
                  "csv": "a folder of steps.csv, samples.csv and metadata.csv"}


def read_csv_checked(path: str | os.PathLike, what: str, expected: str, columns=(),
                     numeric=(), comment: str | None = None):
    """The CSV table at ``path`` as a pandas DataFrame, with ``columns``, those of ``numeric``
    all numbers; ``ValueError`` in one line naming the file (``what``: its kind, as a message
    names it) and ``expected`` when it does not exist, is no CSV table, lacks a column or holds
    text where numbers belong (pandas' own messages run over two lines and name no file)."""
    import pandas as pd

    path = Path(path)
    if not path.is_file():
        raise ValueError(f"{what} {str(path)!r} does not exist: {expected}")
    try:
        frame = pd.read_csv(path, comment=comment, encoding="utf-8-sig")  # BOM or none
    except (pd.errors.ParserError, pd.errors.EmptyDataError, UnicodeDecodeError) as exc:
        first = (str(exc).strip().splitlines() or [type(exc).__name__])[0]
        raise ValueError(f"{what} {str(path)!r} is no CSV table ({first}): {expected}") from None
    missing = [c for c in columns if c not in frame.columns]
    if missing:
        raise ValueError(f"{what} {str(path)!r} lacks column(s) {', '.join(missing)}: "
                         f"{expected}")
    text = [c for c in numeric if not pd.api.types.is_numeric_dtype(frame[c])]
    if text:
        raise ValueError(f"{what} {str(path)!r} has a column {text[0]} that is not all numbers: "
                         f"{expected}")
    return frame


def write_csv_with_sidecar(path: str | os.PathLike, csv_text: str, metadata: dict) -> Path:
    """A plain CSV (no comment lines: spreadsheets read those as data) at ``path`` and its
    metadata as JSON beside it (:func:`sidecar_path`), both written atomically; ``ValueError``
    before anything is written when either would replace a file the user has
    (:func:`check_csv_with_sidecar`)."""
    path = write_atomic(check_csv_with_sidecar(path), csv_text)
    write_json_atomic(sidecar_path(path), metadata)
    return path


def write_workbook_with_sidecar(path: str | os.PathLike, frame, metadata: dict) -> Path:
    """The DataFrame ``frame`` as an ``.xlsx`` workbook of one sheet at ``path`` (numbers as
    numbers, whatever the spreadsheet's decimal separator: a German Excel opens a CSV in one
    column) and its metadata as JSON beside it, as :func:`write_csv_with_sidecar` does."""
    import pandas as pd  # here: the command line starts without pandas

    buffer = io.BytesIO()
    with pd.ExcelWriter(buffer, engine="openpyxl") as book:
        spreadsheet_safe(frame).to_excel(book, sheet_name=Path(path).stem[:31] or "table",
                                         index=False)
    path = write_atomic(check_csv_with_sidecar(path, workbook=True), buffer.getvalue())
    write_json_atomic(sidecar_path(path), metadata)
    return path


def prediction_metadata(prediction) -> dict[str, Any]:
    """Model, parameters, timing, number of points and provenance of a prediction."""
    return {"model": prediction.model, "params": prediction.params,
            "seconds": prediction.seconds, "n_points": int(prediction.force_N.size),
            **provenance()}


def write_prediction_csv(prediction, buf) -> None:
    """The prediction as a plain CSV (one row per point) into the text stream ``buf``; its
    metadata (:func:`prediction_metadata`) goes to a JSON sidecar when written to a file
    (:func:`write_csv_with_sidecar`).

    Written with the ``csv`` module, not pandas (a closed-form solve answers at once): the text
    is what ``to_frame().to_csv(index=False, float_format="%.6g")`` writes, empty cells for NaN.
    """
    import csv

    columns = prediction.columns()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(columns)
    cells = [[_csv_cell(v) for v in values.tolist()] for values in columns.values()]
    writer.writerows(zip(*cells, strict=True))


def _csv_cell(value) -> str:
    if isinstance(value, float):
        return "" if value != value else f"{value:.6g}"  # NaN: an empty cell
    return "" if value is None else str(value)


def read_prediction_header(path) -> dict[str, Any]:
    """The metadata of a CSV: its JSON sidecar, or (files written before sidecars) its
    ``# key: value`` comment lines (values parsed as JSON where they are JSON). A sidecar that
    is no JSON object (cut short, edited) is a one-line ``ValueError`` naming it."""
    sidecar = sidecar_path(path)
    if sidecar.is_file():
        expected = f"expected the JSON object of metadata mkm writes beside {Path(path).name}"
        try:
            header = json.loads(sidecar.read_text(encoding="utf-8-sig"))
        except (ValueError, RecursionError) as exc:  # UnicodeDecodeError is a ValueError
            first = (str(exc).splitlines() or [type(exc).__name__])[0][:80]
            raise ValueError(f"{sidecar} is not valid JSON ({first}): {expected}") from None
        if not isinstance(header, dict):
            raise ValueError(f"{sidecar} holds a JSON {type(header).__name__}: {expected}")
        return header
    header = {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("#"):
                break
            key, sep, value = line[1:].strip().partition(":")
            if sep:
                try:
                    header[key.strip()] = json.loads(value)
                except ValueError:
                    header[key.strip()] = value.strip()
    return header
