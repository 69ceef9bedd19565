"""results_file.py: what a reader of a results file (structure.h5, coupling.h5) may trust.

The writers rewrite the root attribute `complete_steps` after each step's rows are flushed
(structure_solver/output/ResultsWriter.hpp, coupler/CouplingResults.hpp): a process killed
during a flush can leave a row extended but never written (zeros, or garbage). Every reader
takes only the first complete_rows(f) rows of the per-step series.
"""


def complete_rows(f):
    """The number of rows of the per-step series of an open h5py File that are complete: the
    `complete_steps` marker, at most the length of /time_s (older files without the marker: all)."""
    n = len(f["time_s"])
    return min(n, int(f.attrs.get("complete_steps", n)))
