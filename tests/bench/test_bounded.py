"""A call given a bounded time (:func:`mkm.bench.bounded.call_within`): what it returned, what
it raised, or that it did not return; the hung call is let go, not joined."""

import threading

from mkm.bench.bounded import call_within


def test_a_call_that_returns_raises_or_hangs_is_told_apart():
    assert call_within(lambda: None, 5.0, "t") == (True, None)

    def fails():
        raise OSError("refused")

    returned, exc = call_within(fails, 5.0, "t")
    assert returned and isinstance(exc, OSError) and str(exc) == "refused"
    release = threading.Event()
    assert call_within(release.wait, 0.05, "mkm-hangs") == (False, None)
    hung = [t for t in threading.enumerate() if t.name == "mkm-hangs"]
    assert hung and hung[0].daemon  # ends with the process if the driver never returns
    release.set()
    hung[0].join(5.0)
