"""The echo-stage protocol plugin: its declaration, read through the `motionpanel.protocols`
entry point; the protocol and simulator modules are imported only when they are used."""

from __future__ import annotations

from drivers.protocols.registry import ProtocolEntry

ENTRY = ProtocolEntry(
    name="echo-stage",
    display_name="echo-stage",
    protocol="echo_stage.protocol:EchoStageProtocol",
    simulator="echo_stage.device:EchoStageDevice",
    description="example plugin: ASCII lines, MOVE x y -> OK x y, POS? -> POS x y z",
)
