"""Cut a many-record PDF into one PDF per record whose bytes depend on that record alone.

LuaTeX names a page's resources after run-wide numbers (`/F24` is the 24th font of the
run, `/Im3` the third picture), so the same page typeset at another place in another run
uses other names. Each page is therefore rewritten with names given in the order its
content first uses them, resources it never uses are dropped, and qpdf (through pikepdf)
numbers the objects afresh and derives the file ID from the content. Fonts need no work
here: the batch run embeds a separate subset for every record (see typeset.batch).
"""

from __future__ import annotations

import hashlib
import io
from pathlib import Path
from typing import Iterable

import pikepdf

# Which resource category the name operand of each operator lives in.
OPERATOR_CATEGORY = {
    "Tf": "/Font", "Do": "/XObject", "gs": "/ExtGState", "cs": "/ColorSpace",
    "CS": "/ColorSpace", "sh": "/Shading", "scn": "/Pattern", "SCN": "/Pattern",
    "BDC": "/Properties", "DP": "/Properties",
}
PREFIX = {"/Font": "F", "/XObject": "X", "/ExtGState": "G", "/ColorSpace": "C",
          "/Shading": "S", "/Pattern": "P", "/Properties": "M"}


def canonical_names(pdf: pikepdf.Pdf, page: pikepdf.Page) -> None:
    """Rename the page's resources by first use in its content, and drop the unused ones."""
    resources = page.obj.get("/Resources", pikepdf.Dictionary())
    instructions = pikepdf.parse_content_stream(page)
    renamed: dict[tuple[str, str], pikepdf.Name] = {}
    rewritten = []
    for operands, operator in instructions_of(instructions):
        category = OPERATOR_CATEGORY.get(str(operator))
        if category is not None and category in resources:
            operands = [rename(operand, category, resources[category], renamed)
                        for operand in operands]
        rewritten.append((operands, operator))
    fresh = pikepdf.Dictionary()
    for key in resources.keys():
        if key not in PREFIX:
            fresh[key] = resources[key]  # /ProcSet and the like: no names to keep in step
    for (category, old), new in renamed.items():
        if category not in fresh:
            fresh[category] = pikepdf.Dictionary()
        fresh[category][str(new)] = resources[category][old]
    page.obj.Resources = fresh
    page.obj.Contents = pdf.make_stream(pikepdf.unparse_content_stream(rewritten))


def instructions_of(instructions) -> Iterable[tuple[list, pikepdf.Operator]]:
    for instruction in instructions:
        if isinstance(instruction, pikepdf.ContentStreamInlineImage):
            yield instruction.operands, instruction.operator
        else:
            yield list(instruction.operands), instruction.operator


def rename(operand, category: str, names: pikepdf.Dictionary,
           renamed: dict[tuple[str, str], pikepdf.Name]):
    if not isinstance(operand, pikepdf.Name) or str(operand) not in names:
        return operand
    key = (category, str(operand))
    if key not in renamed:
        used = sum(1 for kind, _ in renamed if kind == category)
        renamed[key] = pikepdf.Name(f"/{PREFIX[category]}{used + 1}")
    return renamed[key]


def canonical_subset_tags(pdf: pikepdf.Pdf) -> None:
    """Name each subset font after its glyphs (a hash of its font program), not after where
    LuaTeX read it from: the 'ABCDEF+' prefix LuaTeX writes also hashes the file's path."""
    for font in pdf.objects:
        if not isinstance(font, pikepdf.Dictionary) or font.get("/Type") != "/Font" \
                or font.get("/Subtype") != "/Type0":
            continue
        descendant = font.DescendantFonts[0]
        descriptor = descendant.FontDescriptor
        program = next((descriptor[key] for key in ("/FontFile", "/FontFile2", "/FontFile3")
                        if key in descriptor), None)
        name = str(descendant.BaseFont)[1:]
        if program is None or "+" not in name:
            continue
        old_tag, base = name.split("+", 1)
        # The program (a CFF's name index) spells the tag too: same length, so a byte swap.
        data = program.read_bytes().replace(f"{old_tag}+".encode(), b"AAAAAA+")
        digest = hashlib.sha256(data + base.encode()).digest()
        tag = "".join(chr(ord("A") + byte % 26) for byte in digest[:6])
        program.write(data.replace(b"AAAAAA+", f"{tag}+".encode()))  # compressed on save
        if "/ToUnicode" in font:  # its CMap's name and ordering spell the tag as "TAG-"
            cmap = font.ToUnicode.read_bytes().replace(f"{old_tag}-".encode(), f"{tag}-".encode())
            font.ToUnicode.write(cmap)
        fresh = pikepdf.Name(f"/{tag}+{base}")
        font.BaseFont = descendant.BaseFont = descriptor.FontName = fresh


def save_reproducibly(pdf: pikepdf.Pdf) -> bytes:
    """Bytes that depend on the content only: objects renumbered, the ID hashed from them."""
    buffer = io.BytesIO()
    pdf.save(buffer, deterministic_id=True, compress_streams=True,
             object_stream_mode=pikepdf.ObjectStreamMode.generate,
             stream_decode_level=pikepdf.StreamDecodeLevel.generalized)
    return buffer.getvalue()


def renumbered(data: bytes) -> bytes:
    """Copy the pages once more into a new file: pikepdf numbers copied objects in the order
    it meets them, and only now do the names it walks in (sorted) depend on content alone."""
    with pikepdf.open(io.BytesIO(data)) as first:
        again = pikepdf.new()
        again.pages.extend(first.pages)
        return save_reproducibly(again)


def split_records(pdf_path: Path, page_counts: list[int], *, skip_first: int = 0
                  ) -> list[bytes]:
    """One PDF (bytes) per record, the records' pages being consecutive in `pdf_path` after
    `skip_first` pages (and any pages after the records ignored)."""
    out = []
    with pikepdf.open(pdf_path) as source:
        if len(source.pages) < skip_first + sum(page_counts):
            raise ValueError(f"the batch PDF has {len(source.pages)} pages, expected "
                             f"{skip_first + sum(page_counts)} or more")
        first = skip_first
        for count in page_counts:
            record = pikepdf.new()
            for index in range(first, first + count):
                record.pages.append(source.pages[index])
            for page in record.pages:
                canonical_names(record, page)
            canonical_subset_tags(record)
            out.append(renumbered(save_reproducibly(record)))
            first += count
    return out


OPEN_AT_ONCE = 256  # qpdf reads a copied page's streams from its source only when saving


def concatenate(parts: Iterable[Path], out: Path) -> int:
    """The print shop's one PDF: the records' PDFs in order; returns the pages written (and
    writes nothing for none). Groups of OPEN_AT_ONCE are combined first, so a run of 100,000
    records never holds 100,000 files open."""
    import tempfile

    from floatpage.model.save import atomic_write

    with tempfile.TemporaryDirectory(prefix="floatpage-combine-") as scratch:
        groups, batch = [], []
        for part in parts:
            batch.append(Path(part))
            if len(batch) == OPEN_AT_ONCE:
                groups.append(combine_group(batch, Path(scratch) / f"{len(groups)}.pdf"))
                batch = []
        if batch:
            groups.append(combine_group(batch, Path(scratch) / f"{len(groups)}.pdf"))
        if not groups:
            return 0
        data, pages = combined_bytes(groups)
    atomic_write(out, data, backup=False)
    return pages


def combine_group(parts: list[Path], out: Path) -> Path:
    data, _ = combined_bytes(parts)
    out.write_bytes(data)
    return out


def combined_bytes(parts: list[Path]) -> tuple[bytes, int]:
    combined = pikepdf.new()
    opened = []
    try:
        for part in parts:
            source = pikepdf.open(part)
            opened.append(source)
            combined.pages.extend(source.pages)
        return save_reproducibly(combined), len(combined.pages)
    finally:
        for source in opened:
            source.close()
