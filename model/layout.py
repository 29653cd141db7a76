"""The bridge from the document model to the physics: one Engine per page, and back.

Kept apart from the model's dataclasses so that the model stays physics-free and the physics
stays model-free; this module is the only place that knows both.
"""

from __future__ import annotations

from floatpage.physics import Engine, Params, SettleReport
from floatpage.model.document import ItemAnchor, Page, PhysicsSettings, PointAnchor, Project

POSITION_DECIMALS = 2  # positions are written back to 0.01 mm


def params_from_settings(settings: PhysicsSettings) -> Params:
    """The engine's Params from a project's [physics] table (same field names)."""
    return Params(
        mode=settings.mode,
        alpha=settings.alpha,
        beta=settings.beta,
        delta=settings.delta,
        dt=settings.dt,
        steps_per_frame=settings.steps_per_frame,
        distance=settings.distance,
        heat_decay=settings.heat_decay,
        gutter_mm=settings.gutter_mm,
        seed=settings.seed,
    )


def engine_for_page(page: Page, settings: PhysicsSettings) -> Engine:
    """An Engine holding the page's items at their saved positions, anchors applied.

    The engine starts at rest (``settled``): a page opened from a file keeps the layout it was
    saved with until the first edit or ``reheat``.  A hard anchor or an item anchor does
    position its item, since the anchor is what the user asked for.
    """
    engine = Engine(page.width_mm, page.height_mm, params_from_settings(settings))
    for item in page.items:
        engine.insert(item.id, item.x, item.y, item.w, item.h, decorative=item.decorative)
    for item in page.items:
        anchor = item.anchor
        if isinstance(anchor, PointAnchor):
            engine.anchor_point(item.id, anchor.x, anchor.y, gamma=anchor.gamma,
                                hard=anchor.hard)
        elif isinstance(anchor, ItemAnchor):
            engine.anchor_to(item.id, anchor.to, anchor.dx, anchor.dy)
    engine.mark_settled()
    return engine


def write_back(page: Page, engine: Engine) -> None:
    """Copy the engine's positions into the page's items, rounded to 0.01 mm.

    Items the engine does not know (added to the page since) are left as they are.
    """
    positions = engine.positions()
    for item in page.items:
        if item.id in positions:
            x, y = positions[item.id]
            item.x = round(x, POSITION_DECIMALS)
            item.y = round(y, POSITION_DECIMALS)


def settle_project(project: Project, *, max_steps: int = 200_000) -> list[SettleReport]:
    """Headless: settle every page (physics, then the no-overlap pass) and write positions back.

    Returns one report per page, in page order.
    """
    reports = []
    for page in project.pages:
        engine = engine_for_page(page, project.physics)
        engine.reheat()
        reports.append(engine.settle(max_steps))
        write_back(page, engine)
    return reports
