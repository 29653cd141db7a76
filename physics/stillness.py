"""When a page counts as still: the threshold both modes share."""

# An A4 page counts as still when no item moves more than this per drawn frame (scaled with
# the page by page_scale).  A tenth of a millimetre is below a pixel at any sane zoom and far
# below a terminal cell.
STILL_MM_PER_FRAME = 0.1

# The heat of the gentle run that tells whether a settled page is at rest (model.layout's
# probes).  The snap's rest check (physics.rest_check) predicts that run's first step.
PROBE_HEAT = 0.02
