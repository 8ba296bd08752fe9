"""Which links of an exported side stay inside its tree, judged on the final tree.

A revision's links are judged before any of them exists on disk, in a model of the
side's whole tree (every file written, every folder, every link with its target): a
link's target is walked there as the kernel would walk it, component by component,
through other links (each followed where it really leads, so ``..`` after a linked
folder goes to that folder's parent), and it is kept only when every step of the walk
stays inside the tree and the walk ends on a file or folder of it. Judging each link
as it is created, before the next one exists, lets a chain (``l0 -> l1/..``, ``l1 ->
l2/..``, ..., ``lc -> .``) look inside at each step and end outside once all exist.

The disk then holds a part of the model (links left out, files that could not be
written): a walk there takes the model's steps until one finds nothing, so it never
leaves the tree either.
"""

from __future__ import annotations

from collections.abc import Generator, Iterable

Parts = tuple[str, ...]  # a path below the side's top, one name each
Resolved = tuple[Parts, int] | None  # where a link leads, and the links followed (itself too)
MAX_FOLLOWS = 40  # as Linux: a walk that follows more links fails (ELOOP)
MAX_TARGET = 4095  # bytes: a longer target cannot be made (ENAMETOOLONG)


def parts_of(path: str) -> Parts | None:
    """Return a path's names (``None`` for one that is empty, absolute or has ``.``/``..``)."""
    parts = tuple(path.split("/"))
    if any(part in ("", ".", "..") or "\0" in part for part in parts):
        return None
    return parts


def inside_links(files: Iterable[Parts], links: dict[Parts, str]) -> dict[Parts, str]:
    """Return the links (path -> target) whose whole walk stays inside the final tree.

    ``files`` are the files the side holds, ``links`` every link it would hold. A link
    that is itself a folder of the tree, or lies below a file or another link (a
    malformed tree), is left out with the others.
    """
    tree = _Tree(set(files), links)
    return {path: links[path] for path in sorted(tree.links) if tree.resolve(path) is not None}


class _Tree:
    """The final tree of a side: its files, folders and links, and where each link leads."""

    def __init__(self, files: set[Parts], links: dict[Parts, str]) -> None:
        self.files = files
        folders = {path[:end] for path in files for end in range(len(path))}
        self.links = {path: target for path, target in links.items()
                      if path not in files and path not in folders
                      and not any(path[:end] in files or path[:end] in links
                                  for end in range(1, len(path)))}
        self.folders = folders | {path[:end] for path in self.links
                                  for end in range(len(path))}
        self.known: dict[Parts, Resolved] = {}

    def resolve(self, link: Parts) -> Resolved:
        """Return where a link leads (``None``: out of the tree, nowhere, or a loop).

        Each link's walk is worked out once (a generator that pauses on each link it
        meets), without recursion: a chain as long as the tree allows costs its length.
        """
        if link in self.known:
            return self.known[link]
        walks = [(link, self._walk(link))]
        walking = {link}
        answer: Resolved = None
        while walks:
            name, walk = walks[-1]
            try:
                wanted = walk.send(answer)
            except StopIteration as done:
                self.known[name] = answer = done.value
                walking.discard(name)
                walks.pop()
                continue
            if wanted in self.known:
                answer = self.known[wanted]
            elif wanted in walking:
                answer = None  # a loop: every link on it fails
            else:
                walking.add(wanted)
                walks.append((wanted, self._walk(wanted)))
                answer = None  # (what starts a new walk)
        return self.known[link]

    def _walk(self, link: Parts) -> Generator[Parts, Resolved, Resolved]:
        """Walk a link's target from its folder; yield each link met, to learn where it leads."""
        target = self.links[link]
        if target.startswith("/") or not target or "\0" in target \
                or len(target.encode("utf-8", "surrogateescape")) > MAX_TARGET:
            return None
        here: Parts = link[:-1]
        follows = 1
        for part in target.split("/"):
            if here in self.files:  # (a name after a file: ENOTDIR)
                return None
            if part in ("", "."):
                continue
            if part == "..":
                if not here:  # above the side's top
                    return None
                here = here[:-1]
                continue
            here = (*here, part)
            if here in self.links:
                found = yield here
                if found is None:
                    return None
                follows += found[1]
                if follows > MAX_FOLLOWS:
                    return None
                here = found[0]
            elif here not in self.files and here not in self.folders:
                return None  # nothing there (left out, or never in the tree)
        return here, follows
