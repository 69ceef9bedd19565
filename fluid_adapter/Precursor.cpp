#include "Precursor.hpp"

#include "common/ConfigEmitter.hpp"
#include "common/Fnv1a.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace fsi::fluid {

namespace fs = std::filesystem;

namespace {

bool is_number(const std::string &name, double &value) {
  try {
    std::size_t used = 0;
    value = std::stod(name, &used);
    return used == name.size();
  } catch (const std::exception &) {
    return false;
  }
}

std::string read_text(const fs::path &file) {
  std::ifstream in(file);
  std::string text;
  std::getline(in, text);
  return text;
}

} // namespace

Precursor::Precursor(const PrecursorInputs &inputs, fs::path case_dir, fs::path output_dir)
    : folder_(std::move(output_dir) / "precursor") {
  if (!inputs.openfoam)
    return;
  const auto &foam = *inputs.openfoam;
  end_time_s_ = foam.precursor_time_s;
  time_step_s_ = foam.precursor_time_step_s > 0.0 ? foam.precursor_time_step_s : inputs.coupled_time_step_s;
  coupled_time_step_s_ = inputs.coupled_time_step_s;
  if (wanted())
    fingerprint_ = compute_fingerprint(inputs, case_dir);
}

std::string Precursor::compute_fingerprint(const PrecursorInputs &inputs, const fs::path &case_dir) const {
  common::Fnv1a hash;
  hash.add(inputs.fluid_yaml);
  if (!inputs.collisions_yaml.empty())
    hash.add(inputs.collisions_yaml);
  hash.add(std::to_string(end_time_s_));
  for (const double dt : step_sizes()) // the schedule itself, hand-over ramp included
    hash.add(std::to_string(dt));
  // Every file of the OpenFOAM case folder, in a fixed order, with its relative path.
  const fs::path template_dir = case_dir / inputs.openfoam->case_directory;
  std::vector<fs::path> files;
  if (fs::is_directory(template_dir))
    for (const auto &entry : fs::recursive_directory_iterator(template_dir))
      if (entry.is_regular_file())
        files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const auto &file : files) {
    hash.add(fs::relative(file, template_dir).generic_string());
    hash.add_file(file);
  }
  for (const auto &file : inputs.surface_stl_files)
    hash.add_file(file);
  // A warm start (fluid.openfoam.initial_fields_from): the source's latest fields, so that a rerun
  // of the source run makes this precursor run again.
  if (!inputs.openfoam->initial_fields_from.empty()) {
    fs::path source = inputs.openfoam->initial_fields_from;
    if (source.is_relative())
      source = case_dir / source;
    std::error_code error;
    if (fs::is_directory(source, error)) {
      try {
        const fs::path latest = latest_time_directory(source);
        hash.add(latest.filename().string());
        std::vector<fs::path> fields;
        for (const auto &entry : fs::directory_iterator(latest))
          if (entry.is_regular_file())
            fields.push_back(entry.path());
        std::sort(fields.begin(), fields.end());
        for (const auto &field : fields) {
          hash.add(field.filename().string());
          hash.add_file(field);
        }
      } catch (const std::runtime_error &) { // no fields there: the warm start says so when it maps them
      }
    }
  }
  return hash.hex();
}

std::vector<double> Precursor::step_sizes() const {
  // Backwards from the end: handover_steps at the coupled dt, then a geometric ramp up to the
  // precursor's own dt (each step at most 1.25 times the next), then its own dt from t = 0.
  std::vector<double> tail;
  double covered = 0.0;
  if (coupled_time_step_s_ < time_step_s_) {
    for (int i = 0; i < handover_steps && covered + coupled_time_step_s_ <= end_time_s_ + 1e-12; ++i) {
      tail.push_back(coupled_time_step_s_);
      covered += coupled_time_step_s_;
    }
    for (double dt = 1.25 * coupled_time_step_s_; dt < time_step_s_ && covered + dt <= end_time_s_; dt *= 1.25) {
      tail.push_back(dt);
      covered += dt;
    }
  }
  // The rest in equal steps of at most its own dt (no short last step before the ramp).
  const double bulk_end = end_time_s_ - covered;
  const auto n_bulk = static_cast<std::size_t>(std::ceil(bulk_end / time_step_s_ - 1e-9));
  std::vector<double> steps(n_bulk, n_bulk > 0 ? bulk_end / static_cast<double>(n_bulk) : 0.0);
  steps.insert(steps.end(), tail.rbegin(), tail.rend());
  return steps;
}

bool Precursor::is_current() const {
  return wanted() && fs::exists(stamp_file()) && read_text(stamp_file()) == fingerprint_;
}

void Precursor::mark_complete() const { std::ofstream(stamp_file()) << fingerprint_ << "\n"; }

void Precursor::invalidate() const {
  // Every earlier file goes, unlinked rather than overwritten: a precursor folder seeded with
  // hard links (./fsi rag-ensemble's members, a copy made with cp -al) then never writes into
  // the files it shares with another run's precursor. The launcher's console files stay: it has
  // just made them anew (python/fsi/fsi_launch.py) and writes the solver's residuals into them.
  std::error_code error;
  if (fs::is_directory(folder_))
    for (const auto &entry : fs::directory_iterator(folder_))
      if (entry.path().extension() != ".console")
        fs::remove_all(entry.path(), error);
}

fs::path Precursor::latest_time_directory(const fs::path &folder) {
  fs::path latest;
  double latest_time = -1.0;
  if (fs::is_directory(folder))
    for (const auto &entry : fs::directory_iterator(folder)) {
      double time = 0.0;
      if (entry.is_directory() && is_number(entry.path().filename().string(), time) && time > latest_time) {
        latest_time = time;
        latest = entry.path();
      }
    }
  if (latest.empty())
    throw std::runtime_error(folder.string() + ": no time folder (the precursor wrote no fields)");
  return latest;
}

std::size_t Precursor::install_fields(const fs::path &coupled_case, int n_ranks) const {
  std::vector<std::pair<fs::path, fs::path>> folders; // precursor folder -> coupled case folder
  if (n_ranks <= 1)
    folders.emplace_back(foam_case(), coupled_case);
  for (int rank = 0; n_ranks > 1 && rank < n_ranks; ++rank) {
    const std::string processor = "processor" + std::to_string(rank);
    folders.emplace_back(foam_case() / processor, coupled_case / processor);
  }
  std::size_t copied = 0;
  for (const auto &[from, to] : folders) {
    const fs::path source = latest_time_directory(from), target = to / "0";
    fs::create_directories(target);
    for (const auto &entry : fs::directory_iterator(source))
      if (entry.is_regular_file()) {
        fs::copy_file(entry.path(), target / entry.path().filename(), fs::copy_options::overwrite_existing);
        ++copied;
      }
  }
  if (copied == 0)
    throw std::runtime_error(foam_case().string() + ": the precursor's last time folder holds no field");
  return copied;
}

} // namespace fsi::fluid
