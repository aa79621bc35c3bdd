"""Helpers the tests share: simulator processes, relays, fakes, e2e runners."""
