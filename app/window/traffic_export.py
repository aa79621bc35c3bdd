"""The traffic console's lines shown, written out: as text, or as CSV for a `.csv` file."""

from __future__ import annotations

import csv
from pathlib import Path

from PySide6.QtCore import QCoreApplication
from PySide6.QtWidgets import QFileDialog, QWidget

from app.window.traffic_table import CSV_COLUMNS, TrafficModel


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
