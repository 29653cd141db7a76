"""Typeset many documents in one LuaLaTeX run, then split the PDF into one per document.

The engine's start-up (formats, fonts, TikZ) costs about a second; each further page in
the same run costs a tenth of that, which is what makes `floatpage merge` fast. Two
things could make a record's PDF depend on its neighbours in the run, and both are undone:

- Fonts: LuaTeX embeds one subset per font file for the whole run. Each record loads its
  fonts through its own slot folder of links, and `merge.tex.j2` names the font after the
  link, so each record gets a subset of its own glyphs only.
- Names and object numbers: `typeset.pdf_split` renames and renumbers per record.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from pylatex.utils import NoEscape

from floatpage.typeset.build_folder import build_folder
from floatpage.typeset.compile import compile_pdf, engine_path
from floatpage.typeset.errors import RenderError
from floatpage.typeset.fonts import FaceKey, fallback_candidates
from floatpage.typeset.pdf_split import split_records
from floatpage.typeset.pictures import cache_dir, materialize
from floatpage.typeset.scene import DocumentScene
from floatpage.typeset.templates import make_environment


@dataclass(frozen=True)
class SlotFace:
    """A face as one record of a batch loads it: its files through the record's slot folder."""

    face: FaceKey
    slot: int
    links: tuple[tuple[str, str], ...]  # (real path, link path)

    @property
    def rich(self) -> bool:
        return self.face.rich

    @property
    def fallbacks(self) -> tuple[int, ...]:
        return self.face.fallbacks

    @property
    def tex_command(self) -> str:
        return self.face.tex_command  # the items' templates name the face by it

    @property
    def chain_name(self) -> str:
        return f"{self.face.chain_name}slot{self.slot}"

    @property
    def slot_feature(self) -> NoEscape:
        """A feature no font has: it only makes luaotfload load a fresh instance per record
        (from its in-memory copy of the file), which the patch_font callback then renames."""
        return NoEscape(f";fpslot={self.slot}")

    @property
    def fallback_specs(self) -> list[str]:
        return [spec + f"fpslot={self.slot};" for spec in self.face.fallback_specs]


def font_files(scene: DocumentScene) -> list[Path]:
    """Every font file the scene's faces load: the faces' own and their fallbacks."""
    files: dict[Path, None] = {}
    for face, file in scene.faces:
        files[Path(file)] = None
        for index in face.fallbacks:
            files[fallback_candidates(face.chain_key)[index].path] = None
    return list(files)


def link_fonts(files: list[Path], slot_dir: Path) -> dict[str, str]:
    slot_dir.mkdir(parents=True)
    links: dict[str, str] = {}
    for file in files:
        link = slot_dir / file.name
        if link.is_symlink():
            raise RenderError(f"two font files are both named {file.name} ({file} and "
                              f"{link.readlink()}); floatpage merge needs distinct names")
        link.symlink_to(file)
        links[str(file)] = str(link)
    return links


def record_context(number: int, scene: DocumentScene, slot_root: Path) -> dict:
    slot_dir = slot_root / str(number)
    links = link_fonts(font_files(scene), slot_dir)
    pairs = tuple(links.items())
    faces = [(SlotFace(face, number, pairs), Path(file)) for face, file in scene.faces]
    return {"number": number, "slot_dir": slot_dir, "faces": faces, "colors": scene.colors,
            "picture_dir": scene.picture_dir, "pages": scene.pages}


def batch_tex(scenes: list[DocumentScene], slot_root: Path) -> str:
    records = [record_context(number, scene, slot_root) for number, scene in enumerate(scenes)]
    template = make_environment().get_template("merge.tex.j2")
    try:
        return template.render(records=records)
    except ValueError as error:
        raise RenderError(f"could not write the LaTeX: {error}") from None


def typeset_batch(scenes: list[DocumentScene], *, timeout_s: float = 600.0) -> list[bytes]:
    """One PDF per scene, from one engine run; each independent of the others in the batch."""
    engine_path()
    for scene in scenes:
        for plan in scene.pictures:
            try:
                materialize(plan)
            except OSError as error:
                raise RenderError(f'picture "{plan.source}" could not be converted: '
                                  f"{error}") from None
    with build_folder() as build:
        tex = batch_tex(scenes, Path(build) / "fonts")
        pdf = compile_pdf(tex, Path(build), labels=None, timeout_s=timeout_s,
                          picture_dir=cache_dir())
        return split_records(pdf, [len(scene.pages) for scene in scenes], skip_first=1)
