"""`motionctl ... param list | set NAME|ID VALUE | write FILE`: device parameters from the shell."""

from __future__ import annotations

import sys
import time
from collections.abc import Callable
from typing import Any

from drivers.device.param_profile import read_profile
from drivers.errors import BadInput
from drivers.protocols.base import Protocol
from drivers.protocols.numbers import parse_number
from drivers.protocols.parameters import Parameter, ParameterWritten
from drivers.session.device_session import DeviceSession

SECONDS_PER_PACKET = 1.05  # a Visiomex reply comes 1 s after the packet; used for "time left"
Remember = Callable[[dict[str, float]], None]
# The profiles `param write` read and checked before the port was opened, by (file, protocol):
# what is written, so the file is read once and before anything is sent (not read again after the
# link is open and the start-up commands have gone, where a file changed meanwhile could fail).
_checked: dict[tuple[str, str], dict[str, float]] = {}


def param_rows(protocol: Protocol, last: dict[str, float]) -> list[dict[str, Any]]:
    """Every parameter as a JSON-able row, with the value last written where known."""
    return [
        {
            "id": p.id,
            "name": p.name,
            "unit": p.unit,
            "min": p.minimum,
            "max": p.maximum,
            "step": p.step,
            "output": p.output,
            "description": p.description,
            "last_written": last.get(p.name),
        }
        for p in protocol.parameters
    ]


def param_table(rows: list[dict[str, Any]]) -> str:
    """The rows as an aligned text table."""
    lines = [f"{'id':>2}  {'name':<28} {'unit':<6} {'range':<22} {'last written':<13} kind"]
    for row in rows:
        span = f"{row['min']:g}..{row['max']:g}" + (
            f" /{row['step']:g}" if row["step"] != 1 else ""
        )
        last = "—" if row["last_written"] is None else f"{row['last_written']:g}"
        kind = "output" if row["output"] else "input"
        lines.append(
            f"{row['id']:>2}  {row['name']:<28} {row['unit']:<6} {span:<22} {last:<13} {kind}"
        )
    return "\n".join(lines)


def check_param_offline(protocol: Protocol, args: list[str]) -> None:
    """Refuse a bad parameter command before the port is opened (BadInput)."""
    if not protocol.parameters:
        raise BadInput(f"{protocol.name} has no parameters")
    if args[0] == "set":
        parameter = protocol.parameter(args[1])
        parameter.to_wire(_value(parameter, args[2]))
    elif args[0] == "write":
        outputs: list[str] = []
        _checked[args[1], protocol.name] = read_profile(
            args[1], protocol.parameters, protocol.name, outputs
        )
        if outputs:
            print(
                f"motionctl: {args[1]}: not written: {', '.join(outputs)} "
                "(computed by the firmware, which overwrites them)",
                file=sys.stderr,
            )


def _value(parameter: Parameter, text: str) -> float:
    """A value typed for a parameter; BadInput naming its unit and range."""
    try:
        return parse_number(text, parameter.name)
    except BadInput as exc:
        raise BadInput(f"{exc} ({parameter.range_text()})") from None


def _written(item: ParameterWritten) -> dict[str, Any]:
    return {
        "id": item.parameter.id,
        "name": item.parameter.name,
        "unit": item.parameter.unit,
        "value": item.value,
        "device_values": item.device_values,
        "notes": list(item.notes),
    }


def _progress(index: int, total: int, item: ParameterWritten, started: float) -> None:
    left = (total - index) * SECONDS_PER_PACKET
    rate = (time.monotonic() - started) / index
    print(
        f"motionctl: {index}/{total} {item.parameter.name} = "
        f"{item.parameter.with_unit(item.value)} confirmed "
        f"({rate:.2f} s per packet, about {left:.0f} s left)",
        file=sys.stderr,
        flush=True,
    )


def run_param(session: DeviceSession, args: list[str], remember: Remember) -> dict[str, Any]:
    """Carry out `param set` or `param write`; every confirmed value is remembered at once."""
    protocol = session.protocol
    if args[0] == "set":
        parameter = protocol.parameter(args[1])
        values = {parameter.name: _value(parameter, args[2])}
    else:
        values = _checked.pop((args[1], protocol.name), None) or read_profile(
            args[1], protocol.parameters, protocol.name
        )
    written = []
    started = time.monotonic()
    for index, (name, value) in enumerate(values.items(), start=1):
        item = session.set_parameter(name, value)
        remember({name: value, **item.device_values})
        written.append(_written(item))
        if args[0] == "write":
            _progress(index, len(values), item, started)
        for note in item.notes:
            print(f"motionctl: {name}: {note}", file=sys.stderr)
    return {"written": written, "seconds": round(time.monotonic() - started, 3)}
