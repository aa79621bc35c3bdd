"""`motionsim --link PATH`: a stable name for its pty, made at start, replaced when a new
simulator takes it, removed at exit (like socat's `link=`)."""

from __future__ import annotations

import os
import signal
import time
from collections.abc import Callable
from pathlib import Path

import pytest

from drivers.link.transport import open_link
from drivers.sim.pty_server import make_link, remove_link
from tests.support.simproc import SimProcess

pytestmark = [pytest.mark.e2e, pytest.mark.timeout(60)]


def _until(condition: Callable[[], bool], seconds: float = 5.0) -> bool:
    """Poll `condition` (a file's state) until true or `seconds` pass; its last value."""
    deadline = time.monotonic() + seconds
    while not condition():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.02)
    return True


def test_the_link_names_the_pty_while_it_serves_and_goes_at_exit(tmp_path: Path) -> None:
    link = tmp_path / "stage"
    sim = SimProcess("coxiris", "--instant", "--link", str(link))
    try:
        assert os.readlink(link) == sim.path
        port = open_link(str(link), 115200)  # a client opens the link's name
        try:
            port.write(b"GET_ID\n")
            got = b""
            for _ in range(250):
                got += port.read()
                if got.count(b"\n") == 2:  # ACK, then DONE with the identity
                    break
            assert b"\r\nDONE GET_ID: " in got, got
        finally:
            port.close()
    finally:
        assert sim.stop(signal.SIGTERM) == 0
    assert not os.path.lexists(link)


def test_a_second_simulator_takes_the_link_and_the_first_leaves_it(tmp_path: Path) -> None:
    link = tmp_path / "stage"
    first = SimProcess("coxiris", "--instant", "--link", str(link))
    second = SimProcess("visiomex", "--instant", "--link", str(link))
    try:
        assert os.readlink(link) == second.path
        first.stop()
        assert os.readlink(link) == second.path  # not the first's to remove any more
    finally:
        first.stop()
        second.stop()
    assert not os.path.lexists(link)


def test_a_killed_simulator_leaves_a_dangling_link_that_a_new_one_replaces(
    tmp_path: Path,
) -> None:
    link = tmp_path / "stage"
    sim = SimProcess("coxiris", "--instant", "--link", str(link))
    sim.kill()
    assert os.path.lexists(link)
    assert _until(lambda: not os.path.exists(link))  # the kernel frees the pty a bit later
    again = SimProcess("coxiris", "--instant", "--link", str(link))
    try:
        assert os.readlink(link) == again.path and os.path.exists(link)
    finally:
        again.stop()


def test_make_link_replaces_a_file_and_remove_link_only_its_own(tmp_path: Path) -> None:
    link = tmp_path / "name"
    link.write_text("in the way")
    make_link("/dev/null", str(link))
    assert os.readlink(link) == "/dev/null"
    remove_link("/dev/zero", str(link))
    assert os.path.lexists(link)
    remove_link("/dev/null", str(link))
    assert not os.path.lexists(link)
    assert [p.name for p in tmp_path.iterdir()] == []  # no temporary left behind
