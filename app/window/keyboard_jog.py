"""Keyboard jog for the main window: the jog keys act only where the arrow keys are free."""

from __future__ import annotations

import sys
from functools import cache

from PySide6.QtCore import QT_TRANSLATE_NOOP, QEvent, QObject, Signal
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QApplication, QWidget

from widgets._i18n import fill
from widgets.jog_panel import JogPanel


@cache
def arrow_key_widgets() -> tuple[tuple[type[QWidget], str], ...]:
    """Widgets that use the arrow or page keys themselves (a jog key there is theirs), as the
    hint names them (marked for translation, context "KeyboardJog"); the first match describes
    the widget.

    Looked up when first needed: a PySide class makes all its enums when first imported, which
    the window's first paint need not wait for.
    """
    from PySide6.QtWidgets import (
        QAbstractScrollArea,
        QAbstractSlider,
        QAbstractSpinBox,
        QComboBox,
        QLineEdit,
        QMenu,
        QMenuBar,
        QRadioButton,
        QTabBar,
    )

    return (
        (QLineEdit, QT_TRANSLATE_NOOP("KeyboardJog", "a text field")),
        (QAbstractSpinBox, QT_TRANSLATE_NOOP("KeyboardJog", "a number field")),
        (QComboBox, QT_TRANSLATE_NOOP("KeyboardJog", "a drop-down list")),
        (QAbstractSlider, QT_TRANSLATE_NOOP("KeyboardJog", "a slider")),
        # lists, tables, text views, the console
        (QAbstractScrollArea, QT_TRANSLATE_NOOP("KeyboardJog", "a list or text view")),
        (QRadioButton, QT_TRANSLATE_NOOP("KeyboardJog", "a choice")),
        (QMenuBar, QT_TRANSLATE_NOOP("KeyboardJog", "the menu bar")),
        (QMenu, QT_TRANSLATE_NOOP("KeyboardJog", "a menu")),
        (QTabBar, QT_TRANSLATE_NOOP("KeyboardJog", "tabs")),
    )


def arrow_key_user(widget: QWidget | None) -> str:
    """What `widget` is, when it takes the arrow keys for itself; "" when it leaves them to jog.

    Plots (pyqtgraph views) leave them to jog.
    """
    pg = sys.modules.get("pyqtgraph")  # not imported yet: no plot exists (start-up stays light)
    if widget is None or (pg is not None and isinstance(widget, pg.GraphicsView)):
        return ""
    return next((text for cls, text in arrow_key_widgets() if isinstance(widget, cls)), "")


class KeyboardJog(QObject):
    """An application event filter that jogs `panel` by key for `window`, and says where it acts.

    Jog keys act while `window` is the active window, no popup, menu or dialog is open, the jog
    panel is enabled, and the focus is not in a widget that uses the arrow keys itself. Releasing
    the held key, or the window losing the keyboard, ends a held jog.

    It filters once `attach()`ed: the window attaches it just after its first paint, as an
    application event filter makes PySide wrap every object an event is sent to, before the
    paint (tens of milliseconds at start-up). `refresh()` sets the panel's hint meanwhile (the
    window calls it when it enables or disables the panel).

    While the window has turned motion off for a job under way (`set_motion_blocker`), a jog
    key pressed where it would jog is refused out loud (`refused`, with the reason).
    """

    refused = Signal(str)  # why a jog key pressed now does not jog

    def __init__(self, window: QWidget, panel: JogPanel) -> None:
        super().__init__(window)
        self.window = window
        self.panel = panel
        self._attached = False
        self._detached = False  # for good: the window closed
        self._motion_blocker = ""  # why motion is off while the panel is disabled ("": no link)

    def attach(self) -> None:
        """Start filtering the application's events (once; never after `detach()`)."""
        app = QApplication.instance()
        if app is None or self._attached or self._detached:
            return
        self._attached = True
        app.installEventFilter(self)
        app.focusChanged.connect(self._focus_changed)  # type: ignore[attr-defined]
        self._focus_changed()  # the window may have been activated meanwhile

    def detach(self) -> None:
        """Stop filtering (the window is closing)."""
        self._detached = True
        app = QApplication.instance()
        if app is not None and self._attached:
            self._attached = False
            app.removeEventFilter(self)
            app.focusChanged.disconnect(self._focus_changed)  # type: ignore[attr-defined]

    def set_motion_blocker(self, reason: str) -> None:
        """Why the window turned motion off although connected ("": it did not); the hint says
        it while the panel is disabled."""
        self._motion_blocker = reason
        self.refresh()

    def blocker(self) -> str:
        """Why the jog keys do not act now ("" when they do)."""
        if not self.panel.isEnabled():
            return self._motion_blocker or self.tr("not connected")
        return self._place_blocker()

    def _place_blocker(self) -> str:
        """Why the keys do not reach the jog here: a popup, dialog, window or field has them."""
        if QApplication.activePopupWidget() is not None:
            return self.tr("a menu or list is open")
        if QApplication.activeModalWidget() is not None:
            return self.tr("a dialog is open")
        if not self.window.isActiveWindow():
            return self.tr("another window is active")
        kind = arrow_key_user(QApplication.focusWidget())
        return fill(self.tr("the focus is in %1"), self.tr(kind)) if kind else ""

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Jog on a jog key's press where allowed; end the held jog on its release."""
        kind = event.type()
        if kind in (QEvent.Type.KeyPress, QEvent.Type.KeyRelease) and isinstance(event, QKeyEvent):
            if not self.panel.is_jog_key(event.key()):
                return False
            repeat, stamp = event.isAutoRepeat(), event.timestamp()
            if kind == QEvent.Type.KeyRelease:
                self.panel.handle_key_release(event.key(), auto_repeat=repeat, timestamp=stamp)
                return not self.blocker()  # a field that took the press takes the release
            if self.blocker():
                if not self.panel.is_repeat(event.key(), stamp, auto_repeat=repeat):
                    self.panel.release()  # a popup opened over a held key: stop stepping
                    self._refuse(event.key())
                return False
            return self.panel.handle_key(
                event.key(), event.modifiers(), auto_repeat=repeat, timestamp=stamp
            )
        if kind == QEvent.Type.WindowDeactivate and watched is self.window:
            self.panel.release()
            self._focus_changed()
        elif kind == QEvent.Type.WindowActivate and watched is self.window:
            self._focus_changed()
        return False

    def _refuse(self, key: int) -> None:
        """A jog key pressed where it would jog, while motion is off for a job: say why."""
        reason = self._motion_blocker
        jogs = int(getattr(key, "value", key)) in self.panel.key_map
        if reason and jogs and not self.panel.isEnabled() and not self._place_blocker():
            self.refused.emit(reason)

    def refresh(self) -> None:
        """Say again where the keys act (the jog panel was enabled or disabled)."""
        self._focus_changed()

    def _focus_changed(self, *_args: object) -> None:
        blocker = self.blocker()
        self.panel.set_keyboard_state(not blocker, blocker)
        if blocker and self.panel.held_by_key():
            self.panel.release()
