// The mesh check before gmshload (plugin/core/mesh_check.hpp), on small hand-written MSH files:
// a valid square of two triangles passes; each fault gmshload aborts on is named.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "core/mesh_check.hpp"

namespace {

// The unit square as two counter-clockwise triangles (nodes 1-4), with `elements` overridable.
std::string square(const std::string& format = "2.2 0 8", const std::string& triangles =
                       "1 2 2 1 1 1 2 3\n2 2 2 1 1 1 3 4\n", const std::string& count = "2",
                   bool end = true, double scale = 1) {
  std::string s = "$MeshFormat\n" + format + "\n$EndMeshFormat\n$Nodes\n4\n";
  s += "1 0 0 0\n2 " + std::to_string(scale) + " 0 0\n3 " + std::to_string(scale) + " " +
       std::to_string(scale) + " 0\n4 0 " + std::to_string(scale) + " 0\n$EndNodes\n";
  s += "$Elements\n" + count + "\n" + triangles + (end ? "$EndElements\n" : "");
  return s;
}

std::string check(const std::string& text, double minq = 1e-3) {
  char name[] = "/tmp/sma-mesh-XXXXXX";
  const int fd = mkstemp(name);
  close(fd);
  std::ofstream(name) << text;
  const std::string error = sma::mesh::check_msh(name, minq);
  std::remove(name);
  return error;
}

}  // namespace

TEST(MeshCheck, AValidMeshPasses) { EXPECT_EQ(check(square()), ""); }

TEST(MeshCheck, NamesEachFault) {
  EXPECT_NE(check(square("4.1 0 8")).find("is MSH 4.1"), std::string::npos);
  EXPECT_NE(check(square("2.2 1 8")).find("binary"), std::string::npos);
  EXPECT_NE(check(square("2.2 0 8", "1 2 2 1 1 1 2 3\n", "2")).find("1 of the 2 elements"), std::string::npos);
  EXPECT_NE(check(square("2.2 0 8", "1 2 2 1 1 1 2 3\n2 2 2 1 1 1 3 4\n", "2", false)).find("no $EndElements"),
            std::string::npos);
  EXPECT_NE(check("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0").find("cut off before its elements"),
            std::string::npos);
  EXPECT_NE(check(square("2.2 0 8", "1 2 2 1 1 1 2 9\n2 2 2 1 1 1 3 4\n")).find("triangle 1 uses a node"),
            std::string::npos);
  const std::string cw = check(square("2.2 0 8", "1 2 2 1 1 1 2 3\n2 2 2 1 1 1 4 3\n"));
  EXPECT_NE(cw.find("triangle 2 (centroid 0.333333, 0.666667) is clockwise"), std::string::npos) << cw;
  EXPECT_NE(check("no header").find("not a gmsh MSH file"), std::string::npos);
}

// Faults that gmshload takes without a word and then corrupts memory or reads wrongly on.
TEST(MeshCheck, NamesNodeAndRepeatFaults) {
  const std::string twice = check(square("2.2 0 8", "1 2 2 1 1 1 2 3\n2 2 2 1 1 1 3 4\n3 2 2 1 1 3 1 2\n", "3"));
  EXPECT_NE(twice.find("triangle 3 repeats triangle 1 (the same three nodes)"), std::string::npos) << twice;
  std::string fewer = square();
  fewer.replace(fewer.find("$Nodes\n4\n"), 9, "$Nodes\n5\n");
  EXPECT_NE(check(fewer).find("declares 5 nodes and lists 4"), std::string::npos) << check(fewer);
  std::string dup = square();
  dup.replace(dup.find("\n4 0 "), 4, "\n3 0 ");
  EXPECT_NE(check(dup).find("node 3 is defined twice"), std::string::npos) << check(dup);
  std::string nan = square();
  nan.replace(nan.find("\n2 1.000000 "), 12, "\n2 nan ");
  EXPECT_NE(check(nan).find("a node line is not 'id x y z' with finite coordinates"), std::string::npos) << check(nan);
  std::string huge = square();
  huge.replace(huge.find("\n2 1.000000 "), 12, "\n2 1e300 ");
  EXPECT_NE(check(huge).find("finite coordinates below 1e12"), std::string::npos) << check(huge);
}

TEST(MeshCheck, AreaFloorAndQualityAreGmshloadsAndTheOptions) {
  // A square of side 1e-4 has triangles of area 5e-9 < 1e-8: gmshload's floor, in the mesh's units.
  EXPECT_NE(check(square("2.2 0 8", "1 2 2 1 1 1 2 3\n2 2 2 1 1 1 3 4\n", "2", true, 1e-4)).find("area 5e-09 < 1e-8"),
            std::string::npos);
  // A sliver: q = 4 sqrt(3) (1/2 * 1 * 0.001) / (1 + 2 (0.25 + 1e-6)) = 2.31e-3.
  const std::string sliver = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0.5 0.001 0\n"
                             "$EndNodes\n$Elements\n1\n1 2 2 1 1 1 2 3\n$EndElements\n";
  EXPECT_EQ(check(sliver, 1e-3), "");
  EXPECT_NE(check(sliver, 0.01).find("has quality 0.00231 < 0.01"), std::string::npos) << check(sliver, 0.01);
  EXPECT_EQ(check(sliver, 0), "");
}
