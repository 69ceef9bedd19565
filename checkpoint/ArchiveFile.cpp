#include "checkpoint/ArchiveFile.hpp"

#include "checkpoint/CheckpointError.hpp"
#include "common/Fnv1a.hpp"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fsi::checkpoint {
namespace {

/// Fault hook of the reliability tests (R7): FSI_FAULT_KILL_BEFORE_RENAME=NAME:K kills this
/// process (SIGKILL, nothing cleaned up) when the K-th file named NAME is written and not yet
/// renamed to its final name.
void kill_here_if_asked(const std::filesystem::path &path) {
  static const char *asked = std::getenv("FSI_FAULT_KILL_BEFORE_RENAME");
  if (!asked)
    return;
  static int seen = 0;
  const std::string spec(asked);
  const auto colon = spec.rfind(':');
  const std::string name = spec.substr(0, colon);
  const int k = colon == std::string::npos ? 1 : std::atoi(spec.c_str() + colon + 1);
  if (path.filename() == name && ++seen == k)
    ::raise(SIGKILL);
}

constexpr char magic[] = "FSI-STATE-ARCHIVE\n";
constexpr std::size_t magic_size = sizeof magic - 1;
constexpr std::uint32_t format_version = 1;
constexpr std::uint32_t byte_order_mark = 0x01020304u;
constexpr std::size_t header_size = magic_size + 4 + 4 + 8 + 8;

template <class T> void put(std::string &out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string hex_of(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

std::uint64_t body_hash(const char *data, std::size_t size) {
  common::Fnv1a hash;
  hash.add_raw(data, size);
  return hash.value();
}

std::string encode_body(const StateArchive &archive) {
  std::string body;
  for (const auto &[name, e] : archive.entries()) {
    put<std::uint32_t>(body, static_cast<std::uint32_t>(name.size()));
    body += name;
    put<std::uint8_t>(body, static_cast<std::uint8_t>(e.kind));
    switch (e.kind) {
    case ArchiveEntry::Kind::doubles:
      put<std::uint32_t>(body, static_cast<std::uint32_t>(e.shape.size()));
      for (const auto d : e.shape)
        put<std::uint64_t>(body, d);
      body.append(reinterpret_cast<const char *>(e.values.data()), e.values.size() * sizeof(double));
      break;
    case ArchiveEntry::Kind::integer:
      put<std::int64_t>(body, e.integer);
      break;
    case ArchiveEntry::Kind::text:
      put<std::uint64_t>(body, e.text.size());
      body += e.text;
      break;
    }
  }
  return body;
}

void write_all(int fd, const std::string &bytes, const std::filesystem::path &path) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      throw std::runtime_error("cannot write the checkpoint file '" + path.string() + "': " + std::strerror(errno));
    done += static_cast<std::size_t>(n);
  }
}

void sync_folder(const std::filesystem::path &folder) {
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

/// Reads what `path` holds and checks its frame; returns the body's bytes.
class Cursor {
public:
  Cursor(const std::string &bytes, std::size_t begin, std::size_t end, const std::filesystem::path &path)
      : bytes_(bytes), at_(begin), end_(end), path_(path) {}
  template <class T> T take(const char *what) {
    need(sizeof(T), what);
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::string take_bytes(std::size_t n, const char *what) {
    need(n, what);
    std::string out = bytes_.substr(at_, n);
    at_ += n;
    return out;
  }
  void take_doubles(std::vector<double> &out, std::size_t n, const char *what) {
    if (n > (end_ - at_) / sizeof(double))
      need(end_ - at_ + 1, what);
    out.resize(n);
    std::memcpy(out.data(), bytes_.data() + at_, n * sizeof(double));
    at_ += n * sizeof(double);
  }
  bool done() const { return at_ == end_; }

private:
  void need(std::size_t n, const char *what) const {
    if (n > end_ - at_)
      throw CheckpointError(path_.string() + ": " + what + " runs past the end of the archive's body");
  }
  const std::string &bytes_;
  std::size_t at_, end_;
  const std::filesystem::path &path_;
};

std::string read_file(const std::filesystem::path &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw CheckpointError(path.string() + ": cannot be opened (" + std::strerror(errno) + ")");
  std::ostringstream contents;
  contents << in.rdbuf();
  return contents.str();
}

/// The body's [begin, end) after checking the header, the length and the checksum.
std::pair<std::size_t, std::size_t> checked_frame(const std::string &bytes, const std::filesystem::path &path,
                                                  std::uint64_t &n_entries, std::uint64_t &checksum) {
  if (bytes.size() < header_size + 8)
    throw CheckpointError(path.string() + ": truncated (" + std::to_string(bytes.size()) +
                          " bytes, shorter than an empty archive)");
  if (bytes.compare(0, magic_size, magic) != 0)
    throw CheckpointError(path.string() + ": not a state archive (wrong first bytes)");
  Cursor header(bytes, magic_size, header_size, path);
  const auto version = header.take<std::uint32_t>("the format version");
  const auto order = header.take<std::uint32_t>("the byte-order mark");
  n_entries = header.take<std::uint64_t>("the number of entries");
  const auto body_length = header.take<std::uint64_t>("the body length");
  if (version != format_version)
    throw CheckpointError(path.string() + ": format version " + std::to_string(version) + ", this build reads " +
                          std::to_string(format_version));
  if (order != byte_order_mark)
    throw CheckpointError(path.string() + ": written on a machine of another byte order");
  if (bytes.size() != header_size + body_length + 8)
    throw CheckpointError(path.string() + ": " +
                          (bytes.size() < header_size + body_length + 8 ? "truncated" : "longer than its header says") +
                          " (" + std::to_string(bytes.size()) + " bytes, the header says " +
                          std::to_string(header_size + body_length + 8) + ")");
  Cursor trailer(bytes, header_size + body_length, bytes.size(), path);
  checksum = trailer.take<std::uint64_t>("the checksum");
  const std::uint64_t actual = body_hash(bytes.data() + header_size, body_length);
  if (actual != checksum)
    throw CheckpointError(path.string() + ": checksum mismatch (the file says " + hex_of(checksum) + ", its body is " +
                          hex_of(actual) + "): the file is corrupted");
  return {header_size, header_size + body_length};
}

} // namespace

std::string write_archive(const std::filesystem::path &path, const StateArchive &archive) {
  const std::string body = encode_body(archive);
  const std::uint64_t checksum = body_hash(body.data(), body.size());
  std::string bytes(magic, magic_size);
  put<std::uint32_t>(bytes, format_version);
  put<std::uint32_t>(bytes, byte_order_mark);
  put<std::uint64_t>(bytes, archive.entries().size());
  put<std::uint64_t>(bytes, body.size());
  bytes += body;
  put<std::uint64_t>(bytes, checksum);

  const std::filesystem::path temporary = path.string() + ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error("cannot create the checkpoint file '" + temporary.string() + "': " + std::strerror(errno));
  try {
    write_all(fd, bytes, temporary);
    if (::fsync(fd) != 0)
      throw std::runtime_error("cannot sync the checkpoint file '" + temporary.string() + "': " + std::strerror(errno));
  } catch (...) {
    ::close(fd);
    ::unlink(temporary.c_str());
    throw;
  }
  ::close(fd);
  kill_here_if_asked(path);
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    throw std::runtime_error("cannot rename '" + temporary.string() + "' to '" + path.string() +
                             "': " + std::strerror(error));
  }
  sync_folder(path.parent_path());
  return hex_of(checksum);
}

StateArchive read_archive(const std::filesystem::path &path) {
  const std::string bytes = read_file(path);
  std::uint64_t n_entries = 0, checksum = 0;
  const auto [begin, end] = checked_frame(bytes, path, n_entries, checksum);
  Cursor in(bytes, begin, end, path);
  StateArchive archive;
  archive.set_source(path.string());
  for (std::uint64_t i = 0; i < n_entries; ++i) {
    const auto name_length = in.take<std::uint32_t>("an entry's name length");
    const std::string name = in.take_bytes(name_length, "an entry's name");
    ArchiveEntry e;
    e.kind = static_cast<ArchiveEntry::Kind>(in.take<std::uint8_t>("an entry's kind"));
    switch (e.kind) {
    case ArchiveEntry::Kind::doubles: {
      const auto rank = in.take<std::uint32_t>("an array's rank");
      if (rank > 8)
        throw CheckpointError(path.string() + ": entry '" + name + "' has rank " + std::to_string(rank));
      std::uint64_t count = 1;
      for (std::uint32_t d = 0; d < rank; ++d) {
        e.shape.push_back(in.take<std::uint64_t>("an array's dimension"));
        count *= e.shape.back();
      }
      in.take_doubles(e.values, count, "an array's values");
      break;
    }
    case ArchiveEntry::Kind::integer:
      e.integer = in.take<std::int64_t>("an integer");
      break;
    case ArchiveEntry::Kind::text: {
      const auto length = in.take<std::uint64_t>("a text's length");
      e.text = in.take_bytes(length, "a text");
      break;
    }
    default:
      throw CheckpointError(path.string() + ": entry '" + name + "' has an unknown kind");
    }
    archive.put_entry(name, std::move(e));
  }
  if (!in.done())
    throw CheckpointError(path.string() + ": bytes left after the last entry");
  return archive;
}

std::string archive_checksum(const std::filesystem::path &path) {
  const std::string bytes = read_file(path);
  std::uint64_t n_entries = 0, checksum = 0;
  checked_frame(bytes, path, n_entries, checksum);
  return hex_of(checksum);
}

} // namespace fsi::checkpoint
