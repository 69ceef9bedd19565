"""The Python half of the project: the launcher of ./fsi run (fsi_launch), OpenFOAM dictionaries
(foam_case), results files (results_file, state_archive), pictures (plot_*), the pump's studies
(pump_*, impeller_xdmf), the rag metrics and ensembles (rag_*), reports and studies.

./fsi puts the folder holding this package on PYTHONPATH once for everything it starts (runs,
tests through CTest, benchmarks, studies), so every module imports its siblings as
`from fsi import foam_case`; nothing edits sys.path. A case's own helper (cases/<case>/*.py) is
loaded by path with case_module().
"""

import importlib.util
import os

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def case_module(case, name, cases_dir=None):
    """The module cases/<case>/<name>.py (a case's own measurement, such as flag-in-crossflow's
    flapping), loaded by path, without touching sys.path."""
    path = os.path.join(cases_dir or os.path.join(ROOT, "cases"), case, name + ".py")
    spec = importlib.util.spec_from_file_location("fsi_case_%s_%s" % (case.replace("-", "_"), name), path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
