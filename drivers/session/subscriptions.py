"""A session's typed subscriptions: each `on_...` returns a callable that unsubscribes."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

from drivers.device.client import Client, EventListener
from drivers.device.motion import Motion, MoveStart
from drivers.link.control_lines import BREAK_S, ControlLines
from drivers.link.transport import Link, NoteListener, TrafficListener
from drivers.protocols.events import PositionReport
from drivers.protocols.parameters import ParameterWritten

__all__ = ["SessionLines", "SessionSubscriptions", "Unsubscribe"]

Unsubscribe = Callable[[], None]
"""Called to stop the calls a subscription made (again: nothing happens)."""

_Listener = TypeVar("_Listener", bound=Callable[..., Any])


def subscribe(listeners: list[_Listener], listener: _Listener) -> Unsubscribe:
    """Add `listener` to `listeners`; the callable that takes it out again."""
    listeners.append(listener)

    def unsubscribe() -> None:
        if listener in listeners:
            listeners.remove(listener)

    return unsubscribe


class SessionSubscriptions:
    """What a session tells as it happens, each to the callables subscribed to it."""

    link: Link
    client: Client
    motion: Motion
    _move_ended: list[Callable[[PositionReport], None]]

    def on_position(self, listener: Callable[[PositionReport], None]) -> Unsubscribe:
        """Call `listener` with every position known (read, or where a move ended)."""
        return subscribe(self.motion.position_listeners, listener)

    def on_move_started(self, listener: Callable[[MoveStart], None]) -> Unsubscribe:
        """Call `listener` as each move is sent (from, to, speed, when, how long)."""
        return subscribe(self.motion.move_listeners, listener)

    def on_move_ended(self, listener: Callable[[PositionReport], None]) -> Unsubscribe:
        """Call `listener` with the position once each move, arc, home or raw move has ended."""
        return subscribe(self._move_ended, listener)

    def on_notice(self, listener: Callable[[str], None]) -> Unsubscribe:
        """Call `listener` with what the user should know (a move clamped, a stop)."""
        return subscribe(self.motion.notice_listeners, listener)

    def on_parameter(self, listener: Callable[[ParameterWritten], None]) -> Unsubscribe:
        """Call `listener` with every parameter the device confirmed."""
        return subscribe(self.motion.parameter_listeners, listener)

    def on_traffic(self, listener: TrafficListener) -> Unsubscribe:
        """Call `listener` with every Traffic record (bytes sent or received)."""
        return subscribe(self.link.listeners, listener)

    def on_event(self, listener: EventListener) -> Unsubscribe:
        """Call `listener` with every decoded event and whether it answered a command."""
        return subscribe(self.client.listeners, listener)

    def on_wait(self, listener: Callable[[], None]) -> Unsubscribe:
        """Call `listener` every read while waiting on the device (about every 20 ms)."""
        return subscribe(self.client.wait_hooks, listener)

    def on_link_note(self, listener: NoteListener) -> Unsubscribe:
        """Call `listener` with every control-line change and break made on the port."""
        return subscribe(self.link.note_listeners, listener)

    def notify(self, text: str) -> None:
        """Tell the notice subscribers `text` (as the session tells its own notices)."""
        for listener in list(self.motion.notice_listeners):
            listener(text)


class SessionLines:
    """The port's modem control lines, as a session drives and reads them."""

    link: Link

    def control_lines(self) -> ControlLines:
        """The six lines now (DTR, RTS as driven; CTS, DSR, CD, RI as the device drives)."""
        return self.link.control_lines()

    def set_control(self, name: str, on: bool) -> None:
        """Drive DTR or RTS (`name` "dtr" or "rts"); NoControlLines where the port has none."""
        self.link.set_control(name, on)

    def send_break(self, seconds: float = BREAK_S) -> None:
        """Hold the transmit line low for `seconds` (NoControlLines where the port cannot)."""
        self.link.send_break(seconds)

    @property
    def opening_notes(self) -> tuple[str, ...]:
        """What opening the port found worth noting (a server leaving DTR unconfirmed)."""
        return tuple(self.link.opening_notes)
