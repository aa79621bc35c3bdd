"""Simulated devices: one model per protocol, on a stage model driven by an injectable clock."""
