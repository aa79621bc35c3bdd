"""Small things an operator reads: whole Settings tabs in Spanish, the locale's decimal mark on the
jog presets, hex bytes cut between bytes with "…", the 3D view's buttons readable in the light
theme, "1 error", a failure said once, a relative Go to that is no "jog", Export confirmed, and
a log viewer closed without a window manager."""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QLocale, QPoint, Qt
from PySide6.QtGui import QColor, QImage, QKeySequence, QPainter, QRegion
from PySide6.QtWidgets import QApplication, QPushButton, QToolButton, QWidget

from app.common import i18n
from app.common.settings import write_travel
from app.window.console.export import exported_text
from app.window.console.log_viewer import LogViewer
from app.window.console.status import ConsoleStatus, StatusFigures
from app.window.console.table import (
    BYTES,
    HEX,
    MIXED,
    TEXT,
    TrafficView,
    byte_units,
    elide_bytes,
)
from app.window.console.traffic_console import RawConsole
from app.window.device import jobs
from app.window.device.worker import failure_text
from app.window.main_window import MainWindow
from app.window.preferences import Preferences
from app.window.theme import DARK_PLOT_COLORS, LIGHT_PLOT_COLORS, apply_gl_colors
from drivers.device.travel import TravelLimits
from drivers.errors import BadInput
from drivers.messages import Message
from drivers.protocols.registry import create_protocol
from widgets.jog_panel import JogPanel
from widgets.position_buffer import PositionBuffer
from widgets.settings_dialog import SettingsDialog

pytestmark = pytest.mark.timeout(60)

SIM = "sim://coxiris?speed=100"
BOX = ((-5.0, 5.0), (-5.0, 5.0), (0.0, 2.0))
SHOTS = Path(os.environ.get("COSMETICS_SHOTS", "/tmp/issue22_cosmetics"))
NO_DISPLAY = "DISPLAY" not in os.environ or os.environ.get("QT_QPA_PLATFORM") == "offscreen"


@pytest.fixture
def spanish(qapp: QApplication, monkeypatch: pytest.MonkeyPatch) -> Iterator[QApplication]:
    """The interface in Spanish (our catalog, Qt's, and Spanish numbers) while the test runs."""
    monkeypatch.delenv(i18n.ENV_VAR, raising=False)
    assert i18n.install_translations(qapp, "es") == "es"
    yield qapp
    i18n.remove_translations(qapp)


def _shot(widget: QWidget, name: str) -> None:
    SHOTS.mkdir(parents=True, exist_ok=True)
    assert widget.grab().save(str(SHOTS / f"{name}.png"))


def _connect(qtbot, win: MainWindow) -> None:
    with qtbot.waitSignal(win.settled, timeout=5000):
        win.connect_device(SIM, "coxiris", 115200)


# -- 1. the Settings tabs ----------------------------------------------------------------------


def test_settings_tabs_show_their_whole_titles_in_spanish(qtbot, spanish) -> None:
    dialog = SettingsDialog(Preferences())
    qtbot.addWidget(dialog)
    dialog.show()
    qtbot.waitExposed(dialog)
    bar = dialog.tabs.tabBar()
    titles = [dialog.tabs.tabText(i) for i in range(dialog.tabs.count())]
    assert "Apariencia && idioma" in titles  # the Spanish titles, not the English
    for index, title in enumerate(titles):
        shown, whole = bar.tabRect(index), bar.tabSizeHint(index)
        assert shown.width() >= whole.width(), title  # not elided
        assert shown.right() < bar.width(), title  # not scrolled out of sight
        text = bar.fontMetrics().horizontalAdvance(title.replace("&&", "&"))
        assert shown.width() > text, title
    assert dialog.width() <= 1024  # still fits a small laptop
    _shot(dialog, "settings_es")


# -- 2. the jog presets ------------------------------------------------------------------------


def test_jog_presets_use_the_locales_decimal_mark(qtbot, spanish) -> None:
    assert QLocale().decimalPoint() == ","
    panel = JogPanel()
    qtbot.addWidget(panel)
    texts = [panel.preset_buttons[v].text() for v in (0.01, 0.1, 1.0, 10.0, 100.0)]
    assert texts == ["0,01 mm", "0,1 mm", "1 mm", "10 mm", "100 mm"]
    assert "0,01 mm" in panel.preset_buttons[0.01].toolTip()
    assert panel.inch_preset_buttons[0.001].text() == "0,001 in"


def test_jog_presets_in_english_keep_the_point(qtbot) -> None:
    panel = JogPanel()
    qtbot.addWidget(panel)
    assert panel.preset_buttons[0.01].text() == "0.01 mm"
    assert panel.preset_buttons[100.0].text() == "100 mm"
    assert panel.findChild(QPushButton, "jogStep0_01") is panel.preset_buttons[0.01]


# -- 3. hex bytes cut between bytes ------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "mode", "room", "expected"),
    [
        ("41 42 43 44", HEX, 11, "41 42 43 44"),  # fits: as it is
        ("41 42 43 44", HEX, 10, "41 42 43 …"),
        ("41 42 43 44", HEX, 8, "41 42 …"),
        ("41 42 43 44", HEX, 4, "41 …"),
        ("41 42 43 44", HEX, 3, "…"),
        ("41 42 43 44…", HEX, 9, "41 42 …"),  # the cell's own "…" of bytes not shown
        ("A<00>B<0A>", MIXED, 7, "A<00>B…"),
        ("A<00>B<0A>", MIXED, 5, "A…"),  # not "A<00"
        ("GET\\x00\\n", TEXT, 7, "GET…"),  # not "GET\\x0"
        ("GET\\x00\\n", TEXT, 8, "GET\\x00…"),
    ],
)
def test_elided_bytes_end_between_two_bytes(text, mode, room, expected) -> None:
    got = elide_bytes(text, mode, room)
    assert got == expected
    assert len(got) <= room


def test_byte_units_are_whole_bytes() -> None:
    assert byte_units("41 42 0A", HEX) == ["41 ", "42 ", "0A"]
    assert byte_units("A<00>\\", MIXED) == ["A", "<00>", "\\"]
    assert byte_units("a\\r\\x7F\\\\", TEXT) == ["a", "\\r", "\\x7F", "\\\\"]


def test_the_console_paints_hex_cut_between_bytes_with_an_ellipsis(qtbot, monkeypatch) -> None:
    console = RawConsole()
    qtbot.addWidget(console)
    console.set_time_origin(0.0)
    console.set_protocol(create_protocol("coxiris"))
    console.resize(900, 300)
    console.show()
    qtbot.waitExposed(console)
    data = bytes(range(0x30, 0x30 + 40)) + b"\n"
    console.append_traffic("tx", data, 1.0)
    console.flush()
    console.set_display_mode("hex")
    view = console.view
    view.setColumnWidth(BYTES, 200)
    painted: list[str] = []
    original = TrafficView.fit_bytes

    def recording(self, *args, **kwargs) -> str:
        painted.append(original(self, *args, **kwargs))
        return painted[-1]

    monkeypatch.setattr(TrafficView, "fit_bytes", recording)
    view.viewport().grab()  # painted now, by the view's own paintEvent
    assert painted, "the bytes column was not painted through fit_bytes"
    shown = painted[0]
    assert shown.endswith("…")
    assert re.fullmatch(r"(?:[0-9A-F]{2} )+…", shown), shown
    assert view.fontMetrics().horizontalAdvance(shown) <= 200
    tip = view.model().data(view.model().index(0, BYTES), Qt.ItemDataRole.ToolTipRole)
    assert data.hex(" ").upper() in tip  # the tooltip has every byte
    _shot(console, "console_hex_elided")


# -- 4. the 3D view's buttons in the light theme ------------------------------------------------


def _luminance(colour: QColor) -> float:
    def channel(c: float) -> float:
        return c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4

    return (
        0.2126 * channel(colour.redF())
        + 0.7152 * channel(colour.greenF())
        + (0.0722 * channel(colour.blueF()))
    )


def _contrast_over(button: QToolButton, background: str) -> float:
    """The contrast ratio between the button's text and what is around it, drawn over
    `background` (the scene's colour under the button)."""
    image = QImage(button.size(), QImage.Format.Format_ARGB32)
    image.fill(QColor(background))
    painter = QPainter(image)
    button.render(painter, QPoint(), QRegion(), QWidget.RenderFlag.DrawChildren)
    painter.end()
    levels = [
        _luminance(image.pixelColor(x, y))
        for x in range(image.width())
        for y in range(image.height())
    ]
    return (max(levels) + 0.05) / (min(levels) + 0.05)


@pytest.mark.gl
@pytest.mark.skipif(NO_DISPLAY, reason="needs a display with OpenGL (run under xvfb-run)")
def test_the_3d_views_buttons_read_as_enabled_in_both_themes(qtbot) -> None:
    from widgets.position_view_3d import PositionView3D, make_position_view_3d

    buffer = PositionBuffer(capacity=10)
    buffer.append(0.0, 1.0, 2.0, 0.5)
    view = make_position_view_3d(buffer)
    qtbot.addWidget(view)
    assert isinstance(view, PositionView3D), getattr(view, "reason", "")
    view.resize(480, 320)
    view.show()
    qtbot.waitExposed(view)
    buttons = view.findChildren(QToolButton)
    assert len(buttons) >= 5
    for colors in (LIGHT_PLOT_COLORS, DARK_PLOT_COLORS):
        apply_gl_colors(view.scene, colors)
        view.render_scene()
        for button in buttons:
            assert button.isEnabled()
            ratio = _contrast_over(button, colors.background)
            assert ratio >= 4.5, (button.objectName(), colors.background, ratio)
        view.update()
        _shot(view, f"view3d_{'dark' if colors.dark else 'light'}")


# -- 5. "1 error" ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("count", "expected"),
    [(0, "0 lines"), (1, "1 line"), (2, "2 lines")],
)
def test_the_console_status_says_one_line_one_error_one_match(qtbot, count, expected) -> None:
    parent = QWidget()
    qtbot.addWidget(parent)
    figures = StatusFigures(count, count, 0, 0, count, count, 0)
    status = ConsoleStatus(parent, lambda: figures)
    status.refresh()
    parts = status.label.text().split(" · ")
    assert parts[0] == expected
    if count:
        noun = "error" if count == 1 else "errors"
        match = "match" if count == 1 else "matches"
        assert f"{count} {noun}" in parts and f"{count} {match}" in parts
    assert "1 errors" not in status.label.text() and "1 matches" not in status.label.text()


# -- 6 and 7. a failure said once; a relative Go to is a "relative move" -----------------------


def test_a_relative_go_to_is_no_jog() -> None:
    assert jobs.MoveByJob(1.0, 0.0, 0.0).describe() == "jog by (1, 0, 0) mm"
    assert jobs.MoveByJob(1.0, 0.0, 0.0, jog=False).describe() == "relative move by (1, 0, 0) mm"


def test_a_failure_that_names_its_move_names_it_as_the_job() -> None:
    job = jobs.MoveByJob(10.0, 0.0, 0.0)
    what = Message("jog by ({dx:g}, {dy:g}, {dz:g}) {unit}", dx=10.0, dy=0.0, dz=0.0, unit="mm")
    error = BadInput(Message("{what} refused: {details} (travel limits)", what=what, details="x"))
    assert failure_text(job, error) == "jog by (10, 0, 0) mm refused: x (travel limits)"
    plain = BadInput(Message("the device says no"))
    assert failure_text(job, plain) == "the device says no"


def test_a_refused_jog_and_go_to_are_said_once(qtbot, window: MainWindow) -> None:
    write_travel(window.settings, "coxiris", SIM, TravelLimits(BOX))
    _connect(qtbot, window)
    window.jog_panel.jog_requested.emit("x", 10.0)
    qtbot.waitUntil(lambda: "refused" in window.status_line.message(), timeout=5000)
    said = window.status_line.message()
    assert said.count("jog by (10, 0, 0) mm") == 1, said
    assert "failed" not in said, said
    assert "travel limits" in said

    window.coordinates.go_requested.emit("relative", (0.0, 20.0, 0.0))
    qtbot.waitUntil(lambda: "(0, 20, 0)" in window.status_line.message(), timeout=5000)
    said = window.status_line.message()
    assert said.count("relative move by (0, 20, 0) mm") == 1, said
    assert "jog" not in said and "failed" not in said, said


def test_a_clamped_relative_go_to_is_called_a_relative_move(qtbot, window: MainWindow) -> None:
    write_travel(window.settings, "coxiris", SIM, TravelLimits(BOX, clamp=True))
    _connect(qtbot, window)
    window.coordinates.go_requested.emit("relative", (10.0, 0.0, 0.0))
    clamped = "clamped to the travel limits"
    qtbot.waitUntil(lambda: clamped in window.console.text(), timeout=5000)
    notes = [line for line in window.console.text().splitlines() if clamped in line]
    assert any("relative move by (10, 0, 0) mm clamped" in line for line in notes), notes
    assert not any("jog" in line for line in notes), notes


# -- 8. Export confirmed -----------------------------------------------------------------------


def test_exported_text_counts_lines() -> None:
    assert exported_text(1, "/tmp/a.txt") == "exported 1 line to /tmp/a.txt"
    assert exported_text(12, "/tmp/a.txt") == "exported 12 lines to /tmp/a.txt"


def test_export_is_confirmed_on_the_status_line(qtbot, window: MainWindow, tmp_path) -> None:
    _connect(qtbot, window)
    target = tmp_path / "traffic.txt"
    window.console.ask_export_path = lambda: str(target)
    window.console.export_interactively()
    count = len(target.read_text().splitlines())
    assert count > 0
    assert window.status_line.message() == f"exported {count} lines to {target}"
    assert window.status_line.message_kind() == "info"

    window.console.ask_export_path = lambda: str(tmp_path / "missing" / "traffic.txt")
    window.console.export_interactively()
    assert window.status_line.message().startswith("export failed: ")
    assert window.status_line.message_kind() == "error"
    assert not window.console.error_label.isHidden()  # shown in the console too


# -- 9. the log viewer closed without a window manager ------------------------------------------


@pytest.fixture
def viewer(qtbot) -> LogViewer:
    window = LogViewer(None, "coxiris")
    qtbot.addWidget(window)
    window.show()
    window.activateWindow()
    qtbot.waitActive(window)
    return window


def test_the_log_viewer_has_a_close_button(qtbot, viewer: LogViewer) -> None:
    button = viewer.findChild(QPushButton, "logViewerClose")
    assert button is not None and button.isVisible() and button.toolTip()
    _shot(viewer, "log_viewer")
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not viewer.isVisible(), timeout=2000)


@pytest.mark.parametrize(
    ("key", "modifier"),
    [(Qt.Key.Key_W, Qt.KeyboardModifier.ControlModifier), (Qt.Key.Key_Escape, None)],
)
def test_ctrl_w_and_escape_close_the_log_viewer(qtbot, viewer: LogViewer, key, modifier) -> None:
    keys = {s.key() for s in viewer.close_shortcuts}
    assert QKeySequence("Ctrl+W") in keys and QKeySequence("Esc") in keys
    viewer.console.view.setFocus()
    qtbot.waitUntil(lambda: QApplication.focusWidget() is viewer.console.view, timeout=2000)
    target = QApplication.focusWidget()
    if modifier is None:
        qtbot.keyClick(target, key)
    else:
        qtbot.keyClick(target, key, modifier)
    qtbot.waitUntil(lambda: not viewer.isVisible(), timeout=2000)
