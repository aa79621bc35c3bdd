"""The macro panel (a button per macro, New, Edit, Import, Export) and the macro editor (steps
checked as they are typed; OK only when the device would take every step)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDialogButtonBox

from widgets.macro_editor import MacroEditor, steps_of
from widgets.macro_panel import MacroPanel

pytestmark = pytest.mark.timeout(30)
LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def panel(qtbot) -> MacroPanel:
    widget = MacroPanel()
    qtbot.addWidget(widget)
    widget.show()
    return widget


def test_a_button_per_macro_runs_it_when_runnable(qtbot, panel: MacroPanel) -> None:
    assert panel.empty.isVisible()
    assert not panel.edit_button.isEnabled() and not panel.export_button.isEnabled()
    panel.set_macros([("probe", ("home", "jog 0 0 -2")), ("park", ("move 0 0 5",))])
    assert not panel.empty.isVisible()
    assert list(panel.buttons) == ["probe", "park"]
    assert "jog 0 0 -2" in panel.buttons["probe"].toolTip()
    ran: list[str] = []
    panel.run_requested.connect(ran.append)
    qtbot.mouseClick(panel.buttons["probe"], LEFT)  # not runnable yet: disabled
    panel.set_runnable(True)
    qtbot.mouseClick(panel.buttons["park"], LEFT)
    assert ran == ["park"]
    panel.set_macros([("probe", ("home",))])
    assert list(panel.buttons) == ["probe"] and panel.buttons["probe"].isEnabled()


def test_edit_menu_new_import_export(qtbot, panel: MacroPanel) -> None:
    panel.set_macros([("probe", ("home",))])
    asked: list[str] = []
    panel.edit_requested.connect(lambda name: asked.append(f"edit {name}"))
    panel.new_requested.connect(lambda: asked.append("new"))
    panel.import_requested.connect(lambda: asked.append("import"))
    panel.export_requested.connect(lambda: asked.append("export"))
    panel.edit_menu.actions()[0].trigger()
    for button in (panel.new_button, panel.import_button, panel.export_button):
        qtbot.mouseClick(button, LEFT)
    assert asked == ["edit probe", "new", "import", "export"]


def test_steps_are_lines_without_blanks() -> None:
    assert steps_of(" home \n\n  move 1 2 \n") == ("home", "move 1 2")


def test_the_editor_checks_as_typed_and_keeps_only_a_good_macro(qtbot) -> None:
    def check(name: str, steps: tuple[str, ...]) -> str:
        if not name:
            return "a macro needs a name"
        bad = [s for s in steps if s.split()[0] not in ("home", "move")]
        return f"unknown command {bad[0]!r}" if bad else ("" if steps else "no steps")

    editor = MacroEditor(check, "home · move X Y Z")
    qtbot.addWidget(editor)
    editor.show()
    ok = editor.buttons.button(QDialogButtonBox.StandardButton.Ok)
    kept: list[tuple[str, tuple[str, ...]]] = []
    editor.accepted_macro.connect(lambda name, steps: kept.append((name, steps)))
    assert not ok.isEnabled() and editor.problem.text() == "a macro needs a name"
    assert editor.delete_button is None  # a new macro has nothing to delete
    qtbot.keyClicks(editor.name_edit, "probe")
    editor.steps_edit.setPlainText("home\nfly 3")
    assert not ok.isEnabled() and editor.problem.text() == "unknown command 'fly 3'"
    editor.steps_edit.setPlainText("home\nmove 0 0 -2")
    assert ok.isEnabled() and editor.problem.text() == ""
    qtbot.mouseClick(ok, LEFT)
    assert kept == [("probe", ("home", "move 0 0 -2"))]
    assert not editor.isVisible()


def test_an_existing_macro_can_be_deleted(qtbot) -> None:
    editor = MacroEditor(lambda n, s: "", "", "probe", ("home",))
    qtbot.addWidget(editor)
    editor.show()
    deleted: list[str] = []
    editor.delete_requested.connect(deleted.append)
    assert editor.name_edit.text() == "probe" and editor.steps() == ("home",)
    assert editor.delete_button is not None
    qtbot.mouseClick(editor.delete_button, LEFT)
    assert deleted == ["probe"]
