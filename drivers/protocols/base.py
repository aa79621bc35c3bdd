"""The protocol contract: encoding commands, decoding frames, and following one command's reply."""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from typing import ClassVar

from drivers.errors import BadInput, FrameError, MotionError
from drivers.framers.base import Framer
from drivers.framers.splitter import FrameSplitter
from drivers.messages import Message, message_of
from drivers.protocols.capabilities import Capabilities
from drivers.protocols.commands import Command, MoveBy, SetParameter
from drivers.protocols.events import Event
from drivers.protocols.move_outcome import MoveOutcome
from drivers.protocols.parameters import Parameter, ParameterWritten, find_parameter

Point = tuple[float, float, float]


@dataclass(frozen=True)
class MoveSequence(Command):
    """Moves one sent frame holds, in order (the laser link queues up to 7 in a frame)."""

    moves: tuple[Command, ...]


@dataclass(frozen=True)
class Setting:
    """A number the panel keeps for a protocol (e.g. pi-frame ticks per mm), with its range."""

    name: str
    unit: str
    default: float
    minimum: float
    maximum: float
    description: str  # a Message: it is shown to the operator

    def check(self, value: float) -> float:
        """The value if it is in range; BadInput naming the setting, its unit and its range."""
        if not isinstance(value, (int, float)) or not self.minimum <= value <= self.maximum:
            raise BadInput(
                Message(
                    "{setting} {value} refused: {minimum:g} to {maximum:g} {unit}",
                    setting=self.name,
                    value=value,
                    minimum=self.minimum,
                    maximum=self.maximum,
                    unit=self.unit,
                )
            )
        return float(value)


@dataclass(frozen=True)
class Variant:
    """A wire profile of a protocol (e.g. Visiomex's 12-character board): name and line rate."""

    name: str
    description: str  # a Message: it is shown to the operator
    baud: int | None = None  # None: the protocol's default


@dataclass
class Reply:
    """What one command got back: a typed value where there is one, and every event seen."""

    command: Command
    value: object = None
    events: list[Event] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


class Exchange(ABC):
    """Follows the events that answer one command until it is finished.

    The client feeds every decoded event to `on_event`; once `finished` is true, `result()`
    returns the Reply or raises DeviceError. An exchange that expects no reply is finished at once.
    """

    #: Seconds to wait for the reply to begin (None: the client's default timeout).
    timeout: float | None = None
    #: Seconds to keep reading after the end, for trailing lines that belong to this reply.
    linger: float = 0.0
    #: Seconds the device is expected to be busy before it finishes (a move in a raw packet).
    extra: float = 0.0

    def __init__(self, command: Command) -> None:
        self.command = command
        self.events: list[Event] = []
        self.error: MotionError | None = None
        self.value: object = None
        self.notes: list[str] = []
        self._finished = False

    @property
    def finished(self) -> bool:
        """Whether the reply is complete (or failed)."""
        return self._finished

    def finish(self, value: object = None) -> None:
        """Mark the exchange complete with `value`."""
        self.value = value
        self._finished = True

    def fail(self, error: MotionError) -> None:
        """Mark the exchange failed (a device error, or a reply that makes no sense)."""
        self.error = error
        self._finished = True

    @property
    def wants_more(self) -> bool:
        """After finishing: whether trailing lines of this reply are still expected."""
        return False

    def on_event(self, event: Event) -> bool:
        """Take one event; return True when it belonged to this exchange."""
        taken = self.handle_trailing(event) if self._finished else self.handle(event)
        if taken:
            self.events.append(event)
        return taken

    @abstractmethod
    def handle(self, event: Event) -> bool:
        """Protocol-specific handling of one event; return True when it was taken."""

    def handle_trailing(self, event: Event) -> bool:
        """Take an event that arrives after the end (see `wants_more`)."""
        return False

    def result(self) -> Reply:
        """The reply, or the device's error raised."""
        if self.error is not None:
            raise self.error
        return Reply(self.command, self.value, list(self.events), list(self.notes))


class Protocol(ABC):
    """A wire protocol: its capabilities, framer, encoder, decoder and reply tracking.

    `capabilities` on the class are the default variant's; an instance's may differ by variant.
    """

    name: ClassVar[str]
    capabilities: Capabilities
    #: Seconds to keep between the end of one reply and the next write (device pacing).
    min_gap: ClassVar[float] = 0.0
    #: Seconds of silence the device needs after a packet before the next one, unless it has
    #: answered meanwhile (Visiomex: a packet ends after 1 s without bytes).
    write_gap: ClassVar[float] = 0.0
    #: How many times a frame is sent before its failure is final (Retransmit, DeviceTimeout).
    attempts: ClassVar[int] = 1
    #: Wire profiles; the first is the default. Empty: the protocol has one.
    variants: ClassVar[tuple[Variant, ...]] = ()
    #: Numbered device parameters (empty: none).
    parameters: ClassVar[tuple[Parameter, ...]] = ()
    #: Numbers the panel keeps for the protocol (ticks per mm...), set with `configure`.
    settings: ClassVar[tuple[Setting, ...]] = ()

    def __init__(self, variant: str | None = None) -> None:
        self.variant = self._choose_variant(variant)
        self.values: dict[str, float] = {s.name: s.default for s in self.settings}

    def configure(self, values: dict[str, float]) -> None:
        """Take new setting values (each checked, none taken if one is refused)."""
        known = {s.name: s for s in self.settings}
        checked = {}
        for name, value in values.items():
            if name not in known:
                raise BadInput(
                    Message("{protocol} has no setting {name!r}", protocol=self.name, name=name)
                )
            checked[name] = known[name].check(value)
        self.values.update(checked)
        self.configured()

    def configured(self) -> None:
        """Settings changed: recompute what depends on them (capabilities, limits)."""

    def startup_commands(self) -> list[Command]:
        """Commands to send once the device is identified (e.g. a Firmata stepper's config,
        which an Arduino forgets at every reset)."""
        return []

    def on_sent(self, command: Command) -> None:
        """`command` went on the wire (a write-only device's commanded state follows it)."""

    @classmethod
    def _choose_variant(cls, name: str | None) -> Variant | None:
        if not cls.variants:
            if name:
                raise BadInput(
                    Message(
                        "{protocol} has no wire variants (got {name!r})",
                        protocol=cls.name,
                        name=name,
                    )
                )
            return None
        if not name:
            return cls.variants[0]
        for variant in cls.variants:
            if variant.name == name:
                return variant
        known = ", ".join(v.name for v in cls.variants)
        raise BadInput(
            Message(
                "{protocol} has no variant {name!r} (variants: {known})",
                protocol=cls.name,
                name=name,
                known=known,
            )
        )

    @classmethod
    def default_baud(cls, variant: str | None = None) -> int:
        """The line rate of a variant (or the protocol's)."""
        chosen = cls._choose_variant(variant)
        if chosen is not None and chosen.baud is not None:
            return chosen.baud
        return cls.capabilities.default_baud

    def parameter(self, key: str | int) -> Parameter:
        """A parameter by name or id; BadInput if the protocol has none by that key."""
        return find_parameter(self.parameters, key)

    def derived_values(self, values: dict[str, float]) -> list[tuple[str, str]]:
        """Figures that follow from parameter values (by name), as (label, text) pairs."""
        return []

    def write_warning(self, param_id: int) -> str:
        """What writing this parameter will not do (e.g. the firmware recomputes it), as a
        Message shown before it is sent; "" if it does what it says."""
        return ""

    def assume_parameters(self, values: dict[str, float]) -> None:
        """Take values written earlier (saved by the panel) as what the device holds."""

    def parameter_written(self, command: SetParameter) -> ParameterWritten:
        """Note a confirmed write; returns what the device now holds because of it."""
        return ParameterWritten(self.parameter(command.param_id), command.value)

    def expand(self, command: Command) -> list[Command]:
        """The commands that carry out `command` on the wire (Visiomex speed: two sets)."""
        return [command]

    def move_timing(
        self, command: Command, start: Point, target: Point
    ) -> tuple[float, float] | None:
        """Seconds before a move starts and how long it runs (None: distance over speed)."""
        return None

    def move_outcome(self, command: Command, start: Point, target: Point) -> MoveOutcome:
        """Where a move leaves the stage by the device's own arithmetic, before it is sent
        (default: at `target`, as asked)."""
        return MoveOutcome(target)

    def moving_speed(self) -> float | None:
        """The speed moves really go at, where the device sets it itself and cannot be asked
        (Visiomex: from its step delays); None: the speed set."""
        return None

    def kind_to_length(self, command: MoveBy) -> Point:
        """A relative move's deltas in the length unit (its `kind` may be degrees or steps)."""
        if command.kind != "linear":
            raise BadInput(
                Message(
                    "{protocol} moves are linear only (got {kind!r})",
                    protocol=self.name,
                    kind=command.kind,
                )
            )
        return (command.dx, command.dy, command.dz)

    @abstractmethod
    def new_framer(self) -> Framer:
        """A framer for the device's replies."""

    @abstractmethod
    def encode(self, command: Command) -> bytes:
        """The bytes to write for `command`; raises BadInput before anything is sent."""

    @abstractmethod
    def decode(self, frame: bytes) -> list[Event]:
        """The events in one frame from the device; never raises but FrameError."""

    @abstractmethod
    def exchange(self, command: Command) -> Exchange:
        """A tracker for the reply to `command`."""

    def new_tx_framer(self) -> Framer | None:
        """A framer for what the host sends (None: every write is one frame)."""
        return self.new_framer()

    def describe_sent(self, frame: bytes) -> str:
        """What a frame the host sent means, in the protocol's words (for logs and consoles);
        a Message where it has words to translate."""
        try:
            events = self.decode(frame)
        except FrameError as exc:
            return Message("unreadable: {error}", error=message_of(exc) or str(exc))
        if len(events) == 1:
            return str(events[0])  # the event's Message as it is (a join would make it a str)
        return "; ".join(str(e) for e in events)

    def is_restart(self, event: Event, waiting: Command | None = None) -> bool:
        """Whether `event` is what the device prints when it boots (its banner), while the
        client waits for the reply to `waiting` (None: it waits for nothing). False where the
        device prints nothing at boot: a restart then shows only as a position that changed
        by itself."""
        return False

    def sent_kind(self, frame: bytes) -> str:
        """What a sent frame is, for consoles' filters: `motion`, `poll`, `setting` or `query`."""
        return "query"

    def expects_reply(self, frame: bytes) -> bool:
        """Whether the device answers a sent frame (consoles pair a reply with its request)."""
        return True

    def check_raw(self, data: bytes) -> None:
        """Refuse raw console bytes the device cannot take (BadInput); the default takes all."""

    def raw_exchange(self, data: bytes) -> Exchange | None:
        """A tracker for the reply to raw console bytes, where they are one whole command."""
        return None

    def command_name(self, command: Command) -> str:
        """The command's name as the device knows it (e.g. `GET_POSITION`), for messages."""
        return type(command).__name__

    def sent_command(self, frame: bytes) -> Command | None:
        """What one frame the host sends makes the device do, read as the device reads it: the
        move (MoveTo, MoveBy, Home, Arc, MoveSequence), or None where it moves nothing (a query,
        a setting, a command the device refuses). FrameError where it cannot be read."""
        raise FrameError(Message("{protocol} cannot read sent frames", protocol=self.name))

    def sent_commands(self, data: bytes) -> list[Command | None]:
        """Every frame in bytes the host sends, each as `sent_command` reads it; FrameError for
        bytes that are not whole frames (the device would wait for the rest)."""
        frames, rest = FrameSplitter(self.new_tx_framer()).whole(data)
        if rest:
            raise FrameError(
                Message(
                    "the last {count} bytes are not a whole frame: the device would wait "
                    "for the rest",
                    count=len(rest),
                )
            )
        if not frames:
            raise FrameError(Message("no whole frame in {count} bytes", count=len(data)))
        return [self.sent_command(frame) for frame in frames]
