"""How the traffic console's table shows its lines: bytes as text, hex or mixed; times since
the start, wall-clock or as gaps; the time column shown or not. The strings are in the
console's translation context (RawConsole)."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QObject
from PySide6.QtWidgets import QCheckBox, QComboBox, QWidget

from app.window.console.table import DISPLAY_MODES, TIME, TIME_MODES, TrafficModel, TrafficView

# the names shown for the keys (marked here, translated at use); the keys stay as they are
MODE_NAMES = {
    "text": QT_TRANSLATE_NOOP("RawConsole", "text"),
    "hex": QT_TRANSLATE_NOOP("RawConsole", "hex"),
    "mixed": QT_TRANSLATE_NOOP("RawConsole", "mixed"),
    "relative": QT_TRANSLATE_NOOP("RawConsole", "relative"),
    "absolute": QT_TRANSLATE_NOOP("RawConsole", "absolute"),
    "delta": QT_TRANSLATE_NOOP("RawConsole", "delta"),
}


def _combo(name: str, items: tuple[str, ...], tip: str, slot: Callable) -> QComboBox:
    combo = QComboBox()
    combo.setObjectName(name)
    for key in items:  # the key as item data: the shown name may be translated
        shown = MODE_NAMES.get(key, key)
        combo.addItem(QCoreApplication.translate("RawConsole", shown), key)
    combo.setToolTip(tip)
    combo.currentIndexChanged.connect(lambda index: slot(combo.itemData(index)))
    return combo


class DisplayOptions(QObject):
    """The display's widgets (`mode_combo`, `time_combo`, `timestamps_check`, laid out by the
    console, `parent`) and what they set on the table (`view` showing `model`)."""

    def __init__(self, parent: QWidget, view: TrafficView, model: TrafficModel) -> None:
        super().__init__(parent)
        self.view = view
        self.model = model
        self.mode_combo = _combo(
            "consoleDisplayMode",
            DISPLAY_MODES,
            QCoreApplication.translate(
                "RawConsole",
                "Bytes as text (\\r \\n \\xNN escapes), hex (47 45 54), or mixed (text, <0A> for "
                "the rest)",
            ),
            self.set_display_mode,
        )
        self.time_combo = _combo(
            "consoleTimeMode",
            TIME_MODES,
            QCoreApplication.translate(
                "RawConsole",
                "Times: seconds since the session start, wall-clock time, or the gap since the"
                " line above",
            ),
            self.set_time_mode,
        )
        self.timestamps_check = QCheckBox(QCoreApplication.translate("RawConsole", "Time"))
        self.timestamps_check.setObjectName("consoleTimestamps")
        self.timestamps_check.setChecked(True)
        self.timestamps_check.setToolTip(
            QCoreApplication.translate("RawConsole", "Show the time column")
        )
        self.timestamps_check.toggled.connect(self.set_timestamps)

    def set_display_mode(self, mode: str) -> None:
        """Show bytes as escaped text, hex, or mixed."""
        if mode not in DISPLAY_MODES:
            raise ValueError(f"display mode must be one of {DISPLAY_MODES}, not {mode!r}")
        if mode != self.model.mode:
            self.model.mode = mode
            self.mode_combo.setCurrentIndex(self.mode_combo.findData(mode))
            self.model.refresh()

    def set_time_mode(self, mode: str) -> None:
        """Show times since the session start, as wall-clock times, or as gaps."""
        if mode not in TIME_MODES:
            raise ValueError(f"time mode must be one of {TIME_MODES}, not {mode!r}")
        if mode != self.model.time_mode:
            self.model.time_mode = mode
            self.time_combo.setCurrentIndex(self.time_combo.findData(mode))
            self.model.refresh()

    def timestamps(self) -> bool:
        """Whether the time column is shown."""
        return not self.view.isColumnHidden(TIME)

    def set_timestamps(self, shown: bool) -> None:
        """Show or hide the time column."""
        self.view.setColumnHidden(TIME, not shown)
        self.timestamps_check.setChecked(shown)
