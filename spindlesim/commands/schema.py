"""``spindlesim schema``: the deck's JSON schema, for editor completion and checking of YAML decks, or the
deck key reference in Markdown (docs/deck-reference.md) written from it."""

import json

import click


@click.command("schema")
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True), default=None,
              help="Write the schema to this file instead of standard output.")
@click.option("--markdown", is_flag=True,
              help="The key reference in Markdown (tables per section: key, type, unit, default, range, "
                   "description) instead of the JSON schema; `-o docs/deck-reference.md` regenerates the "
                   "repository's reference.")
def command(output, markdown):
    """JSON schema of a deck (every section, key, unit-carrying name, limit and description), generated from
    the deck's own validation models.  With the YAML language server, put
    `# yaml-language-server: $schema=spindlesim.schema.json` on a deck's first line."""
    from ..deck.reference import deck_reference, deck_schema

    schema = deck_schema()
    text = deck_reference(schema).rstrip("\n") if markdown else json.dumps(schema, indent=1, sort_keys=True)
    if output is None:
        click.echo(text)
    else:
        from pathlib import Path

        Path(output).write_text(text + "\n", encoding="utf-8")
        click.echo(output)
