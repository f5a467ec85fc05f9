"""The inline style sheet of ``report.html`` (output/report.py): screen and print.

No web font, no external sheet: system font stacks only.  Print: A4 or Letter with the same
margins (no page size is forced), each analysis starts a page, a figure and its caption stay
together and fit a page, the deck text prints expanded, colours print as on screen.
"""

CSS = """
:root { --ink: #1d232a; --muted: #5b6570; --line: #d5dae0; --ok: #1e7b34; --warn: #9a6200; --bad: #b3261e;
  --band: #f3f5f7; }
* { box-sizing: border-box; }
html { -webkit-print-color-adjust: exact; print-color-adjust: exact; }
body { margin: 0 auto; max-width: 1060px; padding: 1.5rem 1.5rem 3rem; color: var(--ink); background: #fff;
  font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", Arial, sans-serif; }
h1 { font-size: 1.7rem; margin: 0.1rem 0 0.6rem; overflow-wrap: anywhere; }
h2 { font-size: 1.3rem; margin: 2rem 0 0.6rem; padding-bottom: 0.2rem; border-bottom: 2px solid var(--line); }
h3 { font-size: 1.02rem; margin: 1.2rem 0 0.4rem; }
.kicker { margin: 0; color: var(--muted); text-transform: uppercase; letter-spacing: 0.06em; font-size: 0.8rem; }
.banner { margin: 0.4rem 0; padding: 0.5rem 0.8rem; border-left: 5px solid; background: var(--band); }
.banner.ok { border-color: var(--ok); }
.banner.bad { border-color: var(--bad); }
nav a { margin-right: 1rem; }
a { color: #1f5fa8; }
table { border-collapse: collapse; width: 100%; font-size: 0.9rem; }
th, td { text-align: left; vertical-align: top; padding: 0.3rem 0.5rem; border-bottom: 1px solid var(--line);
  overflow-wrap: break-word; }
td.mono { overflow-wrap: anywhere; }
table.kv th { width: 13rem; color: var(--muted); font-weight: 600; }
table.grid thead th { background: var(--band); }
td.files { color: var(--muted); font-size: 0.85rem; }
.mono, pre, .file { font-family: ui-monospace, "DejaVu Sans Mono", Menlo, Consolas, monospace; }
.mono { font-size: 0.85rem; }
.file { font-weight: normal; color: var(--muted); font-size: 0.9rem; margin-left: 0.4rem; }
.ok { color: var(--ok); }
.warn { color: var(--warn); }
.bad { color: var(--bad); }
.st { font-weight: 600; }
h2 .st { font-size: 0.85rem; margin-left: 0.5rem; padding: 0.05rem 0.45rem; border: 1px solid; border-radius: 3px;
  vertical-align: middle; }
.note { padding: 0.4rem 0.7rem; background: var(--band); overflow-wrap: anywhere; }
ul.failures li { margin: 0.3rem 0; }
.count { color: var(--muted); }
pre { background: var(--band); border: 1px solid var(--line); padding: 0.6rem 0.8rem; font-size: 0.82rem;
  line-height: 1.35; overflow-x: auto; white-space: pre; }
pre .alert { color: var(--bad); font-weight: 700; }
pre.summary { white-space: pre-wrap; overflow-wrap: anywhere; overflow-x: visible; }
.info { color: inherit; }
table.verdicts td:first-child { width: 16rem; font-weight: 600; }
pre.deck { max-height: 40rem; overflow: auto; }
details summary { cursor: pointer; color: #1f5fa8; }
figure { margin: 1.2rem 0; }
figure img { display: block; max-width: 100%; width: auto; height: auto; border: 1px solid var(--line); }
figcaption { margin-top: 0.35rem; font-size: 0.88rem; color: var(--muted); }
footer { margin-top: 3rem; padding-top: 0.6rem; border-top: 1px solid var(--line); color: var(--muted);
  font-size: 0.8rem; }
@page { margin: 16mm 14mm 16mm 14mm; }
@media print {
  body { max-width: none; padding: 0; font-size: 10.5pt; }
  nav, details summary { display: none; }
  a { color: inherit; text-decoration: none; }
  h2 { margin-top: 1.4rem; }
  section.analysis h2, #deck h2 { margin-top: 0; }
  section.analysis, #deck { break-before: page; }
  h2, h3 { break-after: avoid; }
  tr, pre.summary, .note { break-inside: avoid; }
  figure { break-inside: avoid; margin: 0.8rem 0; }
  figure img { max-height: 175mm; max-width: 100%; }
  pre { white-space: pre-wrap; overflow: visible; font-size: 8pt; }
  pre.deck { max-height: none; }
  details::details-content { content-visibility: visible; display: contents; }
}
"""
