"""motionctl after Ctrl-C: the protocol's stop sent where it has one, and what the device does
next said exactly where it has none (drivers/protocols/README.md; the exit status stays 130)."""

from __future__ import annotations

import logging

from drivers.device.motion import MoveStart
from drivers.errors import MotionError
from drivers.messages import Message
from drivers.protocols import commands as cmd
from drivers.session.device_session import DeviceSession

log = logging.getLogger(__name__)

STOP_WAIT_S = 1.0  # each try of the stop's acknowledgement, and the position read after it
# The commands that may set the stage moving; the others are queries and settings.
MOVING_COMMANDS = frozenset({"move", "jog", "home", "arc", "run", "macro", "raw", "step", "dwell"})
# Moves that go through Motion's moves (and are seen by MoveTracker) and nothing else.
TRACKED_COMMANDS = frozenset({"move", "jog", "home", "arc"})


class MoveTracker:
    """Remembers the last move sent (a Motion move listener)."""

    def __init__(self) -> None:
        self.last: MoveStart | None = None

    def __call__(self, started: MoveStart) -> None:
        """A move was sent (or is about to be: Motion tells before it writes)."""
        self.last = started


def _device_goes_on(protocol: str, started: MoveStart | None) -> Message:
    """What a device without a stop does after motionctl stops talking to it."""
    if started is not None and protocol in ("coxiris", "visiomex", "pi-frame"):
        x, y, z = started.target
        target = Message("to ({x:g}, {y:g}, {z:g}) mm", x=x, y=y, z=z)
    else:
        target = Message("to its target")
    if protocol == "coxiris":
        return Message(
            "interrupted: COXIRIS has no stop command; the device finishes the move under way "
            "{target} (a blocking sketch answers nothing until then) and then carries out "
            "what it had already received; motionctl sent nothing more",
            target=target,
        )
    if protocol == "visiomex":
        return Message(
            "interrupted: Visiomex has no stop command; the device carries out the move packet "
            "it was sent {target} (FP0001, its steps, then FA0001); motionctl sent nothing more",
            target=target,
        )
    if protocol == "pi-frame":
        return Message(
            "interrupted: pi-frame has no stop command and sends no replies; the device carries "
            "out the frame it was sent {target}; motionctl sent nothing more",
            target=target,
        )
    if protocol == "firmata":
        return Message(
            "interrupted: Firmata has no stop command; the board finishes the step message "
            "under way (at most 16383 steps) and stops there; the move's later messages, if it "
            "had more, were not sent"
        )
    return Message(
        "interrupted: {protocol} has no stop command; the device finishes what it was sent; "
        "motionctl sent nothing more",
        protocol=protocol,
    )


def after_interrupt(
    session: DeviceSession | None, command: str, tracker: MoveTracker | None = None
) -> Message:
    """After Ctrl-C: send the protocol's stop where it has one (its acknowledgement waited for
    at most a few STOP_WAIT_S tries, then the position read), and say what the device does."""
    if session is None:
        return Message("interrupted before the device was talked to: nothing was sent")
    protocol = session.protocol.name
    if command not in MOVING_COMMANDS:
        return Message("interrupted: {command} does not move the stage", command=command)
    started = tracker.last if tracker is not None else None
    if command in TRACKED_COMMANDS and tracker is not None and started is None:
        return Message("interrupted before the move was sent: the stage does not move")
    if not session.capabilities.stop:
        return _device_goes_on(protocol, started)
    session.timeout = min(session.timeout, STOP_WAIT_S)
    try:
        session.send(cmd.Stop(), timeout=STOP_WAIT_S)
    except KeyboardInterrupt:
        return Message(
            "interrupted again while stopping: the {protocol} stop may not have arrived; "
            "the device may still be moving",
            protocol=protocol,
        )
    except MotionError as exc:
        log.info("the stop after Ctrl-C failed: %s", exc)
        return Message(
            "interrupted: the {protocol} stop was sent but not acknowledged ({error}); the "
            "device may still be moving",
            protocol=protocol,
            error=exc,
        )
    try:
        here = session.position()
    except KeyboardInterrupt:
        here = None
        unread: object = Message("interrupted again")
    except MotionError as exc:
        here, unread = None, exc
    if here is None:
        return Message(
            "interrupted: stopped (the {protocol} stop was acknowledged; its queue is "
            "flushed); where the stage stopped could not be read: {error}",
            protocol=protocol,
            error=unread,
        )
    return Message(
        "interrupted: stopped at ({x:g}, {y:g}, {z:g}) mm (the {protocol} stop was "
        "acknowledged; its queue is flushed)",
        x=here.x,
        y=here.y,
        z=here.z,
        protocol=protocol,
    )
