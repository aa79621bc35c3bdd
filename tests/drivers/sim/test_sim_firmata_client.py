"""An ordinary Firmata client library opens the simulated FirmataPlus board over a pty."""

from __future__ import annotations

import pyfirmata2
import pytest

from tests.support.simproc import SimProcess


@pytest.mark.e2e
@pytest.mark.timeout(30)
def test_pyfirmata2_opens_the_simulated_board() -> None:
    sim = SimProcess("firmata", "--reset-delay", "0.3")
    try:
        # pyFirmata2 waits for the reset, then asks the version, the firmware, the capabilities
        # and the analog mapping, and builds its pin layout from the answers.
        board = pyfirmata2.Arduino(sim.path)
        try:
            assert board.firmware == "FirmataPlus.ino"
            assert board.firmware_version == (2, 5)
            assert board.get_firmata_version() == (2, 5)
            assert (len(board.digital), len(board.analog)) == (14, 6)
        finally:
            board.exit()
    finally:
        assert sim.stop() == 0
