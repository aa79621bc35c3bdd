"""A bench: the devices of one positioning bench, named in a TOML file, opened together.

    [devices.stage]
    port = "/dev/ttyUSB0"
    protocol = "coxiris"
    travel = "-100:100,-50:50,0:20"   # or { x = [-100, 100], y = [-50, 50], z = [0, 20] }
    speed = 10

    [devices.rotary]
    port = "/dev/ttyUSB1"
    protocol = "visiomex"
    variant = "prefixed"

A device takes `port` and `protocol` (required), `variant`, `baud`, `timeout` (s), `travel`,
`speed` (mm/s, set once the device is open) and `settings` (the protocol's, e.g.
`{ ticks_per_mm = 100 }`). The whole file is checked before any port is opened; a refusal is
a `BenchError` naming the file, the device and the line where it can.
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import TracebackType
from typing import Any

from drivers.device.travel import parse_travel
from drivers.errors import BadFile, BadInput
from drivers.files import BENCH_MAX_BYTES, read_text
from drivers.messages import Message
from drivers.protocols.registry import create_protocol, protocol_names
from drivers.session.device_session import DeviceSession, open_device

NAME = re.compile(r"[A-Za-z0-9_-]{1,32}")
KEYS = ("port", "protocol", "variant", "baud", "timeout", "travel", "speed", "settings")
AXES = ("x", "y", "z")


class BenchError(BadFile):
    """A bench file that cannot be used: says which file, which device and why."""


@dataclass(frozen=True)
class BenchDevice:
    """One device of a bench, as its file names it (checked, not opened)."""

    name: str
    port: str
    protocol: str
    variant: str | None = None
    baud: int | None = None
    timeout: float = 2.0
    travel: str | None = None
    speed: float | None = None
    settings: Mapping[str, float] = field(default_factory=dict)

    def open(self, **options: Any) -> DeviceSession:
        """Open this device (`options`: more of `open_device`'s, e.g. `log`); at its speed."""
        session = open_device(
            self.port,
            self.protocol,
            variant=self.variant,
            baud=self.baud,
            timeout=self.timeout,
            settings=self.settings,
            travel=self.travel,
            **options,
        )
        if self.speed is not None and options.get("start", True):
            try:
                session.speed(self.speed)
            except BaseException:
                session.close()
                raise
        return session


def _line_of(text: str, name: str) -> int | None:
    match = re.search(rf"^\s*\[\s*devices\.[\"']?{re.escape(name)}[\"']?\s*\]", text, re.MULTILINE)
    return text.count("\n", 0, match.start()) + 1 if match else None


class _Reader:
    """Checks one bench file's parsed content, naming the file and the device in refusals."""

    def __init__(self, source: str, text: str) -> None:
        self.source, self.text = source, text

    def refuse(self, why: str, device: str | None = None) -> BenchError:
        if device is None:
            return BenchError(Message("{source}: {why}", source=self.source, why=why))
        line = _line_of(self.text, device)
        where = f"{self.source}:{line}" if line else self.source
        return BenchError(
            Message("{where}: device {device!r}: {why}", where=where, device=device, why=why)
        )

    def devices(self, data: dict[str, Any]) -> dict[str, BenchDevice]:
        unknown = sorted(set(data) - {"devices"})
        if unknown:
            raise self.refuse(f"unknown key {unknown[0]!r} (a bench has [devices.NAME] tables)")
        devices = data.get("devices")
        if not isinstance(devices, dict) or not devices:
            raise self.refuse("no devices: name each in a [devices.NAME] table")
        return {name: self.device(name, entry) for name, entry in devices.items()}

    def device(self, name: str, entry: object) -> BenchDevice:
        if not NAME.fullmatch(name):
            raise self.refuse("a name of 1 to 32 letters, digits, '-' or '_'", name)
        if not isinstance(entry, dict):
            raise self.refuse("write it as a [devices.NAME] table", name)
        unknown = sorted(set(entry) - set(KEYS))
        if unknown:
            raise self.refuse(f"unknown key {unknown[0]!r} (known: {', '.join(KEYS)})", name)
        port, protocol = entry.get("port"), entry.get("protocol")
        if not isinstance(port, str) or not port.strip():
            raise self.refuse("port: the device path or URL, in quotes", name)
        choices = protocol_names()
        if protocol not in choices:
            raise self.refuse(f"protocol: one of {', '.join(choices)}", name)
        variant = self._optional(entry, "variant", str, name)
        try:
            made = create_protocol(protocol, variant or None)
        except BadInput as exc:
            raise self.refuse(str(exc), name) from None
        settings = self._settings(entry.get("settings", {}), {s.name for s in made.settings}, name)
        baud = self._optional(entry, "baud", int, name)
        if baud is not None and baud <= 0:
            raise self.refuse("baud: a positive number of bits per second", name)
        timeout = self._number(entry, "timeout", name)
        speed = self._number(entry, "speed", name)
        return BenchDevice(
            name,
            port,
            protocol,
            variant=variant,
            baud=baud,
            timeout=2.0 if timeout is None else timeout,
            travel=self._travel(entry.get("travel"), name),
            speed=speed,
            settings=settings,
        )

    def _optional(self, entry: dict[str, Any], key: str, kind: type, name: str) -> Any:
        value = entry.get(key)
        if value is not None and (not isinstance(value, kind) or isinstance(value, bool)):
            raise self.refuse(
                f"{key}: {'a whole number' if kind is int else 'text in quotes'}", name
            )
        return value

    def _number(self, entry: dict[str, Any], key: str, name: str) -> float | None:
        value = entry.get(key)
        if value is None:
            return None
        if isinstance(value, bool) or not isinstance(value, int | float) or not value > 0:
            raise self.refuse(f"{key}: a positive number", name)
        return float(value)

    def _settings(self, values: object, known: set[str], name: str) -> dict[str, float]:
        if not isinstance(values, dict):
            raise self.refuse("settings: a table such as { ticks_per_mm = 100 }", name)
        for key, value in values.items():
            if key not in known:
                offered = ", ".join(sorted(known)) or "none"
                raise self.refuse(
                    f"settings: {key!r} is not one of the protocol's ({offered})", name
                )
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise self.refuse(f"settings: {key} must be a number", name)
        return {key: float(value) for key, value in values.items()}

    def _travel(self, value: object, name: str) -> str | None:
        if value is None:
            return None
        if isinstance(value, dict):
            value = self._travel_table(value, name)
        if not isinstance(value, str):
            raise self.refuse("travel: 'X0:X1,Y0:Y1,Z0:Z1' or { x = [X0, X1], ... }", name)
        try:
            parse_travel(value)
        except BadInput as exc:
            raise self.refuse(str(exc), name) from None
        return value

    def _travel_table(self, value: dict[str, Any], name: str) -> str:
        ranges = []
        for axis in AXES:
            pair = value.get(axis)
            if not (
                isinstance(pair, list)
                and len(pair) == 2
                and all(isinstance(v, int | float) and not isinstance(v, bool) for v in pair)
            ):
                raise self.refuse(f"travel: {axis} = [lowest, highest] in mm", name)
            ranges.append(f"{pair[0]}:{pair[1]}")
        if set(value) - set(AXES):
            raise self.refuse("travel: the axes are x, y and z", name)
        return ",".join(ranges)


def parse_bench(text: str, source: str = "bench") -> dict[str, BenchDevice]:
    """The devices of a bench file's text, by name, in the file's order; BenchError if any
    is wrong."""
    reader = _Reader(source, text)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise reader.refuse(f"not a bench file: {exc}") from None
    except (ValueError, RecursionError):  # a number too long, nesting too deep
        raise reader.refuse("not a bench file") from None
    return reader.devices(data)


def read_bench(path: str | Path) -> dict[str, BenchDevice]:
    """The devices of the bench file at `path` (see the module's text); BenchError if any is
    wrong or the file cannot be read."""
    text = read_text(path, BENCH_MAX_BYTES, Message("bench file"), BenchError)
    return parse_bench(text, str(path))


class Bench(Mapping[str, DeviceSession]):
    """The open sessions of a bench by name (a context manager that closes them all)."""

    def __init__(self, devices: Mapping[str, BenchDevice], sessions: dict[str, DeviceSession]):
        self.devices = dict(devices)
        self._sessions = sessions

    def __getitem__(self, name: str) -> DeviceSession:
        try:
            return self._sessions[name]
        except KeyError:
            raise KeyError(f"no device {name!r} on this bench ({', '.join(self)})") from None

    def __iter__(self) -> Iterator[str]:
        return iter(self._sessions)

    def __len__(self) -> int:
        return len(self._sessions)

    def stop_all(self) -> None:
        """Ask every device's operation under way to stop (any thread)."""
        for session in self._sessions.values():
            session.request_stop()

    def close(self) -> None:
        """Close every session (each one, whatever another's close raised)."""
        errors = []
        for session in self._sessions.values():
            try:
                session.close()
            except Exception as exc:  # the others are closed all the same
                errors.append(exc)
        if errors:
            raise errors[0]

    def __enter__(self) -> Bench:
        return self

    def __exit__(
        self,
        kind: type[BaseException] | None,
        value: BaseException | None,
        traceback: TracebackType | None,
    ) -> None:
        self.close()


def open_bench(path: str | Path, names: Iterable[str] | None = None, **options: Any) -> Bench:
    """Open the devices of the bench file at `path` (only those `names`, if given) and return
    them by name (a context manager that closes them all). The file is checked whole first;
    should one device fail to open, those opened already are closed and its error raised,
    with a note naming it. `options`: more of `open_device`'s, for every device."""
    devices = read_bench(path)
    chosen = list(devices) if names is None else list(names)
    for name in chosen:
        if name not in devices:
            raise BenchError(
                Message(
                    "{path}: no device {name!r} (the bench has {names})",
                    path=path,
                    name=name,
                    names=", ".join(devices),
                )
            )
    sessions: dict[str, DeviceSession] = {}
    try:
        for name in chosen:
            try:
                sessions[name] = devices[name].open(**options)
            except Exception as exc:
                exc.add_note(f"bench device {name!r}")
                raise
    except BaseException:
        Bench(devices, sessions).close()
        raise
    return Bench({name: devices[name] for name in chosen}, sessions)
