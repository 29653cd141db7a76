"""`floatpage merge`: one personalised document per record of a data file.

Each record fills the template's placeholders (plain substitution, see placeholders.py),
gets its pictures at their own proportions, is settled again by the physics from the
template's positions and must pass the quality gate; many records are then typeset in
one LuaLaTeX run (typeset.batch) on a local process pool or a Dask cluster (run.py).
"""
