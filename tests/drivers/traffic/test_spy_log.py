"""pyserial spy:// captures, written by pyserial itself over a real pty, read back as traffic logs.

`python -m tests.drivers.traffic.test_spy_log` rewrites the committed capture
(tests/data/spy_capture.txt).
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import select
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
import serial

from drivers.protocols import commands as cmd
from drivers.protocols.registry import create_protocol
from drivers.traffic.decoding import decode_records
from drivers.traffic.log_reader import LogError, LogRecord, parse_log, read_any_log
from drivers.traffic.spy_log import parse_spy
from tests.support.simproc import ROOT, SimProcess

pytestmark = [pytest.mark.timeout(60), pytest.mark.usefixtures("settings_file")]

FIXTURE = Path(__file__).resolve().parents[2] / "data" / "spy_capture.txt"
REPLY = b"ACK GET_ID\r\nDONE GET_ID: CX25F7TK9P\r\n"
BINARY = b"\x00\x0a\xff" * 6 + b"\x00\x0a"  # 20 bytes: two hexdump lines


@contextlib.contextmanager
def _pty() -> Iterator[tuple[int, str]]:
    """A pseudo-terminal: the controlling side's descriptor (the 'device') and the port's path."""
    controller, device = os.openpty()
    try:
        yield controller, os.ttyname(device)
    finally:
        os.close(controller)
        os.close(device)


@pytest.fixture
def pty() -> Iterator[tuple[int, str]]:
    """A pseudo-terminal for the test (see `_pty`)."""
    with _pty() as pair:
        yield pair


@contextlib.contextmanager
def _spied(capture: Path, port: str, options: str = "", **before_open: Any) -> Iterator[Any]:
    """`spy://port?file=capture&options` opened (after setting `before_open`, e.g. dtr=False)."""
    link = serial.serial_for_url(
        f"spy://{port}?file={capture}{options}", timeout=2, do_not_open=True
    )
    try:
        for name, value in before_open.items():  # set while closed: no ioctl, which a pty refuses
            setattr(link, name, value)
        link.open()
        yield link
    finally:
        link.close()
        link.formatter.output.close()  # spy never closes its file


def _take(controller: int, count: int, timeout: float = 5.0) -> bytes:
    """Exactly `count` bytes the port wrote, as the device reads them."""
    data, deadline = b"", time.monotonic() + timeout
    while (
        len(data) < count
        and select.select([controller], [], [], max(0, deadline - time.monotonic()))[0]
    ):
        data += os.read(controller, count - len(data))
    assert len(data) == count, f"the device got {data!r}"
    return data


def _write(link: Any, controller: int, data: bytes) -> tuple[str, bytes]:
    """The program writes `data`; the device receives exactly it."""
    link.write(data)
    assert _take(controller, len(data)) == data
    return "tx", data


def _read(link: Any, controller: int, data: bytes) -> tuple[str, bytes]:
    """The device sends `data`; the program reads exactly it, in one read."""
    os.write(controller, data)
    assert link.read(len(data)) == data
    return "rx", data


def _traffic(records: list[LogRecord]) -> list[tuple[str, bytes]]:
    return [(r.direction, r.data) for r in records if not r.note]


def _fixture_session(link: Any, controller: int) -> list[tuple[str, bytes]]:
    """The traffic of the committed capture: a COXIRIS GET_ID and its reply, a binary write."""
    return [
        _write(link, controller, create_protocol("coxiris").encode(cmd.GetId())),
        _read(link, controller, REPLY),
        _write(link, controller, BINARY),
    ]


def _capture_fixture_session(capture: Path, port: str, controller: int) -> list[tuple[str, bytes]]:
    """Capture the fixture's session (DTR off before the open, a flush at the end)."""
    with _spied(capture, port, dtr=False) as link:
        traffic = _fixture_session(link, controller)
        link.flush()
    return traffic


def _unstamped(text: str) -> list[str]:
    return [re.sub(r"^\d+\.\d{3} ", "TIME ", line).rstrip() for line in text.splitlines()]


@pytest.mark.parametrize("options", ["", "&color", "&color&all"])
def test_every_write_and_read_comes_back_with_its_direction(
    tmp_path: Path, pty: tuple[int, str], options: str
) -> None:
    controller, port = pty
    capture = tmp_path / "capture.txt"
    with _spied(capture, port, options, dtr=False, rts=True) as link:
        link.reset_input_buffer()
        expected = [
            _write(link, controller, b"GET_ID\n"),
            _read(link, controller, b"ACK GET_ID\r\nDONE GET_ID: X\r\n"),  # 28 bytes: two lines
            _write(link, controller, bytes(range(256))),  # 16 lines, 0x00 0x0A 0xFF among them
            _write(link, controller, b"\x00\x0a\xff" + b"0123456789abc"),  # exactly one line
            _write(link, controller, b"exactly 16 bytes"),  # ... and another call, not its sequel
            _write(link, controller, b"x" * 32),
            _read(link, controller, b"\xff\x00\x0a" * 7),
            _read(link, controller, b"\n"),
        ]
        link.flush()
        if "all" in options:  # `all` also shows empty reads and in_waiting
            link.timeout = 0.05
            assert link.read(1) == b""
            assert link.in_waiting == 0
    records = parse_spy(capture.read_text(), str(capture))
    assert _traffic(records) == expected
    notes = [r.note for r in records if r.note]
    assert notes[:4] == ["DTR inactive", "RTS active", "Q-RX reset_input_buffer", "Q-TX flush"]
    if "all" in options:
        assert notes[4:] == ["RX <empty>", "Q-RX in_waiting -> 0"]
    times = [r.time for r in records]
    assert times == sorted(times) and times[0] >= 0
    assert read_any_log(capture) == ("pyserial-spy", records)


def test_a_spy_capture_decodes_as_coxiris_frames(tmp_path: Path, pty: tuple[int, str]) -> None:
    controller, port = pty
    capture = tmp_path / "capture.txt"
    _capture_fixture_session(capture, port, controller)
    log_format, records = read_any_log(capture)
    assert log_format == "pyserial-spy"
    frames = decode_records(create_protocol("coxiris"), records)
    assert [(f.direction, f.meaning) for f in frames if f.kind != "note"][:3] == [
        ("tx", "GET_ID"),
        ("rx", "ACK GET_ID"),
        ("rx", "DONE GET_ID: CX25F7TK9P"),
    ]
    assert [f.meaning for f in frames if f.kind == "note"] == ["DTR inactive", "Q-TX flush"]


def test_the_committed_capture_parses_and_is_what_this_pyserial_writes(
    tmp_path: Path, pty: tuple[int, str]
) -> None:
    fixture = FIXTURE.read_text()
    records = parse_spy(fixture, str(FIXTURE))
    assert _traffic(records) == [("tx", b"GET_ID\n"), ("rx", REPLY), ("tx", BINARY)]
    assert [r.note for r in records if r.note] == ["DTR inactive", "Q-TX flush"]
    controller, port = pty
    fresh = tmp_path / "capture.txt"
    _capture_fixture_session(fresh, port, controller)
    assert _unstamped(fresh.read_text()) == _unstamped(fixture), (
        "pyserial's spy:// writes another format now: check drivers/traffic/spy_log.py against it, "
        "then rewrite the capture with `python -m tests.drivers.traffic.test_spy_log`"
    )


def test_our_own_log_is_told_from_a_spy_capture(tmp_path: Path) -> None:
    ours = tmp_path / "session.log"
    ours.write_text(
        "\n# Motion Panel session log\n"
        "000000.001 TX   47 45 54 5F 49 44 0A                                GET_ID.\n"
    )
    assert read_any_log(ours) == ("motionpanel", parse_log(ours.read_text(), str(ours)))


def test_our_log_that_begins_with_a_received_frame_is_ours(tmp_path: Path) -> None:
    # A Firmata board speaks first: `motionctl --log`'s first line was taken for a spy line.
    ours = tmp_path / "firmata.log"
    ours.write_text(
        "000002.000 RX   F9                                                .\n"
        "000002.000 TX   F9 F0 79 F7                                       ..y.\n"
        "000002.001 RX   02 05                                             ..\n"
    )
    log_format, records = read_any_log(ours)
    assert log_format == "motionpanel"
    assert [(r.direction, r.data) for r in records] == [
        ("rx", b"\xf9"),
        ("tx", b"\xf9\xf0\x79\xf7"),
        ("rx", b"\x02\x05"),
    ]


def _edit(lines: list[str], number: int, change: Callable[[str], str | None]) -> str:
    """The capture with line `number` (1-based) changed, or dropped when `change` gives None."""
    changed = change(lines[number - 1])
    kept = lines[: number - 1] + ([] if changed is None else [changed]) + lines[number:]
    return "\n".join(kept) + "\n"


@pytest.mark.parametrize(
    ("number", "change", "line", "why"),
    [
        (2, lambda s: s.replace("47 45", "47 46"), 2, "not a pyserial spy:// hexdump line"),
        (2, lambda s: s.replace("GET_ID.", "GET-ID."), 2, "not a pyserial spy:// hexdump line"),
        (2, lambda s: s.replace(" 0000 ", " 0010 "), 2, "earlier lines are missing"),
        (3, lambda s: None, 3, "offset 0x0010 of a RX call whose earlier lines are missing"),
        (1, lambda s: s.replace("DTR ", "XYZ "), 1, "not a pyserial spy:// hexdump line"),
        (1, lambda s: s + "\nhello world", 2, "not a pyserial spy:// hexdump line"),
        (2, lambda s: s.lower(), 2, "not a pyserial spy:// hexdump line"),
    ],
    ids=["hex-vs-text", "text-vs-hex", "bad-offset", "lost-line", "label", "garbage", "case"],
)
def test_a_damaged_capture_is_refused_naming_the_line(
    number: int, change: Callable[[str], str | None], line: int, why: str
) -> None:
    text = _edit(FIXTURE.read_text().splitlines(), number, change)
    with pytest.raises(LogError, match=re.escape(f"capture.txt line {line}: ") + ".*" + why):
        parse_spy(text, "capture.txt")


def test_lines_of_calls_from_two_threads_may_interleave() -> None:
    dtr, get_id, rx0, rx1, rx2, tx0, tx1, flush = FIXTURE.read_text().splitlines()
    assert " RX   0020" in rx2 and " TX   0010" in tx1
    mixed = "\n".join([dtr, get_id, rx0, tx0, rx1, tx1, rx2, flush])  # a reader thread's lines
    records = parse_spy(mixed, "mixed")
    assert _traffic(records) == [("tx", b"GET_ID\n"), ("rx", REPLY), ("tx", BINARY)]


@pytest.mark.parametrize("options", ["&raw", "&raw&color"])
def test_a_raw_capture_is_refused_with_advice(
    tmp_path: Path, pty: tuple[int, str], options: str
) -> None:
    controller, port = pty
    capture = tmp_path / "raw.txt"
    with _spied(capture, port, options) as link, contextlib.suppress(TypeError):
        link.write(b"GET_ID\n")  # pyserial 3.5 writes bytes to a text file: TypeError
        os.write(controller, b"ACK GET_ID\r\n")
        link.read(12)
    with pytest.raises(LogError, match="hexdump format") as refused:
        read_any_log(capture)
    assert str(capture) in str(refused.value)


def _motionctl(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "app.cli", "--protocol", "coxiris", *args],
        capture_output=True,
        text=True,
        timeout=30,
        cwd=ROOT,
    )


@pytest.mark.e2e
def test_motionctl_decodes_a_capture_and_refuses_what_is_not_one(tmp_path: Path) -> None:
    done = _motionctl("--port", "none", "log", "decode", str(FIXTURE))
    assert done.returncode == 0, done.stderr
    shown = done.stdout.splitlines()
    assert [line.split("  ")[-1].strip() for line in shown][:4] == [
        "DTR inactive",
        "GET_ID",
        "ACK GET_ID",
        "DONE GET_ID: CX25F7TK9P",
    ]
    as_json = json.loads(
        _motionctl("--port", "none", "--json", "log", "decode", str(FIXTURE)).stdout
    )
    assert (
        as_json["format"] == "pyserial-spy" and as_json["frames"][1]["hex"] == "47 45 54 5F 49 44"
    )
    foreign = tmp_path / "notes.txt"
    foreign.write_text("\n\nshopping list\n")
    refused = _motionctl("--port", "none", "log", "decode", str(foreign))
    assert refused.returncode == 2, refused.stderr
    assert (
        f"{foreign}: not a Motion Panel log nor a pyserial spy:// capture: line 3" in refused.stderr
    )
    binary = tmp_path / "capture.bin"
    binary.write_bytes(b"\x00\x0a\xff\xfe" * 64)
    refused = _motionctl("--port", "none", "log", "decode", str(binary))
    assert refused.returncode == 2 and f"{binary}: not UTF-8 text" in refused.stderr


@pytest.mark.e2e
def test_motionctl_talking_through_spy_then_decoding_the_capture(tmp_path: Path) -> None:
    sim = SimProcess("coxiris")
    try:
        capture = tmp_path / "capture.txt"
        moved = _motionctl("--port", f"spy://{sim.path}?file={capture}", "move", "1", "2", "3")
        assert moved.returncode == 0, moved.stderr
    finally:
        assert sim.stop() == 0
        for pipe in (sim.proc.stdout, sim.proc.stderr):
            if pipe is not None:
                pipe.close()  # SimProcess leaves them open
    decoded = _motionctl("--port", "none", "log", "decode", str(capture), "--filter", "move")
    assert decoded.returncode == 0, decoded.stderr
    meanings = [line.split("  ")[-1] for line in decoded.stdout.splitlines()]
    assert meanings == ["ABSOLUTE_MOVE 1 2 3", "ACK ABSOLUTE_MOVE", "DONE ABSOLUTE_MOVE"]


def main() -> None:
    """Rewrite the committed capture with what this pyserial's spy:// writes."""
    with _pty() as (controller, port):
        _capture_fixture_session(FIXTURE, port, controller)
    print(FIXTURE.read_text(), end="")


if __name__ == "__main__":
    main()
