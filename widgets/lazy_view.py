"""Views built just after the window first paints: it shows before the OpenGL scene and plots.

Importing pyqtgraph and its OpenGL module, and building the plots and the OpenGL scene, took
most of the panel's start-up (issue 11's speed table: 5-8 times a bare window). The window is
built with `LazyView` stand-ins instead: plain widgets with the views' object names that take
the calls the window makes (the target, the travel box, the planned path, ...) and keep the last
of each. `DeferredViews` builds the real views once the window has painted (or when something
needs them sooner), puts them in the stand-ins' places, replays the calls and emits `ready`. It
does so a step a turn of the event loop (the views' libraries a step each), so that the device
shown connected, a key or a repaint waits for one step (at most about 0.1 s), not for all.
"""

from __future__ import annotations

import importlib
import logging
from collections.abc import Callable
from functools import partial
from typing import TYPE_CHECKING

from PySide6.QtCore import QEvent, QObject, QTimer, Signal
from PySide6.QtGui import QColor, QPainter, QPaintEvent
from PySide6.QtWidgets import QSplitter, QWidget

if TYPE_CHECKING:  # it imports numpy: not before the window's first paint
    from widgets.position_buffer import PositionBuffer

# What the window may call on a view before it exists. The last call of each of these is
# replayed on the view when it is built, in the order they were last made.
REPLAYED = frozenset(
    {
        "set_target",
        "set_workspace",
        "set_preview",
        "set_program",
        "set_program_done",
        "set_estimated",
        "set_follow",
        "set_view_preset",
        "reset_view",
    }
)
IGNORED = frozenset({"refresh"})  # a new view draws the buffer as it is when shown
# Calls that need the view: it is built at once. Any other attribute builds it too.
FORWARDED = frozenset(
    {
        "clear_trail",
        "target",
        "workspace",
        "preview",
        "program",
        "is_estimated",
        "is_following",
        "grid_spacing",
    }
)
log = logging.getLogger(__name__)
VIEWS_BUILT = "views built: the window is complete"  # a --verbose line the tests wait for
BACKGROUND_3D = QColor(24, 24, 28)  # as the 3D view's scene
BACKGROUND_2D = QColor(0, 0, 0)  # as pyqtgraph's plots


# The views' libraries, imported a step each before the views are built: the longest import
# is then the longest wait the event loop has, not all of them together.
PRELOADED = ("numpy", "pyqtgraph", "OpenGL.GL", "pyqtgraph.opengl")


def _preload(name: str) -> None:
    """Import `name` now, should it import; the view that needs it says what went wrong."""
    try:
        importlib.import_module(name)
    except Exception:  # (no OpenGL here, say: the 3D view shows its notice)
        log.debug("%s did not import ahead of the views", name, exc_info=True)


def position_view_3d(buffer: PositionBuffer | LazyPart) -> QWidget:
    """The 3D view (or its no-OpenGL notice); imports OpenGL."""
    from widgets import position_view_3d as module

    return module.make_position_view_3d(_real_buffer(buffer))


def position_view_2d(buffer: PositionBuffer | LazyPart) -> QWidget:
    """The 2D views; imports pyqtgraph."""
    from widgets.position_view_2d import PositionView2D

    return PositionView2D(_real_buffer(buffer))


def _real_buffer(buffer: PositionBuffer | LazyPart) -> PositionBuffer:
    """The buffer itself (built now if the window has a `LazyPart` for it)."""
    return buffer.build() if isinstance(buffer, LazyPart) else buffer  # type: ignore[return-value]


class LazyView(QWidget):
    """Stands in for a view until `build()`: the same object name, the calls kept for it.

    After `build()` the real view has taken its place in the splitter and the stand-in is
    deleted; a method of it kept from before (a menu's action) calls the real view's.
    """

    def __init__(
        self,
        name: str,
        factory: Callable[[], QWidget],
        background: QColor,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName(name)
        self._factory = factory
        self._background = background
        self._calls: dict[str, tuple[tuple, dict]] = {}  # name: the last call's arguments
        self._real: QWidget | None = None
        self.built_view: Callable[[QWidget], None] | None = None  # told of the real view

    def real(self) -> QWidget | None:
        """The real view once built, else None."""
        return self._real

    def __getattr__(self, name: str) -> object:
        """The views' methods: kept, ignored or forwarded; anything else builds the view."""
        if name.startswith("_"):
            raise AttributeError(name)
        if name in REPLAYED or name in IGNORED or name in FORWARDED:
            return partial(self._call, name)
        return getattr(self.build(), name)

    def _call(self, name: str, *args: object, **kwargs: object) -> object:
        """A view method called on the stand-in (or a method of it kept from before)."""
        if self._real is None:
            if name in REPLAYED:
                self._calls.pop(name, None)  # the last call goes last
                self._calls[name] = (args, kwargs)
                return None
            if name in IGNORED:
                return None
        return getattr(self.build(), name)(*args, **kwargs)

    def build(self) -> QWidget:
        """Build the real view (once), put it in this stand-in's place and replay the calls."""
        if self._real is not None:
            return self._real
        view = self._factory()
        self._real = view
        view.setFocusPolicy(self.focusPolicy())
        parent = self.parentWidget()
        if isinstance(parent, QSplitter):
            parent.replaceWidget(parent.indexOf(self), view)
        elif parent is not None:
            view.setParent(parent)
        for name, (args, kwargs) in self._calls.items():
            getattr(view, name)(*args, **kwargs)
        self._calls.clear()
        self.setObjectName("")  # the real view has the name now
        self.hide()
        self.setParent(None)
        self.deleteLater()
        if self.built_view is not None:
            self.built_view(view)
        return view

    def paintEvent(self, event: QPaintEvent) -> None:
        """The view's background until it is there."""
        QPainter(self).fillRect(self.rect(), self._background)


class LazyPart:
    """Stands in for a part of the window built after its first paint (the traffic console,
    the parameter and device docks): the calls to its `recorded` methods are kept, all of them
    in order, and replayed on the real part when it is built; any other attribute builds it at
    once. `factory` builds the part (and makes it the window's own attribute); a method of the
    stand-in kept from before calls the real part's once it is built. `keep(name, args, kwargs)`,
    if given, returns the (args, kwargs) to keep for a call, such as the time it was made.
    """

    def __init__(
        self,
        factory: Callable[[], object],
        recorded: frozenset[str],
        keep: Callable[[str, tuple, dict], tuple[tuple, dict]] | None = None,
    ) -> None:
        self._factory = factory
        self._recorded = recorded
        self._keep = keep
        self._calls: list[tuple[str, tuple, dict]] = []
        self._real: object | None = None
        self._building = False

    def real(self) -> object | None:
        """The real part once built, else None."""
        return self._real

    def __getattr__(self, name: str) -> object:
        if name.startswith("_"):
            raise AttributeError(name)
        if name in self._recorded:
            return partial(self._call, name)
        return getattr(self.build(), name)

    def _call(self, name: str, *args: object, **kwargs: object) -> object:
        if self._real is None:
            if self._keep is not None:
                args, kwargs = self._keep(name, args, kwargs)
            self._calls.append((name, args, kwargs))
            return None
        return getattr(self._real, name)(*args, **kwargs)

    def build(self) -> object:
        """Build the real part (once) and replay the calls made on the stand-in, in order."""
        if self._real is None:
            if self._building:
                raise RuntimeError("a deferred part was used while it was being built")
            self._building = True
            try:
                real = self._factory()
            finally:
                self._building = False
            self._real = real
            self._factory = None  # type: ignore[assignment]  # (it holds the window)
            calls, self._calls = self._calls, []
            for name, args, kwargs in calls:
                getattr(real, name)(*args, **kwargs)
        return self._real


def built(part: object) -> bool:
    """Whether `part` is a real part (not a `LazyPart` still waiting to be built)."""
    return not isinstance(part, LazyPart)


class DeferredViews(QObject):
    """The window's 3D and 2D views, built once it has painted; then `window.view3d` and
    `window.view2d` are the real ones and `ready` is emitted.

    More building can be added (`add`), such as the window's `LazyPart`s (the traffic console
    and its timeline, the parameter and device docks) and its serial worker. `build_now()`
    builds everything at once (for a screenshot, or a window that is never shown).
    """

    usable = Signal()  # all but the views are built: the docks, the console, the menus
    ready = Signal()

    def __init__(self, window: QWidget, buffer: PositionBuffer | LazyPart) -> None:
        super().__init__(window)  # the window is reached as parent(): no reference cycle to it
        self.view3d = LazyView("positionView3d", partial(position_view_3d, buffer), BACKGROUND_3D)
        self.view2d = LazyView("positionView2d", partial(position_view_2d, buffer), BACKGROUND_2D)
        self.view3d.built_view = partial(self._built, "view3d")
        self.view2d.built_view = partial(self._built, "view2d")
        self._steps: list[Callable[[], object]] = []  # what `add` adds, run first
        self._view_steps: list[Callable[[], object]] = [  # the heaviest last
            *(partial(_preload, name) for name in PRELOADED),
            self.view3d.build,
            self.view2d.build,
        ]
        self._usable = False
        self._ready = False
        self._scheduled = False
        window.installEventFilter(self)

    def _built(self, name: str, view: QWidget) -> None:
        """A view is built: it is the window's `name` from now on."""
        setattr(self.parent(), name, view)

    def add(self, step: Callable[[], object], first: bool = False, plots: bool = False) -> None:
        """Run `step` too when building, before the views (it must be harmless to run twice);
        `first`: before the steps added so far (what the operator waits for); `plots`: with
        the views, once their libraries are imported (a step that imports pyqtgraph)."""
        if plots:
            self._view_steps.append(step)
        elif first:
            self._steps.insert(0, step)
        else:
            self._steps.append(step)

    def is_ready(self) -> bool:
        """Whether everything has been built."""
        return self._ready

    def is_usable(self) -> bool:
        """Whether all but the views has been built (`usable` was emitted)."""
        return self._usable

    def building(self) -> bool:
        """Whether the window has painted and what it needs to be used is still being built
        (the steps before the views)."""
        return self._scheduled and not self._usable

    def build_now(self) -> None:
        """Build whatever is not built yet; emits `usable` and `ready` the first time."""
        if self._ready:
            return
        self.parent().removeEventFilter(self)
        while self._left():
            self._run_one()
        self._finish()

    def _left(self) -> bool:
        """Whether a step (or `usable`, between the two kinds) is still to come."""
        return bool(self._steps or not self._usable or self._view_steps)

    def _run_one(self) -> None:
        """The next step (popped first: they may hold the window, none is kept once run)."""
        if self._steps:
            self._steps.pop(0)()
        elif not self._usable:  # a step of its own, between the two
            self._usable = True
            self.usable.emit()
        elif self._view_steps:
            self._view_steps.pop(0)()

    def _next_step(self) -> None:
        """One step a turn of the event loop, so that what arrives meanwhile (the device
        shown connected, a key, a repaint) waits for one step, not for all of them."""
        if self._ready:
            return
        self._run_one()
        if self._left():
            QTimer.singleShot(0, self, self._next_step)
        else:
            self._finish()

    def _finish(self) -> None:
        if not self._ready:
            self._ready = True
            log.info(VIEWS_BUILT)
            self.ready.emit()

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """At the window's first paint, build just after it (once the event loop is back)."""
        if event.type() == QEvent.Type.Paint and not self._scheduled:
            self._scheduled = True
            self.parent().removeEventFilter(self)
            QTimer.singleShot(0, self, self._next_step)
        return False
