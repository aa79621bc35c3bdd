"""What motionctl prints: results as text or JSON, and failures and notices on stderr, each with
one `motionctl: ` prefix and numbers in plain digits."""

from __future__ import annotations

import json
import logging
import re
import sys
from typing import Any

from app.cli.macro import macro_text
from app.cli.params import param_table
from drivers.messages import plain_number

PREFIX = "motionctl: "
# pyserial's `[Errno 2] could not open port P: [Errno 2] No such file or directory: 'P'`: the
# errno, the port and the file said twice; kept once each.
_TWICE = re.compile(r"\[Errno (\d+)\] could not open port (.+?): \[Errno \1\] (.+?)(?:: '\2')?$")
_PATH_AGAIN = re.compile(r"(\[Errno \d+\] [^:']+): '([^']+)'$")  # ...: [Errno 2] No such...: 'F'


def plain_error(problem: object) -> str:
    """An error as one line for people: without a `motionctl: ` of its own, each errno and
    path said once."""
    text = str(problem).replace("\n", " ").strip()
    while text.startswith(PREFIX):
        text = text[len(PREFIX) :].lstrip()
    text = _TWICE.sub(r"[Errno \1] \3", text)
    again = _PATH_AGAIN.search(text)
    if again is not None and text.count(again.group(2)) > 1:
        text = text[: again.start()] + again.group(1)
    return text


def usage_exit(exc: SystemExit, arguments: list[str]) -> int:
    """The exit status of a command line argparse refused (or of --help): 0 or 2, with a JSON
    line saying so when --json was asked for."""
    if exc.code != 0 and "--json" in arguments:
        print(json.dumps({"error": "invalid command line (see the usage above)", "exit": 2}))
    return 0 if exc.code == 0 else 2


def log_to_stderr(verbose: bool) -> None:
    """motionctl's logging: warnings on stderr (info too with -v), each line prefixed."""
    logging.basicConfig(
        level=logging.INFO if verbose else logging.WARNING,
        format=PREFIX + "%(message)s",
        stream=sys.stderr,
    )


def say(text: object) -> None:
    """One line on stderr, prefixed once."""
    print(PREFIX + plain_error(text), file=sys.stderr, flush=True)


def number(value: float) -> str:
    """A number as `:g` writes it, in plain digits (100000000, not 1e+08)."""
    return plain_number(float(value))


def _program_text(result: dict[str, Any]) -> str:
    """`run`: how far the program got (a streamed one as before: frames, retransmissions), and
    where the stage ended."""
    if result["frames"]:
        return (
            f"{result['executed']}/{result['instructions']} instructions executed in "
            f"{result['frames']} frames, {result['retransmissions']} retransmission(s), "
            f"{result['seconds']:.1f} s"
        )
    ended = "done" if result["finished"] else "stopped"
    text = f"{result['program']} {ended}: {result['executed']}/{result['instructions']} moves"
    text += f" and dwells, {result['seconds']:.1f} s"
    if result.get("position") is not None:
        text += "; at " + _position_text(result)
    return text


def result_text(result: dict[str, Any]) -> str:
    """A command's result as the text motionctl prints."""
    if {"macros", "exported", "imported", "macro"} & result.keys():
        return macro_text(result, result_text)
    if "program" in result:
        return _program_text(result)
    if "position" in result:
        return _position_text(result)
    if "id" in result:
        return str(result["id"] if result["id"] is not None else result["identity"])
    if "speed" in result:
        text = f"{number(result['speed'])} mm/s"
        return text + (" (for the moves that follow)" if result.get("in_moves") else "")
    if "min_speed" in result:
        return f"min {number(result['min_speed'])} mm/s, max {number(result['max_speed'])} mm/s"
    if "reply" in result:
        return "\n".join(result["reply"]) or "sent; the device answered nothing"
    if "configured" in result:
        done = result["configured"]
        pins = " ".join(str(p) for p in done["pins"])
        library = result["version"]
        return f"configured: {done['steps_per_rev']} steps/rev on pins {pins} (library {library})"
    if "text" in result:
        return "\n".join(result["text"])
    if "frames" in result:
        return (
            f"{result['executed']}/{result['instructions']} instructions executed in "
            f"{result['frames']} frames, {result['retransmissions']} retransmission(s), "
            f"{result['seconds']:.1f} s"
        )
    if "status" in result:
        status = result["status"]
        return f"queue {status['queue']}, {'moving' if status['moving'] else 'idle'}"
    if "messages" in result:
        count, seconds = result["messages"], result["seconds"]
        return f"{result['steps']} steps in {count} message(s), about {seconds:.1f} s"
    if "version" in result:
        return f"stepper library version {result['version']}"
    if "parameters" in result:
        return param_table(result["parameters"])
    if "written" in result:
        return "\n".join(
            f"{w['name']} = {number(w['value'])} {w['unit']}".rstrip() for w in result["written"]
        )
    return "ok"


def _position_text(result: dict[str, Any]) -> str:
    """A position, with the jog in degrees or steps that led to it and what the firmware did."""
    lines = []
    jog = result.get("jog")
    if jog is not None:
        x, y = number(jog["x"]), number(jog["y"])
        lines.append(f"jog X {x} Y {y} {jog['unit']}, packet {jog['packet']}")
    if "firmware_note" in result:
        lines.append(result["firmware_note"])
    if result["position"] is None:
        lines.append(result["position_note"])
    else:
        text = " ".join(f"{v:.2f}" for v in result["position"])
        if result.get("counted"):
            text += " (counted, not measured)"
        elif not result.get("measured", True):
            text += " (commanded, not measured)"
        lines.append(text)
    return "\n".join(lines)


class Reporter:
    """Tells the user about failures and notices: on stderr, and as JSON on stdout with --json."""

    def __init__(self, as_json: bool) -> None:
        self.as_json = as_json
        self.notices: list[str] = []

    def notice(self, text: str) -> None:
        """Something the user should know that is not a failure (e.g. a clamped move)."""
        self.notices.append(text)
        say(text)

    def done(self, result: dict[str, Any]) -> int:
        """Print the result (text, or one JSON object); returns 0."""
        if self.as_json:
            if self.notices:
                result["notices"] = self.notices
            print(json.dumps(result))
        else:
            print(result_text(result))
        return 0

    def fail(self, problem: object, status: int) -> int:
        """Report a failure; returns the exit status."""
        message = plain_error(problem)
        print(PREFIX + message, file=sys.stderr, flush=True)
        if self.as_json:
            print(json.dumps({"error": message, "exit": status}))
        return status
