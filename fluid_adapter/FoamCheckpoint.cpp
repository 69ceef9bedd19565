#include "FoamCheckpoint.hpp"

#include "checkpoint/ArchiveFile.hpp"
#include "checkpoint/CheckpointError.hpp"
#include "common/Fnv1a.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <vector>

namespace fsi::fluid {

namespace fs = std::filesystem;

namespace {

std::vector<fs::path> files_under(const fs::path &folder) {
  std::vector<fs::path> files;
  for (const auto &entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file())
      files.push_back(fs::relative(entry.path(), folder));
  std::sort(files.begin(), files.end());
  return files;
}

std::string hash_of(const fs::path &file) {
  common::Fnv1a hash;
  hash.add_file(file);
  return hash.hex();
}

/// system/controlDict: startFrom startTime, startTime the restored time folder (not latestTime:
/// the killed run may have written later time folders).
void start_from(const fs::path &foam_case, const std::string &time_name) {
  const fs::path dict = foam_case / "system" / "controlDict";
  std::ifstream in(dict);
  std::stringstream text;
  text << in.rdbuf();
  const std::regex start_from("startFrom\\s+[A-Za-z]+\\s*;"), start_time("startTime\\s+[^;]+;");
  if (!std::regex_search(text.str(), start_from) || !std::regex_search(text.str(), start_time))
    throw checkpoint::CheckpointError(dict.string() + ": no `startFrom` or `startTime` entry to restart from");
  std::string changed = std::regex_replace(text.str(), start_from, "startFrom       startTime;");
  changed = std::regex_replace(changed, start_time, "startTime       " + time_name + ";");
  std::ofstream(dict) << changed;
}

/// The time folders of one checkpoint, relative to the case: <time>, or processor<k>/<time>.
std::vector<fs::path> time_folders(const std::string &time_name, int n_ranks) {
  if (n_ranks <= 1)
    return {fs::path(time_name)};
  std::vector<fs::path> folders;
  for (int k = 0; k < n_ranks; ++k)
    folders.push_back(fs::path("processor" + std::to_string(k)) / time_name);
  return folders;
}

} // namespace

checkpoint::CheckpointPart FoamCheckpoint::write(const fs::path &foam_case, const std::string &time_name, int n_ranks,
                                                 const fs::path &set_folder, long step) {
  const fs::path target = set_folder / "fluid";
  fs::remove_all(target);
  for (const auto &folder : time_folders(time_name, n_ranks)) {
    fs::create_directories((target / folder).parent_path());
    fs::copy(foam_case / folder, target / folder, fs::copy_options::recursive);
  }
  checkpoint::StateArchive archive;
  archive.put_integer("step", step);
  archive.put_text("time_name", time_name);
  archive.put_integer("n_ranks", n_ranks);
  const auto files = files_under(target);
  archive.put_integer("n_files", static_cast<std::int64_t>(files.size()));
  for (std::size_t i = 0; i < files.size(); ++i) {
    archive.put_text("files/" + std::to_string(i) + "/name", files[i].generic_string());
    archive.put_text("files/" + std::to_string(i) + "/hash", hash_of(target / files[i]));
  }
  return {part_name, checkpoint::write_archive(set_folder / part_name, archive)};
}

std::string FoamCheckpoint::install(const fs::path &set_folder, const fs::path &foam_case, int n_ranks, long step,
                                    const std::string &checksum) {
  const fs::path part = set_folder / part_name;
  const checkpoint::StateArchive archive = checkpoint::read_archive(part);
  if (!checksum.empty() && checkpoint::archive_checksum(part) != checksum)
    throw checkpoint::CheckpointError(part.string() + ": checksum " + checkpoint::archive_checksum(part) +
                                      ", the checkpoint's manifest says " + checksum);
  if (archive.integer("step") != step)
    throw checkpoint::CheckpointError(part.string() + ": holds step " + std::to_string(archive.integer("step")) +
                                      ", the set is of step " + std::to_string(step));
  const auto written_ranks = archive.has("n_ranks") ? archive.integer("n_ranks") : 1;
  if (written_ranks != n_ranks)
    throw checkpoint::CheckpointError(part.string() + ": written by " + std::to_string(written_ranks) +
                                      " MPI ranks; this run has fluid.openfoam.mpi_ranks " + std::to_string(n_ranks) +
                                      " (a restart keeps the decomposition)");
  const std::string time_name = archive.text("time_name");
  const fs::path source = set_folder / "fluid";
  const auto n_files = archive.integer("n_files");
  for (std::int64_t i = 0; i < n_files; ++i) {
    const fs::path file = source / archive.text("files/" + std::to_string(i) + "/name");
    if (!fs::exists(file))
      throw checkpoint::CheckpointError(file.string() + ": missing (" + part.string() + " lists it)");
    if (hash_of(file) != archive.text("files/" + std::to_string(i) + "/hash"))
      throw checkpoint::CheckpointError(file.string() + ": its contents are not the ones checkpointed (hash " +
                                        hash_of(file) + ", " + part.string() + " says " +
                                        archive.text("files/" + std::to_string(i) + "/hash") + ")");
  }
  for (const auto &folder : time_folders(time_name, n_ranks)) {
    if (n_ranks > 1 && !fs::exists(foam_case / folder.parent_path() / "constant"))
      throw checkpoint::CheckpointError((foam_case / folder.parent_path()).string() +
                                        ": no decomposed mesh to resume into (the run's case was removed?)");
    fs::remove_all(foam_case / folder);
    fs::copy(source / folder, foam_case / folder, fs::copy_options::recursive);
  }
  start_from(foam_case, time_name);
  return time_name;
}

} // namespace fsi::fluid
