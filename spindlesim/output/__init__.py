"""spindlesim.output."""
