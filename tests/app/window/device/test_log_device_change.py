"""A session log that changed device: each part decoded by the protocol its connection note
names, in the library, in `motionctl log decode` and in File → Open log (issue 19, item 16)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from app.common.session_log import open_session_log
from app.window.console.log_viewer import LogViewer
from app.window.device import jobs
from app.window.device.worker import SerialWorker
from drivers.protocols.registry import create_protocol
from drivers.traffic.decoding import DecodedFrame, decode_records
from drivers.traffic.lines import KINDS
from drivers.traffic.log_reader import read_log
from tests.support.simproc import ROOT

pytestmark = [pytest.mark.timeout(60), pytest.mark.usefixtures("settings_file")]

LASER_NOTE = "connected to sim://laser-frame (laser-frame, 115200 baud)"


@pytest.fixture
def session_log(qtbot, tmp_path: Path) -> Path:
    """The panel's session log of a real run: the panel's worker connects to sim://visiomex and
    jogs, then connects to sim://laser-frame and jogs, writing through the real session log."""
    path, stream = open_session_log(tmp_path)
    worker = SerialWorker()
    finished: list[object] = []
    worker.job_finished.connect(lambda job, result: finished.append(job))
    worker.job_failed.connect(lambda job, why: finished.append(why))
    worker.set_session_log(stream)
    worker.start()
    try:
        for url, name in (("sim://visiomex", "visiomex"), ("sim://laser-frame", "laser-frame")):
            worker.open_port(url, name, 115200)
            count = len(finished)
            worker.submit(jobs.MoveByJob(1.0, 0.0, 0.0))
            qtbot.waitUntil(lambda count=count: len(finished) > count, timeout=20_000)
            assert isinstance(finished[-1], jobs.MoveByJob), finished[-1]
    finally:
        worker.close_port()
        worker.set_session_log(None)
    return path


def _parts(frames: list[DecodedFrame]) -> tuple[list[DecodedFrame], list[DecodedFrame]]:
    """The frames before and after the laser connection note (notes left out)."""
    notes = [f.meaning for f in frames if f.kind == "note"]
    assert LASER_NOTE in notes, notes
    at = next(i for i, f in enumerate(frames) if f.kind == "note" and f.meaning == LASER_NOTE)
    before = [f for f in frames[:at] if f.kind != "note"]
    after = [f for f in frames[at:] if f.kind != "note"]
    return before, after


def _check_parts(before_meanings: list[str], after_meanings: list[str], kinds: list[str]) -> None:
    assert any(m.startswith("move linear X P0001000") for m in before_meanings), before_meanings
    assert any("FA0001" in m for m in before_meanings), before_meanings  # Visiomex feedback
    assert "GET_ID" in after_meanings and "GET_POSITION" in after_meanings, after_meanings
    assert any("MOVE_LINEAR [1.0, 0.0, 0.0" in m for m in after_meanings), after_meanings
    assert not any("unreadable" in m for m in after_meanings), after_meanings
    assert "error" not in kinds, kinds


@pytest.mark.parametrize("chosen", ["visiomex", "coxiris"])
def test_each_part_is_decoded_by_its_connection_notes_protocol(session_log, chosen) -> None:
    frames = decode_records(create_protocol(chosen), read_log(session_log))
    before, after = _parts(frames)
    _check_parts(
        [f.meaning for f in before], [f.meaning for f in after], [f.kind for f in before + after]
    )


@pytest.mark.e2e
def test_motionctl_log_decode_follows_the_connection_notes(session_log) -> None:
    done = subprocess.run(
        [
            *(sys.executable, "-m", "app.cli", "--port", "none", "--protocol", "visiomex"),
            *("--json", "log", "decode", str(session_log)),
        ],
        capture_output=True,
        text=True,
        timeout=30,
        cwd=ROOT,
    )
    assert done.returncode == 0, done.stderr
    frames = json.loads(done.stdout)["frames"]
    notes = [f["meaning"] for f in frames if f["kind"] == "note"]
    at = next(i for i, f in enumerate(frames) if f["meaning"] == LASER_NOTE)
    before = [f for f in frames[:at] if f["kind"] != "note"]
    after = [f for f in frames[at:] if f["kind"] != "note"]
    assert LASER_NOTE in notes
    _check_parts(
        [f["meaning"] for f in before],
        [f["meaning"] for f in after],
        [f["kind"] for f in before + after],
    )


def test_the_log_viewer_decodes_each_part_by_its_protocol(qtbot, session_log) -> None:
    viewer = LogViewer(None, "coxiris")
    qtbot.addWidget(viewer)
    viewer.show()
    viewer.open(session_log)
    qtbot.waitUntil(lambda: not viewer.busy(), timeout=20_000)
    assert viewer.protocol_combo.currentText() == "visiomex"  # the first note's
    assert "visiomex seed, laser-frame" in viewer.status_text()
    viewer.console.set_filter(kinds=set(KINDS))  # the polls too
    lines = viewer.console.text().splitlines()
    at = next(i for i, line in enumerate(lines) if LASER_NOTE in line)
    before, after = "\n".join(lines[:at]), "\n".join(lines[at:])
    assert "move linear X P0001000" in before and "FA0001" in before
    assert "GET_POSITION" in after and "MOVE_LINEAR" in after
    assert "unreadable" not in after and "FA0001" not in after
