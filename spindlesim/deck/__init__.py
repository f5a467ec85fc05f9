"""Deck loading: YAML with line marks, pydantic validation, located errors (``file:line:col: key: message``)."""

from .errors import DeckError, DeckIssue
from .loader import (LoadedDeck, available_analyses, deck_folder, default_deck, load_deck, parse_deck, require_rotor,
                     require_section)

__all__ = ["DeckError", "DeckIssue", "LoadedDeck", "available_analyses", "deck_folder", "default_deck", "load_deck", "parse_deck", "require_rotor", "require_section"]
