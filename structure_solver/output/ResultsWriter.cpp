#include "structure_solver/output/ResultsWriter.hpp"

#include "hdf5/H5Attributes.hpp"
#include "hdf5/H5Error.hpp"
#include "hdf5/H5FileAccess.hpp"
#include "structure_solver/output/ResultsPaths.hpp"

#include <ctime>
#include <stdexcept>

namespace fsi::structure::output {
namespace {

constexpr hsize_t scalar_rows_per_chunk = 1024;

std::string utc_now_iso8601() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

hdf5::H5Handle create_file(const std::filesystem::path &h5_path) {
  hdf5::silence_hdf5_error_printing();
  const std::string what = "cannot create the results file '" + h5_path.string() + "'";
  const hdf5::H5Handle access = hdf5::file_access_without_locking(what);
  return hdf5::H5Handle::file(H5Fcreate(h5_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), what);
}

std::string prefixed(const std::filesystem::path &h5_path, const std::string &message) {
  return "results file '" + h5_path.string() + "': " + message;
}

} // namespace

ResultsWriter::ResultsWriter(std::filesystem::path h5_path, std::filesystem::path xdmf_path,
                             RunMetadata meta)
    : h5_path_(std::move(h5_path)), file_(create_file(h5_path_)) {
  try {
    write_root_attributes(meta);
    structures_group_ = hdf5::H5Handle::group(
        H5Gcreate2(file_.get(), paths::structures_group, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
        "cannot create group /structures");
    time_s_ = std::make_unique<hdf5::ExtendableDataset>(
        file_.get(), paths::time_s, hdf5::ExtendableDataset::ElementType::float64, std::vector<hsize_t>{},
        scalar_rows_per_chunk, "s");
    step_ = std::make_unique<hdf5::ExtendableDataset>(file_.get(), paths::step,
                                                hdf5::ExtendableDataset::ElementType::int64,
                                                std::vector<hsize_t>{}, scalar_rows_per_chunk, "1");
    flush();
  } catch (const std::runtime_error &error) {
    throw std::runtime_error(prefixed(h5_path_, error.what()));
  }
  xdmf_ = std::make_unique<XdmfWriter>(std::move(xdmf_path), h5_path_);
}

ResultsWriter::~ResultsWriter() = default;

void ResultsWriter::add_structure(const StructureLayout &layout) {
  check_before_first_step("structure '" + layout.name + "'");
  for (const StructureSeries &existing : structures_) {
    if (existing.layout().name == layout.name) {
      throw std::invalid_argument(
          prefixed(h5_path_, "structure '" + layout.name + "' added twice"));
    }
  }
  const Connectivity connectivity = connectivity_of(layout);
  try {
    structures_.emplace_back(structures_group_.get(), layout, connectivity);
    xdmf_->add_structure(layout, connectivity);
    flush();
  } catch (const std::runtime_error &error) {
    fail(error);
  }
}

void ResultsWriter::add_probe(const std::string &name) {
  check_before_first_step("probe '" + name + "'");
  for (const ProbeSeries &existing : probes_) {
    if (existing.name() == name) {
      throw std::invalid_argument(prefixed(h5_path_, "probe '" + name + "' added twice"));
    }
  }
  try {
    if (!probes_group_.valid()) {
      probes_group_ = hdf5::H5Handle::group(
          H5Gcreate2(file_.get(), paths::probes_group, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
          "cannot create group /probes");
    }
    probes_.emplace_back(probes_group_.get(), name);
    flush();
  } catch (const std::runtime_error &error) {
    fail(error);
  }
}

void ResultsWriter::write_step(const StepRecord &record) {
  throw_if_failed();
  check_record(record);
  try {
    append_rows(record);
    flush();
    ++n_saved_;
    // The marker after the rows are flushed: a reader trusts only the rows it counts (HDF5 does
    // not sync, and a process killed during a flush has left an extended but unwritten row).
    hdf5::write_int64_attribute(file_.get(), "complete_steps", n_saved_);
    flush();
    xdmf_->append_step(record.time_s);
  } catch (const std::runtime_error &error) {
    fail(error);
  }
}

void ResultsWriter::set_exit(std::size_t index, double time_s, const std::string &reason) {
  throw_if_failed();
  try {
    structures_.at(index).set_exit(time_s, reason);
    flush();
  } catch (const std::runtime_error &error) {
    fail(error);
  }
}

void ResultsWriter::set_status(const std::string &status) {
  try {
    hdf5::write_string_attribute(file_.get(), "status", status);
    flush();
  } catch (const std::runtime_error &error) {
    throw std::runtime_error(prefixed(h5_path_, error.what()));
  }
}

void ResultsWriter::write_root_attributes(const RunMetadata &meta) {
  hdf5::write_string_attribute(file_.get(), "units", "SI");
  hdf5::write_string_attribute(file_.get(), "config_yaml", meta.config_yaml);
  hdf5::write_string_attribute(file_.get(), "code_version", meta.code_version);
  hdf5::write_string_attribute(file_.get(), "status", "running");
  hdf5::write_string_attribute(file_.get(), "created_utc", utc_now_iso8601());
  hdf5::write_int64_attribute(file_.get(), "complete_steps", 0);
}

void ResultsWriter::check_before_first_step(const std::string &what) const {
  throw_if_failed();
  if (n_saved_ > 0) {
    throw std::logic_error(prefixed(h5_path_, what + " added after the first step"));
  }
}

void ResultsWriter::check_record(const StepRecord &record) const {
  if (record.probes.size() != probes_.size()) {
    throw std::invalid_argument(prefixed(h5_path_, "step " + std::to_string(record.step) + " has " +
                                                       std::to_string(record.probes.size()) +
                                                       " probe states, the file has " +
                                                       std::to_string(probes_.size()) + " probes"));
  }
  if (record.structures.size() != structures_.size()) {
    throw std::invalid_argument(prefixed(h5_path_, "step " + std::to_string(record.step) + " has " +
                                                       std::to_string(record.structures.size()) +
                                                       " structure states, the file has " +
                                                       std::to_string(structures_.size()) +
                                                       " structures"));
  }
  for (std::size_t i = 0; i < structures_.size(); ++i) {
    try {
      structures_[i].check(record.structures[i]);
    } catch (const std::invalid_argument &error) {
      throw std::invalid_argument(prefixed(h5_path_, error.what()));
    }
  }
}

/// Per-structure and per-probe rows first and /time_s last: a reader that trusts the length of /time_s
/// never sees a partly written step.
void ResultsWriter::append_rows(const StepRecord &record) {
  for (std::size_t i = 0; i < structures_.size(); ++i) {
    structures_[i].append(record.structures[i]);
  }
  for (std::size_t i = 0; i < probes_.size(); ++i) {
    probes_[i].append(record.probes[i]);
  }
  const std::int64_t step = record.step;
  step_->append_row(&step);
  time_s_->append_row(&record.time_s);
}

void ResultsWriter::flush() { hdf5::check_hdf5(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL), "cannot flush"); }

void ResultsWriter::throw_if_failed() const {
  if (!failure_.empty()) {
    throw std::runtime_error("results file '" + h5_path_.string() +
                             "' is unusable after an earlier error: " + failure_);
  }
}

void ResultsWriter::fail(const std::exception &error) {
  failure_ = error.what();
  throw std::runtime_error(prefixed(h5_path_, error.what()));
}

} // namespace fsi::structure::output
