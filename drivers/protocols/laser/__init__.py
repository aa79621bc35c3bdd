"""The laser-robot framed link: its codec and its protocol."""
