// The strict configuration reader: spelling suggestions, ranges, types, nested paths with
// file and line in every message, and the YAML echo of the effective configuration.

#include "common/ConfigEmitter.hpp"
#include "common/ConfigReader.hpp"
#include "common/DidYouMean.hpp"

#include <gtest/gtest.h>

namespace fsi::common {
namespace {

struct Inner {
  double length_m = 1.0;
  template <class V> void visit(V &v) { v.number("length_m", length_m, Range::positive("m"), "A length."); }
};

struct Outer {
  int count = 3;
  Inner inner;
  std::vector<Inner> items;
  template <class V> void visit(V &v) {
    v.integer("count", count, Range::at_least(1, "1"), "A count.");
    v.section("inner", inner, "Nested.");
    v.list("items", items, "A list.");
  }
};

std::string error_of(const std::string &yaml) {
  try {
    ConfigReader reader(YAML::Load(yaml), "case.yaml");
    Outer config;
    config.visit(reader);
    reader.finish();
  } catch (const ConfigError &e) {
    return e.what();
  }
  return "";
}

TEST(DidYouMean, SuggestsTheClosestNameOnlyWhenClose) {
  EXPECT_EQ(closest_match("lenght_m", {"length_m", "count"}), "length_m");
  EXPECT_EQ(closest_match("zzzzzz", {"length_m", "count"}), "");
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(ConfigReader, ReportsUnknownNestedKeysWithPathLineAndSuggestion) {
  const std::string message = error_of("count: 2\ninner:\n  lenght_m: 2\n");
  EXPECT_NE(message.find("case.yaml:3: unknown key 'inner.lenght_m'. Did you mean 'length_m'?"), std::string::npos)
      << message;
}

TEST(ConfigReader, ReportsRangeAndTypeErrorsWithTheListIndex) {
  EXPECT_NE(error_of("items:\n  - length_m: 1\n  - length_m: -2\n")
                .find("items[1].length_m = -2 is out of range: allowed > 0 m"),
            std::string::npos);
  EXPECT_NE(error_of("count: many\n").find("count = 'many' is not a valid value"), std::string::npos);
  EXPECT_NE(error_of("count: 0\n").find("count = 0 is out of range"), std::string::npos);
  EXPECT_EQ(error_of("count: 2\ninner: {length_m: 0.5}\nitems: [{length_m: 3}]\n"), "");
}

Outer read_with(const std::string &yaml, const std::vector<std::string> &assignments) {
  ConfigReader reader = ConfigReader(YAML::Load(yaml), "case.yaml").with_assignments(assignments);
  Outer config;
  config.visit(reader);
  reader.finish();
  return config;
}

std::string assignment_error(const std::vector<std::string> &assignments) {
  try {
    (void)read_with("count: 2\ninner: {length_m: 0.5}\n", assignments);
  } catch (const ConfigError &e) {
    return e.what();
  }
  return "";
}

TEST(ConfigReader, AssignmentsOnTheCommandLineGoOverTheFileAndAreCheckedAsItsKeys) {
  const Outer config = read_with("count: 2\ninner: {length_m: 0.5}\n", {"inner.length_m=0.0076", "count=5"});
  EXPECT_EQ(config.inner.length_m, 0.0076);
  EXPECT_EQ(config.count, 5);
  EXPECT_EQ(read_with("count: 2\n", {"inner.length_m=3"}).inner.length_m, 3.0); // a section the file lacks
  EXPECT_EQ(read_with("count: 2\n", {"count=4", "count=7"}).count, 7);          // the last one wins
  EXPECT_NE(assignment_error({"inner.length_m=-0.01"}).find("inner.length_m = -0.01 is out of range: allowed > 0 m"),
            std::string::npos);
  EXPECT_NE(assignment_error({"inner.lenght_m=1"}).find("unknown key 'inner.lenght_m'. Did you mean 'length_m'?"),
            std::string::npos);
  for (const char *malformed : {"inner.length_m", "inner.length_m=", "=3", "inner..length_m=3", "inner.=3"})
    EXPECT_NE(assignment_error({malformed}).find(std::string("--set '") + malformed + "'"), std::string::npos)
        << malformed;
}

struct Indices {
  std::vector<int> index;
  template <class V> void visit(V &v) {
    v.integer_list("index", index, Range::non_negative("1"), "Grid indices.");
  }
};

std::string integer_list_error(const std::string &yaml, std::vector<int> *read = nullptr) {
  try {
    ConfigReader reader(YAML::Load(yaml), "case.yaml");
    Indices config;
    config.visit(reader);
    reader.finish();
    if (read)
      *read = config.index;
  } catch (const ConfigError &e) {
    return e.what();
  }
  return "";
}

TEST(ConfigReader, ReadsIntegerListsOfAnyLengthAndChecksEachEntry) {
  std::vector<int> read;
  EXPECT_EQ(integer_list_error("index: [3, 7]\n", &read), "");
  EXPECT_EQ(read, (std::vector<int>{3, 7}));
  EXPECT_EQ(integer_list_error("index: [4]\n", &read), "");
  EXPECT_EQ(read, (std::vector<int>{4}));
  EXPECT_NE(integer_list_error("index: [1.5, 2]\n").find("index must be a list of integers"), std::string::npos);
  EXPECT_NE(integer_list_error("index: 3\n").find("index must be a list of integers"), std::string::npos);
  EXPECT_NE(integer_list_error("index: [2, -1]\n").find("each entry must be >= 0"), std::string::npos);
  Indices config{{1, 2}};
  EXPECT_EQ(YAML::Load(to_yaml(config))["index"].as<std::vector<int>>(), (std::vector<int>{1, 2}));
}

TEST(ConfigEmitter, EchoesEveryKeyIncludingDefaults) {
  Outer config;
  config.items.resize(1);
  const std::string yaml = to_yaml(config);
  const YAML::Node echoed = YAML::Load(yaml);
  EXPECT_EQ(echoed["count"].as<int>(), 3);
  EXPECT_DOUBLE_EQ(echoed["inner"]["length_m"].as<double>(), 1.0);
  EXPECT_EQ(echoed["items"].size(), 1u);
}

} // namespace
} // namespace fsi::common
