"""`motionctl run FILE [--layer NAME]... [--tolerance MM] [--svg-scale MM]`: a program of any
format (G-code, DXF, SVG, CSV, JSON) on any device, checked whole before the port is opened,
with its progress on stderr."""

from __future__ import annotations

import sys
import time
from dataclasses import dataclass
from typing import Any

from app.common.command_words import RUN_USAGE
from drivers.device.travel import TravelLimits
from drivers.errors import BadInput
from drivers.messages import Message
from drivers.protocols.base import Protocol
from drivers.protocols.numbers import parse_number
from drivers.session.device_session import DeviceSession
from drivers.toolpath.geometry import check_fits, check_speeds, flatten
from drivers.toolpath.loader import load_toolpath
from drivers.toolpath.model import CHORD_TOLERANCE, Toolpath
from drivers.toolpath.streaming import StreamProgress

PROGRESS_EVERY = 0.5  # s between progress lines


class RunUsageError(BadInput):
    """`run`'s arguments are wrong (exit 2, nothing sent)."""


@dataclass(frozen=True)
class RunRequest:
    """What `run` was asked: the file and how to read it."""

    file: str
    layers: tuple[str, ...] | None
    tolerance: float
    svg_scale: float | None


_checked: dict[RunRequest, Toolpath] = {}  # read before the port opened: never read again


def run_request(args: list[str]) -> RunRequest:
    """`run`'s arguments (RunUsageError: refused)."""
    files: list[str] = []
    layers: list[str] = []
    tolerance, scale = CHORD_TOLERANCE, None
    index = 0
    while index < len(args):
        word = args[index]
        if word in ("--layer", "--tolerance", "--svg-scale"):
            if index + 1 >= len(args):
                raise RunUsageError(Message("usage: {usage}", usage=RUN_USAGE))
            value = args[index + 1]
            if word == "--layer":
                layers.append(value)
            elif word == "--tolerance":
                tolerance = parse_number(value, "chord tolerance (mm)")
                if not tolerance > 0:
                    raise RunUsageError(
                        Message(
                            "chord tolerance {value:g} mm refused: it must be above 0",
                            value=tolerance,
                        )
                    )
            else:
                scale = parse_number(value, "SVG scale (mm per unit)")
                if not scale > 0:
                    raise RunUsageError(
                        Message("SVG scale {value:g} refused: it must be above 0", value=scale)
                    )
            index += 2
        else:
            files.append(word)
            index += 1
    if len(files) != 1:
        raise RunUsageError(Message("usage: {usage}", usage=RUN_USAGE))
    return RunRequest(files[0], tuple(layers) or None, tolerance, scale)


def check_run_offline(protocol: Protocol, args: list[str], travel: TravelLimits | None) -> None:
    """Read the program and check it against the travel box and the device's fixed speed
    range before the port is opened (BadInput: refused, nothing sent)."""
    request = run_request(args)
    toolpath = load_toolpath(
        request.file,
        layers=request.layers,
        svg_scale=request.svg_scale,
        tolerance=request.tolerance,
    )
    caps = protocol.capabilities
    check_fits(toolpath, flatten(toolpath, request.tolerance), caps.axes, travel)
    if caps.speed_range is not None and caps.speed and not caps.speed_limits_queryable:
        check_speeds(toolpath, *caps.speed_range, caps.speed_decimals)
    _checked[request] = toolpath


def run_program(session: DeviceSession, args: list[str]) -> dict[str, Any]:
    """Run the program checked offline, telling its progress on stderr; the summary."""
    request = run_request(args)
    toolpath = _checked.pop(request, None) or load_toolpath(
        request.file,
        layers=request.layers,
        svg_scale=request.svg_scale,
        tolerance=request.tolerance,
    )
    for notice in toolpath.notices:
        session.notify(notice)
    shown = [0.0]

    def progress(state: StreamProgress) -> None:
        now = time.monotonic()
        if now - shown[0] < PROGRESS_EVERY and not state.finished:
            return
        shown[0] = now
        print("motionctl: " + progress_text(toolpath, state), file=sys.stderr, flush=True)

    # Ctrl-C ends the run where it is; motionctl then sends the device's stop (interrupt.py).
    state = session.run_program(toolpath, progress, tolerance=request.tolerance)
    here = session.last_position or session.position()
    result: dict[str, Any] = {
        "program": toolpath.name,
        "instructions": state.total,
        "executed": state.executed,
        "frames": state.frames,
        "retransmissions": state.retransmissions,
        "seconds": round(state.seconds, 3),
        "finished": state.finished,
        "position": [here.x, here.y, here.z],
        "measured": here.measured,
    }
    if state.source is not None:
        result["last_line"] = toolpath.where(state.source)
    return result


def progress_text(toolpath: Toolpath, state: StreamProgress) -> str:
    """One progress line: how many done (a streamed program: sent, acknowledged, executed, as
    before), where in the file, the time left."""
    if state.frames:
        parts = [
            f"{state.sent}/{state.total} sent, {state.acknowledged} acknowledged, "
            f"{state.executed} executed, {state.rate:.0f}/s"
        ]
    else:
        parts = [f"{state.executed}/{state.total} done"]
    left = state.seconds_left()
    if left is not None and not state.finished:
        parts.append(f"about {left:.0f} s left")
    if state.source is not None:
        source = toolpath.sources[state.source]
        parts.append(f"{toolpath.where(state.source)}: {source.text.strip()[:60]}")
    return ", ".join(parts)
