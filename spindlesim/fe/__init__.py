"""spindlesim.fe."""
