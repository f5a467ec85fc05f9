"""spindlesim.bearings."""
