"""The acceptance tier's tools: an X server with a window manager, the real panel and simulator
processes, xdotool input, and what a user or the device can see (logs, records, screenshots).

Nothing here reaches into the panel: it is driven only by X input events (xdotool) and observed
only through the session log's bytes, the simulator's own record (`motionsim --record`),
screenshots and the window's geometry.
"""

from __future__ import annotations

import contextlib
import logging
import os
import re
import selectors
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TypeVar

from PySide6.QtCore import QSettings
from PySide6.QtGui import QImage

from app.common.settings import write_travel
from drivers.device.travel import TravelLimits

log = logging.getLogger(__name__)

ROOT = Path(__file__).resolve().parents[2]
TOOLS = ("Xvfb", "openbox", "xdotool", "xprop", "import")
SCREENS = ((1024, 640), (1280, 720), (1600, 1000))
WINDOW_TITLE = "^Motion Panel$"

T = TypeVar("T")

# The status bar's machine-state badge (widgets/status_line.py), as the operator sees it.
STATE_COLOURS = {
    "disconnected": 0x616161,
    "connecting": 0xEF6C00,
    "idle": 0x2E7D32,
    "moving": 0x1565C0,
    "busy": 0x6A1B9A,
    "error": 0xC62828,
}
BADGE_PIXELS = 150  # a badge shows thousands of its colour's pixels; text has a few


class Timeout(AssertionError):
    """A condition the scenario waited for did not come within its deadline."""


def missing_tools() -> list[str]:
    """The X tools the tier needs that are not installed."""
    return [tool for tool in TOOLS if shutil.which(tool) is None]


def wait_for(predicate: Callable[[], T], timeout: float, what: str, interval: float = 0.02) -> T:
    """Poll `predicate` until it returns something true (returned) or `timeout` seconds pass
    (Timeout naming `what`)."""
    deadline = time.monotonic() + timeout
    while True:
        value = predicate()
        if value:
            return value
        if time.monotonic() >= deadline:
            raise Timeout(f"no {what} within {timeout:g} s")
        time.sleep(interval)


def hold(seconds: float, every: Callable[[], object] | None = None) -> None:
    """Let `seconds` pass (an operator holding a key), calling `every` meanwhile."""
    end = time.monotonic() + seconds
    while (left := end - time.monotonic()) > 0:
        if every is not None:
            every()
        time.sleep(min(0.01, left))


# -- the X server ------------------------------------------------------------------------------


class XServer:
    """Xvfb of one screen size with openbox managing it; `display` is ":N"."""

    def __init__(self, width: int, height: int) -> None:
        self.size = (width, height)
        read, write = os.pipe()
        try:
            self.xvfb = subprocess.Popen(
                [
                    "Xvfb",
                    "-displayfd",
                    str(write),
                    "-screen",
                    "0",
                    f"{width}x{height}x24",
                    "+extension",
                    "GLX",
                    "-nolisten",
                    "tcp",
                    "-noreset",  # no reset when its last client (a window manager ended) goes
                ],
                pass_fds=(write,),
                stdout=subprocess.DEVNULL,
                stderr=subprocess.DEVNULL,
            )
        finally:
            os.close(write)
        number = _read_line(read, 20.0, "Xvfb's display number")
        os.close(read)
        self.display = f":{number}"
        self.env = {**os.environ, "DISPLAY": self.display}
        self.env.pop("XAUTHORITY", None)
        self.wm = subprocess.Popen(
            ["openbox", "--sm-disable"],
            env=self.env,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        wait_for(self._managed, 20.0, f"window manager on {self.display}", interval=0.05)

    def _managed(self) -> bool:
        """Whether a window manager owns the screen (_NET_SUPPORTING_WM_CHECK is set)."""
        done = self.run("xprop", "-root", "_NET_SUPPORTING_WM_CHECK", check=False)
        return done.returncode == 0 and "window id" in done.stdout

    def run(
        self, *args: str, check: bool = True, timeout: float = 10.0
    ) -> subprocess.CompletedProcess:
        """Run an X client (xdotool, xprop, import) on this display."""
        done = subprocess.run(
            args, env=self.env, capture_output=True, text=True, timeout=timeout, check=False
        )
        if check and done.returncode != 0:
            raise RuntimeError(f"{' '.join(args)} failed ({done.returncode}): {done.stderr}")
        return done

    def xdotool(self, *args: str) -> str:
        """Run xdotool with `args`; its output."""
        return self.run("xdotool", *args).stdout

    def screenshot(self, path: Path) -> Path:
        """The whole screen as a PNG at `path`."""
        self.run("import", "-window", "root", str(path), timeout=30.0)
        return path

    def grab(self, path: Path, region: tuple[int, int, int, int] | None = None) -> QImage:
        """The screen, or a region (x, y, width, height) of it, as an image (also at `path`)."""
        args = ["import", "-window", "root"]
        if region is not None:
            x, y, w, h = region
            args += ["-crop", f"{w}x{h}+{x}+{y}", "+repage"]
        self.run(*args, str(path), timeout=30.0)
        image = QImage(str(path))
        if image.isNull():
            raise RuntimeError(f"cannot read the screenshot {path}")
        return image

    def stop(self) -> None:
        """End openbox and Xvfb."""
        for proc in (self.wm, self.xvfb):
            if proc.poll() is None:
                proc.terminate()
            try:
                proc.wait(10)
            except subprocess.TimeoutExpired:
                proc.kill()
                proc.wait(10)


def _read_line(fd: int, timeout: float, what: str) -> str:
    """A line from a pipe, within `timeout` seconds."""
    selector = selectors.DefaultSelector()
    selector.register(fd, selectors.EVENT_READ)
    data = b""
    deadline = time.monotonic() + timeout
    try:
        while not data.endswith(b"\n"):
            left = deadline - time.monotonic()
            if left <= 0 or not selector.select(left):
                raise Timeout(f"no {what} within {timeout:g} s")
            chunk = os.read(fd, 64)
            if not chunk:
                raise Timeout(f"{what}: the pipe closed")
            data += chunk
    finally:
        selector.close()
    return data.decode().strip()


def colour_count(image: QImage, rgb: int, tolerance: int = 0) -> int:
    """How many pixels of `image` are the colour `rgb` (0xRRGGBB), each channel within
    `tolerance`."""
    import numpy as np

    image = image.convertToFormat(QImage.Format.Format_RGB32)
    pixels = np.frombuffer(image.constBits(), dtype=np.uint32, count=image.width() * image.height())
    channels = [(pixels >> shift) & 0xFF for shift in (16, 8, 0)]
    wanted = [(rgb >> shift) & 0xFF for shift in (16, 8, 0)]
    close = np.ones(pixels.shape, dtype=bool)
    for channel, value in zip(channels, wanted, strict=True):
        close &= np.abs(channel.astype(np.int16) - value) <= tolerance
    return int(close.sum())


# -- traffic files: the session log and the simulator's record -------------------------------

_RECORD = re.compile(r"^(\d{6,}\.\d{3}) (TX|RX)   ((?:[0-9A-F]{2} ){0,15}[0-9A-F]{2})")
_NOTE = re.compile(r"^(?:(\d{6,}\.\d{3}) )?# ?(.*)$")


@dataclass(frozen=True)
class Entry:
    """One line's record of a traffic log: `direction` "tx"/"rx" with bytes, or a note."""

    time: float
    direction: str
    data: bytes
    note: str = ""


def read_entries(path: Path) -> list[Entry]:
    """The complete lines of a traffic log (the format of `motionctl --log`) as entries; a line
    still being written is left for the next read."""
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except FileNotFoundError:
        return []
    entries: list[Entry] = []
    last = 0.0
    for line in text.split("\n")[:-1]:
        hit = _RECORD.match(line)
        if hit is not None:
            last = float(hit.group(1))
            entries.append(Entry(last, hit.group(2).lower(), bytes.fromhex(hit.group(3))))
            continue
        note = _NOTE.match(line)
        if note is not None:
            stamp = float(note.group(1)) if note.group(1) else last
            entries.append(Entry(stamp, "", b"", note.group(2)))
    return entries


@dataclass(frozen=True)
class Line:
    """A line (terminator removed) that crossed one way, stamped with its last record's time."""

    time: float
    text: str


def split_lines(entries: Iterable[Entry], direction: str) -> list[Line]:
    """The `direction` bytes of `entries` as complete lines (a line protocol: COXIRIS)."""
    lines: list[Line] = []
    pending = b""
    for entry in entries:
        if entry.direction != direction:
            continue
        pending += entry.data
        while b"\n" in pending:
            line, pending = pending.split(b"\n", 1)
            lines.append(Line(entry.time, line.strip(b"\r").decode("ascii", "replace")))
    return lines


class DeviceRecord:
    """The simulator's own record (`motionsim --record`): what the device received and sent,
    with the simulator's times (seconds since it started), mapped to this process's clock."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._offset: float | None = None  # monotonic() - record time, smallest seen

    def entries(self) -> list[Entry]:
        """Every complete record so far; the clock offset is refined from the newest."""
        now = time.monotonic()
        entries = read_entries(self.path)
        stamped = [e for e in entries if e.direction]
        if stamped:
            offset = now - stamped[-1].time
            if self._offset is None or offset < self._offset:
                self._offset = offset
        return entries

    def observe(self) -> None:
        """Read the record once to refine the clock mapping."""
        self.entries()

    def to_local(self, record_time: float) -> float:
        """A record time as time.monotonic() of this process (at the latest: the mapping is
        learnt from when records were seen, never earlier than they were written)."""
        assert self._offset is not None, "the record was never read"
        return record_time + self._offset

    def received_lines(self) -> list[Line]:
        """The lines the device received (COXIRIS commands)."""
        return split_lines(self.entries(), "rx")

    def commands(self, name: str) -> list[Line]:
        """The lines the device received that start with the command `name`."""
        return [line for line in self.received_lines() if line.text.split(" ", 1)[0] == name]

    def sent_lines(self) -> list[Line]:
        """The lines the device sent (COXIRIS replies)."""
        return split_lines(self.entries(), "tx")

    def received_bytes(self) -> bytes:
        """Every byte the device received."""
        return b"".join(e.data for e in self.entries() if e.direction == "rx")

    def received_frames(self, protocol: str) -> list[Line]:
        """What the device received, decoded by the protocol's own decoder (drivers/decoding),
        each frame's meaning as a line (e.g. "STOP" for laser-frame)."""
        from drivers.protocols.registry import create_protocol
        from drivers.traffic.decoding import StreamDecoder

        decoder = StreamDecoder(create_protocol(protocol))
        frames: list[Line] = []
        for entry in self.entries():
            if entry.direction == "rx":  # what the host sent: "tx" to the decoder
                for frame in decoder.feed_bytes("tx", entry.data, entry.time):
                    frames.append(Line(frame.time, str(frame.meaning)))
        return frames


def numbers(line: Line) -> list[float]:
    """The numeric arguments of a command line ("ABSOLUTE_MOVE 12.5 0 0" → [12.5, 0, 0])."""
    return [float(part) for part in line.text.split()[1:]]


@dataclass(frozen=True)
class Frame:
    """A frame of the traffic as the panel saw it: `direction` "tx" (the panel sent it) or
    "rx" (it received it), and its meaning by the protocol's own decoder."""

    time: float
    direction: str
    meaning: str


def decode_frames(entries: Iterable[Entry], protocol: str) -> list[Frame]:
    """`entries` of a session log (the panel's directions), decoded by `protocol`'s decoder."""
    from drivers.protocols.registry import create_protocol
    from drivers.traffic.decoding import StreamDecoder

    decoder = StreamDecoder(create_protocol(protocol))
    frames: list[Frame] = []
    for entry in entries:
        if entry.direction:
            for frame in decoder.feed_bytes(entry.direction, entry.data, entry.time):
                frames.append(Frame(frame.time, entry.direction, str(frame.meaning)))
    return frames


_SEQUENCE = re.compile(r"^SEQUENCE \[(-?\d+)")
_MOVE_LINEAR = re.compile(r"MOVE_LINEAR \[([^\]]*)\]")


def laser_moves(meanings: Iterable[str]) -> list[tuple[float, ...]]:
    """The MOVE_LINEAR targets (x, y, z, speed) that laser-frame frames sent carry, in order;
    a queued frame sent again with its SEQUENCE number (a retransmission) counted once."""
    seen: set[int] = set()
    moves: list[tuple[float, ...]] = []
    for meaning in meanings:
        sequence = _SEQUENCE.match(meaning)
        if sequence is not None:
            number = int(sequence.group(1))
            if number in seen:
                continue
            seen.add(number)
        moves += [
            tuple(float(v) for v in hit.group(1).split(","))
            for hit in _MOVE_LINEAR.finditer(meaning)
        ]
    return moves


class SessionLog:
    """The panel's session logs (MOTIONPANEL_LOG_DIR): every byte of every connection."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder

    def entries(self) -> list[Entry]:
        """Every complete line of every session file, oldest file first."""
        files = sorted(self.folder.glob("session-*.log"), key=lambda p: p.stat().st_mtime_ns)
        return [entry for file in files for entry in read_entries(file)]

    def connections(self) -> list[list[Entry]]:
        """The entries after each `connected to` note, one list per connection."""
        parts: list[list[Entry]] = []
        for entry in self.entries():
            if entry.note.startswith("connected to"):
                parts.append([])
            elif parts:
                parts[-1].append(entry)
        return parts

    def notes(self) -> list[str]:
        """Every note."""
        return [e.note for e in self.entries() if not e.direction]

    def handshakes(self, reply: bytes) -> int:
        """How many connections got `reply` from the device (e.g. b"DONE GET_ID")."""
        return sum(
            reply in b"".join(e.data for e in part if e.direction == "rx")
            for part in self.connections()
        )

    def settled(self, reply: bytes) -> int:
        """How many connections got `reply` and then sent something more (the panel went on
        to poll: it has taken the reply in)."""
        count = 0
        for part in self.connections():
            received = b""
            for index, entry in enumerate(part):
                if entry.direction == "rx":
                    received += entry.data
                    if reply in received:
                        count += any(e.direction == "tx" for e in part[index + 1 :])
                        break
        return count

    def sent_lines(self) -> list[Line]:
        """The lines the panel sent, every connection."""
        return split_lines(self.entries(), "tx")

    def frames(self, protocol: str) -> list[Frame]:
        """Every frame of every connection, both ways, decoded by `protocol`."""
        return decode_frames(self.entries(), protocol)


def motionctl(*args: str, timeout: float = 30.0) -> subprocess.CompletedProcess:
    """Run `motionctl ARGS` to its end; its exit status and output."""
    return subprocess.run(
        [sys.executable, "-m", "app.cli", *args],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=timeout,
        check=False,
    )


# -- the simulated device ----------------------------------------------------------------------


class Sim:
    """A `motionsim PROTOCOL --record FILE` process on a pseudo-terminal; `path` is where the
    panel opens it (the --link path when one is given)."""

    def __init__(
        self,
        protocol: str,
        record: Path,
        *args: str,
        link: Path | None = None,
        control: bool = False,
        startup_timeout: float = 20.0,
    ) -> None:
        extra = [*args]
        if link is not None:
            extra += ["--link", str(link)]
        if control:
            extra.append("--control")
        self.record = DeviceRecord(record)
        self.link = link
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "app.simcli", protocol, "--record", str(record), *extra],
            stdin=subprocess.PIPE if control else subprocess.DEVNULL,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            cwd=ROOT,
        )
        assert self.proc.stdout is not None
        try:
            self.pty = _read_line(
                self.proc.stdout.fileno(), startup_timeout, "motionsim device path"
            )
        except Timeout:
            self.kill()
            _, err = self.proc.communicate(timeout=10)
            raise Timeout(f"motionsim {protocol} {' '.join(extra)} gave no path: {err!r}") from None
        self.path = str(link) if link is not None else self.pty

    def fault(self, command: str, timeout: float = 10.0) -> str:
        """Apply a fault (`--control`); its answer."""
        assert self.proc.stdin is not None and self.proc.stdout is not None
        self.proc.stdin.write(command.encode() + b"\n")
        self.proc.stdin.flush()
        answer = _read_line(self.proc.stdout.fileno(), timeout, f"answer to {command!r}")
        if not answer.startswith("ok "):
            raise RuntimeError(f"motionsim refused {command!r}: {answer}")
        return answer

    def kill(self) -> None:
        """Make the device vanish at once (SIGKILL)."""
        if self.proc.poll() is None:
            self.proc.kill()
        self.proc.wait(10)

    def vanish(self) -> None:
        """Kill the device at once and remove its --link, as a USB adapter's node disappears
        when it is pulled (a stale link could lead to another process's pty, once its number
        is given out again)."""
        self.kill()
        if self.link is not None:
            self.link.unlink(missing_ok=True)

    def stop(self) -> None:
        """End the simulator (SIGTERM, then SIGKILL)."""
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(10)
            except subprocess.TimeoutExpired:
                self.kill()
        for stream in (self.proc.stdin, self.proc.stdout, self.proc.stderr):
            if stream is not None:
                stream.close()


# -- the settings a returning user has ---------------------------------------------------------


def write_settings(
    path: Path,
    *,
    protocol: str,
    port: str,
    travel: tuple[tuple[float, float], ...] | None = None,
    jog_step: float | None = None,
    extra: dict[str, object] | None = None,
) -> Path:
    """Pre-write the settings file a returning user would have (MOTIONPANEL_SETTINGS)."""
    settings = QSettings(str(path), QSettings.Format.IniFormat)
    if travel is not None:
        write_travel(settings, protocol, port, TravelLimits(travel, False))
    if jog_step is not None:
        settings.setValue("jog_step", jog_step)
    for key, value in (extra or {}).items():
        settings.setValue(key, value)
    settings.sync()
    return path


def write_program(path: Path, points: Iterable[tuple[float, float, float, float]]) -> Path:
    """A program file (CSV: x, y, z, speed) of `points`."""
    rows = "".join(f"{x:g},{y:g},{z:g},{speed:g}\n" for x, y, z, speed in points)
    path.write_text("x,y,z,speed\n" + rows, encoding="utf-8")
    return path


# -- the panel ---------------------------------------------------------------------------------


class Panel:
    """The real `motionpanel` process on an X server, driven by xdotool only."""

    def __init__(
        self,
        x: XServer,
        tmp: Path,
        *args: str,
        settings: Path | None = None,
        window_timeout: float = 30.0,
        env_extra: dict[str, str] | None = None,
    ) -> None:
        self.x = x
        self.logs = SessionLog(tmp / "session-logs")
        self.logs.folder.mkdir(parents=True, exist_ok=True)
        env = dict(x.env)
        env.pop("QT_QPA_PLATFORM", None)
        env.update(
            LIBGL_ALWAYS_SOFTWARE="1",
            MOTIONPANEL_SETTINGS=str(settings or tmp / "settings.ini"),
            MOTIONPANEL_LOG_DIR=str(self.logs.folder),
        )
        env.update(env_extra or {})
        self.shots = tmp / "panel-screens"
        self.shots.mkdir(exist_ok=True)
        self.stderr_path = tmp / "panel-stderr.txt"
        self._stderr = self.stderr_path.open("wb")
        self.proc = subprocess.Popen(
            [sys.executable, "-m", "app.main", *args],
            cwd=ROOT,
            env=env,
            stdin=subprocess.DEVNULL,
            stdout=self._stderr,
            stderr=subprocess.STDOUT,
        )
        self.window = wait_for(self._find_window, window_timeout, "Motion Panel window")
        self.fit_to_screen()

    def _find_window(self) -> str:
        """The panel's visible top-level window id, "" while there is none."""
        if self.proc.poll() is not None:
            raise RuntimeError(f"motionpanel exited ({self.proc.returncode}): {self.stderr()}")
        found = self.x.run(
            "xdotool",
            "search",
            "--onlyvisible",
            "--pid",
            str(self.proc.pid),
            "--name",
            WINDOW_TITLE,
            check=False,
        )
        ids = found.stdout.split()
        return ids[0] if ids else ""

    def stderr(self) -> str:
        """What the panel printed."""
        return self.stderr_path.read_text(errors="replace")

    def geometry(self) -> tuple[int, int, int, int]:
        """The window's x, y, width, height on the screen (its content, without the window
        manager's frame; xdotool's position is relative to that frame, so xwininfo's absolute
        one is used)."""
        info = self.x.run("xwininfo", "-id", self.window).stdout
        found = [
            re.search(rf"{label}:\s+(-?\d+)", info)
            for label in ("Absolute upper-left X", "Absolute upper-left Y", "Width", "Height")
        ]
        if not all(found):
            raise AssertionError(f"no geometry in xwininfo's answer: {info}")
        x, y, w, h = (int(match.group(1)) for match in found if match is not None)
        return x, y, w, h

    def fit_to_screen(self) -> None:
        """Move and resize the window to fill the screen, as an operator would (the window
        manager may refuse what the window's minimum size does not allow)."""
        width, height = self.x.size
        self.x.xdotool("windowmove", self.window, "0", "0")
        self.x.xdotool("windowsize", self.window, str(width), str(height))
        wait_for(
            lambda: self.geometry()[2:] != (0, 0) and self.geometry()[2] <= width,
            10.0,
            "window resized to the screen",
        )
        self.fit_inside_screen()  # the title bar pushes the bottom (the status bar) off it

    def fit_inside_screen(self) -> None:
        """Shrink the window so that all of it, status bar included, is on the screen below the
        window manager's title bar (`fit_to_screen` makes the window as big as the screen: its
        bottom goes off the screen when openbox decorates it, as at 1600x1000)."""
        left, top = self.geometry()[:2]
        width, height = self.x.size[0] - max(left, 0), self.x.size[1] - max(top, 0)
        self.x.xdotool("windowsize", self.window, str(width), str(height))
        wait_for(
            lambda: self.geometry()[2:] == (width, height),
            10.0,
            f"window resized to {width}x{height}",
        )

    def activate(self) -> None:
        """Give the window the keyboard (as a click on its title would)."""
        self.x.xdotool("windowactivate", "--sync", self.window)
        wait_for(
            lambda: self.x.xdotool("getactivewindow").strip() == self.window,
            5.0,
            "the panel as the active window",
        )

    def key(self, *keys: str) -> None:
        """Press and release keys (xdotool names: Return, alt+x, ctrl+a...) in the window."""
        self.activate()
        self.x.xdotool("key", "--delay", "30", *keys)

    def type(self, text: str) -> None:
        """Type `text` into whatever has the focus."""
        self.activate()
        self.x.xdotool("type", "--delay", "30", "--", text)

    def keydown(self, key: str) -> None:
        """Press and hold `key`."""
        self.activate()
        self.x.xdotool("keydown", key)

    def keyup(self, key: str) -> None:
        """Release `key`."""
        self.x.xdotool("keyup", key)

    def load_program(self, path: Path, timeout: float = 30.0) -> str:
        """Load a program file as an operator does with the keyboard: the Program panel's Load
        (Alt+L), its path typed in the file dialog, Return; then wait until the panel has read
        it (it reads in the background; the session log notes it). Returns that note."""

        def loaded() -> list[str]:
            return [n for n in self.logs.notes() if n.startswith(f"program loaded: {path.name},")]

        before = len(loaded())
        self.key("alt+l")
        self.answer_file_dialog("^Load a program$", path)
        wait_for(
            lambda: self.alive() and len(loaded()) > before,
            timeout,
            f"the program {path.name} read (the session log's note)",
        )
        return loaded()[-1]

    def dialog(self, title: str, timeout: float = 15.0) -> str:
        """The panel's visible window titled `title` (a regular expression), once it is shown."""

        def find() -> str:
            self.alive()
            found = self.x.run(
                "xdotool",
                "search",
                "--onlyvisible",
                "--pid",
                str(self.proc.pid),
                "--name",
                title,
                check=False,
            )
            return next((w for w in found.stdout.split() if w != self.window), "")

        return wait_for(find, timeout, f"the window {title!r}", interval=0.05)

    def answer_file_dialog(self, title: str, path: Path, timeout: float = 15.0) -> None:
        """In the file dialog titled `title`, replace the file name by `path` and press Return
        (as an operator types a path); wait until the dialog has closed."""
        window = self.dialog(title, timeout)
        self.x.xdotool("windowactivate", "--sync", window)
        wait_for(
            lambda: self.x.xdotool("getactivewindow").strip() == window,
            5.0,
            f"the window {title!r} active",
        )
        self.x.xdotool("key", "--delay", "30", "ctrl+a")
        self.x.xdotool("type", "--delay", "30", "--", str(path))
        self.x.xdotool("key", "Return")

        def closed() -> bool:
            self.alive()
            shown = self.x.run("xdotool", "search", "--onlyvisible", "--name", title, check=False)
            return window not in shown.stdout.split()

        wait_for(closed, timeout, f"the window {title!r} closed", interval=0.05)

    def wait_handshake(self, reply: bytes, timeout: float = 30.0, count: int = 1) -> None:
        """Wait until the session log shows `count` connections answered with `reply`."""
        wait_for(
            lambda: self.alive() and self.logs.handshakes(reply) >= count,
            timeout,
            f"handshake {reply!r} #{count} in the session log",
        )

    def wait_ready(self, reply: bytes, timeout: float = 30.0, count: int = 1) -> None:
        """Wait until the session log shows the `count`th connection answered with `reply`
        and the status bar shows Idle (connected, as the operator sees it)."""
        self.wait_handshake(reply, timeout, count)
        self.wait_state("idle", timeout)

    def alive(self) -> bool:
        """True while the process runs; RuntimeError with its output once it has ended."""
        if self.proc.poll() is not None:
            raise RuntimeError(f"motionpanel exited ({self.proc.returncode}): {self.stderr()}")
        return True

    def screenshot(self, path: Path) -> Path:
        """The screen as a PNG."""
        return self.x.screenshot(path)

    def state(self) -> str:
        """The machine state the status bar's badge shows (by its colour), "" if none."""
        x, y, w, h = self.geometry()
        strip = (max(x, 0), max(y + h - 40, 0), min(w, 300), 40)  # the status bar's left end
        if strip[1] + strip[3] > self.x.size[1]:  # `import` would grab the whole screen
            raise AssertionError(f"the status bar ({strip}) is off the {self.x.size} screen")
        image = self.x.grab(self.shots / "state.png", strip)
        counts = {name: colour_count(image, rgb) for name, rgb in STATE_COLOURS.items()}
        name, count = max(counts.items(), key=lambda item: item[1])
        return name if count >= BADGE_PIXELS else ""

    def type_port(self, port: str, timeout: float = 20.0) -> None:
        """Type `port` in the Port field (its label's mnemonic) and Enter; wait until the
        session log notes the connection to it."""
        self.key("alt+p")
        self.key("ctrl+a")
        self.type(port)
        self.key("Return")
        wait_for(
            lambda: any(n.startswith(f"connected to {port}") for n in self.logs.notes()),
            timeout,
            f"the connection to {port}",
        )

    def wait_state(self, state: str, timeout: float = 30.0) -> None:
        """Wait until the status bar shows the machine state `state` (e.g. "idle")."""
        seen: list[str] = []

        def shown() -> bool:
            seen.append(self.alive() and self.state())
            return seen[-1] == state

        try:
            wait_for(shown, timeout, f"state {state!r} in the status bar", interval=0.1)
        except Timeout as exc:
            raise Timeout(f"{exc}; it showed {sorted(set(seen))}") from None

    def close(self) -> None:
        """End the panel (SIGTERM: it closes its window and port), SIGKILL if it hangs."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(15)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait(10)
        self._stderr.close()


# -- load --------------------------------------------------------------------------------------


@contextlib.contextmanager
def busy_cpu(count: int = 3) -> Iterator[None]:
    """`count` processes of `yes > /dev/null` while the block runs."""
    procs = [
        subprocess.Popen(["yes"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        for _ in range(count)
    ]
    try:
        yield
    finally:
        for proc in procs:
            proc.kill()
        for proc in procs:
            proc.wait(10)
