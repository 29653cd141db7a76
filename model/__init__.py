"""The document model and its project files: UI-free, LaTeX-free, physics-free."""

from floatpage.model.document import (
    FORMAT_VERSION, Background, BlockItem, CalendarItem, ItemAnchor, Page, PhysicsSettings,
    PictureItem, PointAnchor, Project, TextItem,
)
from floatpage.model.errors import FloatpageError, Problem, ProjectFileError
from floatpage.model.project_file import load_project
from floatpage.model.save import atomic_write, dump_project, save_project

__all__ = [
    "FORMAT_VERSION", "Background", "BlockItem", "CalendarItem", "ItemAnchor", "Page",
    "PhysicsSettings", "PictureItem", "PointAnchor", "Project", "TextItem", "FloatpageError",
    "Problem", "ProjectFileError", "load_project", "atomic_write", "dump_project", "save_project",
]
