"""A pyqtgraph plot that lays its title, legend, axis labels and tick labels out for its size.

pyqtgraph sizes a plot's parts from their text and never gives any up: a title and a legend in
one row made the time plot 366 px wide at least, and in a narrower widget its right part was
drawn past the widget's edge; an axis label longer than its axis ran past the plot; tick labels
overlapped on a short axis. `PlotFit` chooses, for the widget's size, what is shown: the title
and the legend while they fit, the long or the short form of each axis label or none, and the
axes' room from the font's metrics. `FittedAxis` draws no tick label over another or over its
axis's label.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import pyqtgraph as pg
from PySide6.QtCore import QEvent, QLocale, QObject, QRectF, Qt
from PySide6.QtGui import QFont, QFontMetricsF
from PySide6.QtWidgets import QApplication, QGraphicsGridLayout, QGraphicsWidget

MIN_VIEW_PX = 40  # the data area keeps at least this much on each side before a label goes
TICK_GAP_PX = 6  # room between two tick labels on one axis
HEADER_GAP_PX = 2  # above and below the title row's text
LABEL_GAP_PX = 2  # between an axis label and the tick labels
RIGHT_TICK_SAMPLE = "00"  # a label centred on the bottom axis's right end (its half past it)


class FittedAxis(pg.AxisItem):
    """An axis whose tick labels never overlap each other or the axis's label (fewer are drawn
    when crowded)."""

    def generateDrawSpecs(self, p):
        """pyqtgraph's drawing, less each tick label that would overlap one kept before it (the
        major ticks' come first)."""
        specs = super().generateDrawSpecs(p)
        if specs is None:
            return None
        axis_spec, tick_specs, text_specs = specs
        gap = TICK_GAP_PX / 2
        kept: list[QRectF] = []
        if self.label is not None and self.label.isVisible():  # nor over the axis's label
            kept.append(self.mapRectFromScene(self.label_text_rect()))
        texts = []
        for spec in text_specs:
            room = spec[0].adjusted(-gap, -gap, gap, gap)
            if any(room.intersects(other) for other in kept):
                continue
            kept.append(spec[0])
            texts.append(spec)
        return axis_spec, tick_specs, texts

    def tickStrings(self, values, scale, spacing):
        """pyqtgraph's tick labels with the interface's decimal mark ("0,5" in French, as the
        readout writes it)."""
        strings = super().tickStrings(values, scale, spacing)
        point = QLocale().decimalPoint()
        return strings if point == "." else [text.replace(".", point) for text in strings]

    def label_text_rect(self) -> QRectF:
        """The label's text (its box less the document's margin) in scene coordinates."""
        margin = self.label.document().documentMargin()
        box = self.label.boundingRect().adjusted(margin, margin, -margin, -margin)
        return self.label.mapRectToScene(box)


class FittedPlotItem(pg.PlotItem):
    """A PlotItem whose title, once a `PlotFit` lays it out, is shown only where it fits."""

    fit: PlotFit | None = None

    def setTitle(self, title: str | None = None, **args: object) -> None:
        """Set the title's text (and colour...); the fit decides whether it is shown."""
        if self.fit is None:
            super().setTitle(title, **args)
            return
        self.titleLabel.setText(title or "", **args)
        self.fit.refit()


def fitted_plot_widget() -> pg.PlotWidget:
    """A PlotWidget with a `FittedPlotItem` and `FittedAxis` axes, ready for a `PlotFit`."""
    axes = {side: FittedAxis(side) for side in ("left", "bottom")}  # (given axes are shown)
    return pg.PlotWidget(plotItem=FittedPlotItem(axisItems=axes))


def _tick_font(axis: pg.AxisItem) -> QFont:
    """The font pyqtgraph draws `axis`'s tick labels in (its QPicture painter's)."""
    font = axis.style["tickFont"]
    return QFont(font) if font is not None else QApplication.font()


def _text_box(metrics: QFontMetricsF, text: str) -> QRectF:
    """The box pyqtgraph gives a tick label (the painter's bounding rect, 0.8 of its height)."""
    box = metrics.boundingRect(QRectF(0, 0, 100, 100), Qt.AlignmentFlag.AlignCenter, text)
    box.setHeight(box.height() * 0.8)
    return box


def _place(layout: QGraphicsGridLayout, item: QGraphicsWidget, cell: tuple[int, int], shown: bool):
    """Show `item` in `layout`'s `cell`, or hide it and take it out (a hidden item's minimum
    size still counts in a QGraphicsGridLayout)."""
    inside = any(layout.itemAt(i) is item for i in range(layout.count()))
    if shown and not inside:
        layout.addItem(item, *cell)
    elif not shown and inside:
        layout.removeItem(item)
    item.setVisible(shown)


class PlotFit(QObject):
    """Lays a plot widget out for its size, each time it is resized.

    Shown while they fit, in this order of giving way: the title, the long form of each axis
    label, the short form, the title row (with the legend); the tick labels always. Axis sizes
    come from the font's metrics (the left axis holds `left_ticks`, e.g. "-1000.0", or grows with
    its tick labels when None). `keep_header` keeps the title row (a legend) over the bottom
    axis's label when the height is short.
    """

    def __init__(
        self,
        widget: pg.PlotWidget,  # from fitted_plot_widget()
        title: str,
        labels: dict[str, Sequence[str]],
        legend: pg.LegendItem | None = None,
        left_ticks: str | None = None,
        keep_header: bool = False,
    ) -> None:
        super().__init__(widget)
        self.widget = widget
        self.plot: pg.PlotItem = widget.getPlotItem()
        self.labels = {side: [text for text in texts if text] for side, texts in labels.items()}
        self.legend = legend
        self.left_ticks = left_ticks
        self.keep_header = keep_header
        self.shown: dict[str, str] = {}  # the axis label shown on each side ("" for none)
        plot = self.plot
        plot.setTitle(title)
        self.title = plot.titleLabel
        plot.layout.removeItem(self.title)
        self.header = pg.GraphicsLayout()
        self.header.setContentsMargins(0, 0, 0, 0)
        self.header.addItem(self.title, row=0, col=0)
        if legend is not None:
            self.header.addItem(legend, row=0, col=1)
        self.header.layout.setColumnStretchFactor(0, 1)
        plot.layout.addItem(self.header, 0, 1)
        for side in ("left", "bottom"):
            axis = plot.getAxis(side)
            axis.setLabel(self.labels[side][0] if self.labels.get(side) else "")
        metrics = QFontMetricsF(_tick_font(plot.getAxis("left")))
        # A left tick label may reach half its height past either end of its axis: the title
        # row (or the top margin left for it) and the bottom axis hold that half. pyqtgraph
        # measures a tick label's box as 0.8 of the text's line; the line is what is kept clear.
        self.tick_height = _text_box(metrics, "0").height()
        line = self.tick_height / 0.8
        self.overhang = math.ceil(line / 2) + 1
        # The bottom axis's last tick label is centred on the data area's right end: half of it
        # lies past that end, kept inside the widget by the right margin.
        right = math.ceil(_text_box(metrics, RIGHT_TICK_SAMPLE).width() / 2) + 1
        m_left, m_top, m_right, m_bottom = plot.layout.getContentsMargins()
        plot.layout.setContentsMargins(m_left, m_top, max(m_right, right), m_bottom)
        plot.getAxis("left").setStyle(hideOverlappingLabels=math.floor(line / 2 - line * 0.1))
        self._left_width = -1.0  # the left axis's width as last fitted
        widget.installEventFilter(self)
        if isinstance(plot, FittedPlotItem):
            plot.fit = self
        # A left axis that grows with its tick labels (as it draws them) narrows the data
        # area: lay the plot out again then, in a turn of its own.
        plot.getAxis("left").geometryChanged.connect(
            self._left_changed, Qt.ConnectionType.QueuedConnection
        )
        self.refit()

    def set_labels(self, labels: dict[str, Sequence[str]]) -> None:
        """New axis labels (long form first, as given to the constructor); laid out again."""
        self.labels = {side: [text for text in texts if text] for side, texts in labels.items()}
        self.shown.clear()  # each side's label set again
        self.refit()

    def refit(self) -> None:
        """Lay the plot out again for the widget's present size."""
        self.apply(self.widget.width(), self.widget.height())
        fitted = QRectF(0, 0, self.widget.width(), self.widget.height())
        if self.plot.geometry() != fitted:  # it grew past the widget before: shrink it back
            self.plot.setGeometry(fitted)

    def _left_changed(self) -> None:
        """Refit if the left axis's width is not the one fitted."""
        if self.plot.getAxis("left").maximumWidth() != self._left_width:
            self.refit()

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Refit when the widget is resized."""
        if watched is self.widget and event.type() == QEvent.Type.Resize:
            size = event.size()  # type: ignore[attr-defined]
            self.apply(size.width(), size.height())
        return False

    def _label_extent(self, side: str, text: str) -> tuple[float, float]:
        """(length along the axis, thickness across it) of `text` as `side`'s label."""
        label = self.plot.getAxis(side).label
        metrics = QFontMetricsF(label.font())
        return metrics.horizontalAdvance(text) + 2, metrics.height()

    def _left_tick_width(self) -> float:
        """The room the left axis's tick labels take."""
        axis = self.plot.getAxis("left")
        if self.left_ticks is None:
            return float(axis.textWidth)
        metrics = QFontMetricsF(_tick_font(axis))
        return math.ceil(_text_box(metrics, self.left_ticks).width())

    def _choose(self, side: str, length: float) -> str:
        """The longest form of `side`'s label that fits `length` px, or ""."""
        for text in self.labels.get(side, []):
            if self._label_extent(side, text)[0] <= length:
                return text
        return ""

    def apply(self, width: int, height: int) -> None:
        """Choose what is shown for a widget of `width` x `height` px, and size the axes."""
        plot = self.plot
        m_left, m_top, m_right, m_bottom = plot.layout.getContentsMargins()
        inner_w = width - m_left - m_right
        inner_h = height - m_top - m_bottom
        left, bottom = plot.getAxis("left"), plot.getAxis("bottom")
        offset_x, offset_y = left.style["tickTextOffset"]
        bottom_ticks = math.ceil(offset_y + self.tick_height / 0.8) + 1
        header_h = max(
            self.title.minimumHeight(),
            self.legend.minimumHeight() if self.legend is not None else 0,
        )
        header_h = math.ceil(header_h) + HEADER_GAP_PX
        label_thick = max(self._label_extent(s, "Xg")[1] for s in ("left", "bottom"))
        label_room = math.ceil(label_thick) + LABEL_GAP_PX
        has_bottom_label = bool(self.labels.get("bottom"))

        def view_height(header: bool, label: bool) -> float:
            top = header_h if header else self.overhang
            return inner_h - top - bottom_ticks - (label_room if label else 0)

        choices = [(True, has_bottom_label), (False, has_bottom_label)]
        if self.keep_header:
            choices.insert(1, (True, False))
        choices.append((False, False))
        header, bottom_label = next(
            (c for c in choices if view_height(*c) >= MIN_VIEW_PX), choices[-1]
        )
        view_h = view_height(header, bottom_label)

        tick_w = self._left_tick_width() + offset_x + 1
        left_text = ""
        if inner_w - tick_w - label_room >= MIN_VIEW_PX:
            left_text = self._choose("left", view_h)
        left_w = tick_w + (label_room if left_text else 0)
        view_w = inner_w - left_w
        bottom_text = self._choose("bottom", view_w) if bottom_label else ""

        self._set_label(left, left_text)
        self._set_label(bottom, bottom_text)
        if self.left_ticks is None:
            left.setWidth(None)  # pyqtgraph's: the tick labels' widest, and the label
        else:
            left.setWidth(math.ceil(left_w))
        bottom.setHeight(bottom_ticks + (label_room if bottom_text else 0))
        self._left_width = left.maximumWidth()
        self._fit_header(header, header_h, width)

    def _fit_header(self, room: bool, header_h: int, width: float) -> None:
        """Show the title and the legend if the height has `room` for their row and the plot's
        minimum width (as Qt's layout computes it) stays within `width`: the title goes first."""
        plot = self.plot
        legend = self.legend is not None
        choices = [(True, legend), (False, legend), (False, False)] if room else []
        choices.append((False, False))
        for show_title, show_legend in choices:
            show_title = show_title and bool(self.title.text)
            header = show_title or show_legend
            _place(self.header.layout, self.title, (0, 0), show_title)
            if self.legend is not None:
                _place(self.header.layout, self.legend, (0, 1), show_legend)
            _place(plot.layout, self.header, (0, 1), header)
            plot.layout.setRowFixedHeight(0, header_h if header else self.overhang)
            self.header.layout.invalidate()
            plot.layout.invalidate()
            minimum = plot.layout.effectiveSizeHint(Qt.SizeHint.MinimumSize)
            if minimum.width() <= width:
                return

    def _set_label(self, axis: pg.AxisItem, text: str) -> None:
        """Show `text` as `axis`'s label; hide the label when ""."""
        side = axis.orientation
        if self.shown.get(side) != text:
            self.shown[side] = text
            if text:
                axis.setLabel(text)
            axis.showLabel(bool(text))
            axis.resizeEvent()
