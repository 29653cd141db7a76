"""The document model and its project files: UI-free, LaTeX-free, physics-free."""

from model.document import (
    FORMAT_VERSION, Background, BlockItem, CalendarItem, ItemAnchor, Page, PhysicsSettings,
    PictureItem, PointAnchor, Project, TextItem,
)
from model.errors import FloatpageError, Problem, ProjectFileError
from model.project_file import load_project
from model.save import atomic_write, dump_project, save_project

__all__ = [
    "FORMAT_VERSION", "Background", "BlockItem", "CalendarItem", "ItemAnchor", "Page",
    "PhysicsSettings", "PictureItem", "PointAnchor", "Project", "TextItem", "FloatpageError",
    "Problem", "ProjectFileError", "load_project", "atomic_write", "dump_project", "save_project",
]
