"""Typeset many documents in one LuaLaTeX run, then split the PDF into one per document.

The engine's start-up (formats, fonts, TikZ) costs about a second; each further page in
the same run costs a tenth of that, which is what makes `floatpage merge` fast. Two
things could make a record's PDF depend on its neighbours in the run, and both are undone:

- Fonts: LuaTeX embeds one subset per font file name for the whole run. Each face of each
  record loads its font through a slot folder of links, and `merge.tex.j2` names the font
  after the link, so the subset holds that face's glyphs in that record only. Records that
  set exactly the same lines in a face share its slot (FontSlots): the glyphs, and so the
  subset, are the same as each would get alone, and the run writes it once, not per record.
- Names and object numbers: `typeset.pdf_split` renames and renumbers per record.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path

from pylatex.utils import NoEscape

from floatpage.typeset.build_folder import build_folder
from floatpage.typeset.compile import check_engine_settings, compile_pdf
from floatpage.typeset.errors import RenderError
from floatpage.typeset.fonts import FaceKey, fallback_candidates
from floatpage.typeset.pdf_split import split_records
from floatpage.typeset.pictures import cache_dir
from floatpage.typeset.placed import PlacedDocument, materialize_pictures
from floatpage.typeset.templates import make_environment, tex_path


@dataclass(frozen=True)
class SlotFace:
    """A face as one record of a batch loads it: a luaotfload request of its own (`fpslot`)
    and a slot folder whose links name the font files, so it gets a subset of its own."""

    face: FaceKey
    file: Path
    slot: int
    slot_dir: Path
    size_bp: float = 10.0

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
    def fallback_specs(self) -> list[str]:
        return [spec + f"fpslot={self.slot};" for spec in self.face.fallback_specs]

    @property
    def request(self) -> NoEscape:
        """What fontspec's \\newfontface would ask luaotfload for, plus the slot."""
        mode = "harf" if self.face.rich else "node"
        chain = f"fallback={self.chain_name};" if self.fallbacks else ""
        request = (f"[{tex_path(self.file)}]:mode={mode};script=latn;language=dflt;-calt;"
                   f"{chain}fpslot={self.slot};")
        return NoEscape(request)


# Every text of a batch is set at this size and scaled to its own: a font instance per
# (face, size) costs luaotfload 25 ms, and fitted sizes differ from record to record.
BATCH_FONT_BP = 10.0


def at_one_size(document: PlacedDocument) -> PlacedDocument:
    """The document with every text group drawn at BATCH_FONT_BP and scaled to its fitted size:
    the same glyphs at the same places, from one font instance per face."""
    def rescaled(item):
        groups = getattr(item, "groups", None)
        if not groups:
            return item
        return replace(item, groups=tuple(
            replace(group, size_pt=BATCH_FONT_BP, scale=group.size_pt / BATCH_FONT_BP)
            for group in groups))

    pages = [replace(page, items=[rescaled(item) for item in page.items]) for page in document.pages]
    return replace(document, pages=pages)


def face_files(face: FaceKey, file: Path) -> list[Path]:
    """Every font file a face loads: its own and its fallbacks'."""
    files = {Path(file): None}
    for index in face.fallbacks:
        files[fallback_candidates(face.chain_key)[index].path] = None
    return list(files)


def link_fonts(files: list[Path], slot_dir: Path) -> None:
    """The slot folder: a link to every font file the face loads, under its own name."""
    slot_dir.mkdir(parents=True)
    for file in files:
        link = slot_dir / file.name
        if link.is_symlink():
            raise RenderError(f"two font files are both named {file.name} ({file} and "
                              f"{link.readlink()}); floatpage merge needs distinct names")
        link.symlink_to(file)


def lines_in_face(document: PlacedDocument, face: FaceKey) -> tuple[str, ...]:
    """Every line the document sets in `face`, as TeX, in drawing order: what decides which
    glyphs (and which ToUnicode entries) the face's subset gets."""
    return tuple(str(run.tex) for page in document.pages for item in page.background + page.items
                 for group in getattr(item, "groups", ()) if group.face == face
                 for run in group.runs)


class FontSlots:
    """The slots of one batch run. A face gets a new slot unless an earlier record of the run
    set exactly the same lines in it; sharing that slot then adds no glyph to its subset, so
    each record's PDF is what it would be alone, and the engine writes one subset, not two
    (a subset costs LuaTeX about 10 ms: it reads the whole font program each time)."""

    def __init__(self, root: Path):
        self.root = root
        self.numbers: dict[tuple, int] = {}

    def face(self, face: FaceKey, file: Path, lines: tuple[str, ...]) -> SlotFace:
        key = (face, Path(file), lines)
        number = self.numbers.get(key)
        if number is None:
            number = self.numbers[key] = len(self.numbers)
            link_fonts(face_files(face, file), self.root / str(number))
        return SlotFace(face, Path(file), number, self.root / str(number), BATCH_FONT_BP)


# Each font slot is a font LuaTeX holds for the rest of the run, about 4 MB of its address
# space: 768 in one run (128 records of six faces, no line shared) passed the 3 GB limit.
MAX_SLOTS_PER_RUN = 256


def runs_within_slots(documents: list[PlacedDocument], max_slots: int = MAX_SLOTS_PER_RUN
                      ) -> list[list[int]]:
    """The documents' indices in consecutive runs whose faces need at most `max_slots` slots
    together (a document that needs more runs alone)."""
    runs: list[list[int]] = []
    keys: set = set()
    for index, document in enumerate(documents):
        mine = {(face, Path(file), lines_in_face(document, face)) for face, file in document.faces}
        if runs and runs[-1] and len(keys | mine) <= max_slots:
            runs[-1].append(index)
            keys |= mine
        else:
            runs.append([index])
            keys = set(mine)
    return runs


def record_context(number: int, document: PlacedDocument, slots: FontSlots) -> dict:
    faces = [slots.face(face, file, lines_in_face(document, face)) for face, file in document.faces]
    return {"number": number, "faces": faces, "pages": document.pages}


def batch_tex(documents: list[PlacedDocument], slot_root: Path) -> str:
    documents = [at_one_size(document) for document in documents]
    slots = FontSlots(slot_root)
    records = [record_context(number, document, slots) for number, document in enumerate(documents)]
    colors = list(dict.fromkeys(color for document in documents for color in document.colors))
    folders = {document.picture_dir for document in documents if document.pictures}
    template = make_environment().get_template("merge.tex.j2")
    try:
        return template.render(records=records, colors=colors,
                               picture_dir=folders.pop() if len(folders) == 1 else None,
                               any_rich=any(face.rich for document in documents
                                            for face, _ in document.faces))
    except ValueError as error:
        raise RenderError(f"could not write the LaTeX: {error}") from None


def typeset_batch(documents: list[PlacedDocument], *, timeout_s: float = 600.0,
                  max_slots: int = MAX_SLOTS_PER_RUN) -> list[bytes]:
    """One PDF per document, from as few engine runs as memory allows (runs_within_slots); each
    PDF independent of the others in its run."""
    pdfs: list[bytes] = []
    for run in runs_within_slots(documents, max_slots):
        pdfs += typeset_run([documents[index] for index in run], timeout_s=timeout_s)
    return pdfs


def typeset_run(documents: list[PlacedDocument], *, timeout_s: float) -> list[bytes]:
    """One PDF per document, from one engine run."""
    check_engine_settings()
    for document in documents:
        materialize_pictures(document)
    with build_folder() as build:
        tex = batch_tex(documents, Path(build) / "fonts")
        # Markers count from 0 in every record: alone, an error names the record's item.
        labels = documents[0].labels if len(documents) == 1 else None
        pdf = compile_pdf(tex, Path(build), labels=labels, timeout_s=timeout_s,
                          picture_dir=cache_dir())
        return split_records(pdf, [len(document.pages) for document in documents], skip_first=1)
