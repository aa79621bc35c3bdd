"""COXIRIS numbers on the wire: parsed into a float, printed by Arduino's Print::printFloat."""

from __future__ import annotations

import random
import shutil
import subprocess
from pathlib import Path

import pytest

from drivers.sim.arduino import print_float
from drivers.sim.arduino import to_float32 as float32
from drivers.sim.clock import ManualClock
from drivers.sim.coxiris_device import CoxirisDevice

pytestmark = pytest.mark.timeout(60)

# Expected texts come from Print::printFloat compiled with a 32-bit double, as on an AVR.
PRINTED_2_DIGITS = [
    ("0.125", "0.12"),  # 0.125 + 0.005 rounds down in float
    ("0.005", "0.00"),
    ("2.675", "2.68"),
    ("1.005", "1.00"),
    ("0.995", "1.00"),
    ("99.995", "100.00"),
    ("1.999", "2.00"),
    ("-0.005", "-0.00"),
    ("-0.0049", "-0.00"),
    ("-0", "0.00"),
    ("123456.789", "123456.79"),
    ("-123456.789", "-123456.79"),
    ("16777217", "16777216.00"),  # beyond 2^24 floats are even
    ("1000000000.5", "1000000000.00"),
    ("2147483647.99", "2147483648.00"),
    ("65535.995", "65536.00"),
    ("4294967040", "4294967040.00"),  # the largest float printed as a number
    ("-4294967040", "-4294967040.00"),
    ("4294967168", "ovf"),  # halfway: rounds to 2^32
    ("-4294967169", "ovf"),
    ("0.0000000000000000000000000000000000000000000014", "0.00"),  # the smallest denormal
    ("340282350000000000000000000000000000000", "ovf"),  # rounds to FLT_MAX
    ("-340282350000000000000000000000000000000", "ovf"),
    ("340282370000000000000000000000000000000", "inf"),
    ("-340282370000000000000000000000000000000", "inf"),  # no sign on infinities
]
PRINTED_0_DIGITS = [
    ("1", "1"),
    ("1.49", "1"),
    ("1.5", "2"),
    ("2.5", "3"),
    ("12.5", "13"),
    ("99.5", "100"),
    ("100", "100"),
]


def _ask(device: CoxirisDevice, clock: ManualClock, text: bytes) -> bytes:
    device.receive(text)
    clock.advance(0.01)
    return device.read_output()


@pytest.mark.parametrize(("number", "text"), PRINTED_2_DIGITS)
def test_position_prints_like_printfloat(number: str, text: str) -> None:
    clock = ManualClock()
    device = CoxirisDevice(clock, instant=True)
    _ask(device, clock, f"ABSOLUTE_MOVE 0 {number} 0\n".encode())
    reply = _ask(device, clock, b"GET_POSITION\n")
    assert reply == f"ACK GET_POSITION\r\nDONE GET_POSITION: 0.00 {text} 0.00\r\n".encode()


@pytest.mark.parametrize(("number", "text"), PRINTED_0_DIGITS)
def test_speed_prints_like_printfloat_with_no_decimals(number: str, text: str) -> None:
    clock = ManualClock()
    device = CoxirisDevice(clock)
    assert _ask(device, clock, f"SET_SPEED {number}\n".encode()) == (
        b"ACK SET_SPEED\r\nDONE SET_SPEED\r\n"
    )
    assert _ask(device, clock, b"GET_SPEED\n").endswith(f": {text}\r\n".encode())


_PRINTFLOAT_C = r"""
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
/* Print::printFloat's rules with double == float, as on an AVR. */
static void print_float(float number, int digits) {
  if (isnan(number)) { puts("nan"); return; }
  if (isinf(number)) { puts("inf"); return; }
  if (number > 4294967040.0f || number < -4294967040.0f) { puts("ovf"); return; }
  if (number < 0.0f) { putchar('-'); number = -number; }
  float rounding = 0.5f;
  for (int i = 0; i < digits; ++i) rounding /= 10.0f;
  number += rounding;
  unsigned long int_part = (unsigned long)number;
  float remainder = number - (float)int_part;
  printf("%lu", int_part);
  if (digits > 0) putchar('.');
  while (digits-- > 0) {
    remainder *= 10.0f;
    unsigned int digit = (unsigned int)remainder;
    printf("%u", digit);
    remainder -= (float)digit;
  }
  putchar('\n');
}
int main(void) {
  int digits; char text[128];
  while (scanf("%d %127s", &digits, text) == 2) print_float((float)strtod(text, NULL), digits);
  return 0;
}
"""


def _seeded_numbers(count: int) -> list[tuple[int, str]]:
    """Decimal numbers as a client would send them: small, large, negative, halfway cases."""
    rng = random.Random(11)
    numbers = []
    for _ in range(count):
        kind = rng.randrange(4)
        if kind == 0:
            text = f"{rng.uniform(-1000, 1000):.{rng.randint(0, 6)}f}"
        elif kind == 1:
            whole = rng.randint(0, 10 ** rng.randint(1, 12))
            text = f"{rng.choice('+-')}{whole}.{rng.randint(0, 999)}"
        elif kind == 2:
            text = f"{rng.choice((-1, 1)) * rng.randint(0, 2**33) / 100:.2f}"
        else:
            text = f"{rng.randint(0, 999)}.{rng.choice(('005', '015', '125', '995', '5', '375'))}"
        numbers.append((rng.choice((0, 2)), text))
    return numbers


@pytest.mark.skipif(shutil.which("cc") is None, reason="needs a C compiler")
def test_seeded_numbers_print_as_the_compiled_printfloat(tmp_path: Path) -> None:
    source, program = tmp_path / "printfloat.c", tmp_path / "printfloat"
    source.write_text(_PRINTFLOAT_C)
    subprocess.run(["cc", "-O0", "-o", str(program), str(source), "-lm"], check=True, timeout=30)
    numbers = _seeded_numbers(20_000)
    lines = "".join(f"{digits} {text}\n" for digits, text in numbers)
    result = subprocess.run([str(program)], input=lines, capture_output=True, text=True, timeout=30)
    expected = result.stdout.splitlines()
    got = [print_float(float32(float(text)), digits) for digits, text in numbers]
    mismatches = [(n, g, e) for n, g, e in zip(numbers, got, expected, strict=True) if g != e]
    assert mismatches == []
