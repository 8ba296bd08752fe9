"""Blocks the report writes once: a later identical block points back to the first.

Many roots of a workspace start the same stack (every nav2 example brings up the same
servers with the same parameter file), and a fleet starts the same robot many times:
written out each time, the same parameter lists made most of the page. A block seen
before becomes a short reference: a link to the first copy, which the page's script
(optional) replaces with a copy of it when the reference comes into view. Without the
script the link still leads there, so nothing is lost either way.

Blocks are compared as the HTML they render to: two references name the same content,
never merely similar content.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from launchverify.render.html_text import esc

SHARE_ABOVE = 400  # characters of HTML below which a block is cheaper written again


@dataclass
class First:
    """Where a block was first written: its element, its link, what it is called."""

    ident: str
    href: str
    label: str  # escaped HTML
    system: int


@dataclass
class Shared:
    """The blocks written so far, by their HTML (or another key as faithful)."""

    first: dict[str, First] = field(default_factory=dict)

    def earlier(self, key: str, here: First) -> First | None:
        """Return where the block of ``key`` was first written; else record it is ``here``."""
        seen = self.first.get(key)
        if seen is None:
            self.first[key] = here
        return seen

    @staticmethod
    def where(seen: First, system: int) -> str:
        """Return how a reference from system ``system`` places the first copy."""
        return "" if seen.system == system else f" in system {seen.system}"

    def block(self, html: str, *, ident: str, href: str, label: str, system: int,
              what: str, tag: str = "div", classes: str = "") -> str:
        """Return ``html`` in a ``tag`` element, or a reference to its first copy.

        ``ident`` is the element's id, ``href`` the anchor a reference links to (the
        row or section holding it), ``label`` (escaped HTML) how a reference names it,
        ``what`` (plain text) what a reference says before it ("the same 12 parameters as").
        """
        attributes = f' class="{esc(classes)}"' if classes else ""
        if len(html) <= SHARE_ABOVE:
            return f"<{tag}{attributes}>{html}</{tag}>"
        seen = self.earlier(html, First(ident, href, label, system))
        if seen is None:
            return f'<{tag}{attributes} id="{esc(ident)}">{html}</{tag}>'
        return (f'<{tag} class="same" data-same="{esc(seen.ident)}">{esc(what)} '
                f'<a href="#{esc(seen.href)}">{seen.label}{self.where(seen, system)}</a>'
                f"</{tag}>")
