#pragma once
// Minimal reading of the XDMF index text for the tests: enough to check the elements users
// rely on (one Grid with a Time per saved step, the row of each step in its Xdmf2 hyperslab
// and Xdmf3 forms, the HDF5 refs).

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fsi::structure::output::testing {

class XdmfText {
public:
  explicit XdmfText(const std::filesystem::path &path) {
    std::ifstream in(path);
    std::ostringstream content;
    content << in.rdbuf();
    text_ = content.str();
  }

  const std::string &text() const { return text_; }

  /// The closing tag is present: the file was not cut while being written.
  bool is_complete() const { return text_.find("</Xdmf>") != std::string::npos; }

  std::vector<double> time_values() const {
    std::vector<double> times;
    for (const std::string &value : texts_after("<Time Value=\"", '"')) {
      times.push_back(std::stod(value));
    }
    return times;
  }

  /// "start stride count" text of every hyperslab, in document order.
  std::vector<std::string> hyperslab_selections() const {
    return texts_after("<DataItem Dimensions=\"3 3\" NumberType=\"Int\" Format=\"XML\">", '<');
  }

  /// Dimensions and path of every heavy-data reference written on one line (whole datasets),
  /// as "DIMS|FILE:PATH".
  std::vector<std::string> hdf_references() const {
    const std::string heavy = "Format=\"HDF\">";
    const std::string item = "<DataItem Dimensions=\"";
    std::vector<std::string> references;
    for (auto at = text_.find(heavy); at != std::string::npos; at = text_.find(heavy, at + 1)) {
      const auto path_at = at + heavy.size();
      if (text_.compare(path_at, 1, "\n") == 0) {
        continue; // a row item: its text is on the next line (row_references())
      }
      const auto dims_at = text_.rfind(item, at) + item.size();
      references.push_back(text_.substr(dims_at, text_.find('"', dims_at) - dims_at) + "|" +
                           text_.substr(path_at, text_.find('<', path_at) - path_at));
    }
    return references;
  }

  /// Text of every row item (the Xdmf3 form "FILE:PATH|start:stride:count:dataspace"), in
  /// document order.
  std::vector<std::string> row_references() const {
    std::vector<std::string> rows;
    for (std::string line : texts_after("Format=\"HDF\">\n", '\n')) {
      line.erase(0, line.find_first_not_of(' '));
      rows.push_back(line);
    }
    return rows;
  }

  std::size_t count(const std::string &needle) const {
    std::size_t n = 0;
    for (auto at = text_.find(needle); at != std::string::npos; at = text_.find(needle, at + 1)) {
      ++n;
    }
    return n;
  }

private:
  /// The text between each occurrence of `prefix` and the next `terminator`.
  std::vector<std::string> texts_after(const std::string &prefix, char terminator) const {
    std::vector<std::string> values;
    for (auto at = text_.find(prefix); at != std::string::npos; at = text_.find(prefix, at + 1)) {
      const auto value_at = at + prefix.size();
      values.push_back(text_.substr(value_at, text_.find(terminator, value_at) - value_at));
    }
    return values;
  }

  std::string text_;
};

} // namespace fsi::structure::output::testing
