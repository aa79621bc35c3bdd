"""The traffic timeline's plots: bytes per second above, latency below, one time axis."""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication
from PySide6.QtWidgets import QVBoxLayout

from widgets.timeline.stores import DIRECTIONS

if TYPE_CHECKING:  # imported where the plots are built: pyqtgraph takes a third of a second
    import pyqtgraph as pg

TX_COLOUR = "#1565c0"  # as the traffic console draws sent bytes
RX_COLOUR = "#2e7d32"  # as the traffic console draws received bytes
LATENCY_COLOUR = "#ef6c00"
GRID_COLOUR = (60, 60, 60)
LEGEND = {  # the directions' names in the legend, translated at use (TrafficTimeline)
    "tx": QT_TRANSLATE_NOOP("TrafficTimeline", "TX"),
    "rx": QT_TRANSLATE_NOOP("TrafficTimeline", "RX"),
}
LEFT_AXIS_WIDTH_PX = 64  # one width for both plots, so one time lines up above the other


def grid() -> pg.GridItem:
    """A background grid that, unlike showGrid, does not repaint the axes on every frame (and
    draws its picture, made again at every step of the followed range, in about 1 ms)."""
    from widgets._fast_grid import FastGrid

    return FastGrid(GRID_COLOUR)


class PlotsMixin:
    """The plots of TrafficTimeline, built on demand (`build_plots`) into its layout."""

    plots: pg.GraphicsLayoutWidget | None
    _layout: QVBoxLayout

    def build_plots(self) -> None:
        """Build the plots (once) and draw what has come so far."""
        if self.plots is not None:
            return
        import pyqtgraph as pg

        self.plots = pg.GraphicsLayoutWidget()
        self.plots.setObjectName("trafficTimelinePlots")
        self.bytes_plot: pg.PlotItem = self.plots.addPlot(row=1, col=0)
        self.latency_plot: pg.PlotItem = self.plots.addPlot(row=2, col=0)

        bp = self.bytes_plot
        bp.setToolTip(
            QCoreApplication.translate(
                "TrafficTimeline",
                "Bytes per second each way, in one-second bins: TX (blue) sent to the device,"
                " RX (green) received. Click a bin to show its first line in the console.",
            )
        )
        # SI prefixes welcome: kB/s, MB/s
        bp.setLabel("left", QCoreApplication.translate("TrafficTimeline", "rate"), units="B/s")
        bp.addItem(grid(), ignoreBounds=True)
        bp.setClipToView(True)
        bp.setDownsampling(auto=True, mode="peak")
        self.curves = {
            "tx": bp.plot(pen=pg.mkPen(TX_COLOUR, width=1.5), name="TX"),
            "rx": bp.plot(pen=pg.mkPen(RX_COLOUR, width=1.5), name="RX"),
        }
        self.legend = self._header_row(
            QCoreApplication.translate("TrafficTimeline", "Bytes per second")
        )

        lp = self.latency_plot
        lp.setTitle(QCoreApplication.translate("TrafficTimeline", "Command latency"))
        lp.setToolTip(
            QCoreApplication.translate(
                "TrafficTimeline",
                "Time from a request to its reply, in ms: one point per answered request"
                " (drawn as dots when few are in view). Click a point to show its line in the"
                " console.",
            )
        )
        lp.setLabel("left", QCoreApplication.translate("TrafficTimeline", "latency"), units="ms")
        lp.setLabel(
            "bottom",
            QCoreApplication.translate("TrafficTimeline", "time since the session started"),
            units="s",
        )
        lp.addItem(grid(), ignoreBounds=True)
        lp.setClipToView(True)
        lp.setDownsampling(auto=True, mode="peak")
        self.latency_curve = lp.plot(
            pen=pg.mkPen(LATENCY_COLOUR, width=1),
            symbol=None,  # see _update_symbols
            symbolSize=5,
            symbolPen=None,
            symbolBrush=pg.mkBrush(LATENCY_COLOUR),
            name="latency",
        )
        lp.setXLink(bp)
        bp.hideAxis("bottom")  # the shared time axis is drawn once, below the latency plot
        lp.getAxis("left").enableAutoSIPrefix(False)  # "ms" must not become "kms"
        lp.getAxis("bottom").enableAutoSIPrefix(False)  # seconds, not "ks"
        for plot in (bp, lp):
            plot.getAxis("left").setWidth(LEFT_AXIS_WIDTH_PX)
            plot.hideButtons()  # Follow replaces the auto-range button
            plot.getViewBox().disableAutoRange()  # follow sets the ranges; clip-to-view needs it
            plot.getViewBox().sigRangeChangedManually.connect(self._user_moved_view)
        lp.getViewBox().sigXRangeChanged.connect(self._update_symbols)
        self.plots.scene().sigMouseClicked.connect(self._on_scene_clicked)
        self._layout.insertWidget(0, self.plots, 1)
        self.refresh()

    def _header_row(self, title: str) -> pg.LegendItem:
        """A row above the bytes plot with its title and a one-row legend, clear of the data.

        The row is an item of the layout widget: moving the plot's own title label into a
        header (as PositionView2D does) crashed the interpreter on exit in a layout widget.
        """
        import pyqtgraph as pg

        legend = pg.LegendItem(colCount=len(DIRECTIONS), horSpacing=4)
        legend.layout.setContentsMargins(4, 2, 4, 2)
        for direction in DIRECTIONS:
            legend.addItem(
                self.curves[direction],
                QCoreApplication.translate("TrafficTimeline", LEGEND[direction]),
            )
        header = pg.GraphicsLayout()
        header.setContentsMargins(0, 0, 0, 0)
        self.bytes_title = pg.LabelItem(title, size="11pt")  # as PlotItem.setTitle draws it
        header.addItem(self.bytes_title, row=0, col=0)
        header.addItem(legend, row=0, col=1)
        header.layout.setColumnStretchFactor(0, 1)
        header.setMaximumHeight(30)
        self.plots.addItem(header, row=0, col=0)
        return legend
