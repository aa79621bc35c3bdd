"""A process that writes or reads the kept counts of a settings file, as a panel or a motionctl
run does, for the tests that run several at once (tests/app/common/test_kept_positions.py).

`python -m tests.support.kept_count_proc write FILE PORT N`: counts (i, i, i) for i = 1..N on PORT;
`panel FILE N`: N other settings written and synced (a panel's geometry, its jog step);
`read FILE PORTS... --until N`: reads every port's count until each is (N, N, N), printing
`mixed` for a count that is not one writer's and `backwards` for one that goes back (a port
written by several, spelt `~PORT`, may go back: another writer is behind).
Each waits for a line on stdin before it starts, so that all start together.
"""

from __future__ import annotations

import sys
import time

from PySide6.QtCore import QSettings

from app.common.settings import read_counted_position, write_counted_position

PROTOCOL = "visiomex"
READ_FOR = 60.0  # s at most


def main(argv: list[str]) -> int:
    """Run one role; the exit status is 0 when it did what it was asked."""
    role, path = argv[0], argv[1]
    settings = QSettings(path, QSettings.Format.IniFormat)
    settings.value("geometry")  # read, as a panel has read it at start
    sys.stdin.readline()  # the start
    if role == "write":
        port, count = argv[2], int(argv[3])
        for i in range(1, count + 1):
            write_counted_position(settings, PROTOCOL, port, (float(i), float(i), float(i)))
        return 0
    if role == "panel":
        for i in range(int(argv[2])):
            settings.setValue("geometry", f"{i:06d}")
            settings.sync()
        return 0
    shared = {p[1:] for p in argv[2:-2] if p.startswith("~")}
    ports, until = [p.lstrip("~") for p in argv[2:-2]], int(argv[-1])
    seen = dict.fromkeys(ports, 0.0)
    end = time.monotonic() + READ_FOR
    while time.monotonic() < end and any(v < until for v in seen.values()):
        for port in ports:
            here = read_counted_position(settings, PROTOCOL, port)
            if here is None:
                continue
            if len(set(here)) != 1:
                print(f"mixed {port} {here}", flush=True)
            elif here[0] < seen[port] and port not in shared:
                print(f"backwards {port} {seen[port]} -> {here[0]}", flush=True)
            seen[port] = max(seen[port], here[0])
    print("seen " + " ".join(f"{p}={v:g}" for p, v in seen.items()), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
