"""Small widget helpers shared by the panels."""

from __future__ import annotations

from PySide6.QtWidgets import QPushButton


def make_button(text: str, name: str, tip: str) -> QPushButton:
    """A push button with its objectName and tooltip."""
    button = QPushButton(text)
    button.setObjectName(name)
    button.setToolTip(tip)
    return button


def overlay_button_style(light_background: bool) -> str:
    """The style of flat buttons drawn over a view (the 3D view's presets): dark text on a
    light chip over a light background, light text over a dark one; both with a border, so
    that an enabled button never looks disabled. The box is the size of a 2 px by 6 px padding
    without a border."""
    if light_background:
        text, chip, edge, hover = "#1e1e1e", "rgba(255, 255, 255, 210)", "#8a8a8a", "#dde9f7"
        checked, checked_text = "rgba(255, 179, 0, 200)", "#1e1e1e"
    else:
        text, chip, edge = "#f0f0f0", "rgba(255, 255, 255, 36)", "rgba(255, 255, 255, 90)"
        hover, checked, checked_text = "rgba(255, 255, 255, 80)", "rgba(255, 179, 0, 130)", "white"
    return (
        f"QToolButton {{ color: {text}; background: {chip}; border: 1px solid {edge};"
        " border-radius: 3px; padding: 1px 5px; }"
        f" QToolButton:hover {{ background: {hover}; }}"
        f" QToolButton:checked {{ background: {checked}; color: {checked_text}; }}"
    )
