#include "checkpoint/CaseIdentity.hpp"

#include <map>
#include <sstream>

namespace fsi::checkpoint {
namespace {

constexpr std::size_t max_named = 6;

/// "key = value" lines as key -> value, in the order they came (a vector of pairs keeps it).
std::vector<std::pair<std::string, std::string>> parse(const std::string &keys) {
  std::vector<std::pair<std::string, std::string>> entries;
  std::istringstream in(keys);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find(" = ");
    if (eq != std::string::npos)
      entries.emplace_back(line.substr(0, eq), line.substr(eq + 3));
  }
  return entries;
}

/// The section holding `key`: "a.b" of "a.b.c", "structures[1]" of "structures[1].mesh"; "" at the top.
std::string parent_of(const std::string &key) {
  const auto dot = key.rfind('.');
  return dot == std::string::npos ? std::string() : key.substr(0, dot);
}

/// Whether `then` had the section `parent` (one of its keys lies in it).
bool had_section(const std::map<std::string, std::string> &then, const std::string &parent) {
  if (parent.empty())
    return false; // a new top-level key is a new section of the case, not a new default
  const std::string prefix = parent + ".";
  const auto it = then.lower_bound(prefix);
  return it != then.end() && it->first.compare(0, prefix.size(), prefix) == 0;
}

std::string listed(const std::vector<std::string> &items) {
  std::string text;
  for (std::size_t i = 0; i < items.size() && i < max_named; ++i)
    text += (i ? "; " : "") + items[i];
  if (items.size() > max_named)
    text += "; and " + std::to_string(items.size() - max_named) + " more";
  return text;
}

} // namespace

CaseIdentity::Verdict CaseIdentity::admits(const CaseIdentity &then) const {
  Verdict verdict;
  if (then.fingerprint_ == fingerprint_) {
    verdict.accepted = true;
    return verdict;
  }
  const std::string differs = "written by another case (fingerprint " + then.fingerprint_ + ", this case's is " +
                              fingerprint_ + ")";
  if (then.keys_.empty() || keys_.empty()) {
    verdict.refusal = differs + ": a change of the case other than run.end_time_s";
    return verdict;
  }
  const auto then_entries = parse(then.keys_);
  const std::map<std::string, std::string> then_map(then_entries.begin(), then_entries.end());
  const auto now_entries = parse(keys_);
  const std::map<std::string, std::string> now_map(now_entries.begin(), now_entries.end());
  std::vector<std::string> changed;
  for (const auto &[key, value] : then_entries) {
    const auto it = now_map.find(key);
    if (it == now_map.end())
      changed.push_back(key + " was " + value + ", is not set now");
    else if (it->second != value)
      changed.push_back(key + " was " + value + ", is " + it->second + " now");
  }
  for (const auto &[key, value] : now_entries)
    if (!then_map.count(key)) {
      if (had_section(then_map, parent_of(key)))
        verdict.added_keys.push_back(key + " = " + value);
      else
        changed.push_back(key + " is new (" + value + ")");
    }
  if (!changed.empty()) {
    verdict.refusal = differs + ": " + listed(changed);
    verdict.added_keys.clear();
    return verdict;
  }
  if (verdict.added_keys.empty()) {
    verdict.refusal = differs + ": its keys agree with this case's, its fingerprint does not (a manifest edited, or "
                                "written by a build that hashes the case otherwise)";
    return verdict;
  }
  verdict.accepted = true;
  return verdict;
}

} // namespace fsi::checkpoint
