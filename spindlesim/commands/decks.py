"""``spindlesim decks [show NAME]``: the embedded decks, one line each, or one deck's text to start from."""

import click


def _embedded() -> dict[str, str]:
    from importlib import resources

    files = resources.files("spindlesim.decks")
    return {p.name[:-5]: p.read_text(encoding="utf-8") for p in sorted(files.iterdir(), key=lambda p: p.name)
            if p.name.endswith(".yaml")}


def _title(text: str) -> str:
    for line in text.splitlines():
        if line.startswith("title:"):
            return line.split(":", 1)[1].strip().strip("'\"")
    return ""


@click.group("decks", invoke_without_command=True)
@click.pass_context
def command(ctx):
    """List the embedded decks (the default deck of each command and the examples); `decks show NAME` prints one,
    e.g. `spindlesim decks show milling_spindle > my_spindle.yaml`."""
    if ctx.invoked_subcommand is None:
        decks = _embedded()
        width = max(len(n) for n in decks)
        for name, text in decks.items():
            click.echo(f"{name:{width}s}  {_title(text)}")


@command.command("show")
@click.argument("name")
def show(name):
    """Print the embedded deck NAME (YAML with its comments)."""
    decks = _embedded()
    if name not in decks:
        import difflib

        near = difflib.get_close_matches(name, decks, n=1)
        hint = f"; did you mean {near[0]!r}?" if near else ""
        raise click.BadParameter(f"no embedded deck {name!r}{hint} (known: {', '.join(decks)})", param_hint="NAME")
    click.echo(decks[name], nl=False)
