"""Deck errors located by file, line, column and key path."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class DeckIssue:
    """One problem in a deck: ``file:line:col: key.path: message`` (1-based line and column).

    A ``severity`` "warning" (a plausibility check, deck/plausibility.py) prints as
    ``file:line:col: key.path: warning: message``.
    """

    file: str
    line: int
    col: int
    path: str
    message: str
    severity: str = "error"

    def __str__(self) -> str:
        where = f"{self.file}:{self.line}:{self.col}"
        text = "".join(c if ord(c) >= 32 and ord(c) != 127 else repr(c)[1:-1] for c in self.message)  # one line
        msg = f"warning: {text}" if self.severity == "warning" else text
        return f"{where}: {self.path}: {msg}" if self.path else f"{where}: {msg}"


class DeckError(Exception):
    """Raised when a deck cannot be read; carries every issue found, not just the first."""

    def __init__(self, issues: list[DeckIssue], total: int | None = None):
        self.issues = list(issues)
        #: issues found; more than ``len(issues)`` when the list was cut (deck.limits.MAX_ISSUES)
        self.total = max(len(self.issues), total or 0)
        text = "\n".join(str(i) for i in self.issues)
        if self.total > len(self.issues):
            text += f"\n... and {self.total - len(self.issues)} more"
        super().__init__(text)
