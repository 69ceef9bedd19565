"""The runs of a study command (disc-study, ercoftac-study) side by side: each run's job on a
pool of threads (a thread waits on its run's processes), a failed run reported while the
others go on, progress after each."""

import concurrent.futures
import time


def run_all(runs, job, jobs, say):
    """Calls job(run) for every run, at most `jobs` at a time. A job that raises RuntimeError
    leaves its message in run.error and is said FAILED; the others go on. Says how many runs are
    done after each. Returns the runs left without a result (run.result None)."""
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as pool:
        futures = {pool.submit(job, r): r for r in runs}
        for i, future in enumerate(concurrent.futures.as_completed(futures)):
            try:
                future.result()
            except RuntimeError as e:
                futures[future].error = str(e)
                say("%s: FAILED: %s" % (futures[future].name, e))
            say("%d of %d runs done, %.0f s" % (i + 1, len(runs), time.monotonic() - start))
    return [r for r in runs if r.result is None]
