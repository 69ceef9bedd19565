#include "checkpoint/CheckpointSet.hpp"

#include "checkpoint/ArchiveFile.hpp"
#include "checkpoint/CheckpointError.hpp"

#include <algorithm>
#include <cstdio>
#include <regex>

namespace fsi::checkpoint {
namespace {

constexpr char manifest_name[] = "manifest.ckpt";

} // namespace

CheckpointSet::CheckpointSet(std::filesystem::path root, CaseIdentity identity, int keep)
    : root_(std::move(root)), identity_(std::move(identity)), keep_(std::max(1, keep)) {}

std::filesystem::path CheckpointSet::folder_of(const std::filesystem::path &root, long step) {
  char name[32];
  std::snprintf(name, sizeof name, "step-%09ld", step);
  return root / name;
}

std::filesystem::path CheckpointSet::begin(long step) const {
  const auto dir = folder(step);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

const std::string &CheckpointSet::Found::checksum_of(const std::string &name) const {
  for (const auto &part : parts)
    if (part.name == name)
      return part.checksum;
  throw CheckpointError((folder / manifest_name).string() + ": lists no part '" + name + "'");
}

void CheckpointSet::complete(long step, double time_s, const std::vector<CheckpointPart> &parts) const {
  const auto dir = folder(step);
  StateArchive manifest;
  manifest.put_integer("format_version", format_version);
  manifest.put_text("fingerprint", identity_.fingerprint());
  if (!identity_.keys().empty())
    manifest.put_text("case_keys", identity_.keys());
  manifest.put_integer("step", step);
  manifest.put_double("time_s", time_s);
  manifest.put_integer("n_parts", static_cast<std::int64_t>(parts.size()));
  for (std::size_t i = 0; i < parts.size(); ++i) {
    manifest.put_text("parts/" + std::to_string(i) + "/name", parts[i].name);
    manifest.put_text("parts/" + std::to_string(i) + "/checksum", parts[i].checksum);
  }
  write_archive(dir / manifest_name, manifest);
  const auto steps = steps_newest_first();
  for (std::size_t i = static_cast<std::size_t>(keep_); i < steps.size(); ++i)
    std::filesystem::remove_all(folder(steps[i]));
}

std::vector<long> CheckpointSet::steps_newest_first() const {
  std::vector<long> steps;
  if (!std::filesystem::is_directory(root_))
    return steps;
  static const std::regex pattern("step-([0-9]{9})");
  for (const auto &entry : std::filesystem::directory_iterator(root_)) {
    std::smatch m;
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && std::regex_match(name, m, pattern) && std::filesystem::exists(entry.path() / manifest_name))
      steps.push_back(std::stol(m[1].str()));
  }
  std::sort(steps.rbegin(), steps.rend());
  return steps;
}

CheckpointSet::Found CheckpointSet::verify(long step) const {
  const auto dir = folder(step);
  const StateArchive manifest = read_archive(dir / manifest_name);
  const auto where = (dir / manifest_name).string();
  if (manifest.integer("format_version") != format_version)
    throw CheckpointError(where + ": checkpoint format " + std::to_string(manifest.integer("format_version")) +
                          ", this build reads " + std::to_string(format_version));
  const auto verdict = identity_.admits(
      {manifest.text("fingerprint"), manifest.has("case_keys") ? manifest.text("case_keys") : std::string()});
  if (!verdict.accepted)
    throw CheckpointError(where + ": " + verdict.refusal);
  if (manifest.integer("step") != step)
    throw CheckpointError(where + ": says step " + std::to_string(manifest.integer("step")) + " in the folder of step " +
                          std::to_string(step));
  const auto n_parts = manifest.integer("n_parts");
  Found found{step, manifest.number("time_s"), dir, {}, {}};
  if (!verdict.added_keys.empty()) {
    std::string added;
    for (const auto &key : verdict.added_keys)
      added += (added.empty() ? "" : "; ") + key;
    found.notes.push_back(where + ": written by a build without the keys " + added +
                          ": continued with them as they are now");
  }
  for (std::int64_t i = 0; i < n_parts; ++i) {
    const std::string name = manifest.text("parts/" + std::to_string(i) + "/name");
    const std::string expected = manifest.text("parts/" + std::to_string(i) + "/checksum");
    const auto part = dir / name;
    if (!std::filesystem::exists(part))
      throw CheckpointError(part.string() + ": missing (the manifest lists it)");
    const std::string actual = archive_checksum(part);
    if (actual != expected)
      throw CheckpointError(part.string() + ": checksum " + actual + ", the manifest says " + expected +
                            " (a part of another checkpoint)");
    found.parts.push_back({name, expected});
  }
  return found;
}

std::optional<CheckpointSet::Found> CheckpointSet::newest(std::vector<std::string> &skipped) const {
  for (const long step : steps_newest_first()) {
    try {
      return verify(step);
    } catch (const CheckpointError &error) {
      skipped.push_back(error.what());
    }
  }
  return std::nullopt;
}

} // namespace fsi::checkpoint
