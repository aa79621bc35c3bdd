"""The synchronous client: writes one command, reads and decodes until its reply is complete."""

from __future__ import annotations

import logging
import threading
import time
from collections.abc import Callable

from drivers.errors import (
    Aborted,
    DeviceError,
    DeviceRestarted,
    DeviceTimeout,
    FrameError,
    QueueFull,
    Retransmit,
)
from drivers.framers.splitter import FrameSplitter
from drivers.link.transport import Link
from drivers.messages import Message, message_of
from drivers.protocols.base import Exchange, Protocol, Reply
from drivers.protocols.commands import Command
from drivers.protocols.events import Event, Undecodable

log = logging.getLogger(__name__)

EventListener = Callable[[Event, bool], None]
"""Called with every decoded event and whether it answered the command in flight."""

BACKPRESSURE_WAIT = 0.05  # s to let a full device queue work itself down before sending again
BACKPRESSURE_LIMIT = 120.0  # s of queue-full replies before giving up
MAX_TIMEOUT_EXTENSION = 5  # a chattering device extends the wait at most this many timeouts
ABANDONED = Message("abandoned: the connection is closing")
"""Why a wait was given up (Aborted)."""


class Client:
    """One protocol over one link; not thread-safe: its owner (CLI or worker) is its only user."""

    def __init__(
        self,
        link: Link,
        protocol: Protocol,
        timeout: float = 2.0,
        clock: Callable[[], float] = time.monotonic,
    ) -> None:
        self.link = link
        self.protocol = protocol
        self.timeout = timeout
        self.clock = clock
        self.splitter = FrameSplitter(protocol.new_framer(), clock())
        """The received bytes cut into frames (drivers/framers/splitter.py)."""
        self.listeners: list[EventListener] = []
        self._last_reply = 0.0
        self._last_write = -1e9
        self._opened = clock()
        self.wait_hooks: list[Callable[[], None]] = []
        """Called every read while waiting (about every 20 ms), e.g. to hand on traffic."""
        self.writes = 0
        """Writes so far: a value read after the last write is still the device's (the panel is
        the only one commanding it)."""
        self.answers = 0
        """Frames that answered a command so far: a boot banner after one is a restart."""
        self.retransmissions = 0
        """Frames sent again (a damaged-frame reply, or no reply in time)."""
        self.backpressure_waits = 0
        """Waits for room in the device's queue (queue-full replies)."""
        self.abort = threading.Event()
        """Set from any thread to make a waiting `execute` raise Aborted."""

    @property
    def _last_rx(self) -> float:
        """When bytes last came from the device."""
        return self.splitter.last_data

    def execute(
        self,
        command: Command,
        timeout: float | None = None,
        extra: float = 0.0,
        *,
        encoded: bytes | None = None,
    ) -> Reply:
        """Send `command` and wait for its reply.

        `timeout` is the silence allowed before the reply is complete (the exchange's or the
        client's default); `extra` adds the time the device is expected to be busy (a blocking
        move). Where the protocol retransmits, the kept copy is sent again on a damaged-frame
        reply or a timeout (`protocol.attempts` in all), and again after a queue-full reply.
        `encoded`: the command's bytes where the caller has made them (not encoded again).
        Raises BadInput before writing, DeviceError, DeviceTimeout or PortError.
        """
        data = self.protocol.encode(command) if encoded is None else encoded
        self.poll()
        attempt = 0
        full_since: float | None = None
        while True:
            exchange = self.protocol.exchange(command)
            self._pace()
            self._write(data)
            if attempt == 0 and full_since is None:
                self.protocol.on_sent(command)
            silence = timeout if timeout is not None else (exchange.timeout or self.timeout)
            try:
                self._await(exchange, silence, max(extra, exchange.extra))
                self._last_reply = self.clock()
                return exchange.result()
            except QueueFull as exc:
                full_since = self.clock() if full_since is None else full_since
                if self.clock() - full_since > BACKPRESSURE_LIMIT:
                    raise DeviceError(
                        Message(
                            "{error}; still full after {seconds:.0f} s",
                            error=exc,
                            seconds=BACKPRESSURE_LIMIT,
                        )
                    ) from exc
                self.backpressure_waits += 1
                self.listen(BACKPRESSURE_WAIT)  # the device works its queue down meanwhile
            except (DeviceTimeout, Retransmit) as exc:
                attempt += 1
                if attempt >= self.protocol.attempts:
                    if self.protocol.attempts == 1:
                        raise
                    name = self.protocol.command_name(command)
                    raise type(exc)(
                        Message(
                            "{command} failed after {tries} tries; the last: {error}",
                            command=name,
                            tries=attempt,
                            error=exc,
                        )
                    ) from exc
                self.retransmissions += 1
                log.info(
                    "retransmitting %s (try %d): %s",
                    self.protocol.command_name(command),
                    attempt + 1,
                    exc,
                )

    def send_only(self, command: Command) -> None:
        """Write a command that gets no reply (write-only devices)."""
        data = self.protocol.encode(command)
        self.poll()
        self._pace()
        self._write(data)
        self.protocol.on_sent(command)
        self._last_reply = self.clock()

    def send_raw(self, data: bytes, extra: float = 0.0) -> Reply | None:
        """Write console bytes as they are (after the protocol's check).

        Where the protocol can follow them as one command, wait for its reply like `execute`
        (a device error is raised; `extra`: seconds the device is expected to be busy, a move);
        otherwise return None at once and replies come unasked.
        """
        self.protocol.check_raw(data)
        exchange = self.protocol.raw_exchange(data)
        self.poll()
        self._pace()
        self._write(data)
        if exchange is not None:
            self._await(exchange, exchange.timeout or self.timeout, max(extra, exchange.extra))
        self._last_reply = self.clock()
        return exchange.result() if exchange is not None else None

    def poll(self) -> list[Event]:
        """Read and decode whatever has arrived unasked (debug lines, late replies)."""
        events: list[Event] = []
        for event in self._read_events(wait=False):
            self._notify(event, False)
            self._check_restart(event)
            events.append(event)
        return events

    def listen(self, seconds: float) -> list[Event]:
        """Read and decode for `seconds` (a write-only device's move under way); Aborted if the
        owner gives up meanwhile."""
        end = self.clock() + seconds
        events: list[Event] = []
        while True:
            self._check_abort()
            for event in self._read_events(wait=True):
                self._notify(event, False)
                self._check_restart(event)
                events.append(event)
            if self.clock() >= end:
                return events

    def close(self) -> None:
        """Close the link."""
        self.link.close()

    def _write(self, data: bytes) -> None:
        self.writes += 1
        self.link.write(data)
        self._last_write = self.clock()

    def _gap(self) -> float:
        """Seconds to wait before the next write may go."""
        gap = self.protocol.min_gap - (self.clock() - self._last_reply)
        if self._last_write < 0 and self._last_rx <= self._opened:
            # Nothing written or heard yet: a device that resets when the port opens (Arduino)
            # needs its start-up time; anything it says first ends the wait.
            gap = max(gap, self.protocol.capabilities.startup_wait - (self.clock() - self._opened))
        if self._last_rx <= self._last_write:
            # Unanswered: the device may still be reading that packet (Visiomex: it ends after
            # 1 s of silence, and a packet sent sooner merges with it).
            gap = max(gap, self.protocol.write_gap - (self.clock() - self._last_write))
        return gap

    def _pace(self) -> None:
        while self._gap() > 0:
            self._check_abort()
            for event in self._read_events(wait=True):
                self._notify(event, False)
                self._check_restart(event)

    def _await(self, exchange: Exchange, silence: float, extra: float) -> None:
        start = self.clock()
        hard_limit = start + extra + silence * MAX_TIMEOUT_EXTENSION
        stray: list[Event] = []
        while not exchange.finished:
            self._check_abort()
            now = self.clock()
            deadline = min(max(start + extra, self._last_rx) + silence, hard_limit)
            if now >= deadline:
                raise DeviceTimeout(self._timeout_message(exchange, silence, extra, stray))
            for event in self._read_events():
                self._check_restart(event, exchange.command)
                taken = exchange.on_event(event)
                if taken:
                    self.answers += 1
                else:
                    stray.append(event)
                self._notify(event, taken)
        linger_end = self.clock() + exchange.linger
        while exchange.wants_more and self.clock() < linger_end:
            for event in self._read_events():
                self._notify(event, exchange.on_event(event))

    def _check_restart(self, event: Event, waiting: Command | None = None) -> None:
        """Raise DeviceRestarted for a boot banner that comes once the device has answered
        (the banner of a board that boots as its port opens is not a restart)."""
        if (
            not self.answers
            or self.clock() - self._opened < self.protocol.capabilities.startup_wait
        ):
            return
        if self.protocol.is_restart(event, waiting):
            if waiting:
                raise DeviceRestarted(
                    Message(
                        "the device restarted during {command} ({event}): "
                        "its position and settings are lost",
                        command=self.protocol.command_name(waiting),
                        event=str(event),
                    )
                )
            raise DeviceRestarted(
                Message(
                    "the device restarted ({event}): its position and settings are lost",
                    event=str(event),
                )
            )

    def _check_abort(self) -> None:
        if self.abort.is_set():
            raise Aborted(ABANDONED)

    def _timeout_message(
        self, exchange: Exchange, silence: float, extra: float, stray: list[Event]
    ) -> str:
        name = self.protocol.command_name(exchange.command)
        seconds = silence + extra
        if exchange.events:
            message = Message(
                "the device did not finish its reply to {command} within {seconds:.3g} s",
                command=name,
                seconds=seconds,
            )
        else:
            message = Message(
                "the device did not answer to {command} within {seconds:.3g} s",
                command=name,
                seconds=seconds,
            )
        if stray:
            message = Message(
                "{message}; it sent {count} unexpected frame(s), the last: {frame}",
                message=message,
                count=len(stray),
                frame=str(stray[-1]),
            )
        if self.protocol.capabilities.busy_silent:
            message = Message(
                "{message} (it may still be moving: {protocol} answers nothing "
                "until a blocking move has ended; try again once it has stopped)",
                message=message,
                protocol=self.protocol.name.upper(),
            )
        return message

    def _read_events(self, wait: bool = True) -> list[Event]:
        data = self.link.read(wait)
        for hook in self.wait_hooks:
            hook()
        now = self.clock()
        frames = self.splitter.feed(data, now)
        frames += self.splitter.idle(now)
        events: list[Event] = []
        for frame in frames:
            try:
                events.extend(self.protocol.decode(frame))
            except FrameError as exc:
                events.append(Undecodable(frame, message_of(exc) or str(exc)))
        return events

    def _notify(self, event: Event, solicited: bool) -> None:
        if not solicited:
            log.debug("unsolicited: %s", event)
        for listener in list(self.listeners):
            listener(event, solicited)
