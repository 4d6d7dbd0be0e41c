"""``mkm identify``: learn a muscle's braid angle, rubber, friction and creep from its bench runs.

:func:`identify` fits them (:mod:`mkm.identify.procedure`), :class:`Identification` writes the
calibration file every command takes (:mod:`mkm.identify.result`), and
:func:`mkm.identify.page.report_section` shows the identified muscle in the report.
"""

from mkm.identify.procedure import identify
from mkm.identify.result import Identification

__all__ = ["Identification", "identify"]
