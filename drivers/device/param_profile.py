"""Parameter profiles: named sets of parameter values in a small, human-editable TOML file.

    # Motion Panel parameter profile
    protocol = "visiomex"

    [parameters]
    thread_distance_x = 10        # mm · Lead-screw pitch of the X axis
    pulley_diameter_x = 38.2      # mm · sent as mm×10

Only `protocol` and the `[parameters]` table are read; values are numbers; names are the
protocol's. Firmware outputs (parameters the firmware computes itself and overwrites, e.g. the
Visiomex's 11, 12, 17-20, 25, 26) are never saved in a profile, and a profile that has them (an
older one, or written by hand) has them checked and then left out: writing them changes nothing
that stays. A file is data: nothing in it is executed, and it is refused whole (nothing sent) if
any line is wrong, if it is not a regular file of at most `PROFILE_MAX_BYTES` (drivers/files.py),
or not UTF-8 text.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

from drivers.errors import BadFile, BadInput
from drivers.files import PROFILE_MAX_BYTES, read_text
from drivers.messages import Message
from drivers.protocols.parameters import Parameter

HEADER = "# Motion Panel parameter profile"


class ProfileError(BadFile):
    """A profile file that cannot be used; says which file, and which line where it can."""


def _line_of(text: str, name: str) -> int | None:
    pattern = re.compile(rf"^\s*[\"']?{re.escape(name)}[\"']?\s*=", re.MULTILINE)
    match = pattern.search(text)
    return text.count("\n", 0, match.start()) + 1 if match else None


def parse_profile(
    text: str,
    parameters: tuple[Parameter, ...],
    protocol: str,
    source: str = "profile",
    outputs: list[str] | None = None,
) -> dict[str, float]:
    """The input values of a profile's text, every one checked; ProfileError on the first
    problem. Firmware outputs are left out (their names are appended to `outputs` if given)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ProfileError(
            Message("{source}: not a parameter profile: {error}", source=source, error=exc)
        ) from None
    except ValueError:  # an integer of over 4300 digits, which int() refuses
        raise ProfileError(
            Message("{source}: not a parameter profile: a number too long", source=source)
        ) from None
    except RecursionError:
        raise ProfileError(
            Message("{source}: not a parameter profile: nested too deeply", source=source)
        ) from None
    named = data.get("protocol")
    if named is not None and not isinstance(named, str):
        raise ProfileError(Message("{source}: protocol must be a name in quotes", source=source))
    if named is not None and named != protocol:
        raise ProfileError(
            Message(
                "{source}: a profile for {named!r}, not for {protocol!r}",
                source=source,
                named=named,
                protocol=protocol,
            )
        )
    unknown_keys = sorted(set(data) - {"protocol", "parameters"})
    if unknown_keys:
        line = _line_of(text, unknown_keys[0])
        if line:
            raise ProfileError(
                Message(
                    "{source} (line {line}): unknown key {key!r}",
                    source=source,
                    line=line,
                    key=unknown_keys[0],
                )
            )
        raise ProfileError(
            Message("{source}: unknown key {key!r}", source=source, key=unknown_keys[0])
        )
    table = data.get("parameters")
    if not isinstance(table, dict) or not table:
        raise ProfileError(
            Message("{source}: no [parameters] table with values in it", source=source)
        )
    by_name = {p.name: p for p in parameters}
    values: dict[str, float] = {}
    for name, value in table.items():
        line = _line_of(text, name)
        where = Message("{source} line {line}", source=source, line=line) if line else source
        parameter = by_name.get(name)
        if parameter is None:
            raise ProfileError(
                Message(
                    "{where}: unknown parameter {name!r} for {protocol}",
                    where=where,
                    name=name,
                    protocol=protocol,
                )
            )
        try:
            parameter.to_wire(value)
        except BadInput as exc:
            raise ProfileError(Message("{where}: {error}", where=where, error=exc)) from None
        except (OverflowError, ValueError):  # an integer too large for a float, or to print
            raise ProfileError(
                Message(
                    "{where}: {name}: not a number the device takes ({range})",
                    where=where,
                    name=name,
                    range=parameter.range_text(),
                )
            ) from None
        if parameter.output:
            if outputs is not None:
                outputs.append(name)
            continue  # the firmware computes it: never written from a profile
        values[name] = float(value)
    if not values:
        raise ProfileError(
            Message(
                "{source}: only firmware outputs ({names}), which a profile does not write",
                source=source,
                names=", ".join(table),
            )
        )
    return values


def read_profile(
    path: str | Path,
    parameters: tuple[Parameter, ...],
    protocol: str,
    outputs: list[str] | None = None,
) -> dict[str, float]:
    """A profile file's input values (firmware outputs left out, named in `outputs`);
    ProfileError for a missing, special, large, binary or malformed file (nothing is sent:
    this only reads)."""
    file = Path(path)
    text = read_text(file, PROFILE_MAX_BYTES, Message("profile"), ProfileError)
    return parse_profile(text, parameters, protocol, str(file), outputs)


def format_profile(
    values: dict[str, float], parameters: tuple[Parameter, ...], protocol: str
) -> str:
    """A profile's text: every given input value, in the protocol's order, with its unit and
    meaning; firmware outputs are left out (the firmware overwrites them)."""
    lines = [HEADER, f'protocol = "{protocol}"', "", "[parameters]"]
    left_out = [p.name for p in parameters if p.output and p.name in values]
    for parameter in parameters:
        if parameter.name not in values or parameter.output:
            continue
        value = parameter.with_unit(values[parameter.name]).split(" ")[0]
        comment = f"{parameter.unit} · " if parameter.unit else ""
        lines.append(f"{parameter.name} = {value:<10}# {comment}{parameter.description}")
    if left_out:
        lines += ["", f"# Not saved: {', '.join(left_out)} (computed by the firmware)."]
    return "\n".join(lines) + "\n"


def write_profile(
    path: str | Path, values: dict[str, float], parameters: tuple[Parameter, ...], protocol: str
) -> int:
    """Save a profile; the number of values saved (firmware outputs are not); ProfileError if
    the file cannot be written."""
    try:
        Path(path).write_text(format_profile(values, parameters, protocol), encoding="utf-8")
    except OSError as exc:
        raise ProfileError(
            Message(
                "cannot write the profile {path}: {error}", path=path, error=exc.strerror or exc
            )
        ) from None
    return sum(1 for p in parameters if p.name in values and not p.output)
