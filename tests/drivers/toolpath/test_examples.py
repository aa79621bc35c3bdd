"""The example programs shipped in resources/examples (the README tells new users to try them)
read and run to their last point on a simulated COXIRIS."""

from __future__ import annotations

from pathlib import Path

import pytest

from drivers import open_device
from drivers.toolpath.loader import load_toolpath

pytestmark = pytest.mark.timeout(60)

EXAMPLES = Path(__file__).resolve().parents[3] / "resources" / "examples"


@pytest.mark.parametrize(
    ("name", "layers", "last"),
    [
        ("part.nc", None, (2.0, 3.0)),
        ("art.svg", None, (30.0, 6.0)),
        ("drawing.dxf", ["CUT"], (28.0, 4.0)),
    ],
)
def test_each_example_runs_to_its_last_point(
    name: str, layers: list[str] | None, last: tuple[float, float]
) -> None:
    toolpath = load_toolpath(EXAMPLES / name, layers=layers)
    if name != "drawing.dxf":  # what the panel skips: the M-codes, a fill-only shape
        assert toolpath.notices
    assert toolpath.layers == (("CUT", "ENGRAVE") if layers else ())
    with open_device("sim://coxiris?instant=1", "coxiris") as stage:
        state = stage.run_program(toolpath)
        here = stage.position()
    assert state.finished and state.executed == state.total
    assert (here.x, here.y) == pytest.approx(last, abs=0.01)
