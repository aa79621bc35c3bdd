"""The traffic console's lines shown, written out: as text, or as CSV for a `.csv` file."""

from __future__ import annotations

import csv
from pathlib import Path

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QFileDialog, QWidget

from app.window.console.table import CSV_COLUMNS, TrafficModel
from widgets import status_line
from widgets._i18n import fill


def ask_save_path(parent: QWidget) -> str:
    """Ask where to export the view (.txt or .csv); "" when cancelled."""
    csv_filter = QCoreApplication.translate("RawConsole", "CSV (*.csv)")
    filters = ";;".join(
        (
            QCoreApplication.translate("RawConsole", "Text (*.txt)"),
            csv_filter,
            QCoreApplication.translate("RawConsole", "All files (*)"),
        )
    )
    path, chosen = QFileDialog.getSaveFileName(
        parent, QCoreApplication.translate("RawConsole", "Export traffic"), "traffic.txt", filters
    )
    if path and chosen == csv_filter and not path.lower().endswith(".csv"):
        path += ".csv"
    return path


def exported_text(count: int, path: str | Path) -> str:
    """The confirmation of an export: `exported 12 lines to /tmp/traffic.txt`."""
    if count == 1:
        template = QCoreApplication.translate("RawConsole", "exported %1 line to %2")
    else:
        template = QCoreApplication.translate("RawConsole", "exported %1 lines to %2")
    return fill(template, count, str(path))


def tell_window(widget: QWidget, text: str, failed: bool = False) -> bool:
    """Show `text` on the status line of `widget`'s window (the StatusLine named statusLine),
    if it has one; whether it did."""
    line = widget.window().findChild(status_line.StatusLine, "statusLine")
    if line is None:
        return False
    line.show_message(text, status_line.FAILURE if failed else status_line.INFO)
    return True


def write_text(model: TrafficModel, path: str | Path, timestamps: bool) -> int:
    """Write the model's rows as text, one a line (with their time if `timestamps`); returns
    the lines written."""
    with Path(path).open("w", encoding="utf-8") as out:
        for row in range(len(model.rows)):
            out.write(model.row_text(row, timestamps) + "\n")
    return len(model.rows)


def write_csv(model: TrafficModel, path: str | Path) -> int:
    """Write the model's rows as CSV (CSV_COLUMNS: line, time, direction, kind, bytes, …, and
    the wall-clock time_iso last); returns the lines written."""
    with Path(path).open("w", encoding="utf-8", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(CSV_COLUMNS)
        for row in range(len(model.rows)):
            writer.writerow(model.csv_row(row))
    return len(model.rows)
