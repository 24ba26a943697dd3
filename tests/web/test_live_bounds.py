"""The server holds a bounded number of live sessions and lets idle ones go."""

from types import SimpleNamespace

import pytest

from trajadapt.errors import SessionStateError
from trajadapt.web.live import IDLE_EXPIRY_S, MAX_LIVE_SESSIONS, make_room


def held(count: int, status: str = "ready", used: float = 0.0) -> dict:
    return {f"s{i}": SimpleNamespace(id=f"s{i}", status=status, used=used + i) for i in range(count)}


def test_expired_sessions_are_let_go():
    live = held(3)
    make_room(live, now=IDLE_EXPIRY_S + 1.5)
    assert sorted(live) == ["s2"]


def test_at_the_bound_the_least_recently_used_idle_session_goes():
    live = held(MAX_LIVE_SESSIONS)
    make_room(live, now=10.0)
    assert len(live) == MAX_LIVE_SESSIONS - 1 and "s0" not in live


def test_sessions_at_work_are_never_let_go_and_a_full_server_says_so():
    live = held(MAX_LIVE_SESSIONS, status="working")
    with pytest.raises(SessionStateError, match="try again"):
        make_room(live, now=IDLE_EXPIRY_S * 10)
    assert len(live) == MAX_LIVE_SESSIONS
