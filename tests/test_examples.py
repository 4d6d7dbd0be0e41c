"""Every script of ``examples/`` runs to its end, so each one's own assertion of the number it
shows holds (the examples are the gallery of the documentation, ``docs/generate.py``).

Scripts run in this process (``runpy``), under the suite's hermetic cache and output folders.
Those that train the default surrogate or solve many FE sweeps are in the slow tier.
"""

import ast
import runpy
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"
# surrogate training (predict_muscle, design_muscle) or 15 FE sweeps (calibrate_from_run)
SLOW = {"predict_muscle", "design_muscle", "calibrate_from_run"}
SCRIPTS = sorted(EXAMPLES.glob("*.py"))


def test_the_gallery_has_the_examples_the_docs_promise():
    assert {p.stem for p in SCRIPTS} >= SLOW | {"stability_map", "read_run", "speed_accuracy"}


@pytest.mark.parametrize("script", [
    pytest.param(p, id=p.stem, marks=[pytest.mark.slow] if p.stem in SLOW else [])
    for p in SCRIPTS])
def test_example_runs_and_asserts_what_it_shows(script, capsys):
    doc = ast.get_docstring(ast.parse(script.read_text(encoding="utf-8")))
    # the first docstring line is the page title in the gallery, the rest its text
    assert doc and "\n\n" in doc and len(doc.splitlines()[0]) < 80
    tree = ast.parse(script.read_text(encoding="utf-8"))
    assert any(isinstance(node, ast.Assert) for node in ast.walk(tree)), "asserts nothing"
    runpy.run_path(str(script), run_name="__main__")
    assert capsys.readouterr().out.strip()
