"""Every word the wrapped panels show goes through Qt's translation: a translator that brackets
every string it is asked for leaves no visible text or tooltip unbracketed. And the sources give
lupdate only literal strings (an f-string inside tr() would be extracted as its template)."""

from __future__ import annotations

import ast
import re
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import Qt, QTranslator
from PySide6.QtWidgets import (
    QAbstractButton,
    QAbstractItemView,
    QApplication,
    QComboBox,
    QGroupBox,
    QLabel,
    QLineEdit,
    QProgressBar,
    QWidget,
)

from app.window.console.traffic_console import RawConsole
from widgets.arc_entry import ArcEntry
from widgets.connection_bar import ConnectionBar
from widgets.coordinate_entry import CoordinateEntry
from widgets.dwell_entry import DwellEntry
from widgets.firmata_panel import FirmataPanel
from widgets.jog_panel import JogPanel
from widgets.macro_editor import MacroEditor
from widgets.macro_panel import MacroPanel
from widgets.parameter_editor import ParameterEditor, ParameterRow
from widgets.piframe_panel import PiFramePanel
from widgets.position_buffer import PositionBuffer
from widgets.position_readout import ESTIMATED, PositionReadout
from widgets.position_view_2d import PositionView2D
from widgets.position_view_3d import PositionView3DPlaceholder
from widgets.program_panel import ProgramPanel
from widgets.send_line import SendLine
from widgets.speed_control import SpeedControl
from widgets.status_line import StatusLine
from widgets.traffic_timeline import TrafficTimeline
from widgets.travel_limits_dialog import TravelLimitsDialog

pytestmark = pytest.mark.timeout(60)

ROOT = Path(__file__).resolve().parents[2]
WRAPPED = [
    "widgets/speed_control.py",
    "widgets/status_line.py",
    "widgets/arc_entry.py",
    "widgets/dwell_entry.py",
    "widgets/firmata_panel.py",
    "widgets/piframe_panel.py",
    "widgets/program_panel.py",
    "widgets/parameter_editor.py",
    "widgets/parameter_table.py",
    "widgets/parameter_values.py",
    "widgets/travel_limits_dialog.py",
    "widgets/send_line.py",
    "widgets/history_line_edit.py",
    "widgets/_buttons.py",
    "widgets/coordinate_entry.py",
    "widgets/_units.py",
    "widgets/position_readout.py",
    "widgets/macro_panel.py",
    "widgets/macro_editor.py",
    "app/window/docks/parameter_dock.py",
    "app/window/docks/device_docks.py",
    "app/window/docks/program_dock.py",
    "app/window/console/log_viewer.py",
    "app/window/device/bridge_session.py",
    "app/window/docks/macro_dock.py",
    "app/window/main_window.py",
    "app/window/device/connection.py",
    "app/window/device/job_desk.py",
    "app/window/device/machine_state.py",
    "app/window/layout/fit_controls.py",
    "app/window/menus.py",
    "app/window/device/worker_link.py",
    "app/window/keyboard_jog.py",
    "app/window/layout/dock_layout.py",
    "app/window/window_tools.py",
    "app/window/docks/work_frame.py",
    "app/window/device/ports.py",
    "app/window/console/feed.py",
    "app/common/session_log.py",
    "widgets/connection_bar.py",
    "widgets/jog_panel.py",
    "widgets/lazy_view.py",
    "widgets/settings_dialog.py",
    "widgets/about_dialog.py",
    "widgets/shortcuts_dialog.py",
    "widgets/control_lines_bar.py",
    "widgets/position_view_2d.py",
    "widgets/view2d/xy_plot.py",
    "widgets/view2d/time_plot.py",
    "widgets/position_view_3d.py",
    "widgets/_gl_scene.py",
    "widgets/view3d/navigation.py",
    "widgets/view3d/notice.py",
    "widgets/_view_common.py",
    "widgets/traffic_timeline.py",
    "widgets/timeline/plots.py",
    "widgets/traffic_format.py",
    "app/window/console/traffic_console.py",
    "app/window/console/display.py",
    "app/window/console/export.py",
    "app/window/console/filter_bar.py",
    "app/window/console/navigation.py",
    "app/window/console/pacing.py",
    "app/window/console/status.py",
    "app/window/console/table.py",
    "app/window/layout/layouts.py",
    "widgets/travel_limits_form.py",
    "widgets/compact_readout.py",
]
OPEN, CLOSE = "⟦", "⟧"
# What is not a word to translate: numbers, units, axis letters, line endings, signs.
NOT_WORDS = re.compile(r"\b(?:mm/s|mm|ms|rpm|LF|CR|µs|s)\b|\\[nr]|[^A-Za-z]")


class Bracketing(QTranslator):
    """Translates every string into ⟦string⟧, so what was not translated shows."""

    def translate(
        self, context: str, source: str, disambiguation: str | None = None, n: int = -1
    ) -> str:
        return f"{OPEN}{source}{CLOSE}" if source else ""

    def isEmpty(self) -> bool:
        return False


@pytest.fixture
def bracketing(qapp: QApplication) -> Iterator[Bracketing]:
    translator = Bracketing()
    qapp.installTranslator(translator)
    yield translator
    qapp.removeTranslator(translator)


def needs_translation(text: str) -> bool:
    """Whether `text` has a word in it (letters once numbers, units and letters X/Y/Z go)."""
    return re.search(r"[A-Za-z]{2,}", NOT_WORDS.sub(" ", text)) is not None


def shown_texts(root: QWidget) -> list[tuple[str, str]]:
    """(where, text) of every text and tooltip a user can see in `root` and its children."""
    found: list[tuple[str, str]] = []

    def add(widget: QWidget, what: str, text: object) -> None:
        if isinstance(text, str) and text:
            found.append((f"{type(widget).__name__}#{widget.objectName()}.{what}", text))

    for widget in [root, *root.findChildren(QWidget)]:
        add(widget, "toolTip", widget.toolTip())
        if widget.isWindow():
            add(widget, "windowTitle", widget.windowTitle())
        if isinstance(widget, QLabel | QAbstractButton):
            add(widget, "text", widget.text())
        if isinstance(widget, QLineEdit):
            add(widget, "placeholderText", widget.placeholderText())
        if isinstance(widget, QGroupBox):
            add(widget, "title", widget.title())
        if isinstance(widget, QProgressBar):
            add(widget, "format", widget.format())
        if isinstance(widget, QComboBox):
            for index in range(widget.count()):
                add(widget, f"item{index}", widget.itemText(index))
                add(
                    widget,
                    f"item{index}.toolTip",
                    widget.itemData(index, Qt.ItemDataRole.ToolTipRole),
                )
        if isinstance(widget, QAbstractItemView) and widget.model() is not None:
            model = widget.model()
            for column in range(model.columnCount()):
                for role in (Qt.ItemDataRole.DisplayRole, Qt.ItemDataRole.ToolTipRole):
                    add(
                        widget,
                        f"header{column}",
                        model.headerData(column, Qt.Orientation.Horizontal, role),
                    )
            for row in range(model.rowCount()):
                for column in range(model.columnCount()):
                    index = model.index(row, column)
                    add(
                        widget,
                        f"cell{row},{column}.toolTip",
                        index.data(Qt.ItemDataRole.ToolTipRole),
                    )
    return found


def untranslated(root: QWidget, allowed: tuple[str, ...] = ()) -> list[tuple[str, str]]:
    """The texts with a word outside every ⟦…⟧, but for the `allowed` ones (data, not words)."""
    left = []
    for where, text in shown_texts(root):
        outside, nested = text, 1
        while nested:  # innermost ⟦…⟧ first: a translated template may hold translated words
            outside, nested = re.subn(f"{OPEN}[^{OPEN}{CLOSE}]*{CLOSE}", " ", outside)
        for data in allowed:
            outside = outside.replace(data, " ")
        if needs_translation(outside):
            left.append((where, text))
    return left


ROWS = [
    ParameterRow(1, "pulley_diameter_x", "mm", 0.0, 99999.9, 0.1, False, "Pulley diameter X"),
    ParameterRow(2, "steps_x", "steps", 1, 65535, 1, True, "Steps per turn X"),
]


def build_panels(qtbot) -> list[tuple[QWidget, tuple[str, ...]]]:
    """The panels, in states that show most of their texts; with the data they show."""
    speed = SpeedControl()
    speed.set_reported(12.0)
    speed.set_note("")
    status = StatusLine()
    status.set_state("moving")
    status.show_message("")
    arc = ArcEntry()
    arc.set_box(((0.0, 5.0), (0.0, 5.0), (0.0, 5.0)))
    firmata = FirmataPanel()
    firmata.set_speed_mm_s(10.0)
    piframe = PiFramePanel()
    program = ProgramPanel()
    program.set_program("path.csv", 12)
    program.show_progress(3, 2, 1, 10.0, 5.0, 0)
    editor = ParameterEditor()
    editor.set_parameters(ROWS)
    editor.set_values({"pulley_diameter_x": 38.2})
    editor.set_status(1, "confirmed")
    editor.set_status(2, "timed out")
    travel = TravelLimitsDialog("sim://coxiris", ((0.0, -1.0), (0.0, 1.0), (0.0, 1.0)), False)
    send = SendLine()
    send.set_mode("hex")
    send.send()  # nothing typed: an error shown
    coordinates = CoordinateEntry()
    coordinates.set_mode("relative")
    readout = PositionReadout()
    readout.set_position(1.0, 2.0, 3.0)
    readout.set_work_zero((1.0, 0.0, 0.0))
    readout.set_measured(False)
    readout.set_status(ESTIMATED)
    macros = MacroPanel()
    macros.set_macros([("Park", ("home", "move 1 2 3"))])
    macro_editor = MacroEditor(lambda name, steps: "", "", "Park", ("home",))
    connection = ConnectionBar()
    connection.set_protocols(["coxiris"])
    connection.set_ports([("sim://coxiris", "simulated coxiris device")])
    connection.set_variants([("v2", "packet format 2")], "v2")
    connection.set_state("error", "")
    jog = JogPanel()
    jog.set_keyboard_state(False, "")
    console = RawConsole()
    console.set_display_mode("hex")
    console.set_time_mode("delta")
    no_gl = PositionView3DPlaceholder("no OpenGL context here")
    panels: list[tuple[QWidget, tuple[str, ...]]] = [
        (speed, ()),
        (status, ()),
        (arc, ()),
        (DwellEntry(), ()),
        (firmata, ()),
        (piframe, ()),
        (program, ("path.csv",)),
        (editor, ("pulley_diameter_x", "steps_x", "Pulley diameter X", "Steps per turn X")),
        (travel, ("sim://coxiris",)),
        (send, ()),
        (coordinates, ()),
        (readout, ()),
        (macros, ("Park", "home", "move")),
        (macro_editor, ("Park", "home", "move", "jog", "wait", "position")),
        (connection, ("sim://coxiris", "simulated coxiris device", "coxiris", "packet format 2")),
        (jog, ()),
        (console, ()),
        (TrafficTimeline(), ()),
        (PositionView2D(PositionBuffer()), ()),
        (no_gl, ("no OpenGL context here",)),
    ]
    for panel, _ in panels:
        qtbot.addWidget(panel)
    return panels


def test_without_a_translator_no_bracket_shows(qtbot) -> None:
    for panel, _ in build_panels(qtbot):
        assert not [t for t in shown_texts(panel) if OPEN in t[1]], type(panel).__name__


def test_every_visible_text_and_tooltip_is_translated(qtbot, bracketing) -> None:
    left = []
    for panel, allowed in build_panels(qtbot):
        assert any(OPEN in text for _, text in shown_texts(panel)), type(panel).__name__
        left += untranslated(panel, allowed)
    assert left == []


def test_logic_does_not_depend_on_the_words_shown(qtbot, bracketing, record) -> None:
    """Combos and labels compared by their shown text would break once translated."""
    send = SendLine()
    qtbot.addWidget(send)
    send.set_mode("hex")
    assert send.mode() == "hex"
    send.set_mode("text")
    send.set_line_ending(b"")
    send.edit.setText("GET_ID")
    assert send.data() == b"GET_ID"
    program = ProgramPanel()
    qtbot.addWidget(program)
    program.set_program("a.csv", 3)
    program.set_running(False)
    assert program.run_button.isEnabled()
    program.set_program("", 0)
    program.set_running(False)
    assert not program.run_button.isEnabled()


def _translate_calls(tree: ast.AST) -> Iterator[ast.Call]:
    names = {"tr", "translate", "QT_TRANSLATE_NOOP", "QT_TR_NOOP"}
    for node in ast.walk(tree):
        if isinstance(node, ast.Call):
            func = node.func
            name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
            if name in names:
                yield node


@pytest.mark.parametrize("path", WRAPPED)
def test_translated_strings_are_literals(path: str) -> None:
    """tr("…"), translate("Context", "…"), QT_TRANSLATE_NOOP("Context", "…"): literal text (or
    a name holding a marked constant), never an f-string, a concatenation or a .format()."""
    tree = ast.parse((ROOT / path).read_text(encoding="utf-8"))
    for call in _translate_calls(tree):
        for arg in call.args[:3]:
            where = f"{path}:{call.lineno}"
            assert not isinstance(arg, ast.JoinedStr), f"f-string in a translation at {where}"
            assert not isinstance(arg, ast.BinOp), f"an expression in a translation at {where}"
            assert not isinstance(arg, ast.Call), f"a call in a translation at {where}"
        func = call.func
        if isinstance(func, ast.Attribute) and func.attr == "translate" and call.args:
            context = call.args[0]
            literal = isinstance(context, ast.Constant) and isinstance(context.value, str)
            assert literal, f"{path}:{call.lineno}: the context must be a literal for lupdate"


def test_lupdate_reads_the_wrapped_files_without_warnings(tmp_path) -> None:
    lupdate = Path(sys.executable).parent / "pyside6-lupdate"
    if not lupdate.exists():
        pytest.skip("pyside6-lupdate is not installed beside this Python")
    ts = tmp_path / "check.ts"
    done = subprocess.run(
        [str(lupdate), *WRAPPED, "-ts", str(ts)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=50,
        check=False,
    )
    assert done.returncode == 0, done.stderr
    output = done.stdout + done.stderr
    assert "warning" not in output.lower(), output
    sources = re.findall(r"<source>(.*?)</source>", ts.read_text(encoding="utf-8"), re.DOTALL)
    assert len(sources) > 250
    assert not [s for s in sources if re.search(r"\{[A-Za-z_][\w.]*(?:[!:][^}]*)?\}", s)]
    contexts = set(re.findall(r"<name>(.*?)</name>", ts.read_text(encoding="utf-8")))
    assert not [c for c in contexts if "." in c or c == "QCoreApplication"], contexts


def _source(call: ast.Call) -> str | None:
    """The literal source text of a translation call (None: a name, translated at use)."""
    func = call.func
    name = func.attr if isinstance(func, ast.Attribute) else getattr(func, "id", "")
    position = 0 if name in ("tr", "QT_TR_NOOP") else 1
    if len(call.args) > position:
        arg = call.args[position]
        if isinstance(arg, ast.Constant) and isinstance(arg.value, str):
            return arg.value
    return None


def test_the_shipped_catalogs_have_every_wrapped_string() -> None:
    """resources/i18n/update.py was run after the strings last changed (translators see them)."""
    shipped = (ROOT / "resources" / "i18n" / "motionpanel_es.ts").read_text(encoding="utf-8")
    missing = []
    for path in WRAPPED:
        tree = ast.parse((ROOT / path).read_text(encoding="utf-8"))
        for call in _translate_calls(tree):
            source = _source(call)
            if source:
                escaped = (
                    source.replace("&", "&amp;")
                    .replace("<", "&lt;")
                    .replace(">", "&gt;")
                    .replace("'", "&apos;")
                    .replace('"', "&quot;")
                )
                if f"<source>{escaped}</source>" not in shipped:
                    missing.append(f"{path}:{call.lineno}: {source!r}")
    assert missing == [], "run resources/i18n/update.py"
