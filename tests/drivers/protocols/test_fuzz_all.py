"""Fuzzing every framer, decoder and file reader: any bytes in, only the project's errors out.

For each registered protocol, the five built-in ones and any installed plugin's (every wire
variant): the framers (RX and TX) fed any stream in any chunking make progress, keep bounded
memory and frame alike however the bytes arrive; the decoder, `describe_sent`, `sent_kind`,
`expects_reply`, `check_raw`, `raw_exchange` and the reply trackers take anything;
`StreamDecoder` and `TrafficIndex` take any traffic and read every
line back; the log, spy, profile and program readers take any text or bytes. The streams mix
valid frames (encoded commands, documented replies) with their mutations and pure noise, so the
fuzzer reaches deep into the decoders. Regression tests for what it found are at the end.
"""

from __future__ import annotations

import contextlib
import json
import re
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from drivers.device.param_profile import ProfileError, parse_profile, read_profile
from drivers.errors import BadInput, FrameError, MotionError
from drivers.framers.base import Framer
from drivers.framers.stuffed import StuffedFramer
from drivers.link.records import Traffic, hexdump_lines
from drivers.protocols import commands as cmd
from drivers.protocols.base import Exchange, Reply
from drivers.protocols.events import (
    Ack,
    Done,
    ErrorReport,
    Event,
    Feedback,
    PositionReport,
    TextLine,
    Undecodable,
)
from drivers.protocols.firmata import StepperConfig, StepperStep, StepperVersion, seven_bit_pairs
from drivers.protocols.laser.codec import (
    CHAR,
    FLOAT,
    INT16,
    UINT8,
    Field,
    Instruction,
    decode_instructions,
)
from drivers.protocols.laser.protocol import GetStatus, LaserReply, QueuedGroup
from drivers.protocols.registry import BUILT_IN, create_protocol, get_protocol_class, protocol_names
from drivers.protocols.visiomex.params import PARAMETERS as VISIOMEX_PARAMETERS
from drivers.sim.clock import ManualClock
from drivers.sim.registry import create_device, simulator_names
from drivers.toolpath.point_program import ProgramError, parse_csv, parse_json, read_program
from drivers.traffic.decoding import DecodedFrame, StreamDecoder, decode_records
from drivers.traffic.index import TrafficIndex
from drivers.traffic.lines import KINDS
from drivers.traffic.log_reader import LogError, LogRecord, parse_log, read_any_log, read_log
from drivers.traffic.search import FilterError, compile_filter
from drivers.traffic.spy_log import _row, parse_spy

pytestmark = pytest.mark.timeout(120)

FUZZ = settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.too_slow])
SENT_KINDS = {"motion", "query", "poll", "setting"}


def _all_variants() -> list[tuple[str, str | None]]:
    out = []
    for name in protocol_names():
        variants = get_protocol_class(name).variants
        out += [(name, v.name) for v in variants] if variants else [(name, None)]
    return out


VARIANTS = _all_variants()
IDS = [f"{n}-{v}" if v else n for n, v in VARIANTS]
assert {n for n, _ in VARIANTS} == set(protocol_names())  # every registered one, plugins too

# -- valid material to start from ---------------------------------------------------------------

COMMANDS: list[cmd.Command] = [
    cmd.GetId(),
    cmd.GetPosition(),
    cmd.GetSpeed(),
    cmd.Help(),
    cmd.Home(),
    cmd.SetHome(),
    cmd.CheckErrors(),
    cmd.Stop(),
    cmd.MoveTo(1, 2, 3),
    cmd.MoveTo(-0.5, 0, 0, 20),
    cmd.MoveBy(1, 2, 0),
    cmd.MoveBy(-3, 0, 0, "steps"),
    cmd.MoveBy(400, 0, 0),
    cmd.SetSpeed(5),
    cmd.Dwell(250),
    cmd.Arc(0, 0, 5, 0, 90, True, 1),
    cmd.SetParameter(3, 38.2),
    cmd.SetParameter(21, 12),
    cmd.Raw(b"FOO\n"),
    cmd.Raw(b"G"),
    cmd.Raw(b"S01000010NNNNNNNNN"),
    GetStatus(),
    QueuedGroup((Instruction(0x01, (Field(FLOAT, (1.0, 2.0, 3.0, 10.0)),)),) * 3, 77),
    StepperConfig(200, (8, 9)),
    StepperStep(300, -500),
    StepperVersion(),
]


def _laser(*instructions: Instruction) -> bytes:
    return StuffedFramer().encode(b"".join(i.encode() for i in instructions))


REPLIES: dict[str, list[bytes]] = {
    "coxiris": [
        line + b"\r\n"
        for line in (
            b"ACK GET_ID",
            b"DONE GET_ID: CX25F7TK9P",
            b"ACK GET_POSITION",
            b"DONE GET_POSITION: 1.00 2.00 3.00",
            b"DONE GET_POSITION: ovf 1 2",
            b"ACK GET_SPEED",
            b"DONE GET_SPEED: nan",
            b"DONE GET_SPEED: 1_0",
            b"ERROR: Unknown command - ",
            b"FOO",
            b"Available commands:",
            b"ERROR: Command too long",
            b"ACK ABSOLUTE_MOVE",
            b"DONE ABSOLUTE_MOVE",
            b"ACK HELP",
            b"DONE HELP",
            b"DONE",
            b"ACK",
        )
    ],
    "visiomex": [
        line + b"\r\n"
        for line in (
            b"FP0001",
            b"FA0001",
            b"FS0003",
            b"FS0021",
            b"FS0028",
            b"FS9999",
            b"EP0003",
            b"EF0002",
            b"EP0042",
            b">FP0001",
            b">FA0001",
            b">FS0003",
            b">EP0001",
            b"steps x: 400",
        )
    ],
    "firmata": [
        bytes.fromhex("F9 02 05"),
        bytes.fromhex("F0 79 02 05") + seven_bit_pairs(b"Stepper.ino") + b"\xf7",
        bytes.fromhex("F0 72 05 00 F7"),
        b"\xf0\x71" + seven_bit_pairs(b"stepper error: bad pins") + b"\xf7",
        b"\xf0\x71" + seven_bit_pairs(b"hello") + b"\xf7",
        bytes.fromhex("E0 01 02"),
        bytes.fromhex("91 7F 01"),
        bytes.fromhex("C0 01"),
        bytes.fromhex("F0 6C 7F F7"),
        bytes.fromhex("F0 79 F7"),
    ],
    "laser-frame": [
        _laser(Instruction(0x10, (Field(FLOAT, (1.0, 2.0, 3.0)),))),
        _laser(Instruction(0x10, (Field(FLOAT, (1.0,)),))),
        _laser(Instruction(0x11, (Field(UINT8, (3, 1)),))),
        _laser(Instruction(0x14, (Field(CHAR, tuple("LSR-01")),))),
        _laser(Instruction(0x12)),
        _laser(Instruction(0x13)),
        _laser(Instruction(0x20, (Field(INT16, (77, 1234)),))),
        _laser(Instruction(0x20, (Field(INT16, (78,)),))),
        *(_laser(Instruction(0x7F, (Field(UINT8, (w, c)),))) for w, c in ((0x20, 1), (0x10, 2))),
        *(_laser(Instruction(0x7F, (Field(UINT8, (0x20, c)),))) for c in (3, 4, 5, 9)),
        _laser(Instruction(0x7F)),
        _laser(Instruction(0x01), Instruction(0x02, (Field(INT16, (5,)),))),
    ],
    "pi-frame": [],  # the board sends nothing; an echo of what was sent is framed like it
}


def sent_samples(protocol) -> list[bytes]:
    """What the host sends for the sample commands the protocol takes."""
    samples = []
    for command in COMMANDS:
        try:
            samples.append(protocol.encode(command))
        except MotionError:
            continue
    return [s for s in samples if s]


# Bytes that mean something to some decoder: line ends, NUL, DEL, the stuffing escape, SysEx
# bounds, latin-1 superscripts (str.isdigit() takes them, int() does not), 0xFF.
ODD_BYTE = st.integers(0, 255) | st.sampled_from(
    [0x00, 0x0A, 0x0D, 0x20, 0x2D, 0x30, 0x39, 0x7F, 0x80, 0x82, 0x90, 0xB2, 0xB9, 0xF0, 0xF7, 0xFF]
)


def mutations(sample: bytes) -> st.SearchStrategy[bytes]:
    """The sample, cut short, its head lost, a byte changed, bytes slipped in or doubled."""
    size = len(sample)
    return st.one_of(
        st.just(sample),
        st.integers(0, size).map(lambda i: sample[:i]),
        st.integers(0, size).map(lambda i: sample[i:]),
        st.tuples(st.integers(0, max(size - 1, 0)), ODD_BYTE).map(
            lambda t: sample[: t[0]] + bytes((t[1],)) + sample[t[0] + 1 :]
        ),
        st.tuples(st.integers(0, size), st.lists(ODD_BYTE, min_size=1, max_size=4).map(bytes)).map(
            lambda t: sample[: t[0]] + t[1] + sample[t[0] :]
        ),
        st.just(sample * 2),
    )


def stream_of(samples: list[bytes], max_pieces: int = 10) -> st.SearchStrategy[bytes]:
    """Valid frames, their mutations and noise, run together."""
    pieces = [st.binary(max_size=48), st.sampled_from([b"\r", b"\n", b"\r\n", b"\x90", b"\xf7"])]
    if samples:
        pieces += [st.sampled_from(samples), st.sampled_from(samples).flatmap(mutations)]
    return st.lists(st.one_of(*pieces), max_size=max_pieces).map(b"".join)


def test_the_sample_replies_are_of_built_in_protocols() -> None:
    """No sample replies left of a protocol gone (one without them uses its simulator's)."""
    assert set(REPLIES) <= {entry.name for entry in BUILT_IN}


def simulated_replies(name: str) -> list[bytes]:
    """What the protocol's simulator answers to the sample commands (for a protocol without
    replies written out in REPLIES, a plugin's)."""
    if name not in simulator_names():
        return []
    protocol, clock = create_protocol(name), ManualClock()
    device = create_device(name, clock, instant=True)
    device.boot()
    out = []
    for frame in sent_samples(protocol):
        device.receive(frame)
        clock.advance(1.0)
        out.append(device.read_output())
    return [reply for reply in out if reply]


_SIMULATED: dict[str, list[bytes]] = {}


def replies_of(name: str) -> list[bytes]:
    """The sample replies of a protocol: written out, or its simulator's."""
    if name in REPLIES:
        return REPLIES[name]
    if name not in _SIMULATED:
        _SIMULATED[name] = simulated_replies(name)
    return _SIMULATED[name]


def samples_for(protocol) -> list[bytes]:
    return replies_of(protocol.name) + sent_samples(protocol)


def chunked(data: bytes) -> st.SearchStrategy[list[bytes]]:
    """`data` cut anywhere into pieces (as a port delivers it)."""
    return st.lists(st.integers(0, len(data)), max_size=8).map(
        lambda cuts: [
            data[a:b] for a, b in zip([0, *sorted(cuts)], [*sorted(cuts), len(data)], strict=True)
        ]
    )


# -- framers ------------------------------------------------------------------------------------


def _bound(framer: Framer) -> int:
    """Most bytes a framer may keep waiting (a stuffed frame's data can be twice its size)."""
    limit = getattr(framer, "max_length", None) or getattr(framer, "length", 0)
    return 2 * limit + 16


def run_framer(framer: Framer, chunks: list[bytes]) -> tuple[list[bytes], bytes]:
    """Feed chunks as StreamDecoder does, checking progress and memory at each step."""
    frames: list[bytes] = []
    rest = b""
    for chunk in chunks:
        buffer = rest + chunk
        for _ in range(len(buffer) + 1):  # every step takes at least one byte, or stops
            used, frame = framer.decode(buffer)
            assert 0 <= used <= len(buffer), (used, buffer)
            if frame is not None:
                assert isinstance(frame, bytes)
                assert used > 0, "a frame given without taking its bytes"
                frames.append(frame)
            if used == 0:
                break
            buffer = buffer[used:]
        else:
            pytest.fail(f"the framer did not stop on {buffer!r}")
        rest = buffer
        assert len(rest) <= _bound(framer), f"{len(rest)} bytes kept waiting"
        split_frames, split_rest = type(framer).split(framer, rest)
        assert (split_frames, split_rest) == ([], rest)  # split agrees: nothing more to take
    used, frame = framer.flush(rest)
    assert 0 <= used <= len(rest)
    if frame is not None:
        frames.append(frame)
    return frames, rest


def framers_of(protocol, small: bool) -> list[Framer]:
    framers = [protocol.new_framer(), protocol.new_tx_framer()]
    framers = [f for f in framers if f is not None]
    if small:  # a short bound, so that the fuzzer reaches the over-long paths
        for framer in framers:
            if hasattr(framer, "max_length"):
                framer.max_length = 24
    return framers


@pytest.mark.parametrize(("name", "variant"), VARIANTS, ids=IDS)
@FUZZ
@given(data=st.data(), small=st.booleans())
def test_framers_progress_bounded_and_delivery_independent(name, variant, data, small) -> None:
    protocol = create_protocol(name, variant)
    stream = data.draw(stream_of(samples_for(protocol)), "stream")
    chunks = data.draw(chunked(stream), "chunks")
    for index, framer in enumerate(framers_of(protocol, small)):
        whole = framers_of(protocol, small)[index]
        assert run_framer(framer, chunks) == run_framer(whole, [stream])


@pytest.mark.parametrize(("name", "variant"), VARIANTS, ids=IDS)
@settings(max_examples=10, deadline=None)
@given(noise=st.binary(min_size=1, max_size=16))
def test_framers_bounded_on_a_long_stream(name, variant, noise) -> None:
    """20 KiB of one repeated pattern, 1 KiB at a time, with the real bounds."""
    protocol = create_protocol(name, variant)
    stream = (noise * (20480 // len(noise) + 1))[:20480]
    for framer in framers_of(protocol, small=False):
        run_framer(framer, [stream[i : i + 1024] for i in range(0, len(stream), 1024)])


# -- decoders and sent-frame helpers --------------------------------------------------------------


def check_events(events: object) -> list[Event]:
    assert isinstance(events, list)
    for event in events:
        assert isinstance(event, Event)
        assert isinstance(str(event), str)
    return events


def decode_or_none(protocol, frame: bytes) -> list[Event] | None:
    try:
        return check_events(protocol.decode(frame))
    except FrameError:
        return None


def check_sent(protocol, frame: bytes) -> None:
    assert isinstance(protocol.describe_sent(frame), str)
    assert protocol.sent_kind(frame) in SENT_KINDS
    assert isinstance(protocol.expects_reply(frame), bool)
    with contextlib.suppress(BadInput):
        protocol.check_raw(frame)


def raw_exchange_or_none(protocol, data: bytes) -> Exchange | None:
    """`raw_exchange`: None, a tracker, or (Visiomex: a packet it cannot send) BadInput."""
    try:
        exchange = protocol.raw_exchange(data)
    except BadInput:
        return None
    assert exchange is None or isinstance(exchange, Exchange)
    return exchange


def feed_exchange(exchange: Exchange, events: list[Event]) -> None:
    """Events in; only booleans, and at the end a Reply or a project error, come out."""
    for event in events:
        assert isinstance(exchange.on_event(event), bool)
        assert isinstance(exchange.finished, bool)
        assert isinstance(exchange.wants_more, bool)
    if exchange.finished:
        with contextlib.suppress(MotionError):
            assert isinstance(exchange.result(), Reply)


def frame_candidates(protocol, stream: bytes) -> list[bytes]:
    """The stream itself, and what each framer makes of it."""
    frames = [stream]
    for framer in framers_of(protocol, small=False):
        frames += framer.split(stream)[0]
    return frames


@pytest.mark.parametrize(("name", "variant"), VARIANTS, ids=IDS)
@FUZZ
@given(data=st.data())
def test_decoders_take_any_frame(name, variant, data) -> None:
    protocol = create_protocol(name, variant)
    stream = data.draw(stream_of(samples_for(protocol), max_pieces=4), "stream")
    samples = st.sampled_from(samples_for(protocol))
    mutant = data.draw(samples.flatmap(mutations).flatmap(mutations), "mutant")
    for frame in [mutant, *frame_candidates(protocol, stream)]:
        decode_or_none(protocol, frame)
        check_sent(protocol, frame)
        exchange = raw_exchange_or_none(protocol, frame)
        if exchange is not None:
            feed_exchange(exchange, decode_or_none(protocol, frame) or [])


def _instructions_or_empty(data: bytes) -> list[Instruction]:
    try:
        return decode_instructions(data)
    except FrameError:
        return []


TEXT = st.text(max_size=24)
BUILT_EVENTS = st.one_of(
    st.builds(Ack, TEXT),
    st.builds(Done, TEXT, st.none() | TEXT),
    st.builds(ErrorReport, TEXT, st.none() | st.sampled_from(["EP0003", "EF0001", "XX"]) | TEXT),
    st.builds(TextLine, TEXT),
    st.builds(
        Feedback,
        st.sampled_from(["FP0001", "FA0001", "FS0003", "FS", "version", "firmware"]) | TEXT,
        st.binary(max_size=8),
        TEXT,
    ),
    st.builds(PositionReport, st.floats(), st.floats(), st.floats()),
    st.builds(Undecodable, st.binary(max_size=8), TEXT),
    st.binary(max_size=40).map(lambda b: LaserReply(tuple(_instructions_or_empty(b)))),
)


@pytest.mark.parametrize(("name", "variant"), VARIANTS, ids=IDS)
@FUZZ
@given(data=st.data())
def test_reply_trackers_take_any_events(name, variant, data) -> None:
    protocol = create_protocol(name, variant)
    stream = data.draw(stream_of(replies_of(name) or sent_samples(protocol)), "replies")
    events: list[Event] = []
    for frame in protocol.new_framer().split(stream)[0]:
        events += decode_or_none(protocol, frame) or []
    built = data.draw(st.lists(BUILT_EVENTS, max_size=4), "built")
    at = data.draw(st.integers(0, len(events)), "at")
    events[at:at] = built
    exchanges = []
    for command in COMMANDS:
        with contextlib.suppress(BadInput):
            exchanges.append(protocol.exchange(command))
    for sample in sent_samples(protocol):
        exchange = raw_exchange_or_none(protocol, sample)
        if exchange is not None:
            exchanges.append(exchange)
    assert exchanges
    for exchange in exchanges:
        feed_exchange(exchange, events)


# -- StreamDecoder and TrafficIndex ---------------------------------------------------------------

DIRECTION = st.sampled_from(["tx", "rx"])


def traffic_of(protocol) -> st.SearchStrategy[list[tuple[str, bytes]]]:
    tx = stream_of(sent_samples(protocol), max_pieces=3)
    rx = stream_of(replies_of(protocol.name) or sent_samples(protocol), max_pieces=3)
    return st.lists(
        st.one_of(st.tuples(st.just("tx"), tx), st.tuples(st.just("rx"), rx)), max_size=10
    )


def check_decoded(frame: DecodedFrame, direction: str) -> None:
    assert frame.direction == direction
    assert frame.kind in ("frame", "error", "text")
    assert isinstance(frame.meaning, str)
    assert isinstance(frame.line(), str)
    assert frame.as_dict()["direction"] == direction


@pytest.mark.parametrize(("name", "variant"), VARIANTS, ids=IDS)
@FUZZ
@given(data=st.data())
def test_stream_decoder_takes_any_traffic(name, variant, data) -> None:
    protocol = create_protocol(name, variant)
    traffic = data.draw(traffic_of(protocol), "traffic")
    decoder = StreamDecoder(protocol)
    for time, (direction, chunk) in enumerate(traffic):
        for frame in decoder.feed_bytes(direction, chunk, float(time)):
            check_decoded(frame, direction)
        for pending_direction in ("tx", "rx"):
            assert len(decoder.pending(pending_direction)) <= 2 * 4096 + 16
    records = [LogRecord(float(t), d, b) for t, (d, b) in enumerate(traffic)]
    records.append(LogRecord(99.0, "", b"", "a note"))
    frames = decode_records(protocol, records)
    assert frames[-1].kind == "note"


@pytest.mark.parametrize(("name", "variant"), VARIANTS, ids=IDS)
@settings(FUZZ, max_examples=35)
@given(data=st.data())
def test_replayed_reply_trackers_pair_as_live_ones(name, variant, data) -> None:
    """The index replays what a request's reply tracker did for an earlier copy of it (its
    script) instead of building the tracker: the pairing, kinds and copies must be the same as
    with every tracker built and fed live. Traffic is repeated so that scripts are replayed."""
    protocol = create_protocol(name, variant)
    whole = [("tx", frame) for frame in sent_samples(protocol)]  # whole frames: trackers engage
    whole += [("rx", frame) for frame in replies_of(protocol.name)]
    vocabulary = st.lists(st.sampled_from(whole), min_size=2, max_size=6, unique=True)
    exchanges = vocabulary.flatmap(lambda words: st.lists(st.sampled_from(words), max_size=60))
    traffic = data.draw(st.one_of(exchanges, traffic_of(protocol)), "traffic") * 3
    replayed, live = TrafficIndex(protocol), TrafficIndex(create_protocol(name, variant))
    live._pairing._scripts.MAX_DEPTH = 0  # nothing learnt: each tracker is built at its first frame
    try:
        for step, (direction, chunk) in enumerate(traffic):
            for index in (replayed, live):
                index.add(direction, chunk, step * 0.5)
        assert len(replayed) == len(live)
        for number in range(len(live)):  # (compared as text: NaN is not equal to itself)
            assert repr(replayed.line(number)) == repr(live.line(number))
        assert repr(replayed.take_latencies()) == repr(live.take_latencies())
    finally:
        replayed.close()
        live.close()


def test_replayed_scripts_tell_apart_frames_that_end_differently() -> None:
    """Found by the test above: `\x01\n` and `\x01\r` are the same text, not the same frame
    (their trackers differ), so a script learnt from one must not be replayed for the other.
    (Found with NUL, which COXIRIS now reads as an empty command: no reply is followed.)"""
    traffic = [("rx", b"\r\x80"), ("tx", b"\x01\n\x01\r")] * 3
    replayed, live = (
        TrafficIndex(create_protocol("coxiris")),
        TrafficIndex(create_protocol("coxiris")),
    )
    live._pairing._scripts.MAX_DEPTH = 0
    try:
        for step, (direction, chunk) in enumerate(traffic):
            for index in (replayed, live):
                index.add(direction, chunk, step * 0.5)
        assert [repr(replayed.line(n)) for n in range(len(replayed))] == [
            repr(live.line(n)) for n in range(len(live))
        ]
        assert live.line(4).pair == 5
    finally:
        replayed.close()
        live.close()


def _spool_text(index: TrafficIndex, line: int) -> bytes:
    """A line's text in the spool, without its newline (what a filter is matched against)."""
    import os

    index.commit()
    start, end = index._columns.offset[line], index._columns.offset[line + 1]
    return os.pread(index._spool.fd, end - start, start)[:-1]


# Every category, lone surrogates weighed up (a paste into the filter box can hold one).
ANY_CHAR = st.characters(exclude_categories=()) | st.characters(categories=["Cs"])
FILTER_TEXT = st.one_of(
    st.text(ANY_CHAR, max_size=10),
    st.text(alphabet="tx rx ACKDONE01 9F.*+?()[]^$|\\{},:-", max_size=10),
    st.sampled_from(
        ["TX", "rx", "ack", "done", "error", "7B 7D", "F0", "poll", "\\d+", "(", "^tx", "\\nrx"]
    ),
)
# What can match across a line end, or at a line start: the spool scan and a line's own text
# disagree on those (see test_filter_is_matched_line_by_line), so they are checked loosely.
_CROSSES_LINES = re.compile(r"[\^$\[\\\n]|\(\?")
SUBSETS = st.none() | st.sets(st.sampled_from(KINDS))
DIRECTION_SUBSETS = st.none() | st.sets(st.sampled_from(["tx", "rx", ""]))


@pytest.mark.parametrize(("name", "variant"), [*VARIANTS, (None, None)], ids=[*IDS, "none"])
@settings(FUZZ, max_examples=35)
@given(data=st.data())
def test_traffic_index_takes_any_traffic_and_reads_every_line(name, variant, data) -> None:
    protocol = create_protocol(name, variant) if name else None
    traffic = data.draw(traffic_of(protocol or create_protocol("coxiris")), "traffic")
    index = TrafficIndex(protocol)
    try:
        for step, (direction, chunk) in enumerate(traffic):
            time = data.draw(st.sampled_from([float(step), step * 7.0, 0.0]), "time")
            index.add(direction, chunk, time, wall=1000.0 + time)
            if step % 4 == 3:
                index.add_note(f"note {step}\t\n", time)
        size = len(index)
        lines = [index.line(n) for n in range(size)]
        for number, line in enumerate(lines):
            assert line.number == number
            assert line.kind in KINDS
            assert line.direction in ("tx", "rx", "")
            assert -1 <= line.pair < size and -1 <= line.first_copy < size
        for outside in (-1, size):
            with pytest.raises(IndexError):
                index.line(outside)
        index.take_latencies()
        assert len(index.times()) == size == len(index.sizes(0, size))
        assert len(index.directions(0, size)) == size
        # filters: by direction and kind, checked line by line; by expression, on the spool text
        directions, kinds = data.draw(DIRECTION_SUBSETS, "dirs"), data.draw(SUBSETS, "kinds")
        start = data.draw(st.integers(0, size), "start")
        chosen = index.select(directions, kinds, None, start).tolist()
        expected = [
            n
            for n in range(start, size)
            if (directions is None or lines[n].direction in directions)
            and (kinds is None or lines[n].kind in kinds)
        ]
        assert chosen == expected
        text = data.draw(FILTER_TEXT, "filter")
        try:
            pattern = compile_filter(text)
        except FilterError:
            return
        found = index.select(directions, kinds, pattern, start).tolist()
        if pattern is None:
            assert found == expected
        elif _CROSSES_LINES.search(text):
            assert set(found) <= set(expected) and found == sorted(set(found))
        else:
            assert found == [n for n in expected if pattern.search(_spool_text(index, n))]
    finally:
        index.close()


@settings(max_examples=150, deadline=None)
@given(text=st.text(ANY_CHAR, max_size=30))
def test_compile_filter_takes_any_text(text: str) -> None:
    try:
        pattern = compile_filter(text)
    except FilterError:
        return
    assert pattern is None or isinstance(pattern, re.Pattern)


# -- file readers -------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def scratch(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("fuzz")


def write_bytes(folder: Path, data: bytes, suffix: str = ".txt") -> Path:
    handle = tempfile.NamedTemporaryFile(dir=folder, suffix=suffix, delete=False)  # noqa: SIM115
    with handle:
        handle.write(data)
    return Path(handle.name)


RECORD = st.tuples(
    st.floats(0, 999999, allow_nan=False), DIRECTION, st.binary(min_size=1, max_size=40)
)


def our_log_lines(records: list[tuple[float, str, bytes]]) -> list[str]:
    lines = []
    for time, direction, data in records:
        lines += hexdump_lines(Traffic(direction, data, time), 0.0)
    return lines


def spy_lines(records: list[tuple[float, str, bytes]]) -> list[str]:
    lines = []
    for time, direction, data in records:
        for offset in range(0, len(data), 16):
            row = _row(data[offset : offset + 16])
            lines.append(f"{time:010.3f} {direction.upper()}   {offset:04X}  {row}")
    return lines


NOISE_LINES = st.sampled_from(
    [
        "",
        "   ",
        "000001.000 # connected",
        "# a note",
        "000001.000 RTS  active",
        "000001.000 RX   <empty>",
        "000001.000 Q-RX reset_input_buffer",
        "\x1b[32m",
        "\x1b[31m000001.000 TX   0000  41",
        "\u0660" * 5 + "\u0661.\u0660\u0660\u0660 TX   41",  # \d and float() take these digits
        "000001.000 TX   41 42 43",
        "000001.000 RX   0010  41",
        "\x00\x00",
        "\ufeff000001.000 TX   41",
        "000001.000 TX   " + "41 " * 15 + "41" + " " * 3 + "A" * 17,
    ]
)


def log_text(make_lines) -> st.SearchStrategy[str]:
    """Valid lines, with noise lines, edits and random text slipped in."""
    return st.tuples(
        st.lists(RECORD, max_size=4).map(make_lines),
        st.lists(st.tuples(st.integers(0, 20), NOISE_LINES | st.text(max_size=30)), max_size=4),
        st.sampled_from(["\n", "\r\n", "\r", "\x85", "\u2028"]),
    ).map(_insert_lines)


def _insert_lines(parts: tuple[list[str], list[tuple[int, str]], str]) -> str:
    lines, extra, newline = parts
    lines = list(lines)
    for at, line in extra:
        lines.insert(at % (len(lines) + 1), line)
    return newline.join(lines)


ANY_LOG_TEXT = st.one_of(log_text(our_log_lines), log_text(spy_lines), st.text(max_size=200))


def check_records(records: object) -> None:
    assert isinstance(records, list) and records
    for record in records:
        assert isinstance(record, LogRecord)
        assert record.direction in ("tx", "rx", "")
        assert isinstance(record.data, bytes) and isinstance(record.note, str)


@FUZZ
@given(text=ANY_LOG_TEXT)
def test_parse_log_and_parse_spy_take_any_text(text: str) -> None:
    for parse in (parse_log, parse_spy):
        with contextlib.suppress(LogError):
            check_records(parse(text, "fuzz"))


@settings(max_examples=80, deadline=None)
@given(
    raw=st.one_of(
        ANY_LOG_TEXT.map(lambda t: t.encode("utf-8", "surrogatepass")),
        st.binary(max_size=300),
        st.tuples(ANY_LOG_TEXT, st.binary(max_size=8)).map(
            lambda t: t[0].encode("utf-8", "surrogatepass") + t[1]
        ),
    )
)
def test_read_any_log_takes_any_bytes(scratch: Path, raw: bytes) -> None:
    path = write_bytes(scratch, raw, ".log")
    try:
        for read in (read_any_log, read_log):
            try:
                result = read(path)
            except LogError:
                continue
            check_records(result[1] if isinstance(result, tuple) else result)
    finally:
        path.unlink()


PROFILE_VALUES = st.one_of(
    st.integers().map(str),
    st.integers(300, 5000).map(lambda n: "1" * n),  # past float, past int()'s 4300 digits
    st.integers(1, 4000).map(lambda n: "0x" + "F" * n),  # hex: no digit limit
    st.floats().map(repr),
    st.sampled_from(
        [
            "inf",
            "nan",
            "-0.0",
            "true",
            '"38.2"',
            "[1, 2]",
            "{a = 1}",
            "1979-05-27",
            "0x" + "F" * 4000,
        ]
    ),
    st.text(max_size=8),
)
PROFILE_TEXT = st.one_of(
    st.tuples(
        st.sampled_from(
            ['protocol = "visiomex"\n', 'protocol = "coxiris"\n', "protocol = 3\n", ""]
        ),
        st.sampled_from(["[parameters]\n"] * 4 + ["[parameters.x]\n", "[other]\n", ""]),
        st.lists(
            st.tuples(
                st.sampled_from([p.name for p in VISIOMEX_PARAMETERS]) | st.text(max_size=6),
                PROFILE_VALUES,
            ),
            max_size=4,
        ),
    ).map(lambda t: t[0] + t[1] + "".join(f"{k} = {v}\n" for k, v in t[2])),
    st.text(max_size=120),
)


def _check_profile(values: dict[str, float]) -> None:
    names = {p.name for p in VISIOMEX_PARAMETERS}
    assert values and set(values) <= names
    assert all(isinstance(v, float) for v in values.values())


@settings(max_examples=200, deadline=None)
@given(text=PROFILE_TEXT)
def test_parse_profile_takes_any_text(text: str) -> None:
    with contextlib.suppress(ProfileError):
        _check_profile(parse_profile(text, VISIOMEX_PARAMETERS, "visiomex"))


@settings(max_examples=40, deadline=None)
@given(raw=st.one_of(PROFILE_TEXT.map(lambda t: t.encode("utf-8", "surrogatepass")), st.binary()))
def test_read_profile_takes_any_bytes(scratch: Path, raw: bytes) -> None:
    path = write_bytes(scratch, raw, ".toml")
    try:
        _check_profile(read_profile(path, VISIOMEX_PARAMETERS, "visiomex"))
    except ProfileError:
        pass
    finally:
        path.unlink()


CELL = st.one_of(
    st.floats().map(repr),
    st.integers(0, 140000).map(lambda n: "1" * n),  # csv refuses a field over 128 Ki
    st.integers().map(str),
    st.sampled_from(["", " 1 ", "1e400", "nan", '"1,2"', '"', "x", "#", "\r", "\x00"]),
)
CSV_TEXT = st.one_of(
    st.tuples(
        st.permutations(["x", "y", "z", "speed"]).map(",".join) | st.text(max_size=12),
        st.lists(st.lists(CELL, min_size=3, max_size=5).map(",".join), max_size=4),
        st.sampled_from(["\n", "\r\n", "\r"]),
    ).map(lambda t: t[2].join([t[0], *t[1]])),
    st.text(max_size=120),
)
JSON_VALUE = st.recursive(
    st.none() | st.booleans() | st.floats() | st.integers() | st.text(max_size=4),
    lambda inner: st.lists(inner, max_size=5) | st.dictionaries(st.text(max_size=6), inner),
    max_leaves=12,
)
JSON_TEXT = st.one_of(
    st.lists(st.lists(st.floats() | st.integers(), min_size=4, max_size=4) | JSON_VALUE).map(
        lambda points: '{"points": ' + repr(points).replace("'", '"') + "}"
    ),
    st.dictionaries(st.just("points"), JSON_VALUE).map(json.dumps),
    st.integers(300, 5000).map(lambda n: '{"points": [[' + "9" * n + ", 1, 1, 1]]}"),
    st.integers(1, 3000).map(lambda n: '{"points": ' + "[" * n + "1" + "]" * n + "}"),
    st.text(max_size=80),
)


def _check_program(points: object) -> None:
    assert isinstance(points, list) and points
    for point in points:
        assert point.speed > 0


@settings(max_examples=150, deadline=None)
@given(csv_text=CSV_TEXT, json_text=JSON_TEXT)
def test_program_parsers_take_any_text(csv_text: str, json_text: str) -> None:
    for parse, text in ((parse_csv, csv_text), (parse_json, json_text)):
        with contextlib.suppress(ProgramError):
            _check_program(parse(text, "fuzz"))


@settings(max_examples=40, deadline=None)
@given(
    raw=st.one_of(
        CSV_TEXT.map(lambda t: t.encode("utf-8", "surrogatepass")),
        JSON_TEXT.map(lambda t: t.encode("utf-8", "surrogatepass")),
        st.binary(max_size=200),
    ),
    suffix=st.sampled_from([".csv", ".json", ".JSON", ".txt"]),
)
def test_read_program_takes_any_bytes(scratch: Path, raw: bytes, suffix: str) -> None:
    path = write_bytes(scratch, raw, suffix)
    try:
        _check_program(read_program(path))
    except ProgramError:
        pass
    finally:
        path.unlink()


@pytest.mark.parametrize("data", [b"", b"\x00" * 1000, b"\xff\xfe\x00A", b"A" * (3 << 20) + b"\n"])
def test_readers_refuse_odd_files_with_their_own_errors(scratch: Path, data: bytes) -> None:
    """Empty, NULs, invalid UTF-8 and a 3 MiB line without an end."""
    path = write_bytes(scratch, data)
    try:
        for read, error in (
            (read_any_log, LogError),
            (read_log, LogError),
            (read_program, ProgramError),
            (lambda p: read_profile(p, VISIOMEX_PARAMETERS, "visiomex"), ProfileError),
        ):
            with pytest.raises(error):
                read(path)
    finally:
        path.unlink()


def test_readers_refuse_a_missing_file(scratch: Path) -> None:
    missing = scratch / "missing"
    with pytest.raises(LogError):
        read_any_log(missing)
    with pytest.raises(ProgramError):
        read_program(missing)
    with pytest.raises(ProfileError):
        read_profile(missing, VISIOMEX_PARAMETERS, "visiomex")


# -- regressions: what the fuzzer found -----------------------------------------------------------


def test_firmata_empty_frame_is_a_frame_error() -> None:
    """`decode(b"")` raised IndexError; `describe_sent(b"")` (an empty write) with it."""
    protocol = create_protocol("firmata")
    with pytest.raises(FrameError):
        protocol.decode(b"")
    assert protocol.describe_sent(b"").startswith("unreadable")


@pytest.mark.parametrize("variant", ["seed", "prefixed", "board12"])
def test_visiomex_describe_sent_superscript_digits(variant: str) -> None:
    """`S²0…`: latin-1 `²` passes str.isdigit() but not int(): describe_sent raised ValueError."""
    protocol = create_protocol("visiomex", variant)
    assert protocol.describe_sent(b"S\xb201234567") == "packet 'S²01234567'"
    assert protocol.describe_sent(b"S01\xb2\xb3\xb9000").startswith("packet")
    assert protocol.describe_sent(b"S03000382NNNNNNNNN") == "set pulley_diameter_x = 38.2 mm"


@pytest.mark.parametrize(
    "text", ["\ud800", "(" * 5000 + ")" * 5000, "a{4294967296}", "x{1,4294967296}"]
)
def test_compile_filter_odd_text_is_a_filter_error(text: str) -> None:
    """A lone surrogate raised UnicodeEncodeError, deep nesting RecursionError, a huge
    repetition OverflowError, out of the console's filter box."""
    with pytest.raises(FilterError):
        compile_filter(text)


@pytest.mark.parametrize(
    "text",
    [
        "[parameters]\nthread_distance_x = " + "1" * 5000,  # ValueError: int over 4300 digits
        "[parameters]\nthread_distance_x = " + "1" * 400,  # OverflowError: int to float
        "[parameters]\nthread_distance_x = 0x" + "F" * 4000,  # OverflowError
        "[parameters]\nthread_distance_x = [0x" + "F" * 4000 + "]",  # ValueError: repr of it
        "[parameters]\nthread_distance_x = " + "[" * 5000 + "]" * 5000,  # RecursionError
        "protocol = 0x" + "F" * 4000 + "\n[parameters]\nthread_distance_x = 1",  # ValueError
    ],
)
def test_profile_odd_numbers_are_profile_errors(text: str) -> None:
    with pytest.raises(ProfileError):
        parse_profile(text, VISIOMEX_PARAMETERS, "visiomex")


@pytest.mark.parametrize(
    "text",
    [
        '{"points": [[' + "1" * 5000 + ", 1, 1, 1]]}",  # ValueError: int over 4300 digits
        '{"points": [[' + "1" * 400 + ", 1, 1, 1]]}",  # OverflowError: int to float
        "[" * 100000 + "]" * 100000,  # RecursionError
    ],
)
def test_program_json_odd_numbers_are_program_errors(text: str) -> None:
    with pytest.raises(ProgramError):
        parse_json(text)


def test_program_csv_huge_field_is_a_program_error() -> None:
    """A field over csv's 131072-character limit raised csv.Error."""
    with pytest.raises(ProgramError, match="line 2"):
        parse_csv("x,y,z,speed\n" + "1" * 200000 + ",1,1,1\n")


def test_program_csv_cr_line_ends() -> None:
    """A CR alone inside a line raised csv.Error ("new-line character seen in unquoted field");
    CR-only line ends (old Mac spreadsheets) are now lines."""
    assert len(parse_csv("x,y,z,speed\r1,2,3,4\r5,6,7,8\r")) == 2
    with pytest.raises(ProgramError, match="2 values"):
        parse_csv("x,y,z,speed\n1,1\r1,1\n")


def _coxiris_index() -> TrafficIndex:
    index = TrafficIndex(create_protocol("coxiris"))
    index.add("tx", b"GET_ID\n", 0.0)
    index.add("rx", b"ACK GET_ID\r\nDONE GET_ID: X\r\n", 0.1)
    index.add("tx", b"GET_POSITION\n", 0.2)
    return index


@pytest.mark.parametrize("text", ["\\nrx", "get_id\\s+rx", "^tx"])
def test_filter_is_matched_line_by_line(text: str) -> None:
    index = _coxiris_index()
    try:
        pattern = compile_filter(text)
        assert pattern is not None
        found = index.select(pattern=pattern).tolist()
        own = [n for n in range(len(index)) if pattern.search(_spool_text(index, n))]
        assert found == own
    finally:
        index.close()


@settings(FUZZ, max_examples=300)
@given(
    buffer=st.lists(st.sampled_from([b"ab", b"x", b"\r", b"\n", b"\r\n", b"", b"long" * 5])).map(
        b"".join
    ),
    limit=st.sampled_from([3, 8, 4096]),
)
def test_line_framer_split_wired_is_split_with_its_wire_spans(buffer: bytes, limit: int) -> None:
    """The line framer's fast path (bytes.splitlines) gives what `split` and the decoder's wire
    spans give, or None where a line is too long for it."""
    from drivers.framers.lines import LineFramer
    from drivers.framers.splitter import wire_spans as _wire_spans

    framer = LineFramer(b"\n", max_length=limit)
    fast = framer.split_wired(buffer)
    frames, rest = framer.split(buffer)
    if fast is None:  # only where a line, with its end, is longer than the limit
        assert max(map(len, buffer.splitlines(True))) >= limit
        return
    assert fast == (frames, _wire_spans(buffer[: len(buffer) - len(rest)], frames), rest)
