"""The window's three layouts, one a job: Operate, Set up and Traffic. Each is a built-in
arrangement of the docks that the operator may change; the change is kept (QMainWindow.saveState,
in the settings) until "Reset layout" puts the built-in one back."""

from __future__ import annotations

import logging
from collections.abc import Callable

from PySide6.QtCore import (
    QByteArray,
    QCoreApplication,
    QEvent,
    QObject,
    QSettings,
    QSize,
    Qt,
    QTimer,
)
from PySide6.QtGui import QAction, QActionGroup, QKeySequence
from PySide6.QtWidgets import (
    QDockWidget,
    QHBoxLayout,
    QLabel,
    QMainWindow,
    QMenu,
    QTabBar,
    QToolButton,
    QWidget,
)

from app.window.layout import arrangements
from app.window.layout.arrangements import (
    BOTTOM,
    CENTRAL,
    CONSOLE,
    CORNERS,
    DEVICE,
    FIRMATA,
    HORIZONTAL,
    JOG,
    MACROS,
    MEMBERS,
    NAMES,
    OBJECT_NAMES,
    OPERATE,
    PARAMETERS,
    PIFRAME,
    PLACES,
    READOUT,
    SETUP,
    SETUP_PANELS,
    SIDE_TITLE,
    SIDE_TITLES,
    SPEED,
    SWITCH_NAMES,
    TIMELINE,
    TOP,
    TRAFFIC,
    VERTICAL,
)
from widgets._i18n import fill
from widgets.compact_readout import CompactReadout
from widgets.position_readout import PositionReadout
from widgets.view_tabs import VIEW_3D, ViewTabs

log = logging.getLogger(__name__)
translate = QCoreApplication.translate  # the strings keep the window's context, "MainWindow"

KEY = "layouts/{name}"  # the window's state in this layout (QMainWindow.saveState)
SPLIT_KEY = "layouts/{name}_view_tab"  # the position view shown (3D or 2D) in this layout
TIMELINE_SHARE = 0.45  # of the height in Traffic, at first (the console takes the rest)
# saveState's version: a state saved by another arrangement is not restored. 28: Operate's
# controls in the left column, the views as tabs filling the centre (issue 28 item 20).
STATE_VERSION = 28


class Layouts(QObject):
    """Switches the window between its layouts; keeps each one's state in `settings`."""

    def __init__(
        self,
        window: QMainWindow,
        settings: QSettings,
        views: ViewTabs,
        tell: Callable[[str], None],
    ) -> None:
        super().__init__(window)
        self.window = window
        self.settings = settings
        self.views = views
        self.tell = tell
        self.current = OPERATE
        self.wanted: dict[str, bool] = dict.fromkeys(DEVICE, False)  # what the device calls for
        self.chosen: set[str] = set()  # device docks shown in this layout by the operator
        self.front: str | None = None  # the device's setup panel to put in front in Set up
        self.held: QSize | None = None  # the window's size before a switch: kept through it
        self.group = QActionGroup(self)
        self.group.setExclusive(True)
        self.actions: dict[str, QAction] = {}
        titles, tips = arrangements.titles(), arrangements.tips()
        for number, name in enumerate(NAMES, start=1):
            action = QAction(titles[name], window)
            action.setObjectName(OBJECT_NAMES[name])
            action.setCheckable(True)
            action.setShortcut(QKeySequence(f"Ctrl+{number}"))
            action.setToolTip(f"{tips[name]} (Ctrl+{number})")
            action.triggered.connect(lambda _=False, name=name: self.switch(name))
            self.group.addAction(action)
            self.actions[name] = action
        self.actions[OPERATE].setChecked(True)
        self.reset_action = QAction(translate("MainWindow", "Reset &layout"), window)
        self.reset_action.setObjectName("layoutReset")
        self.reset_action.setToolTip(
            translate("MainWindow", "Put the docks of this layout back as they were at first")
        )
        self.reset_action.triggered.connect(self.reset)
        self.switcher = self._switcher()
        self._tidy = QTimer(self)
        self._tidy.setSingleShot(True)
        self._tidy.setInterval(0)
        self._tidy.timeout.connect(self._settle)
        self._fresh = False  # a built-in layout not yet sized
        self.after_apply: list[Callable[[], object]] = []  # run once a layout is in
        self.after_device: list[Callable[[], object]] = []  # and once the device's docks are
        # Traffic: the timeline's share of the height, as last set (by the layout or the
        # operator's drag), put back after each resize of the window; and the window's size then.
        self._share: float | None = None
        self._size_seen = QSize()
        self._keep = QTimer(self)
        self._keep.setSingleShot(True)
        self._keep.setInterval(0)
        self._keep.timeout.connect(self._keep_split)
        window.installEventFilter(self)
        for name in (TIMELINE, CONSOLE):
            dock = self._dock(name)
            if dock is not None:
                dock.installEventFilter(self)

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """In Traffic, the split of timeline and console stays as set when the window is resized;
        a change of the split at the same window size is the operator's: it is kept from then."""
        if event.type() != QEvent.Type.Resize or self.current != TRAFFIC:
            return False
        if watched is self.window:
            self._keep.start()
        elif self.window.size() == self._size_seen and not self._keep.isActive():
            self._note_split()
        return False

    # -- the menu and the switcher -------------------------------------------------------------
    def _switcher(self) -> QWidget:
        """Three toggle buttons, one a layout (always on screen: in the status bar)."""
        box = QWidget(self.window)
        box.setObjectName("layoutSwitcher")
        row = QHBoxLayout(box)
        row.setContentsMargins(0, 0, 0, 0)
        row.setSpacing(2)
        self.offer = QLabel(box)  # "this device has parameters: Ctrl+2 for Set up"
        self.offer.setObjectName("layoutOffer")
        self.offer.hide()
        row.addWidget(self.offer)
        readout = self.window.findChild(PositionReadout, "positionReadout")
        self.compact: CompactReadout | None = None  # the position on one line, in Traffic
        if readout is not None:
            self.compact = CompactReadout(readout, box)
            self.compact.hide()
            row.addWidget(self.compact)
        self.buttons: dict[str, QToolButton] = {}
        for name in NAMES:
            button = QToolButton(box)
            button.setObjectName(SWITCH_NAMES[name])
            button.setDefaultAction(self.actions[name])
            button.setAutoRaise(False)
            button.setFocusPolicy(Qt.FocusPolicy.NoFocus)  # the arrow keys stay with jogging
            row.addWidget(button)
            self.buttons[name] = button
        return box

    def add_to_menu(self, menu: QMenu, before: QAction | None = None) -> None:
        """The three layouts and Reset layout in `menu` (before `before`)."""
        for action in (*self.actions.values(), self.reset_action):
            menu.insertAction(before, action)  # type: ignore[arg-type]
        menu.insertSeparator(before)  # type: ignore[arg-type]

    # -- switching ----------------------------------------------------------------------------
    def _dock(self, name: str) -> QDockWidget | None:
        return self.window.findChild(QDockWidget, name, Qt.FindChildOption.FindDirectChildrenOnly)

    def switch(self, name: str) -> None:
        """Show layout `name` (the one left is kept as the operator left it)."""
        if name not in NAMES:
            raise ValueError(name)
        self.actions[name].setChecked(True)
        if name == self.current:
            return
        self.save()
        self.hold_size()
        self.current = name
        if name == SETUP:
            self.offer.hide()
            font = self.buttons[SETUP].font()
            font.setBold(False)
            self.buttons[SETUP].setFont(font)
        self.apply()

    def apply(self) -> None:
        """Put the current layout on screen: as last left if kept, else the built-in one."""
        self.hold_size()
        name = self.current
        state = self.settings.value(KEY.format(name=name))
        self._central(name)
        self._title_bars(name)
        restored = isinstance(state, QByteArray) and self.window.restoreState(state, STATE_VERSION)
        if restored:
            for corner, area in CORNERS[name].items():
                self.window.setCorner(corner, area)
            self.chosen = {
                dock_name
                for dock_name in DEVICE
                if (dock := self._dock(dock_name)) is not None and not dock.isHidden()
            }
            self.views.restore(self.settings.value(SPLIT_KEY.format(name=name)))
            self.fit_device()
        else:
            self.built_in()
        self._done()

    def reset(self) -> None:
        """Put the current layout back to its built-in arrangement (and forget the changes)."""
        self.hold_size()
        self.settings.remove(KEY.format(name=self.current))
        self.settings.remove(SPLIT_KEY.format(name=self.current))
        self.built_in()
        self._done()

    def save(self) -> None:
        """Keep the current layout's state in the settings."""
        self.settings.setValue(KEY.format(name=self.current), self.window.saveState(STATE_VERSION))
        self.settings.setValue(SPLIT_KEY.format(name=self.current), self.views.state())

    def _done(self) -> None:
        self._raise_front()
        for step in self.after_apply:
            step()
        self.keep_size()
        self._tidy.start()

    # -- the window's size: a layout is a new arrangement inside it, never a new size -----------
    def hold_size(self) -> None:
        """Remember the window's size before the docks move (once, until the layout settles),
        and hold its minimum meanwhile: a dock shown in its old place would raise the minimum
        and QMainWindow would grow the window to it (and never shrink it back)."""
        window = self.window
        if self.held is None and window.isVisible() and not window.isFullScreen():
            self.held = QSize(window.size())
            # An explicit minimum is one the layout leaves alone (QLayout::activate).
            minimum = window.minimumSize().expandedTo(QSize(1, 1))
            window.setMinimumSize(0, 0)  # (setting the same minimum would not make it explicit)
            window.setMinimumSize(minimum)

    def keep_size(self) -> None:
        """The docks are in their new places: the window's minimum is the layout's again (it
        grows the window only if the new arrangement needs more room), its size as it was."""
        held = self.held
        if held is None:
            return
        window = self.window
        window.setMinimumSize(0, 0)  # (no explicit minimum: the layout's own)
        if (layout := window.layout()) is not None:
            layout.activate()
        if window.size() != held:
            log.debug("layout switch: window %s back to %s", window.size(), held)
            window.resize(held)

    def _central(self, name: str) -> None:
        self.views.setVisible(CENTRAL[name])
        if self.compact is not None:
            self.compact.setVisible(name == TRAFFIC)

    def _title_bars(self, name: str) -> None:
        """In Operate the docks under the views have their title bar at their side: the views
        keep its height (issue 28 item 20)."""
        for dock_name in SIDE_TITLES:
            if (dock := self._dock(dock_name)) is not None:
                dock.setFeatures(
                    dock.features() | SIDE_TITLE
                    if name == OPERATE
                    else dock.features() & ~SIDE_TITLE
                )

    def built_in(self) -> None:
        """The layout's own arrangement of the docks."""
        name, window = self.current, self.window
        self._central(name)
        self._title_bars(name)
        for corner, area in CORNERS[name].items():
            window.setCorner(corner, area)
        self.chosen = set()
        members = MEMBERS[name]
        placed = [
            dock
            for _, groups in PLACES[name]
            for group in groups
            for dock_name in group
            if (dock := self._dock(dock_name)) is not None
        ]
        for dock in placed:  # hidden while they move: in the old places they would widen the window
            dock.setFloating(False)
            dock.hide()
        for area, groups in PLACES[name]:
            previous: QDockWidget | None = None
            for group in groups:
                docks = [dock for dock_name in group if (dock := self._dock(dock_name))]
                if not docks:
                    continue
                first = docks[0]
                if previous is None:
                    window.addDockWidget(area, first)
                else:  # (before any tab: a tabbed dock takes the one split off it as a tab)
                    across = area in (TOP, BOTTOM) and previous.objectName() == READOUT
                    window.splitDockWidget(previous, first, HORIZONTAL if across else VERTICAL)
                previous = first
        for _, groups in PLACES[name]:
            for group in groups:
                docks = [dock for dock_name in group if (dock := self._dock(dock_name))]
                for dock in docks[1:]:
                    window.tabifyDockWidget(docks[0], dock)
        for dock in placed:
            dock.setVisible(self._shown(dock.objectName(), members))
        for _, groups in PLACES[name]:  # the first dock shown of each tab group on top
            for group in groups:
                for dock_name in group:
                    dock = self._dock(dock_name)
                    if dock is not None and not dock.isHidden():
                        dock.raise_()
                        break
        self.views.restore(VIEW_3D)
        self._fresh = True  # sized once the layout is in (see _settle)

    def _shown(self, name: str, members: frozenset[str]) -> bool:
        if name in DEVICE:
            return self.wanted[name] and (name in members or name in self.chosen)
        return name in members

    def _sizes(self) -> None:
        """The docks' widths and heights as the layout wants them at first."""
        window = self.window
        readout, jog = self._dock(READOUT), self._dock(JOG)
        if readout is None or jog is None:
            return
        width = max(readout.sizeHint().width(), jog.sizeHint().width())
        if self.current == OPERATE:  # the column as narrow as its panels allow: the views wide
            column = [readout, jog, self._dock(SPEED)]
            width = max(d.minimumSizeHint().width() for d in column if d and not d.isHidden())
            window.resizeDocks([readout], [width], HORIZONTAL)
        elif self.current == SETUP:
            right = [
                dock
                for name in (PARAMETERS, FIRMATA, PIFRAME, MACROS)
                if (dock := self._dock(name)) is not None and not dock.isHidden()
            ]
            window.resizeDocks(
                [readout, *right[:1]], [width, window.width() - width][: 1 + len(right[:1])],
                HORIZONTAL,
            )  # fmt: skip
        else:  # the timeline its own height (at most TIMELINE_SHARE), the console the rest
            timeline, console = self._dock(TIMELINE), self._dock(CONSOLE)
            if timeline is not None and console is not None and timeline.isVisible():
                total = timeline.height() + console.height()
                height = min(timeline.sizeHint().height(), int(total * TIMELINE_SHARE))
                height = max(height, timeline.minimumSizeHint().height())
                window.resizeDocks([timeline, console], [height, total - height], VERTICAL)

    # -- the device's docks --------------------------------------------------------------------
    def device_docks(self, wanted: dict[str, bool]) -> None:
        """The connected device calls for these docks (True) and not those (False): show them
        where the current layout has them, and offer Set up if it has setup panels."""
        come = [name for name in SETUP_PANELS if wanted.get(name) and not self.wanted[name]]
        if come:
            self.front = come[0]  # in front when Set up next shows (a saved Set up has Macros)
        self.wanted.update({name: on for name, on in wanted.items() if name in self.wanted})
        self.hold_size()
        self.fit_device()
        self._raise_front()
        offered = [name for name in SETUP_PANELS if wanted.get(name)]
        if offered and self.current != SETUP:
            text = (
                translate("MainWindow", "this device has parameters: %1 for Set up")
                if PARAMETERS in offered
                else translate("MainWindow", "this device has a setup panel: %1 for Set up")
            )
            shortcut = (
                self.actions[SETUP].shortcut().toString(QKeySequence.SequenceFormat.NativeText)
            )
            self.offer.setText(fill(text, shortcut))  # beside the switcher: the status line
            self.offer.show()  # keeps what the connection says
            font = self.buttons[SETUP].font()
            font.setBold(True)
            self.buttons[SETUP].setFont(font)

    def fit_device(self) -> None:
        """Each device dock shown if the device calls for it and the layout has it."""
        members = MEMBERS[self.current]
        for name in DEVICE:
            dock = self._dock(name)
            if dock is None:
                continue
            shown = self._shown(name, members)
            if dock.isHidden() == shown:
                dock.setVisible(shown)
        self.keep_size()
        self._tidy.start()
        for step in self.after_device:  # (a tab group's new tab bar takes room from its dock)
            step()

    def _raise_front(self) -> None:
        """In Set up, the device's own setup panel that just came is the tab in front."""
        if self.current != SETUP or self.front is None:
            return
        dock = self._dock(self.front)
        if dock is not None and not dock.isHidden():
            dock.raise_()
            self.front = None

    def note_toggled(self, dock: QDockWidget, shown: bool) -> None:
        """The operator showed or hid a device's dock from the View menu, in this layout."""
        if shown:
            self.chosen.add(dock.objectName())
        else:
            self.chosen.discard(dock.objectName())

    def _settle(self) -> None:
        """Once the layout is in: the docks' first sizes, and no stray tab bar."""
        self.keep_size()
        self.held = None
        if self._fresh:
            self._fresh = False
            if (layout := self.window.layout()) is not None:
                layout.activate()  # (the docks just shown have their heights)
            self._sizes()
        if self.current == TRAFFIC:
            self._note_split()
        self.hide_stray_tab_bars()

    def _split_docks(self) -> tuple[QDockWidget, QDockWidget] | None:
        timeline, console = self._dock(TIMELINE), self._dock(CONSOLE)
        if timeline is None or console is None:
            return None
        if not (timeline.isVisible() and console.isVisible()) or timeline.isFloating():
            return None
        if console.isFloating() or self.window.dockWidgetArea(timeline) != TOP:
            return None  # (the operator moved them: nothing to keep)
        return timeline, console

    def _note_split(self) -> None:
        """Traffic's split as it is now: kept from here on."""
        docks = self._split_docks()
        total = docks[0].height() + docks[1].height() if docks is not None else 0
        if docks is not None and total > 0:
            self._share = docks[0].height() / total
            self._size_seen = self.window.size()

    def _keep_split(self) -> None:
        """After a resize of the window in Traffic: the split as it was."""
        docks = self._split_docks()
        if docks is not None and self._share is not None and not self._fresh:
            total = docks[0].height() + docks[1].height()
            height = round(total * self._share)
            self.window.resizeDocks(list(docks), [height, total - height], VERTICAL)
        self._size_seen = self.window.size()

    # -- the stray tab bars --------------------------------------------------------------------
    def hide_stray_tab_bars(self) -> None:
        """Hide the dock tab bars QMainWindow left on screen for a group now shown untabbed
        (a "Speed | Macros" bar once lay across the Jog dock after start)."""
        window = self.window
        docks = [
            dock
            for dock in window.findChildren(
                QDockWidget, options=Qt.FindChildOption.FindDirectChildrenOnly
            )
            if dock.isVisible() and not dock.isFloating()
        ]
        for bar in window.findChildren(QTabBar, options=Qt.FindChildOption.FindDirectChildrenOnly):
            if not bar.isVisible():
                continue
            titles = [bar.tabText(index) for index in range(bar.count())]
            groups = [
                dock
                for dock in docks
                if dock.windowTitle() in titles and window.tabifiedDockWidgets(dock)
            ]
            shown = sum(1 for dock in groups if dock.isVisible())
            overlaps = any(
                dock.geometry().intersects(bar.geometry())
                for dock in docks
                if dock.windowTitle() not in titles
            )
            if shown < 2 or overlaps:
                log.debug("stray dock tab bar %s hidden", titles)
                bar.hide()
