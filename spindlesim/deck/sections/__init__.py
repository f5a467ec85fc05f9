"""Deck sections contributed by bearing and analysis packages.

Each module here registers its models with ``spindlesim.deck.schema`` on import;
add the module name to ``_MODULES`` to have it loaded.
"""

from importlib import import_module

_MODULES: tuple[str, ...] = ("contact", "fluidfilm", "dtrb", "transient")

for _name in _MODULES:
    import_module(f"{__name__}.{_name}")
