"""The docs held to what they describe. Figures: each count, rate and p-value a doc quotes
from a committed CSV carries a marker naming how to recompute it (markers.py), and the
check fails where the text and the rows disagree; `tools/doc-check update` rewrites the
text from the rows. References: every file, folder, section and `file:line`-free source
path the docs and the code's comments name must exist (references.py)."""
