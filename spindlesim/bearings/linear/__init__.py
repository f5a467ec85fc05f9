"""Linear coefficient bearings (``type: linear``): K and C given in the deck, optionally per speed."""
