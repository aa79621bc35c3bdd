"""Which request each reply answers, and which earlier frame a retransmission repeats.

A sent frame's kind is the protocol's `sent_kind`; a reply takes its request's kind. Replies are
paired with requests by the protocol's own reply tracker (`raw_exchange`) where it has one, else
the next reply answers the oldest request still waiting (for `REPLY_WINDOW` seconds) that
`expects_reply`. What a request's reply tracker does with each reply frame is learnt once and
replayed for the next copy of the request (see Waiting): traffic repeats itself.
"""

from __future__ import annotations

import logging
from collections import deque
from dataclasses import dataclass

from drivers.protocols.base import Exchange, Protocol
from drivers.traffic.decoding import Frame
from drivers.traffic.lines import KIND_CODE

log = logging.getLogger(__name__)

REPLY_WINDOW = 10.0  # s a request waits for its reply before it counts as unanswered
TYPED_WINDOW = 5.0  # s bytes the operator typed may take to be sent
ERROR = KIND_CODE["error"]
_POLL, _QUERY = KIND_CODE["poll"], KIND_CODE["query"]
_RECEIVED_KIND = {"error": ERROR, "text": KIND_CODE["debug"]}  # else the request's kind


@dataclass(slots=True)
class Waiting:
    """A request waiting for its reply, and where its reply tracker is.

    The tracker is the protocol's (`raw_exchange`): `exchange` once built. Trackers are state
    machines fed events, so what one did with each frame, in order, is the same for every copy
    of a request: the pairing remembers it (a script: `Scripts`) and replays it without building
    the tracker, until a frame comes that the script has not seen; then the tracker is built and
    fed the frames so far (`offered`), and goes on live, adding to the script.
    """

    line: int
    time: float
    data: bytes
    raw: bytes
    kind: int  # its kind's code, which its replies take
    tracked: bool  # the protocol has a tracker for it (else it is answered by order)
    exchange: Exchange | None = None
    state: int = -1  # the script's state it is in (-1: off the script)
    offered: list[Frame] | None = None  # frames replayed so far, while `exchange` is None


class Scripts:
    """What reply trackers did with the frames offered them (see Waiting), by request frame."""

    MAX_STEPS = 20_000  # then forgotten, and learnt again
    MAX_DEPTH = 64  # frames a script follows a request for; the tracker then goes on live

    def __init__(self) -> None:
        self.starts: dict[bytes, int | None] = {}  # request (raw) → first state (None: none)
        self.steps: dict[tuple[int, bytes], tuple[bool, bool, int]] = {}  # → taken, done, next
        self.depth: dict[int, int] = {}  # state → frames since its start
        self.states = 0

    def start(self, data: bytes, tracked: bool) -> int | None:
        """A request's first state (None: it has no tracker)."""
        if len(self.steps) + len(self.starts) >= self.MAX_STEPS:
            self.starts.clear()
            self.steps.clear()
            self.depth.clear()
        state = self.starts[data] = self.states if tracked else None
        if tracked:
            self.depth[self.states] = 0
            self.states += 1
        return state

    def learn(self, state: int, frame: bytes, taken: bool, done: bool) -> int:
        """The tracker in `state` did this with `frame`; returns the next state (-1: no more)."""
        known = self.steps.get((state, frame))
        if known is not None:  # (another copy of the request learnt it first)
            return known[2]
        depth = self.depth.get(state, self.MAX_DEPTH)
        if depth >= self.MAX_DEPTH or len(self.steps) + len(self.starts) >= self.MAX_STEPS:
            return -1
        following = self.states
        self.states += 1
        self.depth[following] = depth + 1
        self.steps[state, frame] = (taken, done, following)
        return following


class Pairing:
    """The requests of one connection waiting for their replies (`protocol`: its decoders)."""

    def __init__(self, protocol: Protocol | None) -> None:
        self.protocol = protocol
        self.waiting: deque[Waiting] = deque()
        self._last_sent: dict[bytes, int] = {}  # frame → line of its first copy, unanswered
        self._last_kind = KIND_CODE["query"]  # of the last frame sent, for a reply unpaired
        self._sent_kinds: dict[bytes, tuple[int, bool]] = {}  # frame → kind code, expects reply
        self._scripts = Scripts()
        self._typed: deque[tuple[float, bytearray]] = deque(maxlen=16)  # (when, bytes left)

    def typed(self, data: bytes, time: float) -> None:
        """Bytes the operator typed, about to be sent at about `time`: a frame of them is a
        query, never hidden as the panel's own polling (a GET_POSITION typed is shown)."""
        self._typed.append((time, bytearray(data)))

    def _was_typed(self, raw: bytes, time: float) -> bool:
        """Whether a frame sent at `time` is (part of) bytes the operator typed; taken off them."""
        typed = self._typed
        while typed and time - typed[0][0] > TYPED_WINDOW:
            typed.popleft()
        for entry in typed:
            pending = entry[1]
            at = pending.find(raw)
            if at >= 0:
                del pending[at : at + len(raw)]
                if not pending:
                    typed.remove(entry)
                return True
        return False

    def _sent_kind(self, data: bytes) -> tuple[int, bool]:
        """A sent frame's kind code and whether it expects a reply (kept in `_sent_kinds`)."""
        protocol = self.protocol
        kind = protocol.sent_kind(data) if protocol else "query"
        expects = protocol is not None and protocol.expects_reply(data)
        if len(self._sent_kinds) >= 4096:
            self._sent_kinds.clear()
        known = self._sent_kinds[data] = (KIND_CODE[kind], expects)
        return known

    def sent(self, frame: Frame, time: float, line: int) -> tuple[int, int]:
        """A frame about to be sent as `line`: the kind code its line takes, and the line of
        its first copy while that one is unanswered (-1: none, this is the first)."""
        data = frame.data
        known = self._sent_kinds.get(data)
        code, expects = known if known is not None else self._sent_kind(data)
        if code == _POLL and self._typed and self._was_typed(frame.raw, time):
            code = _QUERY  # typed by the operator: shown, and so is its reply
        self._last_kind = code
        waiting = self.waiting
        while waiting and time - waiting[0].time > REPLY_WINDOW:
            waiting.popleft()
        first = self._last_sent.get(data)
        if first is None:
            self._last_sent[data] = line
            first = -1
        if not expects:
            return code, first
        scripts = self._scripts
        # Scripts are keyed by the frame's bytes as sent, ends included: two frames with the
        # same text can end differently, and a tracker is built from the whole frame.
        if frame.raw in scripts.starts:  # followed before: replayed (see Waiting)
            state = scripts.starts[frame.raw]
            if state is None:
                waiting.append(Waiting(line, time, data, frame.raw, code, False))
            else:
                waiting.append(Waiting(line, time, data, frame.raw, code, True, None, state, []))
            return code, first
        exchange = self._tracker(frame.raw)
        state = scripts.start(frame.raw, exchange is not None)
        tracked = exchange is not None
        waiting.append(
            Waiting(
                line, time, data, frame.raw, code, tracked, exchange, -1 if state is None else state
            )
        )
        return code, first

    def _tracker(self, raw: bytes) -> Exchange | None:
        """The protocol's reply tracker for a request (None: it pairs by order)."""
        if self.protocol is None:  # (no request waits without one: see sent)
            return None
        try:
            return self.protocol.raw_exchange(raw)
        except Exception:  # a tracker for a frame that makes no sense: pair by order instead
            log.debug("no reply tracker for %r", raw, exc_info=True)
            return None

    def received(self, frame: Frame) -> tuple[Waiting | None, int]:
        """The request a received frame answers (None: none) and the kind code its line takes."""
        request = self._match(frame) if self.waiting else None
        kind = _RECEIVED_KIND.get(frame.kind)
        if kind is None:
            kind = request.kind if request is not None else self._last_kind
        if request is not None and kind != ERROR:
            self._last_sent.pop(request.data, None)  # answered: a copy now is not a retry
        return request, kind

    def _match(self, frame: Frame) -> Waiting | None:
        """The request this received frame belongs to (it stays waiting until finished).

        Trackers are offered the frame newest first: on a one-in-flight device the newest
        request is the one being answered, and a tracker takes what is not its own as garbled.
        A device's own text is not taken as the answer of a request answered by order.
        """
        steps = self._scripts.steps
        for waiting in reversed(self.waiting):
            if not waiting.tracked:
                continue
            if waiting.exchange is None:  # replaying its script
                step = steps.get((waiting.state, frame.raw))
                if step is not None:
                    taken, done, waiting.state = step
                    assert waiting.offered is not None  # kept while replaying
                    waiting.offered.append(frame)
                    if taken:
                        if done:
                            self.waiting.remove(waiting)
                        return waiting
                    continue
                self._go_live(waiting)
                if waiting.exchange is None:
                    continue
            taken, done = self._offer(waiting, waiting.exchange, frame)
            if taken:
                if done:
                    self.waiting.remove(waiting)
                return waiting
        if frame.kind != "text":
            for waiting in self.waiting:
                if not waiting.tracked:
                    self.waiting.remove(waiting)
                    return waiting
        return None

    def _go_live(self, waiting: Waiting) -> None:
        """Build a replayed request's tracker and feed it the frames replayed so far."""
        offered, waiting.offered = waiting.offered or [], None
        exchange = waiting.exchange = self._tracker(waiting.raw)
        if exchange is None:  # (the protocol changed its mind: pair it by order)
            waiting.tracked = False
            return
        state, waiting.state = waiting.state, -1
        for frame in offered:
            self._offer(waiting, exchange, frame)
        waiting.state = state

    def _offer(self, waiting: Waiting, exchange: Exchange, frame: Frame) -> tuple[bool, bool]:
        """Feed a frame's events to a request's live tracker (`exchange`, the waiting one's):
        (taken, the reply is complete), learnt by the script where it follows."""
        events = frame.events
        try:
            if len(events) == 1:
                taken = exchange.on_event(events[0])
            else:
                taken = any(exchange.on_event(event) for event in events)
        except Exception:  # a tracker confused by foreign traffic: not this request's
            log.debug("reply tracker failed on %r", frame.data, exc_info=True)
            taken = False
        done = taken and exchange.finished and not exchange.wants_more
        if waiting.state >= 0:
            waiting.state = self._scripts.learn(waiting.state, frame.raw, taken, done)
        return taken, done
