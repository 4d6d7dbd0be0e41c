"""The layout the wheel and the architecture check rely on: one import root, every package folder
installed, every module of the application in a layer of the import contract; and the lowest
versions ``make test-lowest`` tests are the lower bounds the project declares."""

from __future__ import annotations

import tomllib
from pathlib import Path

from packaging.requirements import Requirement
from packaging.utils import canonicalize_name
from packaging.version import Version

ROOT = Path(__file__).resolve().parent.parent
CONFIG = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))


def _package_dir() -> dict[str, str]:
    return CONFIG["tool"]["setuptools"]["package-dir"]


def test_one_import_root():
    assert {name.split(".")[0] for name in _package_dir()} == {"mkm"}
    assert CONFIG["tool"]["importlinter"]["root_packages"] == ["mkm"]


def test_every_package_folder_is_installed_under_its_name():
    found = set()
    for name, folder in _package_dir().items():
        for init in (ROOT / folder).rglob("__init__.py"):
            parts = init.parent.relative_to(ROOT / folder).parts
            found.add(".".join((name, *parts)))
    # the data folders (package data, no code) are listed too, each with its files' patterns
    data = set(CONFIG["tool"]["setuptools"]["package-data"]) - found
    for name in data:
        top = max((n for n in _package_dir() if name.startswith(n + ".")), key=len)
        folder = ROOT / _package_dir()[top] / Path(*name[len(top) + 1:].split("."))
        assert not list(folder.glob("*.py")), f"{name} holds code: expected data only"
        found.add(name)
    # the mapped folders nest (mkm.fem is in mkm/'s list only through its own mapping)
    assert set(CONFIG["tool"]["setuptools"]["packages"]) == found


def test_every_application_module_is_in_a_layer():
    (layers,) = [c["layers"] for c in CONFIG["tool"]["importlinter"]["contracts"]
                 if c["type"] == "layers"]
    named = {m.strip() for layer in layers for m in layer.replace("|", ":").split(":")}
    modules = {p.stem for p in (ROOT / "mkm").glob("*.py") if p.stem != "__init__"}
    modules |= {p.parent.name for p in (ROOT / "mkm").glob("*/__init__.py")}
    modules |= {name.split(".")[1] for name in _package_dir() if name.count(".") == 1}
    assert modules == named


def test_build_outputs_are_ignored_and_installs_are_quiet():
    """``python -m pip wheel -w dist .`` (getting started) leaves nothing for git to show, and
    the Makefile's editable installs (``make docs`` among them) print no setuptools banner: the
    banner is a UserWarning of the build backend, which inherits the environment."""
    import shutil
    import subprocess

    ignored = (ROOT / ".gitignore").read_text(encoding="utf-8").splitlines()
    assert "dist/" in ignored and "build/" in ignored
    if shutil.which("make") is None:
        return
    lines = subprocess.run(["make", "-n", "-B", ".venv/.installed-docs", ".venv/.installed",
                            ".venv/.installed-test", ".venv-lowest/.installed"], cwd=ROOT,
                           capture_output=True, text=True, check=True, timeout=60
                           ).stdout.splitlines()
    installs = [line for line in lines if "pip install" in line and " -e " in line]
    assert len(installs) == 4
    assert all(line.startswith("PYTHONWARNINGS=ignore::UserWarning ") for line in installs)


def _versions(lines, operator):
    """``{(name, extras): version}`` of the requirements' ``operator`` clauses (one each)."""
    found = {}
    for line in lines:
        requirement = Requirement(line)
        (version,) = [s.version for s in requirement.specifier if s.operator == operator]
        found[canonicalize_name(requirement.name), frozenset(requirement.extras)] = \
            Version(version)  # 1.15 is 1.15.0
    return found


def test_the_lowest_tested_versions_are_the_lower_bounds():
    """``make test-lowest`` installs tools/lowest-requirements.txt: each runtime dependency at
    its lower bound, so a bound raised or added is what that venv tests."""
    text = (ROOT / "tools" / "lowest-requirements.txt").read_text(encoding="utf-8")
    pins = _versions([line for line in text.splitlines()
                      if line.strip() and not line.startswith("#")], "==")
    bounds = _versions(CONFIG["project"]["dependencies"], ">=")
    assert pins == bounds


def _text_io_without_encoding(path: Path) -> list[str]:
    """The calls in ``path`` that open a file as text without naming its encoding: ``open``
    (``Path.open`` with a text mode), ``read_text``, ``write_text`` with neither ``encoding=``
    nor a positional one (``Path.read_text``'s first argument) nor a binary mode."""
    import ast

    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if not isinstance(node, ast.Call):
            continue
        func = node.func
        name = func.id if isinstance(func, ast.Name) else getattr(func, "attr", None)
        if name not in ("open", "read_text", "write_text"):
            continue
        if any(k.arg == "encoding" for k in node.keywords):
            continue
        texts = [a.value for a in node.args if isinstance(a, ast.Constant)
                 and isinstance(a.value, str)]
        if name == "read_text" and node.args or name == "write_text" and len(node.args) > 1:
            continue  # the encoding given positionally
        if name == "open" and (any("b" in t for t in texts) or isinstance(func, ast.Attribute)
                               and not texts):
            continue  # a binary file; a device's, an archive member's or a descriptor's open()
        found.append(f"{path.relative_to(ROOT)}:{node.lineno}")
    return found


def test_every_shipped_text_file_is_opened_with_its_encoding():
    """Windows opens text in its ANSI code page (cp1252 in Western Europe) unless told: a
    ``µs`` or a ``ü`` would be read or written differently there than on Linux."""
    found = [hit for folder in set(_package_dir().values())
             for path in sorted((ROOT / folder).rglob("*.py"))
             for hit in _text_io_without_encoding(path)]
    assert found == []
