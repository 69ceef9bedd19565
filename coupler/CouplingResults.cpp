#include "CouplingResults.hpp"

#include "hdf5/H5Attributes.hpp"
#include "hdf5/H5Error.hpp"
#include "hdf5/H5FileAccess.hpp"

namespace fsi::coupler {

using hdf5::ExtendableDataset;
using hdf5::H5Handle;

CouplingResults::CouplingResults(const std::filesystem::path &h5_path, const std::string &config_yaml,
                                 const std::string &version)
    : path_(h5_path) {
  hdf5::silence_hdf5_error_printing();
  const std::string what = "cannot create the coupling results file " + h5_path.string();
  const H5Handle access = hdf5::file_access_without_locking(what);
  file_ = H5Handle::file(H5Fcreate(h5_path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get()), what);
  hdf5::write_string_attribute(file_.get(), "config_yaml", config_yaml);
  hdf5::write_string_attribute(file_.get(), "code_version", version);
  hdf5::write_string_attribute(file_.get(), "status", "running");
  constexpr hsize_t chunk = 256;
  step_ = std::make_unique<ExtendableDataset>(file_.get(), "step", ExtendableDataset::ElementType::int64,
                                              std::vector<hsize_t>{}, chunk, "1");
  time_ = std::make_unique<ExtendableDataset>(file_.get(), "time_s", ExtendableDataset::ElementType::float64,
                                              std::vector<hsize_t>{}, chunk, "s");
  force_ = std::make_unique<ExtendableDataset>(file_.get(), "total_force_on_fluid_n",
                                               ExtendableDataset::ElementType::float64, std::vector<hsize_t>{3},
                                               chunk, "N");
  iterations_ = std::make_unique<ExtendableDataset>(file_.get(), "coupling_iterations",
                                                    ExtendableDataset::ElementType::int64, std::vector<hsize_t>{},
                                                    chunk, "1");
  residual_ = std::make_unique<ExtendableDataset>(file_.get(), "coupling_residual",
                                                  ExtendableDataset::ElementType::float64, std::vector<hsize_t>{},
                                                  chunk, "1");
  timings_group_ = H5Handle::group(H5Gcreate2(file_.get(), "timings", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                   "cannot create /timings in " + h5_path.string());
  for (const auto name : StepTimings::names)
    timings_.emplace_back(timings_group_.get(), std::string(name), ExtendableDataset::ElementType::float64,
                          std::vector<hsize_t>{}, chunk, "s");
  flush();
}

CouplingResults::CouplingResults(const std::filesystem::path &h5_path, long last_step) : path_(h5_path) {
  hdf5::silence_hdf5_error_printing();
  const std::string what = "cannot open the coupling results file " + h5_path.string() + " to continue it";
  const H5Handle access = hdf5::file_access_without_locking(what);
  file_ = H5Handle::file(H5Fopen(h5_path.c_str(), H5F_ACC_RDWR, access.get()), what);
  {
    const H5Handle steps = H5Handle::dataset(H5Dopen2(file_.get(), "step", H5P_DEFAULT), what);
    const H5Handle space = H5Handle::dataspace(H5Dget_space(steps.get()), what);
    std::vector<std::int64_t> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
    if (!values.empty())
      hdf5::check_hdf5(H5Dread(steps.get(), H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), what);
    while (kept_rows_ < values.size() && values[kept_rows_] <= last_step)
      ++kept_rows_;
    const std::int64_t last_kept = kept_rows_ > 0 ? values[kept_rows_ - 1] : 0;
    if (last_kept != last_step)
      throw std::runtime_error(h5_path.string() + " holds the steps up to " + std::to_string(last_kept) +
                               ", not up to the checkpoint's step " + std::to_string(last_step));
  }
  hdf5::write_string_attribute(file_.get(), "status", "running");
  step_ = std::make_unique<ExtendableDataset>(file_.get(), "step", ExtendableDataset::ElementType::int64, kept_rows_);
  time_ = std::make_unique<ExtendableDataset>(file_.get(), "time_s", ExtendableDataset::ElementType::float64, kept_rows_);
  force_ = std::make_unique<ExtendableDataset>(file_.get(), "total_force_on_fluid_n",
                                               ExtendableDataset::ElementType::float64, kept_rows_);
  iterations_ = std::make_unique<ExtendableDataset>(file_.get(), "coupling_iterations",
                                                    ExtendableDataset::ElementType::int64, kept_rows_);
  residual_ = std::make_unique<ExtendableDataset>(file_.get(), "coupling_residual",
                                                  ExtendableDataset::ElementType::float64, kept_rows_);
  timings_group_ = H5Handle::group(H5Gopen2(file_.get(), "timings", H5P_DEFAULT), what);
  for (const auto name : StepTimings::names)
    timings_.emplace_back(timings_group_.get(), std::string(name), ExtendableDataset::ElementType::float64, kept_rows_);
  if (H5Lexists(file_.get(), "rigid_bodies", H5P_DEFAULT) > 0)
    bodies_group_ = H5Handle::group(H5Gopen2(file_.get(), "rigid_bodies", H5P_DEFAULT), what);
  flush();
}

CouplingResults::~CouplingResults() = default;

void CouplingResults::flush() {
  last_flush_ = std::chrono::steady_clock::now();
  hdf5::check_hdf5(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL), "cannot flush " + path_.string());
  // The marker after the rows are flushed: a reader trusts only the rows it counts.
  hdf5::write_int64_attribute(file_.get(), "complete_steps", static_cast<std::int64_t>(step_->n_rows()));
  hdf5::check_hdf5(H5Fflush(file_.get(), H5F_SCOPE_GLOBAL), "cannot flush " + path_.string());
}

void CouplingResults::write_step(long step, double time_s, const StepTimings &timings,
                                 const double total_force_on_fluid_n[3], int iterations, double residual) {
  const std::int64_t s = step, k = iterations;
  step_->append_row(&s);
  time_->append_row(&time_s);
  force_->append_row(total_force_on_fluid_n);
  iterations_->append_row(&k);
  residual_->append_row(&residual);
  const auto values = timings.values();
  for (std::size_t i = 0; i < values.size(); ++i)
    timings_[i].append_row(&values[i]);
  if (std::chrono::steady_clock::now() - last_flush_ >= std::chrono::seconds(1))
    flush();
}

void CouplingResults::write_rigid_body_load(const std::string &name, const double force_n[3],
                                            const double torque_n_m[3]) {
  auto found = bodies_.find(name);
  if (found == bodies_.end()) {
    if (!bodies_group_.valid())
      bodies_group_ = H5Handle::group(H5Gcreate2(file_.get(), "rigid_bodies", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                      "cannot create /rigid_bodies in " + path_.string());
    BodySeries series;
    if (kept_rows_ > 0 && H5Lexists(bodies_group_.get(), name.c_str(), H5P_DEFAULT) > 0) { // a restart's
      series.group = H5Handle::group(H5Gopen2(bodies_group_.get(), name.c_str(), H5P_DEFAULT),
                                     "cannot open /rigid_bodies/" + name + " in " + path_.string());
      series.force = std::make_unique<ExtendableDataset>(series.group.get(), "force_n",
                                                         ExtendableDataset::ElementType::float64, kept_rows_);
      series.torque = std::make_unique<ExtendableDataset>(series.group.get(), "torque_n_m",
                                                          ExtendableDataset::ElementType::float64, kept_rows_);
      found = bodies_.emplace(name, std::move(series)).first;
      found->second.force->append_row(force_n);
      found->second.torque->append_row(torque_n_m);
      return;
    }
    series.group = H5Handle::group(H5Gcreate2(bodies_group_.get(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                                   "cannot create /rigid_bodies/" + name + " in " + path_.string());
    series.force = std::make_unique<ExtendableDataset>(series.group.get(), "force_n", ExtendableDataset::ElementType::float64,
                                                       std::vector<hsize_t>{3}, 256, "N");
    series.torque = std::make_unique<ExtendableDataset>(series.group.get(), "torque_n_m",
                                                        ExtendableDataset::ElementType::float64, std::vector<hsize_t>{3},
                                                        256, "N m");
    found = bodies_.emplace(name, std::move(series)).first;
  }
  found->second.force->append_row(force_n);
  found->second.torque->append_row(torque_n_m);
}

void CouplingResults::set_status(const std::string &status) {
  hdf5::write_string_attribute(file_.get(), "status", status);
  flush();
}

} // namespace fsi::coupler
