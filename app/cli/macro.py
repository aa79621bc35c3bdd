"""`motionctl ... macro list | run NAME | import FILE | export FILE`: the panel's macros."""

from __future__ import annotations

import sys
from typing import Any

from app.common import macros
from drivers.protocols.base import Protocol
from drivers.protocols.registry import protocol_names
from drivers.session.device_session import DeviceSession


def find_macro(settings: Any, protocol: Protocol, name: str) -> macros.Macro:
    """The saved macro of that name, checked whole (BadMacro: unknown, or a step refused)."""
    saved = macros.read_saved(settings, protocol.name)
    for macro in saved:
        if macro.name == name.strip():
            macros.check_macro(macro, protocol)
            return macro
    names = ", ".join(m.name for m in saved) or "none"
    raise macros.BadMacro(f"no {protocol.name} macro named {name!r} (saved: {names})")


def macro_offline(settings: Any, protocol: Protocol, args: list[str]) -> dict[str, Any] | None:
    """Carry out `macro list|import|export` (no port needed); None for `macro run`."""
    what = args[0]
    if what == "list":
        saved = macros.read_saved(settings, protocol.name)
        return {"macros": [{"name": m.name, "steps": list(m.steps)} for m in saved]}
    if what == "export":
        saved = macros.read_saved(settings, protocol.name)
        try:
            macros.write_macro_file(args[1], saved)
        except OSError as exc:
            raise macros.BadMacro(f"cannot write {args[1]}: {exc.strerror or exc}") from None
        return {"exported": len(saved), "file": args[1]}
    if what == "import":
        incoming = [m for m in macros.read_macro_file(args[1]) if m.protocol == protocol.name]
        for macro in incoming:  # all refused if one is: nothing half imported
            macros.check_macro(macro, protocol)
        merged = macros.merge(macros.read_saved(settings, protocol.name), incoming)
        if len(merged) > macros.MAX_MACROS:
            raise macros.BadMacro(
                f"{len(merged)} {protocol.name} macros; at most {macros.MAX_MACROS}"
            )
        macros.save(settings, protocol.name, merged)
        return {"imported": [m.name for m in incoming], "file": args[1]}
    return None


def every_macro(settings: Any) -> dict[str, Any]:
    """`macro list` without --protocol: the macros saved for every protocol."""
    return {
        "macros": [
            {"name": m.name, "steps": list(m.steps), "protocol": name}
            for name in protocol_names()
            for m in macros.read_saved(settings, name)
        ]
    }


def run_macro(session: DeviceSession, macro: macros.Macro) -> dict[str, Any]:
    """Run a macro, telling each step on stderr; the result of each step in order."""
    count = len(macro.steps)

    def tell(number: int, step: str) -> None:
        print(f"motionctl: step {number}/{count}: {step}", file=sys.stderr, flush=True)

    results = macros.run_macro(session, macro, tell)
    return {
        "macro": macro.name,
        "steps": [{"step": s, **r} for s, r in zip(macro.steps, results, strict=True)],
    }


def macro_text(result: dict[str, Any], line_of: Any) -> str:
    """A macro command's result as text; `line_of` renders one step's result."""
    if "macros" in result:
        if not result["macros"]:
            return "no macros saved for this protocol"
        return "\n".join(
            (f"{m['protocol']} " if "protocol" in m else "")
            + f"{m['name']}: {'; '.join(m['steps'])}"
            for m in result["macros"]
        )
    if "exported" in result:
        return f"{result['exported']} macro(s) written to {result['file']}"
    if "imported" in result:
        names = ", ".join(result["imported"]) or "none for this protocol"
        return f"imported from {result['file']}: {names}"
    lines = []
    for step in result["steps"]:
        rest = {k: v for k, v in step.items() if k != "step"}
        lines.append(f"{step['step']}: {line_of(rest) if rest else 'ok'}")
    return "\n".join(lines)
