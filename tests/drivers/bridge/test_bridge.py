"""The bridge (snoop mode): drivers/bridge.Bridge in-process, and `motionctl bridge` between
`motionsim` and another `motionctl`, every one a process of its own over real pseudo-terminals.

Nothing waits by sleeping: a test waits for a line on a process's output, for bytes on a
descriptor or for a condition, each with a deadline. What the device saw is its own `--record`;
what the bridge saw is its `--log`; both are read back with drivers.traffic.log_reader.read_log.
"""

from __future__ import annotations

import json
import logging
import os
import random
import select
import selectors
import signal
import subprocess
import sys
import threading
import time
import tty
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from drivers.bridge.snoop import Bridge, DeviceVanished
from drivers.errors import PortError
from drivers.link.records import RX, TX, Traffic
from drivers.traffic.log_reader import LogRecord, read_log
from tests.support.simproc import ROOT, SimProcess

pytestmark = [pytest.mark.timeout(60), pytest.mark.usefixtures("settings_file")]

DEADLINE = 10.0  # seconds any one wait may take before the test fails


# -- helpers --------------------------------------------------------------------------------------
def read_exactly(fd: int, count: int, timeout: float = DEADLINE) -> bytes:
    """`count` bytes from `fd`, waiting for them at most `timeout` seconds in all."""
    end = time.monotonic() + timeout
    data = b""
    while len(data) < count:
        left = end - time.monotonic()
        readable, _, _ = select.select([fd], [], [], max(0.0, left))
        if not readable:
            raise AssertionError(f"got {len(data)} of {count} bytes in {timeout} s: {data!r}")
        data += os.read(fd, count - len(data))
    return data


def nothing_arrives(fd: int, within: float) -> bool:
    """True if `fd` has nothing to read for `within` seconds."""
    readable, _, _ = select.select([fd], [], [], within)
    return not readable


def wait_until(condition: Callable[[], bool], timeout: float = DEADLINE) -> None:
    """Wait for `condition` to hold, looking every 10 ms, failing after `timeout` seconds."""
    end = time.monotonic() + timeout
    while not condition():
        if time.monotonic() > end:
            raise AssertionError("the condition did not hold in time")
        time.sleep(0.01)


def stream(records: list[LogRecord], direction: str) -> bytes:
    """All the bytes of one direction of a log, in order."""
    return b"".join(r.data for r in records if r.direction == direction)


def open_program_side(path: str) -> int:
    """The other program's descriptor on the bridge's pty."""
    return os.open(path, os.O_RDWR | os.O_NOCTTY)


class Serving:
    """A bridge's serve_forever on a thread; `error` is what it raised, if anything."""

    def __init__(self, bridge: Bridge) -> None:
        self.bridge = bridge
        self.error: BaseException | None = None
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self) -> None:
        try:
            self.bridge.serve_forever()
        except BaseException as exc:  # handed to the test
            self.error = exc

    def stop(self, timeout: float = DEADLINE) -> None:
        """Stop the bridge and wait for its thread."""
        self.bridge.stop()
        self.thread.join(timeout)
        assert not self.thread.is_alive(), "serve_forever did not return"


class Device:
    """A stand-in device: the master side of a pty, whose slave's path the bridge opens."""

    def __init__(self) -> None:
        self.fd, slave = os.openpty()
        tty.setraw(slave)
        self.path = os.ttyname(slave)
        self._slave = slave

    def opened(self) -> None:
        """The bridge has the slave open: drop ours, so that closing `fd` is a hang-up."""
        if self._slave >= 0:
            os.close(self._slave)
            self._slave = -1

    def vanish(self) -> None:
        """The device goes away (unplugged)."""
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1

    def close(self) -> None:
        """Close what is left."""
        self.opened()
        self.vanish()


@pytest.fixture
def device() -> Iterator[Device]:
    dev = Device()
    yield dev
    dev.close()


@pytest.fixture
def bridged(device: Device) -> Iterator[tuple[Bridge, list[Traffic], Serving]]:
    """A bridge to `device`, serving on a thread, with a tap that keeps every record."""
    seen: list[Traffic] = []
    bridge = Bridge(device.path, 115200, seen.append)
    bridge.open()
    device.opened()
    serving = Serving(bridge)
    yield bridge, seen, serving
    bridge.close()
    serving.thread.join(DEADLINE)


# -- Bridge, in-process ---------------------------------------------------------------------------
EVERY_BYTE = bytes(range(256))


def test_every_byte_goes_through_unchanged_both_ways(
    device: Device, bridged: tuple[Bridge, list[Traffic], Serving]
) -> None:
    bridge, seen, _ = bridged
    program = open_program_side(bridge.path)
    try:
        os.write(program, EVERY_BYTE)
        assert read_exactly(device.fd, 256) == EVERY_BYTE
        os.write(device.fd, EVERY_BYTE[::-1])
        assert read_exactly(program, 256) == EVERY_BYTE[::-1]
    finally:
        os.close(program)
    assert b"".join(r.data for r in seen if r.direction == TX) == EVERY_BYTE
    assert b"".join(r.data for r in seen if r.direction == RX) == EVERY_BYTE[::-1]
    # counted just after the write: the other side may have the bytes a moment before
    wait_until(lambda: (bridge.bytes_to_device, bridge.bytes_from_device) == (256, 256))
    assert all(isinstance(r.time, float) for r in seen)


def test_a_megabyte_each_way_at_once_arrives_whole(
    device: Device, bridged: tuple[Bridge, list[Traffic], Serving]
) -> None:
    """Both directions busy together: back-pressure and partial writes lose nothing."""
    bridge, seen, _ = bridged
    rng = random.Random(7)
    up, down = rng.randbytes(1 << 20), rng.randbytes(1 << 20)
    program = open_program_side(bridge.path)

    def write_all(fd: int, data: bytes) -> None:
        view = memoryview(data)
        while view:
            view = view[os.write(fd, view[:4096]) :]

    writers = [
        threading.Thread(target=write_all, args=(program, up), daemon=True),
        threading.Thread(target=write_all, args=(device.fd, down), daemon=True),
    ]
    for writer in writers:
        writer.start()
    got = {device.fd: bytearray(), program: bytearray()}
    end = time.monotonic() + 30
    try:
        while len(got[device.fd]) < len(up) or len(got[program]) < len(down):
            readable, _, _ = select.select(list(got), [], [], max(0.0, end - time.monotonic()))
            assert readable, "the transfer stalled"
            for fd in readable:
                got[fd] += os.read(fd, 65536)
        for writer in writers:
            writer.join(DEADLINE)
    finally:
        os.close(program)
    assert bytes(got[device.fd]) == up
    assert bytes(got[program]) == down
    assert b"".join(r.data for r in seen if r.direction == TX) == up
    assert b"".join(r.data for r in seen if r.direction == RX) == down
    wait_until(lambda: (bridge.bytes_to_device, bridge.bytes_from_device) == (len(up), len(down)))


@pytest.mark.parametrize("direction", [TX, RX])
def test_the_tap_sees_a_chunk_before_the_other_side_does(device: Device, direction: str) -> None:
    release = threading.Event()
    tapped = threading.Event()

    def tap(record: Traffic) -> None:
        if record.direction == direction:
            tapped.set()
            release.wait(DEADLINE)  # holds the chunk in the tap

    bridge = Bridge(device.path, 115200, tap)
    bridge.open()
    device.opened()
    serving = Serving(bridge)
    program = open_program_side(bridge.path)
    source, destination = (program, device.fd) if direction == TX else (device.fd, program)
    try:
        os.write(source, b"\x00\x0a\x7e")
        assert tapped.wait(DEADLINE)
        assert nothing_arrives(destination, 0.2)  # the tap has it, the other side not yet
        release.set()
        assert read_exactly(destination, 3) == b"\x00\x0a\x7e"
    finally:
        release.set()
        os.close(program)
        serving.stop()
        bridge.close()


def test_stop_returns_promptly_and_close_is_idempotent(
    bridged: tuple[Bridge, list[Traffic], Serving],
) -> None:
    bridge, _, serving = bridged
    start = time.monotonic()
    serving.stop()
    assert time.monotonic() - start < 0.5
    assert serving.error is None
    bridge.close()
    bridge.close()


def test_close_from_another_thread_stops_it(
    bridged: tuple[Bridge, list[Traffic], Serving],
) -> None:
    bridge, _, serving = bridged
    bridge.close()
    serving.thread.join(DEADLINE)
    assert not serving.thread.is_alive() and serving.error is None


def test_the_other_program_closes_and_opens_the_pty_again(
    device: Device, bridged: tuple[Bridge, list[Traffic], Serving]
) -> None:
    bridge, _, serving = bridged
    for round_ in range(3):
        program = open_program_side(bridge.path)
        try:
            os.write(program, f"GET_ID {round_}\n".encode())
            assert read_exactly(device.fd, 9) == f"GET_ID {round_}\n".encode()
            os.write(device.fd, b"ACK\r\n")
            assert read_exactly(program, 5) == b"ACK\r\n"
        finally:
            os.close(program)
    assert serving.thread.is_alive() and serving.error is None


def test_the_device_vanishing_is_a_named_error(
    device: Device, bridged: tuple[Bridge, list[Traffic], Serving]
) -> None:
    bridge, _, serving = bridged
    program = open_program_side(bridge.path)
    try:
        os.write(program, b"x")
        assert read_exactly(device.fd, 1) == b"x"
        device.vanish()
        serving.thread.join(DEADLINE)
    finally:
        os.close(program)
    assert not serving.thread.is_alive(), "serve_forever hangs on a vanished device"
    assert isinstance(serving.error, DeviceVanished)
    assert isinstance(serving.error, PortError)
    assert device.path in str(serving.error) and "went away" in str(serving.error)


def test_a_missing_device_is_a_port_error() -> None:
    bridge = Bridge("/dev/no-such-device-here", 9600)
    with pytest.raises(PortError, match="cannot open /dev/no-such-device-here"):
        bridge.open()
    bridge.close()
    with pytest.raises(PortError, match="not open"):
        Bridge("/dev/no-such-device-here", 9600).serve_forever()


def test_a_failing_tap_is_logged_and_forwarding_goes_on(
    device: Device, caplog: pytest.LogCaptureFixture
) -> None:
    def tap(record: Traffic) -> None:
        raise RuntimeError("disk full")

    with (
        caplog.at_level(logging.ERROR, logger="drivers.bridge.snoop"),
        Bridge(device.path, 115200, tap) as bridge,
    ):
        device.opened()
        serving = Serving(bridge)
        program = open_program_side(bridge.path)
        try:
            for _ in range(2):
                os.write(program, b"ping")
                assert read_exactly(device.fd, 4) == b"ping"
        finally:
            os.close(program)
            serving.stop()
    assert bridge.tap_errors == 2
    assert "tap failed" in caplog.text and "disk full" in caplog.text


def test_a_url_without_a_descriptor_is_bridged_too() -> None:
    """`loop://` echoes: what the program writes comes back to it, through the device side."""
    seen: list[Traffic] = []
    with Bridge("loop://", 115200, seen.append) as bridge:
        serving = Serving(bridge)
        program = open_program_side(bridge.path)
        try:
            os.write(program, b"\x00\x0a\x7e\xff hello")
            assert read_exactly(program, 10) == b"\x00\x0a\x7e\xff hello"
        finally:
            os.close(program)
            serving.stop()
    assert [r.direction for r in seen][:1] == [TX]
    assert b"".join(r.data for r in seen if r.direction == RX) == b"\x00\x0a\x7e\xff hello"


# -- motionctl bridge, between processes ----------------------------------------------------------
class BridgeProcess:
    """`motionctl bridge ...` in a process; `path` is its pty, `lines` what it printed since."""

    def __init__(self, *args: str) -> None:
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "app.cli", "bridge", *args],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
            cwd=ROOT,
        )
        assert self.proc.stdout is not None
        with selectors.DefaultSelector() as selector:
            selector.register(self.proc.stdout, selectors.EVENT_READ)
            ready = selector.select(DEADLINE)
        self.first = self.proc.stdout.readline().strip() if ready else ""
        self.path = self.first
        self.lines: list[str] = []
        self._changed = threading.Condition()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        assert self.proc.stdout is not None
        for line in self.proc.stdout:
            with self._changed:
                self.lines.append(line.rstrip("\n"))
                self._changed.notify_all()

    def wait_for_line(self, text: str, timeout: float = DEADLINE) -> str:
        """The first line printed that contains `text`, waiting for it if need be."""
        with self._changed:
            found = self._changed.wait_for(
                lambda: next((line for line in self.lines if text in line), None), timeout
            )
        assert found, f"no line with {text!r} in {self.lines}"
        return found

    def stop(self, sig: int = signal.SIGTERM) -> tuple[int, str]:
        """Send `sig`; the exit status and stderr."""
        if self.proc.poll() is None:
            self.proc.send_signal(sig)
        return self.wait()

    def wait(self, timeout: float = DEADLINE) -> tuple[int, str]:
        """Wait for the process to end; the exit status and stderr."""
        status = self.proc.wait(timeout)
        self._reader.join(timeout)
        assert self.proc.stderr is not None
        return status, self.proc.stderr.read()

    def kill(self) -> None:
        """End it whatever state it is in."""
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait(DEADLINE)


def motionctl(port: str, protocol: str, *args: str) -> subprocess.CompletedProcess[str]:
    """The third-party program: `motionctl --port PORT --protocol PROTOCOL ARGS`."""
    return subprocess.run(
        [sys.executable, "-m", "app.cli", "--port", port, "--protocol", protocol, *args],
        capture_output=True,
        text=True,
        timeout=30,
        cwd=ROOT,
    )


@pytest.fixture
def processes() -> Iterator[list[SimProcess | BridgeProcess]]:
    """Processes a test started; whatever is still running at the end is killed."""
    started: list[SimProcess | BridgeProcess] = []
    yield started
    for process in reversed(started):
        if process.proc.poll() is None:
            process.kill()


def same_bytes(bridge_log: Path, record: Path) -> bool:
    """The bridge's log and the device's record hold the same bytes, each way."""
    if not (bridge_log.exists() and record.exists()):
        return False
    bridged, device = read_log(bridge_log), read_log(record)
    # The device's RX is what the host wrote (the bridge's TX), its TX what the host read.
    return stream(bridged, TX) == stream(device, RX) and stream(bridged, RX) == stream(device, TX)


def test_coxiris_through_motionctl_bridge(
    tmp_path: Path, processes: list[SimProcess | BridgeProcess]
) -> None:
    record, bridge_log = tmp_path / "device.log", tmp_path / "bridge.log"
    sim = SimProcess("coxiris", "--record", str(record))
    processes.append(sim)
    bridge = BridgeProcess("--port", sim.path, "--protocol", "coxiris", "--log", str(bridge_log))
    processes.append(bridge)
    assert bridge.path.startswith("/dev/") and bridge.path != sim.path

    moved = motionctl(bridge.path, "coxiris", "move", "10", "-5", "2.5")
    assert moved.returncode == 0, moved.stderr
    assert moved.stdout.strip() == "10.00 -5.00 2.50"
    position = motionctl(bridge.path, "coxiris", "--json", "position")
    assert position.returncode == 0, position.stderr
    assert json.loads(position.stdout) == {"position": [10.0, -5.0, 2.5]}

    assert " TX  " in bridge.wait_for_line("ABSOLUTE_MOVE 10 -5 2.5")
    assert " RX  " in bridge.wait_for_line("DONE ABSOLUTE_MOVE")
    assert " RX  " in bridge.wait_for_line("DONE GET_POSITION: 10.00 -5.00 2.50")
    wait_until(lambda: same_bytes(bridge_log, record))
    status, stderr = bridge.stop(signal.SIGINT)
    assert status == 0, stderr
    assert stderr == ""
    records = read_log(bridge_log)
    assert stream(records, TX).count(b"ABSOLUTE_MOVE 10 -5 2.5\n") == 1
    assert b"DONE GET_POSITION: 10.00 -5.00 2.50\r\n" in stream(records, RX)
    assert same_bytes(bridge_log, record)  # after the bridge's own closing note too
    assert sim.stop() == 0


def test_binary_laser_frames_through_motionctl_bridge(
    tmp_path: Path, processes: list[SimProcess | BridgeProcess]
) -> None:
    """X = 63.51 is the float32 3D 0A 7E 42: a newline and a 0x7E on the wire, and zeros."""
    record, bridge_log = tmp_path / "device.log", tmp_path / "bridge.log"
    sim = SimProcess("laser-frame", "--instant", "--record", str(record))
    processes.append(sim)
    bridge = BridgeProcess(
        "--port", sim.path, "--protocol", "laser-frame", "--log", str(bridge_log)
    )
    processes.append(bridge)

    moved = motionctl(bridge.path, "laser-frame", "move", "63.51", "0", "0")
    assert moved.returncode == 0, moved.stderr
    assert moved.stdout.strip() == "63.51 0.00 0.00"
    position = motionctl(bridge.path, "laser-frame", "position")
    assert position.returncode == 0, position.stderr
    assert position.stdout.strip() == "63.51 0.00 0.00"

    assert "3D 0A 7E 42" in bridge.wait_for_line("MOVE_LINEAR [63.5")
    assert "3D 0A 7E 42" in bridge.wait_for_line("GET_POSITION [63.5")
    wait_until(lambda: same_bytes(bridge_log, record))
    status, stderr = bridge.stop(signal.SIGTERM)
    assert status == 0, stderr
    records = read_log(bridge_log)
    sent, got = stream(records, TX), stream(records, RX)
    assert b"\x3d\x0a\x7e\x42" in sent and b"\x3d\x0a\x7e\x42" in got
    assert b"\x00" in sent and b"\x00" in got
    assert sent.startswith(bytes.fromhex("EB 90 82 F0 10 90 82 10"))  # GET_POSITION, stuffed
    assert same_bytes(bridge_log, record)
    assert sim.stop() == 0


def test_json_lines_over_a_url_without_a_descriptor(
    processes: list[SimProcess | BridgeProcess],
) -> None:
    bridge = BridgeProcess("--port", "loop://", "--protocol", "coxiris", "--json")
    processes.append(bridge)
    path = json.loads(bridge.first)["path"]
    program = open_program_side(path)
    try:
        tty.setraw(program)
        os.write(program, b"GET_ID\n")
        assert read_exactly(program, 7) == b"GET_ID\n"  # loop:// echoes
    finally:
        os.close(program)
    sent = json.loads(bridge.wait_for_line('"direction": "tx"'))
    assert sent == {
        "time": sent["time"],
        "direction": "tx",
        "hex": "47 45 54 5F 49 44",
        "meaning": "GET_ID",
        "kind": "frame",
    }
    assert json.loads(bridge.wait_for_line('"direction": "rx"'))["hex"] == "47 45 54 5F 49 44"
    status, stderr = bridge.stop(signal.SIGINT)
    assert status == 0, stderr


def test_a_missing_device_port_exits_3_with_one_line(
    tmp_path: Path, processes: list[SimProcess | BridgeProcess]
) -> None:
    bridge = BridgeProcess("--port", str(tmp_path / "ttyNOPE"), "--protocol", "coxiris")
    processes.append(bridge)
    status, stderr = bridge.wait()
    assert status == 3
    assert bridge.first == "" and bridge.lines == []
    assert len(stderr.strip().splitlines()) == 1
    assert stderr.startswith(f"motionctl: cannot open {tmp_path / 'ttyNOPE'}")


def test_the_device_vanishing_exits_3_with_one_line(
    processes: list[SimProcess | BridgeProcess],
) -> None:
    sim = SimProcess("coxiris")
    processes.append(sim)
    bridge = BridgeProcess("--port", sim.path, "--protocol", "coxiris")
    processes.append(bridge)
    assert bridge.path.startswith("/dev/")
    sim.kill()
    status, stderr = bridge.wait()
    assert status == 3
    assert len(stderr.strip().splitlines()) == 1
    assert stderr.startswith(f"motionctl: the device on {sim.path} went away")


def test_bad_input_exits_2_and_opens_nothing(
    tmp_path: Path, processes: list[SimProcess | BridgeProcess]
) -> None:
    for args in (
        ("--port", "loop://", "--protocol", "nope"),
        ("--port", "loop://", "--protocol", "coxiris", "--baud", "0"),
        ("--port", "loop://", "--protocol", "coxiris", "--log", str(tmp_path / "no" / "x")),
    ):
        bridge = BridgeProcess(*args)
        processes.append(bridge)
        status, stderr = bridge.wait()
        assert status == 2, (args, stderr)
        assert bridge.first == ""
