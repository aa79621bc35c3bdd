"""File → Open log: our logs and spy:// captures browsed decoded, offline, with the filters."""

from __future__ import annotations

from pathlib import Path

import pytest

from app.window.console.log_viewer import LogViewer, detect_protocol
from drivers.link.records import Traffic, TrafficLogWriter
from drivers.traffic.log_reader import LogRecord
from tests.support.simproc import ROOT

pytestmark = [pytest.mark.timeout(60)]


def _write_log(path: Path, note: str | None = None) -> None:
    with path.open("w", encoding="utf-8") as stream:
        writer = TrafficLogWriter(stream, start=0.0)
        if note:
            stream.write(f"000000.000 # {note}\n")
        for direction, data, when in (
            ("tx", b"GET_ID\n", 0.1),
            ("rx", b"ACK GET_ID\r\nDONE GET_ID: CX1\r\n", 0.12),
            ("tx", b"SET_SPEED 0\n", 0.5),
            ("rx", b"ACK SET_SPEED\r\nERROR: Speed must be positive\r\nDONE SET_SPEED\r\n", 0.52),
        ):
            writer(Traffic(direction, data, when))


@pytest.fixture
def viewer(qtbot) -> LogViewer:
    window = LogViewer(None, "visiomex")
    qtbot.addWidget(window)
    window.show()
    return window


def _open(qtbot, viewer: LogViewer, path: Path, protocol: str | None = None) -> None:
    viewer.open(path, protocol)
    qtbot.waitUntil(lambda: not viewer.busy(), timeout=20_000)


def test_the_protocol_comes_from_the_log_and_a_filter_finds_the_failure(qtbot, viewer, tmp_path):
    log = tmp_path / "session.log"
    _write_log(log, "connected to /dev/ttyUSB0 (coxiris, 115200 baud)")
    _open(qtbot, viewer, log)
    assert viewer.protocol_combo.currentText() == "coxiris"
    assert "8 lines" in viewer.status_text() and "motionpanel" in viewer.status_text()
    viewer.console.set_filter(kinds={"error"})
    shown = viewer.console.text().splitlines()
    assert shown == [
        "000000.520 RX  ERROR: Speed must be positive\\r\\n  error: Speed must be positive  [↩ #4]"
    ]
    assert viewer.console.send_line.isHidden()  # offline: nothing to send to


def test_without_a_connection_note_the_traffic_tells_the_protocol_and_another_can_be_chosen(
    qtbot, viewer, tmp_path
):
    log = tmp_path / "plain.log"
    _write_log(log)  # COXIRIS traffic, opened from a window on visiomex
    _open(qtbot, viewer, log)
    assert viewer.protocol_combo.currentText() == "coxiris"
    assert "recognised from its traffic" in viewer.status_text()
    assert "ACK GET_ID" in viewer.console.text()
    _open(qtbot, viewer, log, "visiomex")
    assert viewer.protocol_combo.currentText() == "visiomex"
    assert "recognised" not in viewer.status_text()


def test_traffic_no_protocol_reads_is_decoded_by_the_window_s_protocol(qtbot, viewer, tmp_path):
    log = tmp_path / "noise.log"
    with log.open("w", encoding="utf-8") as stream:
        TrafficLogWriter(stream, start=0.0)(Traffic("rx", b"\x00\x01", 0.1))
    _open(qtbot, viewer, log)
    assert viewer.protocol_combo.currentText() == "visiomex"
    assert "recognised" not in viewer.status_text()


def test_a_spy_capture_opens(qtbot, viewer):
    _open(qtbot, viewer, ROOT / "tests" / "data" / "spy_capture.txt", "coxiris")
    assert "pyserial-spy" in viewer.status_text()
    assert "TX  GET_ID\\n" in viewer.console.text()


@pytest.mark.parametrize(
    ("content", "message"),
    [("hello\nworld\n", "not a Motion Panel log nor a pyserial spy:// capture"), (None, "")],
)
def test_a_file_that_is_not_a_log_gets_a_clear_error(qtbot, viewer, tmp_path, content, message):
    path = tmp_path / "notes.txt"
    if content is None:
        path = tmp_path / "missing.log"
    else:
        path.write_text(content)
    _open(qtbot, viewer, path)
    assert str(path) in viewer.status_text()
    assert message in viewer.status_text()
    assert "c62828" in viewer.status.styleSheet()


def test_detect_protocol_reads_the_connection_note() -> None:
    notes = [LogRecord(0.0, "", b"", "connected to sim://visiomex (visiomex board12, 115200 baud)")]
    assert detect_protocol(notes) == ("visiomex", "board12")
    assert detect_protocol(
        [LogRecord(0.0, "", b"", "bridge /dev/x <-> /dev/pts/3 (laser-frame)")]
    ) == (
        "laser-frame",
        "",
    )
    assert detect_protocol([LogRecord(0.0, "", b"", "connected to x (nothing, 1 baud)")]) is None


def test_a_simulator_s_record_opens_as_the_host_saw_it(qtbot, viewer, tmp_path):
    from drivers.protocols.firmata import FirmataProtocol
    from drivers.traffic.log_origin import device_side_note

    record = tmp_path / "device.log"  # as motionsim --record writes it: the board speaks first
    with record.open("w", encoding="utf-8") as stream:
        writer = TrafficLogWriter(stream, start=0.0)
        writer.note(device_side_note("/dev/pts/9", FirmataProtocol(), 57600))
        writer(Traffic("tx", b"\xf9\x02\x05", 0.1))  # the device's version report
        writer(Traffic("rx", b"\xf0\x79\xf7", 0.2))  # what it read: the host's request
    _open(qtbot, viewer, record)
    assert viewer.protocol_combo.currentText() == "firmata"
    assert "a simulator's record" in viewer.status_text()
    lines = [viewer.console.index.line(n) for n in range(len(viewer.console.index))]
    sent = [line for line in lines if line.direction == "tx"]
    assert [line.data for line in sent] == [b"\xf0\x79\xf7"] and "firmware" in sent[0].meaning
    received = [line for line in lines if line.direction == "rx"]
    assert [line.data for line in received] == [b"\xf9\x02\x05"]
