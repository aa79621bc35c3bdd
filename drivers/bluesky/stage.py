"""The stage as an ophyd-async device for Bluesky: one child per axis, each Movable, Locatable,
Stoppable, Readable and Checkable, all driving one DeviceSession (a move at a time)."""

from __future__ import annotations

import asyncio
import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import Any

from ophyd_async.core import (
    DeviceConnector,
    MovableLogic,
    SignalR,
    StandardMovable,
    StandardReadable,
    TimeoutCalculator,
    soft_signal_r_and_setter,
    soft_signal_rw,
)
from ophyd_async.core import StandardReadableFormat as Format

from drivers.errors import BadInput
from drivers.messages import Message
from drivers.protocols.events import PositionReport
from drivers.protocols.registry import create_protocol
from drivers.session.bench import read_bench
from drivers.session.device_session import DeviceSession, open_device

AXES = ("x", "y", "z")


class _Link:
    """The session a stage's axes share: opened on connect, one move at a time, and the
    readbacks kept to what the session knows (from the thread that learns it)."""

    def __init__(self, opener: Callable[[], DeviceSession], axes: Sequence[str]) -> None:
        self.opener = opener
        self.axes = tuple(axes)
        self.session: DeviceSession | None = None
        self.targets = [0.0, 0.0, 0.0]
        self.lock = threading.Lock()  # held by the thread that runs a move
        self.shown: list[Callable[[float], None]] = []  # each axis's readback setter
        self.truth_set: Callable[[str], None] = lambda _: None
        self.loop: asyncio.AbstractEventLoop | None = None

    def open(self) -> None:
        """Open the session (in a worker thread) and read where the stage is."""
        if self.session is None or self.session.closed:
            self.session = self.opener()
            self.session.on_position(self.report)
        report = self.session.position()
        self.targets = [report.x, report.y, report.z]
        self.report(report)

    def report(self, report: PositionReport) -> None:
        """A position the session knows, from whichever thread: shown in the event loop."""
        if self.loop is not None:
            self.loop.call_soon_threadsafe(self._show, (report.x, report.y, report.z))

    def _show(self, point: tuple[float, float, float]) -> None:
        for setter, value in zip(self.shown, point, strict=False):
            setter(value)
        if self.session is not None:
            self.truth_set(self.session.where().status)

    def check(self, axis: str, value: float) -> None:
        """BadInput, before anything is sent, for a target outside the travel box on `axis`."""
        index = AXES.index(axis)
        travel = self.opened().travel
        if travel is None:
            return
        low, high = travel.box[index]
        if not low <= value <= high:
            raise BadInput(
                Message(
                    "{axis} {value:g} mm refused: outside {low:g}..{high:g} mm (travel limits)",
                    axis=axis.upper(),
                    value=value,
                    low=low,
                    high=high,
                )
            )

    def move(self, axis: str, value: float) -> PositionReport:
        """Move `axis` to `value`, the other axes at their last targets (a worker thread)."""
        with self.lock:
            target = list(self.targets)
            target[AXES.index(axis)] = value
            report = self.opened().move_to(*target)
            self.targets = target
            return report

    def opened(self) -> DeviceSession:
        """The session; BadInput before the stage is connected."""
        if self.session is None:
            raise BadInput(Message("the stage is not connected: connect it first"))
        return self.session


@dataclass
class _AxisMove(MovableLogic[float]):
    """How one axis moves: through the stage's session."""

    link: _Link
    axis: str

    async def check_move(self, new_position: float) -> None:
        """Refuse a target outside the travel box before anything is sent."""
        self.link.check(self.axis, new_position)

    async def move(self, new_position: float, timeout: TimeoutCalculator) -> None:
        """Send the move and wait for its end (the session's own reply timeouts apply)."""
        await self.setpoint.set(new_position)
        await asyncio.to_thread(self.link.move, self.axis, new_position)

    async def stop(self) -> None:
        """Ask the move under way to stop (where the protocol has a stop; elsewhere the move
        under way finishes)."""
        if self.link.session is not None:
            self.link.session.request_stop()


class StageAxis(StandardReadable, StandardMovable[float]):
    """One axis of a stage, in mm: `set`, `locate`, `stop`, `read`, `check_value`."""

    def __init__(self, link: _Link, axis: str, name: str = "") -> None:
        self._link, self._axis = link, axis
        with self.add_children_as_readables(Format.HINTED_SIGNAL):
            self.readback, shown = soft_signal_r_and_setter(float, 0.0, units="mm", precision=3)
        self.setpoint = soft_signal_rw(float, 0.0, units="mm", precision=3)
        link.shown.append(shown)
        super().__init__(name=name)

    @cached_property
    def movable_logic(self) -> _AxisMove:
        """The move's logic, over the stage's session."""
        return _AxisMove(
            setpoint=self.setpoint, readback=self.readback, link=self._link, axis=self._axis
        )


class _SessionConnector(DeviceConnector):
    """Connecting a stage opens its session, then connects its signals."""

    def __init__(self, link: _Link) -> None:
        self.link = link

    async def connect_real(self, device: Any, timeout: float, force_reconnect: bool) -> None:
        """Open the device (in a worker thread), then its axes' signals."""
        self.link.loop = asyncio.get_running_loop()
        await super().connect_real(device, timeout, force_reconnect)
        await asyncio.to_thread(self.link.open)
        for axis, value in zip(self.link.axes, self.link.targets, strict=False):
            await getattr(device, axis).setpoint.set(value)


class Stage(StandardReadable):
    """A stage on `port` speaking `protocol`, its axes as children (`stage.x`, `stage.y`,
    `stage.z`: those the protocol has); `settings`: more of `open_device`'s (travel, speed is
    set with `speed=`, variant, baud...). Connected (the port opened) by `init_devices` or
    `await stage.connect()`; `close()` closes the port."""

    def __init__(self, port: str, protocol: str, name: str = "", **settings: Any) -> None:
        speed = settings.pop("speed", None)
        axes = create_protocol(protocol, settings.get("variant")).capabilities.axes

        def opener() -> DeviceSession:
            session = open_device(port, protocol, **settings)
            if speed is not None:
                session.speed(speed)
            return session

        self._link = _Link(opener, axes)
        for axis in axes:
            with self.add_children_as_readables():
                setattr(self, axis, StageAxis(self._link, axis))
        self.truth: SignalR[str]
        with self.add_children_as_readables(Format.UNCACHED_SIGNAL):
            self.truth, self._link.truth_set = soft_signal_r_and_setter(str, "unread")
        super().__init__(name=name, connector=_SessionConnector(self._link))

    @classmethod
    def from_bench(cls, path: str, device: str, name: str = "") -> Stage:
        """The stage a bench file names `device`."""
        entry = read_bench(path)[device]
        return cls(
            entry.port,
            entry.protocol,
            name=name or device,
            variant=entry.variant,
            baud=entry.baud,
            timeout=entry.timeout,
            travel=entry.travel,
            settings=dict(entry.settings),
            speed=entry.speed,
        )

    @property
    def session(self) -> DeviceSession:
        """The device's session (for what Bluesky does not ask: Set Home, parameters...)."""
        return self._link.opened()

    def close(self) -> None:
        """Close the port."""
        if self._link.session is not None:
            self._link.session.close()
