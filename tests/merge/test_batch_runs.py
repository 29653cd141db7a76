"""Records typeset together: split into runs by the fonts they need, bytes unchanged."""

from floatpage.merge.record_layout import lay_out_record
from floatpage.merge.template import MergeTemplate
from floatpage.typeset.batch import runs_within_slots, typeset_batch
from floatpage.typeset.placed import place_document
from merge_helpers import COLUMNS, rows


def documents_of(folder, records):
    template = MergeTemplate(folder / "offer.toml")
    return [place_document(lay_out_record(template, dict(zip(COLUMNS, values))))
            for values in records]


def test_runs_hold_at_most_so_many_font_slots(merge_folder):
    documents = documents_of(merge_folder, rows(4))
    faces = [len(document.faces) for document in documents]
    assert runs_within_slots(documents, max_slots=10_000) == [[0, 1, 2, 3]]
    split = runs_within_slots(documents, max_slots=max(faces) + 2)
    assert [index for run in split for index in run] == [0, 1, 2, 3] and len(split) > 1
    assert runs_within_slots(documents, max_slots=1) == [[0], [1], [2], [3]]  # alone, if too many


def test_a_split_batch_makes_the_same_bytes_as_one_run(merge_folder):
    documents = documents_of(merge_folder, rows(3))
    assert typeset_batch(documents, max_slots=1) == typeset_batch(documents)
