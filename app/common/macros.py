"""Macros: named sequences of motionctl commands (and waits), per protocol; checked whole before
anything is sent, run step by step on a DeviceSession, kept as JSON (data only, never code)."""

from __future__ import annotations

import json
import logging
import warnings
import weakref
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from app.common.command_words import (
    DEVICE_COMMANDS,
    UsageError,
    check_word_offline,
    run_word,
)
from drivers.device.motion import Motion
from drivers.errors import BadFile, BadInput, MotionError
from drivers.files import MACRO_MAX_BYTES, read_text
from drivers.messages import Message, message_of
from drivers.protocols.base import Protocol
from drivers.protocols.numbers import parse_number
from drivers.protocols.registry import protocol_names
from drivers.session.device_session import DeviceSession

log = logging.getLogger(__name__)

FORMAT = "motionpanel-macros"
VERSION = 1
MAX_NAME = 40
MAX_STEPS = 500
MAX_STEP_CHARS = 1000
MAX_MACROS = 200
MAX_WAIT_S = 3600.0
WAIT_SLICE_S = 0.1  # a wait looks for a stop this often
STEP_COMMANDS = (
    "id", "position", "home", "set-home", "move", "jog", "speed", "limits", "check", "raw",
    "step", "version", "dwell", "arc", "status", "stop", "wait",
)  # fmt: skip
"""What a step may be: motionctl's commands that neither write files nor settings, and `wait S`
(the panel pauses S seconds, reading the port meanwhile)."""


class BadMacro(BadInput):
    """A macro that cannot run: unknown command, bad argument, too long; nothing was sent."""


class BadMacroFile(BadFile):
    """A macro file refused whole: not JSON, not ours, or a macro in it is malformed."""


class MacroStopped(MotionError):
    """The operator stopped the macro between two steps, or during a wait."""


@dataclass(frozen=True)
class Macro:
    """A named sequence of steps for one protocol, e.g. `home`, `move 10 5 0`, `wait 0.5`."""

    name: str
    protocol: str
    steps: tuple[str, ...]

    def describe(self) -> str:
        """E.g. `macro probe (4 steps)`."""
        count = len(self.steps)
        if count == 1:
            return Message("macro {name} ({count} step)", name=self.name, count=count)
        return Message("macro {name} ({count} steps)", name=self.name, count=count)


def split_step(text: str) -> tuple[str, list[str]]:
    """A step's command and arguments: `raw` keeps the rest of the line whole."""
    stripped = text.strip()
    command, _, rest = stripped.partition(" ")
    if command == "raw":
        return command, [rest.strip()] if rest.strip() else []
    return command, rest.split()


def check_name(name: str) -> str:
    """The name, stripped; BadMacro if it is empty, too long or holds control characters."""
    stripped = name.strip()
    if not stripped:
        raise BadMacro(Message("a macro needs a name"))
    if len(stripped) > MAX_NAME:
        raise BadMacro(
            Message(
                "macro name {name!r}… is over {limit} characters",
                name=stripped[:MAX_NAME],
                limit=MAX_NAME,
            )
        )
    if any(not ch.isprintable() for ch in stripped):
        raise BadMacro(Message("macro name {name!r} holds a control character", name=stripped))
    return stripped


def check_macro(macro: Macro, protocol: Protocol) -> None:
    """Refuse a macro any step of which the device would refuse (BadMacro, nothing sent)."""
    name = check_name(macro.name)
    if macro.protocol != protocol.name:
        raise BadMacro(
            Message(
                "macro {name} is for {protocol}, not {device}",
                name=name,
                protocol=macro.protocol,
                device=protocol.name,
            )
        )
    if not macro.steps:
        raise BadMacro(Message("macro {name} has no steps", name=name))
    if len(macro.steps) > MAX_STEPS:
        raise BadMacro(
            Message(
                "macro {name} has {count} steps; at most {limit}",
                name=name,
                count=len(macro.steps),
                limit=MAX_STEPS,
            )
        )
    for number, step in enumerate(macro.steps, 1):
        try:
            check_step(step, protocol)
        except BadInput as exc:
            raise BadMacro(
                Message(
                    "macro {name}, step {number} ({step!r}): {error}",
                    name=name,
                    number=number,
                    step=step.strip()[:60],
                    error=exc,
                )
            ) from None


def check_step(step: str, protocol: Protocol) -> None:
    """Refuse one step as motionctl would refuse the same command (BadInput)."""
    if len(step) > MAX_STEP_CHARS:
        raise BadMacro(Message("the step is over {limit} characters", limit=MAX_STEP_CHARS))
    if any(ch in step for ch in "\r\n\x00"):
        raise BadMacro(Message("a step is one line (use one step per line)"))
    command, args = split_step(step)
    if not command:
        raise BadMacro(Message("the step is empty"))
    if command not in STEP_COMMANDS:
        raise BadMacro(
            Message(
                "unknown command {command!r}; a step is one of: {commands}",
                command=command,
                commands=", ".join(STEP_COMMANDS),
            )
        )
    if command == "wait":
        wait_seconds(args)
        return
    owner = DEVICE_COMMANDS.get(command, (protocol.name,))[0]
    if owner != protocol.name:
        raise BadMacro(Message("{command} is a {owner} command", command=command, owner=owner))
    try:
        check_word_offline(command, args, protocol, None, "linear")
    except UsageError as exc:
        raise BadMacro(message_of(exc) or str(exc)) from None


def wait_seconds(args: list[str]) -> float:
    """The seconds of `wait S`: a number from 0 to MAX_WAIT_S."""
    if len(args) != 1:
        raise BadMacro(Message("usage: wait SECONDS"))
    seconds = parse_number(args[0], "wait")
    if not 0 <= seconds <= MAX_WAIT_S:
        raise BadMacro(
            Message(
                "wait {seconds:g} s refused: from 0 to {limit:g} s",
                seconds=seconds,
                limit=MAX_WAIT_S,
            )
        )
    return seconds


def run_macro(
    session: DeviceSession | Motion,
    macro: Macro,
    on_step: Callable[[int, str], None] = lambda number, step: None,
) -> list[dict[str, Any]]:
    """Run every step in order, each waiting for the device as motionctl does; returns each
    step's result. A `stop` during it ends it between steps, or a wait (MacroStopped). A Motion
    for `session` is deprecated (removed in release 0.3.0)."""
    if isinstance(session, Motion):
        warnings.warn(
            "run_macro(motion, ...) is deprecated and will be removed in release 0.3.0: "
            "pass the DeviceSession",
            DeprecationWarning,
            stacklevel=2,
        )
        session = _session_of(session)
    results: list[dict[str, Any]] = []
    with session.operation():
        for number, step in enumerate(macro.steps, 1):
            if session.stop_requested:
                raise MacroStopped(
                    Message(
                        "macro {name} stopped before step {number} ({step})",
                        name=macro.name,
                        number=number,
                        step=step,
                    )
                )
            on_step(number, step)
            command, args = split_step(step)
            if command == "wait":
                stopped = Message(
                    "macro {name} stopped during step {number}", name=macro.name, number=number
                )
                _wait(session, wait_seconds(args), stopped)
                results.append({"waited": wait_seconds(args)})
            else:
                results.append(run_word(session, command, args))
    return results


_sessions: weakref.WeakKeyDictionary[Motion, DeviceSession] = weakref.WeakKeyDictionary()


def _session_of(motion: Motion) -> DeviceSession:
    """The session over a Motion passed the deprecated way (one per Motion)."""
    session = _sessions.get(motion)
    if session is None:
        session = _sessions[motion] = DeviceSession._around(motion)
    return session


def _wait(session: DeviceSession, seconds: float, stopped: str) -> None:
    """Wait on the port for `seconds`, in slices, so a stop or an abort ends it soon."""
    left = seconds
    while left > 0:
        if session.stop_requested:
            raise MacroStopped(stopped)
        piece = min(WAIT_SLICE_S, left)
        if session.wait(piece):
            raise MacroStopped(stopped)
        left -= piece


# -- as data -----------------------------------------------------------------------------------
def to_data(macros: Iterable[Macro]) -> dict[str, Any]:
    """The JSON-able form of macros, as files and the settings keep them."""
    return {
        "format": FORMAT,
        "version": VERSION,
        "macros": [
            {"name": m.name, "protocol": m.protocol, "steps": list(m.steps)} for m in macros
        ],
    }


def from_data(data: object, where: str) -> list[Macro]:
    """Macros from their JSON-able form; BadMacro naming `where` and the fault if malformed."""
    if not isinstance(data, dict) or data.get("format") != FORMAT:
        raise BadMacro(
            Message(
                '{where}: not a Motion Panel macro file (no "format": "{format}")',
                where=where,
                format=FORMAT,
            )
        )
    if data.get("version") != VERSION:
        raise BadMacro(
            Message(
                "{where}: macro file version {version!r}; this reads {reads}",
                where=where,
                version=data.get("version"),
                reads=VERSION,
            )
        )
    entries = data.get("macros")
    if not isinstance(entries, list):
        raise BadMacro(Message('{where}: "macros" is not a list', where=where))
    if len(entries) > MAX_MACROS:
        raise BadMacro(
            Message(
                "{where}: {count} macros; at most {limit}",
                where=where,
                count=len(entries),
                limit=MAX_MACROS,
            )
        )
    macros: list[Macro] = []
    seen: set[tuple[str, str]] = set()
    known = set(protocol_names())
    for number, entry in enumerate(entries, 1):
        macro = _entry(entry, Message("{where}: macro {number}", where=where, number=number), known)
        if (macro.protocol, macro.name) in seen:
            raise BadMacro(
                Message(
                    "{where}: two {protocol} macros are named {name!r}",
                    where=where,
                    protocol=macro.protocol,
                    name=macro.name,
                )
            )
        seen.add((macro.protocol, macro.name))
        macros.append(macro)
    return macros


def _entry(entry: object, where: str, known: set[str]) -> Macro:
    if not isinstance(entry, dict):
        raise BadMacro(
            Message("{where} is not an object with name, protocol and steps", where=where)
        )
    name, protocol, steps = entry.get("name"), entry.get("protocol"), entry.get("steps")
    if not isinstance(name, str):
        raise BadMacro(Message("{where} has no name", where=where))
    if protocol not in known:
        raise BadMacro(
            Message(
                "{where} ({name!r}): unknown protocol {protocol!r}",
                where=where,
                name=name,
                protocol=protocol,
            )
        )
    if not isinstance(steps, list) or not all(isinstance(s, str) for s in steps):
        raise BadMacro(
            Message('{where} ({name!r}): "steps" is not a list of strings', where=where, name=name)
        )
    if len(steps) > MAX_STEPS or any(len(s) > MAX_STEP_CHARS for s in steps):
        raise BadMacro(
            Message(
                "{where} ({name!r}): over {limit} steps or a step too long",
                where=where,
                name=name,
                limit=MAX_STEPS,
            )
        )
    try:
        return Macro(check_name(name), str(protocol), tuple(s.strip() for s in steps))
    except BadMacro as exc:
        raise BadMacro(Message("{where}: {error}", where=where, error=exc)) from None


def read_macro_file(path: str | Path) -> list[Macro]:
    """The macros in a file (JSON, at most MACRO_MAX_BYTES); BadMacroFile if it is not one.
    Steps are checked against their protocol when run or imported, not here."""
    text = read_text(path, MACRO_MAX_BYTES, Message("macro file"), BadMacroFile)
    try:
        data = json.loads(text, parse_constant=_no_constant)
    except (ValueError, RecursionError) as exc:
        raise BadMacroFile(Message("{path}: not JSON ({error})", path=path, error=exc)) from None
    try:
        return from_data(data, str(path))
    except BadMacro as exc:
        raise BadMacroFile(message_of(exc) or str(exc)) from None


def _no_constant(name: str) -> float:
    """JSON's NaN and Infinity are not data a macro file holds."""
    raise ValueError(Message("{name} is not a JSON number", name=name))


def write_macro_file(path: str | Path, macros: Iterable[Macro]) -> None:
    """Write macros to a file that `read_macro_file` reads back."""
    text = json.dumps(to_data(macros), indent=2, ensure_ascii=False) + "\n"
    Path(path).write_text(text, encoding="utf-8")


def merge(existing: list[Macro], incoming: Iterable[Macro]) -> list[Macro]:
    """`existing` with `incoming` added; one of the same protocol and name replaces the old."""
    merged = {(m.protocol, m.name): m for m in existing}
    for macro in incoming:
        merged[(macro.protocol, macro.name)] = macro
    return list(merged.values())


# -- kept with the settings ------------------------------------------------------------------------
def settings_key(protocol: str) -> str:
    """Where a protocol's macros are kept in the settings (one JSON text)."""
    return f"macros/{protocol}"


def read_saved(settings: Any, protocol: str) -> list[Macro]:
    """The macros saved for a protocol; a malformed entry (an edited file) gives none, logged."""
    text = settings.value(settings_key(protocol))
    if not isinstance(text, str) or not text:
        return []
    try:
        macros = from_data(json.loads(text, parse_constant=_no_constant), Message("saved macros"))
    except (ValueError, RecursionError) as exc:  # BadMacro is a ValueError too
        log.warning("the saved %s macros are unreadable and were left out: %s", protocol, exc)
        return []
    return [m for m in macros if m.protocol == protocol]


def save(settings: Any, protocol: str, macros: Iterable[Macro]) -> None:
    """Keep a protocol's macros in the settings (replacing those kept before)."""
    mine = [m for m in macros if m.protocol == protocol]
    settings.setValue(settings_key(protocol), json.dumps(to_data(mine), ensure_ascii=False))
    settings.sync()
