"""Logs read back and decoded by the protocols' own decoders, in the library and motionctl."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from drivers.device.client import Client
from drivers.device.motion import Motion
from drivers.link.records import TrafficLogWriter
from drivers.link.transport import open_link
from drivers.protocols import commands as cmd
from drivers.protocols.coxiris import CoxirisProtocol
from drivers.protocols.laser.protocol import LaserProtocol
from drivers.traffic.decoding import decode_records
from drivers.traffic.log_reader import LogError, parse_log, read_log
from tests.support.simproc import ROOT

pytestmark = [pytest.mark.timeout(30), pytest.mark.usefixtures("settings_file")]


def _session(path: Path, url: str, protocol: object, run) -> None:  # type: ignore[no-untyped-def]
    link = open_link(url, 115200)
    with path.open("a", encoding="utf-8") as stream:
        link.listeners.append(TrafficLogWriter(stream))
        try:
            run(Motion(Client(link, protocol)))  # type: ignore[arg-type]
        finally:
            link.close()


def test_a_coxiris_log_reads_back_decoded(tmp_path: Path) -> None:
    log = tmp_path / "cx.log"
    _session(log, "sim://coxiris?instant=1", CoxirisProtocol(), lambda m: m.move_to(1, 2, 3))
    frames = decode_records(CoxirisProtocol(), read_log(log))
    meanings = [f.meaning for f in frames]
    assert "ABSOLUTE_MOVE 1 2 3" in meanings and "ACK ABSOLUTE_MOVE" in meanings
    assert any(m.startswith("DONE GET_POSITION: 1.00 2.00 3.00") for m in meanings)
    assert {f.direction for f in frames} == {"tx", "rx"}


def test_a_laser_log_names_every_instruction_and_error(tmp_path: Path) -> None:
    log = tmp_path / "lz.log"
    _session(
        log,
        "sim://laser-frame?instant=1",
        LaserProtocol(),
        lambda m: (
            m.position(),
            m.client.send_raw(b"\xeb\x90\x82\xf0\x10\x90\x82\x11"),  # a wrong sum
            m.client.listen(0.2),  # its error reply is logged as it arrives
        ),
    )
    frames = decode_records(LaserProtocol(), read_log(log))
    assert frames[0].meaning == "GET_POSITION" and frames[0].direction == "tx"
    assert frames[1].meaning == "GET_POSITION [0.0, 0.0, 0.0]"
    errors = [f for f in frames if f.kind == "error" or "error" in f.meaning]
    assert errors and "checksum" in errors[-1].meaning  # the bad sum sent by hand


def test_records_spanning_lines_and_notes_are_rejoined() -> None:
    text = (
        "# Motion Panel session log\n"
        "000000.001 TX   47 45 54 5F 49 44 0A                                GET_ID.\n"
        "000000.002 RX   41 43 4B 20 47 45 54 5F 49 44 0D 0A 44 4F 4E 45   ACK GET_ID..DONE\n"
        "000000.002 RX   20 47 45 54 5F 49 44 3A 20 58 0D 0A                 GET_ID: X..\n"
        "000000.003 # disconnected\n"
    )
    records = parse_log(text)
    assert [r.note for r in records] == ["Motion Panel session log", "", "", "disconnected"]
    assert records[2].data.endswith(b"GET_ID: X\r\n")
    assert [f.meaning for f in decode_records(CoxirisProtocol(), records)][1:4] == [
        "GET_ID",
        "ACK GET_ID",
        "DONE GET_ID: X",
    ]


@pytest.mark.parametrize(
    ("text", "why"),
    [("hello world\n", "line 1: not a traffic log line"), ("# only a note\n", "no traffic")],
)
def test_a_file_that_is_not_a_log_is_refused(text: str, why: str) -> None:
    with pytest.raises(LogError, match=why):
        parse_log(text)


def _motionctl(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "app.cli", "--port", "none", *args],
        capture_output=True,
        text=True,
        timeout=20,
        cwd=ROOT,
    )


@pytest.mark.e2e
def test_motionctl_log_decode_filters_and_prints_json(tmp_path: Path) -> None:
    log = tmp_path / "cx.log"
    _session(
        log, "sim://coxiris?instant=1", CoxirisProtocol(), lambda m: m.client.execute(cmd.GetId())
    )
    done = _motionctl("--protocol", "coxiris", "log", "decode", str(log), "--filter", "done")
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().endswith("DONE GET_ID: CX25F7TK9P")
    assert len(done.stdout.strip().splitlines()) == 1
    as_json = _motionctl("--protocol", "coxiris", "--json", "log", "decode", str(log))
    frames = json.loads(as_json.stdout)["frames"]
    assert [f["meaning"] for f in frames] == ["GET_ID", "ACK GET_ID", "DONE GET_ID: CX25F7TK9P"]
    missing = _motionctl("--protocol", "coxiris", "log", "decode", str(tmp_path / "none.log"))
    assert missing.returncode == 2 and "cannot read the traffic log" in missing.stderr
    foreign = tmp_path / "notes.txt"
    foreign.write_text("shopping list\n")
    refused = _motionctl("--protocol", "coxiris", "log", "decode", str(foreign))
    assert refused.returncode == 2 and "not a traffic log line" in refused.stderr
    bad = _motionctl("--protocol", "coxiris", "log", "decode", str(log), "--filter", "(")
    assert bad.returncode == 2 and "regular expression" in bad.stderr
