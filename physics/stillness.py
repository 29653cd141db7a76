"""When a page counts as still: the threshold both modes share."""

# An A4 page counts as still when no item moves more than this per drawn frame (scaled with
# the page by page_scale).  A tenth of a millimetre is below a pixel at any sane zoom and far
# below a terminal cell.
STILL_MM_PER_FRAME = 0.1
