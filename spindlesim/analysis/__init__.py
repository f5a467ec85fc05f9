"""spindlesim.analysis."""
