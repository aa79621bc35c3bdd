"""The conformance suite: what every front end (the window, motionctl, motionsim, the sniffer,
the log readers) needs of a declared protocol and its simulator, checked in one call.

`check_entry(entry)` returns the problems found, one sentence each (empty: it conforms). It is
run over every registered protocol, the built-in ones and the installed plugins' alike.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from functools import partial
from urllib.parse import quote

from drivers.errors import BadInput, FrameError, MotionError
from drivers.framers.base import Framer
from drivers.protocols import commands as cmd
from drivers.protocols.base import Exchange, Protocol
from drivers.protocols.capabilities import Capabilities
from drivers.protocols.events import Event
from drivers.protocols.registry import ProtocolEntry, get_protocol_class
from drivers.sim.device import SimulatedDevice
from drivers.sim.registry import simulator_class

NAME = re.compile(r"[a-z][a-z0-9-]*\Z")  # a CLI choice, a sim:// host, a settings key
SENT_KINDS = frozenset({"motion", "poll", "setting", "query"})
PROBES: tuple[cmd.Command, ...] = (
    cmd.GetId(),
    cmd.GetPosition(),
    cmd.Home(),
    cmd.SetHome(),
    cmd.MoveTo(1.0, 2.0, 0.0),
    cmd.MoveBy(1.0, 0.0, 0.0),
    cmd.SetSpeed(5.0),
    cmd.GetSpeed(),
    cmd.CheckErrors(),
    cmd.Stop(),
    cmd.Raw(b"?\n"),
)
NOISE = (b"", b"\x00", b"\xff" * 7, b"garbage \xe9\r\n", bytes(range(256)))

Problems = list[str]


def check_entry(entry: ProtocolEntry, settings: Mapping[str, float] | None = None) -> Problems:
    """Every problem of a declaration, its protocol class and its simulator (empty: none);
    `settings`: the protocol's settings its simulator needs to move (Firmata's pins)."""
    problems = check_declaration(entry)
    try:
        protocol_class = get_protocol_class(entry.name)
    except MotionError as exc:
        return [*problems, f"{entry.name}: the protocol class cannot be loaded: {exc}"]
    problems += check_protocol_class(entry, protocol_class)
    names: list[str | None] = [v.name for v in protocol_class.variants]
    for variant in names or [None]:
        try:
            protocol = protocol_class(variant)
        except Exception as exc:  # a front end makes one with the name alone
            problems.append(f"{entry.name}: {protocol_class.__name__}({variant!r}) failed: {exc}")
            continue
        problems += check_protocol(entry.name, protocol)
    if entry.simulator is not None:
        problems += check_simulator(entry)
        if not problems:
            problems += check_session(entry, settings)
    return problems


def check_declaration(entry: ProtocolEntry) -> Problems:
    """The declaration's own fields, as the lists and help texts show them."""
    problems = []
    if not NAME.match(entry.name):
        problems.append(f"{entry.name!r}: a name is lower-case letters, digits and '-'")
    if not entry.display_name.strip():
        problems.append(f"{entry.name}: no display name")
    if not entry.description.strip() or "\n" in entry.description:
        problems.append(f"{entry.name}: the description must be one line of help")
    for target in (entry.protocol, entry.simulator):
        if target is not None and ":" not in target:
            problems.append(f"{entry.name}: {target!r} is not a 'module:Class' path")
    return problems


def check_protocol_class(entry: ProtocolEntry, protocol_class: type[Protocol]) -> Problems:
    """The class attributes a front end reads before it makes an instance."""
    problems = []
    said = getattr(protocol_class, "name", None)
    if said != entry.name:
        problems.append(f"{entry.name}: the class's name is {said!r}")
    declared = tuple(v.name for v in protocol_class.variants)
    if declared != entry.variants:
        problems.append(
            f"{entry.name}: variants declared {entry.variants}, the class has {declared}"
        )
    caps = getattr(protocol_class, "capabilities", None)
    if not isinstance(caps, Capabilities) or not caps.axes:
        problems.append(f"{entry.name}: capabilities must be a Capabilities with axes")
    elif not (isinstance(caps.default_baud, int) and caps.default_baud > 0):
        problems.append(f"{entry.name}: default_baud {caps.default_baud!r} is no line rate")
    return problems


def _never_raises_but(
    problems: Problems, where: str, allowed: type[Exception], call: Callable[[], object]
) -> object:
    try:
        return call()
    except allowed:
        return None
    except Exception as exc:  # what the suite exists to find
        problems.append(f"{where} raised {type(exc).__name__}: {exc}")
        return None


def check_protocol(name: str, protocol: Protocol) -> Problems:
    """The hooks on an instance: framers, encode, exchange, decode and the sent-frame readers."""
    where = f"{name}[{protocol.variant.name}]" if protocol.variant else name
    problems: Problems = []
    if not isinstance(protocol.new_framer(), Framer):
        problems.append(f"{where}: new_framer() is not a Framer")
    tx = protocol.new_tx_framer()
    if tx is not None and not isinstance(tx, Framer):
        problems.append(f"{where}: new_tx_framer() is neither None nor a Framer")
    caps = protocol.capabilities
    required: dict[type[cmd.Command], bool] = {
        cmd.GetPosition: caps.position_feedback,
        cmd.GetId: caps.identity_queryable,
        cmd.Stop: caps.stop,
    }
    frames: list[bytes] = []
    for command in PROBES:
        label = f"{where}: encode({type(command).__name__})"
        frame = _never_raises_but(problems, label, BadInput, partial(protocol.encode, command))
        if frame is None:
            if required.get(type(command)):
                problems.append(f"{label} refused, but the capabilities promise it")
            continue
        if not isinstance(frame, bytes) or not frame:
            problems.append(f"{label} gave {frame!r}, not bytes")
            continue
        frames.append(frame)
        if isinstance(command, cmd.Raw):
            continue  # raw bytes are followed by raw_exchange, where they are one command
        tracker = protocol.exchange(command)
        if not isinstance(tracker, Exchange):
            problems.append(f"{where}: exchange({type(command).__name__}) is not an Exchange")
    if not any(protocol_encodes(protocol, c) for c in (cmd.MoveTo(1, 2, 0), cmd.MoveBy(1, 0, 0))):
        problems.append(f"{where}: neither MoveTo nor MoveBy can be sent: nothing moves")
    for frame in frames:
        problems += _check_sent(where, protocol, frame)
    for data in (*NOISE, *frames):
        events = _never_raises_but(
            problems,
            f"{where}: decode({data[:16]!r})",
            FrameError,
            partial(protocol.decode, data),
        )
        if events is not None and not (
            isinstance(events, list) and all(isinstance(e, Event) for e in events)
        ):
            problems.append(f"{where}: decode({data[:16]!r}) is not a list of events")
    return problems


def protocol_encodes(protocol: Protocol, command: cmd.Command) -> bool:
    """Whether the protocol sends `command` (BadInput: it has no such command)."""
    try:
        return bool(protocol.encode(command))
    except BadInput:
        return False


def _check_sent(where: str, protocol: Protocol, frame: bytes) -> Problems:
    """What consoles and log readers ask of a frame the host sent."""
    problems: Problems = []
    head = f"{where}: sent {frame[:16]!r}"
    described = _never_raises_but(problems, head, Exception, lambda: protocol.describe_sent(frame))
    if not isinstance(described, str):
        problems.append(f"{head}: describe_sent is not text")
    if protocol.sent_kind(frame) not in SENT_KINDS:
        problems.append(f"{head}: sent_kind is not one of {sorted(SENT_KINDS)}")
    if not isinstance(protocol.expects_reply(frame), bool):
        problems.append(f"{head}: expects_reply is not a bool")
    _never_raises_but(
        problems, f"{head}: sent_command", FrameError, lambda: protocol.sent_command(frame)
    )
    _never_raises_but(problems, f"{head}: check_raw", BadInput, lambda: protocol.check_raw(frame))
    return problems


def check_simulator(entry: ProtocolEntry) -> Problems:
    """The simulated device: its class, its protocol and the options motionsim always gives."""
    try:
        device_class = simulator_class(entry.name)
    except MotionError as exc:
        return [f"{entry.name}: {exc}"]
    problems = []
    said = getattr(device_class, "protocol", None)
    if said != entry.name:
        problems.append(f"{entry.name}: the simulator's protocol is {said!r}")
    try:
        make: Callable[..., SimulatedDevice] = device_class
        device = make(lambda: 0.0, None, instant=True, mute=False)
    except Exception as exc:  # motionsim and sim:// pass these two to every simulator
        return [*problems, f"{entry.name}: the simulator does not take instant=, mute=: {exc}"]
    if not (isinstance(device.default_baud, int) and device.default_baud > 0):
        problems.append(f"{entry.name}: the simulator's default_baud is no line rate")
    return problems


def check_session(
    entry: ProtocolEntry, settings: Mapping[str, float] | None = None, timeout: float = 5.0
) -> Problems:
    """The protocol and its simulator together, as the window and motionctl use them: a session
    on `sim://NAME?instant=1` asked where it is, moved 1 mm along X, asked again."""
    from drivers.session.device_session import open_device

    where = f"{entry.name} on its simulator"
    try:
        url = f"sim://{quote(entry.name)}?instant=1"
        with open_device(url, entry.name, timeout=timeout, settings=settings) as s:
            start = s.position()
            target = (1.0, 0.0, 0.0)  # every protocol has an X axis
            moved = s.move_to(*target)
            after = s.position()
    except MotionError as exc:
        return [f"{where}: {exc}"]
    step = max(s.capabilities.resolution or 0.0, 0.01)
    problems = []
    if not all(math.isfinite(v) for v in (start.x, start.y, start.z)):
        problems.append(f"{where}: the first position {start} is not finite")
    reached = (moved.x, moved.y, moved.z)
    if math.dist(reached, target) > 0.5:
        problems.append(f"{where}: moved to {target}, the session says {reached}")
    if math.dist((after.x, after.y, after.z), reached) > step:
        problems.append(f"{where}: after the move at {reached}, asked again: {after}")
    return problems
