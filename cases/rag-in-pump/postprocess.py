#!/usr/bin/python3
"""After a run of rag-in-pump (./fsi run calls it; ./fsi rag-ensemble calls it per member): the
clogging metrics (python/fsi/rag_metrics.py: outcome, residence time, time to the cut-water, wrap on
the leading edge, trap sites, what the rag costs the pump, strain and wall distance) written to
rag_metrics.csv, rag_metrics.yaml and rag_summary.png; and the pictures of the passage
(python/fsi/plot_rag_in_pump.py: rag_sequence.png as the paper's Figs. 12-13, rag_wrap.png as its
Fig. 14, rag_passage.mp4); and the impeller at its pose of every saved frame for ParaView
(python/fsi/impeller_xdmf.py: impeller.xdmf beside structure.xdmf).
Usage: postprocess.py RESULTS_DIR CASE_DIR [--no-animation]"""

import sys

from fsi import impeller_xdmf  # scripts/, on PYTHONPATH (./fsi run, ./fsi rag-ensemble)
from fsi import plot_rag_in_pump
from fsi import rag_metrics


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    if len(args) != 2:
        sys.exit(__doc__.splitlines()[-1])
    out, case_dir = args
    metrics = rag_metrics.write_metrics(out, case_dir)
    files = plot_rag_in_pump.write_pictures(out, case_dir, animation="--no-animation" not in argv)
    files.append(impeller_xdmf.write(out, case_dir))
    print("rag %s%s; rag_metrics.csv, rag_summary.png, %s"
          % (metrics.get("outcome", "?"),
             " at t = %.3g s" % metrics["exit_time_s"] if metrics.get("exit_time_s") is not None else "",
             ", ".join(f.rsplit("/", 1)[-1] for f in files)))


if __name__ == "__main__":
    main(sys.argv)
