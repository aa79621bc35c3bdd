"""Macros as data: steps checked as motionctl checks commands, files read as data only, saved
with the settings, and run step by step on a simulated device."""

from __future__ import annotations

import json
import os
import threading
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.common import macros
from app.common.macros import BadMacro, BadMacroFile, Macro, MacroStopped
from app.common.settings import open_settings
from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.errors import BadFile
from drivers.link.transport import open_link
from drivers.protocols.registry import create_protocol

pytestmark = pytest.mark.timeout(30)

PROBE = Macro("home and probe", "coxiris", ("home", "move 10 5 0", "jog 0 0 -2", "position"))


def coxiris() -> object:
    return create_protocol("coxiris")


def test_a_good_macro_passes_every_check() -> None:
    macros.check_macro(PROBE, coxiris())
    macros.check_macro(Macro("w", "coxiris", ("wait 0.5", "raw GET_ID", "speed 20")), coxiris())


@pytest.mark.parametrize(
    ("steps", "why"),
    [
        ((), "has no steps"),
        (("movee 1 2",), "unknown command 'movee'"),
        (("move 1 x",), "step 1 ('move 1 x')"),
        (("home", "jog 1 2 3 4"), "step 2"),
        (("wait -1",), "wait -1 s refused"),
        (("wait 5000",), "from 0 to 3600 s"),
        (("wait",), "usage: wait SECONDS"),
        (("param set 1 2",), "unknown command 'param'"),
        (("macro run x",), "unknown command 'macro'"),
        (("step 60 200",), "step is a firmata command"),
        (("raw",), "usage: raw TEXT"),
        (("move 1 2\nhome",), "a step is one line"),
        (("speed 1e9",), "not a number the device accepts"),
    ],
)
def test_a_bad_step_is_refused_with_its_number_and_why(steps: tuple[str, ...], why: str) -> None:
    with pytest.raises(BadMacro, match=None) as caught:
        macros.check_macro(Macro("m", "coxiris", steps), coxiris())
    assert why in str(caught.value)


def test_a_macro_for_another_protocol_is_refused() -> None:
    with pytest.raises(BadMacro, match="is for visiomex, not coxiris"):
        macros.check_macro(Macro("m", "visiomex", ("home",)), coxiris())


@pytest.mark.parametrize(
    ("name", "why"),
    [("", "needs a name"), ("  ", "needs a name"), ("x" * 41, "over 40"), ("a\tb", "control")],
)
def test_a_bad_name_is_refused(name: str, why: str) -> None:
    with pytest.raises(BadMacro, match=why):
        macros.check_name(name)


def test_raw_keeps_the_rest_of_its_line() -> None:
    assert macros.split_step("raw  MOVE_TO 1  2 ") == ("raw", ["MOVE_TO 1  2"])
    assert macros.split_step(" move 1  2 ") == ("move", ["1", "2"])


# -- files -------------------------------------------------------------------------------------
def test_a_file_round_trips(tmp_path: Path) -> None:
    other = Macro("go", "visiomex", ("home",))
    path = tmp_path / "m.json"
    macros.write_macro_file(path, [PROBE, other])
    assert macros.read_macro_file(path) == [PROBE, other]


@pytest.mark.parametrize(
    ("text", "why"),
    [
        ("not json", "not JSON"),
        ("[]", "not a Motion Panel macro file"),
        ('{"format": "motionpanel-macros", "version": 2, "macros": []}', "version 2"),
        ('{"format": "motionpanel-macros", "version": 1, "macros": {}}', "is not a list"),
        (
            '{"format": "motionpanel-macros", "version": 1, "macros": [1]}',
            "macro 1 is not an object",
        ),
        (
            '{"format": "motionpanel-macros", "version": 1, "macros": '
            '[{"name": "a", "protocol": "zmodem", "steps": []}]}',
            "unknown protocol 'zmodem'",
        ),
        (
            '{"format": "motionpanel-macros", "version": 1, "macros": '
            '[{"name": "a", "protocol": "coxiris", "steps": "home"}]}',
            "not a list of strings",
        ),
        (
            '{"format": "motionpanel-macros", "version": 1, "macros": '
            '[{"name": "a", "protocol": "coxiris", "steps": []}, '
            '{"name": "a", "protocol": "coxiris", "steps": []}]}',
            "two coxiris macros are named 'a'",
        ),
        ('{"format": "motionpanel-macros", "version": NaN}', "NaN is not a JSON number"),
        ("[" * 100_000, "not JSON"),
        ("{}\x00", "NUL"),
    ],
)
def test_a_malformed_file_is_refused_whole(tmp_path: Path, text: str, why: str) -> None:
    path = tmp_path / "m.json"
    path.write_text(text)
    with pytest.raises(BadMacroFile, match=None) as caught:
        macros.read_macro_file(path)
    assert why in str(caught.value)
    assert str(path) in str(caught.value)


def test_a_fifo_or_a_huge_file_is_refused_without_reading(tmp_path: Path) -> None:
    fifo = tmp_path / "fifo.json"
    os.mkfifo(fifo)
    with pytest.raises(BadFile, match="named pipe"):
        macros.read_macro_file(fifo)
    huge = tmp_path / "huge.json"
    with open(huge, "wb") as stream:
        stream.truncate(10 * 1024**3)  # sparse: refused by its size alone
    with pytest.raises(BadFile, match="larger than"):
        macros.read_macro_file(huge)


@settings(max_examples=200, deadline=None)
@given(st.binary(max_size=400))
def test_arbitrary_bytes_give_our_error_or_macros(tmp_path_factory, data: bytes) -> None:
    path = tmp_path_factory.mktemp("fuzz") / "m.json"
    path.write_bytes(data)
    try:
        read = macros.read_macro_file(path)
    except BadFile:
        return
    assert all(isinstance(m, Macro) for m in read)


# -- kept with the settings ------------------------------------------------------------------
def test_saved_per_protocol_and_read_back(settings_file: Path) -> None:
    settings = open_settings()
    macros.save(settings, "coxiris", [PROBE, Macro("x", "visiomex", ("home",))])
    macros.save(settings, "visiomex", [Macro("x", "visiomex", ("home",))])
    again = open_settings()
    assert macros.read_saved(again, "coxiris") == [PROBE]
    assert macros.read_saved(again, "visiomex") == [Macro("x", "visiomex", ("home",))]
    assert macros.read_saved(again, "firmata") == []


def test_an_edited_unreadable_entry_gives_none(settings_file: Path) -> None:
    settings = open_settings()
    settings.setValue(macros.settings_key("coxiris"), json.dumps({"format": "nope"}))
    assert macros.read_saved(settings, "coxiris") == []


# -- running ---------------------------------------------------------------------------------------
def _motion() -> Motion:
    protocol = create_protocol("coxiris")
    link = open_link("sim://coxiris?instant=1", protocol.capabilities.default_baud)
    motion = Motion(Client(link, protocol, timeout=2.0))
    motion.start()
    return motion


def test_a_macro_runs_each_step_in_order_and_reports_each() -> None:
    motion = _motion()
    told: list[tuple[int, str]] = []
    try:
        results = macros.run_macro(
            motion,
            Macro("m", "coxiris", (*PROBE.steps, "wait 0.05", "raw GET_ID")),
            lambda n, s: told.append((n, s)),
        )
    finally:
        motion.client.link.close()
    assert [n for n, _ in told] == [1, 2, 3, 4, 5, 6]
    assert results[1] == {"position": [10.0, 5.0, 0.0]}
    assert results[3] == {"position": [10.0, 5.0, -2.0]}
    assert results[4] == {"waited": 0.05}
    assert results[5]["reply"][-1].startswith("DONE GET_ID")


def test_a_stop_ends_the_macro_between_steps() -> None:
    motion = _motion()
    told: list[int] = []

    def step(number: int, text: str) -> None:
        told.append(number)
        if number == 2:
            motion.stop_requested.set()

    try:
        with pytest.raises(MacroStopped, match="stopped before step 3"):
            macros.run_macro(
                motion, Macro("m", "coxiris", ("home", "move 1 0 0", "move 2 0 0")), step
            )
        assert motion.position().x == 1.0
    finally:
        motion.client.link.close()
    assert told == [1, 2]


def test_a_stop_ends_a_wait_early() -> None:
    motion = _motion()
    stopper = threading.Timer(0.2, motion.stop_requested.set)
    try:
        stopper.start()
        with pytest.raises(MacroStopped, match="stopped during step 1"):
            macros.run_macro(motion, Macro("m", "coxiris", ("wait 600",)))
    finally:
        stopper.join()
        motion.client.link.close()
