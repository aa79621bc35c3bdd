"""`motionpanel`: the operator's window; with no arguments it opens on the simulated stage."""

from __future__ import annotations

import argparse
import logging
import signal
import sys
from collections.abc import Sequence

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QApplication

from app.common.i18n import LANGUAGES, install_translations, language_arg
from app.common.settings import DEFAULT_PORT, DEFAULT_PROTOCOL, open_settings
from app.startup_marks import watch_startup
from app.window.gc_main_thread import collect_for
from app.window.main_window import MainWindow
from app.window.preferences import read_preferences
from drivers.errors import BadInput, UnknownProtocol
from drivers.protocols.registry import get_protocol_class, protocol_names
from widgets.gl_share import share_opengl_contexts  # imports no OpenGL, no numpy

log = logging.getLogger("motionpanel")

SCREENSHOT_TIMEOUT_MS = 15000
SCREENSHOT_SETTLE_MS = 1500


def build_parser() -> argparse.ArgumentParser:
    """The argument parser for motionpanel."""
    parser = argparse.ArgumentParser(prog="motionpanel", description="Motion Panel control window.")
    parser.add_argument("--port", help=f"device path or pyserial URL (default {DEFAULT_PORT})")
    parser.add_argument("--protocol", choices=protocol_names(), help="default coxiris")
    parser.add_argument("--baud", type=int, help="line speed (default: the protocol's)")
    parser.add_argument(
        "--variant", help="the protocol's wire variant (visiomex: seed, prefixed, board12)"
    )
    parser.add_argument(
        "--screenshot",
        metavar="PATH",
        help="save a PNG of the window once connected and settled, then exit",
    )
    parser.add_argument(
        "--lang",
        metavar="CODE",
        type=language_arg,
        help=f"interface language: {', '.join(LANGUAGES)} (zh, zh-CN and zh_Hans are zh_CN;"
        " default: $MOTIONPANEL_LANG, else the one chosen in Settings, else the system locale,"
        " else en)",
    )
    parser.add_argument("-v", "--verbose", action="store_true", help="log on stderr")
    return parser


def take_screenshot(window: MainWindow, path: str, app: QApplication) -> None:
    """Once connected and settled, save the window to `path` and quit (0; 3 if not connected)."""
    done = False

    def shoot() -> None:
        nonlocal done
        if done:
            return
        done = True
        window.views.build_now()  # the views, console and docks, should they not be built yet
        window.view2d.refresh()
        refresh3d = getattr(window.view3d, "refresh", None)
        if refresh3d is not None:
            refresh3d()
        ok = window.grab().save(path, "PNG")
        if not ok:
            log.error("could not write %s", path)
        app.exit(0 if ok and window.connected else 3)

    window.settled.connect(lambda: QTimer.singleShot(SCREENSHOT_SETTLE_MS, shoot))
    QTimer.singleShot(SCREENSHOT_TIMEOUT_MS, shoot)


def saved_language() -> str:
    """The language chosen in Settings -> Language ("system": none chosen)."""
    return read_preferences(open_settings()).language


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of motionpanel; returns the exit status."""
    parser = build_parser()
    options = parser.parse_args(argv)
    logging.basicConfig(
        level=logging.INFO if options.verbose else logging.WARNING,
        format="motionpanel: %(message)s",
    )
    share_opengl_contexts()  # before the QApplication exists
    app = QApplication.instance() or QApplication(sys.argv[:1])
    app.setApplicationName("Motion Panel")
    install_translations(app, options.lang, saved=saved_language())  # before any widget
    window = MainWindow()
    # Collections from the event loop only; a full one waits while the console catches up.
    collect_for(app, window.views.ready, lambda: window.console.behind())
    signal.signal(signal.SIGINT, lambda *_: window.close())
    explicit = options.port or options.protocol or options.baud
    port = options.port or (DEFAULT_PORT if explicit or options.screenshot else None)
    protocol = options.protocol or DEFAULT_PROTOCOL
    if port is None:
        # No arguments: reconnect to the last port (the simulated stage the first time).
        bar = window.connection_bar
        port, protocol = bar.port(), bar.protocol()
        baud = bar.baud()
    else:
        baud = options.baud
    if options.variant:  # a wrong one is the command line's error, before any window shows
        try:
            baud = baud or get_protocol_class(protocol).default_baud(options.variant)
        except (BadInput, UnknownProtocol) as exc:
            parser.error(str(exc))
    if options.screenshot:
        take_screenshot(window, options.screenshot, app)
    _marks = watch_startup(window)  # bench/startup.py's (None: not asked for)

    def connect() -> None:
        """Just after the first paint: the protocol's module is imported (numpy, for some)."""
        rate = baud or get_protocol_class(protocol).default_baud(options.variant)
        window.connect_device(port, protocol, rate, options.variant)

    window.views.add(connect, first=True)
    window.show()
    status = app.exec()
    window.close()
    return status


if __name__ == "__main__":
    sys.exit(main())
