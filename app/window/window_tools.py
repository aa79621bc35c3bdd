"""What the main window offers beyond jogging and going to coordinates: macros, work coordinates,
the serial control lines, the settings dialog, the theme, and the Help menu."""

from __future__ import annotations

import dataclasses
import logging
from typing import TYPE_CHECKING, Any

from PySide6.QtCore import QObject, Qt
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QApplication, QDockWidget, QMenu

from app.common.settings import device_key
from app.window.docks.work_frame import WorkFrame
from app.window.preferences import Preferences, poll_rates, read_preferences, write_preferences
from widgets._i18n import fill
from widgets.lazy_view import LazyPart, LazyView, built

if TYPE_CHECKING:
    from app.window.docks.macro_dock import MacroDock
    from app.window.services import WindowParts
    from drivers.link.control_lines import ControlLines

log = logging.getLogger(__name__)

ARROWS = {"Left": "←", "Right": "→", "Up": "↑", "Down": "↓"}  # others: as Qt names them
NATIVE = QKeySequence.SequenceFormat.NativeText
MACRO_CALLS = frozenset({"set_protocol", "set_runnable"})
MACRO_DOCK = "macroPanelDock"


def _key_code(text: str) -> int:
    """The key code of a one-key sequence such as "Left" or "PgUp" (0: none)."""
    sequence = QKeySequence(text)
    return sequence[0].key().value if sequence.count() else 0


class WindowTools(QObject):
    """Built with the window (its menus and the work frame at once, the macro dock just after
    the first paint); the window tells it what happens through the methods below."""

    def __init__(self, window: WindowParts) -> None:
        super().__init__(window)  # type: ignore[arg-type]
        self.window = window
        self.prefs: Preferences = read_preferences(window.settings)
        self.work = WorkFrame(window.settings, window.readout, window.coordinates, self._say, self)
        self.macro_dock = QDockWidget(self.tr("Macros"), window)  # type: ignore[call-overload]
        self.macro_dock.setObjectName(MACRO_DOCK)
        window.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, self.macro_dock)
        self.macros: MacroDock = LazyPart(self._build_macros, MACRO_CALLS)  # type: ignore[assignment]
        window.views.add(self.macros.build)
        self.port: tuple[str, str] | None = None  # (protocol, port) connected
        self.theme_menu: QMenu | None = None
        self._following_theme = False
        lines = window.connection_bar.control_lines
        lines.line_toggled.connect(self._on_line_toggled)
        lines.break_requested.connect(self._on_break_requested)
        self.apply_jog_keys()
        window.readout.set_display(self.prefs.units, self.prefs.decimals)
        self.apply_units()
        window.views.add(self.apply_units)  # again once the device docks (the arc) are built
        window.views.ready.connect(self.apply_units)  # and the views
        window.console.set_max_lines(self.prefs.console_max_lines)
        if self.prefs.theme == "system":  # nothing to change before the first paint (asking
            window.views.add(self.apply_theme)  # for the style costs some 40 ms): after it
        else:
            self.apply_theme()

    # -- built after the first paint -----------------------------------------------------------
    def _build_macros(self) -> MacroDock:
        from app.window.docks.macro_dock import MacroDock

        self.macros = MacroDock(self.window, self.window)  # type: ignore[arg-type]
        return self.macros

    # -- menus ---------------------------------------------------------------------------------
    def add_menus(self, file_menu: QMenu, before: QAction, view_menu: QMenu) -> None:
        """Settings… in File (before `before`), Theme in View, and the Help menu."""
        settings = QAction(self.tr("&Settings…"), file_menu)
        settings.triggered.connect(self.edit_settings)
        file_menu.insertAction(before, settings)
        file_menu.insertSeparator(before)
        settings.setObjectName("settingsAction")
        settings.setShortcut(QKeySequence(QKeySequence.StandardKey.Preferences))
        if settings.shortcut().isEmpty():
            settings.setShortcut(QKeySequence("Ctrl+,"))
        settings.setToolTip(self.tr("Poll rates, console, log folder, units, jog keys, theme"))
        self.window.views.add(lambda: self._add_theme_menu(view_menu))  # after the first paint
        help_menu = self.window.menuBar().addMenu(self.tr("&Help"))
        keys = help_menu.addAction(self.tr("&Keyboard shortcuts"), self.show_shortcuts)
        keys.setObjectName("shortcutsAction")
        keys.setShortcut(QKeySequence(QKeySequence.StandardKey.HelpContents))
        about = help_menu.addAction(self.tr("&About Motion Panel"), self.show_about)
        about.setObjectName("aboutAction")

    def _add_theme_menu(self, view_menu: QMenu) -> None:
        """View → Theme (its module is imported after the first paint)."""
        from app.window.theme import ThemeMenu

        self.theme_menu = ThemeMenu(view_menu, self.prefs.theme)
        self.theme_menu.chosen.connect(self._on_theme_chosen)
        view_menu.addMenu(self.theme_menu)

    def apply_theme(self) -> None:
        """The theme the preferences choose, and the plots in its colours."""
        from app.window.theme import apply_theme, theme_notifier

        app = QApplication.instance()
        if isinstance(app, QApplication):
            colors = apply_theme(app, self.prefs.theme)
            if not self._following_theme:  # once: the system may change its scheme later
                theme_notifier().changed.connect(self._recolor)
                self._following_theme = True
            self._recolor(colors)

    def _recolor(self, colors: Any) -> None:
        """The 2D and 3D views in the theme's colours (once they are built)."""
        from app.window.theme import apply_gl_colors, apply_plot_colors

        window = self.window
        if not window.views.is_ready():
            window.views.ready.connect(self._recolor_now, Qt.ConnectionType.UniqueConnection)
            return
        for name in ("xy_plot", "time_plot"):
            plot = getattr(window.view2d, name, None)
            if plot is not None:
                apply_plot_colors(plot, colors)
        scene = getattr(window.view3d, "scene", None)  # None: the 3D view is a notice
        if scene is not None:
            apply_gl_colors(scene, colors)

    def _recolor_now(self) -> None:
        from app.window.theme import current_plot_colors

        self._recolor(current_plot_colors())

    def _on_theme_chosen(self, choice: str) -> None:
        self.prefs = dataclasses.replace(self.prefs, theme=choice)
        write_preferences(self.window.settings, self.prefs)
        self.apply_theme()

    def show_shortcuts(self) -> None:
        """Help → Keyboard shortcuts: every shortcut the window has, and the jog keys."""
        from widgets.shortcuts_dialog import ShortcutsDialog, shortcuts_from_actions

        p = self.prefs
        jog = [
            (f"{p.jog_key_x_minus} / {p.jog_key_x_plus}", self.tr("Jog X - / +")),
            (f"{p.jog_key_y_minus} / {p.jog_key_y_plus}", self.tr("Jog Y - / +")),
            (f"{p.jog_key_z_minus} / {p.jog_key_z_plus}", self.tr("Jog Z - / +")),
            (self.tr("Shift + a jog key"), self.tr("Jog ten times the step")),
            (self.tr("hold a jog key"), self.tr("Keep jogging until it is released")),
        ]
        actions = shortcuts_from_actions(self.window.findChildren(QAction))
        dialog = ShortcutsDialog(actions + jog, self.window)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        dialog.open()

    def show_about(self) -> None:
        """Help → About: version, licence, components."""
        from widgets.about_dialog import AboutDialog

        dialog = AboutDialog(self.window)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        dialog.open()

    def apply_jog_keys(self) -> None:
        """The jog panel's keys as the preferences name them."""
        p = self.prefs
        named = {
            p.jog_key_x_minus: ("x", -1.0),
            p.jog_key_x_plus: ("x", 1.0),
            p.jog_key_y_minus: ("y", -1.0),
            p.jog_key_y_plus: ("y", 1.0),
            p.jog_key_z_minus: ("z", -1.0),
            p.jog_key_z_plus: ("z", 1.0),
        }
        key_map = {code: target for text, target in named.items() if (code := _key_code(text))}
        steps = {p.jog_key_step_smaller: -1, p.jog_key_step_larger: 1}
        step_keys = {code: way for text, way in steps.items() if text and (code := _key_code(text))}

        def name(text: str) -> str:
            return ARROWS.get(text, QKeySequence(text).toString(NATIVE))

        hint = fill(
            self.tr("Keys: %1/%2 X, %3/%4 Y, %5/%6 Z, Shift ×10"),
            *(
                name(t)
                for t in (  # in the order of the panel's own hint: ←/→ X, ↑/↓ Y, PgUp/PgDn Z
                    p.jog_key_x_minus,
                    p.jog_key_x_plus,
                    p.jog_key_y_plus,
                    p.jog_key_y_minus,
                    p.jog_key_z_plus,
                    p.jog_key_z_minus,
                )
            ),
        )
        if step_keys:
            smaller, larger = p.jog_key_step_smaller, p.jog_key_step_larger
            hint += fill(
                self.tr(", %1/%2 step"),
                name(smaller) or "\N{EN DASH}",
                name(larger) or "\N{EN DASH}",
            )
        self.window.jog_panel.set_key_map(key_map, step_keys, hint)

    def apply_units(self) -> None:
        """Lengths and speeds typed and shown in the preferences' units (mm or inches): the Go
        to fields, the jog step, the speed and, once built, the arc and the 2D and 3D views'
        axes, grid and scale; they still hand the window mm and mm/s, and the views draw in mm.
        Converts what is shown; sends nothing."""
        window, units = self.window, self.prefs.units
        window.coordinates.set_units(units)
        window.jog_panel.set_units(units)
        window.speed.set_units(units)
        devices = window.devices
        if built(devices):  # else the step added to window.views sets it once it is built
            devices.arc.set_units(units)
        for view in (window.view3d, window.view2d):
            if not isinstance(view, LazyView):  # a stand-in: that step sets it once built
                view.set_units(units)  # type: ignore[attr-defined]

    # -- settings ------------------------------------------------------------------------------
    def edit_settings(self) -> None:
        """File → Settings…: change the preferences; applied on OK or Apply."""
        from app.common.session_log import log_folder
        from widgets.settings_dialog import SettingsDialog

        dialog = SettingsDialog(self.prefs, self.window, default_log_folder=str(log_folder()))
        dialog.applied.connect(self.apply_preferences)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        dialog.open()
        self.settings_dialog = dialog

    def apply_preferences(self, prefs: Preferences) -> None:
        """Keep new preferences and apply what can be applied now; say what waits."""
        before, self.prefs = self.prefs, prefs
        write_preferences(self.window.settings, prefs)
        changed = [
            f.name
            for f in dataclasses.fields(prefs)
            if getattr(before, f.name) != getattr(prefs, f.name)
        ]
        if {"poll_moving_hz", "poll_idle_s"} & set(changed):
            moving, idle = poll_rates(self.window.settings)
            self.window.to_worker(lambda thread: thread.set_poll_rates(moving, idle))
        if "theme" in changed:
            if self.theme_menu is not None:
                self.theme_menu.set_choice(prefs.theme)  # type: ignore[attr-defined]
            self.apply_theme()
        if "console_max_lines" in changed:
            self.window.console.set_max_lines(prefs.console_max_lines)
        if any(name.startswith("jog_key_") for name in changed):
            self.apply_jog_keys()
        if {"units", "decimals"} & set(changed):
            self.window.readout.set_display(prefs.units, prefs.decimals)
        if "units" in changed:
            self.apply_units()
        if {"session_log", "log_folder"} & set(changed):
            self.window.restart_session_log()
        message = self.tr("settings saved")
        if "language" in changed:
            message = self.tr("settings saved; the language from the next start")
        self._say(message)

    # -- the connection --------------------------------------------------------------------------
    def device_ready(self, protocol: str, variant: str, port: str) -> None:
        """A device answered: its work zero, its macros."""
        self.port = (protocol, port)
        self.work.device_ready(protocol, port)
        self.macros.set_protocol(protocol, variant)

    def protocol_chosen(self, protocol: str) -> None:
        """The protocol chosen in the connection bar: its macros can be edited before connecting."""
        self.macros.set_protocol(protocol)

    def controls_enabled(self, enabled: bool) -> None:
        """Motion allowed or not: the macro buttons follow."""
        self.macros.set_runnable(enabled)
        if not enabled:
            self.work.disconnected()

    def connection_state(self, connected: bool) -> None:
        """Connected (to a device, not a bridge) or not: the control lines follow."""
        self.window.connection_bar.control_lines.set_connected(connected)

    def position(self, position: tuple[float, float, float] | None) -> None:
        """The stage's position as now known (None: unknown)."""
        self.work.set_position(position)

    def home_moved(self, old_home_at: tuple[float, float, float]) -> None:
        """Set Home made `old_home_at` the origin."""
        self.work.home_moved(old_home_at)

    def saved_lines(self, protocol: str, port: str) -> tuple[bool | None, bool | None]:
        """DTR and RTS as last chosen for this device (None: the protocol's default)."""
        key = device_key(protocol, port)
        out: list[bool | None] = []
        for name in ("dtr", "rts"):
            text = str(self.window.settings.value(f"{key}/{name}", "")).lower()
            out.append(True if text == "true" else False if text == "false" else None)
        return out[0], out[1]

    # -- the control lines ---------------------------------------------------------------------
    def _on_line_toggled(self, name: str, on: bool) -> None:
        if self.port is not None:
            self.window.settings.setValue(
                f"{device_key(*self.port)}/{name}", "true" if on else "false"
            )
        self.window.to_worker(lambda thread: thread.set_control_line(name, on))

    def _on_break_requested(self) -> None:
        self.window.to_worker(lambda thread: thread.send_break())

    def show_lines(self, lines: ControlLines) -> None:
        """The control lines as the port reports them."""
        self.window.connection_bar.control_lines.set_lines(lines)

    def _say(self, text: str) -> None:
        self.window.say(text)
