"""A bench file: every device checked before any port is opened, each refusal saying why."""

from __future__ import annotations

from pathlib import Path

import pytest

from drivers import BenchDevice, BenchError, read_bench
from drivers.session.bench import parse_bench

pytestmark = pytest.mark.timeout(30)

GOOD = """
[devices.stage]
port = "/dev/ttyUSB0"
protocol = "coxiris"
travel = { x = [-100, 100], y = [-50, 50.5], z = [0, 20] }
speed = 10

[devices.rotary]
port = "sim://visiomex"
protocol = "visiomex"
variant = "prefixed"
timeout = 5

[devices.head]
port = "/dev/ttyACM0"
protocol = "pi-frame"
baud = 57600
travel = "-10:10,-10:10,0:5"
settings = { ticks_per_mm = 250 }
"""


def test_a_bench_names_its_devices_in_the_files_order() -> None:
    devices = parse_bench(GOOD)
    assert list(devices) == ["stage", "rotary", "head"]
    assert devices["stage"] == BenchDevice(
        "stage", "/dev/ttyUSB0", "coxiris", travel="-100:100,-50:50.5,0:20", speed=10.0
    )
    assert devices["rotary"].variant == "prefixed" and devices["rotary"].timeout == 5.0
    head = devices["head"]
    assert (head.baud, head.travel, dict(head.settings)) == (
        57600,
        "-10:10,-10:10,0:5",
        {"ticks_per_mm": 250.0},
    )


def test_read_from_a_file(tmp_path: Path) -> None:
    path = tmp_path / "bench.toml"
    path.write_text(GOOD, encoding="utf-8")
    assert list(read_bench(path)) == ["stage", "rotary", "head"]


def test_a_file_that_is_not_there_is_refused(tmp_path: Path) -> None:
    with pytest.raises(BenchError, match="cannot read the bench file"):
        read_bench(tmp_path / "none.toml")


def _device(lines: str) -> str:
    return f'[devices.one]\nport = "/dev/ttyUSB0"\nprotocol = "coxiris"\n{lines}\n'


@pytest.mark.parametrize(
    ("text", "why"),
    [
        ("[devices", "not a bench file"),
        ("name = 'lab'\n", "unknown key 'name'"),
        ("", "no devices"),
        ("[devices.'a b']\nport = 'x'\nprotocol = 'coxiris'\n", "a name of 1 to 32 letters"),
        (_device("speeed = 3"), r"bench:1: device 'one': unknown key 'speeed'"),
        ('[devices.one]\nprotocol = "coxiris"\n', "port: the device path"),
        ('[devices.one]\nport = "x"\nprotocol = "grbl"\n', "protocol: one of coxiris, "),
        ('[devices.one]\nport = "x"\nprotocol = "visiomex"\nvariant = "v9"\n', "v9"),
        (_device("baud = 0"), "baud: a positive number"),
        (_device("baud = 9600.5"), "baud: a whole number"),
        (_device("speed = -1"), "speed: a positive number"),
        (_device("speed = true"), "speed: a positive number"),
        (_device("timeout = 0"), "timeout: a positive number"),
        (_device("settings = { ticks_per_mm = 100 }"), "'ticks_per_mm' is not one of"),
        (_device("travel = '0:10,0:10'"), "three ranges"),
        (_device("travel = { x = [0, 10], y = [0, 10] }"), r"travel: z = \[lowest, highest\]"),
        (_device("travel = { x = [0, 10], y = [0, 10], z = [0, 1], w = [0, 1] }"), "x, y and z"),
        (_device("travel = 5"), "travel: 'X0:X1"),
    ],
)
def test_a_wrong_bench_is_refused_saying_why(text: str, why: str) -> None:
    with pytest.raises(BenchError, match=why):
        parse_bench(text)
