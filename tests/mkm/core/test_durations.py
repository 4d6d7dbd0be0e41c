"""Time promises come from this machine's last time for the same task (the user cache)."""

from __future__ import annotations

import pytest

from mkm.core.durations import estimate, expected_seconds, record, timed


@pytest.fixture(autouse=True)
def cache(tmp_path, monkeypatch):
    monkeypatch.setenv("MKM_CACHE_DIR", str(tmp_path))
    return tmp_path


def test_no_promise_before_the_machine_did_it_once():
    assert expected_seconds("surrogate-training-best") is None
    assert estimate("surrogate-training-best") == ("the first time on this machine: no earlier "
                                                   "time to estimate from")


def test_the_promise_is_the_last_time_recorded(cache):
    record("surrogate-training-best", 38.26)
    assert expected_seconds("surrogate-training-best") == pytest.approx(38.3)
    assert estimate("surrogate-training-best") == "about 38 s (this machine, last time)"
    record("surrogate-training-best", 174.0)  # the last time counts, not the first
    assert estimate("surrogate-training-best") == "about 3 min (this machine, last time)"
    assert (cache / "durations.json").is_file()


def test_a_timed_block_records_itself_unless_it_fails(monkeypatch):
    clock = iter([10.0, 52.5])
    monkeypatch.setattr("mkm.core.durations.time.monotonic", lambda: next(clock))
    with timed("identify"):
        pass
    assert expected_seconds("identify") == pytest.approx(42.5)
    with pytest.raises(RuntimeError), timed("broken"):
        raise RuntimeError("interrupted")
    assert expected_seconds("broken") is None


def test_an_unreadable_record_gives_no_estimate_never_an_error(cache):
    (cache / "durations.json").write_text("{not json")
    assert expected_seconds("x") is None
    record("x", 5.0)  # rewritten whole
    assert expected_seconds("x") == 5.0
