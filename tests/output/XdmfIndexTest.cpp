// The XDMF index beside the HDF5 file: one Grid per saved step with its Time, hyperslabs that
// pick row k of the per-step datasets, and references by relative file name.

#include "OutputTestSupport.hpp"
#include "XdmfText.hpp"

#include "structure_solver/output/ResultsReader.hpp"

namespace fsi::structure::output::testing {
namespace {

using XdmfIndex = ScratchFolderTest;

TEST_F(XdmfIndex, ListsOneGridWithItsTimePerSavedStep) {
  {
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    write_sample_run(writer, 3);
  }
  const XdmfText index(xdmf_path());
  ASSERT_TRUE(index.is_complete());
  EXPECT_EQ(index.count("CollectionType=\"Temporal\""), 1u);
  EXPECT_EQ(index.count("CollectionType=\"Spatial\""), 3u);
  EXPECT_EQ(index.time_values(), ResultsReader(h5_path()).time_s());
  EXPECT_EQ(index.time_values(),
            std::vector<double>({sample_time_s(0), sample_time_s(1), sample_time_s(2)}));
}

TEST_F(XdmfIndex, HyperslabsSelectRowKOfPositionsAndVelocities) {
  {
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    write_sample_run(writer, 3);
  }
  std::vector<std::string> expected;
  for (int k = 0; k < 3; ++k) {
    const std::string start = std::to_string(k) + " 0 0 1 1 1 1 ";
    // sheet: geometry and velocity, then fiber: geometry and velocity
    expected.insert(expected.end(), {start + "12 3", start + "12 3", start + "5 3", start + "5 3"});
  }
  EXPECT_EQ(XdmfText(xdmf_path()).hyperslab_selections(), expected);
}

// The same rows in the form the Xdmf3 reader reads (the text of the outer item).
TEST_F(XdmfIndex, RowItemsCarryTheXdmf3HyperslabOfRowK) {
  {
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    write_sample_run(writer, 2);
  }
  std::vector<std::string> expected;
  for (int k = 0; k < 2; ++k) {
    const std::string start = std::to_string(k) + " 0 0:1 1 1:1 ";
    for (const std::string structure : {"sheet", "fiber"}) {
      const std::string shape = structure == "sheet" ? "12 3" : "5 3";
      for (const std::string dataset : {"position_m", "velocity_m_per_s"}) {
        expected.push_back("run.h5:/structures/" + structure + "/" + dataset + "|" + start +
                           shape + ":2 " + shape);
      }
    }
  }
  const XdmfText index(xdmf_path());
  EXPECT_EQ(index.row_references(), expected);
  EXPECT_EQ(index.count("<DataItem Type=\"HyperSlab\" Dimensions=\"1 12 3\" NumberType=\"Float\" "
                        "Precision=\"8\" Format=\"HDF\">"),
            4u);
  EXPECT_EQ(index.count("ItemType=\"HyperSlab\""), 0u) << "Xdmf3 cannot show that form";
}

TEST_F(XdmfIndex, HeavyDataIsReferencedByRelativeFileNameWithCurrentShapes) {
  {
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    write_sample_run(writer, 2);
  }
  const std::vector<std::string> step_references = {
      "6 4|run.h5:/structures/sheet/connectivity",
      "2 12 3|run.h5:/structures/sheet/position_m",
      "2 12 3|run.h5:/structures/sheet/velocity_m_per_s",
      "4 2|run.h5:/structures/fiber/connectivity",
      "2 5 3|run.h5:/structures/fiber/position_m",
      "2 5 3|run.h5:/structures/fiber/velocity_m_per_s",
  };
  std::vector<std::string> expected = step_references;
  expected.insert(expected.end(), step_references.begin(), step_references.end());
  EXPECT_EQ(XdmfText(xdmf_path()).hdf_references(), expected);
}

TEST_F(XdmfIndex, TopologiesAreQuadrilateralsForTheMembraneAndSegmentsForTheFilament) {
  {
    ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
    write_sample_run(writer, 1);
  }
  const XdmfText index(xdmf_path());
  EXPECT_EQ(index.count("<Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"6\">"), 1u);
  EXPECT_EQ(index.count("<Topology TopologyType=\"Polyline\" NumberOfElements=\"4\" "
                        "NodesPerElement=\"2\">"),
            1u);
  EXPECT_EQ(index.count("<Geometry GeometryType=\"XYZ\">"), 2u);
  EXPECT_EQ(index.count("<Attribute Name=\"velocity_m_per_s\" AttributeType=\"Vector\" "
                        "Center=\"Node\">"),
            2u);
}

TEST_F(XdmfIndex, IsRewrittenAfterEveryStepWithoutLeavingATemporaryFile) {
  ResultsWriter writer(h5_path(), xdmf_path(), sample_metadata());
  writer.add_structure(sheet_layout());
  writer.add_structure(fiber_layout());
  EXPECT_TRUE(XdmfText(xdmf_path()).is_complete());
  EXPECT_TRUE(XdmfText(xdmf_path()).time_values().empty());
  for (int k = 0; k < 3; ++k) {
    const SampleStep sample(k);
    writer.write_step(sample.record);
    const XdmfText index(xdmf_path());
    EXPECT_TRUE(index.is_complete());
    EXPECT_EQ(index.time_values().size(), static_cast<std::size_t>(k + 1));
    EXPECT_EQ(index.time_values().back(), sample_time_s(k));
  }
  EXPECT_FALSE(std::filesystem::exists(folder_ / "run.xdmf.tmp"));
}

TEST_F(XdmfIndex, RefersToTheHdf5FileRelativeToItsOwnFolder) {
  std::filesystem::create_directories(folder_ / "data");
  {
    ResultsWriter writer(folder_ / "data" / "run.h5", xdmf_path(), sample_metadata());
    write_sample_run(writer, 1);
  }
  const std::vector<std::string> references = XdmfText(xdmf_path()).hdf_references();
  ASSERT_FALSE(references.empty());
  EXPECT_EQ(references.front(), "6 4|data/run.h5:/structures/sheet/connectivity");
}

} // namespace
} // namespace fsi::structure::output::testing
