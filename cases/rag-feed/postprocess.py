#!/usr/bin/python3
"""After a run of rag-feed (./fsi run calls it): the feed's report (python/fsi/feed_report.py):
each rag's fate (feed_rags.csv), the head and power per revolution against the clean pump
(feed_revolutions.csv), the clog criterion's verdict and the degree of saturation
(feed_report.yaml), feed_timeline.png, feed_retained.png and the movie feed.mp4; and the
impeller at its pose of every saved frame for ParaView (impeller.xdmf beside structure.xdmf).
Usage: postprocess.py RESULTS_DIR CASE_DIR [--no-animation]"""

import sys

from fsi import clog_criterion  # python/, on PYTHONPATH (./fsi run)
from fsi import feed_report
from fsi import impeller_xdmf
from fsi import rag_metrics


def main(argv):
    args = [a for a in argv[1:] if not a.startswith("--")]
    if len(args) != 2:
        sys.exit(__doc__.splitlines()[-1])
    out, case_dir = args
    try:
        report = feed_report.write_report(out, case_dir, animation="--no-animation" not in argv)
    except (feed_report.FeedError, rag_metrics.MetricsError, clog_criterion.CriterionError) as error:
        sys.exit("postprocess.py: %s" % error)
    impeller_xdmf.write(out, case_dir)
    verdict = report["verdict"]
    print("%d rags: %s%s; feed_report.yaml, feed_timeline.png, feed_retained.png"
          % (report["rags"], ", ".join("%d %s" % (n, o.replace("_", " ")) for o, n in report["outcomes"].items() if n),
             "" if verdict is None or verdict["clogged"] is None else ("; clogged at %.1f revolutions (%s)" % (verdict["revolution"], verdict["reason"])
                                         if verdict["clogged"] else "; not clogged")))


if __name__ == "__main__":
    main(sys.argv)
