"""Light and dark themes: the application's palette and the colours the plots draw with.

`apply_theme(app, "system" | "light" | "dark")` sets the palette (and the Fusion style when the
current style cannot draw the chosen scheme) and returns the `PlotColors` to draw with;
`theme_notifier().changed` tells widgets when they change, including when the system switches
between light and dark while "system" is chosen. `apply_plot_colors` and `apply_gl_colors` recolour
pyqtgraph's PlotWidget and GLViewWidget. `ThemeMenu` is a ready View → Theme submenu.

pyqtgraph is imported only by the two `apply_*_colors` functions.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Literal, cast

from PySide6.QtCore import QCoreApplication, QObject, Qt, QTimer, Signal
from PySide6.QtGui import QAction, QActionGroup, QColor, QGuiApplication, QPalette
from PySide6.QtWidgets import QApplication, QMenu, QWidget

from app.window.theme_indicators import apply_indicator_palettes

if TYPE_CHECKING:
    import pyqtgraph as pg

log = logging.getLogger(__name__)

ThemeChoice = Literal["system", "light", "dark"]
THEME_CHOICES: tuple[ThemeChoice, ...] = ("system", "light", "dark")
THEME_SETTING = "view/theme"  # a suggested QSettings key for the choice
THEME_ROLE = "theme_role"  # a plot item's attribute naming its PlotColors field (recoloured)
FUSION = "fusion"
# Styles that draw a dark or a light scheme when asked (QStyleHints.setColorScheme, Qt 6.8+);
# any other (e.g. "windowsvista") is replaced by Fusion for an explicit choice.
SCHEME_AWARE_STYLES = frozenset({FUSION, "windows11", "macos"})


@dataclass(frozen=True)
class PlotColors:
    """Colours for the position plots, as "#rrggbb" names (pyqtgraph and QColor take them)."""

    dark: bool
    background: str
    foreground: str  # axis lines and ticks
    text: str  # tick labels, axis and plot titles, legend
    grid: str
    trail: str
    current: str
    estimated: str  # the current-position marker while the position is estimated
    target: str
    workspace: str  # the travel-limits box
    preview: str  # a planned path, not yet run
    axis_x: str
    axis_y: str
    axis_z: str

    def qcolor(self, role: str) -> QColor:
        """The colour of `role` (a field name) as a QColor."""
        return QColor(getattr(self, role))

    def gl(self, role: str, alpha: float = 1.0) -> tuple[float, float, float, float]:
        """The colour of `role` as an (r, g, b, a) tuple of floats in 0..1, as pyqtgraph.opengl
        items take it."""
        colour = self.qcolor(role)
        return (colour.redF(), colour.greenF(), colour.blueF(), alpha)


DARK_PLOT_COLORS = PlotColors(
    dark=True,
    background="#18181c",
    foreground="#9e9e9e",
    text="#d0d0d0",
    grid="#3c3c44",
    trail="#7986cb",
    current="#ffb300",
    estimated="#80591a",
    target="#ec407a",
    workspace="#26a69a",
    preview="#ffcc80",
    axis_x="#e53935",
    axis_y="#43a047",
    axis_z="#1e88e5",
)
LIGHT_PLOT_COLORS = PlotColors(
    dark=False,
    background="#ffffff",
    foreground="#5f5f5f",
    text="#303030",
    grid="#d9dde3",
    trail="#3949ab",
    current="#f57c00",
    estimated="#f9be80",
    target="#c2185b",
    workspace="#00897b",
    preview="#fb8c00",
    axis_x="#d32f2f",
    axis_y="#388e3c",
    axis_z="#1976d2",
)

_R = QPalette.ColorRole
_G = QPalette.ColorGroup

_DARK = {
    _R.Window: "#2d2d30",
    _R.WindowText: "#e6e6e6",
    _R.Base: "#1f1f22",
    _R.AlternateBase: "#29292c",
    _R.ToolTipBase: "#3a3a3e",
    _R.ToolTipText: "#f0f0f0",
    _R.PlaceholderText: "#8c8c8c",
    _R.Text: "#e6e6e6",
    _R.Button: "#35353a",
    _R.ButtonText: "#e6e6e6",
    _R.BrightText: "#ff6e6e",
    _R.Light: "#4a4a50",
    _R.Midlight: "#3e3e43",
    _R.Mid: "#27272a",
    _R.Dark: "#1a1a1c",
    _R.Shadow: "#0e0e0f",
    _R.Highlight: "#3d7fd6",
    _R.HighlightedText: "#ffffff",
    _R.Link: "#6fb3ff",
    _R.LinkVisited: "#b99cff",
    _R.Accent: "#3d7fd6",
}
_DARK_DISABLED = {
    _R.WindowText: "#7a7a7a",
    _R.Text: "#7a7a7a",
    _R.ButtonText: "#7a7a7a",
    _R.Base: "#262629",
    _R.Highlight: "#4a4a50",
    _R.HighlightedText: "#a0a0a0",
    _R.PlaceholderText: "#5f5f5f",
}
_LIGHT = {
    _R.Window: "#efefef",
    _R.WindowText: "#1e1e1e",
    _R.Base: "#ffffff",
    _R.AlternateBase: "#f5f5f5",
    _R.ToolTipBase: "#ffffdc",
    _R.ToolTipText: "#1e1e1e",
    _R.PlaceholderText: "#8a8a8a",
    _R.Text: "#1e1e1e",
    _R.Button: "#e8e8e8",
    _R.ButtonText: "#1e1e1e",
    _R.BrightText: "#ffffff",
    _R.Light: "#ffffff",
    _R.Midlight: "#f4f4f4",
    _R.Mid: "#b8b8b8",
    _R.Dark: "#a0a0a0",
    _R.Shadow: "#5a5a5a",
    _R.Highlight: "#2f6fc4",
    _R.HighlightedText: "#ffffff",
    _R.Link: "#1a5fb4",
    _R.LinkVisited: "#7c3fb0",
    _R.Accent: "#2f6fc4",
}
_LIGHT_DISABLED = {
    _R.WindowText: "#9a9a9a",
    _R.Text: "#9a9a9a",
    _R.ButtonText: "#9a9a9a",
    _R.Base: "#f3f3f3",
    _R.Highlight: "#c8c8c8",
    _R.HighlightedText: "#ffffff",
    _R.PlaceholderText: "#b4b4b4",
}


def _palette(colours: dict[QPalette.ColorRole, str], disabled: dict[QPalette.ColorRole, str]):
    """A palette with `colours` in every group and `disabled` over them in the Disabled one."""
    palette = QPalette()
    for role, name in colours.items():
        palette.setColor(role, QColor(name))
    for role, name in disabled.items():
        palette.setColor(_G.Disabled, role, QColor(name))
    return palette


def dark_palette() -> QPalette:
    """The dark palette (used with the Fusion style or a scheme-aware native one)."""
    return _palette(_DARK, _DARK_DISABLED)


def light_palette() -> QPalette:
    """The light palette (used with the Fusion style or a scheme-aware native one)."""
    return _palette(_LIGHT, _LIGHT_DISABLED)


def is_dark(palette: QPalette | None = None) -> bool:
    """Whether `palette` (default: the application's) has light text on a dark window."""
    if palette is None:
        palette = QGuiApplication.palette()
    window = palette.color(_G.Active, _R.Window)
    text = palette.color(_G.Active, _R.WindowText)
    return window.lightness() < text.lightness()


def plot_colors(dark: bool) -> PlotColors:
    """The plot colours for a dark or a light palette."""
    return DARK_PLOT_COLORS if dark else LIGHT_PLOT_COLORS


def normalise_choice(choice: str | None) -> ThemeChoice:
    """`choice` if it is one of THEME_CHOICES (any case), else "system" (a saved value may be
    anything)."""
    value = (choice or "").strip().lower()
    if value in THEME_CHOICES:
        return cast(ThemeChoice, value)
    if choice:
        log.warning("unknown theme %r: following the system", choice)
    return "system"


class ThemeNotifier(QObject):
    """Says when the theme changes: `changed` carries the new PlotColors."""

    changed = Signal(object)

    def __init__(self, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.choice: ThemeChoice = "system"
        self.colors: PlotColors = LIGHT_PLOT_COLORS
        self.original_style: str | None = None  # the style before Fusion replaced it
        self.watching: QGuiApplication | None = None  # whose colour scheme is followed

    def update(self, choice: ThemeChoice, colors: PlotColors) -> None:
        """Record `choice` and `colors`; emit `changed` if the colours differ."""
        self.choice = choice
        if colors != self.colors:
            self.colors = colors
            self.changed.emit(colors)

    def system_scheme_changed(self) -> None:
        """The system went light or dark: under "system", once Qt has updated the palette,
        recompute the plot colours."""
        if self.choice == "system":
            QTimer.singleShot(0, self._follow_system)

    def _follow_system(self) -> None:
        if self.choice == "system":
            dark = is_dark()
            app = QApplication.instance()
            if isinstance(app, QApplication):
                apply_indicator_palettes(app, dark)
            self.update("system", plot_colors(dark))


_notifier: ThemeNotifier | None = None


def theme_notifier() -> ThemeNotifier:
    """The one ThemeNotifier: connect to its `changed`, read its `colors` and `choice`."""
    global _notifier
    if _notifier is None:
        _notifier = ThemeNotifier()
    return _notifier


def current_plot_colors() -> PlotColors:
    """The plot colours of the theme applied last (light before any)."""
    return theme_notifier().colors


def _style_name(app: QApplication) -> str:
    return app.style().name().lower()


def apply_theme(app: QApplication, choice: str | None = "system") -> PlotColors:
    """Apply the theme `choice` ("system", "light" or "dark") to `app`; return its plot colours.

    "system" clears any palette set here and restores the style Fusion replaced, so the
    platform's palette shows, and follows it when the system scheme changes. "light" and "dark"
    ask Qt for that colour scheme, switch to Fusion unless the style draws schemes itself, and
    set a palette of their own.
    """
    chosen = normalise_choice(choice)
    notifier = theme_notifier()
    hints = app.styleHints()
    if notifier.watching is not app:
        hints.colorSchemeChanged.connect(notifier.system_scheme_changed)
        notifier.watching = app
    scheme_api = hasattr(hints, "setColorScheme")  # Qt 6.8+
    if chosen == "system":
        if scheme_api:
            hints.unsetColorScheme()
        if notifier.original_style is not None:
            app.setStyle(notifier.original_style)
            notifier.original_style = None
        app.setPalette(QPalette())  # nothing resolved: the style's and platform's palette
        colors = plot_colors(is_dark(app.palette()))
    else:
        dark = chosen == "dark"
        if scheme_api:
            hints.setColorScheme(Qt.ColorScheme.Dark if dark else Qt.ColorScheme.Light)
        style = _style_name(app)
        if style not in SCHEME_AWARE_STYLES or (not scheme_api and style != FUSION):
            if notifier.original_style is None:
                notifier.original_style = style
            app.setStyle(FUSION)
        app.setPalette(dark_palette() if dark else light_palette())
        colors = plot_colors(dark)
    apply_indicator_palettes(app, colors.dark)
    log.info(
        "theme %s (%s, style %s)", chosen, "dark" if colors.dark else "light", _style_name(app)
    )
    notifier.update(chosen, colors)
    return colors


def apply_plot_colors(widget: pg.PlotWidget | pg.PlotItem, colors: PlotColors) -> None:
    """Recolour a pyqtgraph PlotWidget (or PlotItem): background, axes, tick labels, title,
    legend text, the pg.GridItem items in its view box, and its curves that name a colour role
    in a `theme_role` attribute (a PlotColors field: their pen's width and style kept). Other
    curves and markers keep their pens: set those from `colors.trail`, ... yourself."""
    import pyqtgraph as pg

    if hasattr(widget, "setBackground"):
        widget.setBackground(colors.background)
    item = widget.getPlotItem() if hasattr(widget, "getPlotItem") else widget
    for side in ("left", "bottom", "right", "top"):
        axis = item.getAxis(side)
        axis.setPen(colors.foreground)
        axis.setTextPen(colors.text)
    title = item.titleLabel.text
    if title:
        item.setTitle(title, color=colors.text)
    for child in item.getViewBox().addedItems:
        if isinstance(child, pg.GridItem):
            child.setPen(pg.mkPen(colors.grid))
    for child in item.items:  # all the plot's items, those outside its auto-range too
        role = getattr(child, THEME_ROLE, None)
        if role is not None and isinstance(child, pg.PlotCurveItem):
            pen = pg.mkPen(child.opts["pen"])  # a copy: its width and dashes kept
            pen.setColor(colors.qcolor(role))
            child.setPen(pen)
    legend = item.legend
    if legend is not None:
        legend.setLabelTextColor(colors.text)
        for _sample, label in legend.items:  # setLabelTextColor does not redraw them
            label.setText(label.text, color=colors.text)
        background = QColor(colors.background)
        background.setAlpha(200)
        legend.setBrush(pg.mkBrush(background))
        legend.setPen(pg.mkPen(colors.grid))


def apply_gl_colors(view: Any, colors: PlotColors) -> None:
    """Recolour a pyqtgraph GLViewWidget: its background, its GLGridItem items and its lines
    that name a colour role in a `theme_role` attribute (a PlotColors field). Other lines,
    markers and text keep their colours: set those from `colors.gl(...)` yourself."""
    import pyqtgraph.opengl as gl

    view.setBackgroundColor(colors.background)
    for item in view.items:
        if isinstance(item, gl.GLGridItem):
            item.setColor(colors.grid)
        role = getattr(item, THEME_ROLE, None)
        if role is not None and isinstance(item, gl.GLLinePlotItem):
            item.setData(color=colors.gl(role))


class ThemeMenu(QMenu):
    """View → Theme: System, Light, Dark, one checked; choosing one applies it and emits
    `chosen` with its name (save it, e.g. under THEME_SETTING)."""

    chosen = Signal(str)

    def __init__(self, parent: QWidget | None = None, current: str | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("themeMenu")
        self.setTitle(self.tr("&Theme"))
        self.group = QActionGroup(self)
        self.group.setExclusive(True)
        labels = {
            "system": self.tr("Follow the &system"),
            "light": self.tr("&Light"),
            "dark": self.tr("&Dark"),
        }
        self.actions_by_choice: dict[ThemeChoice, QAction] = {}
        for choice in THEME_CHOICES:
            action = QAction(labels[choice], self)
            action.setObjectName(f"theme{choice.capitalize()}")
            action.setCheckable(True)
            action.setData(choice)
            self.group.addAction(action)
            self.addAction(action)
            self.actions_by_choice[choice] = action
        self.set_choice(current if current is not None else theme_notifier().choice)
        self.group.triggered.connect(self._triggered)

    def set_choice(self, choice: str | None) -> None:
        """Check the action of `choice` (applies nothing)."""
        self.actions_by_choice[normalise_choice(choice)].setChecked(True)

    def _triggered(self, action: QAction) -> None:
        choice = normalise_choice(action.data())
        app = QCoreApplication.instance()
        if isinstance(app, QApplication):
            apply_theme(app, choice)
        self.chosen.emit(choice)
