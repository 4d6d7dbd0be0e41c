"""Sphinx configuration of the mkm-bench documentation (``make docs``).

The pages under ``_generated/`` (API reference, measured tables and figures) are written by
``docs/generate.py`` before each build, so the site builds from a clone with no network.
"""

from __future__ import annotations

import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
sys.path.insert(0, str(DOCS))

import generate  # noqa: E402  (docs/generate.py, beside this file)

from mkm import __version__  # noqa: E402

generate.main()


def _numpydoc_template_compiled_once():
    """numpydoc compiles its docstring template in a fresh jinja environment for every object
    it documents (a quarter of the build's time); the same template from the same folders is
    compiled once per build instead, and renders the same pages."""
    import numpydoc.docscrape_sphinx as numpydoc_sphinx
    from jinja2.sandbox import SandboxedEnvironment

    compiled = {}

    class CompiledOnce(SandboxedEnvironment):
        def get_template(self, name, *args, **kwargs):
            folders = getattr(self.loader, "pathchain", getattr(self.loader, "searchpath", ()))
            key = (name, type(self.loader).__name__, tuple(folders))
            if key not in compiled:
                compiled[key] = super().get_template(name, *args, **kwargs)
            return compiled[key]

    numpydoc_sphinx.SandboxedEnvironment = CompiledOnce


_numpydoc_template_compiled_once()

project = "mkm-bench"
author = "the mkm-bench engineers"
copyright = "2026, the mkm-bench engineers"  # noqa: A001  (Sphinx's name)
version = release = __version__.split("+")[0]

extensions = [
    "myst_parser",
    "numpydoc",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "sphinx-mathjax-offline",  # MathJax 3 copied into _static: equations render offline
]
# the local copy, never the CDN (the lab PC has no internet)
mathjax_path = "mathjax/tex-chtml.js"
source_suffix = {".rst": "restructuredtext", ".md": "markdown"}
# the generated tables are included into pages, not pages of their own
exclude_patterns = ["_build", "measured", "_generated/*.md"]
myst_enable_extensions = ["colon_fence", "dollarmath"]
myst_heading_anchors = 3

# scikit-learn adds set_*_request methods to every estimator (metadata routing); their
# docstrings point into scikit-learn's own glossary
autodoc_default_options = {
    "members": True,
    "undoc-members": True,  # a public function without a docstring still gets its entry
    "show-inheritance": True,
    "exclude-members": "set_fit_request, set_predict_request, set_score_request, "
                       "set_transform_request, set_partial_fit_request",
}
# "|Err%|" (the paper's Equation 7 error) is written as in the paper in docstrings; in
# reStructuredText bars mark a substitution, so each spelling stands for itself
rst_prolog = """
.. |Err%| replace:: \\|Err%\\|
.. |residual| replace:: \\|residual\\|
"""
autodoc_member_order = "bysource"
autodoc_typehints = "none"  # numpydoc states the types, with units
# no ``# type:`` comments in the sources: reading them re-parses every documented object's
# source (a tenth of the build) for nothing
autodoc_use_type_comments = False
autosummary_generate = False
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

html_theme = "pydata_sphinx_theme"
html_title = f"mkm-bench {version}"
html_static_path = []
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
html_show_sourcelink = False
