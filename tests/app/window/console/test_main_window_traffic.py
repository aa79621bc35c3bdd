"""The window's traffic tools: decoded console, timeline, File → Open log of the session log."""

from __future__ import annotations

import pytest

from app.window.main_window import MainWindow

pytestmark = pytest.mark.timeout(60)


def _connect(qtbot, win: MainWindow) -> None:
    with qtbot.waitSignal(win.settled, timeout=5000):
        win.connect_device("sim://coxiris?speed=100", "coxiris", 115200)


def test_the_console_decodes_and_the_timeline_follows(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    console = window.console
    qtbot.waitUntil(lambda: console.index.counts["poll"] >= 2, timeout=10_000)
    console.flush()
    assert "poll hidden" in console.status_text()
    assert not any("GET_POSITION" in line for line in console.text().splitlines())
    get_id = next(n for n in range(len(console.index)) if console.index.line(n).meaning == "GET_ID")
    assert console.index.line(get_id).pair > get_id  # its reply is paired
    timeline = window.timeline
    qtbot.waitUntil(lambda: len(timeline.latency_points()[0]) >= 2, timeout=5000)
    assert timeline.bytes_per_second("tx").sum() > 0
    window.timeline_dock.raise_()
    poll = next(n for n in range(len(console.index)) if console.index.line(n).kind == "poll")
    timeline.line_clicked.emit(poll)  # a click on a point goes to its line, shown if hidden
    assert console.current_line() == poll
    assert console.poll_check.isChecked()
    assert not window.console_dock.visibleRegion().isEmpty()  # the console's tab is raised


def test_open_log_shows_the_session_log_decoded(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    qtbot.waitUntil(lambda: window.console.index.counts["poll"] >= 2, timeout=10_000)
    path = window.link.session_log_path
    assert path is not None
    window.logs.ask_path = lambda: str(path)
    file_menu = window.menuBar().actions()[0].menu()
    next(a for a in file_menu.actions() if a.text() == "&Open log…").trigger()
    viewer = window.logs.viewers[-1]
    qtbot.waitUntil(lambda: not viewer.busy(), timeout=20_000)
    assert viewer.protocol_combo.currentText() == "coxiris"  # from the log's connection note
    viewer.console.set_filter(pattern="GET_ID")
    assert "TX  GET_ID\\n" in viewer.console.text()
    viewer.close()


def _typed_lines(console) -> list[int]:
    return [
        n
        for n in range(console.index.first, len(console.index))
        if console.index.line(n).meaning == "GET_POSITION" and console.index.line(n).kind != "poll"
    ]


def test_a_get_position_typed_is_shown_though_polls_are_hidden(qtbot, window: MainWindow) -> None:
    _connect(qtbot, window)
    console = window.console
    qtbot.waitUntil(lambda: console.index.counts["poll"] >= 2, timeout=10_000)
    assert not console.poll_check.isChecked()  # the panel's own polling is hidden
    console.send_line.edit.setText("GET_POSITION")
    console.send()
    qtbot.waitUntil(lambda: (console.flush(), _typed_lines(console))[1] != [], timeout=10_000)
    typed = _typed_lines(console)[0]
    shown = console.text()
    assert "TX  GET_POSITION\\n" in shown  # the operator's line, with the poll filter on
    line = console.index.line(typed)
    qtbot.waitUntil(lambda: console.index.line(typed).pair > typed, timeout=10_000)
    reply = console.index.line(console.index.line(typed).pair)
    assert reply.kind == line.kind == "query" and "GET_POSITION" in reply.meaning
    assert console.index.counts["poll"] >= 2  # the panel's polls stay polls


def test_search_counts_what_the_filters_show_and_says_what_they_hide(
    qtbot, window: MainWindow
) -> None:
    _connect(qtbot, window)
    console = window.console
    qtbot.waitUntil(lambda: console.index.counts["poll"] >= 3, timeout=10_000)
    console.flush()
    assert console.search("GET_POSITION") == 0  # every one is a hidden poll
    status = console.status_text()
    assert "0 matches" in status
    assert "more hidden by the filters" in status
    assert console.find_next() is None
    console.show_poll(True)
    console.flush()
    found = console.search("GET_POSITION")
    assert found >= 3 and "hidden by the filters" not in console.status_text()
    assert console.find_next() is not None
