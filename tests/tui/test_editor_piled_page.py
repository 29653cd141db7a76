"""A page whose items are piled past what settle takes on (model/layout.py MAX_PILED_PAIRS)
opens still in the editor, with its problem shown as overlaps, instead of failing on open."""

from __future__ import annotations

from floatpage.model import BlockItem, Page, Project, save_project
from floatpage.model.layout import MAX_PILED_PAIRS, piled_pairs

from editor_helpers import editor


async def test_a_page_piled_past_what_settle_takes_opens_still(tmp_path):
    path = tmp_path / "pile.toml"
    page = Page(id="p", items=[BlockItem(id=f"b{k}", x=100.0, y=140.0, w=2.0, h=2.0)
                               for k in range(1000)])
    assert piled_pairs(page) == 499_500 > MAX_PILED_PAIRS
    save_project(Project(pages=[page]), path)
    async with editor(path, autostart=True) as (app, pilot):
        await pilot.pause(0.2)
        assert app.session.engine.settled
        assert app.session.engine.quality().overlap_count == 499_500
