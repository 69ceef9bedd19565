#pragma once
// What a restart keeps of the results an earlier run wrote: its saved steps up to the
// checkpoint's step, copied row by row, bit for bit, into the new results file (and probes.csv),
// so that the restarted run appends to them and no step is lost or written twice.

#include "structure_solver/output/ProbeCsv.hpp"
#include "structure_solver/output/ResultsWriter.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace fsi::structure::output {

struct ReplayedSteps {
  long n_rows = 0;     ///< saved steps kept
  long last_step = -1; ///< the last one's step number (-1: none)
};

/// Copies the saved steps of `source` whose step is at most `last_step` and a multiple of
/// `output_every` (the run's own cadence: the extra final step of a run that ended early is
/// left out, as the uninterrupted run does not have it) into `writer` (whose
/// structures and probes are `structure_names` and `probe_names`, in its order) and `csv` (may
/// be null). Throws std::runtime_error naming `source` when it lacks one of them.
ReplayedSteps replay_results(const std::filesystem::path &source, ResultsWriter &writer, ProbeCsv *csv,
                             const std::vector<std::string> &structure_names,
                             const std::vector<std::string> &probe_names, long last_step, long output_every);

} // namespace fsi::structure::output
