"""``spindlesim decks [show NAME]``: the embedded decks with the commands that use each by default, or one
deck's text to start from."""

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
    """List the embedded decks: each one's title and the commands that run it when given no DECK (the others
    are examples); `decks show NAME` prints one, e.g. `spindlesim decks show milling_spindle > my_spindle.yaml`."""
    if ctx.invoked_subcommand is None:
        from ..decks import commands_using

        decks = _embedded()
        width = max(len(n) for n in decks)
        for name, text in decks.items():
            users = commands_using(name)
            use = f"default of: {', '.join(users)}" if users else "example (no command's default)"
            click.echo(f"{name:{width}s}  {_title(text)}")
            click.echo(f"{'':{width}s}  {use}")


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
