"""The window's controls fitted to what the connected device can do."""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.common.messages import localized
from widgets._i18n import fill

if TYPE_CHECKING:
    from app.window.services import WindowParts
    from drivers.protocols.capabilities import Capabilities

translate = QCoreApplication.translate  # the strings keep the window's context, "MainWindow"
# Marked here, translated at use (context "MainWindow"); %1: the device's protocol.
NO_STOP_TIP = QT_TRANSLATE_NOOP(
    "MainWindow",
    "%1 has no stop command: this drops the commands not yet sent; "
    "a move already under way on the device finishes (Esc)",
)
STOP_TIP = QT_TRANSLATE_NOOP(
    "MainWindow", "Stop the stage now: halts the move under way and drops what is queued (Esc)"
)


def fit_controls(window: WindowParts, caps: Capabilities, protocol: str | None) -> None:
    """Fit the controls to what the device can do (on connection, and after new settings);
    `protocol`: the device's (None: not known)."""
    name = protocol.upper() if protocol is not None else translate("MainWindow", "the device")
    jog, coordinates, readout, speed = (
        window.jog_panel,
        window.coordinates,
        window.readout,
        window.speed,
    )
    for widget in (jog, coordinates, readout):
        widget.set_axes_enabled(caps.axes)
    readout.set_measured(caps.position_feedback)
    speed.set_note(localized(caps.speed_note))
    speed.set_decimals(caps.speed_decimals)
    coordinates.set_home_tips(
        localized(caps.home_note)
        if caps.home_note
        else translate("MainWindow", "Go to the home position (0, 0, 0)"),
        translate("MainWindow", "Make the current position the origin (asks first)")
        if caps.set_home or caps.position_feedback
        else fill(
            translate(
                "MainWindow",
                "Restart the panel's count of the position here (asks first); %1 has no "
                "set-home command, so nothing is sent",
            ),
            name,
        ),
    )
    console = window.console
    console.set_line_ending(caps.raw_line_end.encode("ascii"))
    mode = "text" if caps.raw_text else "hex"  # a binary protocol's bytes read as hex
    console.set_display_mode(mode)
    console.set_send_mode(mode)
    for widget in (jog, coordinates, readout):
        widget.set_resolution(caps.resolution)
    tip = (
        translate("MainWindow", STOP_TIP)
        if caps.stop
        else fill(translate("MainWindow", NO_STOP_TIP), name)
    )
    coordinates.set_stop_mode(caps.stop, tip)
    window.stop_action.setText(
        translate("MainWindow", "&Stop")
        if caps.stop
        else translate("MainWindow", "&Drop queued commands")
    )
    window.stop_action.setToolTip(tip)
    speed.setEnabled(caps.speed)
    if caps.speed_range is not None:
        speed.set_range(*caps.speed_range)
