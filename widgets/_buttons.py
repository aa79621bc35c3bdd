"""Small widget helpers shared by the panels."""

from __future__ import annotations

from PySide6.QtWidgets import QPushButton


def make_button(text: str, name: str, tip: str) -> QPushButton:
    """A push button with its objectName and tooltip."""
    button = QPushButton(text)
    button.setObjectName(name)
    button.setToolTip(tip)
    return button
