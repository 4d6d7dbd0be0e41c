"""``mkm identify``: learn a muscle's braid angle, rubber, friction and creep from its bench runs.

:func:`identify` fits them (:mod:`mkm.identify.procedure`), :class:`Identification` writes the
calibration file every command takes (:mod:`mkm.identify.result`), and
:func:`mkm.identify.page.report_section` shows the identified muscle in the report.
"""

__all__ = ["Identification", "identify"]


def __getattr__(name: str):
    """:func:`identify` and :class:`Identification` loaded when first asked for: the package's
    light registry (:mod:`mkm.identify.groups`) is read by ``mkm identify --help`` without
    numpy and scipy."""
    if name == "identify":
        from mkm.identify.procedure import identify

        return identify
    if name == "Identification":
        from mkm.identify.result import Identification

        return Identification
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
