"""`motionctl COMMAND --help`: each command's own usage and what it does, exit 0, as argparse
prints a sub-command's help."""

from __future__ import annotations

import argparse

from app.cli.command_line import COMMANDS, usage_of

HELP_FLAGS = frozenset({"-h", "--help"})
_WHAT = {
    "id": "Print the device's identity (where the protocol can ask it).",
    "position": "Print where the stage is: measured, or, on a device that cannot be asked, "
    "the position kept for the port (counted or commanded), or say that it is unknown.",
    "home": "Home the stage (a move back to 0 where the device has no homing of its own).",
    "set-home": "Make where the stage stands (0, 0, 0); on a device that cannot be asked, "
    "this starts the position kept for the port.",
    "move": "Move to X Y [Z] in mm (absolute).",
    "jog": "Move by DX DY [DZ] in mm (relative; --kind rotational|steps where the protocol "
    "has such moves).",
    "speed": "Print the speed, or set it to VALUE mm/s (kept for the port where the moves "
    "carry the speed).",
    "limits": "Print the device's lowest and highest speed.",
    "check": "Ask the device for errors.",
    "raw": "Send TEXT as it is (hex for binary protocols), through the motion guard: a move "
    "is checked like a typed one; --force sends bytes the protocol cannot read despite a "
    "travel box.",
    "param": "list: the parameters and the values last written; set NAME|ID VALUE: write "
    "one; write FILE: write a profile.",
    "config": "Firmata: configure the stepper (steps per revolution and its 2 or 4 pins); "
    "kept for the port, sent again at each later run.",
    "step": "Firmata: step the motor STEPS steps at SPEED rpm (negative steps reverse).",
    "version": "Firmata: print the stepper library's version.",
    "dwell": "pi-frame: wait MS milliseconds on the device.",
    "arc": "pi-frame: an arc around (CX, CY) of RADIUS mm from START to END degrees.",
    "status": "laser-frame: print the device's queue and whether it moves.",
    "stop": "laser-frame: stop at once and drop the device's queue.",
    "run": "Run a program (G-code, DXF, SVG, CSV, JSON), checked whole before the port is opened.",
    "log": "Decode a traffic log (motionctl --log, motionsim --record, the panel's session "
    "log, a spy:// capture); no port is opened.",
    "macro": "list | import FILE | export FILE: the panel's macros (no port needed); run "
    "NAME: run one on the device.",
}
_EPILOG = (
    "OPTIONS are motionctl's (--port, --protocol, --json, --travel...), before or after the "
    "command: see motionctl --help. Exit status: 0 ok, 1 device reported an error, 2 bad "
    "input (nothing sent), 3 timeout, no device or port error, 130 interrupted (Ctrl-C)."
)


def wants_help(args: list[str]) -> bool:
    """Whether a command's arguments ask for its help."""
    return any(arg in HELP_FLAGS for arg in args)


def command_help(command: str) -> str:
    """The help of one motionctl command, as argparse writes it."""
    if command not in COMMANDS:
        raise KeyError(command)
    parser = argparse.ArgumentParser(
        prog=f"motionctl {command}",
        usage=f"motionctl [OPTIONS] {usage_of(command)}",
        description=_WHAT[command],
        epilog=_EPILOG,
        add_help=False,
    )
    return parser.format_help()
