"""The 2D view's plots lay themselves out for the space they get: at every size, each axis's tick
labels, the axis labels, the title and the legend lie inside the plot widget and clear of each
other, and the plot's right and bottom edges are inside the widget (issue 22)."""

from __future__ import annotations

import itertools

import numpy as np
import pyqtgraph as pg
import pytest
from PySide6.QtCore import QRectF, Qt, QTranslator
from PySide6.QtGui import QPainter, QPicture
from PySide6.QtWidgets import QApplication

from widgets._plot_fit import FittedAxis, PlotFit
from widgets.position_buffer import PositionBuffer
from widgets.position_view_2d import PositionView2D

pytestmark = pytest.mark.timeout(60)

# plot widget sizes: what windows of 1024x640 .. 1600x1000 gave them (before and after their
# docks were rearranged), and wider and taller
SMALL = [(134, 92), (200, 92), (228, 232), (261, 143)]
READABLE = [(300, 180), (377, 183), (416, 207), (432, 273), (523, 323), (340, 260), (420, 200)]
READABLE += [(700, 420), (900, 600), (260, 420)]
TOLERANCE = 0.5  # px: rounding of text boxes


def _circle(buffer: PositionBuffer, radius: float = 40.0) -> None:
    for i in range(300):
        t = i * 0.1
        buffer.append(t, radius * np.cos(t / 3), 0.6 * radius * np.sin(t / 3), t / 4)


def _far(buffer: PositionBuffer) -> None:
    """Long tick labels: positions around -1000..2000 mm."""
    for i in range(50):
        buffer.append(float(i), -1000.0 + 60.0 * i, 1500.0 - 45.0 * i, 0.5 * i)


def _build(qtbot, data: str) -> PositionView2D:
    buffer = PositionBuffer(capacity=1000)
    if data == "circle":
        _circle(buffer)
    elif data == "far":
        _far(buffer)
    view = PositionView2D(buffer)
    qtbot.addWidget(view)
    if data == "circle":
        view.set_workspace(((-50.0, 50.0), (-30.0, 30.0), (0.0, 10.0)))
    view.resize(800, 400)
    view.show()
    qtbot.waitExposed(view)
    return view


def _settle() -> None:
    for _ in range(4):
        QApplication.processEvents()


def _size_plots(view: PositionView2D, width: int, height: int, exact: bool = True) -> None:
    """Resize the view so that each plot widget is `width` x `height` px, side by side when the
    view's own rule puts them so, else one above the other (`exact`: checked)."""
    buttons = view.height() - view.splitter.height()
    handle = view.splitter.handleWidth()
    across = (2 * width + handle, height + buttons)
    if across[0] >= 1.3 * across[1]:
        view.resize(*across)
    else:
        view.resize(width, 2 * height + handle + buttons)
    _settle()
    view.splitter.setSizes([1, 1])  # shared equally
    _settle()
    view.refresh()
    _settle()
    for plot in (view.xy_plot, view.time_plot):
        assert not exact or (abs(plot.width() - width) <= 1 and abs(plot.height() - height) <= 1), (
            plot.size(),
            (width, height),
        )


def _tick_texts(axis: pg.AxisItem) -> list[tuple[str, QRectF]]:
    """The tick labels `axis` draws, each with its text line's rectangle in scene coordinates.

    pyqtgraph's text boxes are 0.8 of the line high, centred on it: the whole line is taken.
    """
    picture = QPicture()
    painter = QPainter(picture)  # as AxisItem.paint draws
    if axis.style["tickFont"] is not None:
        painter.setFont(axis.style["tickFont"])
    specs = axis.generateDrawSpecs(painter)
    painter.end()
    if specs is None:
        return []
    found = []
    for rect, _flags, text in specs[2]:
        extra = rect.height() / 0.8 * 0.1
        line = rect.adjusted(0, -extra, 0, extra)
        found.append((f"{axis.orientation} tick {text!r}", axis.mapRectToScene(line)))
    return found


def _text_rect(item) -> QRectF:
    """A QGraphicsTextItem's text (its box less the document margin) in scene coordinates."""
    margin = item.document().documentMargin()
    return item.mapRectToScene(item.boundingRect().adjusted(margin, margin, -margin, -margin))


def _parts(plot: pg.PlotWidget, fit: PlotFit) -> list[tuple[str, QRectF]]:
    """Every text the plot shows and the legend, named, in scene coordinates."""
    item = plot.getPlotItem()
    parts = []
    for side in ("left", "bottom"):
        axis = item.getAxis(side)
        assert isinstance(axis, FittedAxis)
        parts += _tick_texts(axis)
        if axis.label.isVisible():
            parts.append((f"{side} label {axis.labelText!r}", _text_rect(axis.label)))
    if fit.title.isVisible():
        parts.append(("title", _text_rect(fit.title.item)))
    if fit.legend is not None and fit.legend.isVisible():
        parts.append(("legend", fit.legend.sceneBoundingRect()))
    return parts


def _check_fit(plot: pg.PlotWidget, fit: PlotFit) -> list[str]:
    """What is cut or overlaps in `plot` as drawn now; [] when all fits."""
    problems = []
    inside = QRectF(plot.mapToScene(plot.rect()).boundingRect()).adjusted(
        -TOLERANCE, -TOLERANCE, TOLERANCE, TOLERANCE
    )
    item = plot.getPlotItem().sceneBoundingRect()
    if not inside.contains(item):
        problems.append(f"the plot {item} is not inside the widget {inside}")
    parts = _parts(plot, fit)
    for name, rect in parts:
        if not inside.contains(rect):
            problems.append(f"{name} {rect} is cut (widget {inside})")
    for (name_a, a), (name_b, b) in itertools.combinations(parts, 2):
        common = a.intersected(b)
        if common.width() > TOLERANCE and common.height() > TOLERANCE:
            problems.append(f"{name_a} overlaps {name_b}")
    data = plot.getPlotItem().getViewBox().sceneBoundingRect()
    for name, rect in parts:
        common = data.intersected(rect)
        if name in ("title", "legend") and common.width() > 0 and common.height() > 0:
            problems.append(f"{name} covers the data area")
    return problems


def _tick_count(plot: pg.PlotWidget, side: str) -> int:
    return len(_tick_texts(plot.getPlotItem().getAxis(side)))


def _plots(view: PositionView2D) -> list[tuple[pg.PlotWidget, PlotFit]]:
    return [(view.xy_plot, view.xy_fit), (view.time_plot, view.time_fit)]


@pytest.mark.parametrize("data", ["empty", "circle", "far"])
def test_every_text_fits_at_every_size(qtbot, data: str) -> None:
    view = _build(qtbot, data)
    problems = []
    for width, height in SMALL + READABLE:
        _size_plots(view, width, height)
        for plot, fit in _plots(view):
            found = _check_fit(plot, fit)
            problems += [f"{plot.objectName()} at {width}x{height}: {p}" for p in found]
    assert not problems, "\n".join(problems)


@pytest.mark.parametrize("data", ["circle", "far"])
def test_readable_sizes_keep_labels_ticks_and_the_legend(qtbot, data: str) -> None:
    view = _build(qtbot, data)
    for width, height in READABLE:
        _size_plots(view, width, height)
        for plot, _fit in _plots(view):
            where = f"{plot.objectName()} at {width}x{height}"
            for side in ("left", "bottom"):
                axis = plot.getPlotItem().getAxis(side)
                assert axis.label.isVisible() and axis.labelText, (where, side)
                assert _tick_count(plot, side) >= 2, (where, side)
            data_area = plot.getPlotItem().getViewBox().sceneBoundingRect()
            assert data_area.width() >= 0.5 * width and data_area.height() >= 0.4 * height, where
        assert view.time_fit.legend.isVisible(), (width, height)


def test_the_small_sizes_still_show_ticks_on_both_axes(qtbot) -> None:
    view = _build(qtbot, "circle")
    for width, height in SMALL:
        _size_plots(view, width, height)
        for plot, _fit in _plots(view):
            for side in ("left", "bottom"):
                assert _tick_count(plot, side) >= 1, (plot.objectName(), width, height, side)


def test_labels_shorten_and_the_title_goes_as_the_plot_shrinks(qtbot) -> None:
    view = _build(qtbot, "circle")
    _size_plots(view, 900, 600)
    left, bottom = (view.time_plot.getPlotItem().getAxis(s) for s in ("left", "bottom"))
    assert view.time_fit.title.isVisible() and view.xy_fit.title.isVisible()
    assert bottom.labelText == "time (s, 0 = latest sample)"
    assert left.labelText == "position (mm)"
    _size_plots(view, 228, 232)
    assert not view.time_fit.title.isVisible()
    assert view.time_fit.legend.isVisible()  # the colours' key stays longer than the title
    assert bottom.label.isVisible() and bottom.labelText == "t (s)"
    _size_plots(view, 200, 92)
    assert not view.xy_fit.title.isVisible()
    _size_plots(view, 900, 600)  # and all comes back
    assert view.time_fit.title.isVisible() and view.xy_fit.title.isVisible()
    assert bottom.labelText == "time (s, 0 = latest sample)"


def test_a_retitled_plot_keeps_its_fit(qtbot) -> None:
    """The theme recolours a title with setTitle: a title with no room stays hidden, and the
    title row keeps the height the fit gave it."""
    view = _build(qtbot, "circle")
    _size_plots(view, 228, 232)
    item = view.time_plot.getPlotItem()
    assert not view.time_fit.title.isVisible()
    item.setTitle(item.titleLabel.text, color="#ff0000")
    _settle()
    assert not view.time_fit.title.isVisible()
    assert not _check_fit(view.time_plot, view.time_fit)
    assert "ff0000" in view.time_fit.title.item.toHtml().lower()
    _size_plots(view, 900, 600)
    assert view.time_fit.title.isVisible()


class _LongWords(QTranslator):
    """A translation twice as long as English (as some languages' words are)."""

    def translate(self, context, source, disambiguation=None, n=-1):
        if context == "PositionView2D":
            return f"{source} {source}"
        return None


def test_longer_translations_fit_too(qtbot) -> None:
    translator = _LongWords()
    app = QApplication.instance()
    app.installTranslator(translator)
    try:
        view = _build(qtbot, "circle")
    finally:
        app.removeTranslator(translator)
    assert view.time_plot.getPlotItem().getAxis("left").labelText.count("position (mm)") == 2
    problems = []
    for width, height in SMALL + READABLE:
        _size_plots(view, width, height, exact=False)  # (the longer buttons need more width)
        for plot, fit in _plots(view):
            size = f"{plot.width()}x{plot.height()}"
            problems += [f"{plot.objectName()} at {size}: {p}" for p in _check_fit(plot, fit)]
    assert not problems, "\n".join(problems)


def test_tick_labels_thin_out_on_a_short_axis(qtbot) -> None:
    """pyqtgraph always draws its major ticks' labels, overlapping on a short axis; a fitted
    axis leaves out each one that would overlap another."""
    view = _build(qtbot, "far")
    _size_plots(view, 200, 92)
    plot = view.time_plot.getPlotItem()
    plot.getViewBox().sigRangeChangedManually.emit([True, True])  # as a user's zoom: no refit
    plot.setXRange(-1234.5678, -1234.5, padding=0)  # long labels, finely spaced
    _settle()
    axis = plot.getAxis("bottom")

    def overlaps(specs) -> int:
        pairs = itertools.combinations([rect for rect, _, _ in specs], 2)
        return sum(1 for a, b in pairs if a.intersects(b))

    picture = QPicture()
    painter = QPainter(picture)
    everything = pg.AxisItem.generateDrawSpecs(axis, painter)[2]  # pyqtgraph's own choice
    fitted = axis.generateDrawSpecs(painter)[2]
    painter.end()
    assert overlaps(everything) > 0, [text for _, _, text in everything]
    assert overlaps(fitted) == 0
    assert 1 <= len(fitted) < len(everything)


def test_wider_tick_labels_later_still_fit(qtbot) -> None:
    """The XY plot's left axis grows with its tick labels: fitted while its labels were "-1",
    with its title just fitting, the plot is laid out again when they become "-1500"."""
    view = _build(qtbot, "empty")
    item = view.xy_plot.getPlotItem()
    axis = item.getAxis("left")
    _size_plots(view, 400, 260)
    assert view.xy_fit.title.isVisible()
    narrowest = item.layout.effectiveSizeHint(Qt.SizeHint.MinimumSize).width()
    _size_plots(view, int(narrowest) + 2, 260)  # the title fits, by 2 px or so
    assert view.xy_fit.title.isVisible()
    before = axis.width()
    view.buffer.append(1.0, -1500.0, -1500.0, 0.0)
    view.buffer.append(2.0, 2500.0, 2500.0, 0.0)
    view.refresh()
    view.xy_plot.repaint()  # the axis measures its new labels as it draws them
    qtbot.waitUntil(lambda: axis.width() > before + 2, timeout=5000)
    for _ in range(3):
        _settle()
        view.xy_plot.repaint()
    assert not view.xy_fit.title.isVisible()  # no room left for it
    assert item.sceneBoundingRect().right() <= view.xy_plot.width()
    assert not _check_fit(view.xy_plot, view.xy_fit)


def test_french_tick_labels_use_the_decimal_comma(qtbot) -> None:
    """Issue 28 item 29: the axes write 0,5 where the readout does (the interface's locale)."""
    from PySide6.QtCore import QLocale

    axis = FittedAxis("bottom")
    try:
        QLocale.setDefault(QLocale("fr_FR"))
        assert axis.tickStrings([-0.5, 0.0, 1.5], 1.0, 0.5) == ["-0,5", "0", "1,5"]
    finally:
        QLocale.setDefault(QLocale.system())
    QLocale.setDefault(QLocale("en_US"))
    try:
        assert axis.tickStrings([-0.5, 1.5], 1.0, 0.5) == ["-0.5", "1.5"]
    finally:
        QLocale.setDefault(QLocale.system())


def test_the_data_area_leaves_room_for_the_last_tick_label(qtbot) -> None:
    """Issue 28 item 20: the bottom axis's last tick label, centred on the data area's right end,
    lies inside the widget: the data area ends half a label short of the edge."""
    from PySide6.QtGui import QFontMetricsF

    from widgets._plot_fit import RIGHT_TICK_SAMPLE, _text_box, _tick_font

    view = _build(qtbot, "circle")
    for width, height in READABLE:
        _size_plots(view, width, height)
        for plot, _fit in _plots(view):
            item = plot.getPlotItem()
            half = (
                _text_box(
                    QFontMetricsF(_tick_font(item.getAxis("bottom"))), RIGHT_TICK_SAMPLE
                ).width()
                / 2
            )
            data = item.getViewBox().sceneBoundingRect()
            edge = plot.mapToScene(plot.rect()).boundingRect().right()
            assert edge - data.right() >= half - TOLERANCE, (plot.objectName(), width, height)
