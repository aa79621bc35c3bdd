"""The driver layer's messages in the interface's language (drivers/messages.py makes them)."""

from __future__ import annotations

import logging

from PySide6.QtCore import QCoreApplication

from drivers.messages import CONTEXT, Message, fill, message_of

log = logging.getLogger(__name__)


def localized(value: object) -> str:
    """`value` for the operator: a Message (or an error raised with one) translated with its
    values translated too; anything else as str() gives it. Safe from any thread."""
    said = message_of(value)
    if said is None:
        return str(value)
    template = QCoreApplication.translate(CONTEXT, said.template)
    if template == said.template and not said.values:
        return str(said)
    values = {name: _value(item) for name, item in said.values.items()}
    try:
        return fill(template, values)
    except (KeyError, IndexError, ValueError):
        log.warning("a translation of %r does not fit its values; shown in English", said.template)
        return fill(said.template, values)


def _value(item: object) -> object:
    """A value of a message: translated when it is itself a message or an error; else as is."""
    if isinstance(item, (Message, BaseException)):
        return localized(item)
    return item
