"""Light, dark and system themes: palettes, plot colours, the change signal, pyqtgraph widgets."""

from __future__ import annotations

import os
from collections.abc import Iterator

import pytest
from PySide6.QtGui import QColor, QPalette
from PySide6.QtWidgets import QApplication

from app.window.theme import (
    DARK_PLOT_COLORS,
    LIGHT_PLOT_COLORS,
    ThemeMenu,
    apply_gl_colors,
    apply_plot_colors,
    apply_theme,
    current_plot_colors,
    dark_palette,
    is_dark,
    light_palette,
    normalise_choice,
    plot_colors,
    theme_notifier,
)

pytestmark = pytest.mark.timeout(30)

WINDOW = QPalette.ColorRole.Window


@pytest.fixture
def app(qapp: QApplication) -> Iterator[QApplication]:
    """The application, given back with the system theme and the style it had."""
    style = qapp.style().name()
    window = qapp.palette().color(WINDOW).name()
    yield qapp
    apply_theme(qapp, "system")
    assert qapp.style().name() == style
    assert qapp.palette().color(WINDOW).name() == window


def test_is_dark() -> None:
    assert is_dark(dark_palette())
    assert not is_dark(light_palette())


def test_dark(app: QApplication) -> None:
    colors = apply_theme(app, "dark")
    assert colors == DARK_PLOT_COLORS
    assert colors.dark
    assert app.palette().color(WINDOW) == dark_palette().color(WINDOW)
    assert is_dark()
    assert app.style().name().lower() in {"fusion", "windows11", "macos"}
    assert theme_notifier().choice == "dark"
    assert current_plot_colors() is colors


def test_light(app: QApplication) -> None:
    colors = apply_theme(app, "light")
    assert colors == LIGHT_PLOT_COLORS
    assert not colors.dark
    assert app.palette().color(WINDOW) == light_palette().color(WINDOW)
    assert not is_dark()


def test_system_gives_back_the_platform_palette(app: QApplication) -> None:
    before = app.palette().color(WINDOW)
    apply_theme(app, "dark")
    colors = apply_theme(app, "system")
    assert app.palette().color(WINDOW) == before
    assert colors == plot_colors(is_dark(app.palette()))
    assert theme_notifier().choice == "system"


def test_a_style_that_cannot_draw_dark_is_replaced_then_restored(app: QApplication) -> None:
    original = app.style().name()
    try:
        app.setStyle("Windows")  # Qt's plain style: not scheme-aware
        apply_theme(app, "dark")
        assert app.style().name().lower() == "fusion"
        apply_theme(app, "system")
        assert app.style().name().lower() == "windows"
    finally:
        app.setStyle(original)


def test_unknown_choice_follows_the_system(app: QApplication, caplog) -> None:
    assert normalise_choice("DARK") == "dark"
    assert normalise_choice(None) == "system"
    assert normalise_choice("sepia") == "system"
    assert "sepia" in caplog.text
    apply_theme(app, "sepia")
    assert theme_notifier().choice == "system"


def test_changed_is_emitted_when_the_colours_change(app, qtbot) -> None:
    apply_theme(app, "light")
    seen: list = []
    theme_notifier().changed.connect(seen.append)
    try:
        apply_theme(app, "dark")
        apply_theme(app, "dark")  # no change: no signal
        apply_theme(app, "light")
    finally:
        theme_notifier().changed.disconnect(seen.append)
    assert seen == [DARK_PLOT_COLORS, LIGHT_PLOT_COLORS]


def test_system_scheme_change_is_followed(app, qtbot) -> None:
    apply_theme(app, "system")
    assert not is_dark()  # the offscreen platform is light
    app.setPalette(dark_palette())  # as the platform would on a switch to dark
    with qtbot.waitSignal(theme_notifier().changed, timeout=2000) as blocker:
        theme_notifier().system_scheme_changed()
    assert blocker.args == [DARK_PLOT_COLORS]


def test_plot_colors_for_opengl() -> None:
    red = LIGHT_PLOT_COLORS.gl("axis_x", 0.5)
    assert red[3] == 0.5
    assert red[:3] == pytest.approx(QColor(LIGHT_PLOT_COLORS.axis_x).getRgbF()[:3])
    assert DARK_PLOT_COLORS.qcolor("background") == QColor("#18181c")
    for colors in (DARK_PLOT_COLORS, LIGHT_PLOT_COLORS):
        assert colors.qcolor("background").lightness() != colors.qcolor("text").lightness()


@pytest.mark.parametrize("colors", [DARK_PLOT_COLORS, LIGHT_PLOT_COLORS], ids=["dark", "light"])
def test_apply_plot_colors_to_a_bare_plot_widget(qtbot, colors) -> None:
    pg = pytest.importorskip("pyqtgraph")
    widget = pg.PlotWidget(title="XY")
    qtbot.addWidget(widget)
    grid = pg.GridItem()
    widget.addItem(grid)
    widget.addLegend()
    widget.plot([0, 1, 2], [0, 1, 0], name="trail")
    apply_plot_colors(widget, colors)
    assert widget.backgroundBrush().color() == QColor(colors.background)
    item = widget.getPlotItem()
    for side in ("left", "bottom", "right", "top"):
        axis = item.getAxis(side)
        assert axis.pen().color() == QColor(colors.foreground)
        assert axis.textPen().color() == QColor(colors.text)
    assert grid.opts["pen"].color() == QColor(colors.grid)
    assert item.legend.labelTextColor() == QColor(colors.text)
    for _sample, label in item.legend.items:
        assert colors.text[1:] in label.item.toHtml().lower()
    assert colors.text[1:] in item.titleLabel.item.toHtml().lower()
    widget.resize(200, 150)
    assert not widget.grab().isNull()  # draws with them


NO_DISPLAY = "DISPLAY" not in os.environ and "WAYLAND_DISPLAY" not in os.environ


class _SceneStandIn:
    """What apply_gl_colors uses of a GLViewWidget, for a run with no OpenGL platform."""

    def __init__(self, items: list) -> None:
        self.items = items
        self.opts: dict = {}

    def setBackgroundColor(self, colour: str) -> None:
        self.opts["bgcolor"] = QColor(colour).getRgbF()


def test_apply_gl_colors_sets_background_and_grid(qapp) -> None:
    gl = pytest.importorskip("pyqtgraph.opengl")
    grid = gl.GLGridItem()
    line = gl.GLLinePlotItem(color=(1.0, 0.0, 0.0, 1.0))
    scene = _SceneStandIn([grid, line])
    apply_gl_colors(scene, LIGHT_PLOT_COLORS)
    assert scene.opts["bgcolor"] == pytest.approx(QColor("#ffffff").getRgbF())
    assert grid.color() == QColor(LIGHT_PLOT_COLORS.grid)
    assert line.color == (1.0, 0.0, 0.0, 1.0)  # left alone


@pytest.mark.gl
@pytest.mark.skipif(NO_DISPLAY, reason="needs a display with OpenGL (run under xvfb-run)")
def test_apply_gl_colors_to_a_bare_gl_view(qtbot) -> None:
    gl = pytest.importorskip("pyqtgraph.opengl")
    view = gl.GLViewWidget()
    qtbot.addWidget(view)
    grid = gl.GLGridItem()
    view.addItem(grid)
    apply_gl_colors(view, DARK_PLOT_COLORS)
    assert view.opts["bgcolor"] == pytest.approx(QColor(DARK_PLOT_COLORS.background).getRgbF())
    assert grid.color() == QColor(DARK_PLOT_COLORS.grid)
    view.resize(160, 120)
    view.show()
    qtbot.waitExposed(view)
    image = view.grabFramebuffer()
    assert image.pixelColor(2, 2) == QColor(DARK_PLOT_COLORS.background)
    apply_gl_colors(view, LIGHT_PLOT_COLORS)
    assert view.grabFramebuffer().pixelColor(2, 2) == QColor(LIGHT_PLOT_COLORS.background)


def test_theme_menu(app, qtbot) -> None:
    apply_theme(app, "system")
    menu = ThemeMenu()
    qtbot.addWidget(menu)
    assert menu.objectName() == "themeMenu"
    assert [a.objectName() for a in menu.actions()] == ["themeSystem", "themeLight", "themeDark"]
    assert menu.actions_by_choice["system"].isChecked()
    with qtbot.waitSignal(menu.chosen) as blocker:
        menu.actions_by_choice["dark"].trigger()
    assert blocker.args == ["dark"]
    assert is_dark()
    assert menu.actions_by_choice["dark"].isChecked()
    assert not menu.actions_by_choice["system"].isChecked()
    menu.set_choice("light")
    assert menu.actions_by_choice["light"].isChecked()
