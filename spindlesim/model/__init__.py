"""spindlesim.model."""
