"""The documentation builds (``make docs``: Sphinx, warnings as errors, no network) and every
public function and class of ``mkm``, ``mkm.fem``, ``mkm.bench`` and ``mkm.surrogate`` has a page
in its API reference."""

import importlib
import inspect
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
DOCS = ROOT / "docs"


def _generate():
    sys.path.insert(0, str(DOCS))
    try:
        return importlib.import_module("generate")
    finally:
        sys.path.remove(str(DOCS))


def public_names(module_name: str) -> set[str]:
    """What a module offers: its ``__all__``, else the functions and classes it defines whose
    names have no leading underscore (what autodoc's ``:members:`` documents)."""
    module = importlib.import_module(module_name)
    if hasattr(module, "__all__"):
        return set(module.__all__)
    return {name for name, obj in vars(module).items() if not name.startswith("_")
            and (inspect.isfunction(obj) or inspect.isclass(obj))
            and obj.__module__ == module_name}


def test_every_public_module_of_the_four_packages_is_walked():
    modules = _generate().all_modules()
    for package in ("mkm", "mkm.fem", "mkm.bench", "mkm.surrogate"):
        assert package in modules
    # the mapped folders (bench/, fem/, surrogate/) are walked too, subpackages included
    assert {"mkm.bench.storage", "mkm.fem.fe.model", "mkm.fem.dataset.grid",
            "mkm.surrogate.kinds", "mkm.cli.fem", "mkm.registry"} <= set(modules)


@pytest.mark.slow
def test_the_site_builds_with_warnings_as_errors_and_documents_every_public_name(tmp_path):
    pytest.importorskip("sphinx", reason="the docs extra is not installed (pip install .[docs])")
    from sphinx.util.inventory import InventoryFile

    html = tmp_path / "html"
    done = subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "--keep-going", "-E", "-q", "-b", "html",
         str(DOCS), str(html)], capture_output=True, text=True, timeout=900,
        env={**__import__("os").environ, "MPLBACKEND": "Agg"})
    assert done.returncode == 0, done.stderr[-4000:]
    for page in ("index", "getting-started", "validation", "developer", "whats-new",
                 "guide/force-models", "guide/bench", "_generated/examples/index",
                 "_generated/api/index"):
        assert (html / f"{page}.html").is_file(), page

    with open(html / "objects.inv", "rb") as f:
        inventory = InventoryFile.load(f, "", lambda base, uri: uri)
    documented = {name: uri for kind in ("py:module", "py:function", "py:class", "py:data",
                                         "py:exception", "py:attribute")
                  for name, (_, _, uri, _) in _items(inventory.get(kind, {}))}
    generate, missing = _generate(), []
    for module in generate.all_modules():
        if module not in documented:
            missing.append(module)
        for name in public_names(module):
            target = f"{generate.defining_module(module, name)}.{name}"
            if target not in documented:
                missing.append(target)
    assert not missing, f"no API page for {sorted(set(missing))}"
    # a page, not only an entry: the anchors point into the generated API pages
    assert documented["mkm.fem.eq2.chou_hannaford"].startswith("_generated/api/mkm.fem.eq2.html")


def _items(entries):
    """``(name, (project, version, uri, display))`` pairs, whichever shape the inventory of this
    Sphinx version has."""
    for name, item in entries.items():
        if hasattr(item, "uri"):
            yield name, (item.project_name, item.project_version, item.uri, item.display_name)
        else:
            yield name, tuple(item)
