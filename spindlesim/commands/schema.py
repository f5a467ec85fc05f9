"""``spindlesim schema``: the deck's JSON schema, for editor completion and checking of YAML decks."""

import json

import click


@click.command("schema")
@click.option("-o", "--output", type=click.Path(dir_okay=False, writable=True), default=None,
              help="Write the schema to this file instead of standard output.")
def command(output):
    """JSON schema of a deck (every section, key, unit-carrying name and limit), generated from the deck's own
    validation models.  With the YAML language server, put `# yaml-language-server: $schema=spindlesim.schema.json`
    on a deck's first line."""
    from ..deck.document import deck_model

    schema = deck_model().model_json_schema()
    schema.setdefault("title", "spindlesim deck")
    text = json.dumps(schema, indent=1, sort_keys=True)
    if output is None:
        click.echo(text)
    else:
        from pathlib import Path

        Path(output).write_text(text + "\n", encoding="utf-8")
        click.echo(output)
