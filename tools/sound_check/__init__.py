"""Checks a recording of the game's sound against the engine's logged state."""
