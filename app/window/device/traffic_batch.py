"""The traffic a worker hands to the GUI: batched, at most TRAFFIC_BATCH_S apart."""

from __future__ import annotations

import time
from collections.abc import Callable

from drivers.link.records import Traffic

TRAFFIC_BATCH_S = 0.05  # traffic is handed to the GUI at most this often (20 Hz)


class TrafficBatch:
    """Records kept until the batch is due (or flushed to keep order with a notice)."""

    def __init__(self, emit: Callable[[list[Traffic]], object]) -> None:
        self._emit = emit
        self._records: list[Traffic] = []
        self._sent = 0.0

    def add(self, record: Traffic) -> None:
        """Keep `record`; hand the batch over when one is due."""
        self._records.append(record)
        if record.time - self._sent >= TRAFFIC_BATCH_S:
            self.flush()

    def flush_if_due(self) -> None:
        """Hand the batch over when one is due (called while waiting on the device)."""
        if self._records and time.monotonic() - self._sent >= TRAFFIC_BATCH_S:
            self.flush()

    def flush(self) -> None:
        """Hand over what is kept now (so that what follows is shown after it)."""
        if self._records:
            records, self._records = self._records, []
            self._emit(records)
        self._sent = time.monotonic()
