"""Deck errors located by file, line, column and key path."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class DeckIssue:
    """One problem in a deck: ``file:line:col: key.path: message`` (1-based line and column)."""

    file: str
    line: int
    col: int
    path: str
    message: str

    def __str__(self) -> str:
        where = f"{self.file}:{self.line}:{self.col}"
        return f"{where}: {self.path}: {self.message}" if self.path else f"{where}: {self.message}"


class DeckError(Exception):
    """Raised when a deck cannot be read; carries every issue found, not just the first."""

    def __init__(self, issues: list[DeckIssue]):
        self.issues = list(issues)
        super().__init__("\n".join(str(i) for i in self.issues))
