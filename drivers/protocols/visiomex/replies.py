"""Visiomex replies (drivers/protocols/README.md §2): what the firmware's `FS`/`FP`/`FA` feedback
and `EP`/`EF` error codes mean, and the exchange that follows one packet's reply to its end."""

from __future__ import annotations

import re

from drivers.errors import DeviceError, GarbledReply
from drivers.messages import Message
from drivers.protocols.base import Exchange
from drivers.protocols.commands import Command
from drivers.protocols.events import ErrorReport, Event, Feedback, TextLine
from drivers.protocols.visiomex.model import SILENCE
from drivers.protocols.visiomex.params import BY_ID

REPLY_MARGIN = 0.5  # s beyond the silence window before a reply counts as missing
# What the codes mean (the protocol's documents), made once: decoding a line builds no text.
FEEDBACK = {
    "FP0001": Message("move package confirmed"),
    "FA0001": Message("action accomplished"),
}
ERRORS = {
    "EP0001": Message("package size mismatch"),
    "EP0002": Message("invalid command type"),
    "EP0003": Message("invalid motion type"),
    "EP0004": Message("invalid direction for the X axis"),
    "EP0005": Message("invalid direction for the Y axis"),
    "EP0006": Message("invalid set parameter ID"),
    "EF0001": Message("parse function error in the firmware"),
    "EF0002": Message("invalid driving mechanism"),
}
UNLISTED_ERROR = Message("an error code the documentation does not list")
SET_MEANINGS = {
    number: Message("{parameter} set", parameter=parameter.name)
    for number, parameter in BY_ID.items()
} | {28: Message("{parameter} set", parameter="driving_mechanism_y")}  # the firmware's FS0028
CODE = re.compile(r"(?:FS|FP|FA|EP|EF)\d{4}")


def code_meaning(code: str) -> str:
    """What a feedback code means."""
    if code in FEEDBACK:
        return FEEDBACK[code]
    if code.startswith("FS"):
        number = int(code[2:])
        return SET_MEANINGS.get(number) or Message("parameter {number} set", number=number)
    return Message("feedback code {code} is not documented", code=code)


class VisiomexExchange(Exchange):
    """A set waits for its `FSnnnn`; a move takes the debug lines and `FP0001`, ends at `FA0001`.

    Any `EP`/`EF` code fails the exchange at once with the firmware's message.
    """

    timeout = SILENCE + REPLY_MARGIN

    def __init__(self, command: Command, what: str, expect: str | None, extra: float = 0.0):
        super().__init__(command)
        self.what = what
        self.expect = expect  # None: a move (FP0001, then FA0001); "": any FS code
        self.extra = extra
        self.confirmed = False

    def handle(self, event: Event) -> bool:
        """Track one event of the reply."""
        if isinstance(event, ErrorReport) and event.code:
            if self.expect is None and event.code == "EP0003":
                message = Message(
                    "{command}: the device answered {code} ({meaning}); this firmware revision "
                    "runs the move anyway",
                    command=self.what,
                    code=event.code,
                    meaning=event.message,
                )
            else:
                message = Message(
                    "{command}: the device answered {code} ({meaning})",
                    command=self.what,
                    code=event.code,
                    meaning=event.message,
                )
            self.fail(DeviceError(message))
            return True
        if isinstance(event, Feedback):
            if self.expect is None and event.code == "FP0001":
                self.confirmed = True
            elif self._ends(event.code):
                self.finish(event)
            else:
                wanted = self.expect or "FP0001/FA0001"
                self.fail(
                    GarbledReply(
                        Message(
                            "{command}: expected {wanted}, got {code}",
                            command=self.what,
                            wanted=wanted,
                            code=event.code,
                        )
                    )
                )
            return True
        if isinstance(event, TextLine) and self.expect is None:
            self.notes.append(event.text)  # the firmware's debug lines before FP0001
            return True
        return False

    def _ends(self, code: str) -> bool:
        if self.expect is None:
            return code == "FA0001"
        return code == self.expect or (not self.expect and code.startswith("FS"))
