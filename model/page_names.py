"""Pages the editor named follow their place; pages the user named keep their name.

The editor names a new page `page-N`. It used to take the least free N from the new page's
place, so a page added after the first of "page-1, page-2" became "page-3" at place 2, and the
top bar read "page 2/3 page-3" (user-walk-7). A page whose name is `page-<its place>` is taken
to be the editor's, and is renamed with its place whenever pages are added or removed; any
other name is the user's and is never changed. A project whose pages are not added or removed
is saved with the names it had.
"""

from __future__ import annotations

import itertools
from typing import Iterable

from floatpage.model.document import Page


def place_name(place: int) -> str:
    """The editor's name for the page at `place` (counted from 1)."""
    return f"page-{place}"


def named_by_place(pages: Iterable[Page]) -> set[int]:
    """The `id()`s of the pages whose name is their place's: the editor's names."""
    return {id(page) for place, page in enumerate(pages, 1) if page.id == place_name(place)}


def rename_by_place(pages: list[Page], followers: set[int],
                    other_ids: set[str]) -> dict[str, str]:
    """Give each page in `followers` (by `id()`) the name of its place, in `pages` as they are
    now. A name a user's page or an item (`other_ids`) holds is not taken: that page gets the
    least free `page-N` after it, so names stay unique. Returns {old name: new name} of the
    pages renamed."""
    renamed = {}
    taken = set(other_ids) | {page.id for page in pages if id(page) not in followers}
    for place, page in enumerate(pages, 1):
        if id(page) not in followers:
            continue
        name = place_name(place)
        if name in taken:
            name = next(candidate for candidate in map(place_name, itertools.count(place + 1))
                        if candidate not in taken)
        if name != page.id:
            renamed[page.id] = name
        page.id = name
        taken.add(name)
    return renamed
