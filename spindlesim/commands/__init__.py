"""One click command per module; ``spindlesim.cli`` imports them only when invoked."""
